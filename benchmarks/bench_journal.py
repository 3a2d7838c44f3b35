"""Cost of the fluid-film journal bearing (docs/fluid-film.md), measured in one run.

* ``static_solve_120x30``: document 001's four-recess capillary bearing at ε = 0.25, 0 rpm, Gümbel, 120 × 30 cells
  (the issue's target: ≤ 20 ms on the 2-core machine);
* ``static_solve_240x60``: the same on the command's default grid;
* ``static_solve_jfo_1000rpm``: the same bearing at 1000 rpm with mass-conserving cavitation (active set);
* ``short_bearing_force``: one call of the dynamic short-bearing closed form from Python (numpy).
Ratios are to the 120 × 30 solve in the same run.
"""

from __future__ import annotations

import math

from bearing_mbs.fluid_film.closed_forms import short_bearing_force
from bearing_mbs.fluid_film.journal import FilmGrid, JournalBearing, Recesses
from bearing_mbs.fluid_film.restrictors import Capillary
from bearing_mbs.fluid_film.reynolds import JournalState, Supply, solve_film

from common import best_of, write

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
        (17.5e-6, 3e-6), (1e-4, -2e-4), 104.7, 0.0375, 0.0075, 35e-6, 0.028) for _ in range(calls)]) / calls
    ratios = {name: value / figures["static_solve_120x30"] for name, value in figures.items()}
    return write("journal", {"seconds": figures, "ratio_to_static_solve_120x30": ratios})


if __name__ == "__main__":
    main()
