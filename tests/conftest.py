"""Test-session set-up: numba's on-disk cache is checked against the compiled sources once, before any test."""

from bearing_mbs._numba_cache import invalidate_if_stale


def pytest_configure(config):
    invalidate_if_stale()
