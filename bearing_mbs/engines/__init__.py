"""Engines: each consumes a scene and returns a :class:`bearing_mbs.core.result.Result` of the same layout.

* ``reference`` — our compiled explicit integrators (:mod:`.reference`).
* ``exudyn`` — Exudyn rigid bodies with our force elements in one generic ODE2 object (:mod:`.exudyn`).

Engines know scenes, force elements and solvers, and nothing of any model.
"""

from __future__ import annotations

from bearing_mbs.core.progress import ProgressMeter
from bearing_mbs.core.result import Result
from bearing_mbs.core.scene import Scene
from bearing_mbs.spec.solver import SolverSpec


def simulate(scene: Scene, solver: SolverSpec, end_time: float, progress: ProgressMeter | None = None,
             spec: dict | None = None) -> Result:
    """Run ``scene`` from 0 to ``end_time`` [s] with the engine and settings of ``solver``."""
    if solver.engine == "reference":
        from bearing_mbs.engines.reference.engine import simulate_reference

        return simulate_reference(scene, solver, end_time, progress, spec)
    from bearing_mbs.engines.exudyn.engine import simulate_exudyn

    return simulate_exudyn(scene, solver, end_time, progress, spec)


__all__ = ["simulate"]
