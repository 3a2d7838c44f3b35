"""The quasi-static skidding balance (bearing_mbs.models.cylindrical_roller.steady_skidding) of the lubricated
seed bearing.

References, independent of the code under test:

* pure rolling: with no drag, no rolling resistance and no land friction nothing resists the rolling set, so the
  cage turns at the epicyclic speed ω_i (1 − D_w/D_pw)/2 (closed form): cage slip below 1e-9;
* the power balance (a conservation law): the power the ring's drive supplies, −ω_i × (the rollers' mean torque
  on the ring, from the inner tractions and rolling resistance), equals the mean power dissipated by sliding,
  rolling resistance, drags and the land, to 1e-6 (a wrong sliding or rolling kinematics breaks it);
* Exudyn, integrating the same scene's equations of motion in time (an independent method: the skidding issue's
  cross-check), after the run has settled: cage slip within 5 % relative, or 0.1 percentage point where the
  slip is below 2 %. Exudyn and the reference engine agree to 2 % in tests/test_lubricated_bearing.py.
"""

from __future__ import annotations

import numpy as np
import pytest

from bearing_mbs.contact.lubricant import PRESETS as LUBRICANTS
from bearing_mbs.engines import simulate
from bearing_mbs.models import build_scene, load_spec
from bearing_mbs.models.cylindrical_roller.steady_skidding import solve_skidding
from bearing_mbs.runner import summarize
from bearing_mbs.spec import SpecError

from cases import SCENARIOS

#: The scenario's dry model (variant "dry") with EHL raceways and the constraint cage: each test adds the losses
#: it needs.
LUBRICATED = ["scenario.variant=dry", "lubricant.oil=iso_vg_320_mineral", "lubricant.temperature=60",
              "contact.inner_race.friction_law=ehl", "contact.outer_race.friction_law=ehl", "cage.model=constraint"]


def spec_of(*overrides):
    return load_spec(SCENARIOS / "seed_hss_steady.toml", [*LUBRICATED, *overrides])


def test_without_resistance_the_cage_turns_at_the_epicyclic_speed():
    spec = spec_of("load.radial=6800", "lubricant.model=none", "contact.inner_race.rolling_resistance_arm=0",
                   "contact.outer_race.rolling_resistance_arm=0", "contact.land.friction_coefficient=0")
    solution = solve_skidding(build_scene(spec))
    # the seed-hss preset: D_w = 0.025 m, D_pw = 0.235 m; 1500 rpm
    shaft, cage = 1500 * np.pi / 30, 1500 * np.pi / 30 * (1 - 0.025 / 0.235) / 2
    assert solution.cage_speed == pytest.approx(cage, rel=1e-9)
    assert abs(solution.cage_slip) < 1e-9
    # and every roller spins in the cage at -(ω_i − ω_c) r_i/r, r_i = 0.105 m, r = 0.0125 m: no roller slip
    assert solution.epicyclic_roller_spin == pytest.approx(-(shaft - cage) * 0.105 / 0.0125, rel=1e-12)
    assert np.abs(solution.roller_slip).max() < 1e-6


def test_a_weightless_cage_on_its_land_film_feels_petroffs_torque():
    """Centred (no weight, constraint pockets put no force on it), the film's torque is Petroff's closed form
    2π η Ω R³ L / C: R = (0.245 + 0.004)/2 m, L = 0.071 − 0.055 m (the side rings), C = 0.5 mm / 2; η is the
    preset oil's at 60 °C (its viscosity law is checked in tests/test_lubricant.py). 1e-9 relative."""
    spec = spec_of("load.radial=6800", "scenario.gravity=0", "lubricant.land_film=true", "bearing.cage_width=0.071")
    solution = solve_skidding(build_scene(spec))
    eta = LUBRICANTS["iso_vg_320_mineral"].dynamic_viscosity(60.0)
    petroff = 2 * np.pi * eta * solution.cage_speed * 0.1245**3 * 0.016 / 2.5e-4
    assert solution.land_torque == pytest.approx(-petroff, rel=1e-9)


ROLLING_RESISTANCE = ["contact.inner_race.ehl_rolling_resistance=true",
                      "contact.outer_race.ehl_rolling_resistance=true"]


@pytest.mark.parametrize("drag", ["palmgren", "churning", "churning, EHL rolling resistance"])
@pytest.mark.parametrize("load", [2000.0, 6800.0])
def test_the_drive_power_equals_the_losses(drag, load):
    rolling = ROLLING_RESISTANCE if "rolling" in drag else []
    scene = build_scene(spec_of(f"load.radial={load}", f"lubricant.model={drag.split(',')[0]}", *rolling))
    solution = solve_skidding(scene)
    supplied = -solution.ring_torque * scene.bodies[0].velocity[2]
    assert supplied > 0
    assert solution.power_loss == pytest.approx(supplied, rel=1e-6)


CROSS_CHECKS = {  # (overrides, run end [s]): long enough for each to settle within the tolerance below
    "nominal, Palmgren drag": (["lubricant.model=palmgren", "load.radial=68000"], 0.1),
    "light, Palmgren drag": (["lubricant.model=palmgren", "load.radial=6800"], 0.3),
    "light, churning drag": (["lubricant.model=churning", "load.radial=6800"], 0.3),
    "light, churning drag, land film": (["lubricant.model=churning", "load.radial=6800", "lubricant.land_film=true",
                                         "bearing.cage_width=0.071"], 0.3),
    "2 kN, churning drag, land film, EHL rolling resistance": (
        ["lubricant.model=churning", "load.radial=2000", "lubricant.land_film=true", "bearing.cage_width=0.071",
         *ROLLING_RESISTANCE], 0.5),
}


#: Two of the light-load checks run with the long studies (``make test-slow``): the third covers that regime.
#: In `make test-slow`: the light loads' long runs, and the land film's (54 s; the default suite keeps the nominal case
#: within its 15-minute budget).
SLOW_CROSS_CHECKS = ("light, Palmgren drag", "light, churning drag", "light, churning drag, land film",
                     "2 kN, churning drag, land film, EHL rolling resistance")


@pytest.mark.parametrize("case", [pytest.param(case, marks=pytest.mark.slow) if case in SLOW_CROSS_CHECKS else case
                                  for case in CROSS_CHECKS])
def test_exudyn_settles_on_the_quasi_static_slip(case):
    overrides, end = CROSS_CHECKS[case]
    spec = spec_of(*overrides, f"scenario.end_time={end}", f"analysis.start={end - 0.1 if end > 0.1 else 0.05}")
    scene = build_scene(spec)
    result = simulate(scene, spec.solver, spec.scenario.end_time)
    assert result.success, result.message
    dynamic = summarize(spec, scene, result)["cage_slip"]
    steady = solve_skidding(scene).cage_slip
    if max(dynamic, steady) < 0.02:
        assert abs(dynamic - steady) < 0.001
    else:
        assert steady == pytest.approx(dynamic, rel=0.05)


@pytest.mark.parametrize("scenario, overrides, field", [
    ("seed_hss_startup.toml", [], "drive.profile"),  # a speed ramp has no steady state
    ("seed_hss_load_drop.toml", [], "load.profile"),  # nor has a load step
    ("seed_hss_steady.toml", ["scenario.variant=dry", "cage.model=none"], "cage.model"),
])
def test_a_scene_without_a_steady_caged_state_is_refused(scenario, overrides, field):
    scene = build_scene(load_spec(SCENARIOS / scenario, overrides))
    with pytest.raises(SpecError) as refused:
        solve_skidding(scene)
    assert refused.value.field == field
