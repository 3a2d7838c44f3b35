"""One run, end to end: spec → scene → engine → result, its checks → summary and files.

``run_spec`` is a pure function of the spec (plus a progress meter), which is what studies distribute. The
result it returns carries its checks (:mod:`bearing_mbs.runner.checks`), so its status is final.
"""

from __future__ import annotations

import dataclasses
import logging
import os
from pathlib import Path

import numpy as np

from bearing_mbs.contact.kernel import N_PAIR_OUTPUTS
from bearing_mbs.core.progress import ProgressMeter
from bearing_mbs.core.result import SUCCESS, SUSPECT, Result
from bearing_mbs.core.scene import Scene
from bearing_mbs.elements import scene_counts
from bearing_mbs.engines import simulate
from bearing_mbs.io.json import json_safe, rounded, write_json
from bearing_mbs.models import MODELS, build_scene
from bearing_mbs.numerics.advisor import step_advice, step_warning
from bearing_mbs.numerics.work_precision import SolverChoice, choose_solver
from bearing_mbs.runner.checks import run_checks
from bearing_mbs.runner.outputs import SUMMARY_FILE, Staging
from bearing_mbs.runner.run_time import require_feasible_run_time
from bearing_mbs.runner.units import RUN_UNITS
from bearing_mbs.spec import Spec, SpecError, to_mapping
from bearing_mbs.spec.solver import SolverSpec

log = logging.getLogger(__name__)

RESULT_FILE = "result.npz"
#: The largest share of the machine's physical memory a run's output may need.
OUTPUT_MEMORY_SHARE = 0.5


def run_spec(spec: Spec, progress: ProgressMeter | None = None) -> tuple[Scene, Result]:
    """Build the scene (all validation happens here, before any simulation), run it and check the result. With
    ``[solver] tolerance`` the run takes the setting chosen for it (:func:`spec_for_run`)."""
    scene = build_scene(spec)
    spec, choice = spec_for_run(spec, scene)
    if choice is not None:
        log.info("%s: %s", spec.scenario.name, choice.text())
    run_time_warnings = require_feasible_run_time(scene, spec.solver, spec.scenario.end_time)
    require_output_fits(scene, spec.solver, spec.scenario.end_time)
    require_initial_speeds_within_limit(scene, spec.solver)
    result = simulate_advised(scene, spec.solver, spec.scenario.end_time, progress, spec=to_mapping(spec))
    if run_time_warnings:
        result.metadata.setdefault("warnings", []).extend(run_time_warnings)
    warnings = MODELS[spec.scenario.model].warnings(spec, scene, result)
    result.checks = run_checks(scene, spec.solver, spec.scenario.end_time, result, warnings)
    if not result.completed:
        log.warning("%s: %s", spec.scenario.name, result.message)
    return scene, result


def spec_for_run(spec: Spec, scene: Scene) -> tuple[Spec, SolverChoice | None]:
    """The spec a run of ``scene`` takes: ``spec`` itself, or with ``[solver] tolerance`` its engine's section
    replaced by the setting chosen from the model's work–precision table, with the choice
    (:func:`bearing_mbs.numerics.work_precision.choose_solver`; SpecError before anything runs where none fits)."""
    solver, choice = choose_solver(spec, scene)
    return (spec, None) if choice is None else (dataclasses.replace(spec, solver=solver), choice)


def bytes_per_instant(scene: Scene) -> int:
    """Memory [bytes] of one output instant: time, positions, velocities, pair outputs, constraint forces, work."""
    return 8 * (1 + 2 * scene.coordinate_count + len(scene.pairs) * N_PAIR_OUTPUTS + len(scene.constraints) + 2)


def require_output_fits(scene: Scene, solver: SolverSpec, end_time: float) -> None:
    """Refuse, before anything runs, an output that would need more than :data:`OUTPUT_MEMORY_SHARE` of the
    machine's memory."""
    instants = end_time / solver.output_interval
    per_instant = bytes_per_instant(scene)
    needed = per_instant * (instants + 1)
    available = OUTPUT_MEMORY_SHARE * os.sysconf("SC_PAGE_SIZE") * os.sysconf("SC_PHYS_PAGES")
    if needed > available:
        smallest = end_time * per_instant / available
        raise SpecError("solver.output_interval", solver.output_interval,
                        f">= {smallest:.3g} s: {instants:.3g} output instants of {per_instant} bytes would need "
                        f"{needed / 2**30:.3g} GiB, more than {OUTPUT_MEMORY_SHARE:.0%} of this machine's memory")


