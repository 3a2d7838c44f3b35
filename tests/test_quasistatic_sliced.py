"""Sliced quasi-static model (document 003): crowned, tilting rollers and the 4×4 stiffness of the inner ring.

References and tolerances, per test:
* The planar model (tests/test_quasistatic_planar.py checks it against Stribeck/Harris): an uncrowned,
  untilted sliced roller set must reproduce it, for any number of slices, to round-off (1e-9 relative
  after the Newton loops' 1e-10 force tolerance).
* Analytic Jacobians (per roller 2×2 and the ring's 4×4) against central differences (1e-6 relative, in
  coordinates scaled by the half roller length so that all entries are in N/m).
* Mirror symmetry z → −z of even crowns: the moment is odd and the force even in the tilt (1e-9 relative).
* Eq. 7 of document 003: K_i (K_i + K_o)⁻¹ K_o is symmetric and positive semi-definite; the 4×4 sum of
  such blocks must be symmetric to round-off and have no eigenvalue below −1e-12 of the largest.
* Convergence in the number of slices: the solution with 2560 slices as reference; the observed order of
  the maximum roller load is fitted and printed in the assert message.
"""

import math

import numpy as np
import pytest

from bearing_mbs.models.cylindrical_roller.quasistatic import (
    CircularCrown,
    ConvergenceError,
    Flat,
    LogarithmicCrown,
    NewtonSettings,
    RollerSet,
    SlicedRollerSet,
    plot_load_distribution,
    radial_state,
    sliced_roller_equilibrium,
    sliced_state,
    solve_radial,
    solve_sliced,
)
from bearing_mbs.spec.fields import SpecError

PITCH, DIAMETER, LENGTH = 0.235, 0.025, 0.055
HALF = LENGTH / 2
SCALE = np.array([1.0, 1.0, HALF, HALF])  # (x, y, θx, θy) → lengths


def rollers(**changes):
    return RollerSet(15, PITCH, DIAMETER, LENGTH, **changes)


CIRCULAR = CircularCrown(radius=2.0, straight_length=LENGTH / 2)
LOGARITHMIC = LogarithmicCrown.lundberg(3000.0, LENGTH, 1.15e11, end_drop=2e-5)


def model(crown=CIRCULAR, slices=40, **changes):
    return SlicedRollerSet(rollers(**changes), roller_crown=crown, inner_raceway_crown=Flat(), slices=slices)


# --- bad input -----------------------------------------------------------------------------------------------


@pytest.mark.parametrize(
    "arguments, field, value",
    [
        (dict(roller_crown=CircularCrown(radius=0.01)), "roller_crown.radius", 0.01),
        (dict(inner_raceway_crown=LogarithmicCrown(1e-7, 0.05)), "inner_raceway_crown.length", 0.05),
        (dict(outer_raceway_crown="crowned"), "outer_raceway_crown", "crowned"),
        (dict(slices=0), "slices", 0),
        (dict(slices=12.5), "slices", 12.5),
    ],
)
def test_bad_sliced_model_names_field_value_and_allowed_range(arguments, field, value):
    with pytest.raises(SpecError) as info:
        SlicedRollerSet(rollers(), **arguments)
    assert info.value.field == field and info.value.value == value
    assert info.value.allowed  # says what is allowed


def test_crown_and_raceway_bounds_follow_the_effective_length():
    """A circular crown's radius must reach (L_e − L_r)/2 = L/2 without a straight part (the arc spans the
    effective length), and a logarithmic raceway crown must be at least L long: accepted on the bound (to
    round-off), rejected just below it."""
    SlicedRollerSet(rollers(), roller_crown=CircularCrown(radius=HALF * (1 + 1e-9)))
    with pytest.raises(SpecError) as info:
        SlicedRollerSet(rollers(), roller_crown=CircularCrown(radius=HALF * (1 - 1e-6)))
    assert info.value.field == "roller_crown.radius"
    SlicedRollerSet(rollers(), inner_raceway_crown=LogarithmicCrown(1e-7, LENGTH))
    with pytest.raises(SpecError) as info:
        SlicedRollerSet(rollers(), inner_raceway_crown=LogarithmicCrown(1e-7, LENGTH * (1 - 1e-6)))
    assert info.value.field == "inner_raceway_crown.length"


