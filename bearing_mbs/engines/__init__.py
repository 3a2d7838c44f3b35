"""Engines: each consumes a scene and returns a :class:`bearing_mbs.core.result.Result` of the same layout.

* ``reference`` — our compiled explicit integrators (:mod:`.reference`).
* ``exudyn`` — Exudyn rigid bodies with our contact connectors (:mod:`.exudyn_engine`).

Before a run, a fixed explicit step above the step advisor's stability limit (:mod:`bearing_mbs.advisor`) is
logged as a warning and recorded in ``result.metadata["warnings"]``.
"""

from __future__ import annotations

import logging

from bearing_mbs.core.progress import ProgressMeter
from bearing_mbs.core.result import Result
from bearing_mbs.core.scene import Scene
from bearing_mbs.spec.solver import SolverSpec

log = logging.getLogger(__name__)


def simulate(scene: Scene, solver: SolverSpec, end_time: float, progress: ProgressMeter | None = None,
             spec: dict | None = None) -> Result:
    """Run ``scene`` from 0 to ``end_time`` [s] with the engine and settings of ``solver``."""
    warnings = step_warnings(scene, solver)
    if solver.engine == "reference":
        from bearing_mbs.engines.reference.engine import simulate_reference

        result = simulate_reference(scene, solver, end_time, progress, spec)
    else:
        from bearing_mbs.engines.exudyn.engine import simulate_exudyn

        result = simulate_exudyn(scene, solver, end_time, progress, spec)
    if warnings:
        result.metadata.setdefault("warnings", []).extend(warnings)
    return result


def step_warnings(scene: Scene, solver: SolverSpec) -> list[str]:
    """The step advisor's warnings for this run (logged); never fails a run."""
    from bearing_mbs.numerics.advisor import step_warning

    try:
        message = step_warning(scene, solver)
    except Exception as error:  # the advisor is advice: a failure of its estimate must not stop a run
        log.debug("step advisor failed on %s: %s", scene.name, error)
        return []
    if message:
        log.warning(message)
        return [message]
    return []


__all__ = ["simulate"]
