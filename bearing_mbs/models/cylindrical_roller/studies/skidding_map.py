r"""Steady skidding over load × oil temperature × speed (× diametral clearance), from the quasi-static skidding
balance.

``bearing-mbs skidding-map SCENARIO.toml --out DIR`` solves
:func:`~bearing_mbs.models.cylindrical_roller.steady_skidding.solve_skidding` for the base scenario (a lubricated
bearing at constant speed, e.g. ``scenarios/seed_hss_steady.toml``) at every radial load, oil temperature and
shaft speed given, and with ``clearances`` at every diametral clearance given (``bearing.diametral_clearance``: the
raceways about the base's pitch circle; by default the base's own clearance alone), a few seconds each where a
dynamic run at light load needs seconds of simulated time to settle (docs/skidding.md). It writes

* ``skidding_map.csv`` and ``skidding_map.md``: a row per point (:data:`COLUMNS`);
* ``skidding_map.png``: cage slip against the total radial load, a panel per speed and a curve per temperature
  (a line style per clearance when several are given), with the catalogue minimum-load band when one is given;
* ``roller_slip.png``: the roller slip, the deficit of a roller's spin in the cage against the epicyclic one (what a
  roller-speed sensor on the cage measures), around the orbit, in and out of the load zone, at each load (base
  speed and temperature).

The rows also give the largest roller slip in and out of the load zone, the largest slide-to-roll ratio Δu/u
(sliding over rolling speed) of the loaded inner contacts, the largest frictional power intensity of the inner and
outer raceway contacts over the orbit [W/mm²] (the smearing measure of docs/smearing.md,
:func:`~bearing_mbs.models.cylindrical_roller.steady_skidding.orbit_power_intensity`), the diametral clearance [m]
of the point, and each point's ``status`` (docs/status.md):
``success`` where the balance was found, ``failed`` where it has none (``message`` says why; the point's values are
NaN); its ``checks`` are empty (a point is one solve, with no window to settle). The map's status is its worst
point's (:func:`map_status`).
"""

from __future__ import annotations

import csv
import itertools
import json
import logging
import time
from pathlib import Path

import numpy as np

from bearing_mbs.core.progress import ProgressMeter
from bearing_mbs.core.result import FAILED, SUCCESS
from bearing_mbs.core.status import worst_status
from bearing_mbs.io.figures import new_figure, save_figure
from bearing_mbs.models.cylindrical_roller.metrics import W_PER_MM2
from bearing_mbs.models.cylindrical_roller.name import MODEL_NAME
from bearing_mbs.models.cylindrical_roller.steady_skidding import (
    SkiddingSolution,
    orbit_power_intensity,
    solve_skidding,
)
from bearing_mbs.models.cylindrical_roller.studies.skidding import total_radial_load
from bearing_mbs.models.protocol import StudyServices
from bearing_mbs.spec import Spec, SpecError
from bearing_mbs.spec.fields import finite, positive

log = logging.getLogger(__name__)

#: Output file names (in the output directory).
CSV_FILE, TABLE_FILE, FIGURE_FILE, ROLLER_FILE = ("skidding_map.csv", "skidding_map.md", "skidding_map.png",
                                                  "roller_slip.png")
COLUMNS = ("speed_rpm", "temperature", "clearance", "radial_load", "total_load", "cage_slip",
           "max_roller_slip_loaded", "max_roller_slip_unloaded", "max_inner_slide_to_roll",
           "max_frictional_power_intensity", "max_frictional_power_intensity_inner",
           "max_frictional_power_intensity_outer", "friction_torque", "power_loss", "land_torque", "wall_time_s",
           "status", "message", "checks")
#: The rows' clearance [m] is rounded to the picometre (a preset's raceways give a zero clearance as ~1e-17 m).
PICOMETRE_DIGITS = 12
#: Line styles of the map's curves, one per clearance.
CLEARANCE_STYLES = ("-", "--", ":", "-.")


