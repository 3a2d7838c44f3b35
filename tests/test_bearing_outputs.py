"""Outputs of the bearing model: its figures and animation, the low-load skidding trend, the cage-model comparison.

References:
* Skidding at light load: the primary document's motivation (high-speed-shaft bearings of wind-turbine gearboxes
  skid at low load and high speed, as the gearbox maker observes in service) and its refs. [25, 26, 28]
  (S. Jain & H. Hunt 2011, S. Jain 2012: skidding of wind-turbine bearings grows as the load falls below a minimum
  load; Q. Han, X. Li & F. Chu 2018: skidding of cylindrical roller bearings falls as the radial load rises).
  The test checks our model's trend over three loads: cage slip grows at every step down in load, the lowest
  load's slip is at least twice the nominal load's, and every step down in load raises the slip by more than
  three times the uncertainty of both windows' means: the larger of what the pocket play alone can produce
  over the window (``pocket_play_resolution``, zero for the constraint cage) and the difference between the
  means of the window's two halves (a slip still drifting; measured 2e-8, 2.5e-6, 9e-5 against steps of
  4.3e-4 and 1.5e-3).
* Cage-model table (10 ms from a rolling start at 2 kN, scenarios/cage_models.toml), for every cage model:
  - cage speed against the epicyclic no-slip speed ω_c = ω_i (1 − D_w/D_pw)/2 (Harris & Kotzalas 2006,
    ch. 8), written out here: the cage lags (drag), by less than 1 % (measured 0.05–0.3 %; a sign error or
    (1 + D_w/D_pw) would be off by 100 % or 21 %);
  - the largest roller load at each instant, averaged over the window, against the quasi-static load
    distribution (``quasistatic.solve_radial``, an independent method: Newton on the rollers' static
    equilibrium, with their centrifugal force) for the same bearing, total load (applied + inner-ring and
    shaft weight) and shaft speed, over roller phases 0…2π/Z: within [0.98 min, 1.02 max] of the phases'
    values (measured 678 N against 681.6–685.7 N; without the centrifugal force the static answer is 663 N);
    the mean inner-ring displacement within 5 % of the static one (measured −2.5 %);
  - the ordering of docs/cage-models.md: cage slip constraint < penalty < no cage (the constraint cage has
    no play and is carried by the loaded rollers; without a cage nothing drives the unloaded rollers against
    the drag).
* Runs are short (tens of milliseconds) on Exudyn's generalized-alpha, the fastest engine for the bearing; no
  timings are asserted.
"""

import math
from pathlib import Path

import numpy as np
import pytest

from bearing_mbs.cli import main as cli_main
from bearing_mbs.models import load_spec
from bearing_mbs.models.cylindrical_roller.figures import animate, bearing_figures
from bearing_mbs.models.cylindrical_roller.geometry import BearingGeometry
from bearing_mbs.models.cylindrical_roller.metrics import cage_speed, pair_columns, window
from bearing_mbs.models.cylindrical_roller.quasistatic import RollerSet, solve_radial
from bearing_mbs.models.cylindrical_roller.studies import cage_models, skidding
from bearing_mbs.runner import run_spec, write_outputs
from bearing_mbs.studies.services import SERVICES

SCENARIOS = Path(__file__).resolve().parents[1] / "scenarios"
STEADY = SCENARIOS / "seed_hss_steady.toml"
#: The document's dry model (the steady scenario's variant "dry").
SHORT = ("scenario.variant=dry", "solver.engine=exudyn", "solver.exudyn.method=generalized_alpha",
         "scenario.end_time=0.02", "analysis.start=0.01")
FIGURE_NAMES = {"cage_slip.png", "roller_loads.png", "slip_map.png", "inner_ring_orbit.png"}


@pytest.fixture(scope="module")
def short_run():
    spec = load_spec(STEADY, list(SHORT))
    scene, result = run_spec(spec)
    assert result.success, result.message
    return spec, scene, result


