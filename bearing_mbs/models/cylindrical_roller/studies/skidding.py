r"""Cage slip against radial load: does the cage skid more as the load falls?

Field measurements on wind-turbine high-speed-shaft bearings and the skidding literature say it does: the rollers
and cage are slowed by load-independent drag, while the traction that drives them scales with the load (Jain &
Hunt 2011, Jain 2012, Han, Li & Chu 2018). In the model the load-independent drag is the lubricant's on the rollers
(``[lubricant]``: Palmgren's M0, or the churning drag of an oil–air mixture).

``bearing-mbs skidding SCENARIO.toml --out DIR`` runs :func:`run`: the base scenario (a bearing at constant
speed, e.g. ``scenarios/seed_hss_steady.toml``) at each radial load of :data:`LOADS` with each cage model of
:data:`CAGES`; it writes ``skidding_vs_load.csv`` (a row per run, :data:`COLUMNS`), ``skidding_vs_load.md`` (the
table and the trend of each cage) and ``skidding_vs_load.png`` (cage slip against load, log axes). The total
radial load on the bearing is the applied load plus the weight of the inner ring and its supported shaft mass.

Each row also gives the steady cage slip of the quasi-static skidding balance
(:mod:`bearing_mbs.models.cylindrical_roller.steady_skidding`) with the same laws: the value a run converges to.
At light load the cage and rollers approach it with a time constant of the order of a second (the drive there is
weak), so a short run reads less slip; compare the window halves.

The penalty cage's slip averaged over a window of duration T is only resolved to about
:func:`.settling.pocket_play_resolution`: the cage may shift by the pocket clearance H relative
to the rollers, an angle of about 2H/(D_pw/2), whatever the true slip. The constraint cage has no play
(resolution 0).

Each row carries its run's ``status`` and ``checks`` (docs/status.md) with the ``window_settled`` check
(:mod:`.settling`): a window whose cage slip has not settled makes its run ``suspect``. The
study's status is its worst run's (:func:`study_status`).
"""

from __future__ import annotations

import csv
import json
import logging
from pathlib import Path

import numpy as np

from bearing_mbs.core.progress import ProgressMeter
from bearing_mbs.core.status import failed_check_names, worst_status
from bearing_mbs.io.figures import new_figure, save_figure
from bearing_mbs.models.cylindrical_roller.geometry import BearingGeometry
from bearing_mbs.models.cylindrical_roller.name import MODEL_NAME
from bearing_mbs.models.cylindrical_roller.steady_skidding import solve_skidding
from bearing_mbs.models.cylindrical_roller.studies.settling import pocket_play_resolution, window_halves, window_settled
from bearing_mbs.models.protocol import StudyServices
from bearing_mbs.spec import Spec, SpecError
from bearing_mbs.spec.fields import positive

log = logging.getLogger(__name__)

#: Radial loads [N]: the seed bearing's nominal 68 kN down to 0.3 % of it.
LOADS = (68000.0, 6800.0, 2000.0, 680.0, 200.0)
#: Cage models swept by :func:`sweep`, each with the fields that select it.
CAGES = {
    "penalty": {"cage.model": "penalty"},
    "constraint": {"cage.model": "constraint"},
}
#: Output file names (in the output directory).
CSV_FILE, TABLE_FILE, FIGURE_FILE = "skidding_vs_load.csv", "skidding_vs_load.md", "skidding_vs_load.png"

COLUMNS = ("cage_model", "radial_load", "total_load", "load_fraction", "cage_slip", "cage_slip_first_half",
           "cage_slip_second_half", "quasi_static_slip", "resolution", "settled", "max_roller_slip_inner", "max_roller_load",
           "max_pocket_force", "max_cage_eccentricity", "wall_time_s", "steps", "status", "warnings", "checks")


def check_base(base: Spec, loads) -> None:
    """Raise :class:`SpecError` unless ``base`` is a bearing scenario and every load [N] is positive."""
    if base.scenario.model != MODEL_NAME:
        raise SpecError("scenario.model", base.scenario.model, "the skidding sweep varies a bearing scenario")
    if not loads:
        raise SpecError("loads", loads, "at least one radial load is needed")
    for load in loads:
        positive("loads", load)