def require_initial_speeds_within_limit(scene: Scene, solver: SolverSpec) -> None:
    """Refuse, before anything runs, a body that starts faster than the run's speed guard (it would stop the run
    at t = 0 as a divergence)."""
    _, v = scene.initial_state()
    speeds = np.hypot(v[0::3], v[1::3])
    if speeds.size and speeds.max() > solver.speed_limit:
        body = scene.bodies[int(np.argmax(speeds))].name
        raise SpecError("solver.speed_limit", solver.speed_limit,
                        f"above the fastest initial body speed, {speeds.max():.3g} m/s of {body!r} (or a lower speed "
                        f"in [drive])")


def simulate_advised(scene: Scene, solver: SolverSpec, end_time: float, progress: ProgressMeter | None = None,
                     spec: dict | None = None) -> Result:
    """:func:`bearing_mbs.engines.simulate` with the step advisor's voice: a failure that a smaller step may fix
    quotes the run's step advice (:func:`bearing_mbs.numerics.advisor.step_advice`), and a fixed explicit step
    above the advised stability limit is warned about (logged, and recorded in ``result.metadata["warnings"]``)."""
    warnings = step_warnings(scene, solver)
    result = simulate(scene, solver, end_time, progress, spec, step_advice(scene, solver).text())
    if warnings:
        result.metadata.setdefault("warnings", []).extend(warnings)
    return result


def step_warnings(scene: Scene, solver: SolverSpec) -> list[str]:
    """The step advisor's warnings for this run (logged); advice never fails a run."""
    try:
        message = step_warning(scene, solver)
    except Exception as error:  # the advisor is advice: a failure of its estimate must not stop a run
        log.debug("step advisor failed on %s: %s", scene.name, error)
        return []
    if message:
        log.warning(message)
        return [message]
    return []


def summarize(spec: Spec, scene: Scene, result: Result) -> dict:
    """The summary.json content: run identity, cost, status, checks and the model's metrics, rounded to the
    digits that carry meaning, with a ``units`` map; with ``[solver] tolerance``, the setting chosen
    (``solver_choice``: the settings, their measured error and cost, the table they came from)."""
    spec, choice = spec_for_run(spec, scene)
    summary = {
        "scenario": spec.scenario.name,
        "status": result.status,
        "failure": result.failure.label,
        "message": result.message,
        "checks": [check.to_dict() for check in result.checks],
        "engine": result.engine,
        "solver": result.method,
        "step": result.step,
        "end_time": float(result.time[-1]),
        "wall_time_s": result.stats.wall_time_s,
        "steps": result.stats.steps,
        "rejected_steps": result.stats.rejected_steps,
        "force_evaluations": result.stats.force_evaluations,
        "newton_iterations": result.stats.newton_iterations,
        "scene": scene_counts(scene),
    }
    advice = step_advice(scene, spec.solver)
    summary["step_advice"] = advice.to_dict()
    if choice is not None:
        summary["solver_choice"] = choice.to_dict()
    if result.engine == "exudyn":
        summary["connector"] = result.metadata.get("connector")
    model = MODELS[spec.scenario.model]
    try:
        summary.update(model.metrics(spec, scene, result))
    except Exception as error:  # the metrics read the saved result: their failure must not cost it
        log.error("%s: metrics not computed: %s: %s", spec.scenario.name, type(error).__name__, error)
        summary["metrics_error"] = f"{type(error).__name__}: {error}"
        if summary["status"] == SUCCESS:  # success means every check passed, and the metrics were not computed
            summary["status"] = SUSPECT
    units = {**RUN_UNITS, **model.units, "step_advice": advice.units, "solver_choice": SolverChoice.units}
    summary["units"] = {key: units[key] for key in summary if key in units}
    return {key: rounded(json_safe(value)) for key, value in summary.items()}


def write_outputs(spec: Spec, scene: Scene, result: Result, directory: str | Path, figures: bool = True) -> dict:
    """Write result.npz, summary.json and the figures through a staging directory, then publish them together
    (:class:`bearing_mbs.runner.outputs.Staging`: a failed run never replaces a good result). A figure that
    cannot be drawn is logged and does not lose the rest. Returns the summary, with ``written_to``."""
    staging = Staging(directory)
    result.save(staging.path / RESULT_FILE)
    summary = summarize(spec, scene, result)
    write_json(staging.path / SUMMARY_FILE, summary)
    if figures:
        try:
            MODELS[spec.scenario.model].figures(spec, scene, result, staging.path)
        except Exception as error:  # a figure is a view of the saved result: it must not cost the result
            log.warning("%s: figures not drawn: %s: %s", spec.scenario.name, type(error).__name__, error)
    summary["written_to"] = str(staging.publish(result.status))
    return summary
