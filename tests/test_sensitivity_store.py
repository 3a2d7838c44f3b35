"""The run store: a run is written atomically (directory, then row), present at most once, recovered
without re-running when the driver died between the two writes, and never lost. No cluster: runs are
evaluated in-process with the same pure task function the Dask workers execute."""

import json
import math
import sqlite3

import numpy as np
import pytest

from bearing_mbs.spec import SpecError
from bearing_mbs.studies.sensitivity import (
    IshigamiModel,
    Method,
    Parameter,
    RunStore,
    Study,
    evaluate,
    plan,
    sample,
)
from bearing_mbs.studies.sensitivity.runs import evaluate_runs
from bearing_mbs.studies.sensitivity.store import DATABASE, RUN_FILE, SUMMARY_FILE


def ishigami_study(samples=8):
    bounds = (-math.pi, math.pi)
    return Study("ishigami", IshigamiModel(), [Parameter(f"x{i}", bounds) for i in (1, 2, 3)], ("y",),
                 Method("latin", samples=samples), seed=7)


def record_all(store, study, runs):
    for run in runs:
        (outcome,) = evaluate_runs(study.model, [run])
        store.record(study.model.name, run, outcome)


def test_a_recorded_run_has_a_directory_and_one_row(tmp_path):
    study = ishigami_study()
    keys, runs = plan(study, sample(study))
    with RunStore(tmp_path) as store:
        record_all(store, study, runs.values())
        assert store.keys() == set(keys)
        directory = store.run_directory(keys[0])
    row = json.loads((directory / RUN_FILE).read_text())
    assert row["key"] == keys[0] and row["status"] == "success" and row["attempts"] == 1
    assert json.loads((directory / SUMMARY_FILE).read_text())["y"] == row["summary"]["y"]
    with RunStore(tmp_path) as store:  # reopened: everything is still there, nothing to recover
        assert store.recovered == 0 and store.count() == len(runs)


def test_driver_killed_between_directory_and_row_is_recovered_without_rerunning(tmp_path):
    study = ishigami_study()
    X = sample(study)
    keys, runs = plan(study, X)
    with RunStore(tmp_path) as store:
        record_all(store, study, runs.values())
    with sqlite3.connect(tmp_path / DATABASE) as db:  # the rows of two runs never made it
        db.execute("DELETE FROM runs WHERE key IN (?, ?)", (keys[0], keys[1]))
    leftover = tmp_path / "runs" / keys[2][:2] / f".part-{keys[2]}-999"  # a half-written directory
    leftover.mkdir(parents=True)
    (leftover / RUN_FILE).write_text("{")
    with RunStore(tmp_path) as store:
        assert store.recovered == 2
        assert not leftover.exists()
        # every run is stored: evaluate() has nothing to submit, so it never touches a client
        table = evaluate(study, X, store, client=None)
    assert (table["status"] == "success").all()
    assert np.isfinite(table["y"]).all()
    with sqlite3.connect(tmp_path / DATABASE) as db:
        counts = db.execute("SELECT key, COUNT(*) FROM runs GROUP BY key").fetchall()
    assert sorted(k for k, _ in counts) == sorted(runs) and all(n == 1 for _, n in counts)


def test_replacing_an_errored_run_keeps_one_row(tmp_path):
    study = ishigami_study(samples=2)
    _, runs = plan(study, sample(study))
    run = next(iter(runs.values()))
    error = {"key": run.key, "attempt": 2, "status": "error", "summary": None, "error": "boom", "files": {}}
    with RunStore(tmp_path) as store:
        store.record("ishigami", run, error)
        assert store.finished() == {run.key} and store.finished(retry_errors=True) == set()
        (outcome,) = evaluate_runs(study.model, [run])
        store.record("ishigami", run, outcome)
        assert store.count() == 1 and store.rows()[run.key]["status"] == "success"
        assert json.loads((store.run_directory(run.key) / RUN_FILE).read_text())["status"] == "success"


def test_one_driver_per_directory(tmp_path):
    with RunStore(tmp_path), pytest.raises(SpecError) as error:
        RunStore(tmp_path)
    assert error.value.field == "--out" and error.value.value == str(tmp_path)
    RunStore(tmp_path).close()  # the lock goes with its holder


def test_a_failing_run_returns_its_error_instead_of_raising():
    class Broken(IshigamiModel):
        def evaluate(self, data, keep_result=False):
            raise RuntimeError("no convergence")

    study = ishigami_study(samples=2)
    _, runs = plan(study, sample(study))
    outcomes = evaluate_runs(Broken(), list(runs.values()))
    assert [o["status"] for o in outcomes] == ["error", "error"]
    assert outcomes[0]["error"].startswith("RuntimeError: no convergence")
