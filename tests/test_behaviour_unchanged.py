"""The code keeps its behaviour: fixed runs replayed through the command line against the record
(``tests/behaviour/record.py``; reference: the package as it was recorded, last at commit f36a354, itself checked
against the independent earlier implementation of commit c03eb40).

The comparison holds on every machine (``tests/behaviour/README.md``: the rule and the figures measured on
simulated CPUs, ``tests/behaviour/compare.py``: the rule in code). Each float is held to RTOL = 1e-6 of the scale
of its kind in the run (a force to the run's largest force or load, a position to the bearing's size, a time to the
end time), plus one unit in the last digit a summary writes; text, structure, which values are NaN and the counts
of runs that decide nothing on computed values are exact; the counts of Newton's method and step control within 2 %.

Two more tests hold the rule itself to account: a perturbation of one unit in the last place of an input of each
run whose rounding differences grow (cases 3 and 5, the start-up of the penalty-cage bearing on both engines) stays
within the tolerance over the recorded window, so that window ends before the run's horizon; and a physical change
of 1e-5 of the load fails the comparison, so the tolerance still catches a real change.
Re-record (one command: ``python tests/behaviour/record.py [NAME ...]``) only when the numbers change on purpose.
"""

from __future__ import annotations

import math
import sys
import tomllib
from pathlib import Path

import numpy as np
import pytest

sys.path.insert(0, str(Path(__file__).parent / "behaviour"))
import compare
import record

#: run -> scenario key whose next float up is the rounding-level probe: the runs whose rounding differences grow
#: (case 3 on the dead zone's edge, case 5 through its constraint's projection, the start-up through stick-slip).
ONE_ULP = {
    "seed_case3": "balls.0.position.1",
    "seed_case5": "balls.0.position.1",
    "hss_startup_reference": "load.radial",
    "hss_startup_exudyn": "load.radial",
}
#: run -> scenario key changed by :data:`PHYSICAL_CHANGE` (relative): a real change the comparison must catch.
MUTATIONS = {"stiffness": "load.radial", "hss_steady_reference": "load.radial"}
PHYSICAL_CHANGE = 1e-5


def _scenario_value(name: str, key: str) -> float:
    node = tomllib.loads((record.SCENARIOS / record.RUNS[name][1]).read_text())
    for part in key.split("."):
        node = node[int(part)] if isinstance(node, list) else node[part]
    return float(node)


def _deviations(name: str, directory: Path, extra: tuple[str, ...] = ()) -> list[compare.Deviation]:
    summary, arrays = record.execute(name, directory, extra)
    return compare.compare(summary, arrays, *record.recorded(name))


def _table(deviations: list[compare.Deviation]) -> str:
    return "\n".join(f"{d.where} [{d.unit}]: {d.difference:.3g} against {d.tolerance:.3g} ({d.ratio:.3g}x)"
                     for d in sorted(deviations, key=lambda d: -d.ratio)[:12])


@pytest.mark.parametrize("name", list(record.RUNS))
def test_numbers_match_the_record(name, tmp_path):
    deviations = _deviations(name, tmp_path)
    beyond = [d for d in deviations if d.ratio > 1.0]
    assert not beyond, f"{name} moved beyond rounding:\n{_table(beyond)}"


@pytest.mark.parametrize("name", list(ONE_ULP))
def test_a_one_ulp_perturbation_stays_within_the_tolerance(name, tmp_path):
    key = ONE_ULP[name]
    value = math.nextafter(_scenario_value(name, key), math.inf)
    deviations = _deviations(name, tmp_path, ("--set", f"{key}={value!r}"))
    assert any(d.difference > 0.0 for d in deviations), f"{name}: the perturbation of {key} changed nothing"
    beyond = [d for d in deviations if d.ratio > 1.0]
    assert not beyond, f"{name}: one ulp of {key} grew beyond the tolerance within the window:\n{_table(beyond)}"


@pytest.mark.parametrize("name", list(MUTATIONS))
def test_a_physical_change_fails_the_comparison(name, tmp_path):
    key = MUTATIONS[name]
    value = _scenario_value(name, key) * (1.0 + PHYSICAL_CHANGE)
    deviations = _deviations(name, tmp_path, ("--set", f"{key}={value!r}"))
    assert max(d.ratio for d in deviations) > 1.0, f"{name}: {key} x (1 + {PHYSICAL_CHANGE}) went unnoticed"


def test_a_force_is_compared_on_the_scale_of_the_run():
    """The issue's example: on a 68 kN load, a residual of 1.75e-10 N where 1.89e-10 N was recorded and a load
    component of 8.2e-12 N for 1.7e-12 N are rounding; 1 N on that load is not (1e-6 of 68 kN is 0.068 N)."""
    expected, arrays = record.recorded("stiffness")
    scale = compare.scales(expected, arrays)
    assert scale["N"] >= expected["applied_radial_load"]
    moved = {**expected, "residual": 1.7466929e-10, "load": [8.1854523e-12, expected["load"][1]]}
    assert all(d.ratio <= 1.0 for d in compare.compare_summary(moved, expected, scale))
    moved["residual"] = 1.0
    assert max(d.ratio for d in compare.compare_summary(moved, expected, scale)) > 1.0


def test_exact_entries_stay_exact():
    """Text, structure, NaN and the counts of a fixed-step explicit run admit no difference at all."""
    expected, arrays = record.recorded("hss_steady_reference")
    scale = compare.scales(expected, arrays)
    for changed in ({**expected, "status": "suspect"}, {**expected, "steps": expected["steps"] + 1},
                    {**expected, "scene": {**expected["scene"], "pairs": 90}},
                    {k: v for k, v in expected.items() if k != "cage_slip"}):
        with pytest.raises(compare.Mismatch):
            compare.compare_summary(changed, expected, scale)
    events = arrays["events"].copy()
    events[np.isnan(events)] = 0.0  # events that never happened now have
    with pytest.raises(compare.Mismatch):
        compare.compare_arrays({**arrays, "events": events}, arrays, scale)


def test_a_solvers_counts_may_move_by_one_decision():
    """Exudyn's generalized-alpha decides on computed values (Newton's test, step halving): one flipped decision
    passes, a change of its cost by a tenth does not."""
    expected, arrays = record.recorded("hss_steady_exudyn")
    scale = compare.scales(expected, arrays)
    compare.compare_summary({**expected, "newton_iterations": expected["newton_iterations"] + 1}, expected, scale)
    compare.compare_summary({**expected, "steps": expected["steps"] + 1}, expected, scale)
    with pytest.raises(compare.Mismatch):
        compare.compare_summary({**expected, "force_evaluations": round(expected["force_evaluations"] * 1.1)},
                                expected, scale)
