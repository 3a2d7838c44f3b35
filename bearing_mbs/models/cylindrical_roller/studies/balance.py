"""The bearing's steady skidding balance as a sensitivity study's evaluator (``[study] evaluate =
"skidding_balance"``): a sample of a lubricated bearing scenario is one point of the skidding map
(:func:`.skidding_map.point`: the quasi-static balance of
:func:`bearing_mbs.models.cylindrical_roller.steady_skidding.solve_skidding`) instead of a run."""

from __future__ import annotations

from bearing_mbs.models.cylindrical_roller.studies.skidding_map import COLUMNS, check_grid, point
from bearing_mbs.models.protocol import SteadyBalance

#: Units of the numbers a skidding-balance point reports (the columns of
#: :data:`.skidding_map.COLUMNS` but its status, message and checks): the point's inputs, the steady slips
#: (fractions), the raceways' frictional power intensity and the losses.
BALANCE_UNITS = {
    "speed_rpm": "rpm",
    "temperature": "°C",
    "clearance": "m",
    "radial_load": "N",
    "total_load": "N",
    "cage_slip": "-",
    "max_roller_slip_loaded": "-",
    "max_roller_slip_unloaded": "-",
    "max_inner_slide_to_roll": "-",
    "max_frictional_power_intensity": "W/mm²",
    "max_frictional_power_intensity_inner": "W/mm²",
    "max_frictional_power_intensity_outer": "W/mm²",
    "friction_torque": "N m",
    "power_loss": "W",
    "land_torque": "N m",
    "wall_time_s": "s",
}
#: The skidding map's columns that are not numbers.
BALANCE_TEXT_COLUMNS = ("status", "message", "checks")


def check(services, spec) -> None:
    """Raise :class:`bearing_mbs.spec.SpecError` unless ``spec`` is a caged bearing with a lubricant temperature,
    at constant speed and load (:func:`.skidding_map.check_grid`)."""
    check_grid(services, spec, [spec.load.radial], [spec.lubricant.temperature], [spec.drive.speed_rpm])


def evaluate(services, spec) -> dict:
    """The skidding map's row at the spec's speed, oil temperature and load, with the units of its numbers."""
    row, _ = point(services, spec, spec.drive.speed_rpm, spec.lubricant.temperature, spec.load.radial)
    row["units"] = {key: BALANCE_UNITS[key] for key in row if key in BALANCE_UNITS}
    return row


#: The bearing's steady balance (:class:`~bearing_mbs.models.protocol.SteadyBalance`).
STEADY_BALANCE = SteadyBalance(check=check, evaluate=evaluate,
                               outputs=tuple(column for column in COLUMNS if column not in BALANCE_TEXT_COLUMNS),
                               units=BALANCE_UNITS)
