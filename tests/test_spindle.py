"""A spindle on document 001's hybrid journal bearings (``scenarios/seed_hybrid_spindle.toml``, docs/fluid-film.md).

The recessed bearing's force map (:mod:`bearing_mbs.fluid_film.force_map`) carries the rotor; each check below has a
reference independent of the time integration:

* the map against a Reynolds solve per evaluation at the states of a run (1 %, the issue's bound);
* growth rates of transient runs at 0.95, 1 and 1.05 of the linearised whirl threshold, both engines, against the
  linearised rotor's eigenvalues (2 %), and the whirl at half the spin speed (Newkirk and Taylor 1925);
* the classical threshold of a rigid rotor on isotropic full films, Ω = 2 √(K/m) (the film's cross-coupling
  k_xy = C Ω/2 balances the direct damping at the half-speed whirl; Childs, *Turbomachinery Rotordynamics*, 1993,
  §3.7) with the hydrostatic stiffness K of a centred Reynolds solve (3 %: the hydrodynamic film adds a little
  stiffness at speed);
* the unbalance orbit: the engines agree instant by instant (0.5 % of its radius) and the orbit is the linear forced
  response (K − Ω²M + iΩC)⁻¹ m_u r_u Ω² (2 %);
* the hybrid bearing's hydrostatic share raises the threshold above the same rotor's on plain bores;
* bad input.

All on a 60 × 16 film grid (the map builds in about 9 s; the scenario's 120 × 30 grid in about 40 s).
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from bearing_mbs.fluid_film.journal import FilmGrid
from bearing_mbs.fluid_film.reynolds import JournalState, solve_film
from bearing_mbs.models import build_scene, load_spec
from bearing_mbs.models.rotor.build import equilibrium
from bearing_mbs.models.rotor.linear import growth_rate, unbalance_amplitude, whirl_threshold
from bearing_mbs.models.rotor.metrics import rotor_metrics
from bearing_mbs.runner import run_spec
from bearing_mbs.spec import SpecError

from cases import SCENARIOS

SPINDLE = SCENARIOS / "seed_hybrid_spindle.toml"
GRID = "bearing.grid=[60, 16]"  # the scenario's own


def _run(*overrides):
    spec = load_spec(SPINDLE, [GRID, *overrides])
    scene, result = run_spec(spec)
    assert result.status == "success", result.message
    return spec, result, rotor_metrics(spec, scene, result)


def _constant(rpm, *overrides):
    return _run(f"drive.speed_rpm={rpm}", f"drive.start_rpm={rpm}", "drive.ramp_time=0", *overrides)


#: Exudyn's runs in the default suite; the reference engine's RK4 (three 0.3 s runs, a minute) in `make test-slow`
#: (its rotor runs are held to Exudyn's by the unbalance-orbit test below).
@pytest.mark.parametrize("engine", [pytest.param("reference", marks=pytest.mark.slow), "exudyn"])
def test_whirl_growth_rates_match_the_linearised_rotor(engine):
    """At 0.95 and 1.05 of the threshold the runs' rates (-4.55 / +4.76 1/s on both engines) are the linearised
    eigenvalues' (-4.60 / +4.83) within 2 %; at the threshold itself the run's rate (-0.04 1/s) is within 2 % of
    those rates' size from zero."""
    spec = load_spec(SPINDLE, [GRID])
    threshold = whirl_threshold(spec)
    rates = {}
    for factor in (0.95, 1.0, 1.05):
        rpm = factor * threshold
        _, _, metrics = _constant(rpm, "rotor.unbalance=0", "rotor.initial_offset=[1e-8, 0.0]",
                                  "scenario.end_time=0.3", f"solver.engine={engine}")
        rates[factor] = metrics["whirl_growth_rate"]
        assert 0.45 < metrics["whirl_frequency_ratio"] < 0.55
        if factor != 1.0:
            assert rates[factor] == pytest.approx(growth_rate(spec, rpm * math.pi / 30), rel=0.02), factor
    assert rates[0.95] < 0 < rates[1.05]
    assert abs(rates[1.0]) < 0.02 * rates[1.05]


def test_threshold_is_twice_the_hydrostatic_natural_frequency():
    spec = load_spec(SPINDLE, [GRID])
    b = spec.bearing
    step = 1e-3 * b.radial_clearance
    bearing, supply = b.bearing(), b.supply()
    grid = FilmGrid.build(bearing, *b.grid)
    push = [solve_film(bearing, JournalState((sign * step, 0.0)), supply, grid).force[0] for sign in (1, -1)]
    stiffness = spec.rotor.bearings * -(push[0] - push[1]) / (2 * step)
    classical = 2 * math.sqrt(stiffness / spec.rotor.mass) * 30 / math.pi
    assert whirl_threshold(spec) == pytest.approx(classical, rel=0.03)


def test_hydrostatic_share_raises_the_whirl_threshold_above_plain_bores():
    """The summary's thresholds: the hybrid bearing's at least twice the plain bore's (26 000 against 9 000 rpm)."""
    _, _, metrics = _constant(20000, "scenario.end_time=0.01", "solver.engine=reference")
    assert metrics["plain_whirl_threshold_rpm"] < metrics["linear_whirl_threshold_rpm"] / 2


def test_unbalance_orbit_agrees_across_engines_and_with_the_linear_response():
    """At 10 000 rpm, 0.25 s from the equilibrium (the start's whirl transient, decaying at 40 1/s, is down to 3e-4
    after 0.2 s): over the last 0.05 s the journal centres of Exudyn (generalized-α, h = 2e-5 s) and the reference
    engine (RK4, h = 5e-6 s) differ by less than 0.5 % of the orbit radius, and the orbit's largest distance from the
    equilibrium is the linear steady orbit's semi-major axis within 2 %; the force map stays within 1 % of a Reynolds
    solve per evaluation at the run's states."""
    runs = [_constant(10000, "scenario.end_time=0.25", f"solver.engine={engine}", "solver.exudyn.step=2e-5")
            for engine in ("exudyn", "reference")]
    (_, exudyn, _), (spec, reference, metrics) = runs
    window = reference.time >= 0.2
    np.testing.assert_allclose(exudyn.time, reference.time, rtol=0, atol=1e-12)
    difference = np.hypot(*(exudyn.position[window, :2] - reference.position[window, :2]).T).max()
    assert difference < 0.005 * metrics["orbit_radius"]
    speed = 10000 * math.pi / 30
    largest = np.hypot(*(reference.position[window, :2] - equilibrium(spec, speed)).T).max()
    assert largest == pytest.approx(unbalance_amplitude(spec, speed), rel=0.02)
    assert metrics["map_orbit_error"] < 0.01


@pytest.mark.parametrize("override, field", [
    ("bearing.force='short'", "bearing.force"),
    ("bearing.recesses.restrictor='orifice'", "bearing.recesses.restrictor"),
    ("bearing.recesses.axial_length=0.08", "bearing.recesses.axial_length"),
])
def test_bad_input_is_refused(override, field):
    with pytest.raises(SpecError) as error:
        build_scene(load_spec(SPINDLE, [GRID, override]))
    assert error.value.field == field
