"""Fault suite (docs/status.md): each fault's status, exit code and what was kept. No wrong answer may be reported
as ``success``.

* SIGINT and SIGTERM on both engines: the command stops, exits 128 + the signal's number, and writes what it
  computed with status ``interrupted`` (a real process, signalled once its progress bar shows it stepping);
* an unwritable output directory and an existing result: refused before anything runs (exit 2), the existing
  result untouched; with ``--overwrite``, a failed run goes to ``rejected/`` and never replaces a good result;
* a step far above the stability limit: ``suspect`` (exit 3), with the step and energy checks failed;
* truncation and an energy audit out of bound: a finished run whose output is cut short or whose energy balance
  is broken on purpose is ``suspect``, the failed check naming the value and the bound.
"""

from __future__ import annotations

import dataclasses
import json
import os
import signal
import subprocess
import sys
import threading
from pathlib import Path

import numpy as np
import pytest

from bearing_mbs.cli import main
from bearing_mbs.core.failures import Failure
from bearing_mbs.core.result import FAILED, INTERRUPTED, SUCCESS, SUSPECT, Result
from bearing_mbs.models import load_spec
from bearing_mbs.runner import run_spec
from bearing_mbs.runner.checks import run_checks

from cases import SCENARIOS

STEADY = str(SCENARIOS / "seed_hss_steady.toml")
#: The document's dry model (the steady scenario's variant "dry"), whose step limits these tests cite.
DRY = ["--set", "scenario.variant=dry"]
SHORT = [*DRY, "--set", "scenario.end_time=0.002", "--set", "analysis.start=0.001"]
#: The analysis window of the signalled runs starts after they are stopped [s].
WINDOW_START = 0.5
#: The progress bar's unit: once printed, the engine is stepping (compilation is behind it).
STEPPING = "s simulated"


def _summary(directory: Path) -> dict:
    return json.loads((directory / "summary.json").read_text())


def _signalled_run(tmp_path: Path, engine: str, number: int) -> tuple[int, Path, str]:
    """Start a long run in a child process, send ``number`` once it is stepping; (exit code, out, its stderr)."""
    out = tmp_path / "out"
    command = [sys.executable, "-m", "bearing_mbs.cli", "run", STEADY, "--out", str(out), "--no-figures",
               "--engine", engine, *DRY, "--set", "scenario.end_time=1.0", "--set", f"analysis.start={WINDOW_START}"]
    child = subprocess.Popen(command, stderr=subprocess.PIPE, stdout=subprocess.PIPE, text=True, bufsize=1,
                             cwd=Path(__file__).resolve().parents[1], env={**os.environ, "TQDM_MININTERVAL": "0"})
    stepping = threading.Event()
    lines: list[str] = []

    def watch():
        for line in iter(lambda: child.stderr.read(64), ""):
            lines.append(line)
            if STEPPING in "".join(lines[-3:]):
                stepping.set()
        stepping.set()  # the child ended before stepping: the assertions below say why

    threading.Thread(target=watch, daemon=True).start()
    assert stepping.wait(600), "the run never started stepping"
    child.send_signal(number)
    code = child.wait(timeout=120)
    return code, out, "".join(lines)


@pytest.mark.parametrize("engine", ["reference", "exudyn"])
@pytest.mark.parametrize("number", [signal.SIGINT, signal.SIGTERM], ids=["SIGINT", "SIGTERM"])
def test_a_signal_stops_the_run_and_keeps_what_it_computed(tmp_path, engine, number):
    code, out, log = _signalled_run(tmp_path, engine, number)
    assert code == 128 + number, log[-2000:]
    summary = _summary(out)
    assert summary["status"] == INTERRUPTED
    result = Result.load(out / "result.npz")
    assert result.status == INTERRUPTED
    assert 1 < result.time.size < 10001  # something computed, the run (1 s at 1e-4 s) not finished
    assert 0 < summary["end_time"] < WINDOW_START
    assert np.isfinite(result.position).all()
    # stopped before its analysis window: the window is kept, and no window metric pretends to describe it
    assert summary["analysis_start"] == WINDOW_START and summary["cage_slip"] is None


def test_an_output_under_a_file_is_refused_before_the_run(tmp_path, capsys):
    blocker = tmp_path / "file"
    blocker.write_text("not a directory")
    assert main(["run", STEADY, "--out", str(blocker / "out"), "--quiet", *SHORT]) == 2
    assert blocker.read_text() == "not a directory"
    assert "--out" in capsys.readouterr().err


