"""Test-session set-up: numba's on-disk cache is checked against the compiled sources once, before any test; with
pytest-xdist workers (``make test``), the controller first compiles the engines' kernels into that cache, in two
processes at once (``tests/warm_cache.py``), so that the workers load them rather than each compiling them."""

import warm_cache

from bearing_mbs.core.numba_cache import invalidate_if_stale


def pytest_configure(config):
    if hasattr(config, "workerinput"):  # an xdist worker: its controller has done both
        return
    invalidate_if_stale()
    if (config.getoption("numprocesses", default=None) or 0) and not config.option.collectonly:
        warm_cache.warm()
