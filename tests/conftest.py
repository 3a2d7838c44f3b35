"""Test-session set-up: numba's on-disk cache is checked against the compiled sources once, before any test; with
pytest-xdist workers (``make test``), the controller first compiles the engines' kernels into that cache, in two
processes at once (``tests/warm_cache.py``), so that the workers load them rather than each compiling them; and the
longest modules are handed out first (:data:`LONGEST_FIRST`)."""

import warm_cache

from bearing_mbs.core.numba_cache import invalidate_if_stale

#: The modules that took longest in a two-worker ``make test`` (10 to 110 s each, measured 2026-11-27), longest first.
#: xdist's ``--dist loadscope`` hands whole modules to the workers in collection order; collected alphabetically,
#: these came late and left one worker alone with a long module at the end. Scheduled first, the short modules fill
#: the tail. A module missing here only runs in its alphabetical place.
LONGEST_FIRST = (
    "test_no_traceback_journal.py", "test_lubricated_bearing.py", "test_spindle.py", "test_no_traceback_rotor.py",
    "test_rolling.py", "test_stability.py", "test_static_check.py", "test_impacts.py", "test_steady_skidding.py",
    "test_spec_properties.py", "test_jacobians.py", "test_case4.py", "test_sensitivity_resume.py",
    "test_bearing_engines.py", "test_cage_constraint.py", "test_no_traceback_slewing.py", "test_slewing_pitch.py",
    "test_ehl_line_solver.py",
)


def pytest_collection_modifyitems(config, items):
    rank = {name: place for place, name in enumerate(LONGEST_FIRST)}
    items.sort(key=lambda item: rank.get(item.path.name, len(rank)))  # stable: every module keeps its own order


def pytest_configure(config):
    if hasattr(config, "workerinput"):  # an xdist worker: its controller has done both
        return
    invalidate_if_stale()
    if (config.getoption("numprocesses", default=None) or 0) and not config.option.collectonly:
        warm_cache.warm()
