"""Smearing risk: the frictional power intensity q = |μQ Δu|/(2 b l) of the raceway contacts (docs/smearing.md), in
the quasi-static skidding balance, the skidding map and a dynamic run; and the map's clearance axis.

References:
* the Hertz line contact written out here from K. L. Johnson, *Contact Mechanics* (1985), eq. (4.45): half-width
  a = (4 P R/(π E*))^½ with P the load per length, 1/E* = (1 − ν₁²)/E₁ + (1 − ν₂²)/E₂ and 1/R = 1/R₁ ± 1/R₂
  (− for a roller inside a hollow raceway); steel E = 208 GPa, ν = 0.3, the seed-hss preset's raceways 210/260 mm,
  rollers 25 × 55 mm (docs/bearing.md). Coulomb's law at full sliding: the dry law's erf(2Δu/v_reg) is 1 to 1e-15
  at Δu = 50 v_reg, so its traction is μQ;
* pure rolling (no slip) dissipates nothing by sliding: q = 0, whatever the load;
* the energy balance: the sliding power of all raceway contacts, Σ q·2bl, is part of the bearing's power loss,
  which also holds the rolling resistance, the drags and the land (all > 0 here), so it is positive and smaller.
"""

from __future__ import annotations

import csv
import math

import numpy as np
import pytest

from bearing_mbs.cli import main
from bearing_mbs.engines import simulate
from bearing_mbs.models import build_scene, load_spec
from bearing_mbs.models.cylindrical_roller import metrics
from bearing_mbs.models.cylindrical_roller.steady_skidding import orbit_power_intensity, solve_skidding
from bearing_mbs.models.cylindrical_roller.studies import skidding_map
from bearing_mbs.runner import summarize
from bearing_mbs.spec import SpecError
from bearing_mbs.studies.services import SERVICES

from cases import SCENARIOS

STEADY = SCENARIOS / "seed_hss_steady.toml"
#: Bearing steel (the preset's rings and rollers) and the seed-hss geometry [m], written out (see the references).
YOUNGS, POISSON = 208e9, 0.3
INNER_RACE, OUTER_RACE, ROLLER, LENGTH = 0.105, 0.130, 0.0125, 0.055


def johnson_half_width(load, radius):
    """Johnson's a = (4 P R/(π E*))^½ [m] for steel on steel, P = load/l."""
    contact_modulus = 1 / (2 * (1 - POISSON**2) / YOUNGS)
    return math.sqrt(4 * (load / LENGTH) * radius / (math.pi * contact_modulus))


def test_the_intensity_of_a_sliding_dry_contact_is_coulombs_traction_over_the_hertz_strip():
    """The dry seed bearing (μ = 0.1, v_reg = 0.01 m/s) at full sliding, Δu = 0.5 m/s, on both raceways: q is
    μQΔu/(2al) with Johnson's a, to 1e-12, at 500 N and 5 kN."""
    spec = load_spec(STEADY, ["scenario.variant=dry"])
    scene = build_scene(spec)
    radii = {"inner_race": INNER_RACE * ROLLER / (INNER_RACE + ROLLER),
             "outer_race": OUTER_RACE * ROLLER / (OUTER_RACE - ROLLER)}
    load, sliding, rolling = np.array([500.0, 5000.0]), 0.5, 8.0
    for group, radius in radii.items():
        pair = int(metrics.pair_columns(scene, group)[0])
        traction = metrics.law_traction(scene, pair, load, sliding, rolling)
        intensity = metrics.frictional_power_intensity(traction, sliding, load,
                                                       metrics.raceway_contact(spec, scene, group))
        expected = [0.1 * q * sliding / (2 * johnson_half_width(q, radius) * LENGTH) for q in load]
        np.testing.assert_allclose(intensity, expected, rtol=1e-12, err_msg=group)
    assert metrics.frictional_power_intensity(100.0, 1.0, 0.0, metrics.raceway_contact(spec, scene, "inner_race")) == 0


def test_a_lubricated_raceways_contact_is_the_dry_ones():
    """E', R and l from the EHL traction row (lubricated variant) equal those derived for the dry law (dry variant),
    at one clearance."""
    lubricated, dry = (load_spec(STEADY, [f"scenario.variant={v}", "bearing.diametral_clearance=0"])
                       for v in ("lubricated", "dry"))
    for group in metrics.RACEWAYS:
        np.testing.assert_allclose(metrics.raceway_contact(lubricated, build_scene(lubricated), group),
                                   metrics.raceway_contact(dry, build_scene(dry), group), rtol=1e-12)


def test_pure_rolling_has_no_frictional_power():
    """With no resistance the balance rolls the set at the epicyclic speeds (roller slip < 1e-6, its test in
    test_steady_skidding.py): the intensity is nil wherever a roller carries load. Bound: 1e-6 W/mm², a ten-millionth
    of the lubricated seed's largest intensity at 6.8 kN (about 10 W/mm²); measured 3e-20 W/mm² (sliding 6e-11 m/s).
    And the EHL law's traction at zero slip is exactly 0."""
    spec = load_spec(STEADY, ["scenario.variant=dry", "lubricant.oil=iso_vg_320_mineral", "lubricant.temperature=60",
                              "contact.inner_race.friction_law=ehl", "contact.outer_race.friction_law=ehl",
                              "cage.model=constraint", "load.radial=6800", "lubricant.model=none",
                              "contact.inner_race.rolling_resistance_arm=0",
                              "contact.outer_race.rolling_resistance_arm=0", "contact.land.friction_coefficient=0"])
    scene = build_scene(spec)
    solution = solve_skidding(scene)
    inner, outer = orbit_power_intensity(spec, scene, solution)
    assert (solution.inner_loads > 0).any()
    assert max(inner.max(), outer.max()) / metrics.W_PER_MM2 < 1e-6
    pair = int(metrics.pair_columns(scene, "inner_race")[0])
    assert metrics.law_traction(scene, pair, 5000.0, 0.0, 8.0) == 0.0


