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
from bearing_mbs.core.topology import Topology
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
from bearing_mbs.spec import Spec, SpecError

#: The primary document's raceway laws K δ^1.3 (annex II: KI, KE, NI = NE).
DOCUMENT_STIFFNESS = {"inner_race": 3e10, "outer_race": 4e10}
DOCUMENT_EXPONENT = 1.3

INNER_RING, CAGE = 0, 1


def build_bearing_scene(spec: Spec) -> Scene:
    geometry = BearingGeometry.from_spec(spec.bearing)
    caged = spec.cage.model != "none"
    if caged:
        geometry.require_cage(spec.bearing)
    first_roller = 2 if caged else 1
    drive = spec.drive
    train = GearTrain(drive.gear_train) if drive.kind == "gear_train" else None

    inner_speed = initial_speed(drive)
    rolling = drive.initial_state == "rolling"
    cage_speed = geometry.epicyclic_cage_speed(inner_speed) if rolling else 0.0
    spin = geometry.epicyclic_roller_spin(inner_speed) if rolling else 0.0
    ring_inertia = geometry.inner_ring_inertia + (train.reduced_inertia if train else 0.0)

    bodies = [Body("inner_ring", geometry.inner_ring_mass, ring_inertia, (0.0, 0.0, 0.0), (0.0, 0.0, inner_speed))]
    if caged:
        # a constraint cage guided by its rollers is centred by them: its orbit constraints do not see its
        # translation, so nothing else would hold it (on a land, the land does)
        centred = spec.cage.model == "constraint" and spec.bearing.cage_guidance == "rollers"
        bodies.append(Body("cage", geometry.cage_mass, geometry.cage_inertia, (0.0, 0.0, 0.0), (0.0, 0.0, cage_speed),
                           free=(not centred, not centred, True)))
    radius = geometry.pitch_diameter / 2
    for k, psi in enumerate(geometry.roller_angles):
        x, y = radius * math.cos(psi), radius * math.sin(psi)
        bodies.append(Body(f"roller{k}", geometry.roller_mass, geometry.roller_inertia, (x, y, 0.0),
                           (-cage_speed * y, cage_speed * x, spin)))

    laws = {group: group_law(spec, geometry, group) for group in ("inner_race", "outer_race", "pocket", "land", "roller")}
    r_w = geometry.roller_diameter / 2
    pairs, constraints = [], []
    groups = {"inner_race": [], "outer_race": [], "pocket": [], "pocket_film": [], "roller": [], "land": []}
    film_law = pocket_film_law(spec, geometry) if spec.lubricant.pocket_film else None

    def add(group, pair):
        groups[group].append(len(pairs))
        pairs.append(pair)

    for k in range(geometry.rollers):
        roller = first_roller + k
        add("inner_race", ContactPair(f"roller{k}-inner_race", "circle_circle", INNER_RING, roller, laws["inner_race"],
                                 radius_b=r_w, radius_a=geometry.inner_race_diameter / 2))
        add("outer_race", ContactPair(f"roller{k}-outer_race", "circle_in_circle", GROUND, roller, laws["outer_race"],
                                 radius_b=r_w, radius_a=geometry.outer_race_diameter / 2))
        if spec.cage.model == "penalty":
            for label, point in geometry.pocket_points(k).items():
                add("pocket", ContactPair(f"roller{k}-pocket_{label}", "circle_point", CAGE, roller, laws["pocket"],
                                         radius_b=r_w, anchor=point))
        elif spec.cage.model == "constraint":
            psi = geometry.roller_angles[k]
            constraints.append(OrbitConstraint(f"roller{k}-pocket", CAGE, roller, (math.cos(psi), math.sin(psi))))
        else:
            neighbour = first_roller + (k + 1) % geometry.rollers
            add("roller", ContactPair(f"roller{k}-roller{(k + 1) % geometry.rollers}", "circle_circle", roller,
                                     neighbour, laws["roller"], radius_b=r_w, radius_a=r_w))
        if caged and film_law:
            for label, (point, normal) in geometry.pocket_walls(k).items():
                add("pocket_film", ContactPair(f"roller{k}-pocket_{label}-film", "circle_line", CAGE, roller,
                                               film_law, radius_b=r_w, anchor=point, direction=normal))
    if caged and spec.bearing.cage_guidance == "inner_land":
        add("land", ContactPair("cage-inner_land", "circle_in_circle", CAGE, INNER_RING, laws["land"],
                                 radius_b=geometry.inner_land_radius, radius_a=geometry.cage_bore_radius))
    elif caged and spec.bearing.cage_guidance == "outer_land":
        add("land", ContactPair("cage-outer_land", "circle_in_circle", GROUND, CAGE, laws["land"],
                                 radius_b=geometry.cage_outer_radius, radius_a=geometry.outer_land_radius))

    loads, drives = [], []
    load = spec.load
    if load.radial > 0 or load.final > 0 or (load.profile == "table" and any(load.values)):
        angle = math.radians(load.angle)
        loads.append(Load("radial_load", INNER_RING, (math.cos(angle), math.sin(angle), 0.0), load_profile(spec)))
    if train is not None:
        end = spec.scenario.end_time
        loads.append(Load("drive_torque", INNER_RING, (0.0, 0.0, 1.0),
                          Profile((0.0, end), (train.drive_torque(0.0), train.drive_torque(end)))))
        (fx0, fy0), (fx1, fy1) = train.bearing_load(0.0), train.bearing_load(end)
        loads.append(Load("mesh_load_x", INNER_RING, (1.0, 0.0, 0.0), Profile((0.0, end), (fx0, fx1))))
        loads.append(Load("mesh_load_y", INNER_RING, (0.0, 1.0, 0.0), Profile((0.0, end), (fy0, fy1))))
    else:
        gain = ring_inertia / drive.servo_time_constant
        drives.append(VelocityServo("speed_servo", INNER_RING, gain, speed_profile(drive)))

    coefficients = roller_drag(spec, geometry)
    drags = tuple(Drag(f"roller{k}-drag", first_roller + k, **coefficients) for k in range(geometry.rollers)
                  if coefficients)
    if caged and spec.lubricant.model == "churning":
        drags += (Drag("cage-drag", CAGE, angular_quadratic=cage_drag(spec, geometry)),)
    films = (land_film(spec, geometry),) if spec.lubricant.land_film else ()
    roles = {"inner_ring": [INNER_RING], "rollers": list(range(first_roller, first_roller + geometry.rollers))}
    if caged:
        roles["cage"] = [CAGE]
    for group in ("pocket", "pocket_film"):
        if groups[group]:
            groups[group] = np.reshape(groups[group], (geometry.rollers, -1))
    topology = Topology(bodies=roles, pairs={group: indices for group, indices in groups.items() if len(indices)})
    scene = Scene(spec.scenario.name, tuple(bodies), tuple(pairs), tuple(constraints),
                  (*loads, *drives, *drags, *films), gravity=(0.0, -spec.scenario.gravity), topology=topology)
    _reject_initial_overlap(scene, geometry)
    return scene


