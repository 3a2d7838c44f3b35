"""Readable numpy twin of :mod:`.kernel`: the same pair kinematics and friction-law dispatch, vectorised over
pairs (the functions of :mod:`.kinematics` and :mod:`.friction` on whole arrays). The contact-pair force
element's numpy twin uses it; the tests hold it to the compiled kernel (1e-12 relative).
"""

from __future__ import annotations

import numpy as np

from bearing_mbs.contact import friction, kinematics


def _body_columns(q, index):
    """(x, y, θ) columns of the bodies in ``index`` (zeros for the ground, index −1)."""
    ground = index < 0
    rows = np.where(ground, 0, index)
    state = q.reshape(-1, 3)[rows]
    state[ground] = 0.0
    return state[:, 0], state[:, 1], state[:, 2]


def pair_geometry(pairs, q, v):
    """Gap, gap rate, slip, normal, contact point, relative spin and rolling speed of all pairs (arrays)."""
    ax, ay, atheta = _body_columns(q, pairs.body_a)
    avx, avy, aomega = _body_columns(v, pairs.body_a)
    bx, by, _ = _body_columns(q, pairs.body_b)
    bvx, bvy, bomega = _body_columns(v, pairs.body_b)
    px, py = kinematics.body_point(ax, ay, atheta, pairs.anchor[:, 0], pairs.anchor[:, 1])
    rb = pairs.radius_b

    ra = pairs.radius_a
    pvx, pvy = kinematics.point_velocity(avx, avy, aomega, ax, ay, px, py)
    gap, nx, ny = np.zeros_like(rb), np.zeros_like(rb), np.zeros_like(rb)
    line = pairs.kind == kinematics.PAIR_KINDS.index("circle_line")
    hollow = pairs.kind == kinematics.PAIR_KINDS.index("circle_in_circle")
    outside = ~(line | hollow)  # circle_circle and circle_point (radius_a = 0)
    nlx, nly = kinematics.body_vector(atheta, pairs.direction[:, 0], pairs.direction[:, 1])
    for mask, result in (
        (line, lambda m: kinematics.circle_line(bx[m], by[m], rb[m], px[m], py[m], nlx[m], nly[m])),
        (hollow, lambda m: kinematics.circle_in_circle(bx[m], by[m], rb[m], px[m], py[m], ra[m])),
        (outside, lambda m: kinematics.circle_circle(bx[m], by[m], rb[m], px[m], py[m], ra[m])),
    ):
        gap[mask], nx[mask], ny[mask] = result(mask)
    distance = np.maximum(np.where(hollow, ra - rb - gap, gap + ra + rb), 1e-300)
    turning = kinematics.centre_line_rate(nx, ny, bvx - pvx, bvy - pvy, distance)
    normal_rate = np.where(line, aomega, np.where(hollow, -turning, turning))

    cx, cy = bx - rb * nx, by - rb * ny
    vbx, vby = kinematics.point_velocity(bvx, bvy, bomega, bx, by, cx, cy)
    vax, vay = kinematics.point_velocity(avx, avy, aomega, ax, ay, cx, cy)
    gap_rate, slip = kinematics.relative_motion(nx, ny, vbx, vby, vax, vay)
    rolling = kinematics.rolling_speed(nx, ny, vbx, vby, vax, vay, bvx, bvy, rb, normal_rate)
    return gap, gap_rate, slip, nx, ny, cx, cy, bomega - aomega, rolling


def regularised_sign(law, speed, regularisation_speed):
    """Apply each pair's friction law (integer codes as in ``FRICTION_LAWS``)."""
    sign = np.zeros_like(speed)
    for code, name in enumerate(friction.FRICTION_LAWS):
        mask = law == code
        sign[mask] = friction.FRICTION_SIGN[name](speed[mask], regularisation_speed[mask])
    return sign