def sweep_loads(services: StudyServices, base: Spec, loads=LOADS, progress: ProgressMeter | None = None,
                counted=(0, 0)) -> list[dict]:
    """Run ``base`` at each radial load of ``loads`` [N] with its own cage model; one row per load (keys:
    :data:`COLUMNS`): loads [N], cage slip (window mean and its two halves) [-], the resolution of the window
    [-], largest inner-raceway slip ratio [-], largest roller and pocket force [N], largest cage eccentricity
    [m], cost and status. ``load_fraction`` is the load over the base scenario's. ``counted``: (runs before
    these, runs in the whole study), for the progress meter."""
    check_base(base, loads)
    progress = progress or ProgressMeter()
    before, total = counted if counted[1] else (0, len(loads))
    rows = []
    for k, load in enumerate(loads):
        spec = services.with_overrides(base, {"load.radial": float(load)})
        progress.next_run(before + k + 1, total)
        scene, result = services.run_spec(spec, progress)
        rows.append(sweep_row(services, spec, scene, result, base.load.radial))
        log.info("%s cage, %g N: cage slip %.4g (%s)", spec.cage.model, load, rows[-1]["cage_slip"],
                 rows[-1]["status"])
    return rows


def sweep(services: StudyServices, base: Spec, loads=LOADS, cages: dict[str, dict] | None = None,
          progress: ProgressMeter | None = None) -> dict[str, list[dict]]:
    """:func:`sweep_loads` for each cage model of ``cages`` (name -> fields that select it; default
    :data:`CAGES`): {cage model: rows}."""
    cages = CAGES if cages is None else cages
    check_base(base, loads)
    variants = {name: services.with_overrides(base, selection) for name, selection in cages.items()}  # validated first
    total = len(variants) * len(loads)
    return {name: sweep_loads(services, spec, loads, progress, (k * len(loads), total))
            for k, (name, spec) in enumerate(variants.items())}


def sweep_row(services: StudyServices, spec: Spec, scene, result, nominal_load: float) -> dict:
    """One row of the sweep (see :func:`sweep_loads`); the run's checks get ``window_settled`` (a run that stopped
    early has no checks: its failure says why)."""
    settled = window_settled(spec, scene, result) if result.completed else None
    if settled is not None:
        result.checks = (*result.checks, settled)
    summary = services.summarize(spec, scene, result)
    first, second, duration = window_halves(spec, scene, result)
    return {
        "cage_model": spec.cage.model,
        "radial_load": spec.load.radial,
        "total_load": total_radial_load(spec),
        "load_fraction": spec.load.radial / nominal_load if nominal_load else float("nan"),
        "cage_slip": summary["cage_slip"],
        "cage_slip_first_half": first,
        "cage_slip_second_half": second,
        "quasi_static_slip": quasi_static_slip(scene),
        "resolution": pocket_play_resolution(spec, duration),
        "settled": settled is not None and settled.passed,
        "max_roller_slip_inner": summary["max_roller_slip_inner"],
        "max_roller_load": summary["max_roller_load"],
        "max_pocket_force": summary["max_pocket_force"],
        "max_cage_eccentricity": summary["max_cage_eccentricity"],
        "wall_time_s": summary["wall_time_s"],
        "steps": summary["steps"],
        "status": summary["status"],
        "warnings": "; ".join(summary.get("warnings") or ()),
        "checks": summary["checks"],
    }


def study_status(sweeps: dict[str, list[dict]]) -> str:
    """The study's status: its worst run's (docs/status.md)."""
    return worst_status(row["status"] for rows in sweeps.values() for row in rows)


def quasi_static_slip(scene) -> float:
    """The steady cage slip [-] of the quasi-static skidding balance, NaN (logged) where it has none."""
    try:
        return solve_skidding(scene).cage_slip
    except (ArithmeticError, SpecError) as error:
        log.warning("no quasi-static skidding balance for %s: %s", scene.name, error)
        return float("nan")


def total_radial_load(spec: Spec) -> float:
    """|applied radial load + weight of the inner ring and supported mass| [N] (constant-load scenarios)."""
    geometry = BearingGeometry.from_spec(spec.bearing)
    angle = np.radians(spec.load.angle)
    force = spec.load.radial * np.array([np.cos(angle), np.sin(angle)])
    force[1] -= geometry.inner_ring_mass * spec.scenario.gravity
    return float(np.hypot(*force))


