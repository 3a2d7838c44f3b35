"""Builder of the ``bearing`` model: the planar caged cylindrical roller bearing of the primary document.

Bodies, in this order: the inner ring, the cage (penalty and constraint models), the Z rollers. The outer
ring is fixed: it is the ground. Per roller: an inner-raceway pair (circle–circle) and an outer-raceway pair
(circle inside the hollow outer raceway); then, by cage model,

* ``penalty``: four pocket pairs, roller against the document's pocket edges P and Q and their mirrors
  inside the pitch circle (circle–point; see :mod:`bearing_mbs.geometry`), and with ``[lubricant] pocket_film``
  two film pairs, the oil film between the roller and each flat pocket wall (circle–line, :func:`pocket_film_law`);
* ``constraint``: the roller centre held at its pocket's orbital angle, θ_cage + ψ_k about the bearing axis (an
  orbit constraint), so that the cage's eccentricity on its land imposes no orbital speed on the rollers: the
  model of a cage whose pocket play takes up its float on the land. The pockets then turn the cage but do
  not push it sideways, so a roller-guided constraint cage is held on the axis (its translation fixed) and a
  land-guided one rests on its land under gravity;
  with ``[lubricant] pocket_film`` the same two film pairs as the penalty cage's, whose shear of the roller's spin
  in the cage (the roller centred in its pocket) brakes the roller and drags the cage;
* ``none``: no cage body, and a roller–roller pair between neighbours (Z pairs).

A land-guided cage adds one cage–land pair. The inner ring turns under a velocity servo or the gear train;
the radial load, the gear mesh load, gravity and the lubricant's drag on each roller are added only when
non-zero.
"""

from __future__ import annotations

import math

import numpy as np

from bearing_mbs.contact.ehl import FILM_FORMULAS, reduced_radius
from bearing_mbs.contact.line_contact import (
    PALMGREN_EXPONENT,
    STEEL_CONTACT_MODULUS,
    contact_modulus,
    palmgren_stiffness,
    reduced_modulus,
)
from bearing_mbs.contact.traction import TRACTION_COLUMNS, TRACTION_MODELS
from bearing_mbs.core.scene import GROUND, Body, ContactPair, OrbitConstraint, PairLaw, Profile, Scene
from bearing_mbs.core.topology import Group, Role, Topology
from bearing_mbs.elements import Drag, Load, VelocityServo
from bearing_mbs.elements.journal_bearings import JournalFilm
from bearing_mbs.models.building import initial_gaps, pair_law
from bearing_mbs.models.cylindrical_roller.drivetrain import (
    RPM,
    GearTrain,
    highest_speed_rpm,
    initial_speed,
    speed_profile,
)
from bearing_mbs.models.cylindrical_roller.geometry import BearingGeometry
from bearing_mbs.models.cylindrical_roller.lubrication import (
    cage_drag_coefficient,
    mixture_density,
    orbital_drag_coefficient,
    palmgren_drag_moment,
    replenishment_factor,
    roller_drag_coefficient,
    spin_drag_coefficient,
)
from bearing_mbs.models.cylindrical_roller.operating_oil import OperatingOil, operating_oil
from bearing_mbs.models.cylindrical_roller.spec import CONTACT_GROUPS
from bearing_mbs.spec import Spec, SpecError

#: The primary document's raceway laws K δ^1.3 (annex II: KI, KE, NI = NE).
DOCUMENT_STIFFNESS = {Group.INNER_RACE: 3e10, Group.OUTER_RACE: 4e10}
DOCUMENT_EXPONENT = 1.3
#: The contact groups in the order of the topology.
TOPOLOGY_GROUPS = (Group.INNER_RACE, Group.OUTER_RACE, Group.POCKET, Group.POCKET_FILM, Group.ROLLER, Group.LAND)

INNER_RING, CAGE = 0, 1


