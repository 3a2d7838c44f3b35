"""Rigid bodies in three dimensions: the engine-neutral description of a spatial scene and its output.

The three-dimensional bearing's scene (issue 31): rigid bodies with six degrees of freedom, the force elements of
:mod:`bearing_mbs.core.spatial_elements` between them, run by both engines; the output, its energy audit and the
messages of a run that stops early. The planar :class:`~bearing_mbs.core.scene.Scene` is untouched.

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

from bearing_mbs.core.failures import Failure
from bearing_mbs.core.spatial_elements import (  # noqa: F401 (the elements are the scene's vocabulary)
    RACEWAY_SIDES,
    UNIT_TOLERANCE,
    AxisSpring,
    BodyDrag,
    BodyForce,
    BodyMoment,
    FlangeContact,
    LandFilm,
    PocketFilm,
    SlicedRaceway,
    SpatialPacked,
    SpinServo,
    TranslationSpring,
    pack,
    unit_vector,
    vector,
)


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
        for field in ("inertia", "position", "velocity", "angular_velocity"):
            object.__setattr__(self, field, vector(owner, field, getattr(self, field), 3))
        # a unit quaternion (w, x, y, z)
        object.__setattr__(self, "orientation", unit_vector(owner, "orientation", self.orientation, 4))
        if not self.mass > 0:
            raise ValueError(f"{owner}: mass must be > 0 kg, got {self.mass}")
        moments = self.inertia
        if not all(m > 0 for m in moments) or any(2 * m > sum(moments) * (1 + 1e-12) for m in moments):
            raise ValueError(f"{owner}: inertia {moments} must be three moments > 0, none larger than the sum of "
                             f"the other two")


@dataclass(frozen=True)
class SpatialScene:
    """What gets simulated in three dimensions: the bodies, constant body-fixed moments and world-fixed forces,
    springs that hold a centre along a direction, sliced roller–raceway (and roller–pocket) contacts, roller
    end–flange contacts, spin servos, springs that hold an axis, lubricant drags, land and pocket films, and gravity
    g [m/s²] in the world frame."""

    name: str
    bodies: tuple[SpatialBody, ...]
    moments: tuple[BodyMoment, ...] = ()
    forces: tuple[BodyForce, ...] = ()
    springs: tuple[TranslationSpring, ...] = ()
    raceways: tuple[SlicedRaceway, ...] = ()
    flanges: tuple[FlangeContact, ...] = ()
    servos: tuple[SpinServo, ...] = ()
    axis_springs: tuple[AxisSpring, ...] = ()
    drags: tuple[BodyDrag, ...] = ()
    films: tuple[LandFilm, ...] = ()
    pocket_films: tuple[PocketFilm, ...] = ()
    gravity: tuple[float, float, float] = (0.0, 0.0, 0.0)

    def __post_init__(self):
        owner = f"spatial scene {self.name!r}"
        if not self.bodies:
            raise ValueError(f"{owner}: bodies must not be empty")
        object.__setattr__(self, "gravity", vector(owner, "gravity", self.gravity, 3))
        count = len(self.bodies)
        for what, items in (("moment", self.moments), ("force", self.forces), ("spring", self.springs),
                            ("servo", self.servos), ("axis spring", self.axis_springs), ("drag", self.drags),
                            ("land film", self.films)):
            for item in items:
                if not 0 <= item.body < count:
                    raise ValueError(f"{owner}: a {what} acts on body {item.body}, but the bodies are numbered 0 to "
                                     f"{count - 1}")
        for contact in (*self.raceways, *self.flanges, *self.pocket_films):
            if not (0 <= contact.roller < count and -1 <= contact.ring < count and contact.ring != contact.roller):
                raise ValueError(f"{owner}: contact {contact.name!r} joins bodies {contact.roller} and "
                                 f"{contact.ring}: two different bodies of 0 to {count - 1} (the ring may be -1, the "
                                 f"ground)")

    @property
    def has_forces(self) -> bool:
        """It has force elements beyond gravity (the engines' force kernel runs only then)."""
        return bool(self.moments or self.forces or self.springs or self.raceways or self.flanges or self.servos
                    or self.axis_springs or self.drags or self.films or self.pocket_films)

    def packed(self) -> SpatialPacked:
        """The force elements as the arrays that compiled code reads (:class:`SpatialPacked`)."""
        return pack(self)


class SpatialSeries(NamedTuple):
    """A spatial run's output at its output instants: time (T,) [s]; per body (T, N, ·): position r [m],
    orientation p (unit quaternion, scalar first, its sign continuous in time), velocity ṙ [m/s] (world frame),
    angular velocity ω [rad/s] (body frame); slice_loads (T, C, S) [N]: each raceway contact's slice loads Q_k;
    slice_friction (T, C, S) [W]: the power their friction dissipates, |F_T·v_s| (the smearing measure's numerator);
    flange_loads (T, F) [N]: each flange contact's load; work (T, 2) [J]: the work the loads supplied and the work
    the dampers and friction dissipated since t = 0; stored (T,) [J]: the energy the springs and contacts store; the
    steps taken; ``message``: empty when the run reached its end, else why it stopped (the series then ends at the
    last good output instant) and ``failure`` what kind of stop it was (:class:`~bearing_mbs.core.failures.Failure`:
    ``NONFINITE``, ``SOLVER_FAILED``, ``INTERRUPTED``; ``NONE`` when the run reached its end); wall_time_s: the
    stepping's wall time [s]; an implicit method's work: the steps it rejected, its Newton iterations, its Jacobians
    and its force evaluations (zero where an engine does not count them)."""

    time: np.ndarray
    position: np.ndarray
    orientation: np.ndarray
    velocity: np.ndarray
    angular_velocity: np.ndarray
    slice_loads: np.ndarray
    slice_friction: np.ndarray
    flange_loads: np.ndarray
    work: np.ndarray
    stored: np.ndarray
    steps: int
    message: str = ""
    wall_time_s: float = 0.0
    failure: Failure = Failure.NONE
    rejected: int = 0
    newton_iterations: int = 0
    jacobians: int = 0
    evaluations: int = 0

    @property
    def success(self) -> bool:
        return self.failure == Failure.NONE


def stopped_message(t: float) -> str:
    """Why a run that a stop request (Ctrl-C, SIGTERM, code) ended stopped at t [s]."""
    return f"t = {t:.6g} s: stopped on request; the output up to here is kept"


class EnergyAudit(NamedTuple):
    """A spatial run's energy at its output instants (T,) [J]: kinetic ½ m ṙ² + ½ ω·Iω, gravity's −m g·r, the
    springs' and contacts' stored energy, the work supplied and dissipated since t = 0; ``error`` = (kinetic +
    gravity + stored + dissipated − supplied) − its value at t = 0, which a closed balance keeps at zero."""

    kinetic: np.ndarray
    gravity: np.ndarray
    stored: np.ndarray
    supplied: np.ndarray
    dissipated: np.ndarray

    @property
    def error(self) -> np.ndarray:
        total = self.kinetic + self.gravity + self.stored + self.dissipated - self.supplied
        return total - total[0]


def energy_audit(scene: SpatialScene, series: SpatialSeries) -> EnergyAudit:
    """The energy balance of ``series``, a run of ``scene``."""
    mass = np.array([b.mass for b in scene.bodies])
    inertia = np.array([b.inertia for b in scene.bodies])
    kinetic = 0.5 * (np.einsum("b,tbj->t", mass, series.velocity**2)
                     + np.einsum("bj,tbj->t", inertia, series.angular_velocity**2))
    gravity = -np.einsum("b,j,tbj->t", mass, np.array(scene.gravity), series.position)
    return EnergyAudit(kinetic, gravity, series.stored, series.work[:, 0], series.work[:, 1])


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
