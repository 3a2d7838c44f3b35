"""Drags: force −(c + c_2|v|)·v on a body's centre and torque −(c_θ + c_θ2|ω|)·ω (e.g. the lubricant's drag on a
roller or a cage: linear for a viscous resistance, quadratic for the form drag of a body moving through an oil–air
mixture)."""

from __future__ import annotations

from dataclasses import dataclass
from typing import NamedTuple

import numba
import numpy as np

from bearing_mbs.core.force_element import ForceElement


@dataclass(frozen=True)
class Drag:
    """Drag on a body: force −(linear + quadratic·|v|)·v [N] on its centre and torque
    −(angular + angular_quadratic·|ω|)·ω [N m]; linear [N s/m], angular [N m s/rad], quadratic [N s²/m²] and
    angular_quadratic [N m s²/rad²], all >= 0."""

    name: str
    body: int
    linear: float = 0.0
    angular: float = 0.0
    quadratic: float = 0.0
    angular_quadratic: float = 0.0


class DragArrays(NamedTuple):
    body: np.ndarray  # (G,) int64
    linear: np.ndarray  # (G,) [N s/m]
    angular: np.ndarray  # (G,) [N m s/rad]
    quadratic: np.ndarray  # (G,) [N s²/m²]
    angular_quadratic: np.ndarray  # (G,) [N m s²/rad²]


def pack(drags) -> DragArrays:
    return DragArrays(body=np.array([d.body for d in drags], dtype=np.int64),
                      linear=np.array([d.linear for d in drags], dtype=float),
                      angular=np.array([d.angular for d in drags], dtype=float),
                      quadratic=np.array([d.quadratic for d in drags], dtype=float),
                      angular_quadratic=np.array([d.angular_quadratic for d in drags], dtype=float))


@numba.njit(cache=True, inline="always")
def add_forces(parameters, t, q, v, forces, power):
    drags = parameters
    for j in range(drags.body.size):
        i = 3 * drags.body[j]
        speed_squared = v[i] ** 2 + v[i + 1] ** 2
        resistance = drags.linear[j] + drags.quadratic[j] * np.sqrt(speed_squared)
        angular = drags.angular[j] + drags.angular_quadratic[j] * abs(v[i + 2])
        forces[i] -= resistance * v[i]
        forces[i + 1] -= resistance * v[i + 1]
        forces[i + 2] -= angular * v[i + 2]
        power[1] += resistance * speed_squared + angular * v[i + 2] ** 2


def add_forces_twin(drags, t, q, v, forces, power):
    body_forces, velocities = forces.reshape(-1, 3), v.reshape(-1, 3)
    for j, body in enumerate(drags.body):
        resistance = drags.linear[j] + drags.quadratic[j] * np.hypot(*velocities[body, :2])
        angular = drags.angular[j] + drags.angular_quadratic[j] * abs(velocities[body, 2])
        coefficients = np.array([resistance, resistance, angular])
        body_forces[body] -= coefficients * velocities[body]
        power[1] += coefficients @ velocities[body] ** 2


@numba.njit(cache=True, inline="always")
def add_jacobian(parameters, t, q, v, force_position, force_velocity):
    """∂F/∂v of each drag: −(c + c_2|v|) I − c_2 v vᵀ/|v| on the centre (−c I at rest, where the quadratic term's
    derivative vanishes) and −(c_θ + 2c_θ2|ω|) on the spin; no dependence on q."""
    drags = parameters
    for j in range(drags.body.size):
        i = 3 * drags.body[j]
        speed = np.sqrt(v[i] ** 2 + v[i + 1] ** 2)
        resistance = drags.linear[j] + drags.quadratic[j] * speed
        for r in range(2):
            force_velocity[i + r, i + r] -= resistance
            if speed > 0.0:
                for c in range(2):
                    force_velocity[i + r, i + c] -= drags.quadratic[j] * v[i + r] * v[i + c] / speed
        force_velocity[i + 2, i + 2] -= drags.angular[j] + 2.0 * drags.angular_quadratic[j] * abs(v[i + 2])


ELEMENT = ForceElement(name="drags", item_type=Drag, parameters=DragArrays, pack=pack, add_forces=add_forces,
                       add_forces_twin=add_forces_twin, add_jacobian=add_jacobian)
