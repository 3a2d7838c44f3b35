"""The stability suite (bearing-mbs stability): its ladder logic, the reduced suite, and the full suite (slow).

References and tolerances:
* the ladder walk, on a fake runner with a known threshold: the largest passing rung and the first failing one
  are found exactly;
* the advisor's explicit limit is within a factor of 2 of the measured limit in at least
  90 % of the measured cells, for the reduced suite (5 cases × 3 explicit reference integrators, about a minute)
  and for the full suite (19 cases × 7 solvers, marked slow; about 15 minutes on 2 shared cores);
* the measured limit is bracketed by the energy audit and the spurious-slip comparison, not only by NaN: on the
  nominal case the first failing RK4 rung (2.46e-7 s) is a run the guards let through.
"""

import json
import math

import pytest

from bearing_mbs.core.failures import Failure
from bearing_mbs.models import MODELS, load_spec
from bearing_mbs.studies import stability
from bearing_mbs.studies.stability import (
    REDUCED_SOLVERS,
    SOLVERS,
    failure_reason,
    walk,
)
from bearing_mbs.studies.table import read_rows

from cases import SCENARIOS

#: The cylindrical roller bearing's stability suite: its cases, all and reduced.
SUITE = MODELS["cylindrical_roller"].stability
CASE_NAMES, REDUCED_CASES = SUITE.names, SUITE.reduced

BASE = SCENARIOS / "seed_hss_steady.toml"
#: The suite's base: the document's dry model (the scenario's variant "dry").
DRY = ["scenario.variant=dry"]


class FakeRunner:
    """Passes below ``threshold``; records what was asked."""

    def __init__(self, threshold):
        self.threshold, self.asked = threshold, []

    def verdict(self, setting):
        self.asked.append(setting)
        return ("pass", "") if setting <= self.threshold else ("fail", "spurious slip")


@pytest.mark.parametrize("threshold, largest, first_fail", [
    (1.5, 2.0 ** 0.5, 2.0), (0.3, 2.0 ** -2, 2.0 ** -1.5), (100.0, 4.0, None),
])
def test_walk_finds_the_largest_passing_rung(threshold, largest, first_fail):
    runner = FakeRunner(threshold)
    found = walk(runner, lambda k: 2.0 ** (k / 2), up=4, down=6)
    assert found["largest_pass"] == pytest.approx(largest)
    assert found["first_fail"] == (None if first_fail is None else pytest.approx(first_fail))
    assert found["capped"] == (threshold == 100.0)
    assert found["fail_reason"] == ("" if first_fail is None else "spurious slip")


def test_walk_reports_nothing_when_every_rung_fails():
    found = walk(FakeRunner(0.0), lambda k: 2.0 ** (k / 2), up=4, down=3)
    assert found["largest_pass"] is None and found["first_fail"] == pytest.approx(2.0 ** -1.5)  # the lowest rung tried


def test_failure_reasons_come_from_the_failure_kinds():
    assert failure_reason(Failure.NONFINITE) == "NaN"
    assert failure_reason(Failure.BLOWUP) == "blow-up"
    assert failure_reason(Failure.PENETRATION) == "penetration"
    assert {failure_reason(kind) for kind in (Failure.SOLVER_FAILED, Failure.STEP_UNDERFLOW,
                                              Failure.PROJECTION_FAILED)} == {"solver failure"}


def test_every_case_builds_a_valid_scene():
    from bearing_mbs.models import build_scene

    base = load_spec(BASE, DRY)
    by_name = {case.name: case for case in SUITE.cases}
    counts = {}
    for name in CASE_NAMES:
        scene = build_scene(stability.case_spec(base, by_name[name]))
        counts[name] = sum(1 for b in scene.bodies if b.name.startswith("roller"))
    assert counts["Z = 8"] == 8 and counts["Z = 30"] == 30 and counts["nominal"] == 15
    assert counts["full complement"] > 25


def check_suite(directory, summary, cases, solvers):
    rows = (directory / "stability.csv").read_text().splitlines()
    assert len(rows) == 1 + len(cases) * len(solvers)
    assert (directory / "stability.png").stat().st_size > 10_000
    table = [line for line in (directory / "stability.md").read_text().splitlines()
             if line.startswith("| ") and line.split(" | ")[1] in ("reference", "exudyn")]
    assert len(table) == len(cases) * len(solvers)
    assert json.loads((directory / "summary.json").read_text())["cells"] == len(cases) * len(solvers)
    assert summary["explicit_cells_measured"] >= 0.9 * sum(1 for _, method in solvers
                                                          if method in ("central_difference", "velocity_verlet",
                                                                        "rk4", "rk4")) * len(cases)
    assert summary["fraction_within_factor_2"] >= 0.9, summary["outside_factor_2"]


def test_reduced_suite(tmp_path):
    """The default-test version: 5 cases, the reference's three fixed-step integrators and generalized-alpha."""
    summary = stability.study(load_spec(BASE, DRY), tmp_path, cases=REDUCED_CASES, solvers=REDUCED_SOLVERS)
    check_suite(tmp_path, summary, REDUCED_CASES, REDUCED_SOLVERS)
    rows = {(r["case"], r["solver"]): r for r in read_rows(tmp_path / "stability.csv")}
    nominal = rows[("nominal", "rk4")]
    assert float(nominal["largest_pass"]) == pytest.approx(float(nominal["advised_limit"]))
    assert nominal["fail_reason"] in ("energy audit", "spurious slip")  # bounded but wrong, not NaN
    assert rows[("nominal", "generalized_alpha")]["verdict"].startswith("pass")
    assert math.isinf(float(rows[("nominal", "generalized_alpha")]["advised_limit"]))


def test_stability_command_resumes(tmp_path, capsys):
    from bearing_mbs.cli import main

    arguments = ["stability", str(BASE), "--out", str(tmp_path), "--cases", "nominal", "--solvers", "reference/rk4",
                 "--set", *DRY]
    assert main(arguments) == 0
    assert "1 of 1 explicit cells (100 %)" in capsys.readouterr().out
    first = (tmp_path / "stability.csv").read_text()
    assert main(arguments) == 0  # nothing left to run: the finished cell is read back
    assert (tmp_path / "stability.csv").read_text() == first
    assert main(["stability", str(BASE), "--out", str(tmp_path), "--cases", "no such case"]) == 2


@pytest.mark.slow
def test_full_suite(tmp_path):
    summary = stability.study(load_spec(BASE, DRY), tmp_path, cases=CASE_NAMES, solvers=SOLVERS)
    check_suite(tmp_path, summary, CASE_NAMES, SOLVERS)
