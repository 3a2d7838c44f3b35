r"""A roller against a cylindrical raceway or a plane in three dimensions: document 003's sliced line contact with
exact kinematics (compiled).

Slice k of the roller (centre r_b, rotation R_b, axis R_b e₃) has its centre at c_k = r_b + z_k R_b e₃. Its distance
from the raceway's axis (point o, unit direction a) is d_k = |(c_k − o) − ((c_k − o)·a) a|, along the unit normal
n_k pointing away from the axis. With the side's sign s (+1: the raceway is a ring's outer surface and the roller lies
outside it; −1: a bore with the roller inside), the slice's interference is

.. math::
    \Delta_k = s\,(R - d_k) + r - h_k,

R the raceway's radius, r the roller's, h_k the crown drops. Against a plane (a cage pocket's wall: point o, unit
normal a towards the roller) it is Δ_k = r − (c_k − o)·a − h_k, with n_k = a and s = 1. To first order in the tilts
this is document 003's Δ_k = δ + α z_k − h_k (the approach δ at the roller's centre, the relative tilt α: eq. 12
there). A slice in contact carries

.. math::
    Q_k = C_f\,w\,\Delta_k^{\,n-1}\,(\Delta_k + n\tau\dot\Delta_k) \ge 0,

the slice law of document 003 (eqs. 14–16) with stiffness-proportional damping (τ [s]: the slice's tangent stiffness
n C_f w Δ^(n−1) times τ), Δ̇_k = −s n_k·(ċ_k − v_ring(c_k)) from the roller's and the ring's rigid motions; where the
contact has a damping factor d, the planar laws' hysteresis term d Δ̇_k/v_k is added to the bracket's factor (v_k the
slice's approach speed latched at its onset: :mod:`.normal`). Its elastic part Q_e = C_f w Δ_k^n stores
C_f w Δ_k^(n+1)/(n+1); the rest dissipates (Q_k − Q_e) Δ̇_k >= 0. The force s Q_k n_k acts on the roller at its
surface point P_k = c_k − s r n_k, and its reaction on the ring there; its moment about the roller's centre is
z_k R_b e₃ × s Q_k n_k (the part along n_k has no arm). The slice's friction opposes the sliding velocity v_s of the
roller's material point at P_k against the ring's, in the tangent plane:
F_T = −μ Q_k erf(2|v_s|/v_reg) v_s/|v_s| (the planar model's ``erf`` law, :mod:`.friction`, on the speed), at P_k. A
rolling-resistance arm μ_R adds the moment −μ_R Q_k erf(2 ω_rel r/v_reg) about the roller's axis against its spin
relative to the ring, ω_rel = (ω_b − ω_g)·e₃ (the planar model's, :func:`.friction.rolling_resistance_moment`).
A lubricated slice (a traction row) takes the planar ``ehl`` law's traction at its slip |v_s| and entrainment speed u
(the mean surface velocity relative to the moving contact point, along ê_u) and, with it on, the planar hydrodynamic
rolling resistance f = F_R erf(2u/v_reg): the force (1/2 − w) f ê_u at P and the couple (1 − w) r f about n × ê_u on
the roller (n the normal force's direction on it, w = s r/d the ring's share of the contact point's motion), their
opposites on the ring (:func:`.traction.inlet_shear_reaction`; power −f u).
"""

from __future__ import annotations

import math

import numba

from bearing_mbs.contact.contact_point import (
    NO_TRACTION,
    apply_contact,
    apply_couple,
    apply_force,
    axis_point_velocity,
    entrainment,
    in_world,
    relative_velocity,
    touches,
)
from bearing_mbs.contact.friction import erf_sign, rolling_resistance_moment
from bearing_mbs.contact.line_contact import power_law_energy, power_law_force
from bearing_mbs.contact.normal import hysteresis_factor, latch_approach_speed, reference_approach_speed
from bearing_mbs.contact.traction import inlet_shear_reaction, rolling_force


