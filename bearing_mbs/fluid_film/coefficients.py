r"""Stiffness and damping of a film about an operating point, by central perturbation of the solver's force.

With F the film force on the journal, the eight linearised coefficients are

.. math:: K_{ij} = -\frac{\partial F_i}{\partial e_j},\qquad C_{ij} = -\frac{\partial F_i}{\partial \dot e_j},
          \qquad i, j \in \{x, y\},

taken by central differences with :math:`\Delta e = 10^{-3} C` and :math:`\Delta\dot e = 10^{-3} C\max(|\Omega|,
1\,\mathrm{s^{-1}})` (J. W. Lund, "Review of the concept of dynamic coefficients for fluid film journal bearings",
J. Tribol. 109 (1987) 37–41). The static stiffness ΔF/Δe of document 001 is the slope of the load along the
eccentricity, the same derivative projected on the displacement.
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np

from bearing_mbs.fluid_film.reynolds import JournalState

#: Relative perturbation of the eccentricity (of C) and of its rate (of C·max(|Ω|, 1/s)).
PERTURBATION = 1e-3


def dynamic_coefficients(force, state: JournalState, clearance: float) -> tuple[np.ndarray, np.ndarray]:
    """(K, C): 2×2 stiffness [N/m] and damping [N s/m] of ``force(state) -> (F_x, F_y)`` about ``state``."""
    step = PERTURBATION * clearance
    rate_step = step * max(abs(state.speed), 1.0)
    stiffness, damping = np.zeros((2, 2)), np.zeros((2, 2))
    for j in range(2):
        shift = np.eye(2)[j]
        for matrix, field, delta in ((stiffness, "eccentricity", step), (damping, "eccentricity_rate", rate_step)):
            base = np.asarray(getattr(state, field), dtype=float)
            plus = force(replace(state, **{field: tuple(base + delta * shift)}))
            minus = force(replace(state, **{field: tuple(base - delta * shift)}))
            matrix[:, j] = -(np.asarray(plus) - np.asarray(minus)) / (2 * delta)
    return stiffness, damping


def static_stiffness(force, state: JournalState, clearance: float) -> float:
    """ΔF/Δe [N/m]: minus the slope of ``force(state) -> (F_x, F_y)`` along the eccentricity's direction (x if
    centred), by a central difference of :data:`PERTURBATION` C."""
    e = np.asarray(state.eccentricity, dtype=float)
    direction = e / np.linalg.norm(e) if np.any(e) else np.array([1.0, 0.0])
    step = PERTURBATION * clearance
    plus = np.asarray(force(replace(state, eccentricity=tuple(e + step * direction))))
    minus = np.asarray(force(replace(state, eccentricity=tuple(e - step * direction))))
    return float(-direction @ (plus - minus) / (2 * step))
