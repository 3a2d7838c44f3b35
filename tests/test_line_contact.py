"""Line-contact formulas: Palmgren's law in SI units, the slice form of document 003, contacts in series.

References and tolerances, per test:
* Palmgren (1959) / Harris & Kotzalas (2006, ch. 6): δ[mm] = 3.84e-5 Q^0.9 / l[mm]^0.8 and the rounded
  constant 8.06e4 N/mm² of Q = 8.06e4 δ^(10/9) l^(8/9); the SI law must invert the printed formula to
  round-off (1e-13 relative) and match the rounded constant to its printed precision (0.2 %).
* The slice coefficient C_f = K/L_e must give Q = K δ^(10/9) for an uncrowned, untilted roller with any
  number of slices, to round-off (1e-13 relative).
* Analytic partial derivatives against central differences (truncation O(h²), 1e-6 relative).
* Crowned rollers: the sliced sums against an adaptive quadrature (scipy ``quad``, break points at the crown
  junctions and contact edges, relative accuracy 1e-12) of ∫ C_f (δ + αz − h(z))₊ⁿ dz; the observed order
  is fitted and printed in the assert message.
* Series law: δ_i + δ_o from each contact's own inverse law (independent of K_eq), 1e-13 relative.
"""

import math

import numba
import numpy as np
import pytest
from scipy.integrate import quad
from scipy.optimize import brentq

from bearing_mbs.contact.line_contact import (
    PALMGREN_EXPONENT,
    palmgren_approach,
    palmgren_slice_coefficient,
    palmgren_stiffness,
    power_law_force,
    power_law_stiffness,
    series_inner_share,
    series_stiffness,
    slice_coefficient,
    sliced_contact,
)
from bearing_mbs.models.cylindrical_roller.quasistatic.profiles import CircularCrown, LogarithmicCrown

LENGTH = 0.055  # [m], the primary document's roller length LW
N_EXP = PALMGREN_EXPONENT


def slices(n, length=LENGTH):
    return length * (-0.5 + (np.arange(n) + 0.5) / n), length / n


@pytest.mark.parametrize("length", [0.01, 0.055, 0.2])
@pytest.mark.parametrize("load", [10.0, 2e3, 1e5])
def test_palmgren_si_law_inverts_the_printed_formula(load, length):
    approach_mm = 3.84e-5 * load**0.9 / (1e3 * length) ** 0.8  # the formula as Palmgren prints it
    approach = palmgren_approach(load, length)
    assert approach == pytest.approx(approach_mm * 1e-3, rel=1e-14)
    assert palmgren_stiffness(length) * approach ** (10 / 9) == pytest.approx(load, rel=1e-13)


def test_palmgren_constant_matches_harris_rounded_value():
    """Harris & Kotzalas print K = 8.06e4 l^(8/9) in N and mm: in SI that is 8.06e10 N/m² · l^(8/9)."""
    length = 0.03
    assert palmgren_stiffness(length) == pytest.approx(8.06e10 * length ** (8 / 9), rel=2e-3)


@pytest.mark.parametrize("count", [1, 2, 7, 40, 333])
def test_uncrowned_untilted_slices_reproduce_the_whole_roller_law(count):
    z, width = slices(count)
    for approach in (1e-7, 4e-6, 3e-5):
        contact = sliced_contact(approach, 0.0, z, np.zeros(count), width, palmgren_slice_coefficient(LENGTH), N_EXP)
        expected = palmgren_stiffness(LENGTH) * approach ** (10 / 9)
        assert contact.force == pytest.approx(expected, rel=1e-13)
        assert abs(contact.moment) <= 1e-14 * expected * LENGTH
        assert contact.force_approach == pytest.approx(N_EXP * expected / approach, rel=1e-13)


CROWNS = {
    "circular": CircularCrown(radius=2.0, straight_length=LENGTH / 2),
    "full_circular": CircularCrown(radius=1.0),
    "logarithmic": LogarithmicCrown(scale=2e-7, length=LENGTH, end_drop=2e-5),
    "lundberg": LogarithmicCrown.lundberg(3000.0, LENGTH, 1.15e11),
}


