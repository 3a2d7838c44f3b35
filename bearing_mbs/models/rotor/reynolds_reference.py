"""The rotor at constant speed with the film force of a full Reynolds solve at every evaluation: the reference the
force map and the closed form are measured against, and its cost (docs/fluid-film.md).

Not an engine: four states (x, y and their rates), the speed held at ``drive.speed_rpm``, integrated by scipy's
LSODA (the film's squeeze damping makes the motion stiff) from the scene's initial state. Each force is a
Gümbel solve of :mod:`bearing_mbs.fluid_film.reynolds` on ``bearing.grid``.
"""

from __future__ import annotations

import math
import time as clock
from dataclasses import dataclass

import numpy as np
from scipy.integrate import solve_ivp

from bearing_mbs.fluid_film.journal import FilmGrid
from bearing_mbs.fluid_film.reynolds import JournalState, solve_film
from bearing_mbs.models.rotor.build import equilibrium
from bearing_mbs.models.rotor.spec import RotorSpec


@dataclass(frozen=True)
class ReferenceOrbit:
    """time [s] (T,), centre (T, 2) [m], solves: Reynolds solves made, wall_time_s."""

    time: np.ndarray
    centre: np.ndarray
    solves: int
    wall_time_s: float


def reynolds_orbit(spec: RotorSpec, times: np.ndarray, rtol: float = 1e-8) -> ReferenceOrbit:
    bearing, supply, rotor = spec.bearing.bearing(), spec.bearing.supply(), spec.rotor
    grid = FilmGrid.build(bearing, *spec.bearing.grid)
    speed = spec.drive.speed_rpm * math.pi / 30
    weight = np.array([0.0, -rotor.mass * spec.scenario.gravity])
    solves = 0

    def rates(t, y):
        nonlocal solves
        solves += 1
        film = solve_film(bearing, JournalState((y[0], y[1]), (y[2], y[3]), speed), supply, grid)
        angle = speed * t
        unbalance = rotor.unbalance * speed**2 * np.array([math.cos(angle), math.sin(angle)])
        return [y[2], y[3], *((rotor.bearings * film.force + weight + unbalance) / rotor.mass)]

    start = equilibrium(spec, speed) + np.array(rotor.initial_offset)
    began = clock.perf_counter()
    solution = solve_ivp(rates, (0.0, float(times[-1])), [*start, 0.0, 0.0], method="LSODA", t_eval=times, rtol=rtol,
                         atol=1e-6 * spec.bearing.radial_clearance)
    if not solution.success:
        raise RuntimeError(f"the Reynolds reference did not finish: {solution.message}")
    return ReferenceOrbit(solution.t, solution.y[:2].T, solves, clock.perf_counter() - began)
