r"""A roller's end against a flange in three dimensions: a point contact (compiled).

The roller's end sphere (radius R_e, centre c = r_b + z_s R_b e₃ on its axis) against the flange, the plane through o
with unit normal a towards the roller (both carried by the ring): the approach is δ = R_e − (c − o)·a, at the sphere's
point P = c − R_e a, which must lie within the flange's band of distance from the line through o along a (the ring's
axis): inner <= |(P − o) − ((P − o)·a) a| <= outer. The load is Hertz's for a sphere on a plane (n = 3/2, K from
:func:`bearing_mbs.contact.point_contact.hertz_stiffness`) with the slices' stiffness-proportional damping,

.. math:: Q = K\,\delta^{\,n-1}(\delta + n\tau\dot\delta) \ge 0,

(its elastic part K δ^n storing K δ^(n+1)/(n+1), the rest dissipating) along a on the roller, with friction against the sliding velocity at P (:mod:`.contact_point`).

A flat end's rounded edge is a ring of such spheres (R_e the corner radius) whose centres lie on a circle about the
roller's axis: a contact on the rim puts its sphere's centre at c + R_b (ρ cos φ, ρ sin φ, 0), a point of the roller
that spins with it, and a skewed or tilted roller's rim meets the flange first on one side: the flange resists skew
and tilt to first order, which a sphere on the axis does only to second. (Points fixed in a frame that does not spin
would let the material pass through them: the normal force at a point off the lowest one then has a moment about the
roller's axis whose power is neither stored nor dissipated, 0.3 % of the energy moved in an axially loaded run.)
"""

from __future__ import annotations

import math

import numba

from bearing_mbs.contact.contact_point import (
    NO_TRACTION,
    apply_contact,
    apply_force,
    in_world,
    relative_velocity,
    touches,
)
from bearing_mbs.contact.line_contact import power_law_energy, power_law_force


@numba.njit(cache=True, inline="always")
def band_weight(distance, inner, outer, edge):
    """(w, ∂w/∂d) of a contact point at ``distance`` [m] from the flange's axis: 1 within the band [inner, outer] [m],
    falling to 0 over ``edge`` [m] beyond it by the smooth step 3x² − 2x³ (the flange's rounded edges, so that a point
    crossing an edge loads and unloads continuously and its stored energy w E stays the work done on it); ``edge``
    0: a sharp band."""
    if edge == 0.0:
        return (1.0, 0.0) if inner <= distance <= outer else (0.0, 0.0)
    x, y = (distance - inner) / edge + 1.0, (outer - distance) / edge + 1.0
    if x <= 0.0 or y <= 0.0:
        return 0.0, 0.0
    step_x, slope_x = (1.0, 0.0) if x >= 1.0 else (x * x * (3.0 - 2.0 * x), 6.0 * x * (1.0 - x))
    step_y, slope_y = (1.0, 0.0) if y >= 1.0 else (y * y * (3.0 - 2.0 * y), 6.0 * y * (1.0 - y))
    return step_x * step_y, (slope_x * step_y - step_x * slope_y) / edge


