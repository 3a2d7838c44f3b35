"""Compiled evaluation of all forces of a packed scene except gravity and constraint forces: contacts, loads,
drives and drags.

:func:`scene_forces` loops over the contact pairs, calling the very functions of :mod:`.kinematics`,
:mod:`.normal` and :mod:`.friction` (``register_jitable``: compiled inline here, plain Python elsewhere), then adds the
time-profile loads and the velocity servos. Both engines call it: the reference integrators from compiled code, Exudyn through one
``ObjectGenericODE2`` force user function. :mod:`.twin` is its readable numpy counterpart; the tests hold
the two to 1e-12.
"""

from __future__ import annotations

import numba
import numpy as np

from bearing_mbs.contact import friction, kinematics, normal

#: Columns of the per-pair output array, in order; units: m, m/s, m/s, N, N, N m, W, m/s.
PAIR_OUTPUTS = ("gap", "gap_rate", "slip", "normal_force", "friction_force", "rolling_moment", "power_loss",
                "rolling_speed")
N_PAIR_OUTPUTS = len(PAIR_OUTPUTS)


# Integer codes, read by numba as compile-time constants.
_CIRCLE_LINE = kinematics.PAIR_KINDS.index("circle_line")
_CIRCLE_IN_CIRCLE = kinematics.PAIR_KINDS.index("circle_in_circle")
_ERF, _TANH, _LINEAR, _DEAD_ZONE = (friction.FRICTION_LAWS.index(n) for n in ("erf", "tanh", "linear", "dead_zone"))


@numba.njit(cache=True)
def regularised_sign(law, speed, regularisation_speed):
    """Dispatch to the friction law with integer code ``law`` (see ``FRICTION_LAWS``)."""
    if law == _ERF:
        return friction.erf_sign(speed, regularisation_speed)
    if law == _TANH:
        return friction.tanh_sign(speed, regularisation_speed)
    if law == _LINEAR:
        return friction.linear_sign(speed, regularisation_speed)
    if law == _DEAD_ZONE:
        return friction.dead_zone_sign(speed, regularisation_speed)
    return 0.0  # "none"


@numba.njit(cache=True)
def profile_value(times, values, start, count, t):
    """Value at time t of the piecewise-linear profile stored at [start, start + count) of the tables."""
    return np.interp(t, times[start : start + count], values[start : start + count])


@numba.njit(cache=True, inline="always")
def body_trigonometry(q):
    """cos θ and sin θ of every body, computed once per evaluation rather than once per pair."""
    bodies = q.size // 3
    cos_theta, sin_theta = np.empty(bodies), np.empty(bodies)
    for i in range(bodies):
        cos_theta[i], sin_theta[i] = np.cos(q[3 * i + 2]), np.sin(q[3 * i + 2])
    return cos_theta, sin_theta


@numba.njit(cache=True, inline="always")
def pair_position(kind, a, b, anchor_x, anchor_y, direction_x, direction_y, ra, rb, q, cos_a, sin_a):
    """Gap, normal and a's feature point (px, py) of one pair, from positions only.

    Scalars in, scalars out, on purpose: passing the PairArrays tuple into any call (inlined or not) costs
    ~0.1–0.4 µs of reference counting per pair, more than the geometry. Callers loop over the pairs and pass
    the pair's columns and body a's cos θ, sin θ (1, 0 for the ground) from :func:`body_trigonometry`.
    """
    ax = ay = 0.0
    if a >= 0:
        ax, ay = q[3 * a], q[3 * a + 1]
    rx, ry = kinematics.rotate(cos_a, sin_a, anchor_x, anchor_y)
    px, py = ax + rx, ay + ry
    bx, by = q[3 * b], q[3 * b + 1]
    if kind == _CIRCLE_LINE:
        nlx, nly = kinematics.rotate(cos_a, sin_a, direction_x, direction_y)
        gap, nx, ny = kinematics.circle_line(bx, by, rb, px, py, nlx, nly)
    elif kind == _CIRCLE_IN_CIRCLE:
        gap, nx, ny = kinematics.circle_in_circle(bx, by, rb, px, py, ra)
    else:  # circle_circle, and circle_point with radius_a = 0
        gap, nx, ny = kinematics.circle_circle(bx, by, rb, px, py, ra)
    return gap, nx, ny, px, py


@numba.njit(cache=True, inline="always")
def pair_motion(kind, a, b, ra, rb, gap, nx, ny, px, py, q, v):
    """Gap rate, slip, contact point, relative spin and rolling speed of one pair, after :func:`pair_position`."""
    bx, by = q[3 * b], q[3 * b + 1]
    bvx, bvy, bomega = v[3 * b], v[3 * b + 1], v[3 * b + 2]
    ax = ay = avx = avy = aomega = 0.0
    if a >= 0:
        ax, ay = q[3 * a], q[3 * a + 1]
        avx, avy, aomega = v[3 * a], v[3 * a + 1], v[3 * a + 2]
    pvx, pvy = kinematics.point_velocity(avx, avy, aomega, ax, ay, px, py)
    if kind == _CIRCLE_LINE:
        normal_rate = aomega
    elif kind == _CIRCLE_IN_CIRCLE:
        normal_rate = -kinematics.centre_line_rate(nx, ny, bvx - pvx, bvy - pvy, max(ra - rb - gap, 1e-300))
    else:
        normal_rate = kinematics.centre_line_rate(nx, ny, bvx - pvx, bvy - pvy, max(gap + ra + rb, 1e-300))
    cx, cy = bx - rb * nx, by - rb * ny
    vbx, vby = kinematics.point_velocity(bvx, bvy, bomega, bx, by, cx, cy)
    vax, vay = kinematics.point_velocity(avx, avy, aomega, ax, ay, cx, cy)
    gap_rate, slip = kinematics.relative_motion(nx, ny, vbx, vby, vax, vay)
    rolling = kinematics.rolling_speed(nx, ny, vbx, vby, vax, vay, bvx, bvy, rb, normal_rate)
    return gap_rate, slip, cx, cy, bomega - aomega, rolling


