r"""Derivatives of one pair's kinematics (:mod:`.kernel`): what an analytic force Jacobian is built from.

A pair's quantities depend on the coordinates and velocities of its two bodies, ordered locally as
:math:`z = (x_a, y_a, \theta_a, x_b, y_b, \theta_b)` and :math:`\dot z` likewise (a's entries unused for the
ground). With :math:`D = c_b - p` (b's centre from a's feature point p), the normal n turns as
:math:`\partial n = t\,\kappa`, :math:`\partial t = -n\,\kappa` (t the tangent, κ the normal's angle per unit of
each coordinate):

* on a line of a: κ = ∂θ_a, and :math:`\partial g = n\cdot\partial D + (D\cdot t)\,\kappa`;
* outside a circle or point (σ = 1) or inside a hollow circle (σ = −1), :math:`n = \sigma D/|D|`,
  :math:`\kappa = \sigma\,t\cdot\partial D/|D|` and :math:`\partial g = n\cdot\partial D`.

The contact point :math:`c = c_b - r_b n` moves as :math:`\partial c_b - r_b t\,\kappa`. The relative velocity of
the surfaces at c, :math:`w = v_b(c) - v_a(c)`, gives the gap rate n·w and the slip t·w; their sum s gives the
rolling speed :math:`u = t\cdot s/2 - t\cdot\dot c_b + r_b\dot\varphi`, with :math:`\dot\varphi` the normal's
turning rate (ω_a on a line, :math:`\sigma\,t\cdot\dot D/|D|` on a circle). Differentiating these products term by
term is all there is; ``tests/test_jacobians.py`` holds every derivative to finite differences.

:func:`pair_motion_derivatives` writes them into the rows of a scratch array the caller allocates once for all its
pairs (an analytic Jacobian is evaluated pair after pair, and a dozen small arrays allocated per pair cost more than
the arithmetic); :func:`pair_motion_jacobian` returns them as arrays.
"""

from __future__ import annotations

import numba
import numpy as np

from bearing_mbs.contact import kinematics

_CIRCLE_LINE = kinematics.PAIR_KINDS.index("circle_line")
_CIRCLE_IN_CIRCLE = kinematics.PAIR_KINDS.index("circle_in_circle")

#: Rows of :func:`pair_motion_derivatives`' scratch (12 columns: z, then ż): over z alone (columns 0–5) the gap,
#: the normal's angle κ and the contact point's x and y; over (z, ż) the gap rate, slip, rolling speed, spin and the
#: normal's turning rate (an intermediate).
GAP, KAPPA, POINT_X, POINT_Y, GAP_RATE, SLIP, ROLLING, SPIN, TURN_RATE = range(9)
DERIVATIVE_ROWS, LOCAL_COLUMNS = 9, 12


def new_derivatives() -> np.ndarray:
    """A scratch array for :func:`pair_motion_derivatives` (its rows: :data:`GAP` … :data:`TURN_RATE`)."""
    return np.zeros((DERIVATIVE_ROWS, LOCAL_COLUMNS))


@numba.njit(cache=True)
def pair_motion_jacobian(kind, a, b, anchor_x, anchor_y, direction_x, direction_y, radius_b, q, v):
    """Derivatives of one pair's kinematics at (q, v): (∂gap/∂z, κ, ∂c_x/∂z, ∂c_y/∂z) over the 6 local
    coordinates, and (∂gap_rate, ∂slip, ∂rolling, ∂spin) over the 12 local coordinates and velocities (z, ż).
    Body a = −1 is the ground. (:func:`pair_motion_derivatives` into new arrays.)"""
    out = np.zeros((DERIVATIVE_ROWS, LOCAL_COLUMNS))
    pair_motion_derivatives(kind, a, b, anchor_x, anchor_y, direction_x, direction_y, radius_b, q, v, out)
    return (out[GAP, :6], out[KAPPA, :6], out[POINT_X, :6], out[POINT_Y, :6], out[GAP_RATE], out[SLIP],
            out[ROLLING], out[SPIN])


