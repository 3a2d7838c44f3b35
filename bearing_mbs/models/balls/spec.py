"""Sections of the ``balls`` model: discs (the document's spheres in the plane) in an optional box.

This model covers the primary document's five preliminary cases: free fall, a drop on a floor, a drop
with horizontal speed, two balls in a box, and two balls joined by a rigid distance constraint.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from bearing_mbs.spec import ContactSpec, Spec
from bearing_mbs.spec.fields import SpecError, finite, one_of, positive, require

COORDINATES = ("x", "y", "theta")


@dataclass(frozen=True)
class BallSpec:
    """``[[balls]]``: one disc.

    mass [kg] > 0; radius [m] > 0; position (x, y) [m] of the centre; velocity (vx, vy) [m/s];
    angle [rad]; angular_velocity [rad/s]; inertia [kg m²] > 0, by default the document's solid sphere
    2/5 m r²; free: which of x, y, theta move (the others stay at their initial value and must start at
    rest; case 2 of the document moves y only); name: for messages and outputs.
    """

    mass: float
    radius: float
    position: tuple[float, float]
    velocity: tuple[float, float] = (0.0, 0.0)
    angle: float = 0.0
    angular_velocity: float = 0.0
    inertia: float | None = None
    free: tuple[str, ...] = COORDINATES
    name: str = ""

    def __post_init__(self):
        positive("mass", self.mass)
        positive("radius", self.radius)
        if self.inertia is not None:
            positive("inertia", self.inertia)
        for name in ("position", "velocity"):
            for i, value in enumerate(getattr(self, name)):
                finite(f"{name}.{i}", value)
        finite("angle", self.angle)
        finite("angular_velocity", self.angular_velocity)
        for i, coordinate in enumerate(self.free):
            one_of(f"free.{i}", coordinate, COORDINATES)
        require(len(set(self.free)) == len(self.free), "free", list(self.free), "must not repeat a coordinate")
        speeds = dict(zip(COORDINATES, (*self.velocity, self.angular_velocity)))
        for coordinate, speed in speeds.items():
            if coordinate not in self.free and speed != 0.0:
                field = "angular_velocity" if coordinate == "theta" else "velocity"
                raise SpecError(field, speed, f"must be 0 along the fixed coordinate {coordinate}")

    @property
    def moment_of_inertia(self) -> float:
        """[kg m²]: the given inertia, or 2/5 m r² (solid sphere, as in the document)."""
        return self.inertia if self.inertia is not None else 0.4 * self.mass * self.radius**2


@dataclass(frozen=True)
class BoxSpec:
    """``[box]``: optional floor (its height y [m]) and walls (their x [m]); a missing key means no wall."""

    floor: float | None = None
    left_wall: float | None = None
    right_wall: float | None = None

    def __post_init__(self):
        for name in ("floor", "left_wall", "right_wall"):
            if getattr(self, name) is not None:
                finite(name, getattr(self, name))
        if self.left_wall is not None and self.right_wall is not None:
            require(self.right_wall > self.left_wall, "right_wall", self.right_wall, "must be > left_wall")


@dataclass(frozen=True)
class ConstraintSpec:
    """``[[constraints]]``: a rigid distance between two balls' centres.

    bodies: the two ball indices. length [m] > 0: by default the initial distance. kind: ``distance``.
    """

    bodies: tuple[int, int]
    kind: str = "distance"
    length: float | None = None

    def __post_init__(self):
        one_of("kind", self.kind, ("distance",))
        require(self.bodies[0] != self.bodies[1], "bodies", list(self.bodies), "must be two different balls")
        if self.length is not None:
            positive("length", self.length)


@dataclass(frozen=True)
class BallsContact:
    """``[contact]`` of the balls model: ``wall`` (ball–floor and ball–wall) and ``ball`` (ball–ball). A partial
    table is merged over the group's default."""

    wall: ContactSpec = field(default_factory=ContactSpec)
    ball: ContactSpec = field(default_factory=ContactSpec)


@dataclass(frozen=True)
class BallsModelSpec(Spec):
    """A ``balls`` scenario: the shared sections plus ``[contact]``, ``[[balls]]``, ``[box]`` and
    ``[[constraints]]``."""

    contact: BallsContact = field(default_factory=BallsContact)
    balls: tuple[BallSpec, ...] = ()
    box: BoxSpec | None = None
    constraints: tuple[ConstraintSpec, ...] = ()

    def __post_init__(self):
        super().__post_init__()
        require(len(self.balls) > 0, "balls", [], "the balls model needs at least one [[balls]] entry")
        for i, constraint in enumerate(self.constraints):
            for j, body in enumerate(constraint.bodies):
                require(0 <= body < len(self.balls), f"constraints.{i}.bodies.{j}", body,
                        f"must be a ball index in 0..{len(self.balls) - 1}")
