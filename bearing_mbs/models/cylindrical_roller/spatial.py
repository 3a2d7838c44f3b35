"""The caged cylindrical roller bearing in three dimensions (issue 31): a spec of this model as a
:class:`~bearing_mbs.core.spatial.SpatialScene`.

Bodies, each with six degrees of freedom: the inner ring (0), the cage (1) and the Z rollers (2 …), on the geometry
of :class:`~.geometry.BearingGeometry`; the outer ring is the ground. The bearing's axis is the world's z axis, the
radial plane the planar model's (x, y).

* Rollers against the raceways: sliced line contacts (:mod:`bearing_mbs.contact.sliced_raceway`) with the group's
  line law as the whole roller's, Q = K δ^n (Palmgren's K, or the one given), cut into ``slices`` straight slices;
  the group's friction law on each slice (dry, or the ``ehl`` traction with the slice's load per length).
* Rollers in their pockets: the same contact against the pocket's four edges (:meth:`.BearingGeometry.pocket_points`,
  lines along the axis in the cage's frame, as the planar penalty cage's points), with the pocket group's law.
* The cage on its land, where it is land-guided: its outer surface in the outer ring's land bore, or the inner
  ring's land in its bore, as a sliced contact over the cage's width with the land group's law. A stiff axial spring
  holds the cage's axial position (nothing else would: its pockets' end walls are not modelled).
* Flanges: an NJ-type arrangement, the outer ring's two ribs (planes z = ±(L_w/2 + ``axial_play``/2), their band
  from the outer raceway down by ``rib_height`` × D_w) and the inner ring's rib at −z (its band from the inner
  raceway up), against the rollers' flat ends with a rounded edge (corner radius ``corner_radius`` × D_w): each rib
  meets the edge at its :data:`RIM_POINTS` points, spinning with the roller, those within its band
  (:mod:`bearing_mbs.contact.flange`), each a Hertz sphere-on-plane contact of the corner radius for steel with the
  raceways' boundary friction coefficient (dry: their μ). The edge on the rib's side resists the roller's skew and
  tilt to first order, as real roller ends guided by ribs do; the points stand for the arc of the edge within the
  rib (our choice: 24, 15° apart, about eight within a rib of 0.3 D_w at a time), and the rib's edges are rounded
  over the corner radius, so that the points load and unload continuously as they spin across them.
* The inner ring: driven about the bearing's axis by a spin servo of the planar model's gain (the ring's inertia over
  ``drive.servo_time_constant``), the radial load at its angle, a stiff axial spring (the shaft's location).
* The contacts carry the groups' hysteresis damping (Lankarani–Nikravesh and its family, with an approach speed
  latched per slice), their friction and rolling resistance; ``damping_time`` adds stiffness-proportional damping
  (0 keeps the planar laws alone). The lubricant's drags on the rollers (and, churning, on the cage) are the planar
  model's. Aligned, the two models are the same bearing, and a run reproduces the planar one
  (tests/test_spatial_bearing.py).

Not yet in three dimensions (refused here with the field that asks for them): the constraint and full-complement
cages, the gear train, load and speed profiles. The cage's land film is the planar short journal bearing on the
cage's centre and spin (its tilt in the land is not in it); the pockets' films are the planar law per slice.
"""

from __future__ import annotations

import dataclasses
import math
from typing import NamedTuple

import numpy as np
from scipy.spatial.transform import Rotation

