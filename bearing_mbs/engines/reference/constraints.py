r"""Holonomic constraints for the reference engine: index-1 accelerations plus SHAKE/RATTLE projection.

For constraints :math:`g(q) = 0` with Jacobian :math:`G`, the integrators use accelerations that satisfy
:math:`G\ddot q = \gamma := -\dot G\dot q` (the index-1 form, so every method keeps its order), and after
each accepted step they project (mass-weighted) back onto the constraint manifold:

* positions (SHAKE-type, Newton iterations): :math:`q \leftarrow q - M^{-1}G^T(GM^{-1}G^T)^{-1}g(q)`
  until :math:`|g| \le 10^{-14}` × the constraints' length scale;
* velocities (RATTLE-type): :math:`v \leftarrow v - M^{-1}G^T(GM^{-1}G^T)^{-1}Gv`.

All kinds are written in metres. With :math:`w = c_b - c_a`, :math:`u = \dot w`, :math:`\omega = \dot\theta_a`:

* distance L: :math:`g = (|w|^2 - L^2)/(2L)`, :math:`\partial g/\partial c_b = -\partial g/\partial c_a = w/L`,
  :math:`\dot G\dot q = |u|^2/L`;
* point on a line of body a (point p, unit direction d, both turning with a):
  :math:`g = d \times (c_b - p)`, :math:`\partial g/\partial c_b = -\partial g/\partial c_a = (-d_y, d_x)`,
  :math:`\partial g/\partial\theta_a = -d\cdot w`,
  :math:`\dot G\dot q = -2\omega\, d\cdot u - \omega^2\, d^\perp\cdot w` with :math:`d^\perp = (-d_y, d_x)`;
* orbit (b on the ray from the world origin along d, which turns with a): the same with :math:`p = 0`,
  :math:`w = c_b`, :math:`u = \dot c_b`, and no dependence on a's translation.

The tests check G and Ġq̇ against finite differences. Fixed coordinates have zero inverse mass, so neither
forces nor projections move them. Each constraint couples two bodies, so (G M⁻¹ Gᵀ) λ = r is solved as the sparse
system of the mass and G, body block by body block (:mod:`~bearing_mbs.engines.reference.block_elimination`): its
cost grows with the number of constraints, not with its cube.
"""

from __future__ import annotations

import numba
import numpy as np

from bearing_mbs.contact import kinematics
from bearing_mbs.engines.reference.block_elimination import assemble_constraints, factor, solve
from bearing_mbs.engines.reference.copies import copy_into

PROJECTION_TOLERANCE = 1e-14
MAX_PROJECTION_ITERATIONS = 20
_DISTANCE, _POINT_ON_LINE, _ORBIT = 0, 1, 2


@numba.njit(cache=True)
def constraint_rows(constraints, q, v, residual, rows, gamma):
    """Residuals g [m], Jacobian G compact in ``rows`` (C × 6: ∂g/∂ of body a's x, y, θ, then of body b's;
    overwritten) and γ = −Ġq̇ of all constraints."""
    for k in range(constraints.kind.size):
        a, b, kind = constraints.body_a[k], constraints.body_b[k], constraints.kind[k]
        translates = kind != _ORBIT  # an orbit is about the world origin: a's translation does not enter
        wx, wy = q[3 * b] - translates * q[3 * a], q[3 * b + 1] - translates * q[3 * a + 1]
        ux, uy = v[3 * b] - translates * v[3 * a], v[3 * b + 1] - translates * v[3 * a + 1]
        rows[k, 2] = rows[k, 5] = 0.0
        if kind == _DISTANCE:
            length = constraints.length[k]
            residual[k] = (wx * wx + wy * wy - length * length) / (2 * length)
            gx, gy = wx / length, wy / length
            gamma[k] = -(ux * ux + uy * uy) / length
        else:
            theta, omega = q[3 * a + 2], v[3 * a + 2]
            px = py = 0.0
            if translates:
                px, py = kinematics.body_point(q[3 * a], q[3 * a + 1], theta, constraints.anchor[k, 0],
                                               constraints.anchor[k, 1])
            dx, dy = kinematics.body_vector(theta, constraints.direction[k, 0], constraints.direction[k, 1])
            residual[k] = dx * (q[3 * b + 1] - py) - dy * (q[3 * b] - px)
            gx, gy = -dy, dx
            rows[k, 2] = -(dx * wx + dy * wy)
            gamma[k] = 2 * omega * (dx * ux + dy * uy) + omega * omega * (-dy * wx + dx * wy)
        if translates:
            rows[k, 0], rows[k, 1] = -gx, -gy
        else:
            rows[k, 0] = rows[k, 1] = 0.0
        rows[k, 3], rows[k, 4] = gx, gy


