"""The film's stiffness by central differences near the wall (bearing_mbs.fluid_film.coefficients).

Reference, not from the code under test: Ocvirk's steady short bearing (closed_forms.short_bearing_components,
F. W. Ocvirk, NACA TN 2808, 1952), F_n = −B ε²/(1 − ε²)², F_t = B π ε/(4 (1 − ε²)^(3/2)), B = μΩRL³/C², turned
with the line of centres; its stiffness differentiated by hand:

  K_xx = −F_n'(ε)/C, K_yx = −F_t'(ε)/C (along the eccentricity, on x), K_xy = F_t/e, K_yy = −F_n/e (across it, where
  the force turns with the line of centres), with F_n' = −2Bε(1 + ε²)/(1 − ε²)³, F_t' = Bπ(1 + 2ε²)/(4(1 − ε²)^(5/2)).

A central difference of step Δe errs by about (Δe/(C − e))² times a constant of order (k + 1)(k + 2)/6 for a force
growing as (1 − ε)^(−k) (k ≤ 3 here): the step, 1e-2 of the gap above ε = 0.9, gives 2e-4 (measured: 2.0e-4 of the
largest entry from ε = 0.9 to 0.9999, 9e-6 at 0.5); 5e-4 is held. Lund's fixed step 1e-3 C reaches the wall at
ε = 0.999 (a division by zero here, past the clearance in the Reynolds solver) and crosses it above.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from bearing_mbs.fluid_film import closed_forms
from bearing_mbs.fluid_film.coefficients import dynamic_coefficients, static_stiffness
from bearing_mbs.fluid_film.reynolds import JournalState

#: A short bearing: radius, length, clearance [m], viscosity [Pa s], speed [rad/s].
RADIUS, LENGTH, CLEARANCE, VISCOSITY, OMEGA = 0.0375, 0.01, 35e-6, 0.028, 100.0


def ocvirk_force(state: JournalState) -> tuple[float, float]:
    """The steady short bearing's (F_x, F_y) [N] at the state's eccentricity (its rate ignored)."""
    e_x, e_y = state.eccentricity
    e = math.hypot(e_x, e_y)
    f_n, f_t = closed_forms.short_bearing_components(e / CLEARANCE, state.speed, RADIUS, LENGTH, CLEARANCE, VISCOSITY)
    n_x, n_y = e_x / e, e_y / e
    return f_n * n_x - f_t * n_y, f_n * n_y + f_t * n_x


def ocvirk_stiffness(eps: float) -> np.ndarray:
    """K [N/m] of the steady short bearing at ε, eccentricity on x, differentiated by hand."""
    base = VISCOSITY * OMEGA * RADIUS * LENGTH**3 / CLEARANCE**2
    f_n, f_t = -base * eps**2 / (1 - eps**2) ** 2, base * math.pi * eps / (4 * (1 - eps**2) ** 1.5)
    dn = -base * 2 * eps * (1 + eps**2) / (1 - eps**2) ** 3
    dt = base * math.pi * (1 + 2 * eps**2) / (4 * (1 - eps**2) ** 2.5)
    e = eps * CLEARANCE
    return np.array([[-dn / CLEARANCE, f_t / e], [-dt / CLEARANCE, -f_n / e]])


@pytest.mark.parametrize("eps", [0.5, 0.9, 0.99, 0.999, 0.9999])
def test_the_stiffness_by_central_differences_matches_the_closed_form_up_to_the_wall(eps):
    state = JournalState((eps * CLEARANCE, 0.0), (0.0, 0.0), OMEGA)
    expected = ocvirk_stiffness(eps)
    stiffness, _ = dynamic_coefficients(ocvirk_force, state, CLEARANCE)
    assert np.abs(stiffness - expected).max() < 5e-4 * np.abs(expected).max()
    assert static_stiffness(ocvirk_force, state, CLEARANCE) == pytest.approx(expected[0, 0], rel=5e-4)


def test_the_perturbed_journal_stays_inside_the_clearance():
    """At ε = 0.999 in any direction every perturbed eccentricity is < C (Lund's 1e-3 C would reach it)."""
    seen = []

    def recording_force(state):
        seen.append(math.hypot(*state.eccentricity))
        return ocvirk_force(state)

    for angle in np.linspace(0.0, 2 * np.pi, 7):
        e = 0.999 * CLEARANCE
        state = JournalState((e * math.cos(angle), e * math.sin(angle)), (0.0, 0.0), OMEGA)
        dynamic_coefficients(recording_force, state, CLEARANCE)
        static_stiffness(recording_force, state, CLEARANCE)
    assert max(seen) < CLEARANCE