from bearing_mbs.contact.line_contact import reduced_modulus, slice_coefficient
from bearing_mbs.contact.point_contact import hertz_stiffness
from bearing_mbs.contact.traction import TRACTION_COLUMNS
from bearing_mbs.core.spatial import (
    AxisSpring,
    BodyDrag,
    BodyForce,
    FlangeContact,
    LandFilm,
    PocketFilm,
    SlicedRaceway,
    SpatialBody,
    SpatialScene,
    SpinServo,
    TranslationSpring,
)
from bearing_mbs.core.topology import Group
from bearing_mbs.elements.drags import Drag
from bearing_mbs.elements.journal_bearings import JournalFilm
from bearing_mbs.models.cylindrical_roller.build import (
    CAGE,
    INNER_RING,
    first_roller,
    group_law,
    lubricant_elements,
    pocket_film_law,
    raceway_line_contact,
)
from bearing_mbs.models.cylindrical_roller.drivetrain import initial_speed
from bearing_mbs.models.cylindrical_roller.geometry import BearingGeometry
from bearing_mbs.models.cylindrical_roller.metrics import LineContact, power_intensity
from bearing_mbs.models.cylindrical_roller.operating_oil import operating_oil
from bearing_mbs.spec.fields import SpecError

#: The bodies are numbered as the planar model's caged scene numbers them (its drags apply to them unchanged).
FIRST_ROLLER = first_roller(caged=True)
#: The sliced contacts of roller k are 6k + these (indices into the scene's raceways and slice loads): its
#: raceways, then its pocket's edges P, Q, P_inner, Q_inner; the cage's land contact, if any, is the last.
INNER, OUTER, POCKET = 0, 1, slice(2, 6)
CONTACTS_PER_ROLLER = 6
#: The axial springs' stiffness [N/m] (cage and inner ring): stiff against the loads that reach them.
AXIAL_STIFFNESS = 1e8
#: The shaft's stiffness [N m/rad] holding the inner ring's axis (critically damped): the rollers' moments of a few
#: hundred N m turn it by well under a µrad.
SHAFT_TILT_STIFFNESS = 1e9


class SpatialBearing(NamedTuple):
    """The three-dimensional bearing of a spec: its scene and what the outputs need (the geometry, the epicyclic
    cage speed [rad/s] of the inner ring's speed, the slices' line contacts on the inner and outer raceway)."""

    scene: SpatialScene
    geometry: BearingGeometry
    epicyclic_cage_speed: float
    slice_contacts: tuple[LineContact, LineContact]

    def power_intensity(self, series, contact: int = INNER) -> np.ndarray:
        """Each roller's slices' frictional power intensity [W/m²] on its ``contact`` raceway, (T, Z, slices): the
        smearing measure of docs/smearing.md, q = |F_T·v_s|/(2 b w) with b Hertz's half-width at the slice's load
        per length (:func:`.metrics.power_intensity`)."""
        rollers = self.geometry.rollers
        power = series.slice_friction[:, contact:CONTACTS_PER_ROLLER * rollers:CONTACTS_PER_ROLLER]
        return power_intensity(power, self.slice_loads(series, contact), self.slice_contacts[contact])

    def slice_loads(self, series, contact: int = INNER) -> np.ndarray:
        """Each roller's slice loads [N] on its ``contact`` (:data:`INNER` or :data:`OUTER` raceway) at the output
        instants of ``series`` (a run of :attr:`scene`), (T, Z, slices): the load distribution along the rollers
        (edge loading)."""
        rollers = self.geometry.rollers
        return series.slice_loads[:, contact:CONTACTS_PER_ROLLER * rollers:CONTACTS_PER_ROLLER]

    def roller_loads(self, series, contact: int = INNER) -> np.ndarray:
        """Each roller's load [N] on its ``contact``, the sum of its slice loads, (T, Z)."""
        return self.slice_loads(series, contact).sum(axis=2)

    def attitudes(self, series) -> tuple[np.ndarray, np.ndarray]:
        """Each roller's (skew, tilt) [rad], (T, Z) each: its axis u against the bearing's axis z, turned towards the
        tangent of its orbit (skew, atan2(u·e_t, u·z)) and towards the radius (tilt, atan2(u·e_r, u·z)), e_r and e_t
        at its centre's azimuth."""
        quaternions = series.orientation[:, FIRST_ROLLER:]
        shape = quaternions.shape[:2]
        scalar_last = np.roll(quaternions, -1, axis=-1).reshape(-1, 4)
        axis = Rotation.from_quat(scalar_last).apply([0.0, 0.0, 1.0]).reshape(*shape, 3)  # R e₃
        centres = series.position[:, FIRST_ROLLER:, :2]
        psi = np.arctan2(centres[..., 1], centres[..., 0])
        radial = axis[..., 0] * np.cos(psi) + axis[..., 1] * np.sin(psi)
        tangential = -axis[..., 0] * np.sin(psi) + axis[..., 1] * np.cos(psi)
        return np.arctan2(tangential, axis[..., 2]), np.arctan2(radial, axis[..., 2])

    def cage_slip(self, series) -> np.ndarray:
        """The cage's slip 1 − ω_c/ω_c,epicyclic at the output instants, (T,)."""
        return 1.0 - series.angular_velocity[:, CAGE, 2] / self.epicyclic_cage_speed

    def rib_loads(self, series) -> np.ndarray:
        """Each roller's rib loads [N], (T, Z, 3): the outer ring's rib at +z, at −z, the inner ring's (each the sum
        over its points on the roller's edge, :data:`RIM_ANGLES`)."""
        rollers, points, count = self.geometry.rollers, len(RIM_ANGLES), series.time.size
        outer = series.flange_loads[:, :2 * rollers * points].reshape(count, rollers, 2, points).sum(axis=3)
        inner = series.flange_loads[:, 2 * rollers * points:].reshape(count, rollers, points).sum(axis=2)
        return np.concatenate([outer, inner[:, :, None]], axis=2)


