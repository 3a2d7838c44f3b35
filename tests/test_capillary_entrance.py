"""Capillary entrance losses (``journal.recesses.capillary_entrance_loss``, bearing_mbs/fluid_film/restrictors.py).

The drop across a capillary with its entry is R_c q + K ρ ū²/2, ū = 4q/(πd²), K = 1.25 for a laminar circular tube
(R. K. Shah, J. Fluids Eng. 100 (1978) 177–179, the incremental pressure-drop number K(∞)). Checked here:

* the inflow law solves that quadratic (to 1e-12 of the drop, both directions) and its slope is the derivative;
* with K = 0 it is Hagen–Poiseuille's to round-off, and a capillary sized for a flow and drop passes exactly that flow;
* in the solved film every recess's inflow obeys the law at its recess pressure (to 1e-9 of the supply pressure), and
  the kinetic share of the drop is K Re d/(64 l), the ratio of the two terms written with the capillary's Reynolds
  number (7 % at C = 0.035 mm, 15 % at 0.07 mm for document 001's printed capillary);
* the force map refuses the nonlinear capillary by name.
"""

from __future__ import annotations

import math

import pytest

from bearing_mbs.fluid_film.restrictors import (
    SHAH_ENTRANCE_LOSS,
    Capillary,
    capillary_bore,
    capillary_resistance,
    capillary_reynolds,
)
from bearing_mbs.fluid_film.reynolds import solve_film
from bearing_mbs.models import build_scene, load_spec
from bearing_mbs.models.journal_bearing.static import bearing_of, state_at
from bearing_mbs.spec import SpecError

from cases import SCENARIOS

MU, RHO = 0.028, 860.0


@pytest.mark.parametrize("drop", [5e5, -2e5, 1.0])
def test_the_inflow_solves_the_quadratic_drop(drop):
    capillary = Capillary(0.020, 0.0006, SHAH_ENTRANCE_LOSS)
    flow, slope = capillary.inflow(1e6, 1e6 - drop, MU, RHO)
    resistance = capillary_resistance(0.020, 0.0006, MU)
    velocity = 4 * flow / (math.pi * 0.0006**2)
    assert resistance * flow + SHAH_ENTRANCE_LOSS * RHO * velocity * abs(velocity) / 2 == pytest.approx(drop, rel=1e-12)
    step = 1e-3 * abs(drop)
    difference = (capillary.inflow(1e6, 1e6 - drop + step, MU, RHO)[0]
                  - capillary.inflow(1e6, 1e6 - drop - step, MU, RHO)[0]) / (2 * step)
    assert slope == pytest.approx(difference, rel=1e-6)


def test_without_entrance_loss_it_is_hagen_poiseuille_and_sizing_is_exact():
    resistance = capillary_resistance(0.020, 0.0006, MU)
    assert Capillary(0.020, 0.0006).inflow(1e6, 4e5, MU, RHO) == (6e5 / resistance, -1 / resistance)
    for loss in (0.0, SHAH_ENTRANCE_LOSS):
        sized = Capillary(0.020, capillary_bore(0.020, 2e-6, 5e5, MU, RHO, loss), loss)
        assert sized.inflow(1e6, 5e5, MU, RHO)[0] == pytest.approx(2e-6, rel=1e-12)


@pytest.mark.parametrize("clearance, share", [(35e-6, 0.07), (70e-6, 0.15)])
def test_the_solved_film_obeys_the_law_in_every_recess(clearance, share):
    spec = load_spec(SCENARIOS / "seed_hybrid_journal.toml",
                     [f"journal.radial_clearance={clearance}", "journal.speed_rpm=0", "journal.grid=[120, 30]",
                      f"journal.recesses.capillary_entrance_loss={SHAH_ENTRANCE_LOSS}"])
    bearing, supply = bearing_of(spec)
    film = solve_film(bearing, state_at(spec, 0.25), supply, spec.journal.grid)
    capillary = supply.restrictor
    resistance = capillary_resistance(capillary.length, capillary.diameter, MU)
    for pressure, flow in zip(film.recess_pressures, film.supply_flows, strict=True):
        drop = resistance * flow + capillary.kinetic(RHO) * flow * abs(flow)
        assert drop == pytest.approx(supply.pressure - pressure, abs=1e-9 * supply.pressure)
    flow = film.supply_flows.max()
    kinetic_share = capillary.kinetic(RHO) * flow / resistance
    reynolds = capillary_reynolds(flow, capillary.diameter, MU, RHO)
    assert kinetic_share == pytest.approx(SHAH_ENTRANCE_LOSS * reynolds * capillary.diameter
                                          / (64 * capillary.length), rel=1e-12)
    assert kinetic_share == pytest.approx(share, abs=0.01)


def test_the_force_map_refuses_the_entrance_loss_by_name():
    with pytest.raises(SpecError) as error:
        build_scene(load_spec(SCENARIOS / "seed_hybrid_spindle.toml",
                              ["bearing.recesses.capillary_entrance_loss=1.25"]))
    assert error.value.field == "bearing.recesses.capillary_entrance_loss"
