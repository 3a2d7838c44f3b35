"""Diverging or unphysical runs stop with a message naming the time, the pair or body, and a likely fix;
what was computed before is kept."""

import numpy as np
import pytest

from bearing_mbs.models import build_scene
from cases import seed_spec
from bearing_mbs.engines import simulate

# A step far too large for the contact stiffness: the ball tunnels deep into the floor in one step.
TOO_LARGE = ["scenario.end_time=0.1", "contact.wall.stiffness=6e4"]


@pytest.mark.parametrize(
    "overrides",
    [
        ["solver.reference.method=rk4", "solver.reference.step=2e-3"],
        ["solver.engine=exudyn", "solver.exudyn.method=rk44", "solver.exudyn.step=2e-3"],
    ],
)
def test_penetration_guard_names_time_pair_and_fix(overrides):
    spec = seed_spec(2, TOO_LARGE + ["solver.output_interval=2e-3", *overrides])
    result = simulate(build_scene(spec), spec.solver, spec.scenario.end_time)
    assert not result.success
    assert "ball-floor" in result.message and "t = " in result.message and "reduce the step" in result.message
    # output up to the stop is kept, ending with the state where the run stopped
    assert 0.0 < result.time[-1] < 0.1 and result.time.size > 5
    assert np.all(np.isfinite(result.position))
    depth = -result.pair_series("gap")[-1, 0]
    assert depth > spec.solver.penetration_limit * 0.005


def test_blow_up_names_the_body_and_the_pair():
    """A huge stiffness with a coarse step flings the ball away (finite but absurd): the speed guard stops it."""
    spec = seed_spec(2, ["scenario.end_time=0.1", "contact.wall.stiffness=1e200", "solver.penetration_limit=1.0",
                         "solver.reference.method=rk4", "solver.reference.step=1e-4", "solver.output_interval=1e-3"])
    result = simulate(build_scene(spec), spec.solver, spec.scenario.end_time)
    assert not result.success
    assert "'ball' moves faster than speed_limit" in result.message and "t = " in result.message
    assert "pair in the last good state was 'ball-floor'" in result.message and "reduce the step" in result.message
    assert np.all(np.abs(result.position[-1]) < 1.0)  # the last good state is kept


def test_implicit_solver_failure_on_the_dead_zone_explains_itself():
    """Newton's method cannot follow the document's discontinuous dead-zone friction law.

    It fails near t = 0.0335 s at every step tried, 5e-6 to 2e-5 s (pinned Exudyn 1.13.6), step halving
    included, so the failure is asserted, not assumed.
    """
    spec = seed_spec(3, ["solver.engine=exudyn", "scenario.end_time=0.2"])
    result = simulate(build_scene(spec), spec.solver, spec.scenario.end_time)
    assert not result.success
    assert "t = " in result.message and "dead_zone" in result.message and "erf" in result.message
    assert result.time[-1] > 0
