"""Bad input that only a command or the run as a whole can see, refused before anything runs (docs/status.md).

Each row: the command line, and the field the error must name. The command exits 2, writes nothing, and its
error line is ``error: FIELD = VALUE: what is allowed`` (the format of :class:`bearing_mbs.spec.SpecError`);
the test checks the field and that a value and an allowed range follow, not the wording.
"""

from __future__ import annotations

import pytest

from bearing_mbs.cli import main

from cases import SCENARIOS

STEADY = str(SCENARIOS / "seed_hss_steady.toml")
BALLS = str(SCENARIOS / "seed_case1.toml")
LUBRICATED = STEADY  # lubricated by default; its variant "dry" is the document's model
DRY = ["--set", "scenario.variant=dry"]
SHORT = ["--set", "scenario.end_time=0.002", "--set", "analysis.start=0.001"]

ROWS = {
    # the output: a path under a file is created before nothing else can fail
    "output under a file": (["run", STEADY, "--out", "{file}/out", *SHORT], "--out"),
    # an output that would need more memory than the machine has (1e-12 s over 0.1 s: about 2e11 instants)
    "output beyond memory": (["run", STEADY, "--out", "{out}", "--engine", "reference",
                              "--set", "solver.output_interval=1e-12"], "solver.output_interval"),
    # a body that starts faster than the speed guard (1e9 rpm)
    "speed beyond the guard": (["run", STEADY, "--out", "{out}", "--set", "solver.speed_limit=5", *SHORT],
                               "solver.speed_limit"),
    "animate a balls scenario": (["run", BALLS, "--out", "{out}", "--animate"], "--animate"),
    "solver that does not exist": (["stability", STEADY, "--out", "{out}", "--solvers", "reference/rk5"],
                                   "--solvers"),
    "engine without a method": (["stability", STEADY, "--out", "{out}", "--solvers", "exudyn"], "--solvers"),
    "case that does not exist": (["stability", STEADY, "--out", "{out}", "--cases", "nominal,granite"], "--cases"),
    "explicit Exudyn in the suite on a constraint cage": (["stability", STEADY, "--out", "{out}", "--cases",
                                                           "nominal", "--solvers", "reference/rk4,exudyn/rk4",
                                                           "--set", "cage.model=constraint"],
                                                          "solver.exudyn.method"),
    "convergence window past the end": (["convergence", STEADY, "--out", "{out}", "--set", "scenario.end_time=0.015",
                                         "--set", "analysis.start=0.01"],
                                        "convergence.end"),
    "stiffness of a balls scenario": (["stiffness", BALLS, "--out", "{out}"], "scenario.model"),
    # Exudyn's explicit ladders of the study cannot run a constraint cage: refused before the reference runs
    "explicit Exudyn on a constraint cage": (["convergence", STEADY, "--out", "{out}", *DRY, "--set",
                                              "cage.model=constraint"], "solver.exudyn.method"),
    "skidding map of a dry scenario": (["skidding-map", STEADY, "--out", "{out}", *DRY], "lubricant.temperature"),
    "skidding map beyond the oil's fit": (["skidding-map", LUBRICATED, "--out", "{out}", "--temperatures", "40,150"],
                                          "lubricant.temperature"),
    "skidding map without a cage": (["skidding-map", LUBRICATED, "--out", "{out}", "--set", "cage.model=none"],
                                    "cage.model"),
    "minimum-load band upside down": (["skidding-map", LUBRICATED, "--out", "{out}", "--minimum-load", "9000,4000"],
                                      "--minimum-load"),
}


@pytest.mark.parametrize("name", list(ROWS))
def test_refused_before_anything_runs(name, tmp_path, capsys):
    arguments, field = ROWS[name]
    blocker = tmp_path / "file"
    blocker.write_text("a file, not a directory")
    out = tmp_path / "out"
    argv = [a.format(out=out, file=blocker) for a in arguments]
    assert main(argv) == 2
    assert not out.exists()
    line = capsys.readouterr().err.strip().splitlines()[-1]
    assert line.startswith(f"error: {field} = "), line
    value, _, allowed = line.removeprefix(f"error: {field} = ").partition(": ")
    assert value and allowed, line


def test_a_non_empty_output_is_refused_unless_overwrite(tmp_path, capsys):
    out = tmp_path / "out"
    out.mkdir()
    (out / "notes.txt").write_text("mine")
    assert main(["run", STEADY, "--out", str(out), "--quiet", *SHORT]) == 2
    assert capsys.readouterr().err.strip().splitlines()[-1].startswith("error: --out = ")
    assert [p.name for p in out.iterdir()] == ["notes.txt"]
