"""The checks every finished run is held to (docs/status.md): a run that reached its end is ``success`` only if
all pass, ``suspect`` otherwise.

* ``end_time_reached``: the last output instant is the end time [s] (an engine that stops short without saying
  so truncates the run);
* ``output_instants``: every requested output instant was recorded [count];
* ``step_limit``: a fixed explicit step [s] at or below the step advisor's stability limit (only where a limit
  applies: :func:`bearing_mbs.numerics.advisor.step_against_limit`);
* ``energy_audit``: the energy balance error [-] at or below :data:`bearing_mbs.analysis.ENERGY_AUDIT_BOUND`;
* ``guard_warnings``: the model's warnings (a cage that left its rollers, say) [count], none allowed.

``spurious_slip`` is added by the commands that refine the step to look for it (``run --check-slip``,
``advise --check-slip``). Every fix that changes the step quotes the run's one step advice
(:func:`bearing_mbs.numerics.advisor.step_advice`), so following it passes the ``step_limit`` check.
"""

from __future__ import annotations

from bearing_mbs.analysis import ENERGY_AUDIT_BOUND, energy_balance_error
from bearing_mbs.core.checks import Check, judged, upper_bound
from bearing_mbs.core.result import Result
from bearing_mbs.core.scene import Scene
from bearing_mbs.engines.diagnosis import output_grid
from bearing_mbs.numerics.advisor import step_advice, step_against_limit
from bearing_mbs.spec.solver import SolverSpec

#: A run reached its end time when its last output instant is within this fraction of it.
END_TIME_TOLERANCE = 1e-9


def run_checks(scene: Scene, solver: SolverSpec, end_time: float, result: Result,
               warnings: list[str] = ()) -> tuple[Check, ...]:
    """The checks of a run that reached its end (none for a run that stopped early: its failure says why)."""
    if not result.completed:
        return ()
    last = float(result.time[-1]) if result.time.size else 0.0
    expected = output_grid(end_time, solver.output_interval).size
    advice = step_advice(scene, solver).text()
    checks = [
        judged("end_time_reached", last, end_time, last >= end_time * (1 - END_TIME_TOLERANCE), "s",
               f"the engine stopped at t = {last:.6g} s without an error, short of the end time {end_time:g} s. "
               f"Likely fix: a step well below the end time and the output interval: {advice}"),
        judged("output_instants", result.time.size, expected, result.time.size == expected, "count",
               f"{result.time.size} of {expected} output instants were recorded. Likely fix: a step at most the "
               f"output interval ({solver.output_interval:g} s): {advice}"),
    ]
    step = step_against_limit(scene, solver)
    if step is not None:
        checks.append(upper_bound("step_limit", step.step, step.limit, "s",
                                  f"above the advised stability limit (set by {step.mode}) a run may stay bounded "
                                  f"but slip wrongly. Likely fix: {advice}"))
    checks.append(upper_bound("energy_audit", energy_balance_error(scene, result), ENERGY_AUDIT_BOUND, "-",
                              f"the energy balance does not close. Likely fix: {advice}"))
    checks.append(judged("guard_warnings", len(warnings), 0, not warnings, "count", "; ".join(warnings)))
    return tuple(checks)