def check_grid(services: StudyServices, base: Spec, loads, temperatures, speeds, clearances=None) -> None:
    """Raise :class:`SpecError` before anything runs unless the grid is usable. ``clearances``: diametral
    clearances [m], or None for the base's own."""
    if base.scenario.model != MODEL_NAME:
        raise SpecError("scenario.model", base.scenario.model, "the skidding map varies a bearing scenario")
    if base.cage.model == "none":
        raise SpecError("cage.model", base.cage.model, "a caged bearing: the skidding balance is the cage's torque "
                        "balance")
    if base.lubricant.temperature is None:
        raise SpecError("lubricant.temperature", None, "the skidding map varies a lubricated scenario: give the "
                        "oil and its temperature in [lubricant]")
    for name, values in (("--loads", loads), ("--temperatures", temperatures), ("--speeds", speeds)):
        if not values:
            raise SpecError(name, values, "at least one value is needed")
    for load in loads:
        positive("--loads", load)
    for speed in speeds:
        positive("--speeds", speed)
    for speed in speeds:  # validate every variant before the first solve
        for temperature in temperatures:
            services.with_overrides(base, {"drive.speed_rpm": float(speed),
                                           "lubricant.temperature": float(temperature)})
    if clearances is not None and not clearances:
        raise SpecError("--clearances", clearances, "at least one value is needed")
    for clearance in clearances or ():
        finite("--clearances", clearance)
        try:  # the spec's fit checks and the builder's (a raceway must not overlap what it should not)
            services.build_scene(services.with_overrides(base, clearance_overrides(base, clearance)))
        except SpecError as error:
            raise SpecError("--clearances", clearance, f"a diametral clearance [m] this bearing accepts: {error}") \
                from None


def clearance_overrides(base: Spec, clearance: float) -> dict:
    """The overrides that give ``base`` the diametral clearance [m] about its own pitch circle: the raceways as
    pitch_diameter and diametral_clearance (a resolved spec carries its raceway diameters, which would contradict
    them)."""
    return {"bearing.inner_race_diameter": None, "bearing.outer_race_diameter": None,
            "bearing.pitch_diameter": base.bearing.pitch, "bearing.diametral_clearance": float(clearance)}


def point(services: StudyServices, base: Spec, speed: float, temperature: float, load: float,
          clearance: float | None = None) -> tuple[dict, SkiddingSolution | None]:
    """One row of the map and its solution (None where the balance has no solution; the row says why).
    ``clearance``: the diametral clearance [m], or None for the base's own."""
    overrides = {"drive.speed_rpm": float(speed), "lubricant.temperature": float(temperature),
                 "load.radial": float(load)}
    if clearance is not None:
        overrides.update(clearance_overrides(base, clearance))
    spec = services.with_overrides(base, overrides)
    row = {"speed_rpm": speed, "temperature": temperature, "clearance": round(spec.bearing.clearance, PICOMETRE_DIGITS),
           "radial_load": load, "total_load": total_radial_load(spec), "message": "", "checks": []}
    start = time.perf_counter()
    try:
        scene = services.build_scene(spec)
        solution = solve_skidding(scene)
    except (ArithmeticError, SpecError) as error:
        log.warning("no skidding balance at %g rpm, %g °C, %g N: %s", speed, temperature, load, error)
        nan = float("nan")
        row.update(cage_slip=nan, max_roller_slip_loaded=nan, max_roller_slip_unloaded=nan,
                   max_inner_slide_to_roll=nan, max_frictional_power_intensity=nan,
                   max_frictional_power_intensity_inner=nan, max_frictional_power_intensity_outer=nan,
                   friction_torque=nan, power_loss=nan, land_torque=nan,
                   status=FAILED, message=f"no skidding balance: {error}")
        row["wall_time_s"] = time.perf_counter() - start
        return row, None
    loaded = solution.inner_loads > 0
    slide_to_roll = np.abs(solution.inner_sliding / solution.inner_rolling)[loaded]
    inner, outer = (_largest(q) / W_PER_MM2 for q in orbit_power_intensity(spec, scene, solution))
    row.update(cage_slip=solution.cage_slip, max_roller_slip_loaded=_largest(solution.roller_slip[loaded]),
               max_roller_slip_unloaded=_largest(solution.roller_slip[~loaded]),
               max_inner_slide_to_roll=_largest(slide_to_roll), max_frictional_power_intensity=max(inner, outer),
               max_frictional_power_intensity_inner=inner, max_frictional_power_intensity_outer=outer,
               friction_torque=-solution.ring_torque, power_loss=solution.power_loss,
               land_torque=solution.land_torque, wall_time_s=time.perf_counter() - start, status=SUCCESS)
    return row, solution


