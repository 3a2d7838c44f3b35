"""The lubricant's viscosity–temperature law (ASTM D341) against published worked examples.

References: an SAE-140 gear oil of 404 cSt at 40 °C and 28 cSt at 100 °C has 132.126 cSt at 60 °C (worked example
of the ASTM D341 equation, olezol.com, "Viscosity at any temperature", given to six digits: 1e-4); an oil of 32 cSt at 40 °C and 5.4 cSt at
100 °C has about 8.5 cSt at 80 °C (a published ASTM D341 calculation sheet, 2 %, rounding of the published value).
"""

from __future__ import annotations

import pytest

from bearing_mbs.contact.lubricant import Lubricant


def test_sae_140_at_60_degrees():
    oil = Lubricant("SAE 140", 404e-6, 28e-6)
    assert oil.kinematic_viscosity(60.0) == pytest.approx(132.126e-6, rel=1e-4)


def test_light_oil_at_80_degrees():
    oil = Lubricant("ISO VG 32", 32e-6, 5.4e-6)
    assert oil.kinematic_viscosity(80.0) == pytest.approx(8.5e-6, rel=0.02)


def test_the_fit_passes_through_its_two_points_and_falls_with_temperature():
    oil = Lubricant("VG 320", 320e-6, 24e-6)
    assert oil.kinematic_viscosity(40.0) == pytest.approx(320e-6, rel=1e-12)
    assert oil.kinematic_viscosity(100.0) == pytest.approx(24e-6, rel=1e-12)
    values = [oil.kinematic_viscosity(t) for t in range(-10, 121, 10)]
    assert all(a > b for a, b in zip(values, values[1:]))


def test_dynamic_viscosity_is_density_times_kinematic():
    oil = Lubricant("VG 320", 320e-6, 24e-6, density_15=900.0, thermal_expansion=6.4e-4)
    assert oil.dynamic_viscosity(70.0) == pytest.approx(900.0 * (1 - 6.4e-4 * 55) * oil.kinematic_viscosity(70.0),
                                                       rel=1e-15)


@pytest.mark.parametrize("temperature", [-20.0, 130.0, float("nan")])
def test_a_temperature_outside_the_fit_is_refused(temperature):
    with pytest.raises(ValueError):
        Lubricant("VG 320", 320e-6, 24e-6).kinematic_viscosity(temperature)


@pytest.mark.parametrize("kwargs", [
    {"viscosity_40": 24e-6, "viscosity_100": 320e-6},
    {"viscosity_40": -1.0, "viscosity_100": 24e-6},
    {"viscosity_40": 320e-6, "viscosity_100": 24e-6, "pressure_viscosity": 1e-7},
    {"viscosity_40": 320e-6, "viscosity_100": 24e-6, "density_15": 100.0},
    {"viscosity_40": 320e-6, "viscosity_100": 24e-6, "temperature_range": (50.0, 40.0)},
])
def test_bad_values_are_refused(kwargs):
    with pytest.raises(ValueError):
        Lubricant("bad", **kwargs)