def build_bearing_scene(spec: Spec) -> Scene:
    """The scene of a bearing spec (the module docstring): the geometry and the oil at its operating temperature
    are derived once, then the bodies, the contacts, the loads and drive and the lubricant's elements are laid out
    in turn, and the topology records which is which."""
    geometry = BearingGeometry.from_spec(spec.bearing)
    caged = spec.cage.model != "none"
    if caged:
        geometry.require_cage(spec.bearing)
    oil = operating_oil(spec.lubricant)
    train = GearTrain(spec.drive.gear_train) if spec.drive.kind == "gear_train" else None
    ring_inertia = geometry.inner_ring_inertia + (train.reduced_inertia if train else 0.0)

    bodies = rolling_set(spec, geometry, ring_inertia, caged)
    pairs, constraints, groups = contacts(spec, geometry, oil, caged)
    forces = (*applied_loads(spec, train, ring_inertia), *lubricant_elements(spec, geometry, oil, caged))
    scene = Scene(spec.scenario.name, tuple(bodies), tuple(pairs), tuple(constraints), forces,
                  gravity=(0.0, -spec.scenario.gravity), topology=bearing_topology(geometry, groups, caged))
    _reject_initial_overlap(scene, geometry)
    return scene


def first_roller(caged: bool) -> int:
    """The body index of roller 0: after the inner ring and, if there is one, the cage."""
    return 2 if caged else 1


def rolling_set(spec: Spec, geometry: BearingGeometry, ring_inertia: float, caged: bool) -> list[Body]:
    """The inner ring (of ``ring_inertia`` [kg m²], the gear train's reduced inertia included), the cage and the Z
    rollers on the pitch circle: the ring at the drive's initial speed, the cage and the rollers at rest or, with
    ``drive.initial_state = 'rolling'``, at the epicyclic speeds of that ring speed."""
    drive = spec.drive
    inner_speed = initial_speed(drive)
    rolling = drive.initial_state == "rolling"
    cage_speed = geometry.epicyclic_cage_speed(inner_speed) if rolling else 0.0
    spin = geometry.epicyclic_roller_spin(inner_speed) if rolling else 0.0
    bodies = [Body(str(Role.INNER_RING), geometry.inner_ring_mass, ring_inertia, (0.0, 0.0, 0.0),
                   (0.0, 0.0, inner_speed))]
    if caged:
        # a constraint cage guided by its rollers is centred by them: its orbit constraints do not see its
        # translation, so nothing else would hold it (on a land, the land does)
        centred = spec.cage.model == "constraint" and spec.bearing.cage_guidance == "rollers"
        bodies.append(Body(str(Role.CAGE), geometry.cage_mass, geometry.cage_inertia, (0.0, 0.0, 0.0),
                           (0.0, 0.0, cage_speed), free=(not centred, not centred, True)))
    radius = geometry.pitch_diameter / 2
    for k, psi in enumerate(geometry.roller_angles):
        x, y = radius * math.cos(psi), radius * math.sin(psi)
        bodies.append(Body(f"roller{k}", geometry.roller_mass, geometry.roller_inertia, (x, y, 0.0),
                           (-cage_speed * y, cage_speed * x, spin)))
    return bodies


