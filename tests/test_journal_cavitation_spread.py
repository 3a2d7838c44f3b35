"""The journal command's ``cavitation_spread`` check (models/journal_bearing/checks.py; docs/status.md).

A mass-conserving (JFO) run also solves Gümbel's film and reports |W_JFO / W_Gümbel − 1|. Reference: on a plain bore of
L/D = 1 at ε = 0.6 fed through an ambient groove one cell wide at the thickest film, Raimondi and Boyd's table
(Reynolds' rupture condition, which the JFO film obeys; as reprinted in Shigley) carries 14 % more than the
half-Sommerfeld film (docs/fluid-film.md: 7748 N against 6808 N with Gümbel): the check must report 0.14 ± 0.02 and
pass. A Gümbel run carries no such check.
"""

from __future__ import annotations

import json

import pytest

from bearing_mbs.cli import main

from no_traceback import toml_document


def _summary(tmp_path, cavitation):
    scenario = {"scenario": {"name": "groove", "model": "journal_bearing", "end_time": 1.0},
                "journal": {"diameter": 0.1, "length": 0.1, "radial_clearance": 1e-4, "viscosity": 0.05,
                            "speed_rpm": 3000.0, "eccentricity_ratio": 0.6, "attitude": 180.0,
                            "cavitation": cavitation, "grid": [120, 30],
                            "recesses": {"count": 1, "angular_width": 3.0, "axial_length": 0.1, "depth": 1e-3,
                                         "supply_pressure": 0.0, "restrictor": "none"}}}
    (tmp_path / "groove.toml").write_text(toml_document(scenario))
    main(["journal", str(tmp_path / "groove.toml"), "--out", str(tmp_path / cavitation), "--no-figures"])
    return json.loads((tmp_path / cavitation / "summary.json").read_text())


def test_jfo_reports_its_spread_from_gumbel(tmp_path):
    check = next(c for c in _summary(tmp_path, "jfo")["checks"] if c["name"] == "cavitation_spread")
    assert check["value"] == pytest.approx(0.14, abs=0.02)
    assert check["verdict"] == "pass"


def test_gumbel_has_no_spread_check(tmp_path):
    assert "cavitation_spread" not in {c["name"] for c in _summary(tmp_path, "gumbel")["checks"]}