def map_status(rows: list[dict]) -> str:
    """The map's status: its worst point's (docs/status.md)."""
    return worst_status(row["status"] for row in rows)


def _largest(values: np.ndarray) -> float:
    return float(values.max()) if values.size else 0.0


def run(services: StudyServices, base: Spec, directory: str | Path, loads, temperatures, speeds, minimum_load=None,
        figures: bool = True, progress: ProgressMeter | None = None, clearances=None) -> list[dict]:
    """Solve every point, write the outputs into ``directory`` and return the rows. ``minimum_load``: the
    catalogue minimum-load band (low, high) [N] to mark, or None. ``clearances``: diametral clearances [m], or None
    for the base's own."""
    check_grid(services, base, loads, temperatures, speeds, clearances)
    progress = progress or ProgressMeter()
    clearances = tuple(clearances) if clearances is not None else (None,)
    grid = [(c, s, t, f) for c in clearances for s in speeds for t in temperatures for f in loads]
    rows, profiles = [], {}
    for k, (clearance, speed, temperature, load) in enumerate(grid):
        progress.next_run(k + 1, len(grid))
        row, solution = point(services, base, speed, temperature, load, clearance)
        rows.append(row)
        if solution is not None and (clearance, speed, temperature) == (clearances[0], speeds[0], temperatures[0]):
            profiles[load] = solution
    directory = Path(directory)
    directory.mkdir(parents=True, exist_ok=True)
    with (directory / CSV_FILE).open("w", newline="") as handle:
        writer = csv.DictWriter(handle, COLUMNS)
        writer.writeheader()
        writer.writerows({**row, "checks": json.dumps(row["checks"])} for row in rows)
    (directory / TABLE_FILE).write_text(markdown_table(rows))
    if figures:
        title = f"{base.scenario.name}: quasi-static skidding balance"
        plot_map(rows, directory / FIGURE_FILE, minimum_load, title)
        if profiles:
            where = f", P_d = {_micrometres(rows[0]['clearance'])} µm" if len(clearances) > 1 else ""
            plot_roller_slip(profiles, directory / ROLLER_FILE,
                             f"{base.scenario.name}: {speeds[0]:g} rpm, oil at {temperatures[0]:g} °C{where}")
    return rows


def markdown_table(rows: list[dict]) -> str:
    """Cage slip [%] by load (rows) and speed × temperature (× clearance, when several) (columns), then the largest
    roller slips [%], the largest frictional power intensity [W/mm²] and the friction torque [N m]."""
    keys = sorted({(row["speed_rpm"], row["temperature"], row["clearance"]) for row in rows})
    several = len({row["clearance"] for row in rows}) > 1
    loads = sorted({row["radial_load"] for row in rows}, reverse=True)
    value = {(row["speed_rpm"], row["temperature"], row["clearance"], row["radial_load"]): row for row in rows}

    def heading(speed, temperature, clearance):
        return f"{speed:g} rpm, {temperature:g} °C" + (f", P_d {_micrometres(clearance)} µm" if several else "")

    lines = []
    tables = (("cage slip [%]", "cage_slip", 100.0),
              ("largest roller slip in the load zone [%]", "max_roller_slip_loaded", 100.0),
              ("largest roller slip out of the load zone [%]", "max_roller_slip_unloaded", 100.0),
              ("largest frictional power intensity of a raceway contact [W/mm²]", "max_frictional_power_intensity",
               1.0),
              ("friction torque [N m]", "friction_torque", 1.0))
    for title, field, scale in tables:
        lines += [f"{title}:", "", "| radial load [N] | " + " | ".join(heading(*key) for key in keys) + " |",
                  "|---:|" + "---:|" * len(keys)]
        for load in loads:
            cells = [f"{scale * value[(*key, load)][field]:.3g}" for key in keys]
            lines.append(f"| {load:g} | " + " | ".join(cells) + " |")
        lines.append("")
    failed = [row for row in rows if row["status"] != SUCCESS]
    lines += [f"status: {map_status(rows)} ({len(failed)} of {len(rows)} points without a balance; docs/status.md)"]
    lines += [f"- {heading(row['speed_rpm'], row['temperature'], row['clearance'])}, {row['radial_load']:g} N: "
              f"{row['message']}" for row in failed]
    return "\n".join(lines) + "\n"


