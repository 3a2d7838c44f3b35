"""The force elements of a spatial scene (:mod:`bearing_mbs.core.spatial`): engine-neutral descriptions, validated on
construction, and their packing into the arrays that compiled code reads (:func:`pack`)."""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import NamedTuple

import numpy as np

from bearing_mbs.contact.traction import N_TRACTION_COLUMNS

#: How far from 1 a given unit vector's or quaternion's norm may be.
UNIT_TOLERANCE = 1e-9


def vector(owner: str, field: str, value, size: int) -> tuple[float, ...]:
    """``value`` as ``size`` finite floats, else a ValueError naming ``owner``, ``field`` and the value."""
    values = tuple(float(x) for x in value)
    if len(values) != size or not all(math.isfinite(x) for x in values):
        raise ValueError(f"{owner}: {field} must be {size} finite numbers, got {value!r}")
    return values


def unit_vector(owner: str, field: str, value, size: int = 3) -> tuple[float, ...]:
    """``value`` as :func:`vector` gives it, and of norm 1 within :data:`UNIT_TOLERANCE`, else a ValueError."""
    values = vector(owner, field, value, size)
    norm = math.sqrt(sum(x * x for x in values))
    if abs(norm - 1.0) > UNIT_TOLERANCE:
        raise ValueError(f"{owner}: {field} {values} must be of norm 1, its norm is {norm:.12g}")
    return values


@dataclass(frozen=True)
class BodyMoment:
    """A constant moment [N m] on body ``body`` (an index into the scene's bodies), fixed in the body's frame."""

    body: int
    moment: tuple[float, float, float]

    def __post_init__(self):
        object.__setattr__(self, "moment", vector(f"moment on body {self.body}", "moment", self.moment, 3))


@dataclass(frozen=True)
class BodyForce:
    """A constant force [N] on body ``body`` at its centre of mass, fixed in the world frame."""

    body: int
    force: tuple[float, float, float]

    def __post_init__(self):
        object.__setattr__(self, "force", vector(f"force on body {self.body}", "force", self.force, 3))


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
        object.__setattr__(self, "direction", unit_vector(owner, "direction", self.direction))
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
    traction: a lubricated contact's traction row (:data:`bearing_mbs.contact.traction.TRACTION_COLUMNS`, its length
    the slice width), empty for the ``erf`` law: each slice's friction is then the planar ``ehl`` law's traction at
    its load, its slip |v_s| and its entrainment speed, μ its boundary friction (cylinders only).
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
    traction: tuple[float, ...] = ()

    def __post_init__(self):
        owner = f"raceway contact {self.name!r}"
        if self.traction:
            object.__setattr__(self, "traction", vector(owner, "traction", self.traction, N_TRACTION_COLUMNS))
            if self.side == "plane":
                raise ValueError(f"{owner}: a traction row needs a cylinder, not side {self.side!r}")
        object.__setattr__(self, "centre", vector(owner, "centre", self.centre, 3))
        object.__setattr__(self, "axis", unit_vector(owner, "axis", self.axis))
        slices = len(self.positions)
        for field in ("positions", "drops"):
            object.__setattr__(self, field, vector(owner, field, getattr(self, field), slices))
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
    velocity, friction_coefficient μ >= 0, regularisation_speed v_reg [m/s] > 0. rim_radius ρ [m] >= 0 and rim_angle
    φ [rad]: a sphere on a flat end's rounded rim (R_e its corner radius), its centre ρ off the axis at the angle φ
    from the roller's body axis 1 (:mod:`bearing_mbs.contact.flange`); ρ = 0: on the axis. edge [m] >= 0: the band's
    edges rounded over this width (the load fades out beyond them; 0: sharp).
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
    rim_radius: float = 0.0
    rim_angle: float = 0.0
    edge: float = 0.0

    def __post_init__(self):
        owner = f"flange contact {self.name!r}"
        if not (self.rim_radius >= 0 and math.isfinite(self.rim_radius) and math.isfinite(self.rim_angle)
                and self.edge >= 0 and math.isfinite(self.edge)):
            raise ValueError(f"{owner}: rim_radius {self.rim_radius} m and edge {self.edge} m must be finite and >= 0, "
                             f"rim_angle {self.rim_angle} rad finite")
        object.__setattr__(self, "point", vector(owner, "point", self.point, 3))
        object.__setattr__(self, "normal", unit_vector(owner, "normal", self.normal))
        object.__setattr__(self, "band", vector(owner, "band", self.band, 2))
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
        object.__setattr__(self, "axis", unit_vector(owner, "axis", self.axis))
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
        object.__setattr__(self, "axis", unit_vector(owner, "axis", self.axis))
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
class LandFilm:
    """An oil film between body ``body`` and a bore of the ground about the world's z axis through ``centre`` (x, y)
    [m] (the planar model's cage–land film): a short journal bearing of radius [m], length [m], radial clearance [m]
    and the oil's dynamic viscosity [Pa s], all > 0, on the body's centre in the (x, y) plane and its spin about z
    (:mod:`bearing_mbs.elements.journal_bearings`' law; the body's tilt in the bore is not in it)."""

    body: int
    centre: tuple[float, float]
    radius: float
    length: float
    clearance: float
    viscosity: float

    def __post_init__(self):
        object.__setattr__(self, "centre", vector(f"land film on body {self.body}", "centre", self.centre, 2))
        if not min(self.radius, self.length, self.clearance, self.viscosity) > 0:
            raise ValueError(f"land film on body {self.body}: radius, length, clearance and viscosity must be > 0, "
                             f"got {self}")


