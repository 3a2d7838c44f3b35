"""One voice for step advice: every message that advises a step quotes the step advisor's limit for the run's
method and scene, and following the advice passes the ``step_limit`` check.

Reference: the step advisor's stability limit (:mod:`bearing_mbs.numerics.advisor`, itself checked against the
measured limits in tests/test_advisor.py and docs/numerics.md). The issue's example: RK4 at 1e-4 s on the seed
bearing diverged with the advice 2.5e-5 s, its energy check advised 2.5e-6 s and its step check <= 8e-7 s (limit
1.6e-6 s): three voices, two of them above the limit.
"""

from __future__ import annotations

import json

import pytest

from bearing_mbs.cli import main
from bearing_mbs.core.failures import Failure
from bearing_mbs.core.result import Result
from bearing_mbs.models import build_scene, load_spec
from bearing_mbs.numerics.advisor import advise, step_advice
from bearing_mbs.spec import ReferenceSolver, SolverSpec

from cases import SCENARIOS

STEADY = SCENARIOS / "seed_hss_steady.toml"
SHORT = ["--set", "scenario.end_time=0.002", "--set", "analysis.start=0.001", "--set", "solver.output_interval=1e-4"]


def _run(tmp_path, name, *overrides):
    out = tmp_path / name
    code = main(["run", str(STEADY), "--out", str(out), "--engine", "reference", "--no-figures", "--quiet",
                 *SHORT, *overrides])
    return code, json.loads((out / "summary.json").read_text()), Result.load(out / "result.npz")


def test_every_message_quotes_one_advice_and_following_it_passes_the_step_check(tmp_path):
    # diverges (blows up, or a roller runs through its raceway first): its message quotes the advice
    code, summary, result = _run(tmp_path, "diverged", "--set", "solver.reference.step=1e-4")
    assert code == 1 and result.failure in (Failure.BLOWUP, Failure.PENETRATION)
    spec = load_spec(STEADY, ["solver.engine=reference", "solver.reference.step=1e-4"])
    advice = step_advice(build_scene(spec), spec.solver)
    limit = advise(build_scene(spec)).limit("reference", "rk4")
    assert advice.limit == pytest.approx(limit, rel=1e-12) and advice.value <= limit
    assert advice.text() in result.message
    # bounded but wrong: the step-limit and energy checks quote the same advice (the same value: the advice does not
    # depend on how far above the limit the step is)
    code, summary, result = _run(tmp_path, "bounded", "--set", "solver.reference.step=1e-5")
    failed = {check.name: check for check in result.failed_checks}
    assert code == 3 and {"step_limit", "energy_audit"} <= set(failed)
    quoted = step_advice(build_scene(spec), SolverSpec(engine="reference",
                                                       reference=ReferenceSolver(method="rk4", step=1e-5)))
    assert quoted.value == advice.value and quoted.field == summary["step_advice"]["field"] == "solver.reference.step"
    for check in failed.values():
        assert quoted.text() in check.detail, check.name
    # following the advice passes the step check
    advised = summary["step_advice"]
    code, summary, result = _run(tmp_path, "advised", "--set", f"{advised['field']}={advised['value']}")
    checks = {check.name: check for check in result.checks}
    assert checks["step_limit"].passed and code == 0, [c.line() for c in result.failed_checks]


@pytest.mark.parametrize("method", ["central_difference", "velocity_verlet", "rk4"])
@pytest.mark.parametrize("step", [1e-4, 2e-6, 1e-6, 5e-7, 1e-8])
def test_the_advised_step_never_exceeds_the_limit(method, step):
    """Within the limit or above it, for every fixed-step explicit method of the reference engine: the advice is
    at most the recommended step (half the limit) when the step exceeds it, else a quarter of the step."""
    spec = load_spec(STEADY, ["solver.engine=reference", f"solver.reference.method={method}",
                              f"solver.reference.step={step}"])
    scene = build_scene(spec)
    advice = step_advice(scene, spec.solver)
    limit = advise(scene).limit("reference", method)
    assert advice.limit == pytest.approx(limit, rel=1e-12)
    assert advice.value <= 0.5 * limit * (1 + 1e-12) and advice.value < step