def build_spatial_bearing(spec, slices: int = 10, damping_time: float = 0.0, corner_radius: float = 0.05,
                          rib_height: float = 0.3, axial_play: float = 2e-4, misalignment: float = 0.0,
                          axial_load: float = 0.0, crown=None) -> SpatialBearing:
    """The bearing of ``spec`` (this model's :class:`~.spec.Spec`) in three dimensions (the module's docstring):
    ``slices`` per roller contact (integer >= 1), ``damping_time`` τ [s] >= 0 of every contact (stiffness-proportional
    damping on top of the groups' laws; 0: their laws alone, the planar model's), the rollers' end edges' corner
    radius ``corner_radius`` × D_w in (0, 0.25), the ribs' height ``rib_height`` × D_w in (``corner_radius``, 0.5]
    (they must reach the edge's points), the rollers' total
    axial play between the ribs ``axial_play`` [m] >= 0; the inner ring's ``misalignment`` [rad], its axis tilted
    about the world x axis (in the plane of a load along y) and held there by a stiff shaft (:class:`AxisSpring`);
    an ``axial_load`` [N] >= 0 on the inner ring along +z, carried by its rib and the outer ring's (an NJ-type
    arrangement; without it the inner ring's axial position is held by a stiff spring); the rollers' ``crown``, a
    profile of :mod:`.quasistatic.profiles` (None: straight)."""
    _check_supported(spec)
    if not (isinstance(slices, int) and slices >= 1 and damping_time >= 0 and 0 < corner_radius < 0.25
            and corner_radius < rib_height <= 0.5 and axial_play >= 0 and math.isfinite(misalignment)
            and axial_load >= 0):
        raise SpecError("spatial", (slices, damping_time, corner_radius, rib_height, axial_play, misalignment,
                                    axial_load),
                        "slices must be an integer >= 1, damping_time >= 0 s, corner_radius in (0, 0.25), rib_height "
                        "in (corner_radius, 0.5], axial_play >= 0 m, misalignment finite and axial_load >= 0 N")
    geometry = BearingGeometry.from_spec(spec.bearing)
    geometry.require_cage(spec.bearing)
    oil = operating_oil(spec.lubricant)
    speed = initial_speed(spec.drive)
    rolling = spec.drive.initial_state == "rolling"
    cage_speed = geometry.epicyclic_cage_speed(speed) if rolling else 0.0
    spin = geometry.epicyclic_roller_spin(speed) if rolling else 0.0

    tilt = (math.sin(misalignment / 2), 0.0, 0.0)  # the inner ring turned about x: its quaternion's vector part
    axis = (0.0, -math.sin(misalignment), math.cos(misalignment))  # its axis in the world frame
    # under an axial load the rollers start seated against the outer ring's rib at +z and the inner ring against them:
    # the load goes through the ribs from the start instead of dragging the rollers across the play by friction
    seated = axial_play / 2 if axial_load > 0 else 0.0
    bodies = [_ring("inner_ring", geometry.inner_ring_mass, geometry.inner_ring_inertia, spec.bearing.ring_width,
                    speed, orientation=(math.cos(misalignment / 2), *tilt), position=(0.0, 0.0, 2 * seated)),
              _ring("cage", geometry.cage_mass, geometry.cage_inertia, spec.bearing.cage_width, cage_speed)]
    r, length, mass = geometry.roller_diameter / 2, geometry.roller_length, geometry.roller_mass
    transverse = mass * (3 * r**2 + length**2) / 12
    pitch_radius = geometry.pitch_diameter / 2
    for k, psi in enumerate(geometry.roller_angles):
        x, y = pitch_radius * math.cos(psi), pitch_radius * math.sin(psi)
        bodies.append(SpatialBody(f"roller{k}", mass, (transverse, transverse, geometry.roller_inertia),
                                  position=(x, y, seated), velocity=(-cage_speed * y, cage_speed * x, 0.0),
                                  angular_velocity=(0.0, 0.0, spin)))

    raceways = tuple(contact for k in range(geometry.rollers)
                     for contact in _roller_contacts(spec, geometry, k, slices, damping_time, crown))
    raceways += _land(spec, geometry, slices, damping_time)
    flanges = tuple(flange for k in range(geometry.rollers)
                    for flange in _ribs(spec, geometry, k, corner_radius, rib_height, axial_play, damping_time))
    load = spec.load
    angle = math.radians(load.angle)
    inner_ribs = tuple(rib for k in range(geometry.rollers)
                       for rib in _inner_rib(spec, geometry, k, corner_radius, rib_height, axial_play, damping_time))
    flanges += inner_ribs
    if axial_load > 0:  # the tilted ring's rib touches the roller that stands out most, and enters none
        bodies[INNER_RING] = dataclasses.replace(bodies[INNER_RING], position=(
            0.0, 0.0, 2 * seated - max(_rib_approach(rib, bodies) for rib in inner_ribs)))
    forces = (BodyForce(INNER_RING, (load.radial * math.cos(angle), load.radial * math.sin(angle), axial_load)),) \
        if load.radial > 0 or axial_load > 0 else ()
    servo = SpinServo(INNER_RING, axis, speed, geometry.inner_ring_inertia / spec.drive.servo_time_constant)
    held = (CAGE,) if axial_load > 0 else (INNER_RING, CAGE)  # an axial load finds the ribs
    springs = tuple(TranslationSpring(body, (0.0, 0.0, 1.0), AXIAL_STIFFNESS, 2 * math.sqrt(
        AXIAL_STIFFNESS * bodies[body].mass)) for body in held)
    transverse = bodies[INNER_RING].inertia[0]
    shaft = AxisSpring(INNER_RING, axis, SHAFT_TILT_STIFFNESS, 2 * math.sqrt(SHAFT_TILT_STIFFNESS * transverse))
    drags, films = _lubricant(spec, geometry, oil)
    pocket_films = _pocket_films(spec, geometry, oil, slices) if spec.lubricant.pocket_film else ()
    scene = SpatialScene(f"{spec.scenario.name} (3-D)", tuple(bodies), forces=forces, springs=springs,
                         raceways=raceways, flanges=flanges, servos=(servo,), axis_springs=(shaft,), drags=drags,
                         films=films, pocket_films=pocket_films,
                         gravity=(0.0, -spec.scenario.gravity, 0.0))
    contacts = tuple(LineContact(*raceway_line_contact(spec, geometry, group)[:2], geometry.roller_length / slices)
                     for group in (Group.INNER_RACE, Group.OUTER_RACE))
    return SpatialBearing(scene, geometry, geometry.epicyclic_cage_speed(speed), contacts)