@numba.njit(cache=True, inline="always")  # inlined into the integrators: no per-call reference counting
def scene_forces(packed, t, q, v, latched, forces, pair_out, complete=True):
    """Generalized forces [N, N, N m per body] of contacts, loads and drives, written into ``forces``.

    ``pair_out`` (pairs × :data:`PAIR_OUTPUTS`) receives each pair's gap, gap rate, slip, forces, the power it
    dissipates and its rolling speed. Returns (input power of loads and drives, dissipated power) [W].
    ``complete=False`` (inside integration stages) skips the velocity-level outputs of pairs apart, which no
    force needs (about a third of the evaluation for a bearing, where most pocket and upper raceway pairs are
    apart): their gap rate, slip and rolling speed are left 0.
    Gravity and constraint forces are the engines' business.
    """
    forces[:] = 0.0
    pairs = packed.pairs
    dissipated = 0.0
    cos_theta, sin_theta = body_trigonometry(q)
    for k in range(pairs.kind.size):
        a, b, kind = pairs.body_a[k], pairs.body_b[k], pairs.kind[k]
        ra, rb = pairs.radius_a[k], pairs.radius_b[k]
        gap, nx, ny, px, py = pair_position(
            kind, a, b, pairs.anchor[k, 0], pairs.anchor[k, 1], pairs.direction[k, 0], pairs.direction[k, 1],
            ra, rb, q, cos_theta[a] if a >= 0 else 1.0, sin_theta[a] if a >= 0 else 0.0)
        gap_rate = slip = spin = rolling = 0.0
        if complete or gap < 0.0:
            gap_rate, slip, cx, cy, spin, rolling = pair_motion(kind, a, b, ra, rb, gap, nx, ny, px, py, q, v)
        fn = ft = moment = loss = 0.0
        if gap < 0.0:
            approach = normal.reference_approach_speed(latched[k], gap_rate, pairs.approach_speed_floor[k])
            elastic = normal.elastic_force(gap, pairs.stiffness[k], pairs.exponent[k])
            fn = max(elastic * normal.hysteresis_factor(gap_rate, pairs.damping_factor[k], approach), 0.0)
            law, vreg = pairs.friction_law[k], pairs.regularisation_speed[k]
            ft = friction.friction_force(fn, pairs.friction_coefficient[k], regularised_sign(law, slip, vreg))
            arm = pairs.rolling_resistance_arm[k]
            if arm > 0.0:
                spin_sign = regularised_sign(law, spin * pairs.radius_b[k], vreg)
                moment = friction.rolling_resistance_moment(fn, arm, spin_sign)
            loss = -(fn - elastic) * gap_rate - ft * slip - moment * spin
            fx, fy = fn * nx - ft * ny, fn * ny + ft * nx
            forces[3 * b] += fx
            forces[3 * b + 1] += fy
            forces[3 * b + 2] += (cx - q[3 * b]) * fy - (cy - q[3 * b + 1]) * fx + moment
            if a >= 0:
                forces[3 * a] -= fx
                forces[3 * a + 1] -= fy
                forces[3 * a + 2] -= (cx - q[3 * a]) * fy - (cy - q[3 * a + 1]) * fx + moment
        pair_out[k, 0] = gap
        pair_out[k, 1] = gap_rate
        pair_out[k, 2] = slip
        pair_out[k, 3] = fn
        pair_out[k, 4] = ft
        pair_out[k, 5] = moment
        pair_out[k, 6] = loss
        pair_out[k, 7] = rolling
        dissipated += loss
    supplied = 0.0
    for j in range(packed.load_body.size):
        scale = profile_value(
            packed.profile_times, packed.profile_values, packed.load_profile[j, 0], packed.load_profile[j, 1], t
        )
        for c in range(3):
            i = 3 * packed.load_body[j] + c
            forces[i] += scale * packed.load_vector[j, c]
            supplied += scale * packed.load_vector[j, c] * v[i]
    for j in range(packed.drive_body.size):
        speed = profile_value(
            packed.profile_times, packed.profile_values, packed.drive_profile[j, 0], packed.drive_profile[j, 1], t
        )
        i = 3 * packed.drive_body[j] + 2
        torque = packed.drive_gain[j] * (speed - v[i])
        forces[i] += torque
        supplied += torque * v[i]
    for j in range(packed.drag_body.size):
        i = 3 * packed.drag_body[j]
        linear, angular = packed.drag_linear[j], packed.drag_angular[j]
        forces[i] -= linear * v[i]
        forces[i + 1] -= linear * v[i + 1]
        forces[i + 2] -= angular * v[i + 2]
        dissipated += linear * (v[i] ** 2 + v[i + 1] ** 2) + angular * v[i + 2] ** 2
    return supplied, dissipated
