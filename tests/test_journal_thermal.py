"""The journal film at its effective temperature (``journal.thermal = "effective"``, docs/fluid-film.md).

References (none from the code under test):
* the heat balance itself, from the summary's own outputs: ρ(T_in) c_p Q ΔT equals the friction power P_f, and the
  effective temperature is the mean of inlet and outlet (Raimondi and Boyd's effective-temperature method), to 1e-6;
* the film at the effective viscosity: an isothermal run of the same bearing at that viscosity and the inlet density
  gives the same load, friction and flow (1e-6);
* ASTM D341's Walther line through the oil's two points, written out here: the effective viscosity is its value at
  the effective temperature (1e-7: the summary keeps 8 digits);
* physics: a warmer inlet gives a thinner oil and a smaller rise; an isothermal film at the inlet viscosity carries
  more (the oil thins as it warms).
"""

from __future__ import annotations

import json
import math
from pathlib import Path

import pytest

from bearing_mbs.cli import main

from cases import SCENARIOS

THERMAL = str(SCENARIOS / "seed_hybrid_journal_thermal.toml")
OIL = {"viscosity_40": 32e-6, "viscosity_100": 5.4e-6, "density_15": 870.0, "thermal_expansion": 6.4e-4,
       "specific_heat": 2000.0}


def run(tmp_path, *overrides, code=0, name="out"):
    out = tmp_path / name
    sets = [argument for override in overrides for argument in ("--set", override)]
    assert main(["journal", THERMAL, "--out", str(out), "--no-figures", *sets]) == code
    return json.loads((out / "summary.json").read_text())


def density(temperature):
    return OIL["density_15"] * (1 - OIL["thermal_expansion"] * (temperature - 15.0))


def walther_viscosity(temperature):
    """η = ρν [Pa s], with log10 log10(ν + 0.7) = A − B log10 T (ν in mm²/s, T in K) through 40 and 100 °C."""
    x = [math.log10(t + 273.15) for t in (40.0, 100.0)]
    y = [math.log10(math.log10(nu * 1e6 + 0.7)) for nu in (OIL["viscosity_40"], OIL["viscosity_100"])]
    slope = (y[1] - y[0]) / (x[1] - x[0])
    nu = 10 ** (10 ** (y[0] + slope * (math.log10(temperature + 273.15) - x[0]))) - 0.7
    return density(temperature) * nu * 1e-6


def test_the_heat_balance_closes_at_the_effective_temperature(tmp_path):
    summary = run(tmp_path)
    assert summary["status"] == "success"
    inlet = summary["inlet_temperature"]
    carried = density(inlet) * OIL["specific_heat"] * summary["flow"] * summary["temperature_rise"]
    assert carried == pytest.approx(summary["friction_power"], rel=1e-6)
    assert summary["effective_temperature"] == pytest.approx(inlet + summary["temperature_rise"] / 2, abs=1e-6)
    assert summary["effective_viscosity"] == pytest.approx(walther_viscosity(summary["effective_temperature"]),
                                                           rel=1e-7)
    assert summary["inlet_viscosity"] == pytest.approx(walther_viscosity(inlet), rel=1e-7)


def test_the_film_is_the_isothermal_film_at_the_effective_viscosity(tmp_path):
    effective = run(tmp_path)
    isothermal = run(tmp_path, "journal.thermal='isothermal'", name="iso")
    # the same bearing given by its viscosity instead of its oil: every [journal.oil] key must go
    fixed = tmp_path / "fixed.toml"
    original = Path(THERMAL).read_text()
    text = original.split("[journal.oil]")[0] + "[journal.recesses]" + original.split("[journal.recesses]")[1]
    fixed.write_text(text.replace('thermal = "effective"', f'thermal = "isothermal"\nviscosity = '
                                  f'{effective["effective_viscosity"]!r}\ndensity = {density(40.0)!r}'))
    out = tmp_path / "at_effective"
    assert main(["journal", str(fixed), "--out", str(out), "--no-figures"]) == 0
    at_effective = json.loads((out / "summary.json").read_text())
    for key in ("load_capacity", "friction_power", "flow"):
        assert at_effective[key] == pytest.approx(effective[key], rel=1e-6), key
    assert isothermal["load_capacity"] > effective["load_capacity"]
    assert isothermal["friction_power"] > effective["friction_power"]


def test_a_warmer_inlet_thins_the_oil_and_rises_less(tmp_path):
    cool, warm = run(tmp_path, name="cool"), run(tmp_path, "journal.oil.inlet_temperature=60.0", name="warm")
    assert warm["effective_viscosity"] < cool["effective_viscosity"]
    assert warm["temperature_rise"] < cool["temperature_rise"]


def test_a_film_hotter_than_the_oils_fit_fails_and_says_why(tmp_path):
    """Inlet at 118 °C, 20 000 rpm: the balance passes 120 °C, the top of the viscosity fit: failed, exit 1."""
    summary = run(tmp_path, "journal.oil.inlet_temperature=118.0", "journal.speed_rpm=20000", code=1)
    assert summary["status"] == "failed" and "120" in summary["message"]


@pytest.mark.parametrize("overrides, field", [
    (["journal.viscosity=0.028"], "journal.viscosity"),
    (["journal.oil.inlet_temperature=150.0"], "journal.oil.inlet_temperature"),
    (["journal.oil.specific_heat=0"], "journal.oil.specific_heat"),
    (["journal.thermal='adiabatic'"], "journal.thermal"),
])
def test_bad_thermal_input_is_refused(overrides, field, tmp_path, capsys):
    out = tmp_path / "out"
    sets = [argument for override in overrides for argument in ("--set", override)]
    assert main(["journal", THERMAL, "--out", str(out), *sets]) == 2
    assert not out.exists()
    assert capsys.readouterr().err.strip().splitlines()[-1].startswith(f"error: {field} = ")


def test_effective_needs_an_oil_and_a_flow(tmp_path, capsys):
    seed = str(SCENARIOS / "seed_hybrid_journal.toml")
    assert main(["journal", seed, "--out", str(tmp_path / "a"), "--set", "journal.thermal='effective'"]) == 2
    assert capsys.readouterr().err.strip().splitlines()[-1].startswith("error: journal.thermal = ")