def _lubricant(spec, geometry: BearingGeometry, oil) -> tuple[tuple, tuple]:
    """The planar model's drags and land film (:func:`.build.lubricant_elements`) as spatial elements, on the same
    bodies (:data:`FIRST_ROLLER`)."""
    lubricant = lubricant_elements(spec, geometry, oil, caged=True)
    drags = tuple(BodyDrag(item.body, item.linear, item.quadratic, item.angular, item.angular_quadratic)
                  for item in lubricant if isinstance(item, Drag))
    films = tuple(LandFilm(item.body, item.centre, item.radius, item.length, item.clearance, item.viscosity)
                  for item in lubricant if isinstance(item, JournalFilm))
    return drags, films


def _pocket_films(spec, geometry: BearingGeometry, oil, slices: int) -> tuple:
    """Each roller's films on its pocket's two flat walls (the planar model's pocket film pairs,
    :func:`.build.pocket_film_law`: the wall as tall as the cage ring's section, the film floored at three
    roughnesses), cut into the roller's straight slices."""
    law = pocket_film_law(spec, geometry, oil)
    length, viscosity, half_width, smallest_gap = law.film
    common = {"roller_radius": geometry.roller_diameter / 2, "viscosity": viscosity, "half_width": half_width,
              "smallest_gap": smallest_gap, **{key: value for key, value in _slices(length, slices, 0.0).items()
                                               if key in ("positions", "width")}}
    return tuple(PocketFilm(f"roller{k}-pocket_film_{label}", roller=FIRST_ROLLER + k, ring=CAGE,
                            point=(*point, 0.0), normal=(*normal, 0.0), **common)
                 for k in range(geometry.rollers) for label, (point, normal) in geometry.pocket_walls(k).items())


