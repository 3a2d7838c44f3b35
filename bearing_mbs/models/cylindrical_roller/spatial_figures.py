"""Figures of the bearing in three dimensions (:mod:`.spatial`): the slice load distribution along the rollers, the
rollers' skew and tilt and the cage's slip over time, and the ribs' loads and the smearing measure over time (matplotlib through :mod:`bearing_mbs.io.figures`, no screen
needed)."""

from __future__ import annotations

from pathlib import Path

import numpy as np

from bearing_mbs.io.figures import new_figure, save_figure
from bearing_mbs.models.cylindrical_roller.spatial import INNER, OUTER, SpatialBearing


def plot_slice_loads(bearing: SpatialBearing, series, path: str | Path, *, instant: int = -1, title: str = "") -> Path:
    """The inner raceway's slice loads [N] of every roller at output ``instant``, as a map of roller (by azimuth)
    against the position along its axis [mm]: where edge loading shows. Returns the saved PNG's path."""
    loads = bearing.slice_loads(series, INNER)[instant]  # (Z, slices)
    centres = series.position[instant, 2:, :2]
    azimuth = np.degrees(np.arctan2(centres[:, 1], centres[:, 0]))
    order = np.argsort(azimuth)
    positions = np.array(bearing.scene.raceways[INNER].positions) * 1e3
    figure, axis = new_figure(figsize=(7.0, 4.5))
    image = axis.pcolormesh(positions, azimuth[order], loads[order], shading="nearest", cmap="viridis")
    figure.colorbar(image, ax=axis, label="slice load [N]")
    axis.set_xlabel("position along the roller [mm]")
    axis.set_ylabel("roller azimuth [deg]")
    axis.set_title(title or f"inner raceway slice loads at t = {series.time[instant] * 1e3:.2f} ms")
    return save_figure(figure, path)


def plot_attitudes(bearing: SpatialBearing, series, path: str | Path, *, title: str = "") -> Path:
    """The rollers' skew and tilt [mrad] and the cage's slip over time [ms]. Returns the saved PNG's path."""
    skew, tilt = bearing.attitudes(series)
    time = series.time * 1e3
    figure, axes = new_figure(3, 1, figsize=(7.0, 7.5), sharex=True)
    axes[0].plot(time, skew * 1e3, linewidth=0.8)
    axes[0].set_ylabel("skew [mrad]")
    axes[1].plot(time, tilt * 1e3, linewidth=0.8)
    axes[1].set_ylabel("tilt [mrad]")
    axes[2].plot(time, bearing.cage_slip(series), color="black")
    axes[2].set_ylabel("cage slip [-]")
    axes[2].set_xlabel("time [ms]")
    axes[0].set_title(title or "rollers' skew and tilt, cage slip")
    return save_figure(figure, path)


def plot_ribs_and_smearing(bearing: SpatialBearing, series, path: str | Path, *, title: str = "") -> Path:
    """The ribs' loads summed over the rollers [N] (the outer ring's at +z and −z, the inner ring's) and the largest
    slice frictional power intensity on either raceway [W/mm²] (the smearing measure, docs/smearing.md) over time
    [ms]. Returns the saved PNG's path."""
    time = series.time * 1e3
    ribs = bearing.rib_loads(series).sum(axis=1)  # (T, 3)
    figure, axes = new_figure(2, 1, figsize=(7.0, 5.5), sharex=True)
    for column, label in enumerate(("outer ring, +z", "outer ring, −z", "inner ring")):
        axes[0].plot(time, ribs[:, column], label=label)
    axes[0].set_ylabel("rib load [N]")
    axes[0].legend()
    for contact, label in ((INNER, "inner raceway"), (OUTER, "outer raceway")):
        axes[1].plot(time, bearing.power_intensity(series, contact).max(axis=(1, 2)) * 1e-6, label=label)
    axes[1].set_ylabel("largest slice power intensity [W/mm²]")
    axes[1].set_xlabel("time [ms]")
    axes[1].legend()
    axes[0].set_title(title or "rib loads and the smearing measure")
    return save_figure(figure, path)
