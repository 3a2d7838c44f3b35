"""Cost of the fluid-film journal bearing (docs/fluid-film.md), measured in one run.

* ``static_solve_120x30``: document 001's four-recess capillary bearing at ε = 0.25, 0 rpm, Gümbel, 120 × 30 cells
  (the issue's target: ≤ 20 ms on the 2-core machine);
* ``static_solve_240x60``: the same on the command's default grid;
* ``static_solve_jfo_1000rpm``: the same bearing at 1000 rpm with mass-conserving cavitation (active set);
* ``film_force_recessed_map``: one force evaluation of the hybrid spindle's recessed-bearing force map
  (``seed_hybrid_spindle.toml`` at 20 000 rpm, two bearings, 60 × 16 cells) in the reference engine's time loop (the
  issue's target: ≤ 10 µs); ``recessed_map_build``: building that map;
* ``short_bearing_force``: one call of the dynamic short-bearing closed form from Python (numpy);
* ``film_force_<source>``: one force evaluation inside the reference engine's time loop (its RK4 run's wall time
  divided by its force evaluations: journal bearings, servo, unbalance and the integrator's own work) with the
  ``short`` and ``map`` film forces (target ≤ 5 µs); ``film_force_call_<source>``: one call of the compiled scene
  forces from Python (mostly the call's overhead);
* ``whirl_second_<source>_<engine>``: wall time per simulated second of ``seed_rotor_whirl.toml`` (constant
  11 000 rpm, 0.5 s run), for each force source on each engine, and ``whirl_second_reynolds``: the same with a
  Reynolds solve (60 × 16 cells) per force evaluation (:mod:`bearing_mbs.models.rotor.reynolds_reference`,
  measured over 0.01 s).
Ratios are to the 120 × 30 solve in the same run.
"""

from __future__ import annotations

import math
import time

from bearing_mbs.fluid_film.closed_forms import short_bearing_force
from bearing_mbs.fluid_film.journal import FilmGrid, JournalBearing, Recesses
from bearing_mbs.fluid_film.restrictors import Capillary
from bearing_mbs.fluid_film.reynolds import JournalState, Supply, solve_film

from bearing_mbs.contact.kernel import N_PAIR_OUTPUTS
from bearing_mbs.elements import pack_scene, scene_forces
from bearing_mbs.engines import simulate
from bearing_mbs.models import build_scene, load_spec
from bearing_mbs.models.rotor.reynolds_reference import reynolds_orbit

from common import SCENARIOS, best_of, write

import numpy as np

BEARING = JournalBearing(0.075, 0.075, 35e-6, 0.028, 860.0, Recesses(4, 45.0, 0.060, 0.001))
SUPPLY = Supply(1e6, Capillary(0.020, 0.0006))
STATIC = JournalState((0.25 * 35e-6, 0.0))
TURNING = JournalState((0.5 * 35e-6, 0.0), speed=1000 * 2 * math.pi / 60)


def main() -> dict:
    figures = {}
    for name, state, grid, cavitation in (("static_solve_120x30", STATIC, (120, 30), "gumbel"),
                                          ("static_solve_240x60", STATIC, (240, 60), "gumbel"),
                                          ("static_solve_jfo_1000rpm", TURNING, (120, 30), "jfo")):
        film_grid = FilmGrid.build(BEARING, *grid)
        figures[name] = best_of(lambda: solve_film(BEARING, state, SUPPLY, film_grid, cavitation))
    calls = 2000
    figures["short_bearing_force"] = best_of(lambda: [short_bearing_force(
        17.5e-6, 3e-6, 1e-4, -2e-4, 104.7, 0.0375, 0.0075, 35e-6, 0.028) for _ in range(calls)]) / calls
    whirl = ["drive.speed_rpm=11000", "drive.start_rpm=11000", "drive.ramp_time=0", "scenario.end_time=0.5"]
    for source in ("short", "map"):
        spec = load_spec(SCENARIOS / "seed_rotor_whirl.toml", whirl + [f"bearing.force={source}"])
        packed = pack_scene(build_scene(spec))
        q, v = np.array([12e-6, -10e-6, 0.3]), np.array([1e-3, -2e-3, 1100.0])
        forces, outputs = np.zeros(3), np.zeros((0, N_PAIR_OUTPUTS))
        figures[f"film_force_call_{source}"] = best_of(lambda: [scene_forces(packed, 0.0, q, v, np.zeros(0), forces,
                                                                        outputs) for _ in range(calls)]) / calls
        for engine in ("exudyn", "reference"):
            run = load_spec(SCENARIOS / "seed_rotor_whirl.toml", whirl + [f"bearing.force={source}",
                                                                           f"solver.engine={engine}"])
            scene = build_scene(run)
            simulate(scene, run.solver, 0.01)  # warm-up: compilation and caches
            stats = simulate(scene, run.solver, 0.5).stats
            figures[f"whirl_second_{source}_{engine}"] = stats.wall_time_s / 0.5
            if engine == "reference":
                figures[f"film_force_{source}"] = stats.wall_time_s / stats.force_evaluations
    spindle = load_spec(SCENARIOS / "seed_hybrid_spindle.toml", ["drive.speed_rpm=20000", "drive.start_rpm=20000",
                                                                  "drive.ramp_time=0", "solver.engine=reference"])
    began = time.perf_counter()
    scene = build_scene(spindle)
    figures["recessed_map_build"] = time.perf_counter() - began
    simulate(scene, spindle.solver, 0.001)
    stats = simulate(scene, spindle.solver, 0.1).stats
    figures["film_force_recessed_map"] = stats.wall_time_s / stats.force_evaluations
    spec = load_spec(SCENARIOS / "seed_rotor_whirl.toml", whirl + ["bearing.grid=[60, 16]"])
    figures["whirl_second_reynolds"] = reynolds_orbit(spec, np.linspace(0, 0.01, 11)).wall_time_s / 0.01
    ratios = {name: value / figures["static_solve_120x30"] for name, value in figures.items()}
    return write("journal", {"seconds": figures, "ratio_to_static_solve_120x30": ratios})


if __name__ == "__main__":
    main()
