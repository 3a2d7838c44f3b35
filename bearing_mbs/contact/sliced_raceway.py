r"""A roller against a cylindrical raceway in three dimensions: document 003's sliced line contact with exact
kinematics (compiled).

Slice k of the roller (centre r_b, rotation R_b, axis R_b e₃) has its centre at c_k = r_b + z_k R_b e₃. Its distance
from the raceway's axis (point o, unit direction a) is d_k = |(c_k − o) − ((c_k − o)·a) a|, along the unit normal
n_k pointing away from the axis. With the side's sign s (+1: the raceway is a ring's outer surface and the roller lies
outside it; −1: a bore with the roller inside), the slice's interference is

.. math::
    \Delta_k = s\,(R - d_k) + r - h_k,

R the raceway's radius, r the roller's, h_k the crown drops. To first order in the tilts this is document 003's
Δ_k = δ + α z_k − h_k (the approach δ at the roller's centre, the relative tilt α: eq. 12 there). A slice in contact
carries

.. math::
    Q_k = C_f\,w\,\Delta_k^{\,n-1}\,(\Delta_k + n\tau\dot\Delta_k) \ge 0,

the slice law of document 003 (eqs. 14–16) with stiffness-proportional damping (τ [s]: the slice's tangent stiffness
n C_f w Δ^(n−1) times τ), Δ̇_k = −s n_k·(ċ_k − v_ring(c_k)) from the roller's and the ring's rigid motions. The
force s Q_k n_k acts on the roller at its surface point P_k = c_k − s r n_k, and its reaction on the ring there; its
moment about the roller's centre is z_k R_b e₃ × s Q_k n_k (the part along n_k has no arm). The slice's friction
opposes the sliding velocity v_s of the roller's material point at P_k against the ring's, in the tangent plane:
F_T = −μ Q_k erf(2|v_s|/v_reg) v_s/|v_s| (the planar model's ``erf`` law, :mod:`.friction`, on the speed), at P_k.
"""

from __future__ import annotations

import math

import numba

from bearing_mbs.contact.friction import erf_sign


@numba.njit(cache=True, inline="always")
def _cross_add(a0, a1, a2, b0, b1, b2, out, row, factor):
    """out[row] += factor · (a × b)."""
    out[row, 0] += factor * (a1 * b2 - a2 * b1)
    out[row, 1] += factor * (a2 * b0 - a0 * b2)
    out[row, 2] += factor * (a0 * b1 - a1 * b0)


