"""The rotor's scene, its film force and its static equilibrium.

One planar body (x, y: the journal centre relative to the bearings' centre; θ: the spin) on ``bearings`` identical
:class:`~bearing_mbs.elements.journal_bearings.JournalFilm` bearings, driven by a velocity servo, with an optional
:class:`~bearing_mbs.elements.unbalances.Unbalance`. It starts at the static equilibrium of the start speed plus
``initial_offset``.

The rotor linearised about this equilibrium is :mod:`.linear`'s.
"""

from __future__ import annotations

import logging
import math
from functools import lru_cache

import numpy as np

from bearing_mbs.core.scene import Body, Profile, Scene
from bearing_mbs.core.topology import Role, Topology
from bearing_mbs.elements import VelocityServo
from bearing_mbs.elements.journal_bearings import JournalFilm
from bearing_mbs.elements.unbalances import Unbalance
from bearing_mbs.fluid_film.closed_forms import short_bearing_force
from bearing_mbs.fluid_film.equilibrium import film_equilibrium
from bearing_mbs.fluid_film.force_map import ForceMap, build_force_map, interpolation_error
from bearing_mbs.fluid_film.journal import FilmGrid
from bearing_mbs.fluid_film.reynolds import JournalState, solve_film
from bearing_mbs.models.rotor.spec import BearingSection, RotorSpec
from bearing_mbs.spec import SpecError

log = logging.getLogger(__name__)


@lru_cache(maxsize=8)
def _force_map(section: BearingSection) -> ForceMap:
    if section.recesses is not None:
        log.info("building the recessed bearing's force map from Reynolds solves on %d × %d cells (about 10 s on "
                 "60 × 16, 75 s on 120 × 30)", *section.grid)
    return build_force_map(section.bearing(), tuple(section.grid), section.supply())


def force_map_of(spec: RotorSpec) -> ForceMap:
    return _force_map(spec.bearing)


def map_error(spec: RotorSpec) -> float:
    """The force map's largest interpolation error (:func:`~bearing_mbs.fluid_film.force_map.interpolation_error`)."""
    return _map_error(spec.bearing)


@lru_cache(maxsize=8)
def _map_error(section: BearingSection) -> float:
    return interpolation_error(section.bearing(), _force_map(section), tuple(section.grid), section.supply())


def map_orbit_error(spec: RotorSpec, centres: np.ndarray, velocities: np.ndarray) -> float:
    """The largest |F_map − F_solve| over the largest |F_solve| of the force map against a Reynolds solve (Gümbel, the
    map's grid and supply) at the journal states (centre (x, y) [m]; velocity (ẋ, ẏ) [m/s] and spin [rad/s]) of a
    run."""
    b, table = spec.bearing, force_map_of(spec)
    bearing, supply, grid = b.bearing(), b.supply(), FilmGrid.build(b.bearing(), *b.grid)
    states = np.column_stack([centres, velocities])
    mapped = table.forces(states, b.radial_clearance)
    solved = np.array([solve_film(bearing, JournalState(tuple(state[:2]), tuple(state[2:4]), state[4]), supply,
                                  grid).force for state in states])
    largest = np.hypot(*solved.T).max()
    return float(np.hypot(*(mapped - solved).T).max() / largest) if largest > 0 else 0.0


def film_force(spec: RotorSpec):
    """``force(state) -> (F_x, F_y)`` [N] of all the rotor's bearings together, by the scenario's source."""
    b, count = spec.bearing, spec.rotor.bearings
    if b.force == "short":
        def force(state: JournalState):
            return count * np.array(short_bearing_force(*state.eccentricity, *state.eccentricity_rate,
                                                                state.speed, b.diameter / 2, b.length,
                                                                b.radial_clearance, b.viscosity))
    else:
        table = force_map_of(spec)

        def force(state: JournalState):
            states = [[*state.eccentricity, *state.eccentricity_rate, state.speed]]
            return count * table.forces(states, b.radial_clearance)[0]
    return force


def equilibrium(spec: RotorSpec, speed: float) -> np.ndarray:
    """The journal centre (x, y) [m] where the films carry the rotor's weight at speed Ω [rad/s]
    (:func:`~bearing_mbs.fluid_film.equilibrium.film_equilibrium`)."""
    weight = np.array([0.0, -spec.rotor.mass * spec.scenario.gravity])
    found = film_equilibrium(film_force(spec), spec.bearing.radial_clearance, weight, speed)
    if found is None:
        raise SpecError("drive.start_rpm", speed * 30 / math.pi,
                        "a speed at which the bearings carry the rotor's weight (no film equilibrium found below ε = 1)")
    return found


def speed_profile(spec: RotorSpec) -> Profile:
    drive, end = spec.drive, spec.scenario.end_time
    target = drive.speed_rpm * math.pi / 30
    if drive.ramp_time == 0:
        return Profile((0.0,), (target,))
    return Profile((0.0, drive.ramp_time, max(end, drive.ramp_time)), (drive.start_speed, target, target))


def build_rotor_scene(spec: RotorSpec) -> Scene:
    b, rotor = spec.bearing, spec.rotor
    start = equilibrium(spec, spec.drive.start_speed) + np.array(rotor.initial_offset)
    if np.hypot(*start) >= b.radial_clearance:
        raise SpecError("rotor.initial_offset", list(rotor.initial_offset),
                        f"a start inside the clearance: the equilibrium is at {np.hypot(*start):.3g} m from the centre")
    body = Body("rotor", rotor.mass, rotor.polar_inertia, (start[0], start[1], 0.0),
                (0.0, 0.0, spec.drive.start_speed))
    film = {"name": "bearings", "body": 0, "count": rotor.bearings, "radius": b.diameter / 2, "length": b.length,
            "clearance": b.radial_clearance, "viscosity": b.viscosity, "source": b.force}
    if b.force == "map":
        table = force_map_of(spec)
        film.update(map_normal=table.normal, map_tangential=table.tangential, map_linear=table.linear,
                    map_axes=table.axes)
    forces = [JournalFilm(**film), VelocityServo("drive", 0, spec.drive.gain, speed_profile(spec))]
    if rotor.unbalance > 0:
        forces.append(Unbalance("unbalance", 0, rotor.unbalance))
    return Scene(spec.scenario.name, (body,), forces=tuple(forces), gravity=(0.0, -spec.scenario.gravity),
                 topology=Topology(bodies={Role.ROTOR: [0]}))