@numba.njit(cache=True, inline="always")
def times_rows(constraints, rows, x, k):
    """(G x)_k, with G compact in ``rows``."""
    a, b = 3 * constraints.body_a[k], 3 * constraints.body_b[k]
    total = 0.0
    for d in range(3):
        total += rows[k, d] * x[a + d] + rows[k, 3 + d] * x[b + d]
    return total


@numba.njit(cache=True)  # not inlined: one compiled copy of the block elimination serves the three callers
def _correction(constraints, inverse_mass, rows, system, right_hand_side):
    """Factor the system of the mass and G, and solve it for the multipliers λ of (G M⁻¹ Gᵀ) λ = r and the
    correction M⁻¹ Gᵀ λ that changes G·x by r (``right_hand_side``): into ``system.right_hand_side``, the
    correction first (n), then λ."""
    assemble_constraints(system, inverse_mass, rows, constraints.body_a, constraints.body_b)
    factor(system)
    n = inverse_mass.size
    system.right_hand_side[:n] = 0.0
    copy_into(system.right_hand_side[n:], right_hand_side)
    solve(system)
    return system.right_hand_side[:n], system.right_hand_side[n:]


@numba.njit(cache=True)
def add_constraint_accelerations(constraints, inverse_mass, q, v, a, system):
    """Make the accelerations ``a`` consistent with the constraints (index-1 form), in place, with ``system``
    (:func:`~bearing_mbs.engines.reference.block_elimination.block_system` of the constraints); returns the
    magnitude of each constraint force on its body b [N]."""
    c = constraints.kind.size
    residual, gamma = np.empty(c), np.empty(c)
    rows = np.empty((c, 6))
    constraint_rows(constraints, q, v, residual, rows, gamma)
    for k in range(c):
        gamma[k] -= times_rows(constraints, rows, a, k)
    correction, multipliers = _correction(constraints, inverse_mass, rows, system, gamma)
    for i in range(a.size):
        a[i] += correction[i]
    forces = np.empty(c)
    for k in range(c):
        forces[k] = abs(multipliers[k]) * np.hypot(rows[k, 3], rows[k, 4])
    return forces


@numba.njit(cache=True)
def length_scale(constraints, q):
    """A length [m] for the projection tolerance: the largest constraint length or body distance."""
    scale = 0.0
    for k in range(constraints.kind.size):
        a, b = constraints.body_a[k], constraints.body_b[k]
        scale = max(scale, constraints.length[k], np.hypot(q[3 * b] - q[3 * a], q[3 * b + 1] - q[3 * a + 1]))
    return scale


@numba.njit(cache=True)
def project_positions(constraints, inverse_mass, q, scale, system):
    """SHAKE-type Newton projection of q onto g(q) = 0; returns the final max |g| [m]."""
    c = constraints.kind.size
    residual, gamma = np.empty(c), np.empty(c)
    rows = np.empty((c, 6))
    for _ in range(MAX_PROJECTION_ITERATIONS):
        constraint_rows(constraints, q, q, residual, rows, gamma)
        if np.max(np.abs(residual)) <= PROJECTION_TOLERANCE * scale:
            break
        correction = _correction(constraints, inverse_mass, rows, system, residual)[0]
        for i in range(q.size):
            q[i] -= correction[i]
    return np.max(np.abs(residual))


@numba.njit(cache=True)
def project_velocities(constraints, inverse_mass, q, v, system):
    """RATTLE-type projection of v onto G v = 0, in place."""
    c = constraints.kind.size
    residual, gamma = np.empty(c), np.empty(c)
    rows = np.empty((c, 6))
    constraint_rows(constraints, q, v, residual, rows, gamma)
    for k in range(c):
        gamma[k] = times_rows(constraints, rows, v, k)
    correction = _correction(constraints, inverse_mass, rows, system, gamma)[0]
    for i in range(v.size):
        v[i] -= correction[i]
