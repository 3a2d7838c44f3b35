"""Case 1 against its closed form, and every integrator's order on a smooth problem.

References:
* case 1 (free fall, document eq. 14): y = H − g t²/2 exactly. All methods here integrate a constant
  acceleration exactly (the central difference thanks to its Taylor start), so the tolerance is round-off:
  1e-12 × H.
* order: :func:`tests.cases.ball_in_ring_scene` (permanent contact, smooth friction, velocity-dependent
  forces), reference solution by scipy's DOP853 at rtol 1e-13 on the numpy twin (an independent integrator).
  The observed order is the least-squares slope of log(error) against log(step) over a halving sequence; it
  must be within ±0.25 of the method's order, and the error at the finest step is bounded absolutely.
"""

import numpy as np
import pytest
from scipy.integrate import solve_ivp

from bearing_mbs.contact.kernel import N_PAIR_OUTPUTS
from bearing_mbs.elements import pack_scene, scene_forces_twin
from bearing_mbs.engines import simulate
from bearing_mbs.models import build_scene
from bearing_mbs.spec import ExudynSolver, ReferenceSolver, SolverSpec

from cases import ball_in_ring_scene, seed_spec

END_TIME = 0.05


@pytest.mark.parametrize(
    "engine, method, step",
    [
        ("reference", "central_difference", 0.01),
        ("reference", "velocity_verlet", 0.01),
        ("reference", "rk4", 0.01),
        ("reference", "dopri5", 0.01),
        ("reference", "generalized_alpha", 0.01),
        ("reference", "generalized_alpha_adaptive", 0.01),
        ("exudyn", "rk4", 0.01),
        ("exudyn", "generalized_alpha", 0.01),
        ("exudyn", "dopri5", 0.01),
    ],
)
def test_case1_free_fall_matches_the_closed_form(engine, method, step):
    spec = seed_spec(1, [f"solver.engine={engine}", f"solver.{engine}.method={method}", f"solver.{engine}.step={step}"])
    scene = build_scene(spec)
    result = simulate(scene, spec.solver, spec.scenario.end_time)
    height, g = 10.0, 10.0
    exact = height - 0.5 * g * result.time**2
    assert result.success and result.time[-1] == pytest.approx(1.0)
    assert np.max(np.abs(result.position[:, 1] - exact)) < 1e-12 * height
    if method != "central_difference":  # its velocity is the lagged backward difference
        assert np.max(np.abs(result.velocity[:, 1] + g * result.time)) < 1e-12 * g


@pytest.fixture(scope="module")
def smooth_reference():
    scene = ball_in_ring_scene()
    packed = pack_scene(scene)
    q0, v0 = scene.initial_state()
    n = q0.size

    def rhs(t, y):
        forces, pair_out = np.empty(n), np.empty((1, N_PAIR_OUTPUTS))
        scene_forces_twin(packed, t, y[:n], y[n:], np.zeros(1), forces, pair_out)
        return np.concatenate([y[n:], packed.inverse_mass * forces + packed.gravity])

    solution = solve_ivp(rhs, (0, END_TIME), np.concatenate([q0, v0]), method="DOP853", rtol=1e-13, atol=1e-16)
    return scene, solution.y[:n, -1]


def observed_order(steps, errors):
    return np.polyfit(np.log(steps), np.log(errors), 1)[0]


