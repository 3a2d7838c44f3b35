"""The checks a finished run is held to, as data: the reasons a run that reached its end is ``suspect``.

A run's status (:attr:`bearing_mbs.core.result.Result.status`) is ``success`` only when the engine reached the end
time and every check passed. Each check carries the measured value and the bound it was held to, so a summary or
a sweep shows why a run is suspect without reading its log (docs/status.md lists the checks and their bounds).
"""

from __future__ import annotations

import math
from dataclasses import asdict, dataclass

PASS, FAIL = "pass", "fail"


@dataclass(frozen=True)
class Check:
    """One check: ``name``; ``value`` measured and ``bound`` it is held to (numbers or None, in the units of
    ``unit``); ``verdict`` ``pass`` or ``fail``; ``detail``: what a failure means and its likely fix."""

    name: str
    value: float | None
    bound: float | None
    verdict: str
    unit: str = "-"
    detail: str = ""

    def __post_init__(self):
        if self.verdict not in (PASS, FAIL):
            raise ValueError(f"check {self.name!r}: verdict must be {PASS!r} or {FAIL!r}, got {self.verdict!r}")

    @property
    def passed(self) -> bool:
        return self.verdict == PASS

    def to_dict(self) -> dict:
        return asdict(self)

    @classmethod
    def from_dict(cls, data: dict) -> Check:
        return cls(**data)

    def line(self) -> str:
        """One line for a terminal: verdict, name, value against bound, and the detail of a failure."""
        def number(x):
            return "-" if x is None else f"{x:.3g}"

        text = f"{self.verdict.upper():4} {self.name}: {number(self.value)} (bound {number(self.bound)} {self.unit})"
        return f"{text}: {self.detail}" if self.detail and not self.passed else text


def judged(name: str, value, bound, passed: bool, unit: str = "-", failure: str = "") -> Check:
    """A check with the verdict ``passed``; ``failure`` (what it means, the likely fix) is kept only on a fail."""
    return Check(name, value, bound, PASS if passed else FAIL, unit, "" if passed else failure)


def upper_bound(name: str, value: float | None, bound: float, unit: str = "-", failure: str = "") -> Check:
    """A check that ``value`` ≤ ``bound`` (a missing or non-finite value fails)."""
    return judged(name, value, bound, value is not None and math.isfinite(value) and value <= bound, unit, failure)


def lower_bound(name: str, value: float | None, bound: float, unit: str = "-", failure: str = "") -> Check:
    """A check that ``value`` ≥ ``bound`` (a missing or non-finite value fails)."""
    return judged(name, value, bound, value is not None and math.isfinite(value) and value >= bound, unit, failure)


#: Largest force residual of a quasi-static equilibrium, relative to the load it carries [-]: a millionth, far below
#: what the quasi-static models leave out (the seed bearing's roller weights, 2 N each on 68 kN, are 3e-5 of it).
EQUILIBRIUM_RESIDUAL_BOUND = 1e-6


def equilibrium_residual(relative_residual: float, failure: str = "") -> Check:
    """The ``equilibrium_residual`` check of a quasi-static solution: its force residual relative to the load [-]
    at most :data:`EQUILIBRIUM_RESIDUAL_BOUND` (the solver converged to an equilibrium)."""
    return upper_bound("equilibrium_residual", relative_residual, EQUILIBRIUM_RESIDUAL_BOUND, "-", failure)