@dataclass(frozen=True)
class PocketFilm:
    """The oil film between roller ``roller`` and a flat wall of ring body ``ring``'s pocket (the planar model's
    pocket film, :mod:`bearing_mbs.elements.spatial_pocket_film`): the wall through ``point`` with unit ``normal``
    towards the roller (ring frame), the roller's radius [m] and its slices (centres ``positions`` [m] along its
    axis, ``width`` [m]), the oil's viscosity [Pa s], the wall's half-width [m] and the film's smallest gap [m], all
    > 0."""

    name: str
    roller: int
    ring: int
    point: tuple[float, float, float]
    normal: tuple[float, float, float]
    roller_radius: float
    positions: tuple[float, ...]
    width: float
    viscosity: float
    half_width: float
    smallest_gap: float

    def __post_init__(self):
        owner = f"pocket film {self.name!r}"
        object.__setattr__(self, "point", vector(owner, "point", self.point, 3))
        object.__setattr__(self, "normal", unit_vector(owner, "normal", self.normal))
        object.__setattr__(self, "positions", vector(owner, "positions", self.positions, len(self.positions)))
        if not (self.positions and min(self.roller_radius, self.width, self.viscosity, self.half_width,
                                       self.smallest_gap) > 0):
            raise ValueError(f"{owner}: needs slices, and roller_radius, width, viscosity, half_width and "
                             f"smallest_gap > 0, got {self}")


def pack(scene) -> SpatialPacked:
    """The force elements of a :class:`~bearing_mbs.core.spatial.SpatialScene` as the arrays that compiled code reads."""
    bodies = scene.bodies
    slices = max((len(c.positions) for c in scene.raceways), default=0)

    def column(items, value, dtype=float, shape=()):
        return np.array([value(item) for item in items], dtype=dtype).reshape((len(items), *shape))

    def padded(field):
        return np.array([list(getattr(c, field)) + [0.0] * (slices - len(c.positions)) for c in scene.raceways],
                        dtype=float).reshape(len(scene.raceways), slices)

    races = scene.raceways
    return SpatialPacked(
        column(scene.forces, lambda f: f.body, int), column(scene.forces, lambda f: f.force, shape=(3,)),
        column(scene.moments, lambda m: m.body, int), column(scene.moments, lambda m: m.moment, shape=(3,)),
        column(scene.springs, lambda s: s.body, int), column(scene.springs, lambda s: s.direction, shape=(3,)),
        column(scene.springs, lambda s: bodies[s.body].position, shape=(3,)),
        column(scene.springs, lambda s: s.stiffness), column(scene.springs, lambda s: s.damping),
        column(races, lambda c: c.roller, int), column(races, lambda c: c.ring, int),
        column(races, lambda c: c.centre, shape=(3,)), column(races, lambda c: c.axis, shape=(3,)),
        column(races, lambda c: c.raceway_radius), column(races, lambda c: RACEWAY_SIDES[c.side]),
        column(races, lambda c: c.roller_radius), column(races, lambda c: len(c.positions), int),
        padded("positions"), padded("drops"), column(races, lambda c: c.width),
        column(races, lambda c: c.coefficient), column(races, lambda c: c.exponent),
        column(races, lambda c: c.damping_time), column(races, lambda c: c.friction_coefficient),
        column(races, lambda c: c.regularisation_speed), column(races, lambda c: c.damping_factor),
        column(races, lambda c: c.approach_speed_floor), column(races, lambda c: c.rolling_resistance_arm),
        column(races, lambda c: bool(c.traction), bool),
        np.array([c.traction or (0.0,) * N_TRACTION_COLUMNS for c in races], dtype=float).reshape(
            len(races), N_TRACTION_COLUMNS),
        *_flange_columns(scene.flanges, column),
        column(scene.servos, lambda d: d.body, int), column(scene.servos, lambda d: d.axis, shape=(3,)),
        column(scene.servos, lambda d: d.speed), column(scene.servos, lambda d: d.gain),
        column(scene.axis_springs, lambda a: a.body, int), column(scene.axis_springs, lambda a: a.axis, shape=(3,)),
        column(scene.axis_springs, lambda a: a.stiffness), column(scene.axis_springs, lambda a: a.damping),
        column(scene.drags, lambda d: d.body, int),
        column(scene.drags, lambda d: (d.linear, d.quadratic, d.angular, d.angular_quadratic), shape=(4,)),
        column(scene.films, lambda f: f.body, int), column(scene.films, lambda f: f.centre, shape=(2,)),
        column(scene.films, lambda f: (f.radius, f.length, f.clearance, f.viscosity), shape=(4,)),
        *_pocket_film_columns(scene.pocket_films, column))