def drag_reference_rpm(spec: Spec) -> float:
    """The speed [rpm] at which the lubricant's speed-dependent terms are taken (``[lubricant] reference_rpm``,
    default the drive's highest speed): the drags' coefficients and the starvation factor."""
    return spec.lubricant.reference_rpm or highest_speed_rpm(spec.drive)


def roller_drag(spec: Spec, geometry: BearingGeometry) -> dict[str, float]:
    """The drag coefficients on each roller from ``[lubricant]`` (linear [N s/m], quadratic [N s²/m²], angular
    [N m s/rad]; empty without drag)."""
    lubricant = spec.lubricant
    reference_rpm = drag_reference_rpm(spec)
    if lubricant.model == "none" or not reference_rpm:
        return {}
    inner_speed = reference_rpm * RPM
    cage_speed = geometry.epicyclic_cage_speed(inner_speed)
    if cage_speed**2 == 0:  # a reference speed so near rest (1e-160 rpm) that its square underflows: at rest
        return {}
    if lubricant.model == "churning":
        oil, temperature = lubricant.lubricant(), lubricant.temperature
        density = mixture_density(lubricant.oil_fraction, oil.density(temperature))
        orbital_speed = abs(cage_speed) * geometry.pitch_diameter / 2
        churning = {"quadratic": orbital_drag_coefficient(density, oil.kinematic_viscosity(temperature),
                                                          geometry.roller_diameter, geometry.roller_length,
                                                          orbital_speed),
                    "angular": spin_drag_coefficient(lubricant.oil_fraction * oil.dynamic_viscosity(temperature),
                                                     geometry.roller_diameter / 2, geometry.roller_length)}
        if lubricant.viscous_drag_factor > 0:
            moment = palmgren_drag_moment(lubricant.viscous_drag_factor, oil.kinematic_viscosity(temperature),
                                          reference_rpm, geometry.pitch_diameter)
            churning["linear"] = roller_drag_coefficient(moment, inner_speed, geometry.rollers,
                                                         geometry.pitch_diameter, cage_speed)
        return churning
    moment = lubricant.drag_moment
    if moment is None:
        moment = palmgren_drag_moment(lubricant.drag_factor, lubricant.operating_viscosity(), reference_rpm,
                                      geometry.pitch_diameter)
    linear = roller_drag_coefficient(moment, inner_speed, geometry.rollers, geometry.pitch_diameter, cage_speed)
    return {"linear": linear} if linear > 0 else {}


