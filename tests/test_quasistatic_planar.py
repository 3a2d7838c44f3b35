"""Planar quasi-static model: roller loads, loaded zone and 2×2 stiffness of a radial cylindrical roller bearing.

References and tolerances, per test:
* Stribeck / Harris & Kotzalas (2006, ch. 7): at zero clearance Z·Q_max/F_r → 1/J_r(ε = 0.5) ≈ 4.08 for
  line contact; J_r(ε) = (1/2π)∫(1 − (1 − cos ψ)/(2ε))ⁿ cos ψ dψ over the loaded zone is computed here by
  scipy ``quad`` (n = 10/9). Tolerance 1 % for Z ≥ 18, as the brief asks.
* With clearance, ε = (1 − P_d/(2δ_r))/2 and Z·Q_max/F_r = 1/J_r(ε) up to the finite-Z quadrature error of
  the rollers' sum. For rigid rollers on their radial lines the sum (1/Z)Σ(1 − (1 − cos ψ_j)/(2ε))₊ⁿ cos ψ_j
  is the model's exact answer (checked to 1e-8), and it is the rectangle rule of J_r, whose error with an
  s^(10/9) edge decays like Z^(−19/9): at Z = 30 and ε in [0.2, 0.45] it is below 1.5 % (the same sum, with
  the rollers at any phase, never exceeds 1.3 % there), the tolerance used.
* Analytic Jacobians against central differences (truncation O(h²), 1e-6 relative).
* Series law (Harris ch. 7): independent closed forms, 1e-12 relative.
* Centrifugal force and cage speed (Harris ch. 10) recomputed from the inputs, 1e-12 relative.
"""

import math

import numpy as np
import pytest
from scipy.integrate import quad

from bearing_mbs.contact.line_contact import palmgren_stiffness, series_stiffness
from bearing_mbs.models.cylindrical_roller.quasistatic import (
    ConvergenceError,
    NewtonSettings,
    RollerSet,
    plot_load_distribution,
    radial_roller_equilibrium,
    radial_state,
    solve_radial,
)
from bearing_mbs.spec.fields import SpecError

N_EXP = 10 / 9
PITCH, DIAMETER, LENGTH = 0.235, 0.025, 0.055  # a coherent version of the primary document's bearing


def bearing(rollers=15, **changes):
    diameter = changes.pop("roller_diameter", min(DIAMETER, 0.8 * PITCH * math.sin(math.pi / rollers)))
    return RollerSet(rollers, PITCH, diameter, LENGTH, **changes)


def harris_integral(eps, n=N_EXP):
    """J_r(ε) by adaptive quadrature over the loaded zone |ψ| < ψ_l, cos ψ_l = 1 − 2ε."""
    limit = math.acos(1 - 2 * eps) if eps < 1 else math.pi
    integrand = lambda psi: (1 - (1 - math.cos(psi)) / (2 * eps)) ** n * math.cos(psi)
    return quad(integrand, -limit, limit, epsabs=0, epsrel=1e-12, limit=200)[0] / (2 * math.pi)


def finite_difference_jacobian(function, point, steps):
    columns = []
    for i, step in enumerate(steps):
        delta = np.zeros_like(point)
        delta[i] = step
        columns.append((function(point + delta) - function(point - delta)) / (2 * step))
    return np.stack(columns, axis=1)


# --- bad input -----------------------------------------------------------------------------------------------


@pytest.mark.parametrize(
    "arguments, field",
    [
        (dict(rollers=2), "rollers"),
        (dict(rollers=15.0), "rollers"),
        (dict(pitch_diameter=0.0), "pitch_diameter"),
        (dict(roller_diameter=-0.02), "roller_diameter"),
        (dict(roller_length=0.0), "roller_length"),
        (dict(rollers=30, roller_diameter=PITCH * math.pi / 30), "roller_diameter"),
        (dict(diametral_clearance=-0.01 * DIAMETER), "diametral_clearance"),
        (dict(diametral_clearance=0.1 * DIAMETER), "diametral_clearance"),
        (dict(roller_mass=-1.0), "roller_mass"),
        (dict(inner_exponent=1.5), "inner_exponent"),
        (dict(outer_stiffness=1e9, outer_exponent=0.5), "outer_exponent"),
        (dict(inner_stiffness=-1e9), "inner_stiffness"),
        (dict(first_roller_angle=math.nan), "first_roller_angle"),
    ],
)
def test_bad_roller_set_names_field_value_and_allowed_range(arguments, field):
    values = dict(rollers=15, pitch_diameter=PITCH, roller_diameter=DIAMETER, roller_length=LENGTH)
    values.update(arguments)
    with pytest.raises(SpecError) as info:
        RollerSet(**values)
    error = info.value
    assert error.field == field
    assert error.value == arguments[field] or (math.isnan(arguments[field]) and math.isnan(error.value))
    assert error.allowed  # says what is allowed
    # the message shows the field, the value and what is allowed, whatever its wording
    assert all(str(part) in str(error) for part in (error.field, error.value, error.allowed))


