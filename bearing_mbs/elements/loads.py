"""Time-profile loads: a world-frame force and torque on a body, scaled by a profile of time."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import NamedTuple

import numba
import numpy as np

from bearing_mbs.core.force_element import ForceElement
from bearing_mbs.core.scene import Profile
from bearing_mbs.elements.profiles import pack_profiles, profile_value


@dataclass(frozen=True)
class Load:
    """A world-frame force/torque ``vector`` (Fx [N], Fy [N], Mz [N m]) on a body, scaled by ``profile(t)``."""

    name: str
    body: int
    vector: tuple[float, float, float]
    profile: Profile = field(default_factory=lambda: Profile.constant(1.0))


class LoadArrays(NamedTuple):
    body: np.ndarray  # (L,) int64
    vector: np.ndarray  # (L, 3) [N, N, N m]
    profile: np.ndarray  # (L, 2) int64: start and length in the profile tables
    profile_times: np.ndarray  # [s]
    profile_values: np.ndarray  # [-]


def pack(loads) -> LoadArrays:
    index, times, values = pack_profiles([item.profile for item in loads])
    return LoadArrays(body=np.array([item.body for item in loads], dtype=np.int64),
                      vector=np.array([item.vector for item in loads], dtype=float).reshape(-1, 3),
                      profile=index, profile_times=times, profile_values=values)


@numba.njit(cache=True, inline="always")
def add_forces(parameters, t, q, v, forces, power):
    loads = parameters
    for j in range(loads.body.size):
        scale = profile_value(loads.profile_times, loads.profile_values, loads.profile[j, 0], loads.profile[j, 1], t)
        for c in range(3):
            i = 3 * loads.body[j] + c
            forces[i] += scale * loads.vector[j, c]
            power[0] += scale * loads.vector[j, c] * v[i]


def add_forces_twin(loads, t, q, v, forces, power):
    body_forces, velocities = forces.reshape(-1, 3), v.reshape(-1, 3)
    for j, body in enumerate(loads.body):
        start, count = loads.profile[j]
        scale = np.interp(t, loads.profile_times[start : start + count], loads.profile_values[start : start + count])
        body_forces[body] += scale * loads.vector[j]
        power[0] += scale * loads.vector[j] @ velocities[body]


@numba.njit(cache=True, inline="always")
def add_jacobian(parameters, t, q, v, force_position, force_velocity):
    """Nothing: a profile load depends on time alone."""


ELEMENT = ForceElement(name="loads", item_type=Load, parameters=LoadArrays, pack=pack, add_forces=add_forces,
                       add_forces_twin=add_forces_twin, add_jacobian=add_jacobian)