@pytest.mark.skipif(hasattr(os, "geteuid") and os.geteuid() == 0, reason="root writes into read-only directories")
def test_a_read_only_output_is_refused_before_the_run(tmp_path):
    locked = tmp_path / "locked"
    locked.mkdir()
    locked.chmod(0o500)
    try:
        assert main(["run", STEADY, "--out", str(locked / "out"), "--quiet", *SHORT]) == 2
    finally:
        locked.chmod(0o700)


def test_an_existing_result_is_kept(tmp_path):
    out = tmp_path / "out"
    assert main(["run", STEADY, "--out", str(out), "--quiet", "--no-figures", *SHORT]) == 0
    before = {p.name: p.read_bytes() for p in out.iterdir()}
    assert _summary(out)["status"] == SUCCESS

    # refused without --overwrite, before anything runs
    assert main(["run", STEADY, "--out", str(out), "--quiet", "--no-figures", *SHORT]) == 2
    assert {p.name: p.read_bytes() for p in out.iterdir()} == before

    # a run that fails (RK4 at 1e-4 s, 500 times its stability limit, diverges) never replaces the good result
    failing = [*SHORT, "--engine", "reference", "--set", "solver.reference.step=1e-4"]
    assert main(["run", STEADY, "--out", str(out), "--quiet", "--no-figures", "--overwrite", *failing]) == 1
    assert {p.name: p.read_bytes() for p in out.iterdir() if p.is_file()} == before
    assert _summary(out / "rejected")["status"] == FAILED

    # a good run with --overwrite replaces it, stale files included
    (out / "stale.png").write_bytes(b"old figure")
    assert main(["run", STEADY, "--out", str(out), "--quiet", "--no-figures", "--overwrite", *SHORT]) == 0
    assert sorted(p.name for p in out.iterdir()) == ["result.npz", "summary.json"]


def test_a_step_far_above_the_limit_is_suspect(tmp_path):
    """The reference engine's RK4 at 1e-5 s, 57x the advised limit (docs/numerics.md): bounded, but wrong."""
    out = tmp_path / "out"
    code = main(["run", STEADY, "--out", str(out), "--quiet", "--no-figures", "--engine", "reference",
                 "--set", "solver.reference.step=1e-5", *SHORT])
    assert code == 3
    summary = _summary(out)
    assert summary["status"] == SUSPECT
    failed = {check["name"]: check for check in summary["checks"] if check["verdict"] == "fail"}
    assert failed["step_limit"]["value"] == 1e-5 and failed["step_limit"]["bound"] < 1e-6
    assert failed["energy_audit"]["value"] > failed["energy_audit"]["bound"]


@pytest.fixture(scope="module")
def finished():
    spec = load_spec(STEADY, ["scenario.variant=dry", "scenario.end_time=0.002", "analysis.start=0.001",
                              "solver.engine=reference"])
    scene, result = run_spec(spec)
    assert result.status == SUCCESS, [c.line() for c in result.checks]
    return spec, scene, result


def _failed(spec, scene, result):
    checks = run_checks(scene, spec.solver, spec.scenario.end_time, result)
    judged = dataclasses.replace(result, checks=checks)
    return judged.status, {check.name: check for check in checks if not check.passed}


def test_a_truncated_run_is_suspect(finished):
    spec, scene, result = finished
    cut = dataclasses.replace(result, **{name: getattr(result, name)[:-5] for name in
                                         ("time", "position", "velocity", "pair_output", "constraint_forces",
                                          "work")})
    status, failed = _failed(spec, scene, cut)
    assert status == SUSPECT
    assert failed["end_time_reached"].value == pytest.approx(result.time[-6])
    assert failed["output_instants"].value == result.time.size - 5


def test_an_energy_audit_out_of_bound_is_suspect(finished):
    spec, scene, result = finished
    work = result.work.copy()
    work[:, 0] *= 1.2  # 20 % more work supplied than the bodies received
    status, failed = _failed(spec, scene, dataclasses.replace(result, work=work))
    assert status == SUSPECT
    assert set(failed) == {"energy_audit"}
    assert failed["energy_audit"].value > failed["energy_audit"].bound


def test_a_failed_run_is_never_success(finished):
    result = finished[2]
    for failure in Failure:
        if failure != Failure.NONE:
            assert dataclasses.replace(result, failure=failure).status in (FAILED, INTERRUPTED)
