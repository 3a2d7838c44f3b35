"""Cage-model comparison: the same bearing scenario with a penalty cage, a constraint cage and no cage.

``bearing-mbs cage-models SCENARIO.toml --out DIR`` runs :func:`run`: the base scenario (e.g.
``scenarios/cage_models.toml``) once per case of :data:`CASES` (the three cage models, guided as the base says)
and, unless told otherwise, of :data:`ROLLER_GUIDED` (the two caged models guided by their rollers only, drawn
dashed); it writes the comparison table as ``cage_models.md`` and ``cage_models.csv`` (:data:`COLUMNS`) and two
figures, ``cage_models_slip.png`` (cage slip against time) and ``cage_models_loads.png`` (roller load against
orbital angle).

Each row carries its run's ``status`` and ``checks`` (docs/status.md) with the ``window_settled`` check of its
analysis window (:mod:`.settling`); the comparison's status is its worst run's.
"""

from __future__ import annotations

import csv
import json
import logging
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from bearing_mbs.core.progress import ProgressMeter
from bearing_mbs.core.status import failed_check_names, worst_status
from bearing_mbs.io.figures import new_figure, save_figure
from bearing_mbs.models.cylindrical_roller.figures import cage_slip_series
from bearing_mbs.models.cylindrical_roller.metrics import load_distribution, roller_indices, window
from bearing_mbs.models.cylindrical_roller.name import MODEL_NAME
from bearing_mbs.models.cylindrical_roller.studies.settling import window_settled
from bearing_mbs.models.protocol import StudyServices
from bearing_mbs.spec import Spec, SpecError

log = logging.getLogger(__name__)

MODELS = ("penalty", "constraint", "none")
#: The comparison's cases: label -> fields of the base scenario to change (one case per cage model).
CASES = {model: {"cage.model": model} for model in MODELS}
#: The caged models guided by their rollers only, without the base's land (drawn dashed).
ROLLER_GUIDED = {f"{model}, roller-guided": {"cage.model": model, "bearing.cage_guidance": "rollers"}
                 for model in ("penalty", "constraint")}
#: Output file names (in the output directory).
TABLE_FILE, CSV_FILE = "cage_models.md", "cage_models.csv"
SLIP_FIGURE, LOADS_FIGURE = "cage_models_slip.png", "cage_models_loads.png"

#: Table columns: (key, heading, scale applied to the summary value).
COLUMNS = (
    ("model", "cage model", None),
    ("cage_slip", "cage slip [%]", 100.0),
    ("max_pocket_force", "max pocket force [N]", 1.0),
    ("max_roller_load", "steady max roller load [N]", 1.0),
    ("max_impact_load", "max impact load [N]", 1.0),
    ("inner_ring_displacement", "inner-ring displacement [µm]", 1e6),
    ("max_cage_excursion", "max cage eccentricity [µm]", 1e6),
    ("wall_time_s", "wall time [s]", 1.0),
    ("steps", "steps", None),
    ("force_evaluations", "force evaluations", None),
    ("energy_balance_error", "energy balance error [-]", 1.0),
    ("status", "status", None),
    ("failed_checks", "failed checks", None),
)


@dataclass
class ModelRun:
    """One case's run and its summary (see :func:`bearing_mbs.runner.summarize`); ``model`` is the case's label."""

    model: str
    spec: Spec
    scene: object
    result: object
    summary: dict


def compare(services: StudyServices, base: Spec, cases: dict[str, dict] | None = None,
            progress: ProgressMeter | None = None) -> tuple[list[dict], list[ModelRun]]:
    """Run ``base`` once per case of ``cases`` (label -> fields to change; default :data:`CASES`); returns the
    table rows (one dict per case, keyed as :data:`COLUMNS`, values in SI units) and the runs. Every case is
    validated before the first run (``services``: :class:`~bearing_mbs.models.protocol.StudyServices`)."""
    if base.scenario.model != MODEL_NAME:
        raise SpecError("scenario.model", base.scenario.model, "the cage-model comparison varies a bearing scenario")
    cases = CASES if cases is None else cases
    specs = {label: services.with_overrides(base, changes) for label, changes in cases.items()}
    progress = progress or ProgressMeter()
    runs = []
    for k, (label, spec) in enumerate(specs.items()):
        progress.next_run(k + 1, len(specs))
        scene, result = services.run_spec(spec, progress)
        if result.completed:
            result.checks = (*result.checks, window_settled(spec, scene, result))
        runs.append(ModelRun(label, spec, scene, result, services.summarize(spec, scene, result)))
        log.info("%s: cage slip %s (%s)", label, runs[-1].summary.get("cage_slip"), runs[-1].summary["status"])
    return [table_row(r) for r in runs], runs


def table_row(run: ModelRun) -> dict:
    """The comparison quantities of one run (SI units); ``max_cage_excursion`` is the summary's
    ``max_cage_eccentricity``, the largest distance of the cage centre from the axis over the run (None
    without a cage)."""
    row = {key: run.summary.get(key) for key, _, _ in COLUMNS if key != "max_cage_excursion"}
    row["model"] = run.model
    row["max_cage_excursion"] = run.summary.get("max_cage_eccentricity")
    row["status"] = run.summary["status"]
    row["checks"] = run.summary["checks"]
    row["failed_checks"] = ", ".join(failed_check_names(run.summary["checks"])) or "—"
    row["warnings"] = run.summary.get("warnings") or []
    return row


