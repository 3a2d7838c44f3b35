"""The implicit solvers on the lubricated seed bearing: Exudyn's generalized-alpha with the force elements' analytic
Jacobian, and the reference engine's own generalized-α.

References and tolerances:
* Exudyn with the analytic Jacobian against Exudyn with its own numerical Jacobian (finite differences of the
  force user function, an independent differentiation): both solve the same step equations to Newton's relative
  tolerance (1e-8), so their positions agree to 1e-8 of the largest coordinate, and their cage speeds to 1e-8;
* the reference engine's generalized-α (h = 1e-5 s, its own Newton on the same Jacobian, the constraint cage by
  projection) against the explicit RK4 at its advised step (8e-7 s, docs/numerics.md) and against Exudyn: the
  tolerances of tests/test_bearing_engines.py, cage speed within 0.5 %, largest roller load within 1 %;
* the fastest setting of the revolution benchmark (1e-4 s, ρ∞ = 0.3, Newton tolerance 1e-3) against the same two,
  at the same tolerances;
* a generalized-α step the constraint cage's projection refuses is taken back and retried shorter (the run had
  stopped): at 680 N with 100 µm clearance and 1e-4 s steps, the cage speed after 3 ms within 0.5 % of a 1e-5 s run
  (0.08 % measured; the ring's fall through the clearance is an impact, so positions are not compared);
* the reference engine's sparse Newton step (block elimination) against the dense formula of its Newton matrix,
  written out with numpy, on the seed bearing's own Jacobian: 1e-9 of the increment.
"""

import numpy as np
import pytest

from bearing_mbs.engines import simulate
from bearing_mbs.models import build_scene, load_spec
from bearing_mbs.runner import summarize

from cases import SCENARIOS

#: At the document's zero clearance: at the operating clearance the load, applied at once, drops the ring through it
#: onto its rollers, and the impacts amplify differences within Newton's tolerance far above it (6e-6 of the ring's
#: travel between the two Jacobians; tests/test_skidding_second_pass.py compares the engines under a load ramp).
SHORT = ["scenario.end_time=0.01", "analysis.start=0.005", "solver.output_interval=1e-4",
         "bearing.diametral_clearance=0"]