def contacts(spec: Spec, geometry: BearingGeometry, oil: OperatingOil, caged: bool):
    """(pairs, orbit constraints, pair indices by group): per roller its two raceway pairs, then by cage model its
    pocket pairs, orbit constraint or roller–roller pair, then its pocket films; last the cage's land pair."""
    laws = {group: group_law(spec, geometry, group, oil) for group in CONTACT_GROUPS}
    film_law = pocket_film_law(spec, geometry, oil) if spec.lubricant.pocket_film else None
    raceways, first = geometry.raceways, first_roller(caged)
    r_w = raceways.roller_radius
    pairs, constraints = [], []
    groups = {group: [] for group in TOPOLOGY_GROUPS}

    def add(group, pair):
        groups[group].append(len(pairs))
        pairs.append(pair)

    for k in range(geometry.rollers):
        roller = first + k
        add(Group.INNER_RACE, ContactPair(f"roller{k}-{Group.INNER_RACE}", "circle_circle", INNER_RING, roller,
                                          laws[Group.INNER_RACE], radius_b=r_w, radius_a=raceways.inner_radius))
        add(Group.OUTER_RACE, ContactPair(f"roller{k}-{Group.OUTER_RACE}", "circle_in_circle", GROUND, roller,
                                          laws[Group.OUTER_RACE], radius_b=r_w, radius_a=raceways.outer_radius))
        if spec.cage.model == "penalty":
            for label, point in geometry.pocket_points(k).items():
                add(Group.POCKET, ContactPair(f"roller{k}-pocket_{label}", "circle_point", CAGE, roller,
                                              laws[Group.POCKET], radius_b=r_w, anchor=point))
        elif spec.cage.model == "constraint":
            psi = geometry.roller_angles[k]
            constraints.append(OrbitConstraint(f"roller{k}-pocket", CAGE, roller, (math.cos(psi), math.sin(psi))))
        else:
            neighbour = (k + 1) % geometry.rollers
            add(Group.ROLLER, ContactPair(f"roller{k}-roller{neighbour}", "circle_circle", roller, first + neighbour,
                                          laws[Group.ROLLER], radius_b=r_w, radius_a=r_w))
        if caged and film_law:
            for label, (point, normal) in geometry.pocket_walls(k).items():
                add(Group.POCKET_FILM, ContactPair(f"roller{k}-pocket_{label}-film", "circle_line", CAGE, roller,
                                                   film_law, radius_b=r_w, anchor=point, direction=normal))
    if caged and spec.bearing.cage_guidance == "inner_land":
        add(Group.LAND, ContactPair("cage-inner_land", "circle_in_circle", CAGE, INNER_RING, laws[Group.LAND],
                                    radius_b=geometry.inner_land_radius, radius_a=geometry.cage_bore_radius))
    elif caged and spec.bearing.cage_guidance == "outer_land":
        add(Group.LAND, ContactPair("cage-outer_land", "circle_in_circle", GROUND, CAGE, laws[Group.LAND],
                                    radius_b=geometry.cage_outer_radius, radius_a=geometry.outer_land_radius))
    return pairs, constraints, groups


def applied_loads(spec: Spec, train: GearTrain | None, ring_inertia: float) -> list:
    """The loads and the drive on the inner ring: the radial load (only when non-zero), then the gear train's
    drive torque and mesh load, or else the velocity servo of time constant ``drive.servo_time_constant``."""
    load, items = spec.load, []
    if load.radial > 0 or load.final > 0 or (load.profile == "table" and any(load.values)):
        angle = math.radians(load.angle)
        items.append(Load("radial_load", INNER_RING, (math.cos(angle), math.sin(angle), 0.0), load_profile(spec)))
    if train is not None:
        end = spec.scenario.end_time
        items.append(Load("drive_torque", INNER_RING, (0.0, 0.0, 1.0),
                          Profile((0.0, end), (train.drive_torque(0.0), train.drive_torque(end)))))
        (fx0, fy0), (fx1, fy1) = train.bearing_load(0.0), train.bearing_load(end)
        items.append(Load("mesh_load_x", INNER_RING, (1.0, 0.0, 0.0), Profile((0.0, end), (fx0, fx1))))
        items.append(Load("mesh_load_y", INNER_RING, (0.0, 1.0, 0.0), Profile((0.0, end), (fy0, fy1))))
    else:
        gain = ring_inertia / spec.drive.servo_time_constant
        items.append(VelocityServo("speed_servo", INNER_RING, gain, speed_profile(spec.drive)))
    return items


def lubricant_elements(spec: Spec, geometry: BearingGeometry, oil: OperatingOil, caged: bool) -> tuple:
    """The lubricant's drag on each roller (none without drag) and, churning, on the cage's bars; then the
    cage–land oil film, with ``[lubricant] land_film``."""
    coefficients = roller_drag(spec, geometry, oil)
    first = first_roller(caged)
    drags = tuple(Drag(f"roller{k}-drag", first + k, **coefficients) for k in range(geometry.rollers)
                  if coefficients)
    if caged and spec.lubricant.model == "churning":
        drags += (Drag("cage-drag", CAGE, angular_quadratic=cage_drag(spec, geometry, oil)),)
    films = (land_film(spec, geometry, oil),) if spec.lubricant.land_film else ()
    return (*drags, *films)


