"""Every range a value is refused for carries its unit: "[-10, 120]" alone leaves a user guessing between °C and K.
``in_range`` takes the unit as a required argument, so no range can be written without one; these cases check that
the unit reaches the message a user reads, for a field of each kind of unit."""

from __future__ import annotations

import pytest

from bearing_mbs.models import load_spec
from bearing_mbs.spec import SpecError
from bearing_mbs.spec.fields import in_range

from cases import SCENARIOS


@pytest.mark.parametrize("scenario, override, field, unit", [
    ("seed_hss_steady.toml", "lubricant.temperature=150", "lubricant.temperature", "°C"),
    ("seed_hss_steady.toml", "bearing.supported_mass=-1", "bearing.supported_mass", "kg"),
    ("seed_hss_steady.toml", "solver.penetration_limit=2", "solver.penetration_limit", "(dimensionless)"),
    ("seed_hybrid_journal.toml", "journal.radial_clearance=1", "journal.radial_clearance", "m"),
    ("seed_hybrid_journal.toml", "journal.eccentricity_ratio=1.5", "journal.eccentricity_ratio", "(dimensionless)"),
    ("seed_rotor_unbalance.toml", "drive.speed_rpm=-5", "drive.speed_rpm", "rpm"),
])
def test_a_range_message_carries_the_fields_unit(scenario, override, field, unit):
    with pytest.raises(SpecError) as refused:
        load_spec(SCENARIOS / scenario, [override])
    assert refused.value.field == field
    assert refused.value.allowed.endswith(unit)


def test_a_range_cannot_be_checked_without_a_unit():
    with pytest.raises(TypeError):
        in_range("x", 0.5, 0.0, 1.0)  # the unit is a required argument
