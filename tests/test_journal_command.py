"""``bearing-mbs journal``: document 001's case solves and writes what docs/fluid-film.md reads; bad input exits 2.

References: document 001's Table 3 (stiffness at C = 0.07 mm: theory 4000, NX-FLOW 3950, MATLAB 3480, labelled N/mm,
read by the digest as N per unit eccentricity ratio: a loose ±20 % band, because the document does not state its
theory or the load direction) and the digest's independent finite-volume solution (§1.5, 0 rpm, 1 MPa supply,
load on a recess: W(ε = 0.25) = 677 N at C = 0.035 mm and 862 N at 0.07 mm; the two solvers differ by 5 % at the
smaller clearance, so within 6 %).
"""

from __future__ import annotations

import json

import pytest

from bearing_mbs.cli import main

from cases import SCENARIOS

SEED = str(SCENARIOS / "seed_hybrid_journal.toml")


def _summary(tmp_path, *overrides, figures=False):
    out = tmp_path / "out"
    argv = ["journal", SEED, "--out", str(out), *[a for o in overrides for a in ("--set", o)]]
    assert main(argv + ([] if figures else ["--no-figures"])) == 0
    return json.loads((out / "summary.json").read_text()), out


def test_seed_case_at_1000_rpm_writes_every_output(tmp_path):
    summary, out = _summary(tmp_path, figures=True)
    for key, unit in (("load_capacity", "N"), ("attitude_angle", "deg"), ("flow", "m^3/s"),
                      ("friction_torque", "N m"), ("recess_pressures", "Pa"), ("stiffness", "N/m"),
                      ("damping", "N s/m")):
        assert summary["units"][key] == unit
    assert len(summary["recess_pressures"]) == 4 and len(summary["stiffness"]) == 2 == len(summary["damping"])
    assert summary["friction_power"] > 0 and summary["mass_balance_error"] < 1e-8 and summary["warnings"] == []
    assert (out / "pressure_map.png").stat().st_size > 10_000 and (out / "load_curve.png").stat().st_size > 10_000


@pytest.mark.parametrize("clearance, digest", [(35e-6, 677.0), (70e-6, 862.0)])
def test_hydrostatic_load_and_stiffness_against_the_digest_and_table_3(clearance, digest, tmp_path):
    summary, _ = _summary(tmp_path, "journal.speed_rpm=0", f"journal.radial_clearance={clearance}")
    assert summary["load_capacity"] == pytest.approx(digest, rel=0.06)
    if clearance == 70e-6:
        small = _summary(tmp_path / "small", "journal.speed_rpm=0", f"journal.radial_clearance={clearance}",
                         "journal.eccentricity_ratio=0.05")[0]
        assert small["static_stiffness_per_eccentricity_ratio"] == pytest.approx(4000.0, rel=0.20)
    # the network is the document's fast approximation; it differs from the full solution by under 25 %
    assert 0 < summary["network_difference"] < 0.25


@pytest.mark.parametrize("override, field", [
    ("journal.eccentricity_ratio=1.0", "journal.eccentricity_ratio"),
    ("journal.recesses.angular_width=95", "journal.recesses.angular_width"),
    ("journal.recesses.capillary_length=0.005", "journal.recesses.capillary_length"),
    ("journal.recesses.axial_length=0.08", "journal.recesses.axial_length"),
    ("journal.cavitation='reynolds'", "journal.cavitation"),
    ("journal.grid=[2, 30]", "journal.grid"),
])
def test_bad_input_is_refused(override, field, tmp_path, capsys):
    out = tmp_path / "out"
    assert main(["journal", SEED, "--out", str(out), "--set", override]) == 2
    assert not out.exists()
    assert capsys.readouterr().err.strip().splitlines()[-1].startswith(f"error: {field} = ")
