"""One run, end to end: spec → scene → engine → result → summary and files.

``run_spec`` is a pure function of the spec (plus a progress meter), which is what studies distribute.
"""

from __future__ import annotations

import logging
from pathlib import Path

from bearing_mbs.core.progress import ProgressMeter
from bearing_mbs.core.result import Result
from bearing_mbs.core.scene import Scene
from bearing_mbs.elements import scene_counts
from bearing_mbs.engines import simulate
from bearing_mbs.io.json import json_safe, write_json
from bearing_mbs.models import MODELS, build_scene
from bearing_mbs.numerics.advisor import step_warning
from bearing_mbs.spec import Spec, to_mapping
from bearing_mbs.spec.solver import SolverSpec

log = logging.getLogger(__name__)

RESULT_FILE = "result.npz"
SUMMARY_FILE = "summary.json"


def run_spec(spec: Spec, progress: ProgressMeter | None = None) -> tuple[Scene, Result]:
    """Build the scene (all validation happens here, before any simulation) and run it."""
    scene = build_scene(spec)
    result = simulate_advised(scene, spec.solver, spec.scenario.end_time, progress, spec=to_mapping(spec))
    if not result.success:
        log.warning("%s: %s", spec.scenario.name, result.message)
    return scene, result


def simulate_advised(scene: Scene, solver: SolverSpec, end_time: float, progress: ProgressMeter | None = None,
                     spec: dict | None = None) -> Result:
    """:func:`bearing_mbs.engines.simulate`, with the step advisor's warning when a fixed explicit step exceeds
    the advised stability limit: logged, and recorded in ``result.metadata["warnings"]``."""
    warnings = step_warnings(scene, solver)
    result = simulate(scene, solver, end_time, progress, spec)
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
    """The summary.json content: run identity, cost, status and the model's metrics."""
    summary = {
        "scenario": spec.scenario.name,
        "status": result.status,
        "message": result.message,
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
    if result.engine == "exudyn":
        summary["connector"] = result.metadata.get("connector")
    summary.update(MODELS[spec.scenario.model].metrics(spec, scene, result))
    return {key: json_safe(value) for key, value in summary.items()}


def write_outputs(spec: Spec, scene: Scene, result: Result, directory: str | Path, figures: bool = True) -> dict:
    """Write the result file first (never lost), then summary.json, then the figures."""
    directory = Path(directory)
    directory.mkdir(parents=True, exist_ok=True)
    result.save(directory / RESULT_FILE)
    summary = summarize(spec, scene, result)
    write_json(directory / SUMMARY_FILE, summary)
    if figures:
        MODELS[spec.scenario.model].figures(spec, scene, result, directory)
    return summary