@numba.njit(cache=True)
def pair_motion_derivatives(kind, a, b, anchor_x, anchor_y, direction_x, direction_y, radius_b, q, v, out):
    """The derivatives of :func:`pair_motion_jacobian` into the rows of ``out`` (:func:`new_derivatives`),
    overwritten, without allocating."""
    xa = ya = theta_a = vax = vay = omega_a = 0.0
    if a >= 0:
        xa, ya, theta_a = q[3 * a], q[3 * a + 1], q[3 * a + 2]
        vax, vay, omega_a = v[3 * a], v[3 * a + 1], v[3 * a + 2]
    xb, yb = q[3 * b], q[3 * b + 1]
    vbx, vby, omega_b = v[3 * b], v[3 * b + 1], v[3 * b + 2]
    cos_a, sin_a = np.cos(theta_a), np.sin(theta_a)
    rx, ry = cos_a * anchor_x - sin_a * anchor_y, sin_a * anchor_x + cos_a * anchor_y  # p − c_a
    dx, dy = xb - xa - rx, yb - ya - ry  # D
    # ∂D/∂z; D's rate over z is ω_a (r_x, r_y) in θ_a alone, and over ż it is ∂D/∂z
    d_dx = (-1.0, 0.0, ry, 1.0, 0.0, 0.0)
    d_dy = (0.0, -1.0, -rx, 0.0, 1.0, 0.0)
    # the point p's velocity, and D's rate
    dot_dx, dot_dy = vbx - vax + omega_a * ry, vby - vay - omega_a * rx
    rate_dx_q = (0.0, 0.0, omega_a * rx, 0.0, 0.0, 0.0)
    rate_dy_q = (0.0, 0.0, omega_a * ry, 0.0, 0.0, 0.0)
    if kind == _CIRCLE_LINE:
        nx, ny = cos_a * direction_x - sin_a * direction_y, sin_a * direction_x + cos_a * direction_y
        tx, ty = -ny, nx
        along = dx * tx + dy * ty
        for i in range(6):
            kappa = 1.0 if i == 2 else 0.0
            out[KAPPA, i] = kappa
            out[GAP, i] = nx * d_dx[i] + ny * d_dy[i] + along * kappa
            out[TURN_RATE, i] = 0.0
            out[TURN_RATE, 6 + i] = kappa
    else:
        sigma = -1.0 if kind == _CIRCLE_IN_CIRCLE else 1.0
        distance = np.sqrt(dx * dx + dy * dy)
        nx, ny = sigma * dx / distance, sigma * dy / distance
        tx, ty = -ny, nx
        turn_rate = sigma * (tx * dot_dx + ty * dot_dy) / distance
        normal_rate = nx * dot_dx + ny * dot_dy
        for i in range(6):
            kappa = sigma * (tx * d_dx[i] + ty * d_dy[i]) / distance
            out[KAPPA, i] = kappa
            out[GAP, i] = nx * d_dx[i] + ny * d_dy[i]
            out[TURN_RATE, i] = (sigma * (-kappa * normal_rate + tx * rate_dx_q[i] + ty * rate_dy_q[i])
                                 - turn_rate * sigma * (nx * d_dx[i] + ny * d_dy[i])) / distance
            out[TURN_RATE, 6 + i] = sigma * (tx * d_dx[i] + ty * d_dy[i]) / distance

    cx, cy = xb - radius_b * nx, yb - radius_b * ny
    # c − c_a (c_a moves with x_a, y_a)
    arm_x, arm_y = cx - xa, cy - ya
    # surface velocities at c: v_b(c) = v_cb − r_b ω_b t, v_a(c) = v_ca + ω_a k × (c − c_a)
    vb_x, vb_y = vbx - radius_b * omega_b * tx, vby - radius_b * omega_b * ty
    va_x, va_y = vax - omega_a * arm_y, vay + omega_a * arm_x
    w_x, w_y = vb_x - va_x, vb_y - va_y
    s_x, s_y = vb_x + va_x, vb_y + va_y
    gap_rate, slip = nx * w_x + ny * w_y, tx * w_x + ty * w_y
    # ∂w and ∂s over (v_ax, v_ay, ω_a, v_bx, v_by, ω_b)
    w_x_v = (-1.0, 0.0, arm_y, 1.0, 0.0, -radius_b * tx)
    w_y_v = (0.0, -1.0, -arm_x, 0.0, 1.0, -radius_b * ty)
    s_x_v = (1.0, 0.0, -arm_y, 1.0, 0.0, -radius_b * tx)
    s_y_v = (0.0, 1.0, arm_x, 0.0, 1.0, -radius_b * ty)
    spin_b = radius_b * omega_b
    normal_sum, normal_centre = nx * s_x + ny * s_y, nx * vbx + ny * vby
    for i in range(LOCAL_COLUMNS):
        if i < 6:
            kappa = out[KAPPA, i]
            c_x = (1.0 if i == 3 else 0.0) - radius_b * tx * kappa
            c_y = (1.0 if i == 4 else 0.0) - radius_b * ty * kappa
            out[POINT_X, i], out[POINT_Y, i] = c_x, c_y
            arm_x_q = c_x - 1.0 if (a >= 0 and i == 0) else c_x
            arm_y_q = c_y - 1.0 if (a >= 0 and i == 1) else c_y
            w_x_i = spin_b * nx * kappa + omega_a * arm_y_q
            w_y_i = spin_b * ny * kappa - omega_a * arm_x_q
            s_x_i = spin_b * nx * kappa - omega_a * arm_y_q
            s_y_i = spin_b * ny * kappa + omega_a * arm_x_q
        else:
            kappa = 0.0
            out[GAP, i] = out[KAPPA, i] = out[POINT_X, i] = out[POINT_Y, i] = 0.0
            w_x_i, w_y_i, s_x_i, s_y_i = w_x_v[i - 6], w_y_v[i - 6], s_x_v[i - 6], s_y_v[i - 6]
        out[GAP_RATE, i] = kappa * slip + nx * w_x_i + ny * w_y_i
        out[SLIP, i] = -kappa * gap_rate + tx * w_x_i + ty * w_y_i
        rolling = 0.5 * (-kappa * normal_sum + tx * s_x_i + ty * s_y_i)
        rolling += kappa * normal_centre  # −∂t·v_cb
        if i == 9:
            rolling -= tx
        elif i == 10:
            rolling -= ty
        out[ROLLING, i] = rolling + radius_b * out[TURN_RATE, i]
        out[SPIN, i] = 1.0 if i == 11 else -1.0 if i == 8 else 0.0
