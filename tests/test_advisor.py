"""The step advisor: stability regions, the bearing's linearised modes, and the warning.

Every expected value below comes from a source independent of the code under test; each test names it and the
tolerance, chosen so that a wrong answer fails:

* stability polynomials: a Runge–Kutta method of order p with s = p stages (p <= 4) has R(z) = Σ_{k<=p} z^k/k!, and
  any method of order p has those first p + 1 coefficients (E. Hairer, G. Wanner, Solving Ordinary Differential
  Equations II, 2nd ed., Springer 1996, §IV.2); DOPRI5's z⁶ coefficient is 1/600 (ibid., §IV.2, and Hairer,
  Nørsett & Wanner, Solving ODEs I, §II.5). Exact up to round-off: 1e-14;
* region boundaries on the axes, from those polynomials alone: RK4 reaches 2.7853 on the negative real axis
  (the real root of x³ − 4x² + 12x − 24 = 0, i.e. R(−x) = 1) and 2√2 on the imaginary axis
  (|R(iy)|² = 1 − y⁶/72 + y⁸/576); DOPRI5 3.3066 (the values 2.785 and 3.307 of Hairer & Wanner II, §IV.2). The
  boundaries are found by a search: relative tolerance 1e-6;
* the undamped oscillator q̈ = −ω²q: explicit Euler is unstable at every step (|1 + ihω| > 1), the central
  difference and velocity Verlet are stable for hω < 2 (E. Hairer, C. Lubich, G. Wanner, Geometric Numerical
  Integration, 2nd ed., Springer 2006, §I.5: the Störmer–Verlet scheme on the harmonic oscillator);
* a pure decay v̇ = −λv: the central difference is v⁺ = (1 − hλ)v, stable for hλ < 2; the reference engine's
  velocity Verlet (forces at the predicted velocity) has the amplification matrix of characteristic polynomial
  μ² − (1 − 3x/2)μ − x/2 (x = hλ), whose root −1 appears at x = 1 (Jury's criterion |T| <= 1 + D,
  E. I. Jury, Theory and Application of the z-Transform Method, Wiley 1964);
* the engine itself: a ball pressed on the floor and sliding, whose slip decays at λ = μ Q φ'(0) (1/m + r²/I) in
  the linear range of the friction law (slip v − rω, d/dt of it = −F (1/m + r²/I)). Every reference integrator at
  0.85 × its advised limit damps the slip by 10⁶ in 400 steps; at 1.2 × the limit the slip is not damped even by
  100;
* the bearing's friction mode for equal raceway loads and a solid roller (I = m r²/2): the 2×2 eigenproblem
  M⁻¹C with C = c diag(2, 2r²) has the eigenvalues 2c/m and 4c/m; the erf law F = μ F_N erf(2v/v_reg) (the primary
  document's annex II) has the slope μ F_N · 4/(√π v_reg) at zero slip (erf'(0) = 2/√π, Abramowitz & Stegun
  7.1.1). Exact up to round-off: 1e-12;
* the operating point: the advisor's static roller load equals the quasi-static solver's for the same load, ring
  weight included, with the rollers built from the spec (1e-9 relative); a load applied at once on a linear spring
  peaks at twice its static value, and after a free drop h at 1 + sqrt(1 + 2h/δ_s) times (W. C. Young,
  R. G. Budynas, Roark's Formulas for Stress and Strain, 7th ed., §16.3), to 1e-9 relative.
"""

import math

import numpy as np
import pytest

from bearing_mbs.core.scene import GROUND, Body, ContactPair, PairLaw, Scene
from bearing_mbs.engines import simulate
from bearing_mbs.engines.reference.tableaus import DOPRI5, RK4
from bearing_mbs.models import build_scene, load_spec
from bearing_mbs.models.cylindrical_roller.geometry import BearingGeometry
from bearing_mbs.models.cylindrical_roller.linearise import BearingLayout, roller_modes
from bearing_mbs.models.cylindrical_roller.quasistatic import RollerSet, solve_radial
from bearing_mbs.numerics.advisor import Advice, advise, step_warning
from bearing_mbs.numerics.stability_regions import RK_TABLEAUS, axis_limits, mode_limit, stability_polynomial
from bearing_mbs.runner import simulate_advised
from bearing_mbs.spec import ExudynSolver, ReferenceSolver, SolverSpec

from cases import SCENARIOS, seed_spec

NOMINAL = SCENARIOS / "seed_hss_steady.toml"
RPM = 2 * math.pi / 60  # rad/s in one revolution per minute


def nominal(*overrides):
    """The seed bearing's dry model (its scenario's variant "dry") at the nominal load."""
    spec = load_spec(NOMINAL, ["scenario.variant=dry", *overrides])
    return spec, build_scene(spec)


