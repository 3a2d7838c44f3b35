"""Contact laws against closed forms and an independent integrator.

References and tolerances:
* damping factors d(e) of the hysteresis family, written out here from the papers (:data:`PAPER_DAMPING_FACTOR`,
  never the package's :data:`~bearing_mbs.contact.normal.DAMPING_FACTOR`): Lankarani & Nikravesh 1990
  d = 3(1 − e²)/4; Hunt & Crossley 1975 d = 3(1 − e)/2 (as stated by Marhefka & Orin 1999); Flores et al. 2011
  d = 8(1 − e)/(5e); Gonthier et al. 2004 d = (1 − e²)/e (as bearing_mbs/contact/normal.py cites it). The
  package's factors must equal them to round-off (1e-14 relative);
* effective restitution of the hysteresis family: the closed form χ(1+e*) = ln[(1+χ)/(1−χe*)], derived in
  :func:`expected_restitution` from energy integrals, with χ the paper's d(e), against the restitution one
  impact actually achieves with the package's force law and damping factor, integrated by scipy's DOP853
  (rtol 1e-11): 1e-6 relative (a factor off by 1 % moves e* by about 1e-4 relative or more at every e
  tested);
* energy: d/dδ of the elastic energy equals the elastic force (central differences, 1e-7 relative);
* friction slopes at zero slip: central differences, 1e-6 relative.
"""

import math

import numpy as np
import pytest
from scipy.integrate import solve_ivp
from scipy.optimize import brentq

from bearing_mbs.contact import friction, normal

#: Damping factor d(e) of each hysteresis law, from the cited papers' formulas (independent of the package).
PAPER_DAMPING_FACTOR = {
    # H. M. Lankarani, P. E. Nikravesh, J. Mech. Des. 112 (1990) 369–376: D = 3K(1 − e²)/(4 δ̇⁻)
    "lankarani_nikravesh": lambda e: 3.0 * (1.0 - e * e) / 4.0,
    # K. H. Hunt, F. R. E. Crossley, J. Appl. Mech. 42 (1975) 440–445, as Marhefka & Orin (1999) state it:
    # λ = 3K(1 − e)/(2 δ̇⁻)
    "hunt_crossley": lambda e: 3.0 * (1.0 - e) / 2.0,
    # P. Flores et al., Multibody Syst. Dyn. 25 (2011) 357–375: D = 8K(1 − e)/(5e δ̇⁻)
    "flores": lambda e: 8.0 * (1.0 - e) / (5.0 * e),
    # Y. Gonthier et al., Multibody Syst. Dyn. 11 (2004) 209–233, as bearing_mbs/contact/normal.py cites it:
    # D = K(1 − e²)/(e δ̇⁻)
    "gonthier": lambda e: (1.0 - e * e) / e,
    # the plain power law K δⁿ has no damping
    "power": lambda e: 0.0,
}


def expected_restitution(damping_factor: float) -> float:
    """Effective restitution e* of F = Kδⁿ(1 + χ δ̇/v₀) for an impact at speed v₀ (χ = damping factor).

    With u = δ̇, m u du/dδ = −Kδⁿ(1 + χu/v₀). Integrating u/(1 + χu/v₀) du over compression (v₀ → 0) and
    restitution (0 → −e*v₀) gives the same elastic work both ways, hence χ(1+e*) = ln[(1+χ)/(1−χe*)],
    independent of K, n and m. Solved here for e* in (0, 1).
    """
    chi = damping_factor
    if chi == 0:
        return 1.0

    def residual(e):
        return chi * (1 + e) - math.log((1 + chi) / (1 - chi * e))

    return brentq(residual, 1e-12, min(1.0, 1.0 / chi) * (1 - 1e-12), xtol=1e-15)


def integrate_impact(law, restitution, exponent, v0=1.0, mass=0.1, stiffness=6e6):
    """One impact, integrated by scipy DOP853 with the package's force law and damping factor (the code under
    test); returns separation/impact speed."""
    d = normal.DAMPING_FACTOR[law](restitution)

    def rhs(t, y):
        gap, gap_rate = y
        force = normal.hysteresis_force(gap, gap_rate, stiffness, exponent, d, v0)
        return [gap_rate, force / mass]

    separated = lambda t, y: y[0]
    separated.terminal, separated.direction = True, 1
    solution = solve_ivp(rhs, (0, 1.0), [0.0, -v0], method="DOP853", rtol=1e-11, atol=1e-14, events=separated,
                         first_step=1e-9)
    return solution.y_events[0][0][1] / v0


