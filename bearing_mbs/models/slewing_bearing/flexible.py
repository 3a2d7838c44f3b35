r"""Flexible rings: the condensed ring matrices at every ball, between the diagonals and each ring's rigid motion.

Each ball's sector of each ring is the condensed 4×4 matrix of :mod:`.ring_stiffness` on its two raceway curvature
centres (r₁, a₁, r₂, a₂; node 1 the upper centre, node 2 the lower, radial outward and axial up in both rings);
sectors are independent ("assembled around the ring" block by block, as the thesis's model does). Ball j has the
local displacements z_j = (u₁, u₂, w₁, w₂) of the inner ring's centres relative to the inner ring's rigid motion
x and of the outer ring's (held) centres. Diagonal d joins an inner centre to an outer centre: with d = +1 the
inner centre is the upper one (e_d points up from the outer to the inner centre) and the outer the lower; with
d = −1 the reverse. So

.. math:: s_{jd} = A_0 e_d + B_j x + u_{j,\mathrm{in}(d)} - w_{j,\mathrm{out}(d)},

and the energy :math:`E = \sum_j \tfrac12 z_j^\mathsf T K z_j + \sum_{j,d}\Phi(|s_{jd}|)`, with K = diag(K_inner,
K_outer) and Φ′ = Q the diagonal's Hertz force (:mod:`.load_distribution`), is convex in z. For a given x each
ball's z_j minimises it (Newton on the 8×8 Hessian K + Σ PᵀDP, D = ∂(Qŝ)/∂s, batched over the balls); the bearing
then carries load = ∂E/∂x = Σ Bᵀ Q ŝ, with the analytic stiffness

.. math:: \frac{d\,\mathrm{load}}{dx} = \sum_j \Big[\sum_d B^\mathsf T D_d B
          - \Big(\sum_d B^\mathsf T D_d P_d\Big) H_j^{-1}\Big(\sum_d P_d^\mathsf T D_d B\Big)\Big],

the rigid-ring tangent less what the rings' flexibility gives way (a Schur complement). Rigid rings are the limit
K → ∞.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from bearing_mbs.models.slewing_bearing.ring_stiffness import ring_stiffness

#: P_d (2×8) of diagonal d = +1 (index 0) and d = −1 (index 1): +I on the inner node, −I on the outer node.
_PICK = np.zeros((2, 2, 8))
for _k, (_inner, _outer) in enumerate(((0, 1), (1, 0))):  # d = +1: inner upper (node 1), outer lower (node 2)
    _PICK[_k, :, 2 * _inner : 2 * _inner + 2] = np.eye(2)
    _PICK[_k, :, 4 + 2 * _outer : 4 + 2 * _outer + 2] = -np.eye(2)


@dataclass(frozen=True)
class FlexibleRings:
    """The 4×4 sector matrices [N/m] of the inner and the outer ring."""

    inner: np.ndarray
    outer: np.ndarray

    @classmethod
    def of(cls, pitch_diameter: float, mount: str, coefficients: str = "corrected") -> FlexibleRings:
        return cls(ring_stiffness(pitch_diameter, "inner", mount, coefficients),
                   ring_stiffness(pitch_diameter, "outer", mount, coefficients))

    @property
    def block(self) -> np.ndarray:
        matrix = np.zeros((8, 8))
        matrix[:4, :4], matrix[4:, 4:] = self.inner, self.outer
        return matrix


def _contacts(bearing, x, z):
    """Per ball and diagonal: s (N, 2, 2), Q (N, 2), Qŝ (N, 2, 2) and D = ∂(Qŝ)/∂s (N, 2, 2, 2); B (N, 2, 3)."""
    psi = bearing.azimuths
    c = np.cos(psi)
    b = np.zeros((bearing.balls, 2, 3))
    b[:, 0, 0], b[:, 1, 1], b[:, 1, 2] = c, 1.0, bearing.pitch_diameter / 2 * c
    a0, alpha = bearing.centre_distance, bearing.contact_angle
    unloaded = a0 * np.array([[math.cos(alpha), math.sin(alpha)], [math.cos(alpha), -math.sin(alpha)]])
    s = unloaded[None] + np.einsum("nki,i->nk", b, x)[:, None, :] + np.einsum("dkm,nm->ndk", _PICK, z)
    length = np.linalg.norm(s, axis=-1)
    approach = np.maximum(length - a0, 0.0)
    q = bearing.stiffness * approach**1.5
    slope = 1.5 * bearing.stiffness * np.sqrt(approach)
    unit = s / length[..., None]
    outer = np.einsum("ndk,ndl->ndkl", unit, unit)
    derivative = slope[..., None, None] * outer + (q / length)[..., None, None] * (np.eye(2) - outer)
    return s, q, q[..., None] * unit, derivative, b


class NotConverged(RuntimeError):
    """An iteration of the static solution did not reach its tolerance: the load distribution's Newton loop
    (:func:`~bearing_mbs.models.slewing_bearing.load_distribution.solve`; e.g. too few balls to hold the ring, a
    singular stiffness) or the ring sectors' relaxation (:func:`relax`; e.g. rings far softer than the contacts)."""


def relax(bearing, rings: FlexibleRings, x, z=None, tolerance: float = 1e-12, iterations: int = 60) -> np.ndarray:
    """Each ball's local displacements z (N, 8) [m] at the inner ring's rigid displacement x: the minimum of the
    energy in z, by Newton's method with a backtracking line search on the gradient."""
    block = rings.block
    z = np.zeros((bearing.balls, 8)) if z is None else np.array(z, dtype=float)
    for _ in range(iterations):
        _, _, force, derivative, _ = _contacts(bearing, x, z)
        gradient = z @ block + np.einsum("dkm,ndk->nm", _PICK, force)
        scale = max(np.abs(force).max(), 1.0)
        if np.abs(gradient).max() <= tolerance * scale:
            return z
        hessian = block[None] + np.einsum("dkm,ndkl,dlp->nmp", _PICK, derivative, _PICK)
        step = np.linalg.solve(hessian, -gradient[..., None])[..., 0]
        z = z + step
    raise NotConverged(f"the ring sectors did not settle in {iterations} iterations")


def flexible_state(bearing, rings: FlexibleRings, x, z=None):
    """(load (3,), stiffness (3, 3), ball loads Q (N, 2), contact angles (N, 2) [rad], z (N, 8)) at x."""
    x = np.asarray(x, dtype=float)
    z = relax(bearing, rings, x, z)
    s, q, force, derivative, b = _contacts(bearing, x, z)
    load = np.einsum("nki,ndk->i", b, force)
    rigid = np.einsum("nki,ndkl,nlj->ij", b, derivative, b)
    coupling = np.einsum("nki,ndkl,dlm->nim", b, derivative, _PICK)  # (N, 3, 8)
    hessian = rings.block[None] + np.einsum("dkm,ndkl,dlp->nmp", _PICK, derivative, _PICK)
    relief = np.einsum("nim,nmj->ij", coupling, np.linalg.solve(hessian, np.swapaxes(coupling, 1, 2)))
    angles = np.arctan2(np.abs(s[..., 1]), s[..., 0])
    return load, rigid - relief, q, angles, z
