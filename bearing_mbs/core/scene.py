"""Engine-neutral scene: what gets simulated.

A scene is a flat list of planar rigid bodies, contact pairs, constraints and force elements (loads, drives,
drags, or any registered kind: :mod:`bearing_mbs.core.force_element`), in SI units, with its topology (which
body and pair is which, :mod:`bearing_mbs.core.topology`). A model's ``build`` turns a validated spec into a
scene and includes only what the case needs; both engines consume the same scene.
:func:`bearing_mbs.elements.pack_scene` turns it into the arrays that compiled code reads.

Coordinates: each body has q = (x [m], y [m], θ [rad]) of its centre of mass in the world frame, and
velocities (vx, vy [m/s], ω [rad/s]). Body index −1 in a pair or constraint means the ground (world frame).
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from bearing_mbs.contact.kinematics import PAIR_KINDS
from bearing_mbs.contact.traction import N_TRACTION_COLUMNS
from bearing_mbs.core.topology import Topology

GROUND = -1
#: The columns of a pair law's film (:attr:`PairLaw.film`).
FILM_COLUMNS = ("length", "viscosity", "half_width", "floor")


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
    the kernels use ``damping_factor`` (0 for the plain power law). ``traction`` is the row of
    :data:`bearing_mbs.contact.traction.TRACTION_COLUMNS` of a lubricated (``ehl``) pair, empty otherwise.
    ``film`` is (length l [m], viscosity η [Pa s], the plane's half-width [m], floor [m]) of a pair that carries
    the oil film of a cylinder on a plane (:mod:`bearing_mbs.fluid_film.cylinder_plane`, evaluated at the gap or
    the floor, whichever is larger), empty otherwise.
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
    traction: tuple[float, ...] = ()
    film: tuple[float, ...] = ()

    def __post_init__(self):
        if (self.friction_law == "ehl") != (len(self.traction) == N_TRACTION_COLUMNS):
            raise ValueError(f"a pair law with friction_law {self.friction_law!r} has a traction row of "
                             f"{len(self.traction)} values: 'ehl' needs {N_TRACTION_COLUMNS}, the other laws none")
        if self.film and (len(self.film) != len(FILM_COLUMNS) or min(self.film) <= 0):
            raise ValueError(f"a pair law's film is ({', '.join(FILM_COLUMNS)}), all > 0, not {self.film}")


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


@dataclass(frozen=True)
class OrbitConstraint:
    """The centre of body b stays on the ray from the world origin (the bearing axis) at the angle
    θ_a + ``angle`` [rad]: b's orbital angle follows a's rotation, whatever a's translation. ``direction`` is
    (cos angle, sin angle), the ray's direction in a's frame (the constraint cage: a roller held at its pocket's
    orbital angle, so that the cage's eccentricity on its land imposes no orbital speed on the rollers)."""

    name: str
    body_a: int
    body_b: int
    direction: tuple[float, float]


#: Constraint kinds in the order of their integer codes in compiled code.
CONSTRAINT_KINDS = (DistanceConstraint, PointOnLineConstraint, OrbitConstraint)

#: What an engine can record; a scene lists only what it needs (see :meth:`Scene.sensors`).
SENSORS = ("bodies", "pairs", "constraints", "energy")


def half_cosine(tau):
    """(1 − cos πτ)/2 for τ in [0, 1] and 1 beyond: a ramp from 0 to 1 whose slope starts and ends at zero."""
    tau = np.minimum(np.asarray(tau, dtype=float), 1.0)
    return 0.5 * (1.0 - np.cos(np.pi * tau))


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

    @classmethod
    def smooth_ramp(cls, value: float, duration: float, points: int = 101) -> Profile:
        """From 0 at t = 0 to ``value`` at ``duration`` [s] along the half cosine value (1 − cos πt/T)/2, whose slope
        starts and ends at zero (a linear ramp's slope jumps excite a contact's modes about 15 times more), as
        ``points`` linear pieces; constant after."""
        tau = np.linspace(0.0, 1.0, points)
        return cls(tuple(float(t) for t in duration * tau), tuple(float(v) for v in value * half_cosine(tau)))

    def __call__(self, t):
        return np.interp(t, self.times, self.values)


@dataclass(frozen=True)
class Scene:
    """Everything an engine needs, and nothing more. ``gravity`` is the acceleration (gx, gy) [m/s²]."""

    name: str
    bodies: tuple[Body, ...]
    pairs: tuple[ContactPair, ...] = ()
    constraints: tuple[DistanceConstraint | PointOnLineConstraint | OrbitConstraint, ...] = ()
    forces: tuple = ()
    gravity: tuple[float, float] = (0.0, 0.0)
    topology: Topology = field(default_factory=Topology)

    def __post_init__(self):
        n = len(self.bodies)
        for item in (*self.pairs, *self.constraints):
            if max(item.body_a, item.body_b) >= n:
                raise ValueError(f"{item.name!r} refers to a body index >= {n}")
        for item in self.forces:
            for body in (getattr(item, key) for key in ("body", "body_a", "body_b") if hasattr(item, key)):
                if not GROUND <= body < n or (body == GROUND and hasattr(item, "body")):
                    raise ValueError(f"{item.name!r} refers to body {body}, not in 0..{n - 1}")
        self.topology.check(len(self.bodies), len(self.pairs))

    def items_of(self, kind: type) -> tuple:
        """The force elements of one kind (e.g. ``scene.items_of(Drag)``)."""
        return tuple(item for item in self.forces if isinstance(item, kind))

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
            "energy": bool(self.pairs or self.forces),
        }
        return tuple(name for name in SENSORS if wanted[name])

    def initial_state(self) -> tuple[np.ndarray, np.ndarray]:
        """Flat (q, v) at t = 0, each of length 3 × bodies."""
        q = np.array([b.position for b in self.bodies], dtype=float).ravel()
        v = np.array([b.velocity for b in self.bodies], dtype=float).ravel()
        return q, v