def _rib_approach(rib: FlangeContact, bodies: list) -> float:
    """The approach [m] of ``rib``'s roller end to its flange on the ring at the bodies' positions and orientations
    (:mod:`bearing_mbs.contact.flange`: R_e − (c − o)·a, c the sphere's centre on the end's rim, o and a the flange's
    point and normal in the world frame), per unit of the ring's axial shift: the ring's axis is nearly the world's z.
    Only a point within the flange's band counts (the others: −inf)."""
    ring, roller = bodies[rib.ring], bodies[rib.roller]
    w, x, y, z = ring.orientation
    turn = Rotation.from_quat([x, y, z, w])
    w, x, y, z = roller.orientation
    point, normal = np.add(ring.position, turn.apply(rib.point)), turn.apply(rib.normal)
    centre = np.add(roller.position, Rotation.from_quat([x, y, z, w]).apply(
        [rib.rim_radius * math.cos(rib.rim_angle), rib.rim_radius * math.sin(rib.rim_angle),
         rib.end * (rib.half_length - rib.end_radius)]))
    contact = centre - rib.end_radius * normal
    radial = (contact - point) - np.dot(contact - point, normal) * normal
    if not rib.band[0] <= np.linalg.norm(radial) <= rib.band[1]:
        return -math.inf
    return float((rib.end_radius - np.dot(centre - point, normal)) / normal[2])


def _check_supported(spec) -> None:
    """Refuse, naming the field, what the three-dimensional bearing does not model yet."""
    refusals = (("cage.model", spec.cage.model, spec.cage.model == "penalty", "the penalty cage only"),
                ("drive.kind", spec.drive.kind, spec.drive.kind == "speed", "a speed drive only"),
                ("drive.profile", spec.drive.profile, spec.drive.profile == "constant", "a constant speed only"),
                ("load.profile", spec.load.profile, spec.load.profile == "constant", "a constant load only"))
    for field, value, supported, allowed in refusals:
        if not supported:
            raise SpecError(field, value, f"the three-dimensional bearing models {allowed} so far (docs/spatial.md)")
    for group in (Group.INNER_RACE, Group.OUTER_RACE, Group.POCKET, Group.LAND):
        contact = getattr(spec.contact, group)
        raceway = group in (Group.INNER_RACE, Group.OUTER_RACE)
        if contact.friction_law not in (("erf", "none", "ehl") if raceway else ("erf", "none")):
            raise SpecError(f"contact.{group}.friction_law", contact.friction_law,
                            "the three-dimensional contacts have the erf law (or none), and ehl on the raceways, so "
                            "far (docs/spatial.md)")