def bearing_topology(geometry: BearingGeometry, groups: dict, caged: bool) -> Topology:
    """Which body is the inner ring, the cage and each roller; which pairs form each contact group (the pocket
    groups one row per roller)."""
    first = first_roller(caged)
    roles = {Role.INNER_RING: [INNER_RING], Role.ROLLERS: list(range(first, first + geometry.rollers))}
    if caged:
        roles[Role.CAGE] = [CAGE]
    for group in (Group.POCKET, Group.POCKET_FILM):
        if groups[group]:
            groups[group] = np.reshape(groups[group], (geometry.rollers, -1))
    return Topology(bodies=roles, pairs={group: indices for group, indices in groups.items() if len(indices)})


def drag_reference_rpm(spec: Spec) -> float:
    """The speed [rpm] at which the lubricant's speed-dependent terms are taken (``[lubricant] reference_rpm``,
    default the drive's highest speed): the drags' coefficients and the starvation factor."""
    return spec.lubricant.reference_rpm or highest_speed_rpm(spec.drive)


def roller_drag(spec: Spec, geometry: BearingGeometry, oil: OperatingOil) -> dict[str, float]:
    """The drag coefficients on each roller from ``[lubricant]`` in the operating ``oil`` (linear [N s/m],
    quadratic [N s²/m²], angular [N m s/rad]; empty without drag)."""
    lubricant = spec.lubricant
    reference_rpm = drag_reference_rpm(spec)
    if lubricant.model == "none" or not reference_rpm:
        return {}
    inner_speed = reference_rpm * RPM
    cage_speed = geometry.epicyclic_cage_speed(inner_speed)
    if cage_speed**2 == 0:  # a reference speed so near rest (1e-160 rpm) that its square underflows: at rest
        return {}
    if lubricant.model == "churning":
        density = mixture_density(lubricant.oil_fraction, oil.density)
        orbital_speed = abs(cage_speed) * geometry.pitch_diameter / 2
        churning = {"quadratic": orbital_drag_coefficient(density, oil.kinematic_viscosity,
                                                          geometry.roller_diameter, geometry.roller_length,
                                                          orbital_speed),
                    "angular": spin_drag_coefficient(lubricant.oil_fraction * oil.dynamic_viscosity,
                                                     geometry.roller_diameter / 2, geometry.roller_length)}
        if lubricant.viscous_drag_factor > 0:
            moment = palmgren_drag_moment(lubricant.viscous_drag_factor, oil.kinematic_viscosity, reference_rpm,
                                          geometry.pitch_diameter)
            churning["linear"] = roller_drag_coefficient(moment, inner_speed, geometry.rollers,
                                                         geometry.pitch_diameter, cage_speed)
        return churning
    moment = lubricant.drag_moment
    if moment is None:
        moment = palmgren_drag_moment(lubricant.drag_factor, oil.palmgren_viscosity, reference_rpm,
                                      geometry.pitch_diameter)
    linear = roller_drag_coefficient(moment, inner_speed, geometry.rollers, geometry.pitch_diameter, cage_speed)
    return {"linear": linear} if linear > 0 else {}


def starvation(spec: Spec, geometry: BearingGeometry, oil: OperatingOil) -> float:
    """The raceway contacts' replenishment factor φ_rs (:func:`.lubrication.replenishment_factor`) at the operating
    ``oil``'s viscosity and the drags' reference speed (:func:`drag_reference_rpm`); 1 (fully flooded) without
    ``[lubricant] starvation`` or at rest. The outside diameter is d_o + (d_i − d): an outer ring as thick as the
    inner one."""
    lubricant = spec.lubricant
    reference_rpm = drag_reference_rpm(spec)
    if not lubricant.starvation or not reference_rpm:
        return 1.0
    bore = spec.bearing.inner_ring_bore
    outside = geometry.outer_race_diameter + geometry.inner_race_diameter - bore
    return replenishment_factor(lubricant.replenishment_constant, oil.kinematic_viscosity, reference_rpm, bore,
                                outside)


