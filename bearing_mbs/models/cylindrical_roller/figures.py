r"""Figures of a bearing run, in the style of the skidding literature (matplotlib, no screen needed).

* ``cage_slip.png``: inner-ring and cage speeds [rpm] and the cage slip :math:`1 - \omega_c/\omega_{c,epi}` [%]
  against time, the epicyclic (no-slip) cage speed :math:`\omega_{c,epi} = \omega_i (1 - D_w/D_{pw})/2` taken at
  the inner ring's speed of the same instant;
* ``roller_loads.png``: the inner-raceway roller load [N] against the roller's orbital angle [deg] over the
  analysis window: every sample faint, the binned mean bold;
* ``slip_map.png``: roller × time map of the inner-raceway slip ratio (blank where the contact carries less than
  ``[analysis] load_fraction`` of the largest roller load);
* ``inner_ring_orbit.png``: the inner-ring centre's path [µm].

:func:`animate` draws a GIF of the bearing (rings, cage, rollers with a spin mark coloured by their load); it is
written only on request (``bearing-mbs run --animate``). All quantities come from
:mod:`bearing_mbs.models.cylindrical_roller.metrics`; nothing here computes physics. Figures use matplotlib's object-oriented API
(:mod:`bearing_mbs.io.figures`), so drawing never changes the global backend.
"""

from __future__ import annotations

import logging
from pathlib import Path

import numpy as np

from bearing_mbs.core.topology import Group, Role
from bearing_mbs.io.figures import new_figure, save_figure
from bearing_mbs.models.cylindrical_roller.geometry import BearingGeometry
from bearing_mbs.models.cylindrical_roller.metrics import (
    cage_speed,
    load_distribution,
    pair_columns,
    roller_indices,
    roller_orbit_angles,
    slip_ratios,
    window,
)

log = logging.getLogger(__name__)

RPM_PER_RAD_S = 60 / (2 * np.pi)
#: Below this fraction of the run's largest epicyclic speed the cage slip is not defined (start-up, stop).
SLIP_SPEED_FLOOR = 0.02
#: The slip map's colour limit is this percentile of |s| (a few impacts should not wash out the map).
SLIP_MAP_PERCENTILE = 99.0
DPI = 110


def bearing_figures(spec, scene, result, directory) -> list[Path]:
    """Write the four bearing figures into ``directory``; returns their paths."""
    directory = Path(directory)
    directory.mkdir(parents=True, exist_ok=True)
    drawers = (("cage_slip.png", plot_cage_slip), ("roller_loads.png", plot_roller_loads),
               ("slip_map.png", plot_slip_map), ("inner_ring_orbit.png", plot_inner_ring_orbit))
    paths = []
    for name, draw in drawers:
        figure = draw(spec, scene, result)
        paths.append(save_figure(figure, directory / name, dpi=DPI, status_note=result.status_note))
    log.debug("%s: drew %d figures", scene.name, len(paths))
    return paths


def cage_slip_series(spec, scene, result) -> np.ndarray:
    """(T,) cage slip 1 − ω_c/ω_c,epi [-] at the output instants; NaN where the epicyclic speed is below
    :data:`SLIP_SPEED_FLOOR` of its largest magnitude over the run (the ratio is not defined at rest)."""
    geometry = BearingGeometry.from_spec(spec.bearing)
    epicyclic = geometry.epicyclic_cage_speed(result.velocity[:, 2])
    defined = np.abs(epicyclic) > SLIP_SPEED_FLOOR * max(np.max(np.abs(epicyclic)), 1e-300)
    with np.errstate(divide="ignore", invalid="ignore"):
        return np.where(defined, 1.0 - cage_speed(scene, result) / epicyclic, np.nan)


def plot_cage_slip(spec, scene, result):
    """Speeds [rpm] (top) and cage slip [%] (bottom) against time [s]; the analysis window is shaded."""
    geometry = BearingGeometry.from_spec(spec.bearing)
    figure, (speeds, slip) = new_figure(2, 1, figsize=(7.0, 5.5), sharex=True)
    time = result.time
    speeds.plot(time, result.velocity[:, 2] * RPM_PER_RAD_S, label="inner ring")
    speeds.plot(time, cage_speed(scene, result) * RPM_PER_RAD_S, label="cage")
    speeds.plot(time, geometry.epicyclic_cage_speed(result.velocity[:, 2]) * RPM_PER_RAD_S, "k--", linewidth=0.8,
                label="cage, epicyclic (no slip)")
    speeds.set_ylabel("speed [rpm]")
    speeds.legend(fontsize="small")
    slip.plot(time, 100 * cage_slip_series(spec, scene, result), color="C3")
    slip.axhline(0.0, color="grey", linewidth=0.6)
    slip.set_ylabel("cage slip 1 − ω_c/ω_c,epi [%]")
    slip.set_xlabel("time [s]")
    for axis in (speeds, slip):
        _shade_window(axis, spec, result)
        axis.grid(True, alpha=0.3)
    speeds.set_title(f"{scene.name}: cage slip ({_engine_label(result)})")
    return figure


