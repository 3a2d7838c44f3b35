"""The implicit solvers on the lubricated seed bearing: Exudyn's generalized-alpha with the force elements' analytic
Jacobian, and the reference engine's own generalized-α.

References and tolerances:
* Exudyn with the analytic Jacobian against Exudyn with its own numerical Jacobian (finite differences of the
  force user function, an independent differentiation): both solve the same step equations to Newton's relative
  tolerance (1e-8), so their positions agree to 1e-8 of the largest coordinate, and their cage speeds to 1e-8;
* the reference engine's generalized-α (h = 1e-5 s, its own Newton on the same Jacobian, the constraint cage by
  projection) against the explicit RK4 at its advised step (8e-7 s, docs/numerics.md) and against Exudyn: the
  tolerances of tests/test_bearing_engines.py, cage speed within 0.5 %, largest roller load within 1 %.
"""

import numpy as np
import pytest

from bearing_mbs.engines import simulate
from bearing_mbs.models import build_scene, load_spec
from bearing_mbs.runner import summarize

from cases import SCENARIOS

SHORT = ["scenario.end_time=0.01", "analysis.start=0.005", "solver.output_interval=1e-4"]
SETTINGS = {
    "exudyn_analytic": ["solver.engine=exudyn", "solver.exudyn.step=1e-5", "solver.exudyn.jacobian=analytic"],
    "exudyn_numerical": ["solver.engine=exudyn", "solver.exudyn.step=1e-5", "solver.exudyn.jacobian=numerical"],
    "implicit": ["solver.engine=reference", "solver.reference.method=generalized_alpha",
                 "solver.reference.step=1e-5", "solver.reference.tolerance=1e-6"],
    "explicit": ["solver.engine=reference", "solver.reference.method=rk4", "solver.reference.step=8e-7"],
}


@pytest.fixture(scope="module")
def runs():
    out = {}
    for name, overrides in SETTINGS.items():
        spec = load_spec(SCENARIOS / "seed_hss_steady.toml", SHORT + overrides)
        scene = build_scene(spec)
        result = simulate(scene, spec.solver, spec.scenario.end_time)
        assert result.success, (name, result.message)
        out[name] = (spec, scene, result)
    return out


def test_exudyn_with_the_analytic_jacobian_solves_the_same_steps(runs):
    analytic, numerical = runs["exudyn_analytic"][2], runs["exudyn_numerical"][2]
    assert analytic.metadata["jacobian"] == "analytic" and numerical.metadata["jacobian"] == "numerical"
    assert analytic.metadata["jacobian_user_evaluations"] > 0 == numerical.metadata["jacobian_user_evaluations"]
    scale = np.abs(numerical.position[:, :2]).max()
    np.testing.assert_allclose(analytic.position[:, :2], numerical.position[:, :2], rtol=0, atol=1e-8 * scale)
    a, b = summarize(*runs["exudyn_analytic"]), summarize(*runs["exudyn_numerical"])
    assert a["cage_speed_ratio"] == pytest.approx(b["cage_speed_ratio"], rel=1e-8)
    # the numerical Jacobian costs 2n force evaluations each
    assert analytic.stats.force_evaluations < numerical.stats.force_evaluations


@pytest.mark.parametrize("against", ["explicit", "exudyn_analytic"])
def test_reference_generalized_alpha_agrees_on_the_lubricated_bearing(runs, against):
    implicit, other = summarize(*runs["implicit"]), summarize(*runs[against])
    assert implicit["cage_speed_ratio"] == pytest.approx(other["cage_speed_ratio"], rel=5e-3)
    assert implicit["max_roller_load"] == pytest.approx(other["max_roller_load"], rel=1e-2)
    stats = runs["implicit"][2].stats
    assert stats.newton_iterations >= stats.steps > 0 and stats.jacobian_evaluations > 0