def cage_drag(spec: Spec, geometry: BearingGeometry, oil: OperatingOil) -> float:
    """c_θ2 [N m s²/rad²] of the churning drag on the cage's bars (:func:`.lubrication.cage_drag_coefficient`) in
    the operating ``oil``."""
    density = mixture_density(spec.lubricant.oil_fraction, oil.density)
    return cage_drag_coefficient(density, geometry.rollers, spec.bearing.cage_thickness, geometry.roller_length,
                                 geometry.cage_diameter / 2)


def pocket_film_law(spec: Spec, geometry: BearingGeometry, oil: OperatingOil) -> PairLaw:
    """The law of a pocket film pair: no dry contact of its own (the edge pairs have it), the film of the roller's
    length on a wall as tall as the cage ring's section (:attr:`BearingGeometry.pocket_wall_half_width`), in the
    operating ``oil``, floored at three times the pocket's roughness (Λ = 3)."""
    return PairLaw("power", stiffness=0.0, exponent=1.0, restitution=1.0, damping_factor=0.0,
                   approach_speed_floor=spec.contact.pocket.approach_speed_floor,
                   film=(geometry.roller_length, oil.dynamic_viscosity, geometry.pocket_wall_half_width,
                         3 * spec.contact.pocket.roughness))


def land_film(spec: Spec, geometry: BearingGeometry, oil: OperatingOil) -> JournalFilm:
    """The cage–land oil film: a short journal bearing between the cage and the outer ring's land, as wide as the
    cage's side rings, of the land's radial clearance, in the operating ``oil``."""
    return JournalFilm("cage-land-film", CAGE, 1, geometry.cage_outer_radius,
                       spec.bearing.cage_width - geometry.roller_length,
                       geometry.outer_land_radius - geometry.cage_outer_radius, oil.dynamic_viscosity)


def load_profile(spec: Spec) -> Profile:
    """The radial load's magnitude [N] against time."""
    load = spec.load
    end = load.start + load.duration
    if load.profile == "constant":
        return Profile.smooth_ramp(load.radial, load.ramp_time) if load.ramp_time else Profile.constant(load.radial)
    if load.profile == "step":
        ramp = Profile.smooth_ramp(load.radial, load.ramp_time) if load.ramp_time else Profile.constant(load.radial)
        return Profile((*ramp.times, load.start, end), (*ramp.values, load.radial, load.final))
    if load.profile == "ramp":
        return Profile((0.0, load.start, end), (0.0, 0.0, load.radial))
    return Profile(tuple(load.times), tuple(load.values))


def group_law(spec: Spec, geometry: BearingGeometry, group: str, oil: OperatingOil | None = None):
    """The pair law of a contact group (:class:`~bearing_mbs.core.topology.Group`), with its stiffness model and (for
    ``ehl``) its traction row resolved in the operating ``oil`` (the build's; derived here for a caller outside a
    build that has none)."""
    if oil is None:
        oil = operating_oil(spec.lubricant)
    contact = getattr(spec.contact, group)
    bearing = spec.bearing
    other = bearing.cage_material if group in (Group.POCKET, Group.LAND) else bearing.roller_material
    first = bearing.ring_material if group == Group.LAND else bearing.roller_material
    if group in (Group.INNER_RACE, Group.OUTER_RACE):
        other = bearing.ring_material
    length = bearing.cage_width if group == Group.LAND else geometry.roller_length
    modulus = contact_modulus(first.youngs_modulus, first.poisson_ratio, other.youngs_modulus, other.poisson_ratio)
    row = ()
    if contact.friction_law == "ehl":  # the spec admits it on the raceways only
        row = traction_row(contact, oil, *raceway_line_contact(spec, geometry, group), starvation(spec, geometry, oil))
    if contact.stiffness_model == "given":
        return pair_law(contact, traction=row)
    if contact.stiffness_model == "document":
        if group not in DOCUMENT_STIFFNESS:
            raise SpecError(f"contact.{group}.stiffness_model", "document",
                            "the primary document gives stiffnesses for the raceways only (its KC is '?')")
        return pair_law(contact, stiffness=DOCUMENT_STIFFNESS[group], exponent=DOCUMENT_EXPONENT, traction=row)
    stiffness = palmgren_stiffness(length) * modulus / STEEL_CONTACT_MODULUS
    return pair_law(contact, stiffness=stiffness, exponent=PALMGREN_EXPONENT, traction=row)


