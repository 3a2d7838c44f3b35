"""The rule a replay of the behaviour record is held to (``README.md`` in this folder: the rule, its scales and
the figures measured on simulated machines behind each number).

Compiled kernels (numba/LLVM), libm and LAPACK/OpenBLAS round differently on different CPUs, so a replay on
another machine moves the numbers by rounding; a real change of the code or the physics moves them by more. Every
float is therefore held to a tolerance on the physical scale of its kind in that run:

    |replayed - recorded| <= RTOL * scale(unit) + one unit in the last written digit (summaries only)

* ``unit`` is the quantity's unit: a summary names it in its ``units`` map (``"angle_deg: deg, load_N: N"`` for
  the fields of a list of records), each check in its ``unit`` field, a result array's column in
  :func:`column_units`. A float without a unit is an error: it cannot be compared physically.
* ``scale(unit)`` is the largest magnitude of that unit in the recorded run, summary and arrays together (the
  bearing's size for positions, the load or the largest contact force for forces, the end time for times), at
  least its floor (:data:`NATURAL_SCALES`: 1 for a ratio, a turn for an angle; a force at least the run's energy
  over its size, :func:`scales`). A residual of 1e-10 N on a 68 kN load is zero on this scale.
* a summary writes :data:`~bearing_mbs.io.json.DIGITS` significant digits, so a rounding difference can change
  the last one: one unit in it is allowed on top.

Exact, because the arithmetic is reproducible by construction (integers, text, structure, no floating point):
the key sets, text (status, message, names, verdicts), array shapes, and the counts of a run that takes no decision
on a computed value (a fixed-step explicit method: its steps and force evaluations follow from the end time and the
step by integer arithmetic; the scene's counts; the exit code). The counts of a run that does decide on computed values (Newton's
convergence test, a step-size controller, an iterative static solve: :data:`ADAPTIVE_COUNTS`) may move by one
decision when rounding puts a test value within rounding of its threshold, so they are held to
:data:`ADAPTIVE_COUNT_RTOL`. Which values are NaN or null (events that never happened, angles no roller visited) is
exact too: a physical outcome that rounding could flip only for a pair grazing within rounding of contact (none in
the recorded windows).
"""

from __future__ import annotations

import math
from collections import defaultdict
from dataclasses import dataclass

import numpy as np

from bearing_mbs.contact.kernel import PAIR_OUTPUTS
from bearing_mbs.contact.state import EVENT_COLUMNS
from bearing_mbs.io.json import DIGITS
from bearing_mbs.spec.solver import EXUDYN_ADAPTIVE, EXUDYN_IMPLICIT, REFERENCE_ADAPTIVE, REFERENCE_IMPLICIT

#: Tolerance of every float, relative to the scale of its kind in the run. Rounding-level for these runs (README.md):
#: explicit steps of 1e-7 s resolve a velocity to ulp(position)/step only, and one ulp of case 5's initial height
#: moves its velocities by 5.3e-8 of their scale; the largest deviation on a simulated CPU is 0.066 × RTOL (the
#: start-up on Exudyn, glibc's libm without FMA). A change of 1e-5 of the load fails by 10×.
RTOL = 1e-6
#: Counts of decisions taken on computed values (Newton's test, the step controller, a static solve's
#: iterations), held to this fraction of the recorded count (at least one): one flipped Newton test is one
#: iteration, one extra numerical Jacobian 2n + 1 force evaluations (103 of the seed bearing's 9267), one halved
#: step a few steps of 400; a change of the method's cost (Jacobian reuse, step control) moves them by tens of %.
ADAPTIVE_COUNT_RTOL = 0.02
#: Summary counts that follow a solver's decisions (the others, e.g. the scene's, are exact).
ADAPTIVE_COUNTS = ("steps", "rejected_steps", "force_evaluations", "newton_iterations", "jacobian_evaluations",
                   "iterations")
#: Methods whose counts follow decisions on computed values (a summary without ``solver``, e.g. ``stiffness``'s
#: static Newton solve, is treated as deciding too).
DECIDING_METHODS = frozenset((*REFERENCE_ADAPTIVE, *REFERENCE_IMPLICIT, *EXUDYN_ADAPTIVE, *EXUDYN_IMPLICIT))

