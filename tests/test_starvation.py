"""Starvation of the raceway contacts (SKF's kinematic replenishment factor) and the pressure–viscosity
coefficient carried over temperature (Roelands' index), by hand from their printed forms."""

from __future__ import annotations

import math

import numpy as np
import pytest

from bearing_mbs.contact import traction
from bearing_mbs.contact.lubricant import PRESETS
from bearing_mbs.models import build_scene
from bearing_mbs.models.cylindrical_roller.build import starvation
from bearing_mbs.models.cylindrical_roller.geometry import BearingGeometry
from bearing_mbs.models.cylindrical_roller.lubrication import replenishment_factor
from bearing_mbs.models.cylindrical_roller.operating_oil import operating_oil
from bearing_mbs.models.loading import load_spec

SCENARIO = "scenarios/seed_hss_steady.toml"


def test_the_replenishment_factor_is_skfs_printed_form():
    """φ_rs = exp(−K_rs ν n (d + D) √(K_Z/(2(D − d)))) with ν in mm²/s, n in rpm, d and D in mm, K_Z = 5.1 (SKF
    General Catalogue 6000 EN, 2005): the seed bearing's 160/310 mm in ISO VG 320 at 60 °C (108 mm²/s), 1500 rpm."""
    nu = PRESETS["iso_vg_320_mineral"].kinematic_viscosity(60.0)
    by_hand = math.exp(-3e-8 * (nu * 1e6) * 1500 * (160 + 310) * math.sqrt(5.1 / (2 * (310 - 160))))
    assert replenishment_factor(3e-8, nu, 1500.0, 0.160, 0.310) == pytest.approx(by_hand, rel=1e-12)
    assert 0.70 < by_hand < 0.78


def test_the_seed_bearing_is_starved_more_in_cold_oil_and_at_speed():
    factors = {}
    for temperature in (40, 60, 80):
        for rpm in (1000, 1800):
            spec = load_spec(SCENARIO, [f"lubricant.temperature={temperature}", f"drive.speed_rpm={rpm}",
                                        "lubricant.starvation=true"])
            factors[temperature, rpm] = starvation(spec, BearingGeometry.from_spec(spec.bearing),
                                                  operating_oil(spec.lubricant))
    assert factors[40, 1800] < factors[40, 1000] < factors[60, 1000] < factors[80, 1000] < 1.0
    assert factors[80, 1800] < factors[80, 1000]
    off = load_spec(SCENARIO, ["lubricant.starvation=false"])
    assert starvation(off, BearingGeometry.from_spec(off.bearing), operating_oil(off.lubricant)) == 1.0


def test_the_factor_scales_the_film_and_the_rolling_force_of_a_raceway_row():
    spec = load_spec(SCENARIO, ["lubricant.starvation=true"])
    scene = build_scene(spec)
    pair = scene.pairs[int(scene.topology.group("inner_race")[0])]
    row = np.array(pair.law.traction)
    factor = row[traction.TRACTION_COLUMNS.index("replenishment")]
    flooded = row.copy()
    flooded[traction.TRACTION_COLUMNS.index("replenishment")] = 1.0
    speed, load = 8.0, 5000.0
    assert traction.ehl_traction(row, 0.01, speed, load, 0.1, 0.01)[1] == pytest.approx(
        factor * traction.ehl_traction(flooded, 0.01, speed, load, 0.1, 0.01)[1], rel=1e-12)
    assert traction.rolling_force(row, speed, load) == pytest.approx(factor * traction.rolling_force(flooded, speed,
                                                                                                      load), rel=1e-12)
    assert 0.5 < factor < 0.9


@pytest.mark.parametrize("oil", sorted(PRESETS))
def test_alpha_over_temperature_is_roelands_initial_slope(oil):
    """α(T) is d ln η/dp at p = 0 of Roelands' ln(η/η0) = (ln η0 + 9.67)[(1 + p/p_r)^z − 1], p_r = 1.96e8 Pa,
    with the index z that the preset's α implies at its temperature, held over temperature (a numerical derivative
    of the printed relation; z of the mineral oils within Roelands' 0.4–0.8)."""
    lubricant = PRESETS[oil]
    z = lubricant.roelands_index()
    assert 0.35 < z < 0.8
    for temperature in (40.0, 60.0, 80.0, 100.0):
        eta = lubricant.dynamic_viscosity(temperature)
        def log_ratio(p, eta=eta):
            return (math.log(eta) + 9.67) * ((1 + p / 1.96e8) ** z - 1)

        step = 1e3
        slope = (log_ratio(step) - log_ratio(-step)) / (2 * step)
        assert lubricant.pressure_viscosity_at(temperature) == pytest.approx(slope, rel=1e-6)
    assert lubricant.pressure_viscosity_at(lubricant.pressure_viscosity_temperature) == lubricant.pressure_viscosity
    assert lubricant.pressure_viscosity_at(40.0) > lubricant.pressure_viscosity_at(100.0)


def test_the_operating_alpha_follows_the_chosen_model():
    constant = load_spec(SCENARIO, ["lubricant.temperature=40"])
    roelands = load_spec(SCENARIO, ["lubricant.temperature=40", "lubricant.pressure_viscosity_model=roelands"])
    assert operating_oil(constant.lubricant).pressure_viscosity == 2.2e-8
    assert operating_oil(roelands.lubricant).pressure_viscosity == roelands.lubricant.lubricant().pressure_viscosity_at(40)