def raceway_line_contact(spec: Spec, geometry: BearingGeometry, group: str) -> tuple[float, float, float]:
    """(E' [Pa], R [m], l [m]) of a raceway group's line contact (:attr:`Group.INNER_RACE` or
    :attr:`Group.OUTER_RACE`): the roller's and ring's reduced modulus (:func:`~bearing_mbs.contact.line_contact.
    reduced_modulus`), the reduced radius in the rolling direction (:func:`~bearing_mbs.contact.ehl.reduced_radius`,
    concave on the outer raceway) and the roller's effective length."""
    roller, ring = spec.bearing.roller_material, spec.bearing.ring_material
    modulus = reduced_modulus(roller.youngs_modulus, roller.poisson_ratio, ring.youngs_modulus, ring.poisson_ratio)
    raceway = geometry.inner_race_diameter if group == Group.INNER_RACE else geometry.outer_race_diameter
    radius = reduced_radius(raceway / 2, geometry.roller_diameter / 2, group == Group.OUTER_RACE)
    return modulus, float(radius), geometry.roller_length


def traction_row(contact, oil: OperatingOil, modulus: float, radius: float, length: float,
                 replenishment: float) -> tuple[float, ...]:
    """The lubricated-traction row (:data:`~bearing_mbs.contact.traction.TRACTION_COLUMNS`) of a raceway group:
    its contact settings, the operating ``oil``, the reduced modulus E' [Pa], the reduced radius R [m], the contact
    length l [m] and the starvation's replenishment factor φ_rs (:func:`starvation`)."""
    values = {
        "model": TRACTION_MODELS.index(contact.traction_model),
        "film_formula": FILM_FORMULAS.index(contact.film_formula),
        "thermal": float(contact.thermal_reduction), "viscosity": oil.dynamic_viscosity,
        "pressure_viscosity": oil.pressure_viscosity, "temperature_viscosity": oil.temperature_viscosity,
        "conductivity": oil.thermal_conductivity, "modulus": modulus, "radius": radius, "length": length,
        "roughness": contact.roughness, "eyring_stress": contact.eyring_stress, "shear_modulus": contact.shear_modulus,
        "limiting_shear": contact.limiting_shear_coefficient,
        "rolling_resistance": float(contact.ehl_rolling_resistance),
        "shear_heating": float(contact.shear_heating), "replenishment": replenishment,
    }
    curve = contact.traction_curve or (0.0, 0.0, 0.0, 0.0)
    values.update(zip(("curve_a", "curve_b", "curve_c", "curve_d"), curve))
    return tuple(float(values[name]) for name in TRACTION_COLUMNS)


def _reject_initial_overlap(scene: Scene, geometry: BearingGeometry) -> None:
    """Only a preload may make raceway pairs overlap at the start; anything else is a geometry error."""
    preload = geometry.clearance < 0
    raceways = set(scene.topology.group(Group.INNER_RACE).tolist() + scene.topology.group(Group.OUTER_RACE).tolist())
    for k, (pair, gap) in enumerate(zip(scene.pairs, initial_gaps(scene))):
        if gap < -1e-12 and not (k in raceways and preload):
            raise SpecError("bearing", pair.name, f"overlaps by {-gap:.3g} m at the start: check the cage and "
                            f"land geometry")
