r"""Holonomic constraints for the reference engine: index-1 accelerations plus SHAKE/RATTLE projection.

For constraints :math:`g(q) = 0` with Jacobian :math:`G`, the integrators use accelerations that satisfy
:math:`G\ddot q = \gamma := -\dot G\dot q` (the index-1 form, so every method keeps its order), and after
each accepted step they project (mass-weighted) back onto the constraint manifold:

* positions (SHAKE-type, Newton iterations): :math:`q \leftarrow q - M^{-1}G^T(GM^{-1}G^T)^{-1}g(q)`
  until :math:`|g| \le 10^{-14}\,L^2`;
* velocities (RATTLE-type): :math:`v \leftarrow v - M^{-1}G^T(GM^{-1}G^T)^{-1}Gv`.

Distance constraint between centres a and b: :math:`g = \tfrac12(|c_b - c_a|^2 - L^2)`,
:math:`\partial g/\partial c_b = -\partial g/\partial c_a = d = c_b - c_a`,
:math:`\dot G\dot q = |\dot d|^2`.

Fixed coordinates have zero inverse mass, so neither forces nor projections move them.
"""

from __future__ import annotations

import numba
import numpy as np

PROJECTION_TOLERANCE = 1e-14
MAX_PROJECTION_ITERATIONS = 20


@numba.njit(cache=True)
def constraint_rows(constraints, q, v, residual, jacobian, gamma):
    """Residuals g, Jacobian G (C × n, overwritten) and γ = −Ġq̇ of all constraints."""
    jacobian[:, :] = 0.0
    for k in range(constraints.body_a.size):
        a, b = constraints.body_a[k], constraints.body_b[k]
        dx, dy = q[3 * b] - q[3 * a], q[3 * b + 1] - q[3 * a + 1]
        dvx, dvy = v[3 * b] - v[3 * a], v[3 * b + 1] - v[3 * a + 1]
        residual[k] = 0.5 * (dx * dx + dy * dy - constraints.length[k] ** 2)
        jacobian[k, 3 * b] = dx
        jacobian[k, 3 * b + 1] = dy
        jacobian[k, 3 * a] = -dx
        jacobian[k, 3 * a + 1] = -dy
        gamma[k] = -(dvx * dvx + dvy * dvy)


@numba.njit(cache=True)
def _multiplier_correction(inverse_mass, jacobian, right_hand_side):
    """M⁻¹Gᵀ(GM⁻¹Gᵀ)⁻¹ r: the mass-weighted correction that changes G·x by r."""
    weighted = jacobian * inverse_mass  # G M⁻¹ (row-scaled columns)
    multipliers = np.linalg.solve(weighted @ jacobian.T, right_hand_side)
    return weighted.T @ multipliers


@numba.njit(cache=True)
def add_constraint_accelerations(constraints, inverse_mass, q, v, a):
    """Make the accelerations ``a`` consistent with the constraints (index-1 form), in place."""
    c = constraints.body_a.size
    residual, gamma = np.empty(c), np.empty(c)
    jacobian = np.empty((c, q.size))
    constraint_rows(constraints, q, v, residual, jacobian, gamma)
    a += _multiplier_correction(inverse_mass, jacobian, gamma - jacobian @ a)


@numba.njit(cache=True)
def project_positions(constraints, inverse_mass, q):
    """SHAKE-type Newton projection of q onto g(q) = 0; returns the final max |g| [m²]."""
    c = constraints.body_a.size
    residual, gamma = np.empty(c), np.empty(c)
    jacobian = np.empty((c, q.size))
    scale = np.max(constraints.length) ** 2
    for _ in range(MAX_PROJECTION_ITERATIONS):
        constraint_rows(constraints, q, q, residual, jacobian, gamma)
        if np.max(np.abs(residual)) <= PROJECTION_TOLERANCE * scale:
            break
        q -= _multiplier_correction(inverse_mass, jacobian, residual)
    return np.max(np.abs(residual))


@numba.njit(cache=True)
def project_velocities(constraints, inverse_mass, q, v):
    """RATTLE-type projection of v onto G v = 0, in place."""
    c = constraints.body_a.size
    residual, gamma = np.empty(c), np.empty(c)
    jacobian = np.empty((c, q.size))
    constraint_rows(constraints, q, v, residual, jacobian, gamma)
    v -= _multiplier_correction(inverse_mass, jacobian, jacobian @ v)