@pytest.mark.parametrize("bound", [-0.002 * DIAMETER, 0.05 * DIAMETER])
def test_clearance_bounds_are_the_documented_ones(bound):
    """P_d in [−0.002 D_w, 0.05 D_w] (RollerSet's docstring, the limits of the bearing spec): accepted on the
    bound, rejected just beyond it."""
    RollerSet(15, PITCH, DIAMETER, LENGTH, diametral_clearance=bound)
    beyond = bound * (1 + 1e-6)
    with pytest.raises(SpecError) as info:
        RollerSet(15, PITCH, DIAMETER, LENGTH, diametral_clearance=beyond)
    assert info.value.field == "diametral_clearance" and info.value.value == beyond


def test_rollers_that_overlap_on_the_pitch_circle_are_rejected_even_below_z_dw_equal_pi_dpw():
    """Z·D_w < π·D_pw is necessary but not sufficient: the chord D_pw sin(π/Z) must exceed D_w."""
    rollers = 12
    diameter = 0.999 * PITCH * math.pi / rollers
    assert rollers * diameter < math.pi * PITCH
    with pytest.raises(SpecError) as info:
        RollerSet(rollers, PITCH, diameter, LENGTH)
    assert info.value.field == "roller_diameter" and info.value.value == diameter
    # and just below the chord the same rollers fit
    RollerSet(rollers, PITCH, 0.999 * PITCH * math.sin(math.pi / rollers), LENGTH)


@pytest.mark.parametrize(
    "arguments, field",
    [
        (dict(tolerance=0.0), "tolerance"),
        (dict(max_iterations=0), "max_iterations"),
        (dict(roller_tolerance=1e-3), "roller_tolerance"),
        (dict(roller_max_iterations=2.5), "roller_max_iterations"),
    ],
)
def test_bad_newton_settings_name_the_field(arguments, field):
    with pytest.raises(SpecError) as info:
        NewtonSettings(**arguments)
    assert info.value.field == field


@pytest.mark.parametrize("clearance", [0.0, 2e-5])
def test_zero_load_without_preload_is_rejected_with_the_reason(clearance):
    with pytest.raises(SpecError) as info:
        solve_radial(bearing(diametral_clearance=clearance), (0.0, 0.0))
    assert info.value.field == "load" and tuple(info.value.value) == (0.0, 0.0)


@pytest.mark.parametrize(
    "load, shaft_speed, field",
    [
        ((1.0,), 0.0, "load"),
        ((math.nan, 1.0), 0.0, "load"),
        ("heavy", 0.0, "load"),
        ((1e3, 0.0), math.inf, "shaft_speed"),
    ],
)
def test_bad_load_or_speed_names_the_field(load, shaft_speed, field):
    with pytest.raises(SpecError) as info:
        solve_radial(bearing(), load, shaft_speed=shaft_speed)
    assert info.value.field == field


def test_newton_that_does_not_converge_reports_residual_and_iterations():
    with pytest.raises(ConvergenceError) as info:
        solve_radial(bearing(diametral_clearance=3e-5), (3e3, 4e3), settings=NewtonSettings(max_iterations=1))
    error = info.value
    assert isinstance(error, SpecError)  # bad settings for this load: the same kind as bad input
    assert error.field == "max_iterations" and error.value == 1 and error.iterations == 1
    assert math.isfinite(error.residual) and error.residual > 0.0 and error.tolerance > 0.0


def test_roller_newton_that_does_not_converge_names_its_limit():
    settings = NewtonSettings(roller_max_iterations=1)
    with pytest.raises(ConvergenceError) as info:
        radial_roller_equilibrium(np.array([1e-5, 2e-5]), 500.0, bearing(), settings)
    assert info.value.field == "roller_max_iterations" and info.value.value == 1 and info.value.iterations == 1


# --- per-roller equilibrium and series contacts -------------------------------------------------------------