@numba.njit(cache=True, inline="always")
def entrainment_speed(b, g, z, e0, e1, e2, n0, n1, n2, l0, l1, l2, u0, u1, u2, offset, distance, f0, f1, f2, a0, a1,
                      a2, position, velocity, omega_world):
    """The entrainment speed [m/s] of a slice against a cylinder and its direction
    (:func:`.contact_point.entrainment`), its contact point P = c − offset·n moving at Ṗ = ċ − offset·ṅ: c the slice
    centre at z along roller b's axis e, n the unit normal from the cylinder's axis (through its foot point f, along a)
    at the distance d, turning at ṅ as c moves about the axis (the axis' own tilting left out); l the roller's arm to
    P, u = v_b(P) − v_g(P)."""
    c0, c1, c2 = axis_point_velocity(b, z, e0, e1, e2, velocity, omega_world)
    r0, r1, r2 = c0, c1, c2  # ċ relative to the ring's material point on the axis at f
    if g >= 0:
        h0, h1, h2 = f0 - position[g, 0], f1 - position[g, 1], f2 - position[g, 2]
        v0, v1, v2 = omega_world[g, 0], omega_world[g, 1], omega_world[g, 2]
        r0 -= velocity[g, 0] + v1 * h2 - v2 * h1
        r1 -= velocity[g, 1] + v2 * h0 - v0 * h2
        r2 -= velocity[g, 2] + v0 * h1 - v1 * h0
    along = r0 * a0 + r1 * a1 + r2 * a2
    r0, r1, r2 = r0 - along * a0, r1 - along * a1, r2 - along * a2  # ḋ
    radial = r0 * n0 + r1 * n1 + r2 * n2
    scale = offset / distance  # Ṗ = ċ − offset·ṅ, ṅ = (ḋ − (ḋ·n) n)/d
    return entrainment(b, l0, l1, l2, u0, u1, u2, c0 - scale * (r0 - radial * n0), c1 - scale * (r1 - radial * n1),
                       c2 - scale * (r2 - radial * n2), n0, n1, n2, velocity, omega_world)


