"""The study subcommands of ``bearing-mbs``: skidding, skidding-map, cage-models, static-check and numerics-report.

Smoke tests: each runs on a tiny case (a few milliseconds of simulated time on Exudyn's generalized-alpha, one
load, one engine) and must write its files with each run's status and checks, and exit with the worst run's code
(docs/status.md): 0 when every run succeeded and its window settled, 3 when a window did not settle (a 2 ms window
4 ms after the start is far from the steady slip: the quasi-static balance gives 36 % at 2 kN where the window
reads 1 %); bad input must exit with status 2 before anything runs (no output directory is created). The physics
of these studies is checked elsewhere (tests/test_bearing_outputs.py, tests/test_static_check.py); here only the
command line.
"""

from __future__ import annotations

import csv
import json
from pathlib import Path

import pytest

from bearing_mbs.cli import main

SCENARIOS = Path(__file__).resolve().parents[1] / "scenarios"
STEADY = SCENARIOS / "seed_hss_steady.toml"
#: 4 ms of the seed bearing, analysed over the last 2 ms.
TINY = ["--set", "scenario.end_time=0.004", "--set", "analysis.start=0.002"]


def _verdicts(row) -> dict:
    return {check["name"]: check["verdict"] for check in json.loads(row["checks"])}


def test_skidding_writes_the_sweep_and_an_unsettled_window_is_suspect(tmp_path, capsys):
    """Issue 25: a window that has not settled is a failed check (the run is suspect, the study exits 3), never
    a success."""
    out = tmp_path / "skid"
    code = main(["skidding", str(STEADY), "--out", str(out), "--loads", "68000,2000", "--cages", "constraint",
                 "--quiet", *TINY])
    assert code == 3
    assert {path.name for path in out.iterdir()} == {"skidding_vs_load.csv", "skidding_vs_load.md",
                                                     "skidding_vs_load.png"}
    with (out / "skidding_vs_load.csv").open(newline="") as handle:
        rows = list(csv.DictReader(handle))
    assert [(row["cage_model"], float(row["radial_load"])) for row in rows] == [("constraint", 68000.0),
                                                                             ("constraint", 2000.0)]
    light = rows[1]
    assert (light["status"], light["settled"], _verdicts(light)["window_settled"]) == ("suspect", "False", "fail")
    assert "constraint cage: slip" in capsys.readouterr().out


def test_skidding_of_a_settled_window_succeeds(tmp_path):
    """The dry seed bearing at 68 kN with the constraint cage settles within 10 ms (window halves 0.0160 % and
    0.0157 %, within 5 % of each other): every check passes, exit 0."""
    out = tmp_path / "skid"
    assert main(["skidding", str(STEADY), "--out", str(out), "--loads", "68000", "--cages", "constraint", "--quiet",
                 "--no-figures", "--set", "scenario.variant=dry", "--set", "scenario.end_time=0.02",
                 "--set", "analysis.start=0.01"]) == 0
    with (out / "skidding_vs_load.csv").open(newline="") as handle:
        row = next(csv.DictReader(handle))
    assert row["status"] == "success" and set(_verdicts(row).values()) == {"pass"}
    assert "window_settled" in _verdicts(row)


@pytest.mark.slow  # 12 s, in `make test-slow`; the sweep above keeps the skidding command in the default suite
def test_skidding_map_writes_the_grid_and_its_figures(tmp_path, capsys):
    out = tmp_path / "map"
    code = main(["skidding-map", str(STEADY), "--out", str(out), "--loads",
                 "6800,2000", "--temperatures", "60", "--speeds", "1500", "--minimum-load", "4000,9000", "--quiet"])
    assert code == 0
    assert {path.name for path in out.iterdir()} == {"skidding_map.csv", "skidding_map.md", "skidding_map.png",
                                                     "roller_slip.png"}
    with (out / "skidding_map.csv").open(newline="") as handle:
        rows = list(csv.DictReader(handle))
    assert [float(row["radial_load"]) for row in rows] == [6800.0, 2000.0]
    assert all(row["status"] == "success" and row["checks"] == "[]" for row in rows)
    assert float(rows[1]["cage_slip"]) > float(rows[0]["cage_slip"]) > 0
    assert "cage slip [%]" in capsys.readouterr().out


def test_a_skidding_map_point_without_a_balance_fails(tmp_path):
    """At 1 N, 1800 rpm and −10 °C the oil's drag exceeds what the rollers' traction carries: the cage's torque
    balance has no root above 1 % of the epicyclic speed. The point is failed with its reason, its values NaN, and
    the map exits 1 with its tables written."""
    out = tmp_path / "map"
    assert main(["skidding-map", str(STEADY), "--out", str(out), "--loads", "1", "--temperatures", "-10",
                 "--speeds", "1800", "--no-figures", "--quiet"]) == 1
    with (out / "skidding_map.csv").open(newline="") as handle:
        (row,) = list(csv.DictReader(handle))
    assert row["status"] == "failed" and row["message"] and row["cage_slip"] == "nan"


def test_cage_models_writes_the_table_and_figures(tmp_path):
    """4 ms at 2 kN: the constraint cage's and the cageless set's slip still drift between the window halves
    (window_settled fails, exit 3); the penalty cage's pocket-play resolution over a 1 ms half window is 24 %, so
    its window passes."""
    out = tmp_path / "cages"
    code = main(["cage-models", str(SCENARIOS / "cage_models.toml"), "--out", str(out), "--no-roller-guided",
                 "--quiet", *TINY])
    assert code == 3
    assert {path.name for path in out.iterdir()} == {"cage_models.md", "cage_models.csv", "cage_models_slip.png",
                                                     "cage_models_loads.png"}
    table = (out / "cage_models.md").read_text().strip().splitlines()
    assert len([line for line in table if line.startswith("|")]) == 2 + 3
    with (out / "cage_models.csv").open(newline="") as handle:
        rows = {row["cage model"]: row for row in csv.DictReader(handle)}
    assert {model: row["status"] for model, row in rows.items()} == {"penalty": "success", "constraint": "suspect",
                                                                     "none": "suspect"}
    assert _verdicts(rows["constraint"])["window_settled"] == "fail"