@pytest.mark.parametrize(
    "make, field",
    [
        (lambda: CircularCrown(radius=0.0), "radius"),
        (lambda: CircularCrown(radius=1.0, straight_length=-0.01), "straight_length"),
        (lambda: LogarithmicCrown(scale=-1e-7, length=LENGTH), "scale"),
        (lambda: LogarithmicCrown(scale=1e-7, length=LENGTH, end_drop=0.0), "end_drop"),
        (lambda: LogarithmicCrown.lundberg(-5.0, LENGTH, 1.15e11), "design_load"),
    ],
)
def test_bad_crown_names_the_field(make, field):
    with pytest.raises(SpecError) as info:
        make()
    assert info.value.field == field


def test_zero_load_without_preload_is_rejected():
    with pytest.raises(SpecError) as info:
        solve_sliced(model(), (0.0, 0.0, 0.0, 0.0))
    assert info.value.field == "load" and tuple(info.value.value) == (0.0, 0.0, 0.0, 0.0)
    # a preload (negative clearance) makes the same zero load valid
    assert solve_sliced(model(diametral_clearance=-1e-5), (0.0, 0.0, 0.0, 0.0)).iterations == 0


def test_roller_newton_that_does_not_converge_reports_residual_and_iterations():
    with pytest.raises(ConvergenceError) as info:
        sliced_state(
            model(inner_stiffness=5e9, outer_stiffness=8e9),
            (1e-5, 0.0, 2e-4, 0.0),
            shaft_speed=300.0,
            settings=NewtonSettings(roller_max_iterations=1),
        )
    error = info.value
    assert error.field == "roller_max_iterations" and error.value == 1 and error.iterations == 1
    assert math.isfinite(error.residual) and error.residual > 0 and error.tolerance > 0


# --- profiles ------------------------------------------------------------------------------------------------


def test_crown_formulas():
    """Eq. 13 corrected, R − sqrt(R² − (|z| − L_r/2)²); the logarithmic profile's end drop h(±L/2) = h_m."""
    z = np.array([-0.0275, -0.02, 0.0, 0.01, 0.02, 0.0275])
    overhang = np.maximum(np.abs(z) - 0.0125, 0)
    assert np.allclose(CircularCrown(0.5, 0.025).drop(z), 0.5 - np.sqrt(0.25 - overhang**2), rtol=1e-14, atol=0)
    crown = LogarithmicCrown(scale=3e-7, length=LENGTH, end_drop=2e-5)
    assert crown.drop(np.array([LENGTH / 2]))[0] == pytest.approx(2e-5, rel=1e-12)
    reach = 1 - math.exp(-2e-5 / 3e-7)
    assert crown.drop(z[1:-1]) == pytest.approx(-3e-7 * np.log(1 - reach * (2 * z[1:-1] / LENGTH) ** 2), rel=1e-12)
    assert LOGARITHMIC.scale == pytest.approx(2 * 3000.0 / (math.pi * LENGTH * 1.15e11), rel=1e-14)


# --- per roller ----------------------------------------------------------------------------------------------