def assert_drawn_png(path: Path):
    """A PNG that is not blank: it decodes and has more than a handful of distinct colours."""
    import matplotlib.image

    image = matplotlib.image.imread(path)
    assert image.ndim == 3 and min(image.shape[:2]) > 100, path
    assert np.unique(image.reshape(-1, image.shape[-1]), axis=0).shape[0] > 10, f"{path} looks blank"


def test_bearing_figures_are_written(short_run, tmp_path):
    paths = bearing_figures(*short_run, tmp_path)
    assert {p.name for p in paths} == FIGURE_NAMES
    for path in paths:
        assert_drawn_png(path)


def test_write_outputs_draws_the_models_figures(short_run, tmp_path):
    write_outputs(*short_run, tmp_path)
    assert FIGURE_NAMES <= {p.name for p in tmp_path.iterdir()}


def test_balls_figures_take_the_same_arguments(tmp_path):
    spec = load_spec(SCENARIOS / "seed_case1.toml", [])
    write_outputs(spec, *run_spec(spec), tmp_path)
    assert {"coordinates.png", "trajectory.png", "energy.png"} <= {p.name for p in tmp_path.iterdir()}


def test_animation_writes_the_requested_frames(short_run, tmp_path):
    from PIL import Image

    path = animate(*short_run, tmp_path / "bearing.gif", frames=3)
    with Image.open(path) as gif:
        assert gif.n_frames == 3


def test_cli_animate_writes_a_gif(tmp_path):
    code = cli_main(["run", str(STEADY), "--out", str(tmp_path), "--quiet", "--no-figures", "--animate",
                     "--set", "scenario.variant=dry", "--set", "scenario.end_time=0.002",
                     "--set", "analysis.start=0.001",
                     "--set", "solver.output_interval=2e-4"])
    assert code == 0
    assert (tmp_path / "animation.gif").stat().st_size > 0


@pytest.mark.slow  # 25 s; the lubricated model's trends are in tests/test_lubricated_bearing.py
def test_cage_slip_grows_as_the_load_falls():
    """Skidding at low load, as observed on wind-turbine high-speed-shaft bearings (the primary document's
    motivation and its references [25], [26], [28]): the lubricant's load-independent drag (Palmgren's M0,
    bearing_mbs/lubrication.py) against a traction that falls with the load. Checked on the constraint cage,
    whose pockets add no play: cage slip must grow at every step down in load (6.8 kN, 2 kN, 200 N) and be at
    least twice as large at the lowest load. (The penalty cage's dry pocket impacts add a load-independent slip
    of about 0.5 % that masks the trend above a few hundred newtons: docs/cage-models.md. At the nominal 68 kN
    the constraint cage's common orbital speed against the 22 µm displaced inner ring, δ/R ≈ 0.02 %, is larger
    than the drag's creep: docs/skidding.md.)"""
    base = load_spec(STEADY, ["scenario.variant=dry", "cage.model=constraint", "scenario.end_time=0.1",
                              "analysis.start=0.05"])
    rows = skidding.sweep_loads(SERVICES, base, (6800.0, 2000.0, 200.0))
    assert all(row["status"] == "success" for row in rows)
    trend = skidding.trend(rows)
    slips = [f"{row['radial_load']:g} N: {100 * row['cage_slip']:.3f} %" for row in rows]
    assert trend["monotone"], f"cage slip does not grow as the load falls: {slips}"
    assert trend["ratio"] >= 2.0, f"lowest-load slip / nominal slip = {trend['ratio']:.2f} < 2: {slips}"
    ordered = sorted(rows, key=lambda row: -row["radial_load"])
    uncertainty = [max(row["resolution"], abs(row["cage_slip_first_half"] - row["cage_slip_second_half"]))
                   for row in ordered]
    for k in range(len(ordered) - 1):
        step = ordered[k + 1]["cage_slip"] - ordered[k]["cage_slip"]
        assert step > 3.0 * max(uncertainty[k], uncertainty[k + 1]), (
            f"the slip rises by {step:.3g} from {ordered[k]['radial_load']:g} N to {ordered[k + 1]['radial_load']:g} N, "
            f"not more than 3 times the windows' uncertainty {uncertainty[k:k + 2]}: {slips}")