@pytest.fixture(scope="module")
def map_point():
    """The lubricated seed bearing at 6.8 kN, 60 °C, 1500 rpm: a map row, its solution, spec and scene."""
    base = load_spec(STEADY)
    row, solution = skidding_map.point(SERVICES, base, 1500.0, 60.0, 6800.0)
    spec = load_spec(STEADY, ["load.radial=6800"])
    return row, solution, spec, build_scene(spec)


def test_the_maps_column_is_the_largest_over_the_orbit(map_point):
    row, solution, spec, scene = map_point
    inner, outer = orbit_power_intensity(spec, scene, solution)
    assert row["max_frictional_power_intensity_inner"] == pytest.approx(inner.max() / 1e6, rel=1e-12)
    assert row["max_frictional_power_intensity_outer"] == pytest.approx(outer.max() / 1e6, rel=1e-12)
    assert row["max_frictional_power_intensity"] == max(row["max_frictional_power_intensity_inner"],
                                                        row["max_frictional_power_intensity_outer"]) > 0
    # out of contact, nothing; in the skidding load zone, something
    assert np.all(inner[solution.inner_loads <= 0] == 0) and inner[solution.inner_loads > 0].max() > 0


def test_the_sliding_power_is_part_of_the_bearings_losses(map_point):
    """Z × the orbit mean of Σ q·2bl over both raceways is the rollers' sliding power: positive, below the power the
    drive supplies (the balance's power_loss: sliding + rolling resistance + drags + land)."""
    _, solution, spec, scene = map_point
    rollers = len(scene.topology.role("rollers"))
    power = 0.0
    for q, load, group in zip(orbit_power_intensity(spec, scene, solution),
                              (solution.inner_loads, solution.outer_loads), metrics.RACEWAYS):
        contact = metrics.raceway_contact(spec, scene, group)
        area = np.array([2 * johnson_half_width(f, contact.radius) * LENGTH if f > 0 else 0.0 for f in load])
        power += rollers * np.mean(q * area)
    assert 0 < power < solution.power_loss


def test_a_dynamic_run_reports_its_largest_intensity():
    """10 ms of the lubricated seed bearing at 6.8 kN (Exudyn, generalized-α): the summary has the intensity of each
    raceway and their largest, positive (the rolling set is accelerating into its skid), with their unit."""
    spec = load_spec(STEADY, ["load.radial=6800", "scenario.end_time=0.01", "analysis.start=0.005"])
    scene = build_scene(spec)
    result = simulate(scene, spec.solver, spec.scenario.end_time)
    assert result.success, result.message
    summary = summarize(spec, scene, result)
    inner, outer = (summary[f"max_frictional_power_intensity_{race}"] for race in ("inner", "outer"))
    assert summary["max_frictional_power_intensity"] == max(inner, outer) > 0
    assert metrics.UNITS["max_frictional_power_intensity"] == "W/mm²"


def test_the_map_takes_clearance_as_an_axis(tmp_path):
    """One load, temperature and speed, two clearances: a row per clearance, with its clearance, and the slip
    differs (measured 2.98 % at zero clearance, 0.65 % at 60 µm)."""
    out = tmp_path / "map"
    assert main(["skidding-map", str(STEADY), "--out", str(out), "--loads", "6800", "--temperatures", "60",
                 "--speeds", "1500", "--clearances", "0,6e-5", "--quiet"]) == 0
    with (out / "skidding_map.csv").open(newline="") as handle:
        rows = list(csv.DictReader(handle))
    assert [float(row["clearance"]) for row in rows] == pytest.approx([0.0, 6e-5], abs=1e-12)
    assert all(row["status"] == "success" for row in rows)
    assert float(rows[0]["cage_slip"]) != pytest.approx(float(rows[1]["cage_slip"]), rel=1e-3)
    assert (out / "skidding_map.png").stat().st_size > 0


@pytest.mark.parametrize("clearances", [(0.01,), (-1e-3,), ()])
def test_a_clearance_the_bearing_refuses_is_refused_before_anything_runs(clearances):
    """The seed bearing takes diametral clearances up to 5 % of its roller diameter (1.25 mm) and preloads down to
    0.2 % (-50 µm); an empty list gives no map."""
    with pytest.raises(SpecError) as error:
        skidding_map.check_grid(SERVICES, load_spec(STEADY), [6800.0], [60.0], [1500.0], clearances)
    assert error.value.field == "--clearances"


def test_the_command_refuses_a_bad_clearance_with_exit_status_2(tmp_path, capsys):
    out = tmp_path / "map"
    assert main(["skidding-map", str(STEADY), "--out", str(out), "--clearances", "0.01", "--quiet"]) == 2
    assert not out.exists()
    assert "--clearances" in capsys.readouterr().err
