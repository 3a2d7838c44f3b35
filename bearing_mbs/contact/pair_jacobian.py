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
"""

from __future__ import annotations

import numba
import numpy as np

from bearing_mbs.contact import kinematics

_CIRCLE_LINE = kinematics.PAIR_KINDS.index("circle_line")
_CIRCLE_IN_CIRCLE = kinematics.PAIR_KINDS.index("circle_in_circle")


@numba.njit(cache=True)
def pair_motion_jacobian(kind, a, b, anchor_x, anchor_y, direction_x, direction_y, radius_b, q, v):
    """Derivatives of one pair's kinematics at (q, v): (∂gap/∂z, κ, ∂c_x/∂z, ∂c_y/∂z) over the 6 local
    coordinates, and (∂gap_rate, ∂slip, ∂rolling, ∂spin) over the 12 local coordinates and velocities (z, ż).
    Body a = −1 is the ground."""
    xa = ya = theta_a = vax = vay = omega_a = 0.0
    if a >= 0:
        xa, ya, theta_a = q[3 * a], q[3 * a + 1], q[3 * a + 2]
        vax, vay, omega_a = v[3 * a], v[3 * a + 1], v[3 * a + 2]
    xb, yb = q[3 * b], q[3 * b + 1]
    vbx, vby, omega_b = v[3 * b], v[3 * b + 1], v[3 * b + 2]
    cos_a, sin_a = np.cos(theta_a), np.sin(theta_a)
    rx, ry = cos_a * anchor_x - sin_a * anchor_y, sin_a * anchor_x + cos_a * anchor_y  # p − c_a
    dx, dy = xb - xa - rx, yb - ya - ry  # D
    d_dx = np.array([-1.0, 0.0, ry, 1.0, 0.0, 0.0])
    d_dy = np.array([0.0, -1.0, -rx, 0.0, 1.0, 0.0])
    # the point p's velocity, and D's rate
    dot_dx, dot_dy = vbx - vax + omega_a * ry, vby - vay - omega_a * rx
    rate_dx_q = np.zeros(6)
    rate_dy_q = np.zeros(6)
    rate_dx_q[2], rate_dy_q[2] = omega_a * rx, omega_a * ry
    rate_dx_v = np.array([-1.0, 0.0, ry, 1.0, 0.0, 0.0])
    rate_dy_v = np.array([0.0, -1.0, -rx, 0.0, 1.0, 0.0])

    turn_rate_q = np.zeros(6)
    turn_rate_v = np.zeros(6)
    if kind == _CIRCLE_LINE:
        nx, ny = cos_a * direction_x - sin_a * direction_y, sin_a * direction_x + cos_a * direction_y
        tx, ty = -ny, nx
        kappa = np.zeros(6)
        kappa[2] = 1.0
        gap_q = nx * d_dx + ny * d_dy + (dx * tx + dy * ty) * kappa
        turn_rate_v[2] = 1.0
    else:
        sigma = -1.0 if kind == _CIRCLE_IN_CIRCLE else 1.0
        distance = np.sqrt(dx * dx + dy * dy)
        nx, ny = sigma * dx / distance, sigma * dy / distance
        tx, ty = -ny, nx
        kappa = sigma * (tx * d_dx + ty * d_dy) / distance
        gap_q = nx * d_dx + ny * d_dy
        turn_rate = sigma * (tx * dot_dx + ty * dot_dy) / distance
        turn_rate_q = (sigma * (-kappa * (nx * dot_dx + ny * dot_dy) + tx * rate_dx_q + ty * rate_dy_q)
                       - turn_rate * sigma * (nx * d_dx + ny * d_dy)) / distance
        turn_rate_v = sigma * (tx * rate_dx_v + ty * rate_dy_v) / distance

    cx, cy = xb - radius_b * nx, yb - radius_b * ny
    c_x = np.array([0.0, 0.0, 0.0, 1.0, 0.0, 0.0]) - radius_b * tx * kappa
    c_y = np.array([0.0, 0.0, 0.0, 0.0, 1.0, 0.0]) - radius_b * ty * kappa
    # c − c_a and its derivative (c_a moves with x_a, y_a)
    arm_x, arm_y = cx - xa, cy - ya
    arm_x_q, arm_y_q = c_x.copy(), c_y.copy()
    if a >= 0:
        arm_x_q[0] -= 1.0
        arm_y_q[1] -= 1.0
    # surface velocities at c: v_b(c) = v_cb − r_b ω_b t, v_a(c) = v_ca + ω_a k × (c − c_a)
    vb_x, vb_y = vbx - radius_b * omega_b * tx, vby - radius_b * omega_b * ty
    va_x, va_y = vax - omega_a * arm_y, vay + omega_a * arm_x
    w_x, w_y = vb_x - va_x, vb_y - va_y
    s_x, s_y = vb_x + va_x, vb_y + va_y

    # over (z, ż): positions 0..5, velocities 6..11
    w_x_all, w_y_all = np.zeros(12), np.zeros(12)
    s_x_all, s_y_all = np.zeros(12), np.zeros(12)
    w_x_all[:6] = radius_b * omega_b * nx * kappa + omega_a * arm_y_q
    w_y_all[:6] = radius_b * omega_b * ny * kappa - omega_a * arm_x_q
    s_x_all[:6] = radius_b * omega_b * nx * kappa - omega_a * arm_y_q
    s_y_all[:6] = radius_b * omega_b * ny * kappa + omega_a * arm_x_q
    # ∂/∂(v_ax, v_ay, ω_a, v_bx, v_by, ω_b)
    w_x_all[6:] = np.array([-1.0, 0.0, arm_y, 1.0, 0.0, -radius_b * tx])
    w_y_all[6:] = np.array([0.0, -1.0, -arm_x, 0.0, 1.0, -radius_b * ty])
    s_x_all[6:] = np.array([1.0, 0.0, -arm_y, 1.0, 0.0, -radius_b * tx])
    s_y_all[6:] = np.array([0.0, 1.0, arm_x, 0.0, 1.0, -radius_b * ty])

    gap_rate, slip = nx * w_x + ny * w_y, tx * w_x + ty * w_y
    kappa_all = np.zeros(12)
    kappa_all[:6] = kappa
    gap_rate_all = kappa_all * slip + nx * w_x_all + ny * w_y_all
    slip_all = -kappa_all * gap_rate + tx * w_x_all + ty * w_y_all
    rolling_all = 0.5 * (-kappa_all * (nx * s_x + ny * s_y) + tx * s_x_all + ty * s_y_all)
    rolling_all += kappa_all * (nx * vbx + ny * vby)  # −∂t·v_cb
    rolling_all[9] -= tx
    rolling_all[10] -= ty
    rolling_all[:6] += radius_b * turn_rate_q
    rolling_all[6:] += radius_b * turn_rate_v
    spin_all = np.zeros(12)
    spin_all[11], spin_all[8] = 1.0, -1.0
    return gap_q, kappa, c_x, c_y, gap_rate_all, slip_all, rolling_all, spin_all
