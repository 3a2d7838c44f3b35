r"""Rotating unbalances: the centrifugal force of a mass m_u at radius r_u on a spinning body.

:math:`\mathbf F = m_u r_u\,\omega^2\,(\cos(\theta + \varphi), \sin(\theta + \varphi))` on the body's centre, with θ
and ω the body's angle and angular velocity and φ the unbalance's phase. The unbalance's own mass belongs to the
body's; the tangential term :math:`m_u r_u\dot\omega` of a spin-up is left out (it is small against the drive's
torque and does not excite whirl). The force's power F·v counts as supplied.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import NamedTuple

import numba
import numpy as np

from bearing_mbs.core.force_element import ForceElement


@dataclass(frozen=True)
class Unbalance:
    """An unbalance ``moment`` m_u r_u [kg m] >= 0 at ``phase`` φ [rad] on ``body``."""

    name: str
    body: int
    moment: float
    phase: float = 0.0


class UnbalanceArrays(NamedTuple):
    body: np.ndarray  # (U,) int64
    moment: np.ndarray  # (U,) [kg m]
    phase: np.ndarray  # (U,) [rad]


def pack(unbalances) -> UnbalanceArrays:
    return UnbalanceArrays(body=np.array([u.body for u in unbalances], dtype=np.int64),
                           moment=np.array([u.moment for u in unbalances], dtype=float),
                           phase=np.array([u.phase for u in unbalances], dtype=float))


@numba.njit(cache=True, inline="always")
def add_forces(parameters, t, q, v, forces, power):
    unbalances = parameters
    for j in range(unbalances.body.size):
        i = 3 * unbalances.body[j]
        magnitude = unbalances.moment[j] * v[i + 2] ** 2
        angle = q[i + 2] + unbalances.phase[j]
        f_x, f_y = magnitude * math.cos(angle), magnitude * math.sin(angle)
        forces[i] += f_x
        forces[i + 1] += f_y
        power[0] += f_x * v[i] + f_y * v[i + 1]


def add_forces_twin(unbalances, t, q, v, forces, power):
    for j, body in enumerate(unbalances.body):
        angle = q[3 * body + 2] + unbalances.phase[j]
        force = unbalances.moment[j] * v[3 * body + 2] ** 2 * np.array([np.cos(angle), np.sin(angle)])
        forces[3 * body : 3 * body + 2] += force
        power[0] += force @ v[3 * body : 3 * body + 2]


@numba.njit(cache=True, inline="always")
def add_jacobian(parameters, t, q, v, force_position, force_velocity):
    """The rotating force m e ω² (cos, sin)(θ + φ): ∂/∂θ turns it a quarter turn, ∂/∂ω is 2/ω of it."""
    unbalances = parameters
    for j in range(unbalances.body.size):
        i = 3 * unbalances.body[j]
        angle = q[i + 2] + unbalances.phase[j]
        spin = v[i + 2]
        cos_angle, sin_angle = math.cos(angle), math.sin(angle)
        magnitude = unbalances.moment[j] * spin**2
        force_position[i, i + 2] -= magnitude * sin_angle
        force_position[i + 1, i + 2] += magnitude * cos_angle
        force_velocity[i, i + 2] += 2.0 * unbalances.moment[j] * spin * cos_angle
        force_velocity[i + 1, i + 2] += 2.0 * unbalances.moment[j] * spin * sin_angle


ELEMENT = ForceElement(name="unbalances", item_type=Unbalance, parameters=UnbalanceArrays, pack=pack,
                       add_forces=add_forces, add_forces_twin=add_forces_twin, add_jacobian=add_jacobian)