@numba.njit(cache=True)
def add_sliced_raceways(packed, active, position, rotation, velocity, omega_world, force, moment, slice_loads,
                        slice_friction, latched, latch_next):
    """Add the forces [N] and moments about the bodies' centres [N m], both in the world frame, of the raceway
    contacts that touch an ``active`` body (:func:`.contact_point.touches`) to ``force`` and ``moment``
    (bodies × 3), each one's slice loads Q_k [N] into ``slice_loads[contact]`` and the power its slices' friction
    dissipates, |F_T·v_s| [W], into ``slice_friction[contact]`` (the other contacts' rows keep their values).
    position, velocity (bodies × 3) [m, m/s], rotation (bodies × 3 × 3), omega_world (bodies × 3) [rad/s];
    latched (contacts × slices) [m/s]: the slices' approach speeds latched at their onsets, and ``latch_next`` the
    values an accepted step at this state leaves (:func:`.normal.latch_approach_speed`). Returns the power their
    damping, friction and rolling resistance dissipate [W] and the energy their slices store [J].

    The loop over the contacts is here, inside one compiled call, rather than in the caller: a call per contact
    that is handed ``packed`` (some fifty arrays) costs as much again as the contact's arithmetic in reference
    counting (measured: 0.8 µs a contact)."""
    dissipated = stored = 0.0
    for contact in range(packed.race_roller.size):
        if not touches(active, packed.race_roller[contact], packed.race_ring[contact]):
            continue
        b, g = packed.race_roller[contact], packed.race_ring[contact]
        s, radius = packed.race_side[contact], packed.race_radius[contact]
        roller_radius = packed.race_roller_radius[contact]
        plane = s == 0.0
        if plane:  # the force on the roller is along the plane's normal, as an inner raceway's is along its n
            s = 1.0
        coefficient = packed.race_coefficient[contact] * packed.race_width[contact]
        exponent, tau = packed.race_exponent[contact], packed.race_damping_time[contact]
        mu, regularisation = packed.race_friction[contact], packed.race_regularisation_speed[contact]
        factor, floor = packed.race_damping_factor[contact], packed.race_approach_floor[contact]
        arm = packed.race_rolling_arm[contact]
        lubricated = packed.race_lubricated[contact]  # a cylinder's (SlicedRaceway refuses a plane's)
        d = 0.0
        # the raceway's axis in the world frame
        o0, o1, o2, a0, a1, a2 = in_world(g, position, rotation, packed.race_centre[contact],
                                          packed.race_axis[contact])
        e0, e1, e2 = rotation[b, 0, 2], rotation[b, 1, 2], rotation[b, 2, 2]  # the roller's axis
        for k in range(packed.race_slices[contact]):
            z = packed.race_positions[contact, k]
            c0, c1, c2 = position[b, 0] + z * e0, position[b, 1] + z * e1, position[b, 2] + z * e2
            r0, r1, r2 = c0 - o0, c1 - o1, c2 - o2
            along = r0 * a0 + r1 * a1 + r2 * a2
            slice_loads[contact, k] = 0.0
            slice_friction[contact, k] = 0.0
            latch_next[contact, k] = 0.0
            if plane:  # the distance from the plane, along its normal towards the roller
                interference = roller_radius - along - packed.race_drops[contact, k]
                n0, n1, n2 = a0, a1, a2
            else:
                d0, d1, d2 = r0 - along * a0, r1 - along * a1, r2 - along * a2
                d = math.sqrt(d0 * d0 + d1 * d1 + d2 * d2)
                if d == 0.0:
                    continue
                interference = s * (radius - d) + roller_radius - packed.race_drops[contact, k]
                n0, n1, n2 = d0 / d, d1 / d, d2 / d
            if interference <= 0.0:
                continue
            # the arm of the roller's material point at P_k, and its velocity relative to the ring's there
            l0 = z * e0 - s * roller_radius * n0
            l1 = z * e1 - s * roller_radius * n1
            l2 = z * e2 - s * roller_radius * n2
            u0, u1, u2, p0, p1, p2 = relative_velocity(b, g, l0, l1, l2, position, velocity, omega_world)
            rate = -s * (n0 * u0 + n1 * u1 + n2 * u2)
            elastic = power_law_force(interference, coefficient, exponent)
            approach = reference_approach_speed(latched[contact, k], -rate, floor)
            latch_next[contact, k] = latch_approach_speed(-interference, -rate, latched[contact, k], floor)
            load = max(elastic * (hysteresis_factor(-rate, factor, approach) + exponent * tau * rate / interference),
                       0.0)
            slice_loads[contact, k] = load
            stored += power_law_energy(interference, coefficient, exponent)
            row, rolling, t0, t1, t2 = NO_TRACTION, 0.0, 0.0, 0.0, 0.0
            if lubricated:
                row = packed.race_traction[contact]
                rolling, t0, t1, t2 = entrainment_speed(b, g, z, e0, e1, e2, n0, n1, n2, l0, l1, l2, u0, u1, u2,
                                                        s * roller_radius, d, o0 + along * a0, o1 + along * a1,
                                                        o2 + along * a2, a0, a1, a2, position, velocity, omega_world)
            slice_friction[contact, k] = apply_contact(b, g, l0, l1, l2, p0, p1, p2, n0, n1, n2, s * load, load, u0,
                                                       u1, u2, mu, regularisation, force, moment, row, rolling)
            if lubricated:  # the hydrodynamic rolling resistance (with it on): the planar law along the entrainment
                resisting = rolling_force(row, rolling, load) * erf_sign(rolling, regularisation)
                if resisting > 0.0:
                    tangential, couple = inlet_shear_reaction(resisting, s * roller_radius / d, roller_radius)
                    apply_force(b, g, l0, l1, l2, p0, p1, p2, tangential * t0, tangential * t1, tangential * t2,
                                force, moment)
                    couple *= s  # about the planar pair's n × t, n the normal force's direction on the roller
                    c0 = couple * (n1 * t2 - n2 * t1)
                    c1 = couple * (n2 * t0 - n0 * t2)
                    c2 = couple * (n0 * t1 - n1 * t0)
                    apply_couple(b, g, c0, c1, c2, moment)
                    dissipated += resisting * rolling  # its power is −f u
            dissipated += (load - elastic) * rate + slice_friction[contact, k]
            if arm > 0.0:  # about the roller's axis, against its spin relative to the ring
                spin = omega_world[b, 0] * e0 + omega_world[b, 1] * e1 + omega_world[b, 2] * e2
                if g >= 0:
                    spin -= omega_world[g, 0] * e0 + omega_world[g, 1] * e1 + omega_world[g, 2] * e2
                resisting = rolling_resistance_moment(load, arm, erf_sign(spin * roller_radius, regularisation))
                for j, e in enumerate((e0, e1, e2)):
                    moment[b, j] += resisting * e
                    if g >= 0:
                        moment[g, j] -= resisting * e
                dissipated -= resisting * spin
    return dissipated, stored

