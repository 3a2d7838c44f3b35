"""The rotor's scene, its film force, static equilibrium and linearised whirl threshold.

One planar body (x, y: the journal centre relative to the bearings' centre; θ: the spin) on ``bearings`` identical
:class:`~bearing_mbs.elements.journal_bearings.JournalFilm` bearings, driven by a velocity servo, with an optional
:class:`~bearing_mbs.elements.unbalances.Unbalance`. It starts at the static equilibrium of the start speed plus
``initial_offset``.

The whirl threshold (:func:`whirl_threshold`) is the lowest speed at which the rotor's small motions about its
equilibrium grow: the eigenvalues of :math:`M\\ddot x + C\\dot x + K x = 0`, with K and C the bearings' linearised
coefficients (:mod:`bearing_mbs.fluid_film.coefficients`), cross the imaginary axis.
"""

from __future__ import annotations

import math
from functools import lru_cache

import numpy as np
from scipy.optimize import brentq

from bearing_mbs.core.scene import Body, Profile, Scene
from bearing_mbs.core.topology import Topology
from bearing_mbs.elements import VelocityServo
from bearing_mbs.elements.journal_bearings import JournalFilm
from bearing_mbs.elements.unbalances import Unbalance
from bearing_mbs.fluid_film.closed_forms import short_bearing_force
from bearing_mbs.fluid_film.coefficients import dynamic_coefficients
from bearing_mbs.fluid_film.equilibrium import film_equilibrium
from bearing_mbs.fluid_film.force_map import build_force_map, interpolation_error, map_force
from bearing_mbs.fluid_film.journal import JournalBearing
from bearing_mbs.fluid_film.reynolds import JournalState
from bearing_mbs.models.rotor.spec import RotorSpec
from bearing_mbs.spec import SpecError


def plain_bearing(spec: RotorSpec) -> JournalBearing:
    b = spec.bearing
    return JournalBearing(b.diameter, b.length, b.radial_clearance, b.viscosity)


@lru_cache(maxsize=8)
def _force_map(diameter, length, clearance, viscosity, grid):
    return build_force_map(JournalBearing(diameter, length, clearance, viscosity), grid)


def force_map_of(spec: RotorSpec):
    b = spec.bearing
    return _force_map(b.diameter, b.length, b.radial_clearance, b.viscosity, tuple(b.grid))


def map_error(spec: RotorSpec) -> float:
    """The force map's largest interpolation error (:func:`~bearing_mbs.fluid_film.force_map.interpolation_error`)."""
    return interpolation_error(plain_bearing(spec), force_map_of(spec), tuple(spec.bearing.grid))


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
            return count * np.array(map_force(table.normal, table.tangential, table.eccentricity_step,
                                                      *state.eccentricity, *state.eccentricity_rate, state.speed,
                                                      b.radial_clearance))
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


def growth_rate(spec: RotorSpec, speed: float) -> float:
    """The largest real part [1/s] of the linearised rotor's eigenvalues about its equilibrium at Ω [rad/s]."""
    state = JournalState(tuple(equilibrium(spec, speed)), (0.0, 0.0), speed)
    stiffness, damping = dynamic_coefficients(film_force(spec), state, spec.bearing.radial_clearance)
    mass = spec.rotor.mass
    system = np.block([[np.zeros((2, 2)), np.eye(2)], [-stiffness / mass, -damping / mass]])
    return float(np.linalg.eigvals(system).real.max())


def whirl_threshold(spec: RotorSpec, low_rpm: float = 100.0, high_rpm: float = 1e5) -> float | None:
    """The lowest speed [rpm] in [low, high] at which the linearised rotor becomes unstable (None if never); speeds
    too low for the films to carry the rotor are skipped."""
    speeds = np.geomspace(low_rpm, high_rpm, 40) * math.pi / 30
    rates = []
    for speed in speeds:
        try:
            rates.append(growth_rate(spec, speed))
        except SpecError:
            rates.append(math.nan)
    for k in range(1, len(speeds)):
        if rates[k - 1] < 0 <= rates[k]:
            return brentq(lambda s: growth_rate(spec, s), speeds[k - 1], speeds[k], xtol=1e-6) * 30 / math.pi
    return None


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
        film.update(map_normal=table.normal, map_tangential=table.tangential, map_step=table.eccentricity_step)
    forces = [JournalFilm(**film), VelocityServo("drive", 0, spec.drive.gain, speed_profile(spec))]
    if rotor.unbalance > 0:
        forces.append(Unbalance("unbalance", 0, rotor.unbalance))
    return Scene(spec.scenario.name, (body,), forces=tuple(forces), gravity=(0.0, -spec.scenario.gravity),
                 topology=Topology(bodies={"rotor": [0]}))
