"""The force elements of a spatial scene, summed per body (compiled; both engines call it): world forces, body-fixed
moments, springs that hold a centre along a direction or an axis, spin servos, drags, land films, sliced raceway and
pocket contacts (:mod:`bearing_mbs.contact.sliced_raceway`), flange contacts (:mod:`bearing_mbs.contact.flange`) and
pocket films (:mod:`bearing_mbs.elements.spatial_pocket_film`)."""

from __future__ import annotations

import math
from typing import NamedTuple

import numba
import numpy as np

from bearing_mbs.contact.flange import add_flanges
from bearing_mbs.contact.sliced_raceway import add_sliced_raceways
from bearing_mbs.core.rotations import rotation_from_vector
from bearing_mbs.elements.journal_bearings import held_eccentricity
from bearing_mbs.elements.spatial_pocket_film import add_pocket_films
from bearing_mbs.fluid_film.closed_forms import short_bearing_force, short_bearing_torque


class SpatialWork(NamedTuple):
    """What a force evaluation fills in: the bodies' rotations (N, 3, 3), the forces on them [N] (world frame) and
    the moments about their centres [N m] (body frame) (N, 3), the raceway contacts' slice loads (C, S) [N] and the
    power their slices' friction dissipates (C, S) [W], the flange contacts' loads (F,) [N], and the slices' approach
    speeds an accepted step at this state would latch (C, S) [m/s]; its scratch, the moments and angular velocities in the world frame (N, 3); the state the
    engines advance once per accepted step, the slices' latched approach speeds (C, S) [m/s]; and which bodies' elements
    an evaluation adds (N,) (all; one body's alone where a Jacobian's column wants only the elements that touch it:
    an element is added when one of its bodies is active, and the others keep their last values)."""

    rotation: np.ndarray
    force: np.ndarray
    moment: np.ndarray
    slice_loads: np.ndarray
    slice_friction: np.ndarray
    flange_loads: np.ndarray
    latch_next: np.ndarray
    moment_world: np.ndarray
    omega_world: np.ndarray
    latched: np.ndarray
    active: np.ndarray


def new_work(bodies: int, packed) -> SpatialWork:
    """The :class:`SpatialWork` of ``bodies`` bodies and the contacts of ``packed``
    (:class:`bearing_mbs.core.spatial.SpatialPacked`)."""
    slices = packed.race_positions.shape
    return SpatialWork(np.empty((bodies, 3, 3)), np.empty((bodies, 3)), np.empty((bodies, 3)), np.zeros(slices),
                       np.zeros(slices), np.zeros(packed.flange_roller.size), np.zeros(slices), np.empty((bodies, 3)),
                       np.empty((bodies, 3)), np.zeros(slices), np.ones(bodies, dtype=np.bool_))


@numba.njit(cache=True)
def latch(work):
    """Advance the latched approach speeds to those of the last evaluation (once per accepted step, after an
    evaluation at the accepted state: as the planar engines advance their pairs' state)."""
    work.latched[:] = work.latch_next