SETTINGS = {
    "exudyn_analytic": ["solver.engine=exudyn", "solver.exudyn.step=1e-5", "solver.exudyn.jacobian=analytic"],
    "exudyn_numerical": ["solver.engine=exudyn", "solver.exudyn.step=1e-5", "solver.exudyn.jacobian=numerical"],
    "implicit": ["solver.engine=reference", "solver.reference.method=generalized_alpha",
                 "solver.reference.step=1e-5", "solver.reference.tolerance=1e-6"],
    "explicit": ["solver.engine=reference", "solver.reference.method=rk4", "solver.reference.step=8e-7"],
    # the fastest setting of benchmarks/out/bearing_revolution.json: ten times the step, strong numerical damping
    "implicit_fast": ["solver.engine=reference", "solver.reference.method=generalized_alpha",
                      "solver.reference.step=1e-4", "solver.reference.tolerance=1e-3",
                      "solver.reference.spectral_radius=0.3"],
    # a step that does not divide the output interval (1e-4 s)
    "implicit_odd_step": ["solver.engine=reference", "solver.reference.method=generalized_alpha",
                          "solver.reference.step=7e-5", "solver.reference.tolerance=1e-3",
                          "solver.reference.spectral_radius=0.3"],
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


@pytest.mark.parametrize("implicit_run", ["implicit", "implicit_fast"])
@pytest.mark.parametrize("against", ["explicit", "exudyn_analytic"])
def test_reference_generalized_alpha_agrees_on_the_lubricated_bearing(runs, against, implicit_run):
    implicit, other = summarize(*runs[implicit_run]), summarize(*runs[against])
    assert implicit["cage_speed_ratio"] == pytest.approx(other["cage_speed_ratio"], rel=5e-3)
    assert implicit["max_roller_load"] == pytest.approx(other["max_roller_load"], rel=1e-2)
    stats = runs[implicit_run][2].stats
    assert stats.newton_iterations >= stats.steps > 0 and stats.jacobian_evaluations > 0


def test_a_fixed_step_that_does_not_divide_the_output_interval_keeps_newtons_matrix():
    """7e-5 s in 1e-4 s output intervals: the driver takes two equal steps of 5e-5 s per interval, so the matrix
    formed for the first serves the run (with a 7e-5 s step and a 3e-5 s landing step it was formed on every step,
    their ratio 2.3 being outside the reuse window of 1.4)."""
    spec = load_spec(SCENARIOS / "seed_hss_steady.toml", SHORT + SETTINGS["implicit_odd_step"])
    stats = simulate(build_scene(spec), spec.solver, spec.scenario.end_time).stats
    assert stats.steps >= 2 * 100  # two per output interval, and the retries of the load's first impact
    assert stats.jacobian_evaluations < stats.steps / 5


def newton_step_both_ways(scene, result, slope_q=4e-11, slope_v=1e-5):
    """Newton's increment of the accelerations at the run's last state for a random residual r that the
    constraints allow (G r = 0, r_λ = 0): from the engine's sparse bordered system (engines/reference/
    block_elimination.py, via generalized_alpha.newton_increment) and from the dense formula of the index-1
    dynamics' Newton matrix, −J⁻¹ r with J = I − P M⁻¹(β′K + γ′C), P M⁻¹ = M⁻¹ − M⁻¹Gᵀ(G M⁻¹ Gᵀ)⁻¹ G M⁻¹,
    written out here with numpy. The slopes are β′, γ′ of a 1e-5 s step."""
    from bearing_mbs.contact.kernel import N_PAIR_OUTPUTS
    from bearing_mbs.elements import element_jacobian, pack_scene, scene_forces
    from bearing_mbs.engines.reference.block_elimination import assemble_constraints, factor, subtract_stiffness
    from bearing_mbs.engines.reference.bundles import new_implicit_carry
    from bearing_mbs.engines.reference.constraints import constraint_rows
    from bearing_mbs.engines.reference.engine import newton_system
    from bearing_mbs.engines.reference.generalized_alpha import newton_increment

    packed, n, c = pack_scene(scene), scene.coordinate_count, len(scene.constraints)
    q, v = result.position[-1].copy(), result.velocity[-1].copy()
    latched, pair_out = np.zeros(len(scene.pairs)), np.zeros((len(scene.pairs), N_PAIR_OUTPUTS))
    scene_forces(packed, result.time[-1], q, v, latched, np.zeros(n), pair_out)
    stiffness, damping = np.zeros((n, n)), np.zeros((n, n))
    element_jacobian(packed.elements, result.time[-1], q, v, latched, pair_out, stiffness, damping)
    carry = new_implicit_carry(n, newton_system(scene))
    constraint_rows(packed.constraints, q, v, np.empty(c), carry.constraint_rows, np.empty(c))
    assemble_constraints(carry.newton, packed.inverse_mass, carry.constraint_rows, packed.constraints.body_a,
                         packed.constraints.body_b)
    subtract_stiffness(carry.newton, packed.inverse_mass, stiffness, damping, slope_q, slope_v)
    factor(carry.newton)
    residual = np.random.default_rng(5).standard_normal(n) * (packed.inverse_mass > 0)
    inverse_mass = np.diag(packed.inverse_mass)
    projected = inverse_mass
    if c:
        g = np.zeros((c, n))
        for k, (a, b) in enumerate(zip(packed.constraints.body_a, packed.constraints.body_b)):
            g[k, 3 * a:3 * a + 3] += carry.constraint_rows[k, :3]
            g[k, 3 * b:3 * b + 3] += carry.constraint_rows[k, 3:]
        weighted = g @ inverse_mass
        projected = inverse_mass - weighted.T @ np.linalg.solve(weighted @ g.T, weighted)
        residual -= weighted.T @ np.linalg.solve(weighted @ g.T, g @ residual)  # G r = 0
    newton_increment(packed, carry, residual, np.zeros(c))
    jacobian = np.eye(n) - projected @ (slope_q * stiffness + slope_v * damping)
    return carry.increment, -np.linalg.solve(jacobian, residual), np.abs(stiffness).max() * slope_q


def test_the_sparse_newton_step_is_the_dense_one(runs):
    """Reference: the dense formula (numpy), to 1e-9 of the increment's largest entry, on the lubricated seed
    bearing (constraint cage) at 10 ms; the stiffness term must matter (β′ K / m well above rounding), or the check
    would only test the mass."""
    _, scene, result = runs["implicit"]
    sparse, dense, stiffness_term = newton_step_both_ways(scene, result)
    assert stiffness_term > 1e-3
    np.testing.assert_allclose(sparse, dense, rtol=0, atol=1e-9 * np.abs(dense).max())


def test_the_sparse_newton_step_is_the_dense_one_with_the_penalty_cage():
    """The same on the dry seed bearing (penalty cage: pocket pairs couple the rollers to the cage, no
    constraints), at 1 ms of an RK4 run."""
    spec = load_spec(SCENARIOS / "seed_hss_steady.toml", ["scenario.variant=dry", "scenario.end_time=0.001",
                                                          "solver.output_interval=1e-3", "solver.engine=reference",
                                                          "solver.reference.method=rk4",
                                                          "solver.reference.step=8e-7"])
    scene = build_scene(spec)
    sparse, dense, stiffness_term = newton_step_both_ways(scene, simulate(scene, spec.solver, 0.001))
    assert stiffness_term > 1e-3
    np.testing.assert_allclose(sparse, dense, rtol=0, atol=1e-9 * np.abs(dense).max())


def test_a_step_the_projection_refuses_is_retried_shorter():
    light = ["scenario.end_time=0.003", "analysis.start=0.0015", "solver.output_interval=1e-4", "load.radial=680",
             "bearing.diametral_clearance=1e-4", "solver.engine=reference", "solver.reference.method=generalized_alpha",
             "solver.reference.tolerance=1e-3"]
    cage_speed = {}
    for step, radius in ((1e-4, 0.3), (1e-5, 0.9)):
        spec = load_spec(SCENARIOS / "seed_hss_steady.toml",
                         [*light, f"solver.reference.step={step}", f"solver.reference.spectral_radius={radius}"])
        scene = build_scene(spec)
        result = simulate(scene, spec.solver, spec.scenario.end_time)
        assert result.success, result.message
        cage = [body.name for body in scene.bodies].index("cage")
        cage_speed[step] = result.velocity[-1, 3 * cage + 2]
        if step == 1e-4:
            assert result.stats.rejected_steps > 0
    assert cage_speed[1e-4] == pytest.approx(cage_speed[1e-5], rel=5e-3)