@pytest.mark.parametrize(
    "engine, method, order, coarsest, finest_error",
    [
        ("reference", "central_difference", 1, 2e-5, 5e-7),
        ("reference", "velocity_verlet", 2, 2e-5, 1e-9),
        ("reference", "rk4", 4, 8e-5, 1e-12),
        ("reference", "generalized_alpha", 2, 2e-5, 1e-9),
        ("exudyn", "rk4", 4, 8e-5, 1e-12),
        ("exudyn", "generalized_alpha", 2, 2e-5, 1e-9),
    ],
)
def test_integrator_converges_at_its_order(smooth_reference, engine, method, order, coarsest, finest_error):
    scene, reference = smooth_reference
    steps = coarsest / 2.0 ** np.arange(4)
    errors = []
    for step in steps:
        settings = (ReferenceSolver(method=method, step=step, tolerance=1e-12) if engine == "reference"
                    else ExudynSolver(method=method, step=step, tolerance=1e-12))
        solver = SolverSpec(engine=engine, output_interval=END_TIME, **{engine: settings})
        result = simulate(scene, solver, END_TIME)
        assert result.success, result.message
        errors.append(np.max(np.abs(result.position[-1] - reference)))
    fitted = observed_order(steps, errors)
    assert abs(fitted - order) < 0.25, f"{engine} {method}: observed order {fitted:.2f}, expected {order}; errors {errors}"
    assert errors[-1] < finest_error


def test_adaptive_pair_error_falls_at_fifth_order_in_work(smooth_reference):
    """DOPRI5: error against accepted steps over tolerances 1e-6 … 1e-10 has slope −5 ± 0.6 in log–log."""
    scene, reference = smooth_reference
    steps, errors = [], []
    for tolerance in 10.0 ** -np.arange(6, 11):
        solver = SolverSpec(output_interval=END_TIME,
                            reference=ReferenceSolver(method="dopri5", step=1e-3, tolerance=tolerance))
        result = simulate(scene, solver, END_TIME)
        steps.append(result.stats.steps)
        errors.append(np.max(np.abs(result.position[-1] - reference)))
    slope = -observed_order(np.array(steps, float), errors)
    assert abs(slope - 5) < 0.6, f"dopri5: error ∝ steps^-{slope:.2f}, expected 5; {list(zip(steps, errors))}"
    assert errors[-1] < 1e-10


def test_adaptive_generalized_alpha_error_falls_at_second_order_in_work(smooth_reference):
    """Generalized-α with step control: error against accepted steps over tolerances 1e-7 … 1e-11 has slope
    −2 ± 0.4 in log–log (its order; the step follows tolerance^(1/3) from the third-order local estimate), and the
    finest run is within 5e-8 m of the DOP853 reference (a local tolerance of 1e-11 over its ~1000 steps)."""
    scene, reference = smooth_reference
    steps, errors = [], []
    for tolerance in 10.0 ** -np.arange(7, 12):
        solver = SolverSpec(output_interval=END_TIME, reference=ReferenceSolver(
            method="generalized_alpha_adaptive", step=1e-3, tolerance=tolerance))
        result = simulate(scene, solver, END_TIME)
        assert result.success, result.message
        steps.append(result.stats.steps)
        errors.append(np.max(np.abs(result.position[-1] - reference)))
    slope = -observed_order(np.array(steps, float), errors)
    assert abs(slope - 2) < 0.4, f"generalized_alpha_adaptive: error ∝ steps^-{slope:.2f}; {list(zip(steps, errors))}"
    assert errors[-1] < 5e-8


@pytest.mark.parametrize("method, tolerance", [("central_difference", 1e-13), ("velocity_verlet", 1e-13),
                                               ("rk4", 1e-13), ("dopri5", 1e-13), ("generalized_alpha", 1e-11)])
def test_output_interval_does_not_change_the_solution(method, tolerance):
    """Decimated output and the progress chunks are observation only: the final state is the same whether the
    engine stops every 0.1 ms or only at the end: to round-off (1e-13 m), and for generalized-α to its Newton
    tolerance (its Newton matrix may be formed at other instants; tolerance 1e-12 gives 1e-11 m)."""
    scene = ball_in_ring_scene()
    finals = []
    for interval in (END_TIME, 1e-4):
        solver = SolverSpec(output_interval=interval, reference=ReferenceSolver(method=method, step=1e-5,
                                                                                tolerance=1e-12))
        finals.append(simulate(scene, solver, END_TIME).position[-1])
    np.testing.assert_allclose(finals[0], finals[1], rtol=0, atol=tolerance)