def _pocket_film_columns(films, column) -> tuple:
    """The pocket films' columns of :class:`SpatialPacked` (slices padded to the longest film's count)."""
    slices = max((len(f.positions) for f in films), default=0)
    positions = np.array([list(f.positions) + [0.0] * (slices - len(f.positions)) for f in films],
                         dtype=float).reshape(len(films), slices)
    return (column(films, lambda f: f.roller, int), column(films, lambda f: f.ring, int),
            column(films, lambda f: f.point, shape=(3,)), column(films, lambda f: f.normal, shape=(3,)),
            column(films, lambda f: f.roller_radius), column(films, lambda f: len(f.positions), int), positions,
            column(films, lambda f: f.width),
            column(films, lambda f: (f.viscosity, f.half_width, f.smallest_gap), shape=(3,)))


def _flange_columns(flanges, column) -> tuple:
    """The flange contacts' columns of :class:`SpatialPacked` (the sphere's centre as z along the roller's axis)."""
    return (column(flanges, lambda c: c.roller, int), column(flanges, lambda c: c.ring, int),
            column(flanges, lambda c: c.end * (c.half_length - c.end_radius)), column(flanges, lambda c: c.end_radius),
            column(flanges, lambda c: c.point, shape=(3,)), column(flanges, lambda c: c.normal, shape=(3,)),
            column(flanges, lambda c: c.band, shape=(2,)), column(flanges, lambda c: c.stiffness),
            column(flanges, lambda c: c.exponent), column(flanges, lambda c: c.damping_time),
            column(flanges, lambda c: c.friction_coefficient), column(flanges, lambda c: c.regularisation_speed),
            column(flanges, lambda c: (c.rim_radius * math.cos(c.rim_angle), c.rim_radius * math.sin(c.rim_angle)),
                   shape=(2,)), column(flanges, lambda c: c.edge), *_rim_groups(flanges))


def _rim_groups(flanges) -> tuple[np.ndarray, np.ndarray]:
    """The runs of consecutive flange contacts that are points of one rim (the same roller end, flange and rim
    radius > 0): each run's length at its first contact (0 at the others, 1 outside a run), and its rim radius."""
    group, radius = np.ones(len(flanges), dtype=int), np.zeros(len(flanges))
    first = 0
    for k in range(1, len(flanges) + 1):
        if k < len(flanges) and flanges[k].rim_radius > 0 and _same_rim(flanges[first], flanges[k]):
            group[k] = 0
            continue
        group[first], radius[first] = k - first, flanges[first].rim_radius
        first = k
    return group, radius


def _same_rim(a, b) -> bool:
    """Two flange contacts are points of one rim: all but their rim angles (and names) alike."""
    return (a.roller, a.ring, a.end, a.half_length, a.end_radius, a.point, a.normal, a.rim_radius) == (
        b.roller, b.ring, b.end, b.half_length, b.end_radius, b.point, b.normal, b.rim_radius)


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
    race_lubricated: np.ndarray
    race_traction: np.ndarray
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
    flange_rim: np.ndarray
    flange_edge: np.ndarray
    flange_group: np.ndarray
    flange_group_radius: np.ndarray
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
    film_body: np.ndarray
    film_centre: np.ndarray
    film: np.ndarray
    film_wall_roller: np.ndarray
    film_wall_ring: np.ndarray
    film_wall_point: np.ndarray
    film_wall_normal: np.ndarray
    film_wall_radius: np.ndarray
    film_wall_slices: np.ndarray
    film_wall_positions: np.ndarray
    film_wall_width: np.ndarray
    film_wall_law: np.ndarray