@numba.njit(cache=True)
def add_flanges(packed, active, position, rotation, velocity, omega_world, force, moment, flange_loads):
    """Add the forces [N] and moments [N m] (world frame, about the bodies' centres) of the flange contacts that
    touch an ``active`` body to ``force`` and ``moment`` and each one's load [N] into ``flange_loads[contact]``; the
    state as :func:`bearing_mbs.contact.sliced_raceway.add_sliced_raceways` takes it (and, as there, the loop over
    the contacts inside this call); returns the power they dissipate [W] and the energy they store [J]. The points of
    one rim (``flange_group``: their count at the first, 0 at the others) are passed over together when the rim's
    lowest point along the flange's normal, its centre circle's radius ρ times |e₃ × a| below the axis, cannot reach
    the flange."""
    dissipated = stored = 0.0
    skip_until = 0
    for contact in range(packed.flange_roller.size):
        if not touches(active, packed.flange_roller[contact], packed.flange_ring[contact]):
            continue
        flange_loads[contact] = 0.0
        if contact < skip_until:  # a point of a rim that cannot reach its flange
            continue
        b, g = packed.flange_roller[contact], packed.flange_ring[contact]
        o0, o1, o2, a0, a1, a2 = in_world(g, position, rotation, packed.flange_point[contact],
                                          packed.flange_normal[contact])
        z, radius = packed.flange_sphere[contact], packed.flange_end_radius[contact]
        group = packed.flange_group[contact]
        if group > 1:  # the first of a rim's points: none reaches the flange if the rim's lowest point cannot
            e0, e1, e2 = rotation[b, 0, 2], rotation[b, 1, 2], rotation[b, 2, 2]
            tilt = e0 * a0 + e1 * a1 + e2 * a2
            reach = radius + packed.flange_group_radius[contact] * math.sqrt(max(1.0 - tilt * tilt, 0.0)) - (
                (position[b, 0] + z * e0 - o0) * a0 + (position[b, 1] + z * e1 - o1) * a1
                + (position[b, 2] + z * e2 - o2) * a2)
            if reach <= 0.0:
                skip_until = contact + group
                continue
        # the sphere's centre from the roller's centre, R_b (ρ cos φ, ρ sin φ, z_s): on the axis, or a point of the
        # end's rim that spins with the roller
        along, across = packed.flange_rim[contact, 0], packed.flange_rim[contact, 1]
        x0 = along * rotation[b, 0, 0] + across * rotation[b, 0, 1] + z * rotation[b, 0, 2]
        x1 = along * rotation[b, 1, 0] + across * rotation[b, 1, 1] + z * rotation[b, 1, 2]
        x2 = along * rotation[b, 2, 0] + across * rotation[b, 2, 1] + z * rotation[b, 2, 2]
        # the arm of the sphere's point P nearest the flange, from the roller's centre
        l0 = x0 - radius * a0
        l1 = x1 - radius * a1
        l2 = x2 - radius * a2
        r0, r1, r2 = position[b, 0] + l0 - o0, position[b, 1] + l1 - o1, position[b, 2] + l2 - o2  # P − o
        approach = -(r0 * a0 + r1 * a1 + r2 * a2)
        if approach <= 0.0:
            continue
        d0, d1, d2 = r0 + approach * a0, r1 + approach * a1, r2 + approach * a2  # radial part of P − o
        distance = math.sqrt(d0 * d0 + d1 * d1 + d2 * d2)
        weight, slope = band_weight(distance, packed.flange_band[contact, 0], packed.flange_band[contact, 1],
                                    packed.flange_edge[contact])
        if weight == 0.0:
            continue
        u0, u1, u2, p0, p1, p2 = relative_velocity(b, g, l0, l1, l2, position, velocity, omega_world)
        rate = -(a0 * u0 + a1 * u1 + a2 * u2)
        stiffness, exponent = packed.flange_stiffness[contact], packed.flange_exponent[contact]
        elastic = weight * power_law_force(approach, stiffness, exponent)
        load = max(elastic * (1.0 + exponent * packed.flange_damping_time[contact] * rate / approach), 0.0)
        flange_loads[contact] = load
        friction = apply_contact(b, g, l0, l1, l2, p0, p1, p2, a0, a1, a2, load, load, u0, u1, u2,
                                 packed.flange_friction[contact], packed.flange_regularisation_speed[contact], force,
                                 moment, NO_TRACTION, 0.0)
        energy = power_law_energy(approach, stiffness, exponent)
        if slope != 0.0:  # over the rounded edge: the radial force −(∂w/∂d) E of the stored energy w E, through the
            # sphere's centre (the energy depends on the centre alone)
            radial = -slope * energy / distance
            apply_force(b, g, x0, x1, x2, p0 + radius * a0, p1 + radius * a1, p2 + radius * a2, radial * d0,
                        radial * d1, radial * d2, force, moment)
        dissipated += (load - elastic) * rate + friction
        stored += weight * energy
    return dissipated, stored
