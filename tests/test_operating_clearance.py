"""The seed bearing's operating clearance (bearing_mbs.models.cylindrical_roller.clearance), by hand: ISO 5753-1's
group 3 for a 160 mm bore, Lamé's thick ring on a solid shaft for the fit, α ΔT D_pw for the rings' temperature
difference; and the lubricated seed scenarios run at it."""

from __future__ import annotations

import pytest

from bearing_mbs.models.cylindrical_roller import clearance
from bearing_mbs.models.cylindrical_roller.geometry import BearingGeometry
from bearing_mbs.models.loading import load_spec


def test_group_3_of_a_160_mm_bore():
    """ISO 5753-1, cylindrical roller bearings with a cylindrical bore, over 140 up to 160 mm: group 3 is
    115-165 µm, group N 70-120 µm (as SKF's catalogue reproduces the table)."""
    assert clearance.internal_clearance(0.160, "3") == pytest.approx((115e-6, 165e-6))
    assert clearance.internal_clearance(0.160, "N") == pytest.approx((70e-6, 120e-6))
    with pytest.raises(ValueError):
        clearance.internal_clearance(0.300, "3")
    with pytest.raises(ValueError):
        clearance.internal_clearance(0.160, "C7")


def test_the_fit_takes_up_lames_raceway_growth():
    """A ring (bore d, outside F) pressed with diametral interference I on a solid shaft of the same steel: the
    contact pressure p from the two Lamé solutions (shaft: radial shrink p a/E (1 − ν); ring: bore growth
    p a/E [(b² + a²)/(b² − a²) + ν]; together I/2), and the ring's outside growth 2 p a² b/(E (b² − a²))."""
    modulus, poisson, interference, bore, outside = 210e9, 0.3, 55.5e-6, 0.160, 0.210
    a, b = bore / 2, outside / 2
    pressure = (interference / 2) / (a / modulus * ((1 - poisson) + (b * b + a * a) / (b * b - a * a) + poisson))
    growth = 2 * (2 * pressure * a * a * b / (modulus * (b * b - a * a)))
    assert clearance.fit_reduction(interference, bore, outside) == pytest.approx(growth, rel=1e-12)
    assert growth == pytest.approx(42.3e-6, abs=0.1e-6)


def test_the_seed_operating_clearance():
    """140 µm (group 3's middle) − 42.3 µm (p6, +43/+68 µm, at the mean) − 12e-6 × 10 K × 235 mm = 69.5 µm."""
    assert clearance.SEED_OPERATING_CLEARANCE == pytest.approx(140e-6 - 42.3e-6 - 28.2e-6, abs=0.1e-6)


@pytest.mark.parametrize("name", ["seed_hss_steady", "seed_hss_startup", "seed_hss_load_drop",
                                  "seed_hss_emergency_stop", "seed_hss_gear_driven"])
def test_the_lubricated_seed_scenarios_run_at_it_and_the_document_at_zero(name):
    lubricated = load_spec(f"scenarios/{name}.toml")
    assert BearingGeometry.from_spec(lubricated.bearing).clearance == pytest.approx(
        clearance.SEED_OPERATING_CLEARANCE, abs=0.5e-6)
    dry = load_spec(f"scenarios/{name}.toml", ["scenario.variant=dry"])
    assert BearingGeometry.from_spec(dry.bearing).clearance == pytest.approx(0.0, abs=1e-12)