def starvation(spec: Spec, geometry: BearingGeometry) -> float:
    """The raceway contacts' replenishment factor φ_rs (:func:`.lubrication.replenishment_factor`) at the oil's
    viscosity and the drags' reference speed (:func:`drag_reference_rpm`); 1 (fully flooded) without ``[lubricant] starvation`` or at rest. The
    outside diameter is d_o + (d_i − d): an outer ring as thick as the inner one."""
    lubricant = spec.lubricant
    reference_rpm = drag_reference_rpm(spec)
    if not lubricant.starvation or not reference_rpm:
        return 1.0
    bore = spec.bearing.inner_ring_bore
    outside = geometry.outer_race_diameter + geometry.inner_race_diameter - bore
    return replenishment_factor(lubricant.replenishment_constant,
                                lubricant.lubricant().kinematic_viscosity(lubricant.temperature), reference_rpm,
                                bore, outside)


def cage_drag(spec: Spec, geometry: BearingGeometry) -> float:
    """c_θ2 [N m s²/rad²] of the churning drag on the cage's bars (:func:`.lubrication.cage_drag_coefficient`)."""
    lubricant = spec.lubricant
    density = mixture_density(lubricant.oil_fraction, lubricant.lubricant().density(lubricant.temperature))
    return cage_drag_coefficient(density, geometry.rollers, spec.bearing.cage_thickness, geometry.roller_length,
                                 geometry.cage_diameter / 2)


def pocket_film_law(spec: Spec, geometry: BearingGeometry) -> PairLaw:
    """The law of a pocket film pair: no dry contact of its own (the edge pairs have it), the film of the roller's
    length on a wall as tall as the cage ring's section (:attr:`BearingGeometry.pocket_wall_half_width`), in the oil
    at its operating temperature, floored at three times the pocket's roughness (Λ = 3)."""
    lubricant = spec.lubricant
    viscosity = lubricant.lubricant().dynamic_viscosity(lubricant.temperature)
    return PairLaw("power", stiffness=0.0, exponent=1.0, restitution=1.0, damping_factor=0.0,
                   approach_speed_floor=spec.contact.pocket.approach_speed_floor,
                   film=(geometry.roller_length, viscosity, geometry.pocket_wall_half_width,
                         3 * spec.contact.pocket.roughness))