def comparison_status(rows: list[dict]) -> str:
    """The comparison's status: its worst run's (docs/status.md)."""
    return worst_status(row["status"] for row in rows)


def markdown_table(rows: list[dict]) -> str:
    """The rows as a Markdown table in the units of the headings."""
    lines = ["| " + " | ".join(heading for _, heading, _ in COLUMNS) + " |",
             "|" + "|".join("---" if scale is None else "---:" for _, _, scale in COLUMNS) + "|"]
    for row in rows:
        lines.append("| " + " | ".join(_cell(row[key], scale) for key, _, scale in COLUMNS) + " |")
    return "\n".join(lines) + "\n"


def write_csv(rows: list[dict], path: Path) -> Path:
    """The rows as CSV, in the units of the headings, with each run's checks as JSON (last column)."""
    with Path(path).open("w", newline="") as handle:
        writer = csv.writer(handle)
        writer.writerow([heading for _, heading, _ in COLUMNS] + ["checks"])
        for row in rows:
            writer.writerow(["" if row[key] is None else row[key] if scale is None else row[key] * scale
                             for key, _, scale in COLUMNS] + [json.dumps(row["checks"])])
    return Path(path)


def plot_cage_slip(runs: list[ModelRun], path: Path) -> Path:
    """Cage slip [%] of every case against time [s] in one plot."""
    figure, axis = new_figure(figsize=(7.0, 3.8))
    for n, r in enumerate(runs):
        axis.plot(r.result.time, 100 * cage_slip_series(r.spec, r.scene, r.result), _line_style(r),
                  color=f"C{n}", linewidth=0.9, label=f"{r.model} (mean {100 * r.summary['cage_slip']:.3g} %)")
    last = runs[-1]
    start = last.result.time[window(last.spec, last.result)][0]
    axis.axvspan(start, last.result.time[-1], color="grey", alpha=0.12, linewidth=0, label="analysis window")
    axis.axhline(0.0, color="grey", linewidth=0.6)
    axis.set_xlabel("time [s]")
    axis.set_ylabel("cage slip 1 − ω_c/ω_c,epi [%]")
    axis.set_title(f"{runs[0].spec.scenario.name}: cage slip by cage model")
    axis.grid(True, alpha=0.3)
    axis.legend(fontsize="small")
    return save_figure(figure, path, dpi=100)


def plot_roller_loads(runs: list[ModelRun], path: Path) -> Path:
    """Mean inner-raceway roller load [N] against orbital angle [deg] over the analysis window, per case."""
    figure, axis = new_figure(figsize=(7.0, 3.8))
    for n, r in enumerate(runs):
        bins = 2 * roller_indices(r.scene).size
        angles, loads = load_distribution(r.scene, r.result, window(r.spec, r.result), bins)
        axis.plot(angles, loads, "o" + _line_style(r), color=f"C{n}", markersize=3, label=r.model)
    axis.set_xlim(0.0, 360.0)
    axis.set_xticks(np.arange(0, 361, 45))
    axis.set_xlabel("orbital angle ψ [deg] (0 along +x, counter-clockwise; load towards 270°)")
    axis.set_ylabel("mean inner-raceway load [N]")
    axis.set_title(f"{runs[0].spec.scenario.name}: roller loads by cage model")
    axis.grid(True, alpha=0.3)
    axis.legend(fontsize="small")
    return save_figure(figure, path, dpi=100)


def write(rows: list[dict], runs: list[ModelRun], directory: str | Path, figures: bool = True) -> list[Path]:
    """Write the Markdown table, the CSV and (``figures``) the two figures into ``directory``; returns their
    paths."""
    directory = Path(directory)
    directory.mkdir(parents=True, exist_ok=True)
    table = directory / TABLE_FILE
    others = sum(row["status"] != "success" for row in rows)
    table.write_text(markdown_table(rows) + f"\nstatus: {comparison_status(rows)} ({others} of {len(rows)} runs not "
                                            "success; docs/status.md)\n")
    paths = [table, write_csv(rows, directory / CSV_FILE)]
    if figures:
        paths += [plot_cage_slip(runs, directory / SLIP_FIGURE), plot_roller_loads(runs, directory / LOADS_FIGURE)]
    return paths


def run(services: StudyServices, base: Spec, directory: str | Path, roller_guided: bool = True, figures: bool = True,
        progress: ProgressMeter | None = None) -> list[dict]:
    """:func:`compare` the cases of :data:`CASES` (and of :data:`ROLLER_GUIDED` when ``roller_guided``), then
    :func:`write` the outputs into ``directory``; returns the table rows. The runs' warnings are logged."""
    rows, runs = compare(services, base, {**CASES, **ROLLER_GUIDED} if roller_guided else CASES, progress)
    write(rows, runs, directory, figures)
    for row in rows:
        for warning in row["warnings"]:
            log.warning("%s: %s", row["model"], warning)
    return rows


def _line_style(run: ModelRun) -> str:
    """Dashed for a cage guided by its rollers only, solid otherwise."""
    return "--" if run.spec.bearing.cage_guidance == "rollers" and run.spec.cage.model != "none" else "-"


def _cell(value, scale) -> str:
    if value is None:
        return "—"
    if isinstance(value, str):
        return value
    if scale is None:
        return f"{value:d}" if isinstance(value, int) else f"{value:g}"
    return f"{value * scale:.3g}"
