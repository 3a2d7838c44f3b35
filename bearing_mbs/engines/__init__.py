"""Engines: each consumes a scene and returns a :class:`bearing_mbs.result.Result` of the same layout.

* ``reference`` — our compiled explicit integrators (:mod:`.reference`).
* ``exudyn`` — Exudyn rigid bodies with our contact connectors (:mod:`.exudyn_engine`).
"""

from __future__ import annotations

from ..progress import ProgressMeter
from ..result import Result
from ..scene import Scene
from ..spec.solver import SolverSpec


def simulate(scene: Scene, solver: SolverSpec, end_time: float, progress: ProgressMeter | None = None,
             spec: dict | None = None) -> Result:
    """Run ``scene`` from 0 to ``end_time`` [s] with the engine and settings of ``solver``."""
    if solver.engine == "reference":
        from .reference.engine import simulate_reference

        return simulate_reference(scene, solver, end_time, progress, spec)
    from .exudyn_engine import simulate_exudyn

    return simulate_exudyn(scene, solver, end_time, progress, spec)


__all__ = ["simulate"]