@numba.njit(cache=True)
def spatial_forces(packed, position, velocity, omega_body, work):
    """The forces, moments and contact loads of ``work`` at the state: position, velocity [m, m/s] (world frame,
    N × 3), ``work.rotation`` (filled in by the caller), omega_body [rad/s] (body frame). Returns the power the loads
    supply and the power the dampers and friction dissipate [W], and the energy the springs and contacts store [J]
    (gravity is the engines')."""
    rotation, force, moment_world, omega_world = work.rotation, work.force, work.moment_world, work.omega_world
    bodies = position.shape[0]
    for i in range(bodies):
        for j in range(3):
            force[i, j] = 0.0
            moment_world[i, j] = 0.0
            omega_world[i, j] = (rotation[i, j, 0] * omega_body[i, 0] + rotation[i, j, 1] * omega_body[i, 1]
                                 + rotation[i, j, 2] * omega_body[i, 2])
            work.moment[i, j] = 0.0
    supplied = dissipated = stored = 0.0
    active = work.active
    for k in range(packed.force_body.size):
        if not active[packed.force_body[k]]:
            continue
        for j in range(3):
            force[packed.force_body[k], j] += packed.force[k, j]
            supplied += packed.force[k, j] * velocity[packed.force_body[k], j]
    for k in range(packed.moment_body.size):
        if not active[packed.moment_body[k]]:
            continue
        for j in range(3):
            work.moment[packed.moment_body[k], j] += packed.moment[k, j]
            supplied += packed.moment[k, j] * omega_body[packed.moment_body[k], j]
    for k in range(packed.spring_body.size):
        b, e = packed.spring_body[k], packed.spring_direction[k]
        if not active[b]:
            continue
        stretch = speed = 0.0
        for j in range(3):
            stretch += (position[b, j] - packed.spring_anchor[k, j]) * e[j]
            speed += velocity[b, j] * e[j]
        pull = packed.spring_stiffness[k] * stretch + packed.spring_damping[k] * speed
        for j in range(3):
            force[b, j] -= pull * e[j]
        stored += 0.5 * packed.spring_stiffness[k] * stretch * stretch
        dissipated += packed.spring_damping[k] * speed * speed
    for k in range(packed.servo_body.size):  # M = g (Ω − ω·a) a, in the world frame
        b, a = packed.servo_body[k], packed.servo_axis[k]
        if not active[b]:
            continue
        spin = omega_world[b, 0] * a[0] + omega_world[b, 1] * a[1] + omega_world[b, 2] * a[2]
        torque = packed.servo_gain[k] * (packed.servo_speed[k] - spin)
        for j in range(3):
            moment_world[b, j] += torque * a[j]
        supplied += torque * spin
    for k in range(packed.axis_body.size):  # M = k (e₃ × a) − c ω⊥, in the world frame
        b, a = packed.axis_body[k], packed.axis_direction[k]
        if not active[b]:
            continue
        e0, e1, e2 = rotation[b, 0, 2], rotation[b, 1, 2], rotation[b, 2, 2]
        w0, w1, w2 = omega_world[b, 0], omega_world[b, 1], omega_world[b, 2]
        along = w0 * e0 + w1 * e1 + w2 * e2
        p0, p1, p2 = w0 - along * e0, w1 - along * e1, w2 - along * e2  # ω without its spin about e₃
        stiffness, damping = packed.axis_stiffness[k], packed.axis_damping[k]
        moment_world[b, 0] += stiffness * (e1 * a[2] - e2 * a[1]) - damping * p0
        moment_world[b, 1] += stiffness * (e2 * a[0] - e0 * a[2]) - damping * p1
        moment_world[b, 2] += stiffness * (e0 * a[1] - e1 * a[0]) - damping * p2
        stored += stiffness * (1.0 - (e0 * a[0] + e1 * a[1] + e2 * a[2]))  # the potential of k (e₃ × a)
        dissipated += damping * (p0 * p0 + p1 * p1 + p2 * p2)
    for k in range(packed.drag_body.size):  # the lubricant's drag: on the centre, and about the body's axis
        b = packed.drag_body[k]
        if not active[b]:
            continue
        linear, quadratic, angular, angular_quadratic = (packed.drag[k, 0], packed.drag[k, 1], packed.drag[k, 2],
                                                         packed.drag[k, 3])
        speed = math.sqrt(velocity[b, 0] ** 2 + velocity[b, 1] ** 2 + velocity[b, 2] ** 2)
        resistance = linear + quadratic * speed
        for j in range(3):
            force[b, j] -= resistance * velocity[b, j]
        spin = omega_body[b, 2]
        work.moment[b, 2] -= (angular + angular_quadratic * abs(spin)) * spin
        dissipated += resistance * speed * speed + (angular + angular_quadratic * abs(spin)) * spin * spin
    for k in range(packed.film_body.size):  # land films: the planar short journal bearing in the (x, y) plane
        b = packed.film_body[k]
        if not active[b]:
            continue
        radius, length, clearance, viscosity = packed.film[k, 0], packed.film[k, 1], packed.film[k, 2], packed.film[k, 3]
        e_x, e_y, eps = held_eccentricity(position[b, 0] - packed.film_centre[k, 0],
                                          position[b, 1] - packed.film_centre[k, 1], clearance)
        speed = omega_world[b, 2]
        f_x, f_y = short_bearing_force(e_x, e_y, velocity[b, 0], velocity[b, 1], speed, radius, length, clearance,
                                       viscosity)
        torque = short_bearing_torque(eps, speed, radius, length, clearance, viscosity)
        force[b, 0] += f_x
        force[b, 1] += f_y
        moment_world[b, 2] += torque
        dissipated -= f_x * velocity[b, 0] + f_y * velocity[b, 1] + torque * speed
    lost, kept = add_sliced_raceways(packed, active, position, rotation, velocity, omega_world, force, moment_world,
                                     work.slice_loads, work.slice_friction, work.latched, work.latch_next)
    dissipated, stored = dissipated + lost, stored + kept
    lost, kept = add_flanges(packed, active, position, rotation, velocity, omega_world, force, moment_world,
                             work.flange_loads)
    dissipated, stored = dissipated + lost, stored + kept
    dissipated += add_pocket_films(packed, active, position, rotation, velocity, omega_world, force, moment_world)
    for i in range(bodies):  # the contacts' world moments in the body frame: Rᵀ M
        for j in range(3):
            work.moment[i, j] += (rotation[i, 0, j] * moment_world[i, 0] + rotation[i, 1, j] * moment_world[i, 1]
                                  + rotation[i, 2, j] * moment_world[i, 2])
    return supplied, dissipated, stored


@numba.njit(cache=True)
def spatial_generalized_forces(packed, q, q_t, work, out):
    """Exudyn's generalized forces of a spatial scene's nodes (rotation-vector nodes: q = (r, φ), q̇ = (ṙ, ω) per
    body, ω in the body frame): (F, M) per body, F in the world frame and M in the body frame, into ``out`` (6N,),
    and ``work`` as :func:`spatial_forces` fills it; returns what that returns."""
    bodies = q.size // 6
    state = q.reshape(bodies, 6)
    rates = q_t.reshape(bodies, 6)
    for b in range(bodies):
        rotation_from_vector(state[b, 3], state[b, 4], state[b, 5], work.rotation[b])
    powers = spatial_forces(packed, state[:, :3], rates[:, :3], rates[:, 3:], work)
    for b in range(bodies):
        for j in range(3):
            out[6 * b + j] = work.force[b, j]
            out[6 * b + 3 + j] = work.moment[b, j]
    return powers