@pytest.mark.parametrize("law", ["lankarani_nikravesh", "hunt_crossley", "flores", "gonthier"])
@pytest.mark.parametrize("exponent", [1.5, 10 / 9])
@pytest.mark.parametrize("restitution", [0.3, 0.6, 0.9, 0.99])
def test_hysteresis_laws_give_the_closed_form_restitution(law, exponent, restitution):
    expected = expected_restitution(PAPER_DAMPING_FACTOR[law](restitution))
    assert integrate_impact(law, restitution, exponent) == pytest.approx(expected, rel=1e-6)


@pytest.mark.parametrize("law", normal.NORMAL_LAWS)
def test_damping_factors_are_the_papers_formulas(law):
    for restitution in (0.05, 0.3, 0.6, 0.9, 0.99, 1.0):
        assert normal.DAMPING_FACTOR[law](restitution) == pytest.approx(
            PAPER_DAMPING_FACTOR[law](restitution), rel=1e-14, abs=1e-300), (law, restitution)


@pytest.mark.parametrize("law", normal.NORMAL_LAWS)
def test_damping_factor_vanishes_for_elastic_impacts_and_decreases_with_restitution(law):
    factor = normal.DAMPING_FACTOR[law]
    assert factor(1.0) == 0.0
    values = [factor(e) for e in np.linspace(0.05, 1.0, 20)]
    assert all(a >= b for a, b in zip(values, values[1:]))


def test_power_law_is_conservative_and_never_pulls():
    gap = np.linspace(-1e-3, 1e-3, 101)
    for rate in (-1.0, 1.0):
        force = normal.hysteresis_force(gap, rate, 1e8, 1.5, 0.0, 1.0)
        np.testing.assert_array_equal(force, normal.elastic_force(gap, 1e8, 1.5))
    assert np.all(normal.hysteresis_force(gap, 50.0, 1e8, 1.5, 2.0, 1.0) >= 0)


def test_elastic_energy_is_the_potential_of_the_elastic_force():
    gap, eps = -np.array([1e-5, 1e-4, 3e-4]), 1e-9
    dE = (normal.elastic_energy(gap + eps, 6e6, 1.3) - normal.elastic_energy(gap - eps, 6e6, 1.3)) / (2 * eps)
    np.testing.assert_allclose(-dE, normal.elastic_force(gap, 6e6, 1.3), rtol=1e-7)


def test_approach_speed_floor():
    """Below the floor the damping uses the floor: the force equals the force at the floor speed."""
    floor = 1e-3
    latched_slow = normal.latch_approach_speed(-1e-5, -1e-6, 0.0, floor)
    assert latched_slow == floor
    slow = normal.hysteresis_force(-1e-5, -2e-4, 1e8, 1.5, 0.5, normal.reference_approach_speed(0.0, -1e-6, floor))
    at_floor = normal.hysteresis_force(-1e-5, -2e-4, 1e8, 1.5, 0.5, floor)
    assert slow == at_floor


def test_approach_speed_is_latched_at_onset_kept_in_contact_and_reset_after():
    floor = 1e-3
    latched = normal.latch_approach_speed(-1e-6, -0.3, 0.0, floor)  # onset at 0.3 m/s
    assert latched == 0.3
    latched = normal.latch_approach_speed(-1e-4, +0.1, latched, floor)  # still in contact, rebounding
    assert latched == 0.3
    assert normal.latch_approach_speed(+1e-6, +0.25, latched, floor) == 0.0  # apart
    # before the latch exists the current approach speed is used
    assert normal.reference_approach_speed(0.0, -0.7, floor) == 0.7


@pytest.mark.parametrize("law", ["erf", "tanh", "linear"])
def test_regularised_friction_is_odd_bounded_saturating_with_the_documented_slope(law):
    sign, v_reg = friction.FRICTION_SIGN[law], 0.01
    slip = np.linspace(-1, 1, 2001)
    phi = sign(slip, v_reg)
    np.testing.assert_allclose(phi, -sign(-slip, v_reg), atol=0)
    assert np.all(np.abs(phi) <= 1)
    assert sign(10 * v_reg, v_reg) == pytest.approx(1.0, abs=1e-8)
    eps = 1e-9
    slope = (sign(eps, v_reg) - sign(-eps, v_reg)) / (2 * eps)
    assert slope * v_reg == pytest.approx(friction.ZERO_SLIP_SLOPE[law], rel=1e-6)


def test_dead_zone_rule_of_the_document():
    sign = friction.dead_zone_sign
    assert sign(0.5e-3, 1e-3) == 0 and sign(-0.99e-3, 1e-3) == 0
    assert sign(1e-3, 1e-3) == 1 and sign(-2e-3, 1e-3) == -1


def test_friction_and_rolling_resistance_oppose_motion():
    normal_force = 10.0
    assert friction.friction_force(normal_force, 0.2, friction.erf_sign(0.05, 0.01)) < 0
    assert friction.rolling_resistance_moment(normal_force, 1e-4, friction.erf_sign(-3.0, 0.01)) == pytest.approx(
        1e-3
    )
