"""The step advisor: stability regions, the bearing's linearised modes, and the engines' warning.

References and tolerances:
* stability polynomials: the Taylor coefficients of exp(z) up to the order of each method (classical; exact to
  1e-15), and DOPRI5's z⁶ coefficient 1/600 (Hairer, Nørsett & Wanner, Solving ODEs I, §II.5);
* region boundaries: RK4 reaches 2.7853 on the negative real axis and 2√2 on the imaginary axis (the roots of
  |R(z)| = 1 on those axes, Hairer & Wanner II, Fig. IV.2.1); DOPRI5 reaches 3.3066 on the real axis. The
  reference engine's central difference (v⁺ = v + h f(q, v), q⁺ = q + h v⁺) has hλ < 2 and hω < 2 in closed
  form, its velocity Verlet hω < 2 and hλ < 1 (its amplification matrix has the eigenvalue −1 at hλ = 1). The
  boundaries are found by a search; tolerance 1e-6 relative;
* the formulas against the engine itself: a ball pressed on the floor and sliding, whose slip decays at
  λ = μ Q φ'(0) (1/m + r²/I) in the linear range of the friction law. Every reference integrator at 0.85 × its
  advised limit damps the slip by 10⁶ in 400 steps; at 1.2 × the limit the slip is not damped even by 100 (RK4
  and the central difference let it grow to the saturation of the law; velocity Verlet locks into a period-2
  chatter of the friction force around a frozen, wrong slip);
* the bearing's friction mode for equal raceway loads and a solid roller: λ = 4 μ Q φ'(0)/m (closed form of the
  2×2 eigenproblem), to 1e-12 relative;
* the operating point: the advisor's static roller load equals the quasi-static solver's for the same load, ring
  weight included, built independently from the spec's geometry (1e-9 relative); the dynamic factor of a load
  applied at once is 2 without clearance and 1 + sqrt(1 + 2h/δ) with a drop h (the linear drop formula).
"""

import logging
import math

import numpy as np
import pytest

from bearing_mbs.numerics.advisor import (
    Advice,
    BearingLayout,
    advise,
    axis_limits,
    mode_limit,
    stability_polynomial,
    step_warning,
)
from bearing_mbs.models import build_scene
from cases import SCENARIOS, seed_spec
from bearing_mbs.contact.friction import ZERO_SLIP_SLOPE
from bearing_mbs.engines import simulate
from bearing_mbs.runner import simulate_advised
from bearing_mbs.engines.reference.tableaus import DOPRI5, RK4
from bearing_mbs.models.cylindrical_roller.geometry import BearingGeometry
from bearing_mbs.models.cylindrical_roller.quasistatic import solve_radial
from bearing_mbs.core.scene import GROUND, Body, ContactPair, PairLaw, Scene
from bearing_mbs.spec import ExudynSolver, ReferenceSolver, SolverSpec
from bearing_mbs.models import load_spec

NOMINAL = SCENARIOS / "seed_hss_steady.toml"


def nominal(*overrides):
    spec = load_spec(NOMINAL, list(overrides))
    return spec, build_scene(spec)


def test_stability_polynomials_are_the_exponential_series():
    taylor = [1 / math.factorial(k) for k in range(5)]
    assert np.allclose(stability_polynomial(RK4.a, RK4.b), taylor, rtol=0, atol=1e-15)
    dopri = stability_polynomial(DOPRI5.a, DOPRI5.b)
    assert np.allclose(dopri[:6], [1 / math.factorial(k) for k in range(6)], rtol=0, atol=1e-15)
    assert dopri[6] == pytest.approx(1 / 600, rel=1e-12)


@pytest.mark.parametrize("method, real, imaginary", [
    ("reference/rk4", 2.785293563, 2 * math.sqrt(2)),
    ("exudyn/rk44", 2.785293563, 2 * math.sqrt(2)),
    ("reference/dopri5", 3.306567893, None),
    ("reference/central_difference", 2.0, 2.0),
    ("reference/velocity_verlet", 1.0, 2.0),
])
def test_stability_region_boundaries(method, real, imaginary):
    limits = axis_limits(method)
    assert limits["real"] == pytest.approx(real, rel=1e-6)
    if imaginary is not None:
        assert limits["imaginary"] == pytest.approx(imaginary, rel=1e-6)