@pytest.mark.parametrize("crown", CROWNS.values(), ids=CROWNS.keys())
@pytest.mark.parametrize("approach, tilt", [(6e-6, 0.0), (4e-6, 2e-4), (1.5e-5, -5e-4)])
def test_sliced_derivatives_match_central_differences(crown, approach, tilt):
    z, width = slices(40)
    drops, cf = crown.drop(z), palmgren_slice_coefficient(LENGTH)
    contact = sliced_contact(approach, tilt, z, drops, width, cf, N_EXP)
    half = LENGTH / 2
    # Scaled Jacobian of (Q, M/ℓ) against (δ, ℓα), all entries in N/m.
    analytic = np.array(
        [
            [contact.force_approach, contact.force_tilt / half],
            [contact.force_tilt / half, contact.moment_tilt / half**2],
        ]
    )
    h = 1e-6 * approach
    numeric = np.empty((2, 2))
    for column, (dd, da) in enumerate([(h, 0.0), (0.0, h / half)]):
        plus = sliced_contact(approach + dd, tilt + da, z, drops, width, cf, N_EXP)
        minus = sliced_contact(approach - dd, tilt - da, z, drops, width, cf, N_EXP)
        numeric[:, column] = [(plus.force - minus.force) / (2 * h), (plus.moment - minus.moment) / (2 * h * half)]
    assert np.linalg.norm(numeric - analytic) <= 1e-6 * np.linalg.norm(analytic)
    # The energy is the potential of the force: dE/dδ = Q.
    plus = sliced_contact(approach + h, tilt, z, drops, width, cf, N_EXP).energy
    minus = sliced_contact(approach - h, tilt, z, drops, width, cf, N_EXP).energy
    assert (plus - minus) / (2 * h) == pytest.approx(contact.force, rel=1e-6)


@pytest.mark.parametrize("crown", CROWNS.values(), ids=CROWNS.keys())
def test_tilt_moment_is_antisymmetric(crown):
    z, width = slices(41)
    drops, cf = crown.drop(z), palmgren_slice_coefficient(LENGTH)
    for tilt in (1e-5, 3e-4, 1e-3):
        plus = sliced_contact(5e-6, tilt, z, drops, width, cf, N_EXP)
        minus = sliced_contact(5e-6, -tilt, z, drops, width, cf, N_EXP)
        assert plus.moment > 0.0
        assert minus.moment == pytest.approx(-plus.moment, rel=1e-12)
        assert minus.force == pytest.approx(plus.force, rel=1e-12)


def reference_resultants(crown, approach, tilt, straight=None):
    """Q and M by adaptive quadrature, with break points at the crown junctions and the contact edges."""
    cf = palmgren_slice_coefficient(LENGTH)

    def interference(z):
        return approach + tilt * z - float(crown.drop(z))

    points = [] if straight is None else [-straight / 2, straight / 2]
    for a, b in ((-LENGTH / 2, 0.0), (0.0, LENGTH / 2)):
        if interference(a) * interference(b) < 0:
            points.append(brentq(interference, a, b, xtol=1e-18))

    def load(z):
        return cf * max(interference(z), 0.0) ** N_EXP

    options = dict(points=sorted(points), limit=400, epsabs=0.0, epsrel=1e-12)
    force = quad(load, -LENGTH / 2, LENGTH / 2, **options)[0]
    moment = quad(lambda z: load(z) * z, -LENGTH / 2, LENGTH / 2, **options)[0]
    return force, moment


def observed_order(counts, errors):
    return -np.polyfit(np.log(counts), np.log(errors), 1)[0]


def test_crowned_roller_in_full_contact_converges_at_second_order():
    """Whole length in contact, crown junctions on slice boundaries (N multiple of 4): the slices are the
    midpoint rule of an integrand f with continuous f' (the circular crown is C¹), so by Euler–Maclaurin the
    error is −(h²/24)(f'(L/2) − f'(−L/2)) + o(h²). The fitted order must be 1.9–2.1, and the error with
    64 slices must agree with that leading term within 5 % (an absolute bound derived, not measured)."""
    crown = CircularCrown(radius=10.0, straight_length=LENGTH / 2)  # end drop 9.5 µm
    approach, tilt = 1.5e-5, 1e-4
    cf = palmgren_slice_coefficient(LENGTH)
    force, _ = reference_resultants(crown, approach, tilt, straight=LENGTH / 2)
    counts = np.array([8, 16, 32, 64, 128, 256])
    errors = []
    for count in counts:
        z, width = slices(count)
        contact = sliced_contact(approach, tilt, z, crown.drop(z), width, cf, N_EXP)
        errors.append((contact.force - force) / force)
    order = observed_order(counts, np.abs(errors))

    def slope(z):  # f'(z) for |z| > L_r/2, with the crown slope h'(z) = s/sqrt(R² − s²), s = |z| − L_r/2
        s = abs(z) - LENGTH / 4
        crown_slope = math.copysign(s / math.sqrt(crown.radius**2 - s**2), z)
        interference = approach + tilt * z - float(crown.drop(z))
        return cf * N_EXP * interference ** (N_EXP - 1) * (tilt - crown_slope)

    h = LENGTH / 64
    leading = -(h**2 / 24) * (slope(LENGTH / 2) - slope(-LENGTH / 2)) / force
    assert 1.9 <= order <= 2.1, f"observed order {order:.3f}, errors {errors}"
    assert errors[3] == pytest.approx(leading, rel=0.05), f"error {errors[3]:.3e} with 64 slices, order {order:.3f}"


