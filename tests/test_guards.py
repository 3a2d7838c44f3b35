"""Diverging or unphysical runs stop with a typed failure kind (``Result.failure``) and a message naming the
time, the pair or body, and a likely fix; what was computed before is kept.

The tests assert the kind and the facts in the data (stop time, last state, the pair at fault); each keeps one
check that the message names the pair or body and the stop time, without pinning its wording.
"""

import math
import re

import numpy as np
import pytest

from bearing_mbs.core.failures import Failure
from bearing_mbs.engines import simulate
from bearing_mbs.models import build_scene

from cases import seed_spec

NUMBER = re.compile(r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?")


def names_time_and(message: str, time: float, *names: str) -> bool:
    """The message mentions every name and, as a number (any format), the time of the stop."""
    numbers = [float(n) for n in NUMBER.findall(message)]
    return all(name in message for name in names) and any(math.isclose(n, time, rel_tol=1e-5) for n in numbers)


# A step far too large for the contact stiffness: the ball tunnels deep into the floor in one step.
TOO_LARGE = ["scenario.end_time=0.1", "contact.wall.stiffness=6e4"]


@pytest.mark.parametrize(
    "overrides",
    [
        ["solver.reference.method=rk4", "solver.reference.step=2e-3"],
        ["solver.engine=exudyn", "solver.exudyn.method=rk4", "solver.exudyn.step=2e-3"],
    ],
)
def test_penetration_guard_names_time_pair_and_fix(overrides):
    spec = seed_spec(2, TOO_LARGE + ["solver.output_interval=2e-3", *overrides])
    result = simulate(build_scene(spec), spec.solver, spec.scenario.end_time)
    assert result.failure is Failure.PENETRATION and not result.success
    # output up to the stop is kept, ending with the state where the run stopped
    assert 0.0 < result.time[-1] < 0.1 and result.time.size > 5
    assert np.all(np.isfinite(result.position))
    # the deepest pair in that state is the ball on the floor, beyond the guard: penetration_limit × radius
    gaps = result.pair_series("gap")[-1]
    assert result.pair_names[int(np.argmin(gaps))] == "ball-floor"
    radius = spec.balls[0].radius
    assert -gaps.min() > spec.solver.penetration_limit * radius
    assert names_time_and(result.message, result.time[-1], "ball-floor"), result.message


def test_blow_up_names_the_body_and_the_pair():
    """A huge stiffness with a coarse step flings the ball away (finite but absurd): the speed guard stops it."""
    spec = seed_spec(2, ["scenario.end_time=0.1", "contact.wall.stiffness=1e200", "solver.penetration_limit=1.0",
                         "solver.reference.method=rk4", "solver.reference.step=1e-4", "solver.output_interval=1e-3"])
    result = simulate(build_scene(spec), spec.solver, spec.scenario.end_time)
    assert result.failure is Failure.BLOWUP and result.failure.diverged and not result.success
    assert 0.0 < result.time[-1] < 0.1
    # the last good state is kept: finite, near the floor, slower than the guard's speed_limit
    assert np.all(np.isfinite(result.velocity[-1])) and np.all(np.abs(result.position[-1]) < 1.0)
    assert np.abs(result.velocity[-1]).max() < spec.solver.speed_limit
    assert result.body_names == ("ball",) and result.pair_names == ("ball-floor",)
    assert names_time_and(result.message, result.time[-1], "ball", "ball-floor"), result.message


def test_implicit_solver_failure_on_the_dead_zone_explains_itself():
    """Newton's method cannot follow the document's discontinuous dead-zone friction law.

    It fails near t = 0.0335 s at every step tried, 5e-6 to 2e-5 s (pinned Exudyn 1.13.6), step halving
    included, so the failure is asserted, not assumed.
    """
    spec = seed_spec(3, ["solver.engine=exudyn", "scenario.end_time=0.2"])
    result = simulate(build_scene(spec), spec.solver, spec.scenario.end_time)
    assert result.failure is Failure.SOLVER_FAILED and not result.success
    assert 0.03 < result.time[-1] < 0.04  # near t = 0.0335 s, where it fails at every step tried
    assert [pair.law.friction_law for pair in build_scene(spec).pairs] == ["dead_zone"]  # the one pair's law
    # names the law at fault and the smooth one to use instead
    assert names_time_and(result.message, result.time[-1], "dead_zone", "erf"), result.message


@pytest.mark.parametrize("engine, method, switch", [("exudyn", "generalized_alpha", False),
                                                    ("exudyn", "rk4", True), ("reference", "rk4", True)])
def test_a_divergence_fix_fits_what_the_run_already_uses(engine, method, switch):
    """The likely fix names a value (a quarter of the step the run used), and offers the implicit solver only to
    a run that is not already implicit (the trust issue: a 1e12 N load on generalized-alpha was told to use
    generalized-alpha)."""
    from bearing_mbs.engines.diagnosis import divergence_fix
    from bearing_mbs.spec.solver import ExudynSolver, ReferenceSolver, SolverSpec

    settings = {engine: (ExudynSolver if engine == "exudyn" else ReferenceSolver)(method=method, step=1e-5)}
    fix = divergence_fix(SolverSpec(engine=engine, **settings))
    assert "2.5e-06 s" in fix
    assert ("generalized_alpha" in fix) == switch