def _micrometres(length: float) -> str:
    return f"{1e6 * length:.4g}"


def plot_map(rows: list[dict], path: Path, minimum_load, title: str = "") -> Path:
    """Cage slip against total load: a panel per speed, a colour per temperature and, when the rows hold several
    clearances, a line style per clearance (:data:`CLEARANCE_STYLES`, repeated beyond four)."""
    speeds = sorted({row["speed_rpm"] for row in rows})
    temperatures = sorted({row["temperature"] for row in rows})
    clearances = sorted({row["clearance"] for row in rows})
    figure, axes = new_figure(1, len(speeds), figsize=(4.2 * len(speeds), 4.2), sharey=True, squeeze=False)
    for axis, speed in zip(axes[0], speeds):
        for (n, temperature), (m, clearance) in itertools.product(enumerate(temperatures), enumerate(clearances)):
            chosen = sorted((row for row in rows if (row["speed_rpm"], row["temperature"], row["clearance"]) ==
                             (speed, temperature, clearance)), key=lambda row: row["total_load"])
            label = f"oil at {temperature:g} °C"
            if len(clearances) > 1:
                label += f", P_d = {_micrometres(clearance)} µm"
            axis.plot([row["total_load"] for row in chosen], [100 * row["cage_slip"] for row in chosen], "o",
                      linestyle=CLEARANCE_STYLES[m % len(CLEARANCE_STYLES)], color=f"C{n}", label=label)
        if minimum_load is not None:
            axis.axvspan(*minimum_load, color="0.85", zorder=0, label="catalogue minimum load")
        axis.set_xscale("log")
        axis.set_yscale("log")
        axis.set_title(f"{speed:g} rpm")
        axis.set_xlabel("total radial load [N]")
        axis.grid(True, which="both", alpha=0.3)
    axes[0][0].set_ylabel("cage slip [%]")
    axes[0][0].legend(fontsize="small", loc="lower left")
    figure.suptitle(title)
    return save_figure(figure, path, dpi=100)


def plot_roller_slip(profiles: dict[float, SkiddingSolution], path: Path, title: str = "") -> Path:
    figure, axis = new_figure(figsize=(6.5, 4.0))
    for n, (load, solution) in enumerate(sorted(profiles.items(), reverse=True)):
        degrees = np.degrees(solution.roller_angles)
        axis.plot(degrees, 100 * solution.roller_slip, color=f"C{n}", label=f"{load:g} N")
        loaded = np.where(solution.inner_loads > 0, 1.0, np.nan)
        axis.plot(degrees, 100 * loaded * solution.roller_slip, color=f"C{n}", linewidth=3)
    axis.set_ylabel("roller slip: spin deficit in the cage [%]")
    axis.set_xlabel("roller azimuth [deg] (thick: in the load zone)")
    axis.legend(fontsize="small", title="radial load")
    axis.grid(True, alpha=0.3)
    axis.set_title(title)
    return save_figure(figure, path, dpi=100)
