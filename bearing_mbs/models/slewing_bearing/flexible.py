r"""Flexible rings: each ball's sectors of the two rings, between the balls' diagonals and the rings' rigid motion.

**Which node is which.** The condensed 4×4 matrices of :mod:`.ring_stiffness` act on two raceway curvature centres
(r₁, a₁, r₂, a₂; radial outward, axial up). Node 1 is the centre of the ring's *upper* raceway arc, node 2 that of
its lower arc, in both rings: a ball touches the upper arc above its centre, so that arc's centre lies *below* the
ball centre, on the contact line through the ball. The matrices say so themselves (``tests/test_slewing_flexible.py``):
each node is stiff along its contact line and soft across it (inner ring: node 1 along (1, −1), node 2 along
(1, 1); outer ring the mirror image), and clamping a ring's bolted face (the inner ring's bottom, the outer ring's
top) stiffens most the node of the arc nearest that face. So the diagonal d = +1 (from the outer ring's lower
centre up to the inner ring's upper centre, :mod:`.load_distribution`) joins the outer ring's node 1 to the inner
ring's node 2, and d = −1 the inner ring's node 1 to the outer ring's node 2.

**Coupling** (``coupling``). The thesis's finite-element sector ties each curvature centre rigidly to the raceway
inside the contact ellipse (its model takes the ellipse's semi-axes a, b as parameters). So a matrix's compliance
C = K⁻¹ holds two things: the ring's structural deformation, which both centres share, and the local indentation
and rocking of each rigid ellipse, which only its own centre sees. The ball's Hertz spring already carries the
local part (Hertz's approach is the half-space's, to far from the contact). We split C = S + L with S the part the
two nodes share: S₁₂ = C₁₂ and, from the SVD C₁₂ = U Σ Vᵀ, S₁₁ = U Σ Uᵀ, S₂₂ = V Σ Vᵀ (the smallest positive
semi-definite completion, S = W Σ Wᵀ with W = [U; V]). What remains, L, is block diagonal by construction, and it
behaves as a local compliance must: along the contact line 4.0–6.5e-10 m/N whatever the diameter (0.5–2.5 m) and
the mount (free or clamped), where S changes a hundredfold; Galin's rigid elliptical punch on a half-space with the
thesis's ellipse (a = 8.298 mm, b = 1.304 mm) gives 5.67e-10 m/N (``tests/test_slewing_flexible.py``).

* ``structural`` (default): the rings enter through S only: two coordinates η per ring and ball, the centres
  moving by W η with the energy ½ ηᵀ Σ⁻¹ η.
* ``full_matrix``: the whole matrix K on the centres (η the centres' displacements, 8 per ball), in series with
  the Hertz springs: counts the contacts' local deformation twice (kept to show what it does, docs/slewing.md).

The sectors are independent ("assembled around the ring" block by block, as the thesis's model does) and massless:
for each inner-ring displacement every ball's η minimises its energy
(:func:`bearing_mbs.elements.slewing_balls.ball_state`, which the force element shares); the bearing's stiffness
is the rigid-ring tangent less a Schur complement for what the sectors give way. Rigid rings are the limit K → ∞.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property

import numpy as np

from bearing_mbs.elements.slewing_balls import flexible_bearing_state
from bearing_mbs.models.slewing_bearing.ring_stiffness import ring_stiffness
from bearing_mbs.spec import SpecError

COUPLINGS = ("structural", "full_matrix")
#: A shared mode whose compliance is below this fraction of the matrix's largest compliance is rigid (left out).
SHARED_FLOOR = 1e-9

#: The matrix node (0: node 1, the upper arc's centre; 1: node 2) of the inner and the outer ring on each diagonal
#: (index 0: d = +1, the inner ring's upper centre and the outer ring's lower one; index 1: d = −1).
NODES_ON_DIAGONAL = ((1, 0), (0, 1))


def split_compliance(stiffness: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """A sector matrix's compliance C = K⁻¹ [m/N] split as S + L (module docstring): returns (W (4, 2), Σ (2,),
    L (4, 4)) with S = W diag(Σ) Wᵀ the part the two nodes share and L the block-diagonal rest."""
    compliance = np.linalg.inv(stiffness)
    u, sigma, vt = np.linalg.svd(compliance[:2, 2:])
    shared = np.vstack([u, vt.T])
    return shared, sigma, compliance - shared @ np.diag(sigma) @ shared.T


def _picks() -> np.ndarray:
    """P_d (2, 2, 8): the diagonal's separation gains +I of its inner-ring node and −I of its outer-ring node."""
    picks = np.zeros((2, 2, 8))
    for d, (inner, outer) in enumerate(NODES_ON_DIAGONAL):
        picks[d, :, 2 * inner: 2 * inner + 2] = np.eye(2)
        picks[d, :, 4 + 2 * outer: 4 + 2 * outer + 2] = -np.eye(2)
    return picks


