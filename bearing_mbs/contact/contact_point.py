"""A contact point between a roller and a ring in three dimensions (compiled): the ring's features in the world
frame, the relative velocity of the two bodies' material points there, and the normal and friction forces applied
at it, with their reactions. Shared by
the sliced raceway contact (:mod:`.sliced_raceway`) and the flange contact (:mod:`.flange`).

Arms and velocities are in the world frame: l = P − r_b from the roller's centre, p = P − r_g from the ring's
(body index g, −1: the ground, which neither moves nor takes forces).
"""

from __future__ import annotations

import math

import numba
import numpy as np

from bearing_mbs.contact.friction import erf_sign
from bearing_mbs.contact.traction import ehl_traction

#: The traction row of a dry contact: none (the ``erf`` law).
NO_TRACTION = np.zeros(0)


@numba.njit(cache=True, inline="always")
def cross_add(a0, a1, a2, b0, b1, b2, out, row, factor):
    """out[row] += factor · (a × b)."""
    out[row, 0] += factor * (a1 * b2 - a2 * b1)
    out[row, 1] += factor * (a2 * b0 - a0 * b2)
    out[row, 2] += factor * (a0 * b1 - a1 * b0)


@numba.njit(cache=True, inline="always")
def touches(active, roller, ring):
    """A contact between ``roller`` and ``ring`` (−1: the ground) touches a body that ``active`` (bodies,) marks."""
    return active[roller] or (ring >= 0 and active[ring])


@numba.njit(cache=True, inline="always")
def in_world(g, position, rotation, point, direction):
    """A point [m] and a direction given in ring g's frame (the world's for the ground, g = −1) in the world frame:
    (p0, p1, p2, d0, d1, d2)."""
    p0, p1, p2, d0, d1, d2 = point[0], point[1], point[2], direction[0], direction[1], direction[2]
    if g < 0:
        return p0, p1, p2, d0, d1, d2
    r = rotation[g]
    return (position[g, 0] + r[0, 0] * p0 + r[0, 1] * p1 + r[0, 2] * p2,
            position[g, 1] + r[1, 0] * p0 + r[1, 1] * p1 + r[1, 2] * p2,
            position[g, 2] + r[2, 0] * p0 + r[2, 1] * p1 + r[2, 2] * p2,
            r[0, 0] * d0 + r[0, 1] * d1 + r[0, 2] * d2, r[1, 0] * d0 + r[1, 1] * d1 + r[1, 2] * d2,
            r[2, 0] * d0 + r[2, 1] * d1 + r[2, 2] * d2)


@numba.njit(cache=True, inline="always")
def relative_velocity(b, g, l0, l1, l2, position, velocity, omega_world):
    """The velocity [m/s] of roller b's material point at arm l against ring g's there, and the ring's arm p [m]:
    (u0, u1, u2, p0, p1, p2)."""
    w0, w1, w2 = omega_world[b, 0], omega_world[b, 1], omega_world[b, 2]
    u0 = velocity[b, 0] + w1 * l2 - w2 * l1
    u1 = velocity[b, 1] + w2 * l0 - w0 * l2
    u2 = velocity[b, 2] + w0 * l1 - w1 * l0
    p0 = p1 = p2 = 0.0
    if g >= 0:
        p0, p1, p2 = position[b, 0] + l0 - position[g, 0], position[b, 1] + l1 - position[g, 1], \
            position[b, 2] + l2 - position[g, 2]
        v0, v1, v2 = omega_world[g, 0], omega_world[g, 1], omega_world[g, 2]
        u0 -= velocity[g, 0] + v1 * p2 - v2 * p1
        u1 -= velocity[g, 1] + v2 * p0 - v0 * p2
        u2 -= velocity[g, 2] + v0 * p1 - v1 * p0
    return u0, u1, u2, p0, p1, p2


@numba.njit(cache=True, inline="always")
def axis_point_velocity(b, z, e0, e1, e2, velocity, omega_world):
    """The velocity [m/s] of roller b's point at z [m] along its axis e (world frame): v_b + ω_b × z e."""
    w0, w1, w2 = omega_world[b, 0], omega_world[b, 1], omega_world[b, 2]
    return (velocity[b, 0] + z * (w1 * e2 - w2 * e1), velocity[b, 1] + z * (w2 * e0 - w0 * e2),
            velocity[b, 2] + z * (w0 * e1 - w1 * e0))