def plot_roller_loads(spec, scene, result):
    """Inner-raceway roller load [N] against orbital angle [deg] over the analysis window."""
    mask = window(spec, result)
    angles = np.degrees(roller_orbit_angles(scene, result)[mask]).ravel()
    forces = result.pair_series("normal_force")[mask][:, pair_columns(scene, Group.INNER_RACE)].ravel()
    centres, means = load_distribution(scene, result, mask, 2 * roller_indices(scene).size)
    figure, axis = new_figure(figsize=(7.0, 4.0))
    axis.plot(angles, forces, ".", color="C0", alpha=0.08, markersize=2, label="samples")
    axis.plot(centres, means, "o-", color="C1", label="mean per bin")
    axis.axvline(np.mod(spec.load.angle, 360.0), color="grey", linestyle=":", label="radial load direction")
    axis.set_xlim(0.0, 360.0)
    axis.set_xticks(np.arange(0, 361, 45))
    axis.set_xlabel("orbital angle ψ [deg] (0 along +x, counter-clockwise)")
    axis.set_ylabel("inner-raceway roller load [N]")
    axis.grid(True, alpha=0.3)
    axis.legend(fontsize="small")
    axis.set_title(f"{scene.name}: roller loads, t ≥ {result.time[mask][0]:.3g} s")
    return figure


def plot_slip_map(spec, scene, result):
    """Inner-raceway slip ratio [-] of each roller against time: diverging colours, blank where unloaded."""
    ratios = slip_ratios(scene, result, Group.INNER_RACE, spec.analysis.load_fraction)
    finite = np.abs(ratios[np.isfinite(ratios)])
    limit = float(np.percentile(finite, SLIP_MAP_PERCENTILE)) if finite.size else 1.0
    limit = limit if limit > 0 else 1.0
    figure, axis = new_figure(figsize=(7.5, 4.0))
    rollers = np.arange(ratios.shape[1] + 1) - 0.5
    mesh = axis.pcolormesh(_cell_edges(result.time), rollers, ratios.T, cmap="RdBu_r", vmin=-limit, vmax=limit,
                           shading="flat", rasterized=True)
    colorbar = figure.colorbar(mesh, ax=axis)
    colorbar.set_label("slip ratio s = v_slip/u [-]")
    axis.set_xlabel("time [s]")
    axis.set_ylabel("roller")
    axis.set_title(f"{scene.name}: inner-raceway slip ratio\n(blank where the roller load is below "
                   f"{100 * spec.analysis.load_fraction:g} % of the largest)", fontsize="medium")
    return figure


def plot_inner_ring_orbit(spec, scene, result):
    """Path of the inner-ring centre [µm]: the whole run faint, the analysis window bold, its mean marked."""
    mask = window(spec, result)
    x, y = 1e6 * result.position[:, 0], 1e6 * result.position[:, 1]
    figure, axis = new_figure(figsize=(5.5, 5.0))
    axis.plot(x, y, color="C0", alpha=0.3, linewidth=0.8, label="whole run")
    axis.plot(x[mask], y[mask], color="C0", linewidth=1.2, label="analysis window")
    axis.plot(x[mask].mean(), y[mask].mean(), "+", color="C3", markersize=12, label="window mean")
    axis.plot(0.0, 0.0, "k.", label="outer-ring centre")
    axis.set_aspect("equal", adjustable="datalim")
    axis.set_xlabel("x [µm]")
    axis.set_ylabel("y [µm]")
    axis.grid(True, alpha=0.3)
    axis.legend(fontsize="small")
    axis.set_title(f"{scene.name}: inner-ring centre")
    return figure