def trend(rows: list[dict]) -> dict:
    """Is the cage slip larger at lower load? ``monotone``: it grows at every step down in load;
    ``ratio``: slip at the lowest load over slip at the highest; ``margin``: their difference over the
    resolution of the window (inf for a cage without play)."""
    ordered = sorted(rows, key=lambda row: -row["radial_load"])
    slips = np.array([row["cage_slip"] for row in ordered])
    return {
        "monotone": bool(np.all(np.diff(slips) > 0)),
        "ratio": float(slips[-1] / slips[0]) if slips[0] != 0 else float("inf"),
        "margin": float((slips[-1] - slips[0]) / max(row["resolution"] for row in ordered))
        if any(row["resolution"] for row in ordered) else float("inf"),
    }


def plot_slip_against_load(sweeps: dict[str, list[dict]], path: Path, title: str = "") -> Path:
    """Cage slip [%] against total radial load [N], one curve per cage model (log axes), with the halves of
    each window as a bar and the quasi-static balance dashed and, around the penalty curve, the pocket-play
    resolution of the window as a band;
    the largest inner-raceway slip ratio below."""
    figure, (cage, rollers) = new_figure(2, 1, figsize=(6.5, 6.0), sharex=True)
    styles = {"penalty": ("C0", "o"), "constraint": ("C1", "s")}
    all_slips = []
    for n, (name, rows) in enumerate(sweeps.items()):
        color, marker = styles.get(name, (f"C{n + 2}", "^"))
        rows = sorted(rows, key=lambda row: row["total_load"])
        load = np.array([row["total_load"] for row in rows])
        slip = 100 * np.array([row["cage_slip"] for row in rows])
        halves = 100 * np.array([[row["cage_slip_first_half"], row["cage_slip_second_half"]] for row in rows])
        resolution = 100 * np.array([row["resolution"] for row in rows])
        all_slips.extend([*slip, *halves.ravel()])
        if resolution.any():
            cage.fill_between(load, np.clip(slip - resolution, 1e-6, None), slip + resolution, color=color,
                              alpha=0.15, linewidth=0,
                              label=f"{name}: ± pocket-play resolution ({resolution.max():.2g} %)")
        cage.vlines(load, halves.min(axis=1), halves.max(axis=1), color=color, alpha=0.6, linewidth=2)
        cage.plot(load, slip, marker + "-", color=color, label=f"{name} cage (bars: window halves)")
        cage.plot(load, 100 * np.array([row["quasi_static_slip"] for row in rows]), marker + "--", color=color,
                  fillstyle="none", label=f"{name} cage, quasi-static balance")
        rollers.plot(load, [row["max_roller_slip_inner"] or np.nan for row in rows], marker + "-", color=color,
                     label=f"{name} cage")
    cage.set_yscale("log" if min(all_slips) > 0 else "symlog")
    cage.set_ylabel("cage slip [%]")
    cage.legend(fontsize="small", loc="lower left")
    rollers.set_ylabel("largest inner-raceway\nslip ratio [-]")
    rollers.set_yscale("log")
    rollers.legend(fontsize="small", loc="lower left")
    rollers.set_xlabel("total radial load on the bearing [N] (applied + inner-ring and shaft weight)")
    rollers.set_xscale("log")
    loads = [row["total_load"] for rows in sweeps.values() for row in rows]
    rollers.set_xlim(min(loads) / 1.5, max(loads) * 1.5)
    for axis in (cage, rollers):
        axis.grid(True, which="both", alpha=0.3)
    cage.set_title(title)
    return save_figure(figure, path, dpi=100)