@numba.njit(cache=True)
def add_sliced_raceway(packed, contact, position, rotation, velocity, omega_world, force, moment, slice_loads):
    """Add raceway contact ``contact``'s forces [N] and moments about the bodies' centres [N m], both in the world
    frame, to ``force`` and ``moment`` (bodies × 3), and its slice loads Q_k [N] into ``slice_loads[contact]``.
    position, velocity (bodies × 3) [m, m/s], rotation (bodies × 3 × 3), omega_world (bodies × 3) [rad/s]."""
    b, g = packed.race_roller[contact], packed.race_ring[contact]
    s, radius, roller_radius = packed.race_side[contact], packed.race_radius[contact], packed.race_roller_radius[contact]
    coefficient = packed.race_coefficient[contact] * packed.race_width[contact]
    exponent, tau = packed.race_exponent[contact], packed.race_damping_time[contact]
    mu, regularisation = packed.race_friction[contact], packed.race_regularisation_speed[contact]
    # the raceway's axis in the world frame
    o0, o1, o2 = packed.race_centre[contact, 0], packed.race_centre[contact, 1], packed.race_centre[contact, 2]
    a0, a1, a2 = packed.race_axis[contact, 0], packed.race_axis[contact, 1], packed.race_axis[contact, 2]
    if g >= 0:
        rg = rotation[g]
        o0, o1, o2 = (position[g, 0] + rg[0, 0] * o0 + rg[0, 1] * o1 + rg[0, 2] * o2,
                      position[g, 1] + rg[1, 0] * o0 + rg[1, 1] * o1 + rg[1, 2] * o2,
                      position[g, 2] + rg[2, 0] * o0 + rg[2, 1] * o1 + rg[2, 2] * o2)
        a0, a1, a2 = (rg[0, 0] * a0 + rg[0, 1] * a1 + rg[0, 2] * a2, rg[1, 0] * a0 + rg[1, 1] * a1 + rg[1, 2] * a2,
                      rg[2, 0] * a0 + rg[2, 1] * a1 + rg[2, 2] * a2)
    e0, e1, e2 = rotation[b, 0, 2], rotation[b, 1, 2], rotation[b, 2, 2]  # the roller's axis
    w0, w1, w2 = omega_world[b, 0], omega_world[b, 1], omega_world[b, 2]
    for k in range(packed.race_slices[contact]):
        z = packed.race_positions[contact, k]
        c0, c1, c2 = position[b, 0] + z * e0, position[b, 1] + z * e1, position[b, 2] + z * e2
        r0, r1, r2 = c0 - o0, c1 - o1, c2 - o2
        along = r0 * a0 + r1 * a1 + r2 * a2
        d0, d1, d2 = r0 - along * a0, r1 - along * a1, r2 - along * a2
        d = math.sqrt(d0 * d0 + d1 * d1 + d2 * d2)
        interference = s * (radius - d) + roller_radius - packed.race_drops[contact, k]
        slice_loads[contact, k] = 0.0
        if interference <= 0.0 or d == 0.0:
            continue
        n0, n1, n2 = d0 / d, d1 / d, d2 / d
        # the arm of the roller's material point at P_k, and its velocity relative to the ring's there
        l0, l1, l2 = z * e0 - s * roller_radius * n0, z * e1 - s * roller_radius * n1, z * e2 - s * roller_radius * n2
        u0 = velocity[b, 0] + w1 * l2 - w2 * l1
        u1 = velocity[b, 1] + w2 * l0 - w0 * l2
        u2 = velocity[b, 2] + w0 * l1 - w1 * l0
        if g >= 0:
            p0, p1, p2 = position[b, 0] + l0 - position[g, 0], position[b, 1] + l1 - position[g, 1], \
                position[b, 2] + l2 - position[g, 2]
            v0, v1, v2 = omega_world[g, 0], omega_world[g, 1], omega_world[g, 2]
            u0 -= velocity[g, 0] + v1 * p2 - v2 * p1
            u1 -= velocity[g, 1] + v2 * p0 - v0 * p2
            u2 -= velocity[g, 2] + v0 * p1 - v1 * p0
        normal_speed = n0 * u0 + n1 * u1 + n2 * u2
        rate = -s * normal_speed
        load = max(coefficient * interference ** (exponent - 1.0) * (interference + exponent * tau * rate), 0.0)
        slice_loads[contact, k] = load
        f = s * load  # the normal force on the roller is f n
        f0, f1, f2 = f * n0, f * n1, f * n2
        if mu > 0.0:  # friction against the sliding velocity in the tangent plane
            t0, t1, t2 = u0 - normal_speed * n0, u1 - normal_speed * n1, u2 - normal_speed * n2
            speed = math.sqrt(t0 * t0 + t1 * t1 + t2 * t2)
            if speed > 0.0:
                friction = -mu * load * erf_sign(speed, regularisation) / speed
                f0, f1, f2 = f0 + friction * t0, f1 + friction * t1, f2 + friction * t2
        force[b, 0] += f0
        force[b, 1] += f1
        force[b, 2] += f2
        _cross_add(l0, l1, l2, f0, f1, f2, moment, b, 1.0)
        if g >= 0:
            force[g, 0] -= f0
            force[g, 1] -= f1
            force[g, 2] -= f2
            _cross_add(p0, p1, p2, f0, f1, f2, moment, g, -1.0)  # at P_k, about the ring's centre