def animate(spec, scene, result, path, frames: int = 120, fps: int = 20) -> Path:
    """Write a GIF of the bearing at ``frames`` output instants spread evenly over the run; returns the path.

    Drawn to scale (displacements of micrometres are not visible): the outer raceway, the inner ring with a
    spin mark, the cage (penalty and constraint models) with its pocket edges, and each roller with a spin
    mark, filled by its inner-raceway load [N] (colour scale: the largest load in the analysis window).
    """
    from matplotlib import animation
    from matplotlib.cm import ScalarMappable
    from matplotlib.colors import Normalize
    from matplotlib.patches import Circle

    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    geometry = BearingGeometry.from_spec(spec.bearing)
    instants = np.unique(np.linspace(0, result.time.size - 1, max(int(frames), 1)).round().astype(int))
    rollers = roller_indices(scene)
    loads = result.pair_series("normal_force")[:, pair_columns(scene, Group.INNER_RACE)]
    colours = ScalarMappable(Normalize(0.0, max(float(loads[window(spec, result)].max()), 1e-300)), "viridis")
    cage = scene.topology.body(Role.CAGE) if scene.topology.has(Role.CAGE) else None
    r_w, r_i = geometry.roller_diameter / 2, geometry.inner_race_diameter / 2

    figure, axis = new_figure(figsize=(5.0, 5.4))
    reach = 1.08 * geometry.outer_race_diameter / 2
    axis.set_xlim(-reach, reach)
    axis.set_ylim(-reach, reach)
    axis.set_aspect("equal")
    axis.set_axis_off()
    axis.add_patch(Circle((0, 0), geometry.outer_race_diameter / 2, fill=False, linewidth=1.5))
    inner = axis.add_patch(Circle((0, 0), r_i, fill=False, linewidth=1.5))
    inner_mark, = axis.plot([], [], "k-", linewidth=1.0)
    discs = [axis.add_patch(Circle((0, 0), r_w, edgecolor="k", linewidth=0.5)) for _ in rollers]
    spin_marks = [axis.plot([], [], "w-", linewidth=0.8)[0] for _ in rollers]
    cage_ring = axis.add_patch(Circle((0, 0), geometry.cage_diameter / 2, fill=False, color="C1", linewidth=1.0))
    cage_ring.set_visible(cage is not None)
    pockets, = axis.plot([], [], "o", color="C1", markersize=2.5)
    label = axis.text(0.0, 1.0, "", transform=axis.transAxes, va="top", fontsize="small")
    figure.colorbar(colours, ax=axis, shrink=0.7, label="inner-raceway roller load [N]")
    slip = cage_slip_series(spec, scene, result)
    pocket_points = np.array([list(geometry.pocket_points(k).values()) for k in range(geometry.rollers)]).reshape(-1, 2)

    def draw(frame):
        i = instants[frame]
        x0, y0, theta = result.position[i, :3]
        inner.center = (x0, y0)
        inner_mark.set_data([x0, x0 + r_i * np.cos(theta)], [y0, y0 + r_i * np.sin(theta)])
        for k, body in enumerate(rollers):
            x, y, phi = result.position[i, 3 * body: 3 * body + 3]
            discs[k].center = (x, y)
            discs[k].set_facecolor(colours.to_rgba(loads[i, k]))
            spin_marks[k].set_data([x, x + r_w * np.cos(phi)], [y, y + r_w * np.sin(phi)])
        if cage is not None:
            xc, yc, tc = result.position[i, 3 * cage: 3 * cage + 3]
            cage_ring.center = (xc, yc)
            c, s = np.cos(tc), np.sin(tc)
            px, py = pocket_points.T
            pockets.set_data(xc + c * px - s * py, yc + s * px + c * py)
        slip_text = "" if np.isnan(slip[i]) else f", cage slip {100 * slip[i]:.2f} %"
        note = f"\n{result.status_note}" if result.status_note else ""
        label.set_text(f"t = {result.time[i]:.4f} s, {result.velocity[i, 2] * RPM_PER_RAD_S:.0f} rpm{slip_text}{note}")
        return [inner, inner_mark, *discs, *spin_marks, cage_ring, pockets, label]

    movie = animation.FuncAnimation(figure, draw, frames=instants.size, blit=False)
    movie.save(path, writer=animation.PillowWriter(fps=fps), dpi=80)
    log.info("%s: wrote %d animation frames to %s", scene.name, instants.size, path)
    return path


def _shade_window(axis, spec, result) -> None:
    """Shade the analysis window; nothing where the run stopped before it."""
    start = spec.analysis.window_start(spec.scenario.end_time)
    if result.time.size and result.time[-1] >= start:
        axis.axvspan(start, result.time[-1], color="grey", alpha=0.12, linewidth=0)


def _cell_edges(time: np.ndarray) -> np.ndarray:
    """Edges of cells centred on the output instants [s]."""
    if time.size == 1:
        return np.array([time[0] - 0.5, time[0] + 0.5])
    middle = 0.5 * (time[1:] + time[:-1])
    return np.concatenate([[2 * time[0] - middle[0]], middle, [2 * time[-1] - middle[-1]]])


def _engine_label(result) -> str:
    return f"{result.engine} {result.method}, h = {result.step:g} s"