@pytest.mark.parametrize("crown", [CIRCULAR, LOGARITHMIC, Flat()], ids=["circular", "logarithmic", "flat"])
@pytest.mark.parametrize("centrifugal", [0.0, 600.0])
def test_roller_condensed_stiffness_matches_central_differences(crown, centrifugal):
    sliced = model(crown, inner_stiffness=5e9, outer_stiffness=8e9)
    radial = np.array([4e-6, 1.2e-5, 2.5e-5, 1e-5])
    tilt = np.array([0.0, 1e-4, -3e-4, 6e-4])
    eq = sliced_roller_equilibrium(sliced, radial, tilt, centrifugal)
    h = 1e-6 * radial
    columns = []
    for d_radial, d_tilt in ((h, 0 * h), (0 * h, h / HALF)):
        plus = sliced_roller_equilibrium(sliced, radial + d_radial, tilt + d_tilt, centrifugal)
        minus = sliced_roller_equilibrium(sliced, radial - d_radial, tilt - d_tilt, centrifugal)
        columns.append(
            np.stack([plus.inner.force - minus.inner.force, (plus.inner.moment - minus.inner.moment) / HALF], axis=1)
            / (2 * h[:, None])
        )
    numeric = np.stack(columns, axis=2)  # (Z, 2, 2), scaled
    analytic = eq.stiffness / np.array([[1.0, HALF], [HALF, HALF**2]])
    for j in range(len(radial)):
        assert np.linalg.norm(numeric[j] - analytic[j]) <= 1e-6 * np.linalg.norm(analytic[j]), j
    # Equilibrium of every roller: forces and moments balance, with the centrifugal force outward.
    assert np.allclose(eq.outer.force - eq.inner.force, centrifugal, rtol=0, atol=1e-10 * eq.outer.force.max())
    assert np.allclose(eq.outer.moment, eq.inner.moment, rtol=0, atol=1e-10 * eq.outer.force.max() * HALF)


def test_roller_between_raceways_without_touching_them_is_loose():
    sliced = model(CIRCULAR, diametral_clearance=4e-5)
    eq = sliced_roller_equilibrium(sliced, np.array([1e-5, 5e-5]), np.array([0.0, 0.0]), 0.0)
    assert eq.loose.tolist() == [True, False]
    assert eq.inner.force[0] == 0.0 and np.all(eq.stiffness[0] == 0.0) and eq.inner.force[1] > 0.0


# --- the ring ------------------------------------------------------------------------------------------------


@pytest.mark.parametrize("slices", [1, 7, 40])
def test_uncrowned_untilted_sliced_model_reproduces_the_planar_model(slices):
    base = rollers(diametral_clearance=2e-5)
    sliced = SlicedRollerSet(base, slices=slices)
    planar = solve_radial(base, (3e3, 4e3), shaft_speed=300.0)
    solution = solve_sliced(sliced, (3e3, 4e3, 0.0, 0.0), shaft_speed=300.0)
    assert np.allclose(solution.displacement[:2], planar.displacement, rtol=1e-9, atol=0)
    assert np.allclose(solution.inner_loads, planar.inner_loads, rtol=0, atol=1e-9 * planar.max_roller_load)
    assert np.allclose(solution.stiffness[:2, :2], planar.stiffness, rtol=0, atol=1e-9 * planar.stiffness.max())
    assert np.allclose(solution.stiffness[:2, 2:], 0.0, atol=1e-9 * planar.stiffness.max() * HALF)
    assert np.allclose(solution.roller_tilts, 0.0, atol=1e-15)


@pytest.mark.parametrize(
    "crown, displacement, shaft_speed, clearance",
    [
        (CIRCULAR, (1.2e-5, 7e-6, 1e-4, -2e-4), 0.0, 2e-5),
        (CIRCULAR, (6e-6, -3e-6, -3e-4, 1e-4), 400.0, 0.0),
        (LOGARITHMIC, (8e-6, 2e-6, 5e-5, 2e-4), 300.0, -5e-6),
    ],
)
def test_ring_stiffness_matches_central_differences(crown, displacement, shaft_speed, clearance):
    sliced = model(crown, diametral_clearance=clearance)
    point = np.array(displacement)
    state = sliced_state(sliced, point, shaft_speed=shaft_speed)
    size = np.linalg.norm(point * SCALE)
    columns = []
    for i in range(4):
        step = np.zeros(4)
        step[i] = 1e-6 * size / SCALE[i]
        plus = sliced_state(sliced, point + step, shaft_speed=shaft_speed).load
        minus = sliced_state(sliced, point - step, shaft_speed=shaft_speed).load
        columns.append((plus - minus) / (2 * step[i]))
    numeric = np.stack(columns, axis=1) / np.outer(SCALE, SCALE)
    analytic = state.stiffness / np.outer(SCALE, SCALE)
    assert np.linalg.norm(numeric - analytic) <= 1e-6 * np.linalg.norm(analytic)


