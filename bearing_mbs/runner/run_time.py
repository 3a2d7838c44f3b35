"""Whether the machine can run a scene to its end time: an estimate of the run time before anything runs.

The estimate is the number of steps times the measured cost of a step. The steps are ``end_time`` over the step the
run will take: its fixed step (central difference's contact step where set), or for an adaptive method the smaller of
its largest step and the step advisor's stability limit for the method and scene
(:mod:`bearing_mbs.numerics.advisor`), which its step cannot exceed for long. The cost of a step is measured on this
machine by a short probe of :data:`PROBE_STEPS` steps of the same scene and solver (after the engine has compiled).

The probe runs only when the run could take long: a step of any engine here costs more than
:data:`MIN_STEP_COST`, so a run of fewer than :data:`WARN_RUN_TIME` / :data:`MIN_STEP_COST` steps cannot exceed
:data:`WARN_RUN_TIME` and costs nothing to check. Beyond :data:`REFUSE_RUN_TIME` the run is refused naming
``scenario.end_time``; beyond :data:`WARN_RUN_TIME` it is warned about (docs/status.md).
"""

from __future__ import annotations

import dataclasses
import logging
import math
from dataclasses import dataclass

from bearing_mbs.core.scene import Scene
from bearing_mbs.engines import simulate
from bearing_mbs.numerics.advisor import advise
from bearing_mbs.spec import SpecError
from bearing_mbs.spec.solver import SolverSpec

log = logging.getLogger(__name__)

#: A lower bound of the wall time of one step of any engine and scene here [s] (the cheapest measured, a ball on a
#: floor on the reference engine, costs about 0.1 µs; a bearing step 20–600 µs, docs/numerics.md).
MIN_STEP_COST = 1e-7
#: A run estimated to take longer than this is warned about [s].
WARN_RUN_TIME = 3600.0
#: A run estimated to take longer than this is refused [s]: a week of one core with no result is not a run a user
#: meant to start.
REFUSE_RUN_TIME = 7 * 86400.0
#: Steps of the probe that measures the cost of a step [-].
PROBE_STEPS = 200


@dataclass(frozen=True)
class RunTimeEstimate:
    """``steps`` of ``step`` [s] at ``step_cost`` [s] each (measured; None when the run is too short to measure):
    ``run_time`` [s]."""

    steps: float
    step: float
    step_cost: float | None

    @property
    def run_time(self) -> float | None:
        return None if self.step_cost is None else self.steps * self.step_cost

    def text(self) -> str:
        hours = self.run_time / 3600
        return (f"{self.steps:.3g} steps of {self.step:.3g} s at the measured {self.step_cost * 1e6:.3g} µs per step: "
                f"about {hours:.3g} h" + (f" ({hours / 24:.3g} days)" if hours > 48 else ""))


def run_step(scene: Scene, solver: SolverSpec) -> float:
    """The step [s] the run will mostly take (module docstring)."""
    settings = solver.active
    step = getattr(settings, "contact_step", None) or settings.step
    if settings.adaptive:
        limit = advise(scene).limit(solver.engine, settings.method)
        if limit is not None and math.isfinite(limit):
            step = min(step, limit)
    return step


def estimate_run_time(scene: Scene, solver: SolverSpec, end_time: float) -> RunTimeEstimate:
    """The run time of ``scene`` to ``end_time`` [s]; the cost of a step is measured only for a run that could
    exceed :data:`WARN_RUN_TIME` (module docstring)."""
    step = run_step(scene, solver)
    steps = end_time / step
    if steps * MIN_STEP_COST <= WARN_RUN_TIME:
        return RunTimeEstimate(steps, step, None)
    probe_end = PROBE_STEPS * solver.active.step
    probe = simulate(scene, dataclasses.replace(solver, output_interval=probe_end), probe_end)
    cost = probe.stats.wall_time_s / max(probe.stats.steps, 1)
    return RunTimeEstimate(steps, step, max(cost, MIN_STEP_COST))


def require_feasible_run_time(scene: Scene, solver: SolverSpec, end_time: float) -> list[str]:
    """Refuse, before the run, an ``end_time`` the machine cannot reach within :data:`REFUSE_RUN_TIME`; returns the
    warning (logged) for one beyond :data:`WARN_RUN_TIME`, else nothing."""
    estimate = estimate_run_time(scene, solver, end_time)
    run_time = estimate.run_time
    if run_time is None or run_time <= WARN_RUN_TIME:
        return []
    if run_time > REFUSE_RUN_TIME:
        feasible = end_time * REFUSE_RUN_TIME / run_time
        raise SpecError("scenario.end_time", end_time,
                        f"a run this machine can finish within {REFUSE_RUN_TIME / 86400:g} days: "
                        f"{estimate.text()}; at most about {feasible:.3g} s at this step")
    warning = f"{scene.name}: scenario.end_time = {end_time:g} s needs {estimate.text()}"
    log.warning(warning)
    return [warning]