def test_roller_condensed_stiffness_matches_central_differences():
    rollers = bearing(inner_stiffness=4e9, outer_stiffness=9e9, outer_exponent=1.3)
    approaches = np.array([-2e-6, 1e-7, 3e-6, 1.5e-5, 4e-5])
    for centrifugal in (0.0, 800.0):
        eq = radial_roller_equilibrium(approaches, centrifugal, rollers)
        h = 1e-6 * np.abs(approaches)
        plus = radial_roller_equilibrium(approaches + h, centrifugal, rollers).inner_load
        minus = radial_roller_equilibrium(approaches - h, centrifugal, rollers).inner_load
        numeric = (plus - minus) / (2 * h)
        assert np.allclose(eq.stiffness, numeric, rtol=1e-6, atol=1e-6 * eq.stiffness.max())
        assert np.allclose(eq.outer_load - eq.inner_load, centrifugal, rtol=0, atol=1e-12 * eq.outer_load.max())


def test_equal_laws_split_the_total_approach_in_halves():
    rollers = bearing(diametral_clearance=1e-5)
    state = radial_state(rollers, (2e-5, 1e-5))
    loaded = state.loaded
    assert loaded.sum() >= 3
    total = state.inner_approaches + state.outer_approaches
    assert np.allclose(state.inner_approaches[loaded], total[loaded] / 2, rtol=1e-12)
    assert np.allclose(state.outer_approaches[loaded], total[loaded] / 2, rtol=1e-12)


@pytest.mark.parametrize("ratio", [1.0, 2.5])
def test_series_formula_equals_the_newton_condensed_chain(ratio):
    inner = palmgren_stiffness(LENGTH)
    rollers = bearing(inner_stiffness=inner, outer_stiffness=ratio * inner)
    equivalent = series_stiffness(inner, ratio * inner, N_EXP)
    approaches = np.array([1e-7, 5e-6, 3e-5])
    eq = radial_roller_equilibrium(approaches, 0.0, rollers)
    assert np.allclose(eq.inner_load, equivalent * approaches**N_EXP, rtol=1e-12)
    assert np.allclose(eq.stiffness, N_EXP * equivalent * approaches ** (N_EXP - 1), rtol=1e-12)


# --- inner-ring equilibrium ----------------------------------------------------------------------------------


@pytest.mark.parametrize(
    "changes, displacement, shaft_speed",
    [
        (dict(), (1.2e-5, -4e-6), 0.0),
        (dict(diametral_clearance=2e-5), (1.5e-5, 1.1e-5), 300.0),
        (
            dict(diametral_clearance=-8e-6, outer_stiffness=9e9, outer_exponent=1.3, inner_stiffness=5e9),
            (3e-6, 1e-6),
            500.0,
        ),
    ],
)
def test_stiffness_matrix_matches_central_differences(changes, displacement, shaft_speed):
    rollers = bearing(**changes)
    point = np.array(displacement)
    state = radial_state(rollers, point, shaft_speed=shaft_speed)
    numeric = finite_difference_jacobian(
        lambda u: radial_state(rollers, u, shaft_speed=shaft_speed).load, point, [1e-6 * np.linalg.norm(point)] * 2
    )
    assert np.linalg.norm(numeric - state.stiffness) <= 1e-6 * np.linalg.norm(state.stiffness)
    assert np.array_equal(state.stiffness, state.stiffness.T)
    assert np.linalg.eigvalsh(state.stiffness).min() >= 0.0


@pytest.mark.parametrize("rollers", [12, 18, 24, 30, 60])
def test_zero_clearance_max_roller_load_tends_to_stribeck_line_contact_value(rollers):
    expected = 1.0 / harris_integral(0.5)
    assert expected == pytest.approx(4.08, abs=0.01)
    load = 1e4
    solution = solve_radial(bearing(rollers), (load, 0.0))
    ratio = solution.max_roller_load * rollers / load
    if rollers >= 18:
        assert ratio == pytest.approx(expected, rel=1e-2), f"Z = {rollers}: Z·Qmax/Fr = {ratio:.4f}"
    assert ratio == pytest.approx(expected, rel=2e-2), f"Z = {rollers}: Z·Qmax/Fr = {ratio:.4f}"
    assert np.linalg.norm(solution.load - (load, 0.0)) <= 1e-9 * load


@pytest.mark.parametrize("rollers, load_angle", [(20, 0.0), (20, 0.7), (15, -2.0)])
def test_zero_clearance_loaded_zone_is_plus_minus_90_degrees(rollers, load_angle):
    load = 5e3 * np.array([math.cos(load_angle), math.sin(load_angle)])
    solution = solve_radial(bearing(rollers), load)
    assert solution.loaded_zone_half_angle == pytest.approx(math.pi / 2, abs=1e-12)
    direction = np.arctan2(solution.displacement[1], solution.displacement[0])
    offset = np.abs(np.angle(np.exp(1j * (solution.roller_angles - direction))))
    inside, outside = offset < math.pi / 2 - 1e-9, offset > math.pi / 2 + 1e-9
    assert np.all(solution.inner_loads[inside] > 0.0)
    assert np.all(solution.inner_loads[outside] == 0.0)
    assert np.all(solution.inner_loads[~inside & ~outside] <= 1e-12 * solution.max_roller_load)