@pytest.mark.parametrize(
    "crown, load",
    [
        (CIRCULAR, (1e4, 0.0, 0.0, 0.0)),
        (CIRCULAR, (6e3, -3e3, 40.0, 25.0)),
        (LOGARITHMIC, (2e3, 5e3, -30.0, 0.0)),
    ],
)
def test_stiffness_under_load_is_symmetric_positive_semidefinite(crown, load):
    solution = solve_sliced(model(crown, diametral_clearance=1e-5), load, shaft_speed=200.0)
    assert np.linalg.norm(solution.load - np.array(load)) <= 1e-8 * np.linalg.norm(load)
    scaled = solution.stiffness / np.outer(SCALE, SCALE)
    assert np.array_equal(solution.stiffness, solution.stiffness.T)
    eigenvalues = np.linalg.eigvalsh(scaled)
    assert eigenvalues.min() >= -1e-12 * eigenvalues.max()
    assert eigenvalues.min() > 0.0  # tilt is resisted too: enough rollers carry load


@pytest.mark.parametrize("crown", [CIRCULAR, LOGARITHMIC, Flat()], ids=["circular", "logarithmic", "flat"])
def test_ring_tilt_produces_an_antisymmetric_moment(crown):
    sliced = model(crown)
    for tilt in (5e-5, 2e-4, 8e-4):
        plus = sliced_state(sliced, (1e-5, 0.0, 0.0, tilt))
        minus = sliced_state(sliced, (1e-5, 0.0, 0.0, -tilt))
        assert plus.load[3] > 0.0
        assert minus.load[3] == pytest.approx(-plus.load[3], rel=1e-9)
        assert minus.load[0] == pytest.approx(plus.load[0], rel=1e-9)
        assert abs(plus.load[1]) <= 1e-9 * plus.load[0] and abs(plus.load[2]) <= 1e-9 * plus.load[0] * HALF
        assert np.allclose(minus.roller_tilts, -plus.roller_tilts, rtol=1e-6, atol=1e-12)


def test_moment_load_is_carried_and_displacement_gives_it_back():
    sliced = model(LOGARITHMIC, diametral_clearance=1e-5)
    load = (4e3, 1e3, 60.0, -20.0)
    solution = solve_sliced(sliced, load, shaft_speed=150.0)
    reverse = sliced_state(sliced, solution.displacement, shaft_speed=150.0)
    assert np.allclose(reverse.load, load, rtol=1e-8, atol=1e-8 * 4e3 * HALF)
    assert solution.displacement[2] > 0 and solution.displacement[3] < 0


def test_preloaded_bearing_without_load_is_stiff_in_every_direction():
    solution = solve_sliced(model(CIRCULAR, diametral_clearance=-1e-5), (0.0, 0.0, 0.0, 0.0))
    assert solution.iterations == 0
    eigenvalues = np.linalg.eigvalsh(solution.stiffness / np.outer(SCALE, SCALE))
    assert eigenvalues.min() > 0.0
    assert solution.stiffness[0, 0] == pytest.approx(solution.stiffness[1, 1], rel=1e-10)
    assert solution.stiffness[2, 2] == pytest.approx(solution.stiffness[3, 3], rel=1e-10)


def test_max_roller_load_converges_with_the_number_of_slices():
    """Reference: 2560 slices. Contact edges fall inside the rollers (see test_line_contact.py), so the order
    is fitted over N = 10…160 and must exceed 1.5; the error with 40 slices must stay below 0.2 %."""
    load = (1e4, 0.0, 0.0, 0.0)
    reference = solve_sliced(model(CIRCULAR, slices=2560), load).max_roller_load
    counts = np.array([10, 20, 40, 80, 160])
    loads = [solve_sliced(model(CIRCULAR, slices=n), load).max_roller_load for n in counts]
    errors = np.abs(np.array(loads) / reference - 1)
    order = -np.polyfit(np.log(counts), np.log(errors), 1)[0]
    assert order >= 1.5, f"observed order {order:.3f}, errors {errors}"
    assert errors[2] <= 2e-3, f"error {errors[2]:.2e} with 40 slices (order {order:.3f})"