MASS, RADIUS, STIFFNESS, G, MU, V_REG = 0.1, 0.01, 1e7, 10.0, 0.5, 1e-3
INERTIA = 0.4 * MASS * RADIUS**2
#: Friction decay rate of the sliding ball: μ Q φ'(0) (1/m + r²/I), Q = m g, φ'(0) = 1/v_reg (linear law).
BALL_RATE = MU * MASS * G * ZERO_SLIP_SLOPE["linear"] / V_REG * (1 / MASS + RADIUS**2 / INERTIA)


def sliding_ball(method, step, steps=400):
    """A ball (0.1 kg, r = 10 mm) resting on the floor at its static penetration, sliding at 5 % of v_reg, no spin.

    Friction: saturated linear, μ = 0.5, v_reg = 1 mm/s; normal law: the plain power law K δ^1.5 (undamped; its
    oscillation limit is 20 times above the friction one). Returns the final |slip| over the initial one.

    One output at the end: the engine evaluates the forces afresh at the start of each output chunk, which would
    interrupt velocity Verlet's reuse of its predicted-velocity acceleration (see docs/numerics.md).
    """
    law = PairLaw("power", STIFFNESS, 1.5, 1.0, 0.0, 1e-3, "linear", MU, V_REG)
    penetration = (MASS * G / STIFFNESS) ** (1 / 1.5)
    ball = Body("ball", MASS, INERTIA, (0.0, RADIUS - penetration, 0.0), (0.05 * V_REG, 0.0, 0.0))
    floor = ContactPair("ball-floor", "circle_line", GROUND, 0, law, radius_b=RADIUS)
    scene = Scene("sliding_ball", (ball,), (floor,), gravity=(0.0, -G))
    end = steps * step
    solver = SolverSpec(engine="reference", output_interval=end, reference=ReferenceSolver(method=method, step=step))
    result = simulate(scene, solver, end)
    assert result.success, result.message
    slip = result.pair_series("slip")[:, 0]
    return abs(slip[-1] / slip[0])


@pytest.mark.parametrize("method", ["central_difference", "velocity_verlet", "rk4"])
def test_advised_friction_limit_separates_decay_from_growth_in_the_engine(method):
    limit = mode_limit(f"reference/{method}", 0.0, -BALL_RATE)
    below, above = sliding_ball(method, 0.85 * limit), sliding_ball(method, 1.2 * limit)
    assert below < 1e-6, f"{method}: slip not damped at 0.85 x the advised limit {limit:.3g} s: {below:.3g}"
    assert above > 1e-2, f"{method}: slip damped at 1.2 x the advised limit {limit:.3g} s: {above:.3g}"


def test_friction_mode_of_a_solid_roller_under_equal_loads():
    spec, scene = nominal("contact.inner_race.rolling_resistance_arm=0", "contact.outer_race.rolling_resistance_arm=0")
    layout = BearingLayout.of(scene)
    load = 10e3
    friction = [m for m in layout.roller_modes("test", load, load) if m.name.startswith("friction")][0]
    law = spec.contact.inner_race
    coefficient = law.friction_coefficient * load * ZERO_SLIP_SLOPE[law.friction_law] / law.regularisation_speed
    assert layout.roller_inertia == pytest.approx(layout.roller_mass * layout.roller_radius**2 / 2, rel=1e-12)
    assert -friction.beta == pytest.approx(4 * coefficient / layout.roller_mass, rel=1e-12)


def test_operating_point_is_the_quasi_static_solution_and_a_sudden_load_doubles():
    spec, scene = nominal()
    point = advise(scene).operating_point
    geometry = BearingGeometry.from_spec(spec.bearing)
    weight = geometry.inner_ring_mass * spec.scenario.gravity
    speed = spec.drive.speed_rpm * 2 * math.pi / 60
    static = solve_radial(geometry.roller_set(), (0.0, -spec.load.radial - weight), shaft_speed=speed)
    assert point["max_roller_load"] == pytest.approx(static.max_roller_load, rel=1e-9)
    assert point["load_factor"] == pytest.approx(2.0, rel=1e-9)  # zero clearance: no drop
    peak = solve_radial(geometry.roller_set(), (0.0, -2 * (spec.load.radial + weight)), shaft_speed=speed)
    assert point["peak_roller_load"] == pytest.approx(peak.max_roller_load, rel=1e-9)


