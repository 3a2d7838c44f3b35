"""Engines: each consumes a scene and returns a :class:`bearing_mbs.core.result.Result` of the same layout.

* ``reference`` — our compiled explicit integrators (:mod:`.reference`).
* ``exudyn`` — Exudyn rigid bodies with our force elements in one generic ODE2 object (:mod:`.exudyn`).

Engines know scenes, force elements and solvers, and nothing of any model, nor of each other: what both do
around their stepping (the run's frame, the guard on a state, the output a stopped run keeps, the ``Result``) is in
:mod:`.run`, the failure messages in :mod:`.diagnosis`.

Both stop within about a second of a SIGINT or SIGTERM (:mod:`bearing_mbs.core.interrupt`) with the failure kind
``INTERRUPTED`` and every output instant computed so far.
"""

from __future__ import annotations

from bearing_mbs.core.interrupt import StopRequest, active_request, stop_on_signals
from bearing_mbs.core.progress import ProgressMeter
from bearing_mbs.core.result import Result
from bearing_mbs.core.scene import Scene
from bearing_mbs.spec.solver import SolverSpec


def simulate(scene: Scene, solver: SolverSpec, end_time: float, progress: ProgressMeter | None = None,
             spec: dict | None = None, step_advice: str | None = None) -> Result:
    """Run ``scene`` from 0 to ``end_time`` [s] with the engine and settings of ``solver``; SIGINT and SIGTERM
    stop it with what it computed (inside a caller's :func:`~bearing_mbs.core.interrupt.stop_on_signals` block,
    that block's request). ``step_advice``: the words of the fix that changes the step, quoted by a failure's
    message (:func:`bearing_mbs.runner.simulate_advised` passes the step advisor's; engines know no model)."""
    request = active_request()
    if request is None:
        with stop_on_signals(StopRequest()) as request:
            return _simulate(scene, solver, end_time, progress, spec, request, step_advice)
    return _simulate(scene, solver, end_time, progress, spec, request, step_advice)


def check_supported(scene: Scene, solver: SolverSpec) -> None:
    """Raise :class:`~bearing_mbs.spec.SpecError` before anything runs if the engine cannot run ``scene`` with
    ``solver`` (e.g. Exudyn's explicit solvers and a scene with constraints); the reference engine runs all."""
    if solver.engine == "exudyn":
        from bearing_mbs.engines.exudyn.engine import check_supported as exudyn_check

        exudyn_check(scene, solver)


def _simulate(scene, solver, end_time, progress, spec, stop, step_advice) -> Result:
    if solver.engine == "reference":
        from bearing_mbs.engines.reference.engine import simulate_reference

        return simulate_reference(scene, solver, end_time, progress, spec, stop, step_advice)
    from bearing_mbs.engines.exudyn.engine import simulate_exudyn

    return simulate_exudyn(scene, solver, end_time, progress, spec, stop, step_advice)


__all__ = ["check_supported", "simulate"]