def test_cage_models_table_has_the_three_models():
    comparison = cage_models
    rows, runs = comparison.compare(SERVICES, load_spec(SCENARIOS / "cage_models.toml",
                                              ["scenario.end_time=0.01", "analysis.start=0.005"]))
    assert [row["model"] for row in rows] == list(comparison.MODELS)
    for row in rows:
        # the cageless roller set's 5 ms window has not settled (its halves differ by a third of the mean slip):
        # that run is suspect by window_settled alone (docs/status.md); the table's values are still checked
        failed = {check["name"] for check in row["checks"] if check["verdict"] == "fail"}
        assert row["status"] == "success" or (row["model"] == "none" and failed == {"window_settled"}), row
        caged = row["model"] != "none"
        for key, _, _ in comparison.COLUMNS[1:]:
            if key in ("status", "failed_checks"):  # text columns (docs/status.md)
                continue
            value = row[key]
            if key in ("max_pocket_force", "max_cage_excursion") and not caged:
                assert value is None
            else:
                assert isinstance(value, (int, float)) and math.isfinite(value), (row["model"], key, value)
    table = comparison.markdown_table(rows)
    assert len(table.strip().splitlines()) == 2 + len(comparison.MODELS)
    slips = {run.model: epicyclic_cage_slip(run) for run in runs}
    for run in runs:
        # the cage (or the roller set) lags the no-slip epicyclic speed, by less than 1 %
        assert 0.0 < slips[run.model] < 1e-2, (run.model, slips[run.model])
        # the largest roller load against the quasi-static load distribution (an independent method)
        static = quasistatic_max_roller_loads(run.spec)
        dynamic = instantaneous_max_roller_load(run)
        assert 0.98 * min(static) <= dynamic <= 1.02 * max(static), (run.model, dynamic, static)
        displacement = solve_radial_for(run.spec).displacement
        assert run.summary["inner_ring_displacement"] == pytest.approx(np.hypot(*displacement), rel=5e-2), run.model
    assert slips["constraint"] < slips["penalty"] < slips["none"], slips


def epicyclic_cage_slip(run) -> float:
    """1 − mean cage speed / mean ω_i (1 − D_w/D_pw)/2 over the window (Harris & Kotzalas 2006, ch. 8)."""
    geometry = BearingGeometry.from_spec(run.spec.bearing)
    mask = window(run.spec, run.result)
    inner = run.result.velocity[mask, 2].mean()
    return 1.0 - cage_speed(run.scene, run.result)[mask].mean() / (
        inner * (1 - geometry.roller_diameter / geometry.pitch_diameter) / 2)


def instantaneous_max_roller_load(run) -> float:
    """Largest inner-raceway roller load at each output instant, averaged over the window [N]."""
    mask = window(run.spec, run.result)
    loads = run.result.pair_series("normal_force")[mask][:, pair_columns(run.scene, "inner_race")]
    return float(loads.max(axis=1).mean())


def solve_radial_for(spec, phase: float = 0.0):
    """The quasi-static solution for the scenario's bearing, total radial load and shaft speed."""
    geometry = BearingGeometry.from_spec(spec.bearing)
    rollers = RollerSet(geometry.rollers, geometry.pitch_diameter, geometry.roller_diameter, geometry.roller_length,
                        diametral_clearance=geometry.clearance, roller_mass=geometry.roller_mass,
                        first_roller_angle=phase)
    angle = math.radians(spec.load.angle)
    load = (spec.load.radial * math.cos(angle),
            spec.load.radial * math.sin(angle) - geometry.inner_ring_mass * spec.scenario.gravity)
    return solve_radial(rollers, load, shaft_speed=spec.drive.speed_rpm * 2 * math.pi / 60)


def quasistatic_max_roller_loads(spec, phases: int = 7) -> list[float]:
    """Quasi-static largest roller load [N] with roller 0 at ``phases`` angles over one roller spacing."""
    spacing = 2 * math.pi / BearingGeometry.from_spec(spec.bearing).rollers
    return [solve_radial_for(spec, k * spacing / phases).max_roller_load for k in range(phases)]
