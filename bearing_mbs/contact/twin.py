"""Readable numpy twin of :mod:`.kernel`: the same laws and kinematics, vectorised over pairs.

It calls the functions of :mod:`.kinematics`, :mod:`.normal` and :mod:`.friction` on whole arrays and
assembles with ``np.add.at``. It is the ``python`` connector of the Exudyn engine and the reference the
tests hold the compiled kernel to (1e-12 relative).
"""

from __future__ import annotations

import numpy as np

from bearing_mbs.contact import friction, kinematics, normal
from bearing_mbs.contact.kernel import N_PAIR_OUTPUTS


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


def scene_forces(packed, t, q, v, latched, forces, pair_out, complete=True):
    """Same contract as :func:`bearing_mbs.contact.kernel.scene_forces`; always complete (``complete`` is
    accepted for the same call signature)."""
    pairs = packed.pairs
    gap, gap_rate, slip, nx, ny, cx, cy, spin, rolling = pair_geometry(pairs, q, v)
    approach = normal.reference_approach_speed(latched, gap_rate, pairs.approach_speed_floor)
    fn = normal.hysteresis_force(gap, gap_rate, pairs.stiffness, pairs.exponent, pairs.damping_factor, approach)
    ft = friction.friction_force(
        fn, pairs.friction_coefficient, regularised_sign(pairs.friction_law, slip, pairs.regularisation_speed)
    )
    spin_sign = regularised_sign(pairs.friction_law, spin * pairs.radius_b, pairs.regularisation_speed)
    moment = friction.rolling_resistance_moment(fn, pairs.rolling_resistance_arm, spin_sign)
    damping = fn - normal.elastic_force(gap, pairs.stiffness, pairs.exponent)
    loss = -damping * gap_rate - ft * slip - moment * spin

    fx, fy = fn * nx - ft * ny, fn * ny + ft * nx
    qb = q.reshape(-1, 3)
    a, b = pairs.body_a, pairs.body_b
    torque_b = (cx - qb[b, 0]) * fy - (cy - qb[b, 1]) * fx + moment
    body_forces = np.zeros((q.size // 3, 3))
    np.add.at(body_forces, b, np.column_stack([fx, fy, torque_b]))
    on_a = a >= 0
    ai = a[on_a]
    torque_a = (cx[on_a] - qb[ai, 0]) * fy[on_a] - (cy[on_a] - qb[ai, 1]) * fx[on_a] + moment[on_a]
    np.add.at(body_forces, ai, -np.column_stack([fx[on_a], fy[on_a], torque_a]))

    supplied = 0.0
    velocities = v.reshape(-1, 3)
    for j, body in enumerate(packed.load_body):
        start, count = packed.load_profile[j]
        scale = np.interp(t, packed.profile_times[start : start + count], packed.profile_values[start : start + count])
        body_forces[body] += scale * packed.load_vector[j]
        supplied += scale * packed.load_vector[j] @ velocities[body]
    for j, body in enumerate(packed.drive_body):
        start, count = packed.drive_profile[j]
        speed = np.interp(t, packed.profile_times[start : start + count], packed.profile_values[start : start + count])
        torque = packed.drive_gain[j] * (speed - velocities[body, 2])
        body_forces[body, 2] += torque
        supplied += torque * velocities[body, 2]

    dissipated = loss.sum()
    for j, body in enumerate(packed.drag_body):
        coefficients = np.array([packed.drag_linear[j], packed.drag_linear[j], packed.drag_angular[j]])
        body_forces[body] -= coefficients * velocities[body]
        dissipated += coefficients @ velocities[body] ** 2

    forces[:] = body_forces.ravel()
    pair_out[:, :N_PAIR_OUTPUTS] = np.column_stack([gap, gap_rate, slip, fn, ft, moment, loss, rolling])
    return supplied, dissipated
