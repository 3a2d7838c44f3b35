"""PNG figures of a ``balls`` result (matplotlib, no screen needed)."""

from __future__ import annotations

from pathlib import Path

from bearing_mbs.analysis import energy
from bearing_mbs.core.result import Result
from bearing_mbs.core.scene import Scene
from bearing_mbs.io.figures import new_figure, save_figure


def balls_figures(spec, scene: Scene, result: Result, directory: Path) -> list[Path]:
    """Coordinates against time, trajectories, contact forces and energy (``spec`` is not needed)."""
    paths = []
    fig, axes = new_figure(3, 1, sharex=True, figsize=(7, 7))
    for i, body in enumerate(scene.bodies):
        for c, (axis, label) in enumerate(zip(axes, ("x [m]", "y [m]", "θ [rad]"))):
            axis.plot(result.time, result.position[:, 3 * i + c], label=body.name)
            axis.set_ylabel(label)
    axes[0].legend()
    axes[-1].set_xlabel("time [s]")
    fig.suptitle(f"{scene.name}: coordinates ({result.engine} {result.method})")
    paths.append(save_figure(fig, directory / "coordinates.png", status_note=result.status_note))

    fig, axis = new_figure(figsize=(6, 5))
    for i, body in enumerate(scene.bodies):
        axis.plot(result.position[:, 3 * i], result.position[:, 3 * i + 1], label=body.name)
    axis.set_aspect("equal", adjustable="datalim")
    axis.set_xlabel("x [m]")
    axis.set_ylabel("y [m]")
    axis.legend()
    axis.set_title(f"{scene.name}: trajectories")
    paths.append(save_figure(fig, directory / "trajectory.png", status_note=result.status_note))

    if scene.pairs:
        fig, axis = new_figure(figsize=(7, 4))
        forces = result.pair_series("normal_force")
        for k, pair in enumerate(scene.pairs):
            if forces[:, k].max() > 0:
                axis.plot(result.time, forces[:, k], label=pair.name)
        axis.set_xlabel("time [s]")
        axis.set_ylabel("normal force [N]")
        if axis.lines:
            axis.legend(fontsize="small")
        axis.set_title(f"{scene.name}: contact forces at output instants"
                       + ("" if axis.lines else " (no contact at any output instant)"))
        paths.append(save_figure(fig, directory / "contact_forces.png", status_note=result.status_note))

    fig, axis = new_figure(figsize=(7, 4))
    for name, series in energy(scene, result).items():
        axis.plot(result.time, series, label=name)
    axis.set_xlabel("time [s]")
    axis.set_ylabel("energy [J]")
    axis.legend()
    axis.set_title(f"{scene.name}: energy")
    paths.append(save_figure(fig, directory / "energy.png", status_note=result.status_note))
    return paths
