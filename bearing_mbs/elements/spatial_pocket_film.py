r"""The oil film between a roller and a flat cage pocket wall in three dimensions, slice by slice (compiled; here
rather than among the contacts because it joins their kinematics to :mod:`bearing_mbs.fluid_film`'s law).

The wall is a plane carried by the ring body g (the cage): through o with unit normal a towards the roller. Slice k of
the roller (centre c_k = r_b + z_k R_b e₃, radius r, width w) has the gap h_k = (c_k − o)·a − r to it (floored at
the film's smallest gap, three roughnesses), at the surface point P_k = c_k − r a; the relative velocity of the
roller's material point there against the wall's, u = v_b(P) − v_g(P), gives the gap rate ḣ = a·u and the sliding
velocity u_t = u − (a·u) a; the entrainment is the mean surface velocity relative to the moving point P (which turns
with the wall, Ṗ = ċ_k − r ω_g × a), in the wall's plane, of speed U along ê_U. Each slice carries the planar pocket
film's law (:func:`bearing_mbs.fluid_film.cylinder_plane.film_forces` for a cylinder of the slice's width on a
plane of the wall's half-width: the film's load W along a, the Couette force against u_t, and the Poiseuille shear
f_P gathered at P as the planar contact does on a line, (1/2) f_P along ê_U and the couple r f_P about a × ê_U:
:func:`bearing_mbs.contact.traction.inlet_shear_reaction` with the wall's share 0), with the opposites on the wall.
The film stores nothing: the power the pair takes, −(F·u + C·(ω_b − ω_g)), is dissipated.
"""

from __future__ import annotations

import math

import numba

from bearing_mbs.contact.contact_point import (
    apply_couple,
    apply_force,
    axis_point_velocity,
    entrainment,
    in_world,
    relative_velocity,
    touches,
)
from bearing_mbs.contact.traction import inlet_shear_reaction
from bearing_mbs.fluid_film.cylinder_plane import film_forces


@numba.njit(cache=True)
def add_pocket_films(packed, active, position, rotation, velocity, omega_world, force, moment):
    """Add the forces [N] and moments [N m] (world frame, about the bodies' centres) of the pocket films that touch
    an ``active`` body to ``force`` and ``moment``; the state as
    :func:`bearing_mbs.contact.sliced_raceway.add_sliced_raceways` takes it. Returns the power they dissipate [W]."""
    dissipated = 0.0
    for film in range(packed.film_wall_roller.size):
        b, g = packed.film_wall_roller[film], packed.film_wall_ring[film]
        if not touches(active, b, g):
            continue
        o0, o1, o2, a0, a1, a2 = in_world(g, position, rotation, packed.film_wall_point[film],
                                          packed.film_wall_normal[film])
        radius, width = packed.film_wall_radius[film], packed.film_wall_width[film]
        viscosity, half_width, floor = (packed.film_wall_law[film, 0], packed.film_wall_law[film, 1],
                                        packed.film_wall_law[film, 2])
        e0, e1, e2 = rotation[b, 0, 2], rotation[b, 1, 2], rotation[b, 2, 2]
        w0, w1, w2 = omega_world[b, 0], omega_world[b, 1], omega_world[b, 2]
        g0 = g1 = g2 = 0.0
        if g >= 0:
            g0, g1, g2 = omega_world[g, 0], omega_world[g, 1], omega_world[g, 2]
        turn0, turn1, turn2 = g1 * a2 - g2 * a1, g2 * a0 - g0 * a2, g0 * a1 - g1 * a0  # ṅ = ω_g × a
        for k in range(packed.film_wall_slices[film]):
            z = packed.film_wall_positions[film, k]
            c0, c1, c2 = position[b, 0] + z * e0, position[b, 1] + z * e1, position[b, 2] + z * e2
            gap = max((c0 - o0) * a0 + (c1 - o1) * a1 + (c2 - o2) * a2 - radius, floor)
            l0, l1, l2 = z * e0 - radius * a0, z * e1 - radius * a1, z * e2 - radius * a2
            u0, u1, u2, p0, p1, p2 = relative_velocity(b, g, l0, l1, l2, position, velocity, omega_world)
            rate = a0 * u0 + a1 * u1 + a2 * u2
            s0, s1, s2 = u0 - rate * a0, u1 - rate * a1, u2 - rate * a2  # sliding, in the wall's plane
            sliding = math.sqrt(s0 * s0 + s1 * s1 + s2 * s2)
            q0, q1, q2 = axis_point_velocity(b, z, e0, e1, e2, velocity, omega_world)  # ċ; P moves at ċ − r ṅ
            speed, t0, t1, t2 = entrainment(b, l0, l1, l2, u0, u1, u2, q0 - radius * turn0, q1 - radius * turn1,
                                            q2 - radius * turn2, a0, a1, a2, velocity, omega_world)
            load, couette, poiseuille = film_forces(viscosity, speed, sliding, rate, radius, width, half_width, gap)
            tangential, couple = inlet_shear_reaction(poiseuille, 0.0, radius)
            f0, f1, f2 = load * a0, load * a1, load * a2
            if sliding > 0.0:
                f0, f1, f2 = f0 + couette * s0 / sliding, f1 + couette * s1 / sliding, f2 + couette * s2 / sliding
            c0 = c1 = c2 = 0.0
            if speed > 0.0:
                f0, f1, f2 = f0 + tangential * t0, f1 + tangential * t1, f2 + tangential * t2
                c0, c1, c2 = couple * (a1 * t2 - a2 * t1), couple * (a2 * t0 - a0 * t2), couple * (a0 * t1 - a1 * t0)
            apply_force(b, g, l0, l1, l2, p0, p1, p2, f0, f1, f2, force, moment)
            apply_couple(b, g, c0, c1, c2, moment)
            dissipated -= f0 * u0 + f1 * u1 + f2 * u2 + c0 * (w0 - g0) + c1 * (w1 - g1) + c2 * (w2 - g2)
    return dissipated
