"""The eight coefficients over speed at the equilibrium under a static load (``journal.coefficient_speeds_rpm``,
``journal.static_load``; bearing_mbs/models/journal_bearing/speeds.py, fluid_film/equilibrium.py).

Reference (independent of the code under test): Ocvirk's short bearing (closed_forms.short_bearing_force and
short_bearing_components, the dynamic and the steady closed forms) on a bearing of L/D = 0.05, where the Reynolds
solution approaches it: at each speed the equilibrium eccentricity ratio of the closed form's steady load within 2 %,
and K and C at the solver's equilibrium within 3 % of the largest entry (the tolerance of the solver's own test
against Ocvirk). The film at the reported equilibrium carries the load to 1e-6 of it (a fresh solve).
"""

from __future__ import annotations

import csv
import json
import math

import numpy as np
import pytest
from scipy.optimize import brentq

from bearing_mbs.cli import main
from bearing_mbs.fluid_film import closed_forms
from bearing_mbs.fluid_film.coefficients import dynamic_coefficients
from bearing_mbs.fluid_film.journal import JournalBearing
from bearing_mbs.fluid_film.reynolds import JournalState, solve_film

from no_traceback import toml_document

D, C, MU = 0.05, 35e-6, 0.028
LENGTH = 0.05 * D
SPEEDS_RPM = [1000.0, 3000.0, 10000.0]


def short_load(eps, speed):
    return math.hypot(*closed_forms.short_bearing_components(eps, speed, D / 2, LENGTH, C, MU))


@pytest.fixture(scope="module")
def solved(tmp_path_factory):
    load = short_load(0.5, 3000 * math.pi / 30)
    scenario = {"scenario": {"name": "short_plain", "model": "journal_bearing", "end_time": 1.0},
                "journal": {"diameter": D, "length": LENGTH, "radial_clearance": C, "viscosity": MU,
                            "speed_rpm": 3000.0, "eccentricity_ratio": 0.5, "grid": [240, 20],
                            "coefficient_speeds_rpm": SPEEDS_RPM, "static_load": [0.0, -load]}}
    folder = tmp_path_factory.mktemp("speeds")
    (folder / "short.toml").write_text(toml_document(scenario))
    assert main(["journal", str(folder / "short.toml"), "--out", str(folder / "out")]) == 0
    return load, json.loads((folder / "out" / "summary.json").read_text()), folder / "out"


def test_the_equilibria_and_coefficients_follow_the_short_bearing(solved):
    load, summary, _ = solved
    bearing = JournalBearing(D, LENGTH, C, MU)
    for row in summary["coefficients_over_speed"]:
        speed = row["speed_rpm"] * math.pi / 30
        expected = brentq(lambda eps, speed=speed: short_load(eps, speed) - load, 1e-6, 0.999)
        assert row["eccentricity_ratio"] == pytest.approx(expected, rel=0.02), row["speed_rpm"]
        state = JournalState(tuple(row["eccentricity"]), (0.0, 0.0), speed)
        force = solve_film(bearing, state, grid=(240, 20)).force
        assert np.abs(force + [0.0, -load]).max() < 1e-6 * load

        def closed(s):
            return np.array(closed_forms.short_bearing_force(*s.eccentricity, *s.eccentricity_rate, s.speed, D / 2,
                                                             LENGTH, C, MU))

        stiffness, damping = dynamic_coefficients(closed, state, C)
        assert np.abs(np.array(row["stiffness"]) - stiffness).max() < 0.03 * np.abs(stiffness).max()
        assert np.abs(np.array(row["damping"]) - damping).max() < 0.03 * np.abs(damping).max()


def test_the_table_and_the_figure_are_written(solved):
    _, summary, out = solved
    with open(out / "coefficients.csv") as handle:
        rows = list(csv.DictReader(handle))
    assert [float(row["speed_rpm"]) for row in rows] == SPEEDS_RPM
    assert float(rows[0]["kxx"]) == pytest.approx(summary["coefficients_over_speed"][0]["stiffness"][0][0])
    assert (out / "coefficients.png").stat().st_size > 10_000
    assert summary["status"] == "success"
