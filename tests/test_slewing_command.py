"""``bearing-mbs slewing``: the shipped scenarios of document 002 solve and write what docs/slewing.md says.

References: the ball counts of the thesis's Table 2 (44 … 224, exact); the summary's curve is the solver's
(checked against the thesis's FE curve in tests/test_slewing_load_distribution.py) and its largest contact
pressure at the FE model's 0.42 mm is the exact Hertz pressure of its largest ball load (1e-9); the status and
checks (docs/status.md) against ISO 76's 4200 MPa and a one- and two-ball bearing; bad input exits 2 with nothing
written.
"""

from __future__ import annotations

import itertools
import json

import pytest

from bearing_mbs.cli import main

from cases import SCENARIOS

BALLS = {"0500": 44, "1000": 89, "1500": 134, "2000": 179, "2500": 224}
#: ISO 76:2006's contact pressure at the static load rating of ball bearings (other than self-aligning) [Pa].
ISO_76_BALL_PRESSURE = 4200e6


def _failed(summary) -> set[str]:
    return {check["name"] for check in summary["checks"] if check["verdict"] == "fail"}


@pytest.mark.parametrize("diameter", list(BALLS))
def test_the_seed_scenarios_solve(diameter, tmp_path):
    """At the FE model's 0.42 mm the largest ball's contact reaches 4149–4215 MPa: within ISO 76's 4200 MPa for
    D_pw >= 1 m (success, exit 0), beyond it for the 0.5 m bearing (suspect by contact_pressure, exit 3)."""
    code = main(["slewing", str(SCENARIOS / f"seed_slewing_{diameter}.toml"), "--out", str(tmp_path / "out"),
                 "--no-figures"])
    summary = json.loads((tmp_path / "out" / "summary.json").read_text())
    beyond = summary["max_contact_pressure"] > ISO_76_BALL_PRESSURE
    assert beyond == (diameter == "0500")
    assert (code, summary["status"], _failed(summary)) == ((3, "suspect", {"contact_pressure"}) if beyond
                                                           else (0, "success", set()))
    assert summary["balls"] == BALLS[diameter]
    displacements, forces = zip(*summary["axial_curve"])
    assert displacements[-1] == pytest.approx(0.42e-3) and all(b > a for a, b in itertools.pairwise(forces))
    assert summary["units"]["axial_curve"] == "m, N" and summary["units"]["max_contact_pressure"] == "Pa"
    assert len(summary["ball_loads"]) == BALLS[diameter] == len(summary["contact_angles"])


def test_the_documents_validation_case_writes_both_curves_and_the_finite_element_one(tmp_path):
    out = tmp_path / "out"
    assert main(["slewing", str(SCENARIOS / "seed_slewing_1500_validation.toml"), "--out", str(out)]) == 0
    summary = json.loads((out / "summary.json").read_text())
    assert (summary["rings"], summary["mount"], summary["coupling"]) == ("flexible", "fixed", "structural")
    assert all(0 < f < r for (_, f), (_, r) in zip(summary["axial_curve"], summary["rigid_axial_curve"]))
    assert [d for d, _ in summary["finite_element_axial_curve"]] == pytest.approx([d for d, _ in
                                                                                    summary["axial_curve"]])
    assert len(summary["rigid_ball_loads"]) == len(summary["ball_loads"])
    assert (out / "axial_curve.png").stat().st_size > 10_000


def test_the_stiffness_names_each_entry_and_its_unit(tmp_path):
    out = tmp_path / "out"
    assert main(["slewing", str(SCENARIOS / "seed_slewing_pitch.toml"), "--out", str(out), "--no-figures"]) == 0
    stiffness = json.loads((out / "summary.json").read_text())["stiffness"]
    assert len(stiffness) == 9
    assert stiffness["d_axial_force/d_axial"]["unit"] == "N/m" and stiffness["d_moment/d_tilt"]["unit"] == "N m/rad"
    assert stiffness["d_axial_force/d_axial"]["value"] > 0


def test_a_combined_load_writes_the_state_and_figures(tmp_path):
    out = tmp_path / "out"
    assert main(["slewing", str(SCENARIOS / "seed_slewing_1500.toml"), "--out", str(out),
                 "--set", "load.axial_displacements=[]", "--set", "load.axial=5e6", "--set", "load.moment=2e6"]) == 0
    summary = json.loads((out / "summary.json").read_text())
    assert summary["load"] == pytest.approx([0.0, 5e6, 2e6], abs=1e-2)
    assert (out / "ball_loads.png").stat().st_size > 10_000


def test_the_pitch_bearing_load_case_succeeds(tmp_path):
    """The blade root's static load (0.5 MN axial, 3 MN m): equilibrium reached, 4054 MPa at the largest ball."""
    out = tmp_path / "out"
    assert main(["slewing", str(SCENARIOS / "seed_slewing_pitch.toml"), "--out", str(out), "--no-figures"]) == 0
    summary = json.loads((out / "summary.json").read_text())
    assert summary["status"] == "success"
    assert {check["name"] for check in summary["checks"]} == {"ball_count", "equilibrium_residual",
                                                               "contact_pressure"}


def test_a_one_ball_bearing_fails_and_says_why(tmp_path):
    """Issue 25: one ball cannot hold the ring against a tilting moment; the load distribution does not converge:
    status failed, exit 1, the summary written with the failed ball_count check, no figures."""
    out = tmp_path / "out"
    assert main(["slewing", str(SCENARIOS / "seed_slewing_pitch.toml"), "--out", str(out),
                 "--set", "slewing.balls=1"]) == 1
    summary = json.loads((out / "summary.json").read_text())
    assert summary["status"] == "failed" and summary["message"] and _failed(summary) == {"ball_count"}
    assert not list(out.glob("*.png"))


def test_two_balls_are_suspect(tmp_path):
    """Two balls on one diameter carry the pitch load in the model's plane only, at 12 GPa: ball_count and
    contact_pressure fail (exit 3); the equilibrium itself is reached."""
    out = tmp_path / "out"
    assert main(["slewing", str(SCENARIOS / "seed_slewing_pitch.toml"), "--out", str(out), "--no-figures",
                 "--set", "slewing.balls=2"]) == 3
    assert _failed(json.loads((out / "summary.json").read_text())) == {"ball_count", "contact_pressure"}


@pytest.mark.parametrize("overrides, field", [
    (["slewing.conformity=1.2"], "slewing.conformity"),
    (["slewing.contact_angle=95"], "slewing.contact_angle"),
    (["slewing.balls=300"], "slewing.balls"),
    (["load.axial=1e6"], "load.axial_displacements"),
    (["slewing.rings='elastic'"], "slewing.rings"),
    (["slewing.mount='bolted'"], "slewing.mount"),
    (["slewing.coupling='series'"], "slewing.coupling"),
    (["slewing.mount='free'", "slewing.coefficients='as_printed'"], "slewing.coefficients"),
])
def test_bad_input_is_refused(overrides, field, tmp_path, capsys):
    out = tmp_path / "out"
    sets = [argument for override in overrides for argument in ("--set", override)]
    assert main(["slewing", str(SCENARIOS / "seed_slewing_1500.toml"), "--out", str(out), *sets]) == 2
    assert not out.exists()
    assert capsys.readouterr().err.strip().splitlines()[-1].startswith(f"error: {field} = ")