@pytest.mark.parametrize("name", ["circular", "full_circular"])
def test_crowned_roller_with_contact_edges_converges(name):
    """Contact edges inside the roller: the integrand vanishes like s^(10/9) at an edge placed arbitrarily in a
    slice, so the error is O(N^-(19/9)) with an oscillating constant. The fitted order must exceed 1.5 and
    the error with 320 slices stay below 1e-3 relative (the fully crowned case has only ~35 slices in
    contact at N = 320)."""
    crown = CROWNS[name]
    approach, tilt = 5e-6, 1e-4
    straight = crown.straight_length or None
    force, moment = reference_resultants(crown, approach, tilt, straight=straight)
    counts = np.array([10, 20, 40, 80, 160, 320])
    errors = []
    for count in counts:
        z, width = slices(count)
        contact = sliced_contact(approach, tilt, z, crown.drop(z), width, palmgren_slice_coefficient(LENGTH), N_EXP)
        errors.append(abs(contact.force - force) / force + abs(contact.moment - moment) / (force * LENGTH))
    order = observed_order(counts, errors)
    assert order >= 1.5, f"observed order {order:.3f}, errors {np.array(errors)}"
    assert errors[-1] <= 1e-3, f"relative error {errors[-1]:.2e} with 320 slices (order {order:.3f})"


@pytest.mark.parametrize("ratio", [1.0, 2.0, 0.3])
def test_series_law_adds_the_two_approaches(ratio):
    inner, outer = 6e9, 6e9 * ratio
    equivalent = series_stiffness(inner, outer, N_EXP)
    for load in (50.0, 5e3):
        approach_inner = (load / inner) ** (1 / N_EXP)
        approach_outer = (load / outer) ** (1 / N_EXP)
        total = approach_inner + approach_outer
        assert equivalent * total**N_EXP == pytest.approx(load, rel=1e-13)
        assert series_inner_share(inner, outer, N_EXP) * total == pytest.approx(approach_inner, rel=1e-13)
    if ratio == 1.0:
        assert equivalent == pytest.approx(inner / 2**N_EXP, rel=1e-14)


def test_power_law_stiffness_is_the_derivative_and_vanishes_out_of_contact():
    for approach in (1e-7, 1e-5):
        h = 1e-6 * approach
        numeric = (power_law_force(approach + h, 6e9, N_EXP) - power_law_force(approach - h, 6e9, N_EXP)) / (2 * h)
        assert power_law_stiffness(approach, 6e9, N_EXP) == pytest.approx(numeric, rel=1e-8)
    assert power_law_stiffness(-1e-6, 6e9, 1.0) == 0.0
    assert power_law_stiffness(0.0, 6e9, 1.0) == 0.0
    assert power_law_force(-1e-6, 6e9, N_EXP) == 0.0


def test_scalar_laws_compile_inline_with_numba():
    """The register_jitable functions must compile inside a numba kernel and agree with plain Python."""

    @numba.njit
    def chain(length, approach):
        k = palmgren_stiffness(length)
        keq = series_stiffness(k, k, 10.0 / 9.0)
        return power_law_force(approach, keq, 10.0 / 9.0) + power_law_stiffness(approach, k, 10.0 / 9.0) * 0.0 + (
            slice_coefficient(k, length) * 0.0
        )

    expected = power_law_force(1e-5, series_stiffness(palmgren_stiffness(0.05), palmgren_stiffness(0.05), N_EXP), N_EXP)
    assert chain(0.05, 1e-5) == pytest.approx(expected, rel=1e-14)
    assert math.isfinite(chain(0.05, -1e-5))
