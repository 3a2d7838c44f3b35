"""Engine-neutral scene: what gets simulated.

A scene is a flat list of planar rigid bodies, contact pairs, constraints, loads and drives, in SI units.
Builders (:mod:`bearing_mbs.builders`) turn a validated spec into a scene and include only what the case
needs; both engines consume the same scene. :meth:`Scene.pack` turns it into the arrays that the compiled
kernel, its numpy twin and the reference integrators read.

Coordinates: each body has q = (x [m], y [m], θ [rad]) of its centre of mass in the world frame, and
velocities (vx, vy [m/s], ω [rad/s]). Body index −1 in a pair or constraint means the ground (world frame).
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import NamedTuple

import numpy as np

from bearing_mbs.contact.friction import FRICTION_LAWS
from bearing_mbs.contact.kinematics import PAIR_KINDS

GROUND = -1


@dataclass(frozen=True)
class Body:
    """A planar rigid body.

    mass [kg] > 0; inertia [kg m²] > 0 about the centre of mass; position (x, y, θ) and velocity
    (vx, vy, ω) at t = 0; ``free`` marks which of x, y, θ move (a fixed coordinate keeps its initial value
    and must start at rest).
    """

    name: str
    mass: float
    inertia: float
    position: tuple[float, float, float]
    velocity: tuple[float, float, float] = (0.0, 0.0, 0.0)
    free: tuple[bool, bool, bool] = (True, True, True)

    def __post_init__(self):
        if not (self.mass > 0 and self.inertia > 0):
            raise ValueError(f"body {self.name!r}: mass and inertia must be > 0, got {self.mass}, {self.inertia}")
        for k in range(3):
            if not self.free[k] and self.velocity[k] != 0.0:
                raise ValueError(f"body {self.name!r}: fixed coordinate {k} must start at rest")


@dataclass(frozen=True)
class PairLaw:
    """Resolved contact-law numbers of one pair (see :mod:`bearing_mbs.contact`).

    ``normal_law`` and ``restitution`` are kept for reporting and for the native Exudyn connector;
    the kernels use ``damping_factor`` (0 for the plain power law).
    """

    normal_law: str
    stiffness: float
    exponent: float
    restitution: float
    damping_factor: float
    approach_speed_floor: float
    friction_law: str = "none"
    friction_coefficient: float = 0.0
    regularisation_speed: float = 1e-2
    rolling_resistance_arm: float = 0.0


@dataclass(frozen=True)
class ContactPair:
    """A circle on body b against a feature of body a (ground if ``body_a == GROUND``).

    kind: one of :data:`bearing_mbs.contact.kinematics.PAIR_KINDS`. ``anchor`` [m] is, in a's frame, a point
    of the line, the centre of a's circle, or the point; ``direction`` is the line's unit normal towards the
    free side (circle_line only); ``radius_a`` [m] is a's circle (outer or hollow) radius; ``radius_b`` [m]
    is b's circle radius.
    """

    name: str
    kind: str
    body_a: int
    body_b: int
    law: PairLaw
    radius_b: float
    radius_a: float = 0.0
    anchor: tuple[float, float] = (0.0, 0.0)
    direction: tuple[float, float] = (0.0, 1.0)

    def __post_init__(self):
        if self.kind not in PAIR_KINDS:
            raise ValueError(f"pair {self.name!r}: kind {self.kind!r} not in {PAIR_KINDS}")
        if self.body_b < 0 or self.body_a < GROUND or self.body_a == self.body_b:
            raise ValueError(f"pair {self.name!r}: bodies ({self.body_a}, {self.body_b}) are not valid")


@dataclass(frozen=True)
class DistanceConstraint:
    """Rigid distance ``length`` [m] between the centres of bodies a and b."""

    name: str
    body_a: int
    body_b: int
    length: float


@dataclass(frozen=True)
class PointOnLineConstraint:
    """The centre of body b stays on a line fixed in body a: through ``anchor`` [m] along the unit
    ``direction`` (both in a's frame). Motion along the line and b's rotation stay free (the constraint
    cage: a roller on its pocket's radial line)."""

    name: str
    body_a: int
    body_b: int
    anchor: tuple[float, float]
    direction: tuple[float, float]


#: Constraint kinds in the order of their integer codes in compiled code.
CONSTRAINT_KINDS = (DistanceConstraint, PointOnLineConstraint)

#: What an engine can record; a scene lists only what it needs (see :meth:`Scene.sensors`).
SENSORS = ("bodies", "pairs", "constraints", "energy")


@dataclass(frozen=True)
class Profile:
    """A time function: piecewise linear through (times [s], values), constant outside."""

    times: tuple[float, ...]
    values: tuple[float, ...]

    def __post_init__(self):
        if len(self.times) != len(self.values) or len(self.times) == 0:
            raise ValueError("profile: times and values must be non-empty and of equal length")
        if np.any(np.diff(self.times) < 0):
            raise ValueError("profile: times must not decrease")

    @classmethod
    def constant(cls, value: float) -> Profile:
        return cls((0.0,), (float(value),))

    def __call__(self, t):
        return np.interp(t, self.times, self.values)


@dataclass(frozen=True)
class Load:
    """A world-frame force/torque ``vector`` (Fx [N], Fy [N], Mz [N m]) on a body, scaled by ``profile(t)``."""

    name: str
    body: int
    vector: tuple[float, float, float]
    profile: Profile = field(default_factory=lambda: Profile.constant(1.0))


@dataclass(frozen=True)
class VelocityServo:
    """Drive torque ``gain * (speed(t) - ω)`` [N m] on a body: works with explicit and implicit solvers."""

    name: str
    body: int
    gain: float
    speed: Profile


@dataclass(frozen=True)
class Drag:
    """Viscous drag on a body: force −linear·v [N] on its centre and torque −angular·ω [N m]; linear
    [N s/m] >= 0, angular [N m s/rad] >= 0 (e.g. the lubricant's drag on a roller)."""

    name: str
    body: int
    linear: float
    angular: float = 0.0


@dataclass(frozen=True)
class Scene:
    """Everything an engine needs, and nothing more. ``gravity`` is the acceleration (gx, gy) [m/s²]."""

    name: str
    bodies: tuple[Body, ...]
    pairs: tuple[ContactPair, ...] = ()
    constraints: tuple[DistanceConstraint | PointOnLineConstraint, ...] = ()
    loads: tuple[Load, ...] = ()
    drives: tuple[VelocityServo, ...] = ()
    drags: tuple[Drag, ...] = ()
    gravity: tuple[float, float] = (0.0, 0.0)

    def __post_init__(self):
        n = len(self.bodies)
        for item in (*self.pairs, *self.constraints):
            if max(item.body_a, item.body_b) >= n:
                raise ValueError(f"{item.name!r} refers to a body index >= {n}")
        for item in (*self.loads, *self.drives, *self.drags):
            if not 0 <= item.body < n:
                raise ValueError(f"{item.name!r} refers to body {item.body}, not in 0..{n - 1}")

    @property
    def coordinate_count(self) -> int:
        return 3 * len(self.bodies)

    @property
    def sensors(self) -> tuple[str, ...]:
        """What the engines record: body states always; pair outputs when there are pairs; constraint forces
        when there are constraints; the energy audit (work of losses and of loads and drives) when anything
        can dissipate or do work."""
        wanted = {
            "bodies": True,
            "pairs": bool(self.pairs),
            "constraints": bool(self.constraints),
            "energy": bool(self.pairs or self.loads or self.drives or self.drags),
        }
        return tuple(name for name in SENSORS if wanted[name])

    def counts(self) -> dict:
        """Item counts, for the 'only what is needed' tests and for reports."""
        return {
            "bodies": len(self.bodies),
            "pairs": len(self.pairs),
            "constraints": len(self.constraints),
            "loads": len(self.loads) + (1 if any(self.gravity) else 0),
            "drives": len(self.drives),
            "drags": len(self.drags),
            "sensors": len(self.sensors),
        }

    def initial_state(self) -> tuple[np.ndarray, np.ndarray]:
        """Flat (q, v) at t = 0, each of length 3 × bodies."""
        q = np.array([b.position for b in self.bodies], dtype=float).ravel()
        v = np.array([b.velocity for b in self.bodies], dtype=float).ravel()
        return q, v

    def pack(self) -> PackedScene:
        return pack_scene(self)


class PairArrays(NamedTuple):
    """Contact pairs as arrays (one entry per pair), read by the kernel and its numpy twin."""

    kind: np.ndarray  # int64, index into PAIR_KINDS
    body_a: np.ndarray  # int64, −1 = ground
    body_b: np.ndarray  # int64
    anchor: np.ndarray  # (P, 2) [m]
    direction: np.ndarray  # (P, 2)
    radius_a: np.ndarray  # [m]
    radius_b: np.ndarray  # [m]
    stiffness: np.ndarray  # [N/m^n]
    exponent: np.ndarray  # [-]
    damping_factor: np.ndarray  # [-]
    approach_speed_floor: np.ndarray  # [m/s]
    friction_law: np.ndarray  # int64, index into FRICTION_LAWS
    friction_coefficient: np.ndarray  # [-]
    regularisation_speed: np.ndarray  # [m/s]
    rolling_resistance_arm: np.ndarray  # [m]


class ConstraintArrays(NamedTuple):
    """Constraints as arrays (unused columns of a kind are zero)."""

    kind: np.ndarray  # int64, index into CONSTRAINT_KINDS
    body_a: np.ndarray  # int64
    body_b: np.ndarray  # int64
    length: np.ndarray  # [m], distance constraints
    anchor: np.ndarray  # (C, 2) [m], point-on-line constraints, in a's frame
    direction: np.ndarray  # (C, 2), point-on-line constraints, unit, in a's frame


class PackedScene(NamedTuple):
    """A scene as flat arrays. Coordinates are ordered body by body: (x, y, θ) of body 0, then body 1, …"""

    inverse_mass: np.ndarray  # (3N,) 1/m, 1/m, 1/I; 0 on fixed coordinates
    gravity: np.ndarray  # (3N,) gravitational acceleration on free translational coordinates
    pairs: PairArrays
    constraints: ConstraintArrays
    load_body: np.ndarray  # (L,) int64
    load_vector: np.ndarray  # (L, 3)
    load_profile: np.ndarray  # (L, 2) int64: start and length in the profile tables
    drive_body: np.ndarray  # (D,) int64
    drive_gain: np.ndarray  # (D,) [N m s/rad]
    drive_profile: np.ndarray  # (D, 2) int64
    drag_body: np.ndarray  # (G,) int64
    drag_linear: np.ndarray  # (G,) [N s/m]
    drag_angular: np.ndarray  # (G,) [N m s/rad]
    profile_times: np.ndarray  # flat table of all profiles' times [s]
    profile_values: np.ndarray  # flat table of all profiles' values


def _pack_pairs(pairs) -> PairArrays:
    def column(get, dtype=float):
        return np.array([get(p) for p in pairs], dtype=dtype)

    return PairArrays(
        kind=column(lambda p: PAIR_KINDS.index(p.kind), np.int64),
        body_a=column(lambda p: p.body_a, np.int64),
        body_b=column(lambda p: p.body_b, np.int64),
        anchor=column(lambda p: p.anchor).reshape(-1, 2),
        direction=column(lambda p: p.direction).reshape(-1, 2),
        radius_a=column(lambda p: p.radius_a),
        radius_b=column(lambda p: p.radius_b),
        stiffness=column(lambda p: p.law.stiffness),
        exponent=column(lambda p: p.law.exponent),
        damping_factor=column(lambda p: p.law.damping_factor),
        approach_speed_floor=column(lambda p: p.law.approach_speed_floor),
        friction_law=column(lambda p: FRICTION_LAWS.index(p.law.friction_law), np.int64),
        friction_coefficient=column(lambda p: p.law.friction_coefficient),
        regularisation_speed=column(lambda p: p.law.regularisation_speed),
        rolling_resistance_arm=column(lambda p: p.law.rolling_resistance_arm),
    )


def _pack_constraints(constraints) -> ConstraintArrays:
    def column(get, dtype=float):
        return np.array([get(c) for c in constraints], dtype=dtype)

    return ConstraintArrays(
        kind=column(lambda c: CONSTRAINT_KINDS.index(type(c)), np.int64),
        body_a=column(lambda c: c.body_a, np.int64),
        body_b=column(lambda c: c.body_b, np.int64),
        length=column(lambda c: getattr(c, "length", 0.0)),
        anchor=column(lambda c: getattr(c, "anchor", (0.0, 0.0))).reshape(-1, 2),
        direction=column(lambda c: getattr(c, "direction", (0.0, 0.0))).reshape(-1, 2),
    )


def pack_scene(scene: Scene) -> PackedScene:
    free = np.array([b.free for b in scene.bodies], dtype=bool).ravel()
    inverse_mass = np.array([[1 / b.mass, 1 / b.mass, 1 / b.inertia] for b in scene.bodies]).ravel() * free
    gravity = np.zeros(scene.coordinate_count)
    gravity[0::3], gravity[1::3] = scene.gravity
    gravity *= free

    profiles, index = [], []
    for profile in [item.profile for item in scene.loads] + [item.speed for item in scene.drives]:
        index.append((sum(len(p.times) for p in profiles), len(profile.times)))
        profiles.append(profile)
    index = np.array(index, dtype=np.int64).reshape(-1, 2)
    n_loads = len(scene.loads)

    return PackedScene(
        inverse_mass=inverse_mass,
        gravity=gravity,
        pairs=_pack_pairs(scene.pairs),
        constraints=_pack_constraints(scene.constraints),
        load_body=np.array([item.body for item in scene.loads], dtype=np.int64),
        load_vector=np.array([item.vector for item in scene.loads], dtype=float).reshape(-1, 3),
        load_profile=index[:n_loads],
        drive_body=np.array([item.body for item in scene.drives], dtype=np.int64),
        drive_gain=np.array([item.gain for item in scene.drives], dtype=float),
        drive_profile=index[n_loads:],
        drag_body=np.array([d.body for d in scene.drags], dtype=np.int64),
        drag_linear=np.array([d.linear for d in scene.drags], dtype=float),
        drag_angular=np.array([d.angular for d in scene.drags], dtype=float),
        profile_times=np.array([t for p in profiles for t in p.times], dtype=float),
        profile_values=np.array([v for p in profiles for v in p.values], dtype=float),
    )