def markdown_table(sweeps: dict[str, list[dict]]) -> str:
    """All rows as a Markdown table (slips in %), each with its run's status and failed checks."""
    lines = ["| cage | radial load [N] | total load [N] | cage slip [%] | window halves [%] | quasi-static [%] | "
             "resolution [%] | settled | largest inner-raceway slip ratio | max roller load [N] | "
             "max pocket force [N] | max cage eccentricity [µm] | wall [s] | status | failed checks |",
             "|---|---:|---:|---:|---:|---:|---:|---|---:|---:|---:|---:|---:|---|---|"]
    for name, rows in sweeps.items():
        for row in rows:
            lines.append(
                f"| {name} | {row['radial_load']:g} | {row['total_load']:.0f} | {100 * row['cage_slip']:.3g} | "
                f"{100 * row['cage_slip_first_half']:.3g}, {100 * row['cage_slip_second_half']:.3g} | "
                f"{100 * row['quasi_static_slip']:.3g} | {100 * row['resolution']:.3g} | "
                f"{'yes' if row['settled'] else 'no'} | "
                f"{_number(row['max_roller_slip_inner']):.3g} | {row['max_roller_load']:.0f} | "
                f"{_number(row['max_pocket_force']):.0f} | "
                f"{1e6 * _number(row['max_cage_eccentricity']):.0f} | {row['wall_time_s']:.1f} | {row['status']} | "
                f"{', '.join(failed_check_names(row['checks'])) or '—'} |")
    return "\n".join(lines) + "\n"


def status_text(sweeps: dict[str, list[dict]]) -> str:
    """The study's status line: its worst run's, and how many runs are not ``success``."""
    rows = [row for rows in sweeps.values() for row in rows]
    others = sum(row["status"] != "success" for row in rows)
    return f"status: {study_status(sweeps)} ({others} of {len(rows)} runs not success; docs/status.md)\n"


def _number(value) -> float:
    """A table's value: NaN for a quantity the run does not have (None), the value otherwise, zero included."""
    return float("nan") if value is None else value


def trend_text(sweeps: dict[str, list[dict]]) -> str:
    """One line per cage model: :func:`trend` in words."""
    lines = []
    for name, rows in sweeps.items():
        found = trend(rows)
        lines.append(f"{name} cage: slip {'grows' if found['monotone'] else 'does not grow'} at every step down "
                     f"in load; lowest-load / highest-load slip {found['ratio']:.3g}; difference "
                     f"{found['margin']:.3g} × the pocket-play resolution")
    return "\n".join(lines) + "\n"


def write(sweeps: dict[str, list[dict]], directory: str | Path, title: str = "", figures: bool = True) -> list[Path]:
    """Write the CSV, the Markdown table with the trends and (``figures``) the figure into ``directory``;
    returns their paths."""
    directory = Path(directory)
    directory.mkdir(parents=True, exist_ok=True)
    table = directory / CSV_FILE
    with table.open("w", newline="") as handle:
        writer = csv.DictWriter(handle, COLUMNS)
        writer.writeheader()
        for rows in sweeps.values():
            writer.writerows({**row, "checks": json.dumps(row["checks"])} for row in rows)
    markdown = directory / TABLE_FILE
    markdown.write_text(markdown_table(sweeps) + "\n" + trend_text(sweeps) + "\n" + status_text(sweeps))
    paths = [table, markdown]
    if figures:
        paths.append(plot_slip_against_load(sweeps, directory / FIGURE_FILE, title))
    return paths


def run(services: StudyServices, base: Spec, directory: str | Path, loads=LOADS, cages: dict[str, dict] | None = None,
        figures: bool = True, progress: ProgressMeter | None = None) -> dict[str, list[dict]]:
    """:func:`sweep` the base scenario, then :func:`write` the outputs into ``directory``; returns the rows
    by cage model. Rows that did not settle or carry warnings are logged."""
    sweeps = sweep(services, base, loads, cages, progress)
    title = (f"{base.scenario.name}: {base.drive.speed_rpm:g} rpm, cage guidance "
             f"{base.bearing.cage_guidance}")
    write(sweeps, directory, title, figures)
    for name, rows in sweeps.items():
        for row in rows:
            if not row["settled"]:
                log.warning("%s cage, %g N: the cage slip has not settled (window halves %.3g, %.3g; the "
                            "quasi-static balance gives %.3g): run longer", name, row["radial_load"],
                            row["cage_slip_first_half"], row["cage_slip_second_half"], row["quasi_static_slip"])
            if row["warnings"]:
                log.warning("%s cage, %g N: %s", name, row["radial_load"], row["warnings"])
    return sweeps
