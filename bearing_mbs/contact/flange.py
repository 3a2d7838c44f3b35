r"""A roller's spherical end against a flange in three dimensions: a point contact (compiled).

The roller's end sphere (radius R_e, centre c = r_b + z_s R_b e₃ on its axis) against the flange, the plane through o
with unit normal a towards the roller (both carried by the ring): the approach is δ = R_e − (c − o)·a, at the sphere's
point P = c − R_e a, which must lie within the flange's band of distance from the line through o along a (the ring's
axis): inner <= |(P − o) − ((P − o)·a) a| <= outer. The load is Hertz's for a sphere on a plane (n = 3/2, K from
:func:`bearing_mbs.contact.point_contact.hertz_stiffness`) with the slices' stiffness-proportional damping,

.. math:: Q = K\,\delta^{\,n-1}(\delta + n\tau\dot\delta) \ge 0,

(its elastic part K δ^n storing K δ^(n+1)/(n+1), the rest dissipating) along a on the roller, with friction against the sliding velocity at P (:mod:`.contact_point`).
"""

from __future__ import annotations

import math

import numba

from bearing_mbs.contact.contact_point import NO_TRACTION, apply_contact, in_world, relative_velocity, touches
from bearing_mbs.contact.line_contact import power_law_energy, power_law_force


@numba.njit(cache=True)
def add_flanges(packed, active, position, rotation, velocity, omega_world, force, moment, flange_loads):
    """Add the forces [N] and moments [N m] (world frame, about the bodies' centres) of the flange contacts that
    touch an ``active`` body to ``force`` and ``moment`` and each one's load [N] into ``flange_loads[contact]``; the
    state as :func:`bearing_mbs.contact.sliced_raceway.add_sliced_raceways` takes it (and, as there, the loop over
    the contacts inside this call); returns the power they dissipate [W] and the energy they store [J]."""
    dissipated = stored = 0.0
    for contact in range(packed.flange_roller.size):
        if not touches(active, packed.flange_roller[contact], packed.flange_ring[contact]):
            continue
        b, g = packed.flange_roller[contact], packed.flange_ring[contact]
        o0, o1, o2, a0, a1, a2 = in_world(g, position, rotation, packed.flange_point[contact],
                                          packed.flange_normal[contact])
        flange_loads[contact] = 0.0
        z, radius = packed.flange_sphere[contact], packed.flange_end_radius[contact]
        # the arm of the sphere's point P nearest the flange, from the roller's centre
        l0 = z * rotation[b, 0, 2] - radius * a0
        l1 = z * rotation[b, 1, 2] - radius * a1
        l2 = z * rotation[b, 2, 2] - radius * a2
        r0, r1, r2 = position[b, 0] + l0 - o0, position[b, 1] + l1 - o1, position[b, 2] + l2 - o2  # P − o
        approach = -(r0 * a0 + r1 * a1 + r2 * a2)
        if approach <= 0.0:
            continue
        d0, d1, d2 = r0 + approach * a0, r1 + approach * a1, r2 + approach * a2  # radial part of P − o
        distance = math.sqrt(d0 * d0 + d1 * d1 + d2 * d2)
        if not packed.flange_band[contact, 0] <= distance <= packed.flange_band[contact, 1]:
            continue
        u0, u1, u2, p0, p1, p2 = relative_velocity(b, g, l0, l1, l2, position, velocity, omega_world)
        rate = -(a0 * u0 + a1 * u1 + a2 * u2)
        stiffness, exponent = packed.flange_stiffness[contact], packed.flange_exponent[contact]
        elastic = power_law_force(approach, stiffness, exponent)
        load = max(elastic * (1.0 + exponent * packed.flange_damping_time[contact] * rate / approach), 0.0)
        flange_loads[contact] = load
        friction = apply_contact(b, g, l0, l1, l2, p0, p1, p2, a0, a1, a2, load, load, u0, u1, u2,
                                 packed.flange_friction[contact], packed.flange_regularisation_speed[contact], force,
                                 moment, NO_TRACTION, 0.0)
        dissipated += (load - elastic) * rate + friction
        stored += power_law_energy(approach, stiffness, exponent)
    return dissipated, stored
