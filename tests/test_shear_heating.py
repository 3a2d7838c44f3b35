"""The film's shear heating (bearing_mbs.contact.shear_heating) against a numerical solution of the problem it
solves: plane Couette flow between walls at one temperature, viscosity μ0 e^(−β ΔT), heat conducted to the walls.

Reference: scipy's collocation solver (solve_bvp) on the flow and energy equations written out in full (velocity and
temperature as unknowns, the stress as a free parameter), not on the closed form's reduced equation. Tolerance: the
issue's 1 % over Nahme numbers 0.1–50; the collocation is converged to 1e-8, so a wrong closed form (for example
the reduction at twice or half the Nahme number, 5–30 % off over this range) fails it.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.integrate import solve_bvp

from bearing_mbs.contact import traction
from bearing_mbs.contact.shear_heating import nahme_reduction

NAHME_NUMBERS = (0.1, 0.3, 1.0, 3.0, 10.0, 30.0, 50.0)


def couette_stress_ratio(nahme: float) -> float:
    """τ/τ_iso of the Couette film at Nahme number Na, by collocation on the dimensionless equations
    u' = τ e^θ, θ'' = −Na τ u' (y in [0, 1], u(0) = 0, u(1) = 1, θ(0) = θ(1) = 0; θ = β ΔT, τ in units of
    μ0 U/h), continued from the isothermal solution through increasing Na."""
    y = np.linspace(0.0, 1.0, 201)
    guess, stress = np.vstack([y, np.zeros_like(y), np.zeros_like(y)]), 1.0
    for na in np.geomspace(min(nahme, 0.05), nahme, 12):
        def equations(_, state, parameter, na=na):
            _, theta, flux = state
            rate = parameter[0] * np.exp(theta)
            return np.vstack([rate, flux, -na * parameter[0] * rate])

        def boundary(left, right, _):
            return np.array([left[0], right[0] - 1.0, left[1], right[1]])

        solution = solve_bvp(equations, boundary, y, guess, p=[stress], tol=1e-8, max_nodes=100000)
        assert solution.success, solution.message
        guess, stress = solution.sol(y), solution.p[0]
    return stress


@pytest.mark.parametrize("nahme", NAHME_NUMBERS)
def test_the_nahme_reduction_matches_the_couette_film(nahme):
    assert nahme_reduction(nahme)[0] == pytest.approx(couette_stress_ratio(nahme), rel=0.01)


@pytest.mark.parametrize("nahme", NAHME_NUMBERS)
def test_a_newtonian_eyring_film_is_reduced_as_the_couette_film(nahme):
    """The traction law applies the reduction at the film's own isothermal stress: in the Newtonian limit
    (τ0, G and the limiting shear out of reach) its stress is η̄ Δu/h × the Couette film's ratio at
    Na = β η̄ Δu²/k."""
    slip, speed, film, pressure, half_width = 0.5, 10.0, 1e-6, 5e8, 2e-4
    viscosity, alpha = 0.05, 1e-8  # η̄ = η0 e^(α p̄) = 7.4 Pa s
    huge = 1e30
    isothermal = traction.eyring_traction(slip, speed, film, pressure, half_width, viscosity, alpha, huge, huge, huge)
    mean_viscosity = viscosity * math.exp(alpha * pressure)
    assert isothermal * pressure == pytest.approx(mean_viscosity * slip / film, rel=1e-9)
    heating = nahme / (mean_viscosity * slip**2)  # β/k giving Na
    heated = traction.eyring_traction(slip, speed, film, pressure, half_width, viscosity, alpha, huge, huge, huge,
                                      heating)
    assert heated / isothermal == pytest.approx(couette_stress_ratio(nahme), rel=0.01)


def test_the_reduction_slope_is_its_derivative():
    """d ln R/d ln Na against a central difference, across the series switch and into the hot range."""
    for nahme in (1e-12, 3e-9, 1e-6, 0.1, 2.0, 50.0, 1e4):
        step = 1e-5
        ahead, behind = (math.log(nahme_reduction(nahme * math.exp(s))[0]) for s in (step, -step))
        assert nahme_reduction(nahme)[1] == pytest.approx((ahead - behind) / (2 * step), rel=1e-5, abs=1e-9)


def test_a_cool_film_is_not_reduced_and_a_hot_one_is():
    assert nahme_reduction(0.0) == (1.0, 0.0)
    assert nahme_reduction(1e-6)[0] == pytest.approx(1 - 1e-6 / 12, rel=1e-12)  # the series 1 − Na/12
    assert 0.0 < nahme_reduction(1e6)[0] < 0.01
