r"""Planar pair kinematics, kept apart from the force laws.

A contact pair joins a feature of body *a* (a line, a circle, a hollow circle or a point, fixed in a's
frame, or in the world when a is the ground) and a **circle** of radius :math:`r_b` centred on body *b*.
Each function returns the gap :math:`g` [m] (positive = clearance) and the unit normal :math:`n`, the
direction in which the normal force acts on body b. The contact point is on b's surface,
:math:`p = c_b - r_b n`. With :math:`v_{rel} = v_b(p) - v_a(p)`:

* gap rate :math:`\dot g = n \cdot v_{rel}` (exact: the rotational parts vanish along n for these shapes,
  and the tests check it against finite differences of the gap);
* slip speed :math:`v = t \cdot v_{rel}`, :math:`t = (-n_y, n_x)`;
* rolling speed :math:`u`: the mean speed of both surfaces relative to the moving contact point (see
  :func:`rolling_speed`).

Only ufuncs and arithmetic are used, so the numpy twin and the numba kernel share this source.
Coincident centres (e.g. a concentric cage and land) give :math:`n = 0` and no NaN.
"""

from __future__ import annotations

import numpy as np
from numba.extending import register_jitable

#: Pair kinds in the order of their integer codes in the compiled kernel.
PAIR_KINDS = ("circle_line", "circle_circle", "circle_in_circle", "circle_point")
#: Where b's circle sits against a's feature, per kind (see :func:`contact_point_share`): 0 on a line, +1 outside a
#: circle or point, −1 inside a hollow circle.
ORIENTATION = (0.0, 1.0, -1.0, 1.0)

_TINY = 1e-300


@register_jitable
def rotate(cos_theta, sin_theta, local_x, local_y):
    """World components of a vector (local_x, local_y) of a body turned by θ, given cos θ and sin θ."""
    return cos_theta * local_x - sin_theta * local_y, sin_theta * local_x + cos_theta * local_y


@register_jitable
def body_point(x, y, theta, local_x, local_y):
    """World position of a point fixed at (local_x, local_y) [m] in a body at (x, y, theta)."""
    rx, ry = rotate(np.cos(theta), np.sin(theta), local_x, local_y)
    return x + rx, y + ry


@register_jitable
def body_vector(theta, local_x, local_y):
    """World components of a vector fixed in a body rotated by theta [rad]."""
    return rotate(np.cos(theta), np.sin(theta), local_x, local_y)


@register_jitable
def point_velocity(vx, vy, omega, x, y, px, py):
    r"""Velocity [m/s] of the material point p of a body with centre (x, y): :math:`v + \omega \times (p-c)`."""
    return vx - omega * (py - y), vy + omega * (px - x)


@register_jitable
def circle_line(bx, by, radius_b, px, py, nx, ny):
    """Circle (centre b, radius_b) against a line through p with unit normal n pointing to the free side."""
    return (bx - px) * nx + (by - py) * ny - radius_b, nx, ny


@register_jitable
def circle_circle(bx, by, radius_b, px, py, radius_a):
    """Circle b outside circle a (centre p, radius_a); radius_a = 0 gives circle–point."""
    dx, dy = bx - px, by - py
    distance = np.sqrt(dx * dx + dy * dy)
    scale = 1.0 / np.maximum(distance, _TINY)
    return distance - radius_a - radius_b, dx * scale, dy * scale


@register_jitable
def circle_in_circle(bx, by, radius_b, px, py, radius_a):
    """Circle b inside the hollow circle a (centre p, radius_a); n points back towards a's centre."""
    dx, dy = bx - px, by - py
    distance = np.sqrt(dx * dx + dy * dy)
    scale = 1.0 / np.maximum(distance, _TINY)
    return radius_a - radius_b - distance, -dx * scale, -dy * scale


@register_jitable
def circle_point(bx, by, radius_b, px, py):
    """Circle b against a point p (a pocket edge): the circle–circle formula with zero radius."""
    return circle_circle(bx, by, radius_b, px, py, 0.0)


@register_jitable
def relative_motion(nx, ny, vbx, vby, vax, vay):
    """Gap rate [m/s] and slip speed [m/s] from the contact points' velocities on b and a."""
    rx, ry = vbx - vax, vby - vay
    return nx * rx + ny * ry, -ny * rx + nx * ry


@register_jitable
def centre_line_rate(nx, ny, relative_vx, relative_vy, distance):
    """Rotation rate [rad/s] of the line from a's centre point to b's centre (distance > 0), given b's
    centre velocity relative to that point: the normal of a circle–circle, hollow or point pair turns with
    it (with the opposite sign for the hollow circle, whose normal points inwards)."""
    return (-ny * relative_vx + nx * relative_vy) / distance


@register_jitable
def contact_point_share(orientation, radius_a, radius_b, gap):
    r"""The share w [-] of a's centre of curvature in the contact point's motion along the tangent,
    :math:`t\cdot\dot p = (1 - w)\,t\cdot\dot c_b + w\,t\cdot\dot c_a`, as :func:`rolling_speed` moves it:
    :math:`w = r_b/d` outside a circle or point (``orientation`` +1), :math:`-r_b/d` inside a hollow circle (−1),
    d the centres' distance; 0 on a line (0), where instead :math:`t\cdot\dot p = t\cdot\dot c_b - r_b\omega_a`."""
    distance = radius_a + orientation * (radius_b + gap)
    return orientation * radius_b / np.maximum(distance, _TINY)


@register_jitable
def rolling_speed(nx, ny, vbx, vby, vax, vay, cbvx, cbvy, radius_b, normal_rate):
    r"""Rolling (entrainment) speed [m/s]: the mean speed of the two surfaces relative to the moving contact
    point, :math:`u = t\cdot(v_b(p) + v_a(p))/2 - t\cdot\dot p` with :math:`\dot p = \dot c_b - r_b\dot\varphi t`
    (:math:`p = c_b - r_b n`, the normal turning at :math:`\dot\varphi`). Slip over rolling speed is the
    slip ratio of a rolling contact: 0 in pure rolling even against a fixed raceway."""
    contact_point_speed = -ny * cbvx + nx * cbvy - radius_b * normal_rate
    return 0.5 * (-ny * (vbx + vax) + nx * (vby + vay)) - contact_point_speed
