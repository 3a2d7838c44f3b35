"""The load-distribution figure: roller loads against azimuth (matplotlib, no screen needed).

Uses the object-oriented API (:mod:`bearing_mbs.io.figures`), so drawing never changes the global matplotlib
backend; matplotlib is imported on the first call only, which keeps
``import bearing_mbs.models.cylindrical_roller.quasistatic`` light.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from bearing_mbs.io.figures import new_figure, save_figure
from bearing_mbs.models.cylindrical_roller.quasistatic.planar import RadialSolution
from bearing_mbs.models.cylindrical_roller.quasistatic.sliced import SlicedSolution


def plot_load_distribution(solution: RadialSolution | SlicedSolution, path: str | Path, *, title: str = "",
                           note: str | None = None) -> Path:
    """Draw inner and outer roller loads [N] against azimuth [deg] and save a PNG; returns the path. ``note``: the
    status of a solution that is not ``success``, stamped on the figure.

    Azimuths are wrapped to (−180°, 180°]; dashed lines mark the continuous loaded zone ±ψ_l around the
    displacement direction when the solution provides it (planar model).
    """
    path = Path(path)
    angles = np.degrees(np.angle(np.exp(1j * solution.roller_angles)))
    order = np.argsort(angles)
    figure, axis = new_figure(figsize=(7.0, 4.0))
    axis.plot(angles[order], solution.inner_loads[order], "o-", label="inner contact")
    if np.any(solution.outer_loads != solution.inner_loads):
        axis.plot(angles[order], solution.outer_loads[order], "s--", label="outer contact")
    half_angle = getattr(solution, "loaded_zone_half_angle", None)
    if half_angle is not None:
        centre = np.degrees(np.arctan2(solution.displacement[1], solution.displacement[0]))
        for side in (-1.0, 1.0):
            edge = (centre + side * np.degrees(half_angle) + 180.0) % 360.0 - 180.0
            axis.axvline(edge, color="grey", linestyle=":", linewidth=1.0)
    axis.set_xlim(-180.0, 180.0)
    axis.set_xticks(np.arange(-180, 181, 45))
    axis.set_xlabel("roller azimuth ψ [deg]")
    axis.set_ylabel("roller load Q [N]")
    fx, fy = solution.load[:2]
    axis.set_title(title or f"load distribution: Z = {solution.rollers.rollers}, F = ({fx:.4g}, {fy:.4g}) N")
    axis.grid(True, alpha=0.3)
    axis.legend()
    return save_figure(figure, path, dpi=120, status_note=note)
