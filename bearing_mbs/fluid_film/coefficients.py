r"""Stiffness and damping of a film about an operating point, by central perturbation of the solver's force.

With F the film force on the journal, the eight linearised coefficients are

.. math:: K_{ij} = -\frac{\partial F_i}{\partial e_j},\qquad C_{ij} = -\frac{\partial F_i}{\partial \dot e_j},
          \qquad i, j \in \{x, y\},

taken by central differences with :math:`\Delta e = 10^{-3} C` and :math:`\Delta\dot e = \Delta e\,\max(|\Omega|,
1\,\mathrm{s^{-1}})` (J. W. Lund, "Review of the concept of dynamic coefficients for fluid film journal bearings",
J. Tribol. 109 (1987) 37–41). The static stiffness ΔF/Δe of document 001 is the slope of the load along the
eccentricity, the same derivative projected on the displacement.

Near the wall the step shrinks with the film: :math:`\Delta e = \min(10^{-3} C,\ 10^{-2}(C - |e|))` (:func:`eccentricity_step`),
so the perturbed journal stays inside the clearance for every ε < 1 and the step stays a fixed small fraction of the
gap, the length over which the film's force changes (it grows as :math:`(1 - \varepsilon)^{-k}`, so a central
difference's relative error is of order :math:`(\Delta e/(C - |e|))^2 = 10^{-4}` there). Near the centre it shrinks
with the eccentricity, to :math:`10^{-2}|e|` (not below :math:`10^{-6} C`): a step of 10⁻³ C turns the line of
centres of a hybrid bearing's equilibrium at |e| = 0.0025 C by 22°, and its whirl growth rate moved by 1.3 %. The step
is Lund's wherever 0.1 ≤ ε ≤ 0.9.
"""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np

from bearing_mbs.fluid_film.reynolds import JournalState

#: Relative perturbation of the eccentricity (of C) and of its rate (of the step times max(|Ω|, 1/s)).
PERTURBATION = 1e-3
#: Largest step as a fraction of the remaining gap C − |e|: it keeps |e| + Δe < C, and binds above ε = 0.9.
GAP_PERTURBATION = 1e-2
#: Largest step as a fraction of the eccentricity |e| (binds below ε = 0.1), and the smallest step (of C).
CENTRE_PERTURBATION = 1e-2
SMALLEST_PERTURBATION = 1e-6


def eccentricity_step(state: JournalState, clearance: float) -> float:
    """Δe [m] = min(:data:`PERTURBATION` C, :data:`GAP_PERTURBATION` (C − |e|), max(:data:`CENTRE_PERTURBATION`
    |e|, :data:`SMALLEST_PERTURBATION` C)) at ``state``, clearance C [m]."""
    eccentricity = math.hypot(*state.eccentricity)
    return min(PERTURBATION * clearance, GAP_PERTURBATION * (clearance - eccentricity),
               max(CENTRE_PERTURBATION * eccentricity, SMALLEST_PERTURBATION * clearance))


def dynamic_coefficients(force, state: JournalState, clearance: float) -> tuple[np.ndarray, np.ndarray]:
    """(K, C): 2×2 stiffness [N/m] and damping [N s/m] of ``force(state) -> (F_x, F_y)`` about ``state``."""
    delta_e = eccentricity_step(state, clearance)
    rate_step = delta_e * max(abs(state.speed), 1.0)
    stiffness, damping = np.zeros((2, 2)), np.zeros((2, 2))
    for j in range(2):
        shift = np.eye(2)[j]
        for matrix, field, delta in ((stiffness, "eccentricity", delta_e), (damping, "eccentricity_rate", rate_step)):
            base = np.asarray(getattr(state, field), dtype=float)
            plus = force(replace(state, **{field: tuple(base + delta * shift)}))
            minus = force(replace(state, **{field: tuple(base - delta * shift)}))
            matrix[:, j] = -(np.asarray(plus) - np.asarray(minus)) / (2 * delta)
    return stiffness, damping


def static_stiffness(force, state: JournalState, clearance: float) -> float:
    """ΔF/Δe [N/m]: minus the slope of ``force(state) -> (F_x, F_y)`` along the eccentricity's direction (x if
    centred), by a central difference of :func:`eccentricity_step`."""
    e = np.asarray(state.eccentricity, dtype=float)
    magnitude = math.hypot(*e)  # scaled: |e| of 1e-200 m does not underflow to 0 as its square does
    direction = e / magnitude if magnitude > 0 else np.array([1.0, 0.0])
    delta_e = eccentricity_step(state, clearance)
    plus = np.asarray(force(replace(state, eccentricity=tuple(e + delta_e * direction))))
    minus = np.asarray(force(replace(state, eccentricity=tuple(e - delta_e * direction))))
    return float(-direction @ (plus - minus) / (2 * delta_e))