def test_clearance_adds_the_drop_to_the_dynamic_factor():
    spec, scene = nominal("bearing.pitch_diameter=0.235", "bearing.diametral_clearance=2e-4")
    point = advise(scene).operating_point
    geometry = BearingGeometry.from_spec(spec.bearing)
    weight = geometry.inner_ring_mass * spec.scenario.gravity
    static = solve_radial(geometry.roller_set(), (0.0, -spec.load.radial - weight),
                          shaft_speed=spec.drive.speed_rpm * 2 * math.pi / 60)
    drop = 1e-4  # half the diametral clearance
    elastic = float(np.hypot(*static.displacement)) - drop
    assert point["load_factor"] == pytest.approx(1 + math.sqrt(1 + 2 * drop / elastic), rel=1e-9)
    assert point["load_factor"] > 3


def test_seed_bearing_advice_is_friction_limited():
    """EXUDYN_NOTES.md: friction, not the Hertz stiffness, limits explicit steps on the seed bearing."""
    _, scene = nominal()
    advice = advise(scene)
    limit, mode = advice.limit_and_mode("reference", "rk4")
    assert mode.startswith("friction, loaded roller")
    assert 1e-7 < limit < 3e-7  # measured: RK4 passes at 1.74e-7 s and fails at 2.46e-7 s (docs/numerics.md)
    assert advice.limit("exudyn", "rk44") == pytest.approx(limit, rel=1e-12)  # the same tableau
    assert advice.limit("exudyn", "generalized_alpha") == math.inf
    assert advice.limit("exudyn", "velocity_verlet") is None
    assert advice.recommended("reference", "rk4") <= 0.5 * limit
    assert advise(scene) is advice  # cached per scene


def test_step_warning_only_above_the_limit_and_only_for_fixed_explicit_steps():
    _, scene = nominal()
    rk4 = lambda step: SolverSpec(engine="reference", reference=ReferenceSolver(method="rk4", step=step))
    message = step_warning(scene, rk4(5e-7))
    assert message is not None and "5e-07 s exceeds" in message and "friction" in message and "advise" in message
    assert step_warning(scene, rk4(1e-7)) is None
    assert step_warning(scene, SolverSpec(engine="exudyn", exudyn=ExudynSolver(step=1e-4))) is None  # implicit
    assert step_warning(scene, SolverSpec(reference=ReferenceSolver(method="dopri5", step=1e-3))) is None
    balls = build_scene(seed_spec(2))
    assert not advise(balls).applies and step_warning(balls, rk4(1e-3)) is None


def test_simulate_logs_and_records_the_warning(caplog):
    _, scene = nominal()
    solver = SolverSpec(engine="reference", output_interval=1e-5, reference=ReferenceSolver(method="rk4", step=5e-7))
    with caplog.at_level(logging.WARNING, logger="bearing_mbs.runner"):
        result = simulate_advised(scene, solver, 1e-5)
    assert result.success
    assert len(result.metadata["warnings"]) == 1 and "exceeds the advised stability limit" in caplog.text
    quiet = SolverSpec(engine="reference", output_interval=1e-5, reference=ReferenceSolver(method="rk4", step=1e-7))
    assert "warnings" not in simulate_advised(scene, quiet, 1e-5).metadata


def test_advise_command_prints_the_limits(capsys):
    from bearing_mbs.cli import main

    assert main(["advise", str(NOMINAL), "--engine", "reference"]) == 0
    out = capsys.readouterr().out
    assert "reference/rk4" in out and "friction, loaded roller" in out and "within the advice" in out
    assert main(["advise", str(SCENARIOS / "seed_case2.toml")]) == 0
    assert "no advice" in capsys.readouterr().out


def test_an_advice_without_a_model_has_no_limits():
    assert Advice(False, "not a bearing").limit("reference", "rk4") is None