def test_static_check_writes_its_json(tmp_path, capsys):
    out = tmp_path / "static"
    code = main(["static-check", str(SCENARIOS / "static_check.toml"), "--out", str(out), "--engines", "exudyn",
                 "--loads", "20000", "--no-stiffness"])
    assert code == 0
    data = json.loads((out / "static_check.json").read_text())
    assert [row["engine"] for row in data["static"]] == ["exudyn"] and data["stiffness"] == []
    assert data["status"] == data["static"][0]["status"] == "success"
    assert {"window_drift", "window_amplitude"} <= {check["name"] for check in data["static"][0]["checks"]}
    assert abs(data["static"][0]["displacement_error"]) < 1e-2
    assert "Qmax dyn" in capsys.readouterr().out


def test_numerics_report_writes_figure_and_tables(tmp_path):
    study = tmp_path / "study"
    study.mkdir()
    columns = ("engine", "solver", "step", "tolerance", "error", "wall_time_s", "force_evaluations", "steps",
               "status", "positions", "cage_speed", "roller_loads", "slips")
    with (study / "convergence.csv").open("w", newline="") as handle:
        writer = csv.DictWriter(handle, columns)
        writer.writeheader()
        for solver, step, time, error in (("central_difference", 5.555555555555556e-07, 2.0, 1e-3),
                                          ("central_difference", 1.25e-07, 8.0, 5e-5),
                                          ("rk4", 1e-7, 3.0, 1e-5), ("rk4", 5e-8, 6.0, 1e-6)):
            writer.writerow({"engine": "reference", "solver": solver, "step": step, "tolerance": "",
                             "error": error, "wall_time_s": time, "force_evaluations": 100, "steps": 10,
                             "status": "success", "positions": error, "cage_speed": error, "roller_loads": error,
                             "slips": error / 10})
    out = tmp_path / "report"
    assert main(["numerics-report", str(study), "--name", "tiny", "--out", str(out)]) == 0
    assert {path.name for path in out.iterdir()} == {"work_precision_tiny.png", "work_precision_tiny.md"}
    assert "cheapest sound setting" in (out / "work_precision_tiny.md").read_text()


def test_a_run_is_sound_by_its_slip_error_relative_to_the_slips_where_they_are_large(tmp_path):
    """1e-4 absolute where the reference's slips are small (the dry bearing's 1.6e-5); 1 % of the largest slip where
    that is larger (the lubricated bearing's 6 %: an error of 3e-4 is 0.5 % of it)."""
    from bearing_mbs.studies.numerics_report import read

    columns = ("engine", "solver", "step", "tolerance", "error", "wall_time_s", "status", "positions", "cage_speed",
               "roller_loads", "slips")
    with (tmp_path / "convergence.csv").open("w", newline="") as handle:
        writer = csv.DictWriter(handle, columns)
        writer.writeheader()
        for slips in (5e-5, 3e-4, 9e-4):
            writer.writerow({"engine": "reference", "solver": "rk4", "step": 1e-6, "tolerance": "", "error": 1e-6,
                             "wall_time_s": 1.0, "status": "success", "positions": 1e-6, "cage_speed": 1e-6,
                             "roller_loads": 1e-6, "slips": slips})
    assert [r["sound"] for r in read(tmp_path)] == [True, False, False]
    (tmp_path / "summary.json").write_text('{"reference_largest_slip": 0.06}')
    assert [r["sound"] for r in read(tmp_path)] == [True, True, False]


@pytest.mark.parametrize("arguments", [
    ["skidding", str(STEADY), "--cages", "brass"],                                 # no such cage model
    ["skidding", str(STEADY), "--loads", "68000,heavy"],                           # not a number
    ["skidding", str(STEADY), "--loads", "-5"],                                    # not a positive load
    ["skidding", str(SCENARIOS / "seed_case1.toml")],                              # not a bearing
    ["cage-models", str(SCENARIOS / "cage_models.toml"), "--set", "cage.model=wooden"],
    ["cage-models", str(SCENARIOS / "seed_case1.toml")],
    ["static-check", str(SCENARIOS / "static_check.toml"), "--engines", "abaqus"],
    ["static-check", str(SCENARIOS / "static_check.toml"), "--loads", "0"],
    ["static-check", str(SCENARIOS / "seed_case1.toml")],
    ["numerics-report", str(SCENARIOS), "--name", "none"],                        # no convergence.csv
])
def test_study_commands_reject_bad_input_with_exit_status_2(tmp_path, capsys, arguments):
    out = tmp_path / "out"
    assert main([*arguments, "--out", str(out)]) == 2
    assert not out.exists()
    assert "error:" in capsys.readouterr().err


def test_numerics_report_rejects_an_unknown_norm(tmp_path, capsys):
    study = tmp_path / "study"
    study.mkdir()
    (study / "convergence.csv").write_text("engine,solver,step,tolerance,error,wall_time_s,status\n")
    assert main(["numerics-report", str(study), "--name", "x", "--out", str(tmp_path / "out"),
                 "--norms", "energy"]) == 2
    assert not (tmp_path / "out").exists()