#: The natural scale of a kind that has one, a floor under its largest recorded magnitude: a ratio's is 1 (all of
#: it), an angle's a turn (an angle is used modulo a turn; a rotation that has not started has no other scale).
NATURAL_SCALES = {"-": 1.0, "rad": 2.0 * math.pi, "deg": 360.0}
#: Units of the result arrays' columns (``bearing_mbs.core.result.Result``): per body (x, y, θ) and (vx, vy, ω);
#: per pair the kernel's outputs; per constraint its force; the work supplied and dissipated; per pair its events.
BODY_POSITION_UNITS = ("m", "m", "rad")
BODY_VELOCITY_UNITS = ("m/s", "m/s", "rad/s")
PAIR_OUTPUT_UNITS = {"gap": "m", "gap_rate": "m/s", "slip": "m/s", "normal_force": "N", "friction_force": "N",
                     "rolling_moment": "N m", "power_loss": "W", "rolling_speed": "m/s"}
EVENT_UNITS = {"impact_time": "s", "impact_speed": "m/s", "separation_time": "s", "separation_speed": "m/s"}
assert tuple(PAIR_OUTPUT_UNITS) == PAIR_OUTPUTS, "the kernel's outputs changed: give each its unit here"
assert tuple(EVENT_UNITS) == EVENT_COLUMNS, "the event columns changed: give each its unit here"


