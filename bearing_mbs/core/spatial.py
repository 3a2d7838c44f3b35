"""Rigid bodies in three dimensions: the engine-neutral description of a spatial scene and its output.

The first parts of the three-dimensional bearing (issue 31): rigid bodies with six degrees of freedom under constant
loads, springs that hold a coordinate, sliced roller–raceway contacts and roller end–flange contacts, run by both
engines. EHL traction, the cage and a bearing model come next; the planar :class:`~bearing_mbs.core.scene.Scene` is untouched.

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
class BodyForce:
    """A constant force [N] on body ``body`` at its centre of mass, fixed in the world frame."""

    body: int
    force: tuple[float, float, float]

    def __post_init__(self):
        object.__setattr__(self, "force", _vector(f"force on body {self.body}", "force", self.force, 3))


@dataclass(frozen=True)
class TranslationSpring:
    """A linear spring and damper that holds body ``body``'s centre at its initial position along the unit vector
    ``direction`` (world frame): F = −(k (r − r(0))·e + c ṙ·e) e, stiffness k [N/m] > 0, damping c [N s/m] >= 0
    (as a flange or a cage holds a roller until they are modelled)."""

    body: int
    direction: tuple[float, float, float]
    stiffness: float
    damping: float = 0.0

    def __post_init__(self):
        owner = f"spring on body {self.body}"
        object.__setattr__(self, "direction", _vector(owner, "direction", self.direction, 3))
        if abs(math.sqrt(sum(x * x for x in self.direction)) - 1.0) > UNIT_TOLERANCE:
            raise ValueError(f"{owner}: direction {self.direction} must be a unit vector")
        if not (self.stiffness > 0 and self.damping >= 0):
            raise ValueError(f"{owner}: stiffness {self.stiffness} N/m must be > 0 and damping {self.damping} N s/m "
                             f">= 0")


#: The surfaces a sliced contact runs on: ``inner`` a cylinder's outer surface (an inner ring's raceway, the roller
#: outside it) and ``outer`` a bore (the roller inside it), with the sign s of the interference s (R − d) + r − h;
#: ``plane`` a plane (a cage pocket's wall), code 0.
RACEWAY_SIDES = {"inner": 1.0, "outer": -1.0, "plane": 0.0}


@dataclass(frozen=True)
class SlicedRaceway:
    """A roller against a cylindrical raceway or a plane, as a line contact cut into slices (document 003's slices,
    in three dimensions: :mod:`bearing_mbs.contact.sliced_raceway`).

    roller, ring: body indices (ring −1: the ground); the roller's axis is its body axis 3. side: ``inner``,
    ``outer`` or ``plane`` (:data:`RACEWAY_SIDES`). For a cylinder, centre [m] and axis (unit) of its axis, in the
    ring's frame (the world's for the ground), and its radius raceway_radius R [m] > 0 (an ``inner`` one may have
    R = 0: an edge, as a cage pocket's); for a plane, a point of it and its unit normal towards the roller
    (raceway_radius unused). roller_radius r [m] > 0. positions: the slice centres
    z_k [m] along the roller's axis from its centre; drops: the summed crown drops h_k [m] >= 0 of roller and
    raceway there; width: the slice width w [m] > 0. A slice carries Q_k = C_f w Δ_k^(n−1) (Δ_k + n τ Δ̇_k) >= 0
    at interference Δ_k > 0: coefficient C_f [N/m^(n+1)] > 0, exponent n >= 1, damping_time τ [s] >= 0
    (stiffness-proportional damping: the slice's tangent stiffness times τ); with damping_factor d >= 0 also the
    planar model's hysteresis damping, the factor 1 + d Δ̇_k/v_k added, v_k the slice's approach speed latched at its
    contact onset, at least approach_speed_floor [m/s] > 0 (Lankarani–Nikravesh's d for a restitution, as the
    planar laws). Each slice's friction opposes its sliding velocity v_s in the tangent plane: μ Q_k erf(2|v_s|/v_reg),
    the planar model's ``erf`` law, with friction_coefficient μ >= 0 and regularisation_speed v_reg [m/s] > 0; a
    rolling_resistance_arm μ_R [m] >= 0 offsets each slice's load against the roller's spin relative to the ring,
    the moment −μ_R Q_k erf(2 ω_rel r/v_reg) about the roller's axis (the planar model's rolling resistance).
    """

    name: str
    roller: int
    ring: int
    centre: tuple[float, float, float]
    axis: tuple[float, float, float]
    raceway_radius: float
    side: str
    roller_radius: float
    positions: tuple[float, ...]
    drops: tuple[float, ...]
    width: float
    coefficient: float
    exponent: float
    damping_time: float = 0.0
    friction_coefficient: float = 0.0
    regularisation_speed: float = 1e-2
    damping_factor: float = 0.0
    approach_speed_floor: float = 0.1
    rolling_resistance_arm: float = 0.0

    def __post_init__(self):
        owner = f"raceway contact {self.name!r}"
        for field in ("centre", "axis"):
            object.__setattr__(self, field, _vector(owner, field, getattr(self, field), 3))
        slices = len(self.positions)
        for field in ("positions", "drops"):
            object.__setattr__(self, field, _vector(owner, field, getattr(self, field), slices))
        if abs(math.sqrt(sum(x * x for x in self.axis)) - 1.0) > UNIT_TOLERANCE:
            raise ValueError(f"{owner}: axis {self.axis} must be a unit vector")
        if self.side not in RACEWAY_SIDES:
            raise ValueError(f"{owner}: side {self.side!r} must be one of {sorted(RACEWAY_SIDES)}")
        if slices == 0 or min(self.drops) < 0:
            raise ValueError(f"{owner}: needs at least one slice and drops >= 0, got {slices} slices, drops "
                             f"{self.drops}")
        for field in ("roller_radius", "width", "coefficient"):
            if not getattr(self, field) > 0:
                raise ValueError(f"{owner}: {field} must be > 0, got {getattr(self, field)}")
        if not (self.raceway_radius > 0 or self.side == "plane" or (self.side == "inner" and self.raceway_radius == 0)):
            raise ValueError(f"{owner}: raceway_radius {self.raceway_radius} m must be > 0 (0 allowed on the inner "
                             f"side: an edge)")
        if not (self.exponent >= 1 and self.damping_time >= 0):
            raise ValueError(f"{owner}: exponent {self.exponent} must be >= 1 and damping_time {self.damping_time} s "
                             f">= 0")
        if not (self.friction_coefficient >= 0 and self.regularisation_speed > 0 and self.damping_factor >= 0
                and self.approach_speed_floor > 0 and self.rolling_resistance_arm >= 0):
            raise ValueError(f"{owner}: friction_coefficient {self.friction_coefficient}, damping_factor "
                             f"{self.damping_factor} and rolling_resistance_arm {self.rolling_resistance_arm} m must "
                             f"be >= 0, regularisation_speed {self.regularisation_speed} m/s and approach_speed_floor "
                             f"{self.approach_speed_floor} m/s > 0")


@dataclass(frozen=True)
class FlangeContact:
    """A roller's spherical end against a flange: a point contact (:mod:`bearing_mbs.contact.flange`).

    roller, ring: body indices (ring −1: the ground). end: +1 or −1, the roller's end at z = end · half_length [m]
    along its axis (body axis 3); end_radius R_e [m] > 0: the radius of that end's sphere, whose centre lies on the
    axis at end · (half_length − R_e). The flange is the plane through ``point`` with unit ``normal`` (pointing
    towards the roller), both in the ring's frame, within the band ``band`` = (inner, outer) [m] of distance from the
    line through ``point`` along ``normal`` (the ring's axis: the flange's radial extent); outside it there is no
    contact. The load is Q = K δ^n (1 + n τ δ̇/δ) >= 0 at approach δ > 0: stiffness K [N/m^n] > 0 (Hertz's, for a
    sphere on a plane, with n = 3/2), damping_time τ [s] >= 0; friction μ Q erf(2|v_s|/v_reg) against the sliding
    velocity, friction_coefficient μ >= 0, regularisation_speed v_reg [m/s] > 0.
    """

    name: str
    roller: int
    ring: int
    end: int
    half_length: float
    end_radius: float
    point: tuple[float, float, float]
    normal: tuple[float, float, float]
    band: tuple[float, float]
    stiffness: float
    exponent: float = 1.5
    damping_time: float = 0.0
    friction_coefficient: float = 0.0
    regularisation_speed: float = 1e-2

    def __post_init__(self):
        owner = f"flange contact {self.name!r}"
        for field in ("point", "normal"):
            object.__setattr__(self, field, _vector(owner, field, getattr(self, field), 3))
        object.__setattr__(self, "band", _vector(owner, "band", self.band, 2))
        if abs(math.sqrt(sum(x * x for x in self.normal)) - 1.0) > UNIT_TOLERANCE:
            raise ValueError(f"{owner}: normal {self.normal} must be a unit vector")
        if self.end not in (1, -1):
            raise ValueError(f"{owner}: end {self.end!r} must be +1 or -1")
        if not (0 < self.end_radius and 0 < self.half_length and 0 <= self.band[0] < self.band[1]):
            raise ValueError(f"{owner}: end_radius {self.end_radius} m and half_length {self.half_length} m must be "
                             f"> 0, band {self.band} m an interval 0 <= inner < outer")
        if not (self.stiffness > 0 and self.exponent >= 1 and self.damping_time >= 0
                and self.friction_coefficient >= 0 and self.regularisation_speed > 0):
            raise ValueError(f"{owner}: stiffness {self.stiffness} must be > 0, exponent {self.exponent} >= 1, "
                             f"damping_time {self.damping_time} s >= 0, friction_coefficient "
                             f"{self.friction_coefficient} >= 0, regularisation_speed {self.regularisation_speed} m/s > 0")


@dataclass(frozen=True)
class SpinServo:
    """A drive that holds body ``body``'s angular velocity about the unit world ``axis`` at ``speed`` Ω [rad/s]: the
    moment M = g (Ω − ω·a) a [N m] with gain g [N m s] > 0 (a motor's speed loop, or a shaft stiff in torsion)."""

    body: int
    axis: tuple[float, float, float]
    speed: float
    gain: float

    def __post_init__(self):
        owner = f"spin servo on body {self.body}"
        object.__setattr__(self, "axis", _vector(owner, "axis", self.axis, 3))
        if abs(math.sqrt(sum(x * x for x in self.axis)) - 1.0) > UNIT_TOLERANCE:
            raise ValueError(f"{owner}: axis {self.axis} must be a unit vector")
        if not (math.isfinite(self.speed) and self.gain > 0):
            raise ValueError(f"{owner}: speed {self.speed} rad/s must be finite and gain {self.gain} N m s > 0")


@dataclass(frozen=True)
class AxisSpring:
    """A torsion spring and damper that turns body ``body``'s axis 3 towards the unit world direction ``axis``
    (a shaft that holds a ring's axis, here misaligned): M = k (e₃ × a) − c (ω − (ω·e₃) e₃) [N m], stiffness
    k [N m/rad] > 0, damping c [N m s/rad] >= 0; it leaves the spin about e₃ free."""

    body: int
    axis: tuple[float, float, float]
    stiffness: float
    damping: float = 0.0

    def __post_init__(self):
        owner = f"axis spring on body {self.body}"
        object.__setattr__(self, "axis", _vector(owner, "axis", self.axis, 3))
        if abs(math.sqrt(sum(x * x for x in self.axis)) - 1.0) > UNIT_TOLERANCE:
            raise ValueError(f"{owner}: axis {self.axis} must be a unit vector")
        if not (self.stiffness > 0 and self.damping >= 0):
            raise ValueError(f"{owner}: stiffness {self.stiffness} N m/rad must be > 0 and damping {self.damping} "
                             f"N m s/rad >= 0")


@dataclass(frozen=True)
class BodyDrag:
    """The drag of a lubricant on body ``body`` (the planar model's): force −(linear + quadratic·|ṙ|) ṙ [N] on its
    centre and moment −(angular + angular_quadratic·|ω₃|) ω₃ [N m] about its axis 3 against its spin ω₃; linear
    [N s/m], quadratic [N s²/m²], angular [N m s/rad], angular_quadratic [N m s²/rad²], all >= 0."""

    body: int
    linear: float = 0.0
    quadratic: float = 0.0
    angular: float = 0.0
    angular_quadratic: float = 0.0

    def __post_init__(self):
        if not min(self.linear, self.quadratic, self.angular, self.angular_quadratic) >= 0:
            raise ValueError(f"drag on body {self.body}: its coefficients must be >= 0, got {self}")


@dataclass(frozen=True)
class SpatialScene:
    """What gets simulated in three dimensions: the bodies, constant body-fixed moments and world-fixed forces,
    springs that hold a centre along a direction, sliced roller–raceway (and roller–pocket) contacts, roller
    end–flange contacts, spin servos, springs that hold an axis, lubricant drags, and gravity g [m/s²] in the
    world frame."""

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
    gravity: tuple[float, float, float] = (0.0, 0.0, 0.0)

    def __post_init__(self):
        owner = f"spatial scene {self.name!r}"
        if not self.bodies:
            raise ValueError(f"{owner}: bodies must not be empty")
        object.__setattr__(self, "gravity", _vector(owner, "gravity", self.gravity, 3))
        count = len(self.bodies)
        for what, items in (("moment", self.moments), ("force", self.forces), ("spring", self.springs),
                            ("servo", self.servos), ("axis spring", self.axis_springs), ("drag", self.drags)):
            for item in items:
                if not 0 <= item.body < count:
                    raise ValueError(f"{owner}: a {what} acts on body {item.body}, but the bodies are numbered 0 to "
                                     f"{count - 1}")
        for contact in (*self.raceways, *self.flanges):
            if not (0 <= contact.roller < count and -1 <= contact.ring < count and contact.ring != contact.roller):
                raise ValueError(f"{owner}: contact {contact.name!r} joins bodies {contact.roller} and "
                                 f"{contact.ring}: two different bodies of 0 to {count - 1} (the ring may be -1, the "
                                 f"ground)")

    @property
    def has_forces(self) -> bool:
        """It has force elements beyond gravity (the engines' force kernel runs only then)."""
        return bool(self.moments or self.forces or self.springs or self.raceways or self.flanges or self.servos
                    or self.axis_springs or self.drags)

    def packed(self) -> SpatialPacked:
        """The force elements as the arrays that compiled code reads (:class:`SpatialPacked`)."""
        bodies = self.bodies
        slices = max((len(c.positions) for c in self.raceways), default=0)

        def column(items, value, dtype=float, shape=()):
            return np.array([value(item) for item in items], dtype=dtype).reshape((len(items), *shape))

        def padded(field):
            return np.array([list(getattr(c, field)) + [0.0] * (slices - len(c.positions)) for c in self.raceways],
                            dtype=float).reshape(len(self.raceways), slices)

        races = self.raceways
        return SpatialPacked(
            column(self.forces, lambda f: f.body, int), column(self.forces, lambda f: f.force, shape=(3,)),
            column(self.moments, lambda m: m.body, int), column(self.moments, lambda m: m.moment, shape=(3,)),
            column(self.springs, lambda s: s.body, int), column(self.springs, lambda s: s.direction, shape=(3,)),
            column(self.springs, lambda s: bodies[s.body].position, shape=(3,)),
            column(self.springs, lambda s: s.stiffness), column(self.springs, lambda s: s.damping),
            column(races, lambda c: c.roller, int), column(races, lambda c: c.ring, int),
            column(races, lambda c: c.centre, shape=(3,)), column(races, lambda c: c.axis, shape=(3,)),
            column(races, lambda c: c.raceway_radius), column(races, lambda c: RACEWAY_SIDES[c.side]),
            column(races, lambda c: c.roller_radius), column(races, lambda c: len(c.positions), int),
            padded("positions"), padded("drops"), column(races, lambda c: c.width),
            column(races, lambda c: c.coefficient), column(races, lambda c: c.exponent),
            column(races, lambda c: c.damping_time), column(races, lambda c: c.friction_coefficient),
            column(races, lambda c: c.regularisation_speed), column(races, lambda c: c.damping_factor),
            column(races, lambda c: c.approach_speed_floor), column(races, lambda c: c.rolling_resistance_arm),
            *_flange_columns(self.flanges, column),
            column(self.servos, lambda d: d.body, int), column(self.servos, lambda d: d.axis, shape=(3,)),
            column(self.servos, lambda d: d.speed), column(self.servos, lambda d: d.gain),
            column(self.axis_springs, lambda a: a.body, int), column(self.axis_springs, lambda a: a.axis, shape=(3,)),
            column(self.axis_springs, lambda a: a.stiffness), column(self.axis_springs, lambda a: a.damping),
            column(self.drags, lambda d: d.body, int),
            column(self.drags, lambda d: (d.linear, d.quadratic, d.angular, d.angular_quadratic), shape=(4,)))


def _flange_columns(flanges, column) -> tuple:
    """The flange contacts' columns of :class:`SpatialPacked` (the sphere's centre as z along the roller's axis)."""
    return (column(flanges, lambda c: c.roller, int), column(flanges, lambda c: c.ring, int),
            column(flanges, lambda c: c.end * (c.half_length - c.end_radius)), column(flanges, lambda c: c.end_radius),
            column(flanges, lambda c: c.point, shape=(3,)), column(flanges, lambda c: c.normal, shape=(3,)),
            column(flanges, lambda c: c.band, shape=(2,)), column(flanges, lambda c: c.stiffness),
            column(flanges, lambda c: c.exponent), column(flanges, lambda c: c.damping_time),
            column(flanges, lambda c: c.friction_coefficient), column(flanges, lambda c: c.regularisation_speed))


class SpatialPacked(NamedTuple):
    """A spatial scene's force elements as arrays (see the element classes for the fields and units): world
    forces, body moments, springs, raceway contacts (slices padded to the longest contact's count), flange contacts
    (``flange_sphere``: the end sphere's centre z along the roller's axis [m])."""

    force_body: np.ndarray
    force: np.ndarray
    moment_body: np.ndarray
    moment: np.ndarray
    spring_body: np.ndarray
    spring_direction: np.ndarray
    spring_anchor: np.ndarray
    spring_stiffness: np.ndarray
    spring_damping: np.ndarray
    race_roller: np.ndarray
    race_ring: np.ndarray
    race_centre: np.ndarray
    race_axis: np.ndarray
    race_radius: np.ndarray
    race_side: np.ndarray
    race_roller_radius: np.ndarray
    race_slices: np.ndarray
    race_positions: np.ndarray
    race_drops: np.ndarray
    race_width: np.ndarray
    race_coefficient: np.ndarray
    race_exponent: np.ndarray
    race_damping_time: np.ndarray
    race_friction: np.ndarray
    race_regularisation_speed: np.ndarray
    race_damping_factor: np.ndarray
    race_approach_floor: np.ndarray
    race_rolling_arm: np.ndarray
    flange_roller: np.ndarray
    flange_ring: np.ndarray
    flange_sphere: np.ndarray
    flange_end_radius: np.ndarray
    flange_point: np.ndarray
    flange_normal: np.ndarray
    flange_band: np.ndarray
    flange_stiffness: np.ndarray
    flange_exponent: np.ndarray
    flange_damping_time: np.ndarray
    flange_friction: np.ndarray
    flange_regularisation_speed: np.ndarray
    servo_body: np.ndarray
    servo_axis: np.ndarray
    servo_speed: np.ndarray
    servo_gain: np.ndarray
    axis_body: np.ndarray
    axis_direction: np.ndarray
    axis_stiffness: np.ndarray
    axis_damping: np.ndarray
    drag_body: np.ndarray
    drag: np.ndarray


class SpatialSeries(NamedTuple):
    """A spatial run's output at its output instants: time (T,) [s]; per body (T, N, ·): position r [m],
    orientation p (unit quaternion, scalar first, its sign continuous in time), velocity ṙ [m/s] (world frame),
    angular velocity ω [rad/s] (body frame); slice_loads (T, C, S) [N]: each raceway contact's slice loads Q_k;
    flange_loads (T, F) [N]: each flange contact's load; work (T, 2) [J]: the work the loads supplied and the work
    the dampers and friction dissipated since t = 0; stored (T,) [J]: the energy the springs and contacts store; the
    steps taken; ``message``: empty when the run reached its end, else why it stopped (the series then ends at the
    last good output instant: a state no longer finite, or a stop request); wall_time_s: the stepping's wall time
    [s]."""

    time: np.ndarray
    position: np.ndarray
    orientation: np.ndarray
    velocity: np.ndarray
    angular_velocity: np.ndarray
    slice_loads: np.ndarray
    flange_loads: np.ndarray
    work: np.ndarray
    stored: np.ndarray
    steps: int
    message: str = ""
    wall_time_s: float = 0.0

    @property
    def success(self) -> bool:
        return not self.message


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
