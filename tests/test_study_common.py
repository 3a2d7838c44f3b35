"""The studies' shared plumbing (bearing_mbs.studies.common) and the io package: no simulation runs here.

References: ``load_spec`` with ``--set`` overrides is the reference for :func:`with_overrides` (the same
validation); linear interpolation is exact for linear series; JSON must be strict (no NaN)."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest

from bearing_mbs.io.figures import new_figure, save_figure
from bearing_mbs.io.json import json_safe, write_json
from bearing_mbs.models import load_spec
from bearing_mbs.spec import SpecError
from bearing_mbs.studies.common import refined, resample, setting_of, solver_at, with_overrides

STEADY = Path(__file__).resolve().parents[1] / "scenarios" / "seed_hss_steady.toml"


def test_with_overrides_validates_like_set_overrides():
    base = load_spec(STEADY)
    changed = with_overrides(base, {"load.radial": 2000.0, "cage.model": "constraint"})
    assert changed == load_spec(STEADY, ["load.radial=2000", "cage.model=constraint"])
    assert with_overrides(base, {"convergence": None}).convergence is None
    with pytest.raises(SpecError) as error:
        with_overrides(base, {"load.radiall": 1.0})
    assert error.value.field == "load.radiall"
    with pytest.raises(SpecError) as error:
        with_overrides(base, {"cage.model": "wooden"})
    assert error.value.field == "cage.model" and error.value.value == "wooden"


def test_refinement_halves_steps_and_divides_tolerances_by_32():
    solver = load_spec(STEADY).solver
    fixed = solver_at(solver, "reference", "rk4", 1e-7, largest_step=1e-5)
    assert fixed.engine == "reference" and fixed.reference.step == 1e-7
    assert setting_of(refined(fixed)) == 5e-8
    adaptive = solver_at(solver, "exudyn", "dopri5", 1e-6, largest_step=1e-5)
    assert (adaptive.exudyn.step, adaptive.exudyn.tolerance) == (1e-5, 1e-6)
    assert setting_of(refined(adaptive)) == 1e-6 / 32


def test_resample_is_exact_on_the_same_grid_and_linear_between():
    times = np.linspace(0.0, 1.0, 11)
    series = np.stack([2 * times, 3 * times - 1], axis=1)[:, :, None]
    assert resample(times, series, times) is series
    at = np.array([0.05, 0.55])
    np.testing.assert_allclose(resample(times, series, at)[:, :, 0], [[0.1, -0.85], [1.1, 0.65]])


def test_json_is_strict_and_written_atomically(tmp_path):
    data = {"a": float("nan"), "b": [1.0, float("inf"), (2, np.float64(3.5))], "c": np.arange(2)}
    assert json_safe(data) == {"a": None, "b": [1.0, None, [2, 3.5]], "c": [0, 1]}
    path = write_json(tmp_path / "x.json", data)
    assert json.loads(path.read_text()) == json_safe(data) and not (tmp_path / "x.json.part").exists()


def test_figures_are_saved_whole_without_a_backend(tmp_path):
    figure, axis = new_figure(figsize=(3, 2))
    axis.plot([0, 1], [1, 0])
    path = save_figure(figure, tmp_path / "sub" / "f.png")
    assert path.read_bytes()[:4] == b"\x89PNG" and not (tmp_path / "sub" / "f.png.part").exists()
