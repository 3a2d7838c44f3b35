"""The whole pipeline, sample → Dask evaluate → persist → analyze → report, on one local cluster
(2 worker processes, one thread each) shared by the module.

Pipeline check: SALib's Ishigami function through this pipeline reproduces its analytic Sobol indices
within the tolerance of SALib's own tests (``tests/test_sobol.py``, ``test_parallel_first_order``:
``assert_allclose(Si["S1"], [0.31, 0.44, 0.00], atol=5e-2, rtol=1e-1)``, and the same for ST), here
against the exact values (Saltelli et al. 2008) rather than their two-digit roundings.
"""

import math
import textwrap
from pathlib import Path

import numpy as np
import pytest

from bearing_mbs.core.result import Result
from bearing_mbs.studies.sensitivity import (
    IshigamiModel,
    Method,
    Parameter,
    RunStore,
    Study,
    connect,
    ishigami_indices,
    load_study,
    run_study,
)

ROOT = Path(__file__).resolve().parents[1]
SHIPPED = ROOT / "scenarios" / "study_drop_morris.toml"
PI = math.pi


@pytest.fixture(scope="module")
def client():
    with connect(workers=2) as client:
        yield client


def ishigami_toml(tmp_path, sampler="sobol", samples=1024, analyzer="", runs_per_task=256) -> Path:
    parameters = "".join(f'[[parameters]]\nname = "x{i}"\nbounds = [{-PI!r}, {PI!r}]\n' for i in (1, 2, 3))
    path = tmp_path / "ishigami.toml"
    path.write_text(textwrap.dedent(f"""
        [study]
        name = "ishigami_{sampler}"
        model = "ishigami"
        outputs = ["y"]
        seed = 12345
        [method]
        sampler = "{sampler}"
        samples = {samples}
        {analyzer}
        [execution]
        runs_per_task = {runs_per_task}
        """) + parameters)
    return path


def test_ishigami_sobol_indices_through_the_pipeline(client, tmp_path):
    study = load_study(ishigami_toml(tmp_path))
    result = run_study(study, tmp_path / "out", client=client, figures=False)
    D, N = 3, 1024
    assert len(result.table) == N * (D + 2) and result.complete
    indices = result.indices["y"].to_df()
    exact = ishigami_indices()
    np.testing.assert_allclose(indices["S1"], exact["S1"], atol=5e-2, rtol=1e-1)
    np.testing.assert_allclose(indices["ST"], exact["ST"], atol=5e-2, rtol=1e-1)
    assert (indices[["S1_conf", "ST_conf"]] > 0).all().all()
    with RunStore(tmp_path / "out") as store:
        assert store.count() == result.stats.planned == result.stats.evaluated
    again = run_study(study, tmp_path / "out", client=client, report=False)
    assert again.stats.evaluated == 0 and again.stats.skipped == result.stats.planned
    np.testing.assert_array_equal(again.table["y"], result.table["y"])


def test_latin_hypercube_with_rbd_fast_analysis(client, tmp_path):
    """RBD-FAST first-order indices from a Latin hypercube, against the same analytic S1 (the estimator
    is biased at small N, so only the ranking and a loose bound are checked)."""
    study = load_study(ishigami_toml(tmp_path, "latin", 1024))
    result = run_study(study, tmp_path / "out", client=client, figures=False)
    df = result.indices["y"].to_df()
    assert list(df.columns) == ["S1", "S1_conf"]
    np.testing.assert_allclose(df["S1"], ishigami_indices()["S1"], atol=0.1)
    assert df["S1"].idxmax() == "x2"


def test_shipped_morris_study_end_to_end(client, tmp_path):
    """The shipped study, shortened to 4 trajectories and keeping result files: indices, figures, the
    table of runs, and each run's result.npz next to its summary."""
    study = load_study(SHIPPED, ["method.samples=4", "execution.keep_results=true"])
    out = tmp_path / "drop"
    result = run_study(study, out, client=client)
    assert result.complete
    assert len(result.table) == 4 * (len(study.parameters) + 1)
    mu_star = result.indices["restitution_effective"].to_df()["mu_star"]
    assert mu_star.idxmax() == "contact.wall.restitution"  # e drives the rebound, the others barely
    report = result.report.read_text()
    for name in ("morris_restitution_effective.png", "scatter_max_penetration.png", "runs.csv"):
        assert (out / "report" / name).is_file() and name in report
    assert "μ*" in report
    with RunStore(out) as store:
        directory = store.run_directory(result.table["key"][0])
    stored = Result.load(directory / "result.npz")
    assert stored.success and stored.spec["contact"]["wall"]["restitution"] == result.table.iloc[0, 0]