def land_film(spec: Spec, geometry: BearingGeometry) -> JournalFilm:
    """The cage–land oil film: a short journal bearing between the cage and the outer ring's land, as wide as the
    cage's side rings, of the land's radial clearance, in the oil at its operating temperature."""
    lubricant = spec.lubricant
    return JournalFilm("cage-land-film", CAGE, 1, geometry.cage_outer_radius,
                       spec.bearing.cage_width - geometry.roller_length,
                       geometry.outer_land_radius - geometry.cage_outer_radius,
                       lubricant.lubricant().dynamic_viscosity(lubricant.temperature))


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


def group_law(spec: Spec, geometry: BearingGeometry, group: str):
    """The pair law of a contact group, with its stiffness model and (for ``ehl``) its traction row resolved."""
    contact = getattr(spec.contact, group)
    bearing = spec.bearing
    other = bearing.cage_material if group in ("pocket", "land") else bearing.roller_material
    first = bearing.ring_material if group == "land" else bearing.roller_material
    if group in ("inner_race", "outer_race"):
        other = bearing.ring_material
    length = bearing.cage_width if group == "land" else geometry.roller_length
    modulus = contact_modulus(first.youngs_modulus, first.poisson_ratio, other.youngs_modulus, other.poisson_ratio)
    row = ()
    if contact.friction_law == "ehl":  # the spec admits it on the raceways only
        row = traction_row(contact, spec.lubricant, *raceway_line_contact(spec, geometry, group),
                           starvation(spec, geometry))
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
    """(E' [Pa], R [m], l [m]) of a raceway group's line contact ('inner_race' or 'outer_race'): twice the roller's
    and ring's reduced modulus (:func:`~bearing_mbs.contact.line_contact.reduced_modulus`), the reduced radius
    in the rolling direction (:func:`~bearing_mbs.contact.ehl.reduced_radius`, concave on the outer raceway) and the
    roller's effective length."""
    roller, ring = spec.bearing.roller_material, spec.bearing.ring_material
    modulus = reduced_modulus(roller.youngs_modulus, roller.poisson_ratio, ring.youngs_modulus, ring.poisson_ratio)
    raceway = geometry.inner_race_diameter if group == "inner_race" else geometry.outer_race_diameter
    radius = reduced_radius(raceway / 2, geometry.roller_diameter / 2, group == "outer_race")
    return modulus, float(radius), geometry.roller_length


def traction_row(contact, lubricant, modulus: float, radius: float, length: float,
                 replenishment: float) -> tuple[float, ...]:
    """The lubricated-traction row (:data:`~bearing_mbs.contact.traction.TRACTION_COLUMNS`) of a raceway group:
    its contact settings, the oil at the operating temperature, E' [Pa], the reduced radius R [m], the contact
    length l [m] and the starvation's replenishment factor φ_rs (:func:`starvation`)."""
    oil, temperature = lubricant.lubricant(), lubricant.temperature
    values = {
        "model": TRACTION_MODELS.index(contact.traction_model),
        "film_formula": FILM_FORMULAS.index(contact.film_formula),
        "thermal": float(contact.thermal_reduction), "viscosity": oil.dynamic_viscosity(temperature),
        "pressure_viscosity": lubricant.operating_pressure_viscosity(),
        "temperature_viscosity": oil.temperature_viscosity(temperature),
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
    raceways = set(scene.topology.group("inner_race").tolist() + scene.topology.group("outer_race").tolist())
    for k, (pair, gap) in enumerate(zip(scene.pairs, initial_gaps(scene))):
        if gap < -1e-12 and not (k in raceways and preload):
            raise SpecError("bearing", pair.name, f"overlaps by {-gap:.3g} m at the start: check the cage and "
                            f"land geometry")
