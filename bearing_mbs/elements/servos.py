"""Velocity servos: a drive torque ``gain · (speed(t) − ω)`` on a body (explicit and implicit solvers alike)."""

from __future__ import annotations

from dataclasses import dataclass
from typing import NamedTuple

import numba
import numpy as np

from bearing_mbs.core.force_element import ForceElement
from bearing_mbs.core.scene import Profile
from bearing_mbs.elements.profiles import pack_profiles, profile_value


@dataclass(frozen=True)
class VelocityServo:
    """Drive torque ``gain * (speed(t) - ω)`` [N m] on a body; gain [N m s/rad], speed(t) [rad/s]."""

    name: str
    body: int
    gain: float
    speed: Profile


class ServoArrays(NamedTuple):
    body: np.ndarray  # (D,) int64
    gain: np.ndarray  # (D,) [N m s/rad]
    profile: np.ndarray  # (D, 2) int64: start and length in the profile tables
    profile_times: np.ndarray  # [s]
    profile_values: np.ndarray  # [rad/s]


def pack(servos) -> ServoArrays:
    index, times, values = pack_profiles([item.speed for item in servos])
    return ServoArrays(body=np.array([item.body for item in servos], dtype=np.int64),
                       gain=np.array([item.gain for item in servos], dtype=float),
                       profile=index, profile_times=times, profile_values=values)


@numba.njit(cache=True, inline="always")
def add_forces(parameters, t, q, v, forces, power):
    servos = parameters
    for j in range(servos.body.size):
        speed = profile_value(servos.profile_times, servos.profile_values, servos.profile[j, 0],
                              servos.profile[j, 1], t)
        i = 3 * servos.body[j] + 2
        torque = servos.gain[j] * (speed - v[i])
        forces[i] += torque
        power[0] += torque * v[i]


def add_forces_twin(servos, t, q, v, forces, power):
    body_forces, velocities = forces.reshape(-1, 3), v.reshape(-1, 3)
    for j, body in enumerate(servos.body):
        start, count = servos.profile[j]
        speed = np.interp(t, servos.profile_times[start : start + count], servos.profile_values[start : start + count])
        torque = servos.gain[j] * (speed - velocities[body, 2])
        body_forces[body, 2] += torque
        power[0] += torque * velocities[body, 2]


@numba.njit(cache=True, inline="always")
def add_jacobian(parameters, t, q, v, force_position, force_velocity):
    """∂T/∂ω = −gain on each driven body's spin."""
    servos = parameters
    for j in range(servos.body.size):
        i = 3 * servos.body[j] + 2
        force_velocity[i, i] -= servos.gain[j]


ELEMENT = ForceElement(name="drives", item_type=VelocityServo, parameters=ServoArrays, pack=pack,
                       add_forces=add_forces, add_forces_twin=add_forces_twin, add_jacobian=add_jacobian)