@numba.njit(cache=True, inline="always")
def entrainment(b, l0, l1, l2, u0, u1, u2, q0, q1, q2, n0, n1, n2, velocity, omega_world):
    """The entrainment speed [m/s] at a contact point P (roller b's arm l, relative velocity u = v_b(P) − v_g(P)) that
    moves at Ṗ = q, and its direction (a unit vector, zero at rest): the mean velocity of the two surfaces relative to
    P, (v_b(P) + v_g(P))/2 − Ṗ, in the plane normal to n (the planar kinematics' rolling speed:
    :func:`bearing_mbs.contact.kinematics.rolling_speed`)."""
    w0, w1, w2 = omega_world[b, 0], omega_world[b, 1], omega_world[b, 2]
    m0 = velocity[b, 0] + w1 * l2 - w2 * l1 - 0.5 * u0 - q0
    m1 = velocity[b, 1] + w2 * l0 - w0 * l2 - 0.5 * u1 - q1
    m2 = velocity[b, 2] + w0 * l1 - w1 * l0 - 0.5 * u2 - q2
    normal = m0 * n0 + m1 * n1 + m2 * n2
    m0, m1, m2 = m0 - normal * n0, m1 - normal * n1, m2 - normal * n2
    speed = math.sqrt(m0 * m0 + m1 * m1 + m2 * m2)
    if speed == 0.0:
        return 0.0, 0.0, 0.0, 0.0
    return speed, m0 / speed, m1 / speed, m2 / speed


@numba.njit(cache=True, inline="always")
def apply_contact(b, g, l0, l1, l2, p0, p1, p2, n0, n1, n2, normal, load, u0, u1, u2, mu, regularisation, force,
                  moment, row, rolling):
    """Add to roller b, at arm l, the force ``normal`` · n [N] and the friction against the sliding velocity v_s (u
    without its part along n), with the opposite force on ring g at arm p; moments about the bodies' centres, all in
    the world frame. The friction is μ·load·erf(2|v_s|/v_reg) (the ``erf`` law), or, given a traction ``row``
    (:data:`bearing_mbs.contact.traction.TRACTION_COLUMNS`), the lubricated traction of
    :func:`bearing_mbs.contact.traction.ehl_traction` at the slip |v_s| and the entrainment speed ``rolling`` [m/s],
    μ then its boundary friction. Returns the power the friction dissipates, −F_T·v_s >= 0 [W]."""
    f0, f1, f2 = normal * n0, normal * n1, normal * n2
    dissipated = 0.0
    lubricated = row.size > 0
    if mu > 0.0 or lubricated:
        along = n0 * u0 + n1 * u1 + n2 * u2
        t0, t1, t2 = u0 - along * n0, u1 - along * n1, u2 - along * n2
        speed = math.sqrt(t0 * t0 + t1 * t1 + t2 * t2)
        if speed > 0.0:
            if lubricated:
                coefficient = ehl_traction(row, speed, rolling, load, mu, regularisation)[0]
            else:
                coefficient = mu * erf_sign(speed, regularisation)
            friction = -load * coefficient / speed
            f0, f1, f2 = f0 + friction * t0, f1 + friction * t1, f2 + friction * t2
            dissipated = -friction * speed * speed
    apply_force(b, g, l0, l1, l2, p0, p1, p2, f0, f1, f2, force, moment)
    return dissipated


@numba.njit(cache=True, inline="always")
def apply_couple(b, g, c0, c1, c2, moment):
    """Add the couple c [N m] (world frame) to roller b and its opposite to ring g (−1: the ground)."""
    moment[b, 0] += c0
    moment[b, 1] += c1
    moment[b, 2] += c2
    if g >= 0:
        moment[g, 0] -= c0
        moment[g, 1] -= c1
        moment[g, 2] -= c2


@numba.njit(cache=True, inline="always")
def apply_force(b, g, l0, l1, l2, p0, p1, p2, f0, f1, f2, force, moment):
    """Add the force f [N] to roller b at arm l and its opposite to ring g (−1: the ground) at arm p, with their
    moments about the bodies' centres, all in the world frame."""
    force[b, 0] += f0
    force[b, 1] += f1
    force[b, 2] += f2
    cross_add(l0, l1, l2, f0, f1, f2, moment, b, 1.0)
    if g >= 0:
        force[g, 0] -= f0
        force[g, 1] -= f1
        force[g, 2] -= f2
        cross_add(p0, p1, p2, f0, f1, f2, moment, g, -1.0)