def test_sliced_load_distribution_figure_is_written(tmp_path):
    solution = solve_sliced(model(), (3e3, 4e3, 20.0, 0.0))
    path = plot_load_distribution(solution, tmp_path / "sliced.png")
    assert path.exists() and path.stat().st_size > 1000


def test_planar_state_and_sliced_state_agree_for_flat_rollers_at_a_given_displacement():
    base = rollers(diametral_clearance=-4e-6)
    planar = radial_state(base, (5e-6, 2e-6), shaft_speed=500.0)
    sliced = sliced_state(SlicedRollerSet(base, slices=13), (5e-6, 2e-6, 0.0, 0.0), shaft_speed=500.0)
    assert np.allclose(sliced.load[:2], planar.load, rtol=1e-11)
    assert np.allclose(sliced.outer_loads, planar.outer_loads, rtol=1e-11)


def test_bracketed_safeguard_finds_the_same_roller_equilibrium_as_newton(monkeypatch):
    """The block (v(β), g(β)) safeguard is an independent route to the same equilibrium (1e-9 relative)."""
    from bearing_mbs.models.cylindrical_roller.quasistatic import sliced as sliced_module

    sliced = model(LOGARITHMIC, inner_stiffness=5e9, outer_stiffness=8e9)
    radial, tilt = np.array([3e-6, 1.2e-5, 2.5e-5]), np.array([2e-4, -1e-4, 6e-4])
    newton = sliced_roller_equilibrium(sliced, radial, tilt, 400.0)
    monkeypatch.setattr(sliced_module, "NEWTON_ITERATIONS", 0)
    safeguard = sliced_roller_equilibrium(sliced, radial, tilt, 400.0)
    assert safeguard.iterations > 0
    scale = newton.outer.force.max()
    assert np.allclose(safeguard.inner.force, newton.inner.force, rtol=0, atol=1e-9 * scale)
    assert np.allclose(safeguard.inner.moment, newton.inner.moment, rtol=0, atol=1e-9 * scale * HALF)
    assert np.allclose(safeguard.roller_tilt, newton.roller_tilt, rtol=1e-7, atol=1e-12)
    assert np.allclose(safeguard.outer.force - safeguard.inner.force, 400.0, rtol=0, atol=1e-9 * scale)


@pytest.mark.parametrize(
    "rollers_count, clearance, load, shaft_speed",
    [
        (8, 1e-4, (1e-3 * math.cos(0.1), 1e-3 * math.sin(0.1), 5.5e-7, 2.75e-7), 300.0),  # 1 mN, 100 µm clearance
        (15, 2e-5, (math.cos(0.1), math.sin(0.1), 0.0165, 0.00825), 0.0),  # 1 N with a large moment
        (5, 0.0, (233.0, -2028.0, -2.2, -1.4), 1500.0),  # 5 rollers, F_c = 8 kN lifts most inner contacts
    ],
)
def test_hard_cases_converge(rollers_count, clearance, load, shaft_speed):
    """Few rollers in contact make K singular at the start: the ring Newton must still reach the load
    (relative residual 1e-8, the solver's tolerance plus round-off of light loads with clearance)."""
    base = RollerSet(rollers_count, PITCH, DIAMETER, LENGTH, diametral_clearance=clearance)
    sliced = SlicedRollerSet(base, roller_crown=CircularCrown(1.0, 0.02))
    solution = solve_sliced(sliced, load, shaft_speed=shaft_speed)
    scaled = (solution.load - np.array(load)) / SCALE
    assert np.linalg.norm(scaled) <= 1e-8 * np.linalg.norm(np.array(load) / SCALE)
