"""Rigid bodies in three dimensions: the engine-neutral description of a spatial scene and its output.

The first part of the three-dimensional bearing (issue 31): free rigid bodies with six degrees of freedom under
constant loads, run by both engines. Contacts, constraints and a bearing model come next; the planar
:class:`~bearing_mbs.core.scene.Scene` is untouched.

Coordinates, per body: the centre of mass r (x, y, z) [m] in the world frame; the orientation as a unit quaternion
p = (w, x, y, z), scalar first, that turns body-frame vectors into world-frame ones (u_world = R(p) u_body); the
velocity ṙ [m/s] in the world frame; the angular velocity ω [rad/s] in the body frame. The body frame is the frame
of the principal axes of inertia at the centre of mass.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import NamedTuple

import numpy as np

#: How far from 1 a given orientation quaternion's norm may be.
UNIT_TOLERANCE = 1e-9


def _vector(owner: str, field: str, value, size: int) -> tuple[float, ...]:
    values = tuple(float(x) for x in value)
    if len(values) != size or not all(math.isfinite(x) for x in values):
        raise ValueError(f"{owner}: {field} must be {size} finite numbers, got {value!r}")
    return values


@dataclass(frozen=True)
class SpatialBody:
    """A rigid body with six degrees of freedom.

    mass [kg] > 0; inertia: the principal moments of inertia (I₁, I₂, I₃) [kg m²] about the centre of mass, each
    > 0 and none larger than the sum of the other two (a real mass distribution); position r [m] and velocity ṙ
    [m/s] of the centre of mass in the world frame, orientation p (unit quaternion, scalar first) and angular
    velocity ω [rad/s] in the body frame, at t = 0.
    """

    name: str
    mass: float
    inertia: tuple[float, float, float]
    position: tuple[float, float, float] = (0.0, 0.0, 0.0)
    orientation: tuple[float, float, float, float] = (1.0, 0.0, 0.0, 0.0)
    velocity: tuple[float, float, float] = (0.0, 0.0, 0.0)
    angular_velocity: tuple[float, float, float] = (0.0, 0.0, 0.0)

    def __post_init__(self):
        owner = f"body {self.name!r}"
        for field, size in (("inertia", 3), ("position", 3), ("orientation", 4), ("velocity", 3),
                            ("angular_velocity", 3)):
            object.__setattr__(self, field, _vector(owner, field, getattr(self, field), size))
        if not self.mass > 0:
            raise ValueError(f"{owner}: mass must be > 0 kg, got {self.mass}")
        moments = self.inertia
        if not all(m > 0 for m in moments) or any(2 * m > sum(moments) * (1 + 1e-12) for m in moments):
            raise ValueError(f"{owner}: inertia {moments} must be three moments > 0, none larger than the sum of "
                             f"the other two")
        norm = math.sqrt(sum(x * x for x in self.orientation))
        if abs(norm - 1.0) > UNIT_TOLERANCE:
            raise ValueError(f"{owner}: orientation {self.orientation} must be a unit quaternion (w, x, y, z), "
                             f"its norm is {norm:.12g}")


@dataclass(frozen=True)
class BodyMoment:
    """A constant moment [N m] on body ``body`` (an index into the scene's bodies), fixed in the body's frame."""

    body: int
    moment: tuple[float, float, float]

    def __post_init__(self):
        object.__setattr__(self, "moment", _vector(f"moment on body {self.body}", "moment", self.moment, 3))


@dataclass(frozen=True)
class SpatialScene:
    """What gets simulated in three dimensions: the bodies, constant body-fixed moments, and gravity g [m/s²] in the
    world frame."""

    name: str
    bodies: tuple[SpatialBody, ...]
    moments: tuple[BodyMoment, ...] = ()
    gravity: tuple[float, float, float] = (0.0, 0.0, 0.0)

    def __post_init__(self):
        if not self.bodies:
            raise ValueError(f"spatial scene {self.name!r}: bodies must not be empty")
        object.__setattr__(self, "gravity", _vector(f"spatial scene {self.name!r}", "gravity", self.gravity, 3))
        for load in self.moments:
            if not 0 <= load.body < len(self.bodies):
                raise ValueError(f"spatial scene {self.name!r}: a moment acts on body {load.body}, but the bodies are "
                                 f"numbered 0 to {len(self.bodies) - 1}")

    def body_moments(self) -> np.ndarray:
        """The total body-fixed moment on each body (N, 3) [N m]."""
        total = np.zeros((len(self.bodies), 3))
        for load in self.moments:
            total[load.body] += load.moment
        return total


class SpatialSeries(NamedTuple):
    """A spatial run's output at its output instants: time (T,) [s]; per body (T, N, ·): position r [m],
    orientation p (unit quaternion, scalar first, its sign continuous in time), velocity ṙ [m/s] (world frame),
    angular velocity ω [rad/s] (body frame); the steps taken; ``message``: empty when the run reached its end, else
    why it stopped (the series then ends at the last good output instant)."""

    time: np.ndarray
    position: np.ndarray
    orientation: np.ndarray
    velocity: np.ndarray
    angular_velocity: np.ndarray
    steps: int
    message: str = ""

    @property
    def success(self) -> bool:
        return not self.message


def nonfinite_message(scene: SpatialScene, finite: np.ndarray, last_angular_velocity: np.ndarray, t: float,
                      step: float) -> str:
    """Why a run stops whose bodies' states at t [s] are not all finite (``finite`` (N,) per body): the time, the
    culprit (of the bodies not finite, the one that turned fastest at the last output instant,
    ``last_angular_velocity`` (N, 3) [rad/s]; an engine may spread one body's blow-up to all) and a fix."""
    speed = np.where(finite, -np.inf, np.linalg.norm(last_angular_velocity, axis=1))
    body = int(np.argmax(speed))
    return (f"t = {t:.6g} s: the state of body {scene.bodies[body].name!r} is not finite (at the last output it turned at "
            f"{np.linalg.norm(last_angular_velocity[body]):.3g} rad/s). Likely fix: a step well below "
            f"1/|ω| = {1 / max(np.linalg.norm(last_angular_velocity[body]), 1e-300):.3g} s (now {step:.3g} s)")


def check_times(step: float, end_time: float, output_interval: float) -> None:
    """Reject, before anything runs, a step, end time or output interval [s] that is not a finite number > 0."""
    for field, value in (("step", step), ("end_time", end_time), ("output_interval", output_interval)):
        if not (isinstance(value, (int, float)) and math.isfinite(value) and value > 0):
            raise ValueError(f"{field} must be a finite number of seconds > 0, got {value!r}")
