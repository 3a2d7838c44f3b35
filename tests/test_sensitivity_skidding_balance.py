"""``[study] evaluate``: a study's samples evaluated by the quasi-static skidding balance instead of a run, through
the real pipeline (a local cluster of one worker process), on the run's spec, store and status logic; and the
``steady_run`` evaluator's settling check."""

import textwrap
from pathlib import Path

import numpy as np
import pytest

from bearing_mbs.models import build_scene, spec_from_mapping
from bearing_mbs.models.cylindrical_roller.steady_skidding import solve_skidding
from bearing_mbs.models.cylindrical_roller.studies.balance import BALANCE_TEXT_COLUMNS, BALANCE_UNITS
from bearing_mbs.models.cylindrical_roller.studies.skidding_map import COLUMNS
from bearing_mbs.spec import SpecError
from bearing_mbs.studies.sensitivity import (
    SkiddingBalanceModel,
    SteadyRunModel,
    load_study,
    plan,
    run_study,
    sample,
)

ROOT = Path(__file__).resolve().parents[1]
STEADY = ROOT / "scenarios" / "seed_hss_steady.toml"
SEED_CASE2 = ROOT / "scenarios" / "seed_case2.toml"

# 1800 rpm and oil at -10 °C: at 68 kN the traction carries the drags; at 1 N the oil's drag exceeds what the
# rollers' traction carries, and the cage's torque balance has no root (tests/test_cli_studies.py)
GRID = """
[[parameters]]
name = "load.radial"
values = [68000.0, 1.0]
"""


def balance_study(tmp_path, evaluate: str = "skidding_balance", scenario: Path = STEADY,
                  outputs: str = '"cage_slip", "friction_torque"', parameters: str = GRID,
                  overrides: str = '"drive.speed_rpm=1800", "lubricant.temperature=-10"') -> Path:
    path = tmp_path / "study.toml"
    path.write_text(textwrap.dedent(f"""
        [study]
        name = "balance"
        scenario = "{scenario}"
        evaluate = "{evaluate}"
        overrides = [{overrides}]
        outputs = [{outputs}]
        [method]
        sampler = "grid"
        """) + textwrap.dedent(parameters))
    return path


def test_the_balance_evaluates_a_sample_on_the_runs_spec_and_a_point_without_balance_fails(tmp_path):
    study = load_study(balance_study(tmp_path))
    assert isinstance(study.model, SkiddingBalanceModel)
    X = sample(study)
    keys, runs = plan(study, X)
    as_run = load_study(balance_study(tmp_path, evaluate="run", outputs='"cage_slip"'))
    run_keys, run_runs = plan(as_run, X)
    assert [runs[k].inputs for k in keys] == [run_runs[k].inputs for k in run_keys]  # the same spec as a run's
    assert set(keys).isdisjoint(run_keys)  # but another run: the evaluator is part of its identity

    result = run_study(study, tmp_path / "out", workers=1, figures=False)
    table = result.table
    heavy, light = table.iloc[0], table.iloc[1]
    assert heavy["status"] == "success" and heavy["attempts"] == 1
    spec = spec_from_mapping(runs[keys[0]].inputs)
    expected = solve_skidding(build_scene(spec)).cage_slip  # the balance on its own, outside the pipeline
    assert heavy["cage_slip"] == pytest.approx(expected, rel=1e-6)
    assert heavy["friction_torque"] > 0
    # no balance: a failed run (its reason kept, its outputs NaN), recorded once, not an error to retry
    assert light["status"] == "failed" and light["attempts"] == 1
    assert "no skidding balance" in light["error"]
    assert np.isnan(light["cage_slip"]) and np.isnan(light["friction_torque"])
    assert result.status == "failed" and result.stats.errors == 0
    summary = (tmp_path / "out" / "runs" / keys[0][:2] / keys[0] / "summary.json").read_text()
    assert '"cage_slip": "-"' in summary and '"friction_torque": "N m"' in summary  # the units travel with it

    again = run_study(study, tmp_path / "out", report=False)  # resumed from the store: nothing runs, no cluster
    assert again.stats.evaluated == 0 and again.stats.skipped == 2
    assert again.table["status"].tolist() == ["success", "failed"]


def test_every_number_the_balance_reports_has_a_unit():
    assert set(COLUMNS) - set(BALANCE_TEXT_COLUMNS) <= set(BALANCE_UNITS)
    assert set(SkiddingBalanceModel(str(STEADY)).outputs()) <= set(BALANCE_UNITS)


@pytest.mark.parametrize("evaluate, scenario, field", [
    ("skidding_dance", STEADY, "study.evaluate"),  # no such evaluator
    ("skidding_balance", SEED_CASE2, "study.evaluate"),  # a ball dropped on a floor has no cage to skid
    ("steady_run", SEED_CASE2, "study.evaluate"),
])
def test_an_evaluator_that_cannot_evaluate_the_study_is_a_spec_error_naming_the_field(tmp_path, evaluate, scenario,
                                                                                      field):
    path = balance_study(tmp_path, evaluate) if scenario == STEADY else balance_study(
        tmp_path, evaluate, scenario, '"max_penetration"', '[[parameters]]\nname = "balls.0.mass"\nvalues = [0.1, 0.2]\n',
        overrides="")
    with pytest.raises(SpecError) as error:
        load_study(path)
    assert error.value.field == field and error.value.value == evaluate


def test_a_builtin_model_takes_no_evaluator(tmp_path):
    path = tmp_path / "study.toml"
    path.write_text('[study]\nname = "i"\nmodel = "ishigami"\nevaluate = "skidding_balance"\noutputs = ["y"]\n'
                    '[method]\nsampler = "grid"\n[[parameters]]\nname = "x1"\nvalues = [0.0, 1.0]\n')
    with pytest.raises(SpecError) as error:
        load_study(path)
    assert error.value.field == "study.evaluate"


def test_an_output_the_balance_does_not_report_is_refused(tmp_path):
    with pytest.raises(SpecError) as error:
        load_study(balance_study(tmp_path, outputs='"cage_slip", "max_pocket_force"'))
    assert error.value.field == "study.outputs.1"


def test_a_steady_run_holds_its_window_to_settle():
    """4 ms from the epicyclic start: the constraint cage's slip still drifts between the window's halves, so the
    window_settled check fails and the run is suspect."""
    tiny = ("scenario.end_time=0.004", "analysis.start=0.002", "solver.output_interval=1e-4")
    steady = SteadyRunModel(str(STEADY), tiny)
    summary, _ = steady.evaluate(steady.canonical(steady.base()))
    checks = {check["name"]: check["verdict"] for check in summary["checks"]}
    assert checks["window_settled"] == "fail" and summary["status"] == "suspect"