class Flaky(IshigamiModel):
    """Raises for x1 > 2 (every attempt), and on the first attempt of x1 < -2 (a marker file per input
    remembers the attempt across worker processes)."""

    def __init__(self, markers):
        object.__setattr__(self, "markers", str(markers))

    def evaluate(self, data, keep_result=False):
        if data["x1"] > 2:
            raise ValueError("x1 beyond the model's range")
        marker = Path(self.markers) / f"{data['x1']!r}-{data['x2']!r}-{data['x3']!r}"
        if data["x1"] < -2 and not marker.exists():
            marker.touch()
            raise RuntimeError("transient failure")
        return super().evaluate(data, keep_result)


def test_failed_runs_are_retried_once_then_recorded_and_never_stop_the_study(client, tmp_path):
    bounds = (-PI, PI)
    study = Study("flaky", Flaky(tmp_path), [Parameter(f"x{i}", bounds) for i in (1, 2, 3)], ("y",),
                  Method("sobol", samples=16), seed=3)
    result = run_study(study, tmp_path / "out", client=client, figures=False)
    table = result.table
    broken, transient = table["x1"] > 2, table["x1"] < -2
    assert broken.any() and transient.any()
    assert (table.loc[broken, "status"] == "error").all() and (table.loc[broken, "attempts"] == 2).all()
    assert table.loc[broken, "error"].str.startswith("ValueError: x1 beyond").all()
    assert (table.loc[transient, "status"] == "success").all() and (table.loc[transient, "attempts"] == 2).all()
    assert (table.loc[~broken & ~transient, "attempts"] == 1).all()
    assert result.stats.errors == table.loc[broken, "key"].nunique()
    assert result.indices["y"].result is None and "no value" in result.indices["y"].note
    assert result.status == "failed"  # a run that ended in an error counts as failed (exit code 1)
    assert "ended in an error" in result.report.read_text()
    with RunStore(tmp_path / "out") as store:
        assert store.count() == table["key"].nunique()  # every run recorded, errors included
    again = run_study(study, tmp_path / "out", client=client, report=False)
    assert again.stats.evaluated == 0  # errors are recorded results; --retry-errors runs them again
    retried = run_study(study, tmp_path / "out", client=client, report=False, retry_errors=True)
    assert retried.stats.evaluated == table.loc[broken, "key"].nunique()


class Suspicious(IshigamiModel):
    """Reaches its end everywhere but fails a check for x1 > 2 (a run of ``suspect`` status, as a simulation's)."""

    def evaluate(self, data, keep_result=False):
        summary, files = super().evaluate(data, keep_result)
        passed = data["x1"] <= 2
        check = {"name": "window_settled", "value": data["x1"], "bound": 2.0, "unit": "-",
                 "verdict": "pass" if passed else "fail", "detail": "" if passed else "x1 beyond 2"}
        return {**summary, "status": "success" if passed else "suspect", "checks": [check]}, files


def test_a_study_is_as_good_as_its_worst_run(client, tmp_path):
    """Issue 25: the study's status (and the sweep's exit code) is its worst run's; the table names each run's
    failed checks."""
    from bearing_mbs.cli.options import exit_code

    study = Study("suspicious", Suspicious(), [Parameter(f"x{i}", (-PI, PI)) for i in (1, 2, 3)], ("y",),
                  Method("latin", samples=16), seed=3)
    result = run_study(study, tmp_path / "out", client=client, figures=False)
    beyond = result.table["x1"] > 2
    assert beyond.any() and (~beyond).any()
    assert result.status == "suspect" and exit_code(result.status) == 3
    assert (result.table.loc[beyond, "failed_checks"] == "window_settled").all()
    assert (result.table.loc[~beyond, "failed_checks"] == "").all()