def column_units(key: str, array: np.ndarray) -> np.ndarray:
    """The unit of each entry of result array ``key``, broadcastable against it."""
    width = array.shape[-1] if array.ndim > 1 else 1
    if key == "time":
        return np.array("s")
    if key == "position":
        return np.array(BODY_POSITION_UNITS * (width // 3))
    if key == "velocity":
        return np.array(BODY_VELOCITY_UNITS * (width // 3))
    if key == "pair_output":
        return np.array(list(PAIR_OUTPUT_UNITS.values()))
    if key == "constraint_forces":
        return np.array("N")
    if key == "work":
        return np.array("J")
    if key == "events":
        return np.array(list(EVENT_UNITS.values()))
    raise KeyError(f"result array {key!r} has no units here: add them to {__name__}.column_units")


class Mismatch(AssertionError):
    """A difference no rounding can make: a key, a text, a shape, a NaN, an exact count."""


@dataclass(frozen=True)
class Deviation:
    """The largest difference of one quantity (a summary entry or an array's unit) and what it is allowed."""

    where: str
    unit: str
    difference: float
    tolerance: float

    @property
    def ratio(self) -> float:
        """difference / tolerance: above 1 fails."""
        if self.difference == 0.0:
            return 0.0
        return self.difference / self.tolerance if self.tolerance > 0.0 else math.inf


def _field_units(text: str) -> dict[str, str]:
    """``"angle_deg: deg, load_N: N"`` → {"angle_deg": "deg", "load_N": "N"}."""
    return {part.split(":")[0].strip(): part.split(":")[1].strip() for part in text.split(",")}


def summary_leaves(summary: dict, path: str = ""):
    """(path, value, unit) of every leaf of a summary: ``unit`` from its ``units`` map (or a check's own ``unit``),
    None where it has none (text, the scene's counts, the exit code)."""
    units = summary.get("units", {})

    def walk(value, where, unit):
        if isinstance(value, dict):
            fields = _field_units(unit) if isinstance(unit, str) and ":" in unit else {}
            if "unit" in value and "verdict" in value:  # a check: its value and bound are in its own unit
                fields = {"value": value["unit"], "bound": value["unit"]}
            for key, item in value.items():
                yield from walk(item, f"{where}.{key}", fields.get(key))
        elif isinstance(value, list):
            for i, item in enumerate(value):
                yield from walk(item, f"{where}[{i}]", unit)
        else:
            yield where, value, unit

    for key, value in summary.items():
        yield from walk(value, f"{path}{key}", None if key == "units" else units.get(key))


def scales(summary: dict, arrays: dict[str, np.ndarray]) -> dict[str, float]:
    """The scale of each unit in a recorded run: the largest finite magnitude of that unit in its summary and
    arrays, at least :data:`NATURAL_SCALES`, and

    * a force at least the run's energy over its size (J / m: the weight of bodies that fall freely, where the
      only recorded force, a distance constraint's, is a rounding residue of zero);
    * a power at least the force scale times the speed scale: a pair's power loss is a friction force times a
      slip speed, so its rounding error is either factor's times the other's scale (the largest recorded power
      is far smaller: the large forces roll, the large slips carry little force). Its factors are compared on
      their own scales.
    """
    largest: dict[str, float] = defaultdict(float)
    for _, value, unit in summary_leaves(summary):
        if isinstance(value, (int, float)) and not isinstance(value, bool) and unit and unit != "count":
            largest[unit] = max(largest[unit], abs(value))
    for key, array in arrays.items():
        units = np.broadcast_to(column_units(key, array), array.shape)
        for unit in np.unique(units):
            values = np.abs(array[(units == unit) & np.isfinite(array)])
            if values.size:
                largest[str(unit)] = max(largest[str(unit)], float(values.max()))
    for unit, floor in NATURAL_SCALES.items():
        largest[unit] = max(largest[unit], floor)
    if largest["m"] > 0.0:
        largest["N"] = max(largest["N"], largest["J"] / largest["m"])
    largest["W"] = max(largest["W"], largest["N"] * largest["m/s"])
    return dict(largest)


def last_digit(value: float) -> float:
    """One unit in the last of the :data:`DIGITS` significant digits a summary writes ``value`` with."""
    return 10.0 ** (math.floor(math.log10(abs(value))) - DIGITS + 1) if value else 0.0


def _adaptive(summary: dict) -> bool:
    return summary.get("solver") is None or summary["solver"] in DECIDING_METHODS


def compare_summary(actual: dict, expected: dict, scale: dict[str, float]) -> list[Deviation]:
    """Raise :class:`Mismatch` on an exact difference; return the deviation of every float entry."""
    found = {where: (value, unit) for where, value, unit in summary_leaves(actual)}
    wanted = list(summary_leaves(expected))
    if set(found) != {where for where, _, _ in wanted}:
        raise Mismatch(f"entries differ: only replayed {sorted(set(found) - {w for w, _, _ in wanted})}, "
                       f"only recorded {sorted({w for w, _, _ in wanted} - set(found))}")
    deciding = _adaptive(expected)
    deviations = []
    for where, e, unit in wanted:
        a = found[where][0]
        number = isinstance(e, (int, float)) and not isinstance(e, bool)
        if unit == "count" or (number and isinstance(e, int) and unit is None):
            if deciding and where.split(".")[-1] in ADAPTIVE_COUNTS:
                allowed = max(1, math.floor(ADAPTIVE_COUNT_RTOL * abs(e)))
                if not isinstance(a, int) or abs(a - e) > allowed:
                    raise Mismatch(f"{where}: {a!r} against {e!r} (a solver's count, ±{allowed} allowed)")
            elif a != e or type(a) is not type(e):
                raise Mismatch(f"{where}: {a!r} against {e!r} (an exact count)")
        elif number:
            if unit is None:
                raise Mismatch(f"{where}: the float {e!r} has no unit; give it one in the summary's units map")
            if not isinstance(a, (int, float)) or isinstance(a, bool):
                raise Mismatch(f"{where}: {a!r} against {e!r}")
            tolerance = RTOL * scale.get(unit, 0.0) + last_digit(e)
            deviations.append(Deviation(where, unit, abs(a - e), tolerance))
        elif a != e:
            raise Mismatch(f"{where}: {a!r} against {e!r} (text, structure or null: exact)")
    return deviations


def compare_arrays(actual: dict[str, np.ndarray], expected: dict[str, np.ndarray],
                   scale: dict[str, float]) -> list[Deviation]:
    """Raise :class:`Mismatch` on a shape or NaN difference; return the largest deviation of each array's units."""
    if set(actual) != set(expected):
        raise Mismatch(f"arrays differ: {sorted(actual)} against {sorted(expected)}")
    deviations = []
    for key, e in expected.items():
        a = actual[key]
        if a.shape != e.shape:
            raise Mismatch(f"{key}: shape {a.shape} against {e.shape}")
        finite = np.isfinite(e)
        if not np.array_equal(np.isfinite(a), finite) or not np.array_equal(a[~finite], e[~finite], equal_nan=True):
            raise Mismatch(f"{key}: NaN or inf at {np.argwhere(np.isfinite(a) != finite)[:5].tolist()} (events "
                           "that happened in one run only, or samples missing)")
        units = np.broadcast_to(column_units(key, e), e.shape)
        for unit in np.unique(units):
            chosen = (units == unit) & finite
            if not chosen.any():
                continue
            difference = float(np.abs(a[chosen] - e[chosen]).max())
            deviations.append(Deviation(key, str(unit), difference, RTOL * scale.get(str(unit), 0.0)))
    return deviations


def compare(actual_summary: dict, actual_arrays: dict[str, np.ndarray], expected_summary: dict,
            expected_arrays: dict[str, np.ndarray]) -> list[Deviation]:
    """Every deviation of a replay from its record (raises :class:`Mismatch` on an exact difference)."""
    scale = scales(expected_summary, expected_arrays)
    return [*compare_summary(actual_summary, expected_summary, scale),
            *compare_arrays(actual_arrays, expected_arrays, scale)]


def worst_by_unit(deviations: list[Deviation]) -> dict[str, Deviation]:
    """The deviation of largest ratio for each unit."""
    worst: dict[str, Deviation] = {}
    for deviation in deviations:
        if deviation.unit not in worst or deviation.ratio > worst[deviation.unit].ratio:
            worst[deviation.unit] = deviation
    return worst