def taylor(order: int) -> list[float]:
    """The coefficients 1/k! of exp(z) up to z^order."""
    return [1 / math.factorial(k) for k in range(order + 1)]


def test_stability_polynomials_are_the_exponential_series():
    assert np.allclose(stability_polynomial(RK4.a, RK4.b), taylor(4), rtol=0, atol=1e-14)
    dopri = stability_polynomial(DOPRI5.a, DOPRI5.b)
    assert np.allclose(dopri[:6], taylor(5), rtol=0, atol=1e-14)
    assert dopri[6] == pytest.approx(1 / 600, rel=1e-12)


@pytest.mark.parametrize("method, order", [
    ("exudyn/explicit_euler", 1), ("exudyn/explicit_midpoint", 2), ("exudyn/rk33", 3), ("exudyn/rk4", 4),
    ("exudyn/ode23", 3), ("exudyn/rk67", 6), ("exudyn/dopri5", 5),
])
def test_exudyn_tableaus_have_the_polynomial_of_their_order(method, order):
    """Order p: the first p + 1 coefficients are 1/k!; the methods with s = p stages (p <= 4, and ODE23 whose
    fourth stage has weight 0) have no more."""
    coefficients = stability_polynomial(*RK_TABLEAUS[method])
    assert np.allclose(coefficients[: order + 1], taylor(order), rtol=0, atol=1e-14)
    if order <= 4:
        assert np.allclose(coefficients[order + 1 :], 0.0, rtol=0, atol=1e-14)


def real_axis_limit(coefficients) -> float:
    """The smallest x > 0 with |R(−x)| = 1 for R(z) = Σ c_k z^k, from the polynomial alone (numpy roots)."""
    polynomial = np.polynomial.Polynomial(coefficients)(np.polynomial.Polynomial([0.0, -1.0]))
    roots = [r.real for sign in (1.0, -1.0) for r in (polynomial - sign).roots()
             if abs(r.imag) < 1e-9 and r.real > 1e-9]
    return min(roots)


#: RK4's axis limits in closed form: x³ − 4x² + 12x − 24 = 0 on the real axis, y = 2√2 on the imaginary axis.
RK4_REAL = max(r.real for r in np.roots([1.0, -4.0, 12.0, -24.0]) if abs(r.imag) < 1e-12)
DOPRI5_REAL = real_axis_limit(taylor(5) + [1 / 600])


def test_closed_forms_of_the_axis_limits_are_the_published_values():
    """The independent references themselves, against the values printed by Hairer & Wanner (4 digits)."""
    assert RK4_REAL == pytest.approx(2.785, abs=5e-4)
    assert DOPRI5_REAL == pytest.approx(3.307, abs=5e-4)
    assert real_axis_limit(taylor(4)) == pytest.approx(RK4_REAL, rel=1e-12)


@pytest.mark.parametrize("method, real, imaginary", [
    ("reference/rk4", RK4_REAL, 2 * math.sqrt(2)),
    ("exudyn/rk4", RK4_REAL, 2 * math.sqrt(2)),
    ("reference/dopri5", DOPRI5_REAL, None),
    ("reference/central_difference", 2.0, 2.0),
    ("reference/velocity_verlet", 1.0, 2.0),
])
def test_stability_region_boundaries(method, real, imaginary):
    limits = axis_limits(method)
    assert limits["real"] == pytest.approx(real, rel=1e-6)
    if imaginary is not None:
        assert limits["imaginary"] == pytest.approx(imaginary, rel=1e-6)


def test_mass_spring_limits_are_the_closed_forms():
    """m = 2 kg on k = 8e6 N/m: ω = sqrt(k/m) = 2000 rad/s. Central difference and RK4 at h = 2/ω and 2√2/ω
    (1e-6 relative); explicit Euler has no stable step (limit 0)."""
    mass, stiffness = 2.0, 8e6
    omega = math.sqrt(stiffness / mass)
    alpha = -stiffness / mass
    assert mode_limit("reference/central_difference", alpha, 0.0) == pytest.approx(2 / omega, rel=1e-6)
    assert mode_limit("reference/velocity_verlet", alpha, 0.0) == pytest.approx(2 / omega, rel=1e-6)
    assert mode_limit("reference/rk4", alpha, 0.0) == pytest.approx(2 * math.sqrt(2) / omega, rel=1e-6)
    assert mode_limit("exudyn/explicit_euler", alpha, 0.0) == 0.0


