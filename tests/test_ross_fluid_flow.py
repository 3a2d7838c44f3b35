"""Our finite-volume journal film against ROSS's finite-difference one (``ross.bearings.fluid_flow.FluidFlow``,
isothermal, Gümbel), run where ROSS installs (``pip install -e '.[ross]'``; skipped elsewhere).

Plain journals, both solvers grid-refined: ROSS's documented ``fluid_flow_example2`` bearing (D = 0.1 m, L = 0.03 m,
C = 0.1 mm, 0.1 Pa s, 157.1 rad/s) at ε = 0.3 and 0.6, and one of ours at L/D = 1 (ε = 0.5). ROSS converges at first
order from above (node grids 16 × 32 … 64 × 128: the load differences halve with each doubling); its
Richardson-extrapolated load and attitude are compared with ours on 240 × 60 cells (converged to 0.05 %). Measured:
−0.16 %, +0.14 % and +0.03 % on the load, at most 0.05° on the attitude; the bounds, 1 % and 0.3°, are several times
the extrapolation's own uncertainty and below the 1.7–4.2 % and 1.4° by which ROSS's finest grid still differs.
"""

from __future__ import annotations

import math
import warnings

import pytest

from bearing_mbs.fluid_film.journal import JournalBearing
from bearing_mbs.fluid_film.reynolds import JournalState, solve_film

pytest.importorskip("ross")

EXAMPLE = {"length": 0.03, "radius_rotor": 0.0499, "radius_stator": 0.05, "viscosity": 0.1, "omega": 157.1}
OURS = {"length": 0.1, "radius_rotor": 0.04995, "radius_stator": 0.05, "viscosity": 0.02, "omega": 300.0}
GRIDS = ((16, 32), (32, 64), (64, 128))


def _ross(case, eps, nodes):
    from ross.bearings.fluid_flow import FluidFlow
    from ross.bearings.fluid_flow_coefficients import calculate_oil_film_force

    clearance = case["radius_stator"] - case["radius_rotor"]
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        film = FluidFlow(*nodes, case["length"], case["omega"], 0.0, 0.0, case["radius_rotor"], case["radius_stator"],
                         case["viscosity"], 860.0, eccentricity=eps * clearance, attitude_angle=math.pi / 4)
        radial, tangential, _, _ = calculate_oil_film_force(film, force_type="numerical")
    return math.hypot(radial, tangential), math.degrees(math.atan2(tangential, radial))


def _extrapolated(values):
    """Richardson's extrapolation of the last of three values on grids refined by 2, at their observed order."""
    coarse, medium, fine = values
    ratio = (coarse - medium) / (medium - fine)
    return fine + (fine - medium) / (ratio - 1)


@pytest.mark.parametrize("case, eps", [(EXAMPLE, 0.3), (EXAMPLE, 0.6), (OURS, 0.5)])
def test_our_film_is_rosss_fluid_flow_refined(case, eps):
    clearance = case["radius_stator"] - case["radius_rotor"]
    loads, attitudes = zip(*(_ross(case, eps, nodes) for nodes in GRIDS), strict=True)
    bearing = JournalBearing(2 * case["radius_rotor"], case["length"], clearance, case["viscosity"])
    film = solve_film(bearing, JournalState((eps * clearance, 0.0), (0.0, 0.0), case["omega"]), grid=(240, 60))
    assert film.load_capacity == pytest.approx(_extrapolated(loads), rel=0.01)
    assert film.attitude_angle == pytest.approx(_extrapolated(attitudes), abs=0.3)
    assert abs(loads[-1] / film.load_capacity - 1) > 0.005  # ROSS's finest grid alone is not yet converged