def _ring(name: str, mass: float, polar: float, width: float, speed: float,
          orientation=(1.0, 0.0, 0.0, 0.0), position=(0.0, 0.0, 0.0)) -> SpatialBody:
    """A ring of polar moment ``polar`` [kg m²] and axial ``width`` [m], spinning at ``speed`` [rad/s] about its axis:
    its transverse moment, that of a thin-walled annulus about a diameter, polar/2 + m w²/12."""
    transverse = polar / 2 + mass * width**2 / 12
    return SpatialBody(name, mass, (transverse, transverse, polar), position=position, orientation=orientation,
                       angular_velocity=(0.0, 0.0, speed))


def _law(spec, geometry: BearingGeometry, group: str, length: float, slices: int) -> dict:
    """A group's law as a sliced contact's: the whole line's Q = K δ^n over ``length`` [m] with its hysteresis
    damping, its friction (dry, or the ``ehl`` law's traction row for a slice of ``length``/``slices``) and rolling
    resistance."""
    pair = group_law(spec, geometry, group)
    friction = pair.friction_coefficient if pair.friction_law != "none" else 0.0
    traction = list(pair.traction)
    if traction:  # the row of a slice: its load per length is the slice's load over its width
        traction[TRACTION_COLUMNS.index("length")] = length / slices
    return {"coefficient": float(slice_coefficient(pair.stiffness, length)), "exponent": pair.exponent,
            "friction_coefficient": friction, "regularisation_speed": pair.regularisation_speed,
            "damping_factor": pair.damping_factor, "approach_speed_floor": pair.approach_speed_floor,
            "rolling_resistance_arm": pair.rolling_resistance_arm, "traction": tuple(traction)}


def _slices(length: float, slices: int, damping_time: float, crown=None) -> dict:
    """The slices of a line of ``length`` [m], with the drops of ``crown`` (None: straight)."""
    positions = length * (-0.5 + (np.arange(slices) + 0.5) / slices)
    drops = crown.drop(positions) if crown is not None else np.zeros(slices)
    return {"positions": tuple(positions), "drops": tuple(float(d) for d in drops), "width": length / slices,
            "damping_time": damping_time}


def _roller_contacts(spec, geometry: BearingGeometry, k: int, slices: int, damping_time: float, crown) -> list:
    """Roller k's inner raceway, outer raceway and pocket edges, in the order of :data:`CONTACTS_PER_ROLLER`."""
    length = geometry.roller_length
    common = {"roller": FIRST_ROLLER + k, "roller_radius": geometry.roller_diameter / 2,
              **_slices(length, slices, damping_time, crown)}
    contacts = [
        SlicedRaceway(f"roller{k}-inner_race", ring=INNER_RING, centre=(0, 0, 0), axis=(0, 0, 1),
                      raceway_radius=geometry.inner_race_diameter / 2, side="inner",
                      **_law(spec, geometry, Group.INNER_RACE, length, slices), **common),
        SlicedRaceway(f"roller{k}-outer_race", ring=-1, centre=(0, 0, 0), axis=(0, 0, 1),
                      raceway_radius=geometry.outer_race_diameter / 2, side="outer",
                      **_law(spec, geometry, Group.OUTER_RACE, length, slices), **common)]
    pocket = _law(spec, geometry, Group.POCKET, length, slices)
    for label, point in geometry.pocket_points(k).items():  # an edge: a line along the axis, a cylinder of radius 0
        contacts.append(SlicedRaceway(f"roller{k}-pocket_{label}", ring=CAGE, centre=(*point, 0.0), axis=(0, 0, 1),
                                      raceway_radius=0.0, side="inner", **pocket, **common))
    return contacts


