"""Validation helpers: every error names the field, the value and what is allowed."""

from __future__ import annotations

import math


class SpecError(ValueError):
    """Invalid user input. ``field`` is the dotted path (``contact.wall.stiffness``) once loading adds it."""

    def __init__(self, field: str, value, allowed: str):
        self.field, self.value, self.allowed = field, value, allowed
        super().__init__(f"{field} = {value!r}: {allowed}")

    def within(self, prefix: str) -> SpecError:
        """The same error with the section path prefixed."""
        if not prefix:
            return self
        return SpecError(f"{prefix}.{self.field}" if self.field else prefix, self.value, self.allowed)


def require(condition: bool, field: str, value, allowed: str) -> None:
    if not condition:
        raise SpecError(field, value, allowed)


def finite(field: str, value) -> None:
    require(value is not None and math.isfinite(value), field, value, "must be a finite number")


def positive(field: str, value) -> None:
    finite(field, value)
    require(value > 0, field, value, "must be > 0")


def non_negative(field: str, value) -> None:
    finite(field, value)
    require(value >= 0, field, value, "must be >= 0")


#: How a dimensionless range is marked in a message.
DIMENSIONLESS = "-"


def in_range(field: str, value, low: float, high: float, unit: str, *, low_open=False, high_open=False) -> None:
    """``value`` in the interval from low to high [``unit``; :data:`DIMENSIONLESS` for none]; open or closed at each
    end. The message carries the unit, e.g. "must be in [-10, 120] °C"."""
    finite(field, value)
    above = value > low if low_open else value >= low
    below = value < high if high_open else value <= high
    bracket = f"{'(' if low_open else '['}{low:g}, {high:g}{')' if high_open else ']'}"
    require(above and below, field, value,
            f"must be in {bracket} {'(dimensionless)' if unit == DIMENSIONLESS else unit}")


def one_of(field: str, value, options) -> None:
    require(value in options, field, value, f"must be one of {', '.join(map(str, options))}")
