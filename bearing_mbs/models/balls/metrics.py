"""Summary metrics of the ``balls`` model."""

from __future__ import annotations

from bearing_mbs.analysis import (
    constraint_violation,
    energy,
    energy_balance_error,
    max_penetration,
    restitution_effective,
)
from bearing_mbs.core.result import Result
from bearing_mbs.core.scene import Scene

#: Units of :func:`balls_metrics`' entries.
UNITS = {"max_penetration": "m", "restitution_effective": "-", "final_velocity_x": "m/s", "final_position_y": "m",
         "energy_initial": "J", "energy_final": "J", "max_constraint_violation": "m", "energy_balance_error": "-"}


def balls_metrics(spec, scene: Scene, result: Result) -> dict:
    """Summary metrics of the balls model (first ball for the kinematic ones)."""
    e = energy(scene, result)
    metrics = {
        "max_penetration": max_penetration(result),
        "restitution_effective": restitution_effective(result),
        "final_velocity_x": float(result.velocity[-1, 0]),
        "final_position_y": float(result.position[-1, 1]),
        "energy_initial": float(e["total"][0]),
        "energy_final": float(e["total"][-1]),
    }
    if scene.constraints:
        metrics["max_constraint_violation"] = float(constraint_violation(scene, result).max())
    if "energy" in scene.sensors:
        metrics["energy_balance_error"] = energy_balance_error(scene, result)
    return metrics
