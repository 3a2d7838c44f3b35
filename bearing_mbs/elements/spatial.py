"""The force elements of a spatial scene, summed per body (compiled; both engines call it): world forces, body-fixed
moments, springs that hold a coordinate, sliced raceway contacts (:mod:`bearing_mbs.contact.sliced_raceway`)."""

from __future__ import annotations

import numba

from bearing_mbs.contact.sliced_raceway import add_sliced_raceway
from bearing_mbs.core.rotations import rotation_from_vector


@numba.njit(cache=True)
def spatial_forces(packed, position, rotation, velocity, omega_body, force, moment_body, moment_world, omega_world,
                   slice_loads):
    """The force [N] on each body's centre in the world frame into ``force``, the moment about it [N m] in the body's
    frame into ``moment_body`` (bodies × 3), the raceway contacts' slice loads [N] into ``slice_loads``; from the
    state: position, velocity [m, m/s] (world), rotation (bodies × 3 × 3), omega_body [rad/s] (body frame).
    ``moment_world`` and ``omega_world`` (bodies × 3) are scratch."""
    bodies = position.shape[0]
    for i in range(bodies):
        for j in range(3):
            force[i, j] = 0.0
            moment_world[i, j] = 0.0
            omega_world[i, j] = (rotation[i, j, 0] * omega_body[i, 0] + rotation[i, j, 1] * omega_body[i, 1]
                                 + rotation[i, j, 2] * omega_body[i, 2])
            moment_body[i, j] = 0.0
    for k in range(packed.force_body.size):
        for j in range(3):
            force[packed.force_body[k], j] += packed.force[k, j]
    for k in range(packed.moment_body.size):
        for j in range(3):
            moment_body[packed.moment_body[k], j] += packed.moment[k, j]
    for k in range(packed.spring_body.size):
        b, c = packed.spring_body[k], packed.spring_coordinate[k]
        force[b, c] -= (packed.spring_stiffness[k] * (position[b, c] - packed.spring_anchor[k])
                        + packed.spring_damping[k] * velocity[b, c])
    for contact in range(packed.race_roller.size):
        add_sliced_raceway(packed, contact, position, rotation, velocity, omega_world, force, moment_world,
                           slice_loads)
    for i in range(bodies):  # the contacts' world moments in the body frame: Rᵀ M
        for j in range(3):
            moment_body[i, j] += (rotation[i, 0, j] * moment_world[i, 0] + rotation[i, 1, j] * moment_world[i, 1]
                                  + rotation[i, 2, j] * moment_world[i, 2])


@numba.njit(cache=True)
def spatial_generalized_forces(packed, q, q_t, rotation, force, moment_body, moment_world, omega_world, slice_loads,
                               out):
    """Exudyn's generalized forces of a spatial scene's nodes (rotation-vector nodes: q = (r, φ), q̇ = (ṙ, ω) per
    body, ω in the body frame): (F, M) per body, F in the world frame and M in the body frame, into ``out`` (6N,);
    the rest as :func:`spatial_forces`."""
    bodies = q.size // 6
    state = q.reshape(bodies, 6)
    rates = q_t.reshape(bodies, 6)
    for b in range(bodies):
        rotation_from_vector(state[b, 3], state[b, 4], state[b, 5], rotation[b])
    spatial_forces(packed, state[:, :3], rotation, rates[:, :3], rates[:, 3:], force, moment_body, moment_world,
                   omega_world, slice_loads)
    for b in range(bodies):
        for j in range(3):
            out[6 * b + j] = force[b, j]
            out[6 * b + 3 + j] = moment_body[b, j]