def _land(spec, geometry: BearingGeometry, slices: int, damping_time: float) -> tuple:
    """The cage's land contact (none for a roller-guided cage): the cage in the outer ring's land bore, or the inner
    ring's land in the cage's bore."""
    guidance, width = spec.bearing.cage_guidance, spec.bearing.cage_width
    common = {**_law(spec, geometry, Group.LAND, width, slices), **_slices(width, slices, damping_time),
              "centre": (0, 0, 0), "axis": (0, 0, 1), "side": "outer"}
    if guidance == "outer_land":
        return (SlicedRaceway("cage-outer_land", roller=CAGE, ring=-1, roller_radius=geometry.cage_outer_radius,
                              raceway_radius=geometry.outer_land_radius, **common),)
    if guidance == "inner_land":
        return (SlicedRaceway("cage-inner_land", roller=INNER_RING, ring=CAGE, roller_radius=geometry.inner_land_radius,
                              raceway_radius=geometry.cage_bore_radius, **common),)
    return ()


#: The points of a roller end's edge that meet a rib: angles [rad] about the roller's axis, fixed in the roller.
RIM_POINTS = 24
RIM_ANGLES = tuple(2 * math.pi * k / RIM_POINTS for k in range(RIM_POINTS))


def _ribs(spec, geometry: BearingGeometry, k: int, corner_radius: float, rib_height: float, axial_play: float,
          damping_time: float) -> list:
    """Roller k's two ends' edges against the outer ring's ribs, at :data:`RIM_ANGLES`."""
    bearing = spec.bearing
    roller, ring = bearing.roller_material, bearing.ring_material
    radius = corner_radius * geometry.roller_diameter
    modulus = reduced_modulus(roller.youngs_modulus, roller.poisson_ratio, ring.youngs_modulus, ring.poisson_ratio)
    outer = group_law(spec, geometry, Group.OUTER_RACE)
    friction = outer.friction_coefficient if outer.friction_law != "none" else 0.0
    race = geometry.outer_race_diameter / 2
    half = geometry.roller_length / 2
    return [FlangeContact(f"roller{k}-rib{'+' if end > 0 else '-'}{index}", roller=FIRST_ROLLER + k, ring=-1, end=end,
                          half_length=half, end_radius=radius, point=(0.0, 0.0, end * (half + axial_play / 2)),
                          normal=(0.0, 0.0, -end), band=(race - rib_height * geometry.roller_diameter, race),
                          stiffness=hertz_stiffness((1 / radius, 1 / radius, 0.0, 0.0), modulus),
                          damping_time=damping_time, friction_coefficient=friction,
                          regularisation_speed=outer.regularisation_speed,
                          rim_radius=geometry.roller_diameter / 2 - radius, rim_angle=angle, edge=radius)
            for end in (1, -1) for index, angle in enumerate(RIM_ANGLES)]


def _inner_rib(spec, geometry: BearingGeometry, k: int, corner_radius: float, rib_height: float, axial_play: float,
               damping_time: float) -> list:
    """Roller k's end at −z against the inner ring's rib (an NJ-type bearing), at :data:`RIM_ANGLES`: pushed along +z,
    the inner ring takes the rollers against the outer ring's rib at +z."""
    race = geometry.inner_race_diameter / 2
    inner = group_law(spec, geometry, Group.INNER_RACE)
    return [dataclasses.replace(
        outer, name=f"roller{k}-inner_rib{index}", ring=INNER_RING, normal=(0.0, 0.0, 1.0),
        band=(race, race + rib_height * geometry.roller_diameter),
        friction_coefficient=inner.friction_coefficient if inner.friction_law != "none" else 0.0,
        regularisation_speed=inner.regularisation_speed)
        for index, outer in enumerate(_ribs(spec, geometry, k, corner_radius, rib_height, axial_play,
                                            damping_time)[len(RIM_ANGLES):])]  # the rib at −z