@dataclass(frozen=True)
class FlexibleRings:
    """Each ball's ring sectors: ``modes`` M_d (2, 2, m) [m per unit of η] moving diagonal d's separation, and the
    sectors' stiffness ``sector`` K_η (m, m); ``inner`` and ``outer`` are the 4×4 matrices [N/m] they come from."""

    inner: np.ndarray
    outer: np.ndarray
    coupling: str = "structural"

    def __post_init__(self):
        if self.coupling not in COUPLINGS:
            raise SpecError("coupling", self.coupling, f"one of {', '.join(COUPLINGS)}")

    @classmethod
    def of(cls, pitch_diameter: float, mount: str, coefficients: str = "corrected",
           coupling: str = "structural") -> FlexibleRings:
        return cls(ring_stiffness(pitch_diameter, "inner", mount, coefficients),
                   ring_stiffness(pitch_diameter, "outer", mount, coefficients), coupling)

    @cached_property
    def _basis(self) -> tuple[np.ndarray, np.ndarray]:
        """(Φ (8, m): the eight centre displacements per unit of η, K_η (m, m))."""
        if self.coupling == "full_matrix":
            stiffness = np.zeros((8, 8))
            stiffness[:4, :4], stiffness[4:, 4:] = self.inner, self.outer
            return np.eye(8), stiffness
        columns, compliance = [], []
        for k, matrix in enumerate((self.inner, self.outer)):
            shared, sigma, _ = split_compliance(matrix)
            for column, value in zip(shared.T, sigma):
                if value > SHARED_FLOOR * np.abs(np.linalg.inv(matrix)).max():  # else the nodes share nothing
                    columns.append(np.concatenate([column, np.zeros(4)] if k == 0 else [np.zeros(4), column]))
                    compliance.append(value)
        return np.array(columns, dtype=float).reshape(-1, 8).T, np.diag(1.0 / np.array(compliance, dtype=float))

    @property
    def modes(self) -> np.ndarray:
        return np.einsum("dkc,cm->dkm", _picks(), self._basis[0])

    @property
    def sector(self) -> np.ndarray:
        return self._basis[1]


class NotConverged(RuntimeError):
    """An iteration of the static solution did not reach its tolerance: the load distribution's Newton loop
    (:func:`~bearing_mbs.models.slewing_bearing.load_distribution.solve`; e.g. too few balls to hold the ring, a
    singular stiffness) or a ball's ring sectors (:func:`flexible_state`; e.g. rings far softer than the contacts)."""


def flexible_state(bearing, rings: FlexibleRings, x, eta=None):
    """(load (3,), stiffness (3, 3), ball loads Q (N, 2), contact angles (N, 2) [rad], sector coordinates η (N, m))
    at the inner ring's displacement x, every ball's η relaxed from ``eta`` (default 0)."""
    modes, sector = rings.modes, rings.sector
    eta = np.zeros((bearing.balls, sector.shape[0])) if eta is None else np.array(eta, dtype=float)
    load, stiffness, loads, s, _, converged = flexible_bearing_state(
        bearing.balls, bearing.pitch_diameter / 2, bearing.centre_distance, bearing.contact_angle, bearing.stiffness,
        np.ascontiguousarray(modes), np.ascontiguousarray(sector), np.asarray(x, dtype=float), eta)
    if not converged:
        raise NotConverged("the ring sectors did not settle: a ball's relaxation did not converge")
    return load, stiffness, loads, np.arctan2(np.abs(s[..., 1]), s[..., 0]), eta