MASS, RADIUS, STIFFNESS, G, MU, V_REG = 0.1, 0.01, 1e7, 10.0, 0.5, 1e-3
INERTIA = 0.4 * MASS * RADIUS**2
#: Friction decay rate of the sliding ball [1/s]: μ Q φ'(0) (1/m + r²/I), Q = m g, φ'(0) = 1/v_reg (linear law).
BALL_RATE = MU * MASS * G / V_REG * (1 / MASS + RADIUS**2 / INERTIA)


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
    spec, scene = nominal("contact.inner_race.rolling_resistance_arm=0", "contact.outer_race.rolling_resistance_arm=0",
                          "lubricant.model=none")
    law = spec.contact.inner_race
    assert law.friction_law == "erf" and spec.contact.outer_race == law
    layout = BearingLayout.of(scene)
    geometry = BearingGeometry.from_spec(spec.bearing)
    mass, radius = geometry.roller_mass, geometry.roller_diameter / 2
    assert layout.roller_inertia == pytest.approx(mass * radius**2 / 2, rel=1e-12)  # a solid cylinder
    load = 10e3
    friction = [m for m in roller_modes(layout, "test", load, load) if m.name.startswith("friction")][0]
    coefficient = law.friction_coefficient * load * 4 / (math.sqrt(math.pi) * law.regularisation_speed)
    assert -friction.beta == pytest.approx(4 * coefficient / mass, rel=1e-12)


def spec_rollers(spec) -> RollerSet:
    """The quasi-static rollers from the spec's numbers (Palmgren's laws: the scenario's raceways are steel)."""
    bearing = spec.bearing
    return RollerSet(rollers=bearing.rollers, pitch_diameter=bearing.pitch, roller_diameter=bearing.roller_diameter,
                     roller_length=bearing.roller_length, diametral_clearance=bearing.clearance,
                     roller_mass=BearingGeometry.from_spec(bearing).roller_mass)


def test_operating_point_is_the_quasi_static_solution_and_a_sudden_load_doubles():
    spec, scene = nominal()
    point = advise(scene).operating_point
    weight = BearingGeometry.from_spec(spec.bearing).inner_ring_mass * spec.scenario.gravity
    speed = spec.drive.speed_rpm * RPM
    assert spec.load.angle == -90.0 and abs(spec.bearing.clearance) < 1e-12  # zero up to round-off
    static = solve_radial(spec_rollers(spec), (0.0, -spec.load.radial - weight), shaft_speed=speed)
    assert point["max_roller_load"] == pytest.approx(static.max_roller_load, rel=1e-9)
    assert point["load_factor"] == pytest.approx(2.0, rel=1e-9)  # zero clearance: no drop
    peak = solve_radial(spec_rollers(spec), (0.0, -2 * (spec.load.radial + weight)), shaft_speed=speed)
    assert point["peak_roller_load"] == pytest.approx(peak.max_roller_load, rel=1e-9)


def test_clearance_adds_the_drop_to_the_dynamic_factor():
    spec, scene = nominal("bearing.pitch_diameter=0.235", "bearing.diametral_clearance=2e-4")
    point = advise(scene).operating_point
    weight = BearingGeometry.from_spec(spec.bearing).inner_ring_mass * spec.scenario.gravity
    static = solve_radial(spec_rollers(spec), (0.0, -spec.load.radial - weight), shaft_speed=spec.drive.speed_rpm * RPM)
    drop = 1e-4  # the ring falls through half the diametral clearance
    elastic = float(np.hypot(*static.displacement)) - drop
    assert point["load_factor"] == pytest.approx(1 + math.sqrt(1 + 2 * drop / elastic), rel=1e-9)
    assert point["load_factor"] > 3


def test_seed_bearing_advice_is_friction_limited():
    """Friction, not the contact stiffness, limits explicit steps on the seed bearing (docs/numerics.md)."""
    _, scene = nominal()
    advice = advise(scene)
    limit, mode = advice.limit_and_mode("reference", "rk4")
    assert mode.startswith("friction, loaded roller")
    assert 1e-7 < limit < 3e-7  # measured: RK4 passes at 1.74e-7 s and fails at 2.46e-7 s (docs/numerics.md)
    assert advice.limit("exudyn", "rk4") == pytest.approx(limit, rel=1e-12)  # the same tableau
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
    import logging

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

    assert main(["advise", str(NOMINAL), "--engine", "reference", "--set", "scenario.variant=dry"]) == 0
    out = capsys.readouterr().out
    assert "reference/rk4" in out and "friction, loaded roller" in out and "within the advice" in out
    assert main(["advise", str(SCENARIOS / "seed_case2.toml")]) == 0
    assert "no advice" in capsys.readouterr().out


def test_an_advice_without_a_model_has_no_limits():
    assert Advice(False, "not a bearing").limit("reference", "rk4") is None
