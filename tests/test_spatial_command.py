"""``bearing-mbs spatial``: the bearing in three dimensions from a scenario file (docs/spatial.md).

What is checked: the command writes its summary, series and figures, the summary agrees with the series it wrote
(the largest slice load, the end time), its status is ``success`` only with a closed energy audit; bad input (a
scenario the three-dimensional model does not cover, a bad option) exits 2 naming the field, before anything runs,
and leaves no output directory behind.
"""

from __future__ import annotations

import json

import numpy as np
import pytest

from bearing_mbs.cli import main
from bearing_mbs.spec import methods

from cases import SCENARIOS

SCENARIO = str(SCENARIOS / "seed_hss_steady.toml")


@pytest.mark.parametrize("method", [[], ["--method", methods.RK4.name]])
def test_the_command_writes_its_summary_series_and_figures(tmp_path, method):
    out = tmp_path / "spatial"
    code = main(["spatial", SCENARIO, "--out", str(out), "--set", "scenario.variant=dry", "--end-time", "3e-4",
                 "--misalignment", "5e-4", "--crown-radius", "2.0", "--quiet", *method])
    assert code == 0
    summary = json.loads((out / "summary.json").read_text())
    assert summary["method"] == (method[-1] if method else methods.GENERALIZED_ALPHA.name)
    assert summary["step_s"] == (2e-7 if method else 1e-5)
    series = np.load(out / "series.npz")
    assert summary["status"] == "success" and summary["energy_audit_error"] <= summary["energy_audit_tolerance"]
    np.testing.assert_allclose(summary["end_time_s"], 3e-4, rtol=1e-9)
    np.testing.assert_allclose(summary["largest_slice_load_N"], series["slice_loads"].max(), rtol=1e-12)
    assert series["orientation"].shape[1] == 17  # inner ring, cage, 15 rollers
    assert 0 < summary["largest_tilt_rad"] < 1e-3  # the misaligned ring tilts its loaded rollers
    for figure in ("slice_loads.png", "attitudes.png", "ribs_smearing.png"):
        assert (out / figure).stat().st_size > 10_000


@pytest.mark.parametrize("arguments, field", [
    ([], "cage.model"),  # the lubricated variant's constraint cage: not in three dimensions yet
    (["--set", "scenario.variant=dry", "--slices", "0"], "--slices"),
    (["--set", "scenario.variant=dry", "--engine", "abaqus"], "--engine"),
    (["--set", "scenario.variant=dry", "--method", methods.DOPRI5.name], "--method"),
    (["--set", "scenario.variant=dry", "--method", methods.RK4.name, "--spectral-radius", "0.5"], "--spectral-radius"),
    (["--set", "scenario.variant=dry", "--engine", "exudyn", "--tolerance", "1e-6"], "--tolerance"),
    (["--set", "scenario.variant=dry", "--spectral-radius", "1.5"], "--spectral-radius"),
    (["--set", "scenario.variant=dry", "--axial-load", "-1"], "--axial-load"),
])
def test_bad_input_exits_2_naming_the_field_and_leaves_nothing(tmp_path, capsys, arguments, field):
    out = tmp_path / "spatial"
    assert main(["spatial", SCENARIO, "--out", str(out), "--quiet", *arguments]) == 2
    assert field in capsys.readouterr().err
    assert not out.exists()
