"""Compiled per-pair kinematics: gap, normal, gap rate, slip and rolling speed of one pair at a time.

Scalar functions over one pair's columns, calling the very functions of :mod:`.kinematics` and
:mod:`.friction` (``register_jitable``: compiled inline here, plain Python elsewhere). The contact-pair force
element (:mod:`bearing_mbs.elements.contact_pairs`) and the per-pair state update (:mod:`.state`) use them;
:mod:`.twin` is the vectorised numpy counterpart.
"""

from __future__ import annotations

import numba
import numpy as np

from bearing_mbs.contact import friction, kinematics, traction

#: Columns of the per-pair output array, in order; units: m, m/s, m/s, N, N, N m, W, m/s.
PAIR_OUTPUTS = ("gap", "gap_rate", "slip", "normal_force", "friction_force", "rolling_moment", "power_loss",
                "rolling_speed")
N_PAIR_OUTPUTS = len(PAIR_OUTPUTS)


# Integer codes, read by numba as compile-time constants.
_CIRCLE_LINE = kinematics.PAIR_KINDS.index("circle_line")
_CIRCLE_IN_CIRCLE = kinematics.PAIR_KINDS.index("circle_in_circle")
_ERF, _TANH, _LINEAR, _DEAD_ZONE, _EHL = (friction.FRICTION_LAWS.index(n)
                                         for n in ("erf", "tanh", "linear", "dead_zone", "ehl"))


@numba.njit(cache=True)
def regularised_sign(law, speed, regularisation_speed):
    """Dispatch to the friction law with integer code ``law`` (see ``FRICTION_LAWS``)."""
    if law == _ERF or law == _EHL:
        return friction.erf_sign(speed, regularisation_speed)
    if law == _TANH:
        return friction.tanh_sign(speed, regularisation_speed)
    if law == _LINEAR:
        return friction.linear_sign(speed, regularisation_speed)
    if law == _DEAD_ZONE:
        return friction.dead_zone_sign(speed, regularisation_speed)
    return 0.0  # "none"


@numba.njit(cache=True)
def regularised_sign_slope(law, speed, regularisation_speed):
    """dφ/dv [s/m] of :func:`regularised_sign` (0 for ``none`` and, almost everywhere, the dead zone)."""
    if law == _ERF or law == _EHL:
        return friction.erf_sign_slope(speed, regularisation_speed)
    if law == _TANH:
        return friction.tanh_sign_slope(speed, regularisation_speed)
    if law == _LINEAR:
        return friction.linear_sign_slope(speed, regularisation_speed)
    return 0.0  # "none" and "dead_zone"


@numba.njit(cache=True, inline="always")
def tangential_force(law, normal_force, coefficient, slip, rolling, regularisation_speed, traction_row):
    """Friction force on body b [N] (along the tangent) of a pair in contact: μ F_N φ(v) for the Coulomb laws,
    the lubricated traction of :mod:`.traction` for ``ehl``."""
    if law == _EHL:
        if normal_force <= 0.0:
            return 0.0
        mu = traction.ehl_traction(traction_row, slip, rolling, normal_force, coefficient, regularisation_speed)[0]
        return -mu * normal_force
    return friction.friction_force(normal_force, coefficient, regularised_sign(law, slip, regularisation_speed))


@numba.njit(cache=True, inline="always")
def rolling_resistance(law, friction_force, normal_force, arm, spin, rolling, orientation, radius_a, radius_b, gap,
                       regularisation_speed, traction_row):
    """(tangential force [N], moment [N m]) on body b of a pair in contact: its ``friction_force`` plus what
    resists its rolling, the dry arm's moment against the relative spin ω_b − ω_a [rad/s] and, for ``ehl`` with it
    on, the hydrodynamic rolling resistance's tangential force and couple against the rolling speed u [m/s]
    (:mod:`.traction`); orientation and gap [m] place b against a's feature
    (:func:`.kinematics.contact_point_share`). Without the latter the friction force is returned as it came."""
    moment = 0.0
    if arm > 0.0:
        spin_sign = regularised_sign(law, spin * radius_b, regularisation_speed)
        moment = friction.rolling_resistance_moment(normal_force, arm, spin_sign)
    if law == _EHL:
        force = traction.rolling_force(traction_row, rolling, normal_force)
        if force > 0.0:
            share = kinematics.contact_point_share(orientation, radius_a, radius_b, gap)
            tangential, couple = traction.rolling_resistance(force, rolling, regularisation_speed, share, radius_b)
            return friction_force + tangential, moment + couple
    return friction_force, moment


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