@pytest.mark.parametrize("eps", [0.2, 0.3, 0.4, 0.45])
def test_clearance_raises_max_load_as_harris_integral_says(eps):
    rollers_count, clearance = 30, 4e-5
    rollers = bearing(rollers_count, diametral_clearance=clearance)
    equivalent = series_stiffness(rollers.inner_stiffness, rollers.outer_stiffness, N_EXP)
    radial = clearance / (2 * (1 - 2 * eps))  # δ_r for this ε
    load = rollers_count * equivalent * (radial - clearance / 2) ** N_EXP * harris_integral(eps)
    solution = solve_radial(rollers, (load, 0.0))
    measured = 0.5 * (1 - clearance / (2 * solution.displacement[0]))
    ratio = solution.max_roller_load * rollers_count / load
    angles = solution.roller_angles
    finite_sum = np.sum(np.clip(1 - (1 - np.cos(angles)) / (2 * measured), 0, None) ** N_EXP * np.cos(angles))
    assert ratio == pytest.approx(rollers_count / finite_sum, rel=1e-8)
    assert ratio == pytest.approx(1 / harris_integral(measured), rel=1.5e-2), f"ε = {measured:.3f}"
    assert ratio > 1 / harris_integral(0.5)
    assert solution.loaded_zone_half_angle == pytest.approx(math.acos(1 - 2 * measured), rel=1e-9)


def test_max_load_grows_monotonically_with_clearance():
    ratios = [
        solve_radial(bearing(30, diametral_clearance=c), (1e4, 0.0)).max_roller_load * 30 / 1e4
        for c in (0.0, 1e-5, 3e-5, 6e-5)
    ]
    assert np.all(np.diff(ratios) > 0), ratios


def test_centrifugal_force_loads_outer_contacts_by_m_r_d_pw_omega_c_squared():
    rollers = bearing(roller_mass=0.2, diametral_clearance=1e-5)
    speed = 400.0
    cage = 0.5 * speed * (1 - rollers.roller_diameter / PITCH)
    expected = 0.2 * PITCH / 2 * cage**2
    solution = solve_radial(rollers, (2e3, 7e3), shaft_speed=speed)
    assert solution.centrifugal_force == pytest.approx(expected, rel=1e-12)
    assert np.allclose(solution.outer_loads - solution.inner_loads, expected, rtol=1e-10)
    assert np.linalg.norm(solution.load - (2e3, 7e3)) <= 1e-9 * 7e3
    assert solution.loaded_zone_half_angle < solve_radial(rollers, (2e3, 7e3)).loaded_zone_half_angle


def test_default_roller_mass_is_a_solid_steel_cylinder():
    rollers = bearing()
    assert rollers.roller_mass == pytest.approx(7850 * math.pi * rollers.roller_diameter**2 / 4 * LENGTH, rel=1e-14)


def test_displacement_of_the_solution_gives_back_the_load():
    rollers = bearing(diametral_clearance=2e-5, first_roller_angle=0.3)
    solution = solve_radial(rollers, (-4e3, 2.5e3), shaft_speed=250.0)
    reverse = radial_state(rollers, solution.displacement, shaft_speed=250.0)
    assert np.allclose(reverse.load, (-4e3, 2.5e3), rtol=0, atol=1e-9 * 4e3)
    assert np.allclose(reverse.inner_loads, solution.inner_loads, rtol=1e-12, atol=1e-9)


def test_preload_without_load_has_the_isotropic_closed_form_stiffness():
    """All rollers at δ = −P_d/2: K = (Z/2) n K_eq δ^(n−1) I because Σcos²ψ_j = Z/2 for Z >= 3."""
    clearance = -1e-5
    rollers = bearing(17, diametral_clearance=clearance)
    solution = solve_radial(rollers, (0.0, 0.0))
    equivalent = series_stiffness(rollers.inner_stiffness, rollers.outer_stiffness, N_EXP)
    expected = 17 / 2 * N_EXP * equivalent * (-clearance / 2) ** (N_EXP - 1)
    assert np.allclose(solution.stiffness, expected * np.eye(2), rtol=0, atol=1e-12 * expected)
    assert solution.iterations == 0
    assert solution.loaded_zone_half_angle == math.pi


def test_load_distribution_figure_is_written(tmp_path):
    solution = solve_radial(bearing(diametral_clearance=2e-5), (3e3, 4e3), shaft_speed=300.0)
    path = plot_load_distribution(solution, tmp_path / "figures" / "load.png")
    assert path.exists() and path.stat().st_size > 1000
