"""Cage-model comparison: the same scenario with a penalty cage, a constraint cage and no cage.

``run()`` simulates ``cage_models.toml`` (or another base) once per case of :data:`CASES` (by default the three
cage models, guided as the base says: on the outer-ring land) and returns the comparison table; ``main()`` adds
the two caged models guided by their rollers only (:data:`ROLLER_GUIDED`), and writes the table as Markdown
and CSV with two figures (cage slip against time, roller load against orbital angle). The write-up is
docs/cage-models.md.

    python scenarios/cage_models.py                      # writes into docs/figures/
    python scenarios/cage_models.py --out out/cage --set scenario.end_time=0.05 --set analysis.start=0.02
"""

from __future__ import annotations

import argparse
import csv
import logging
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from bearing_mbs.models.cylindrical_roller.metrics import load_distribution, roller_indices, window
from bearing_mbs.models.cylindrical_roller.figures import cage_slip_series
from bearing_mbs.runner import run_spec, summarize
from bearing_mbs.models import load_spec

BASE = Path(__file__).with_name("cage_models.toml")
OUT = Path(__file__).resolve().parents[1] / "docs" / "figures"
MODELS = ("penalty", "constraint", "none")
#: The comparison's cases: label -> overrides of the base scenario (by default one per cage model).
CASES = {model: (f"cage.model={model}",) for model in MODELS}
#: The caged models guided by their rollers only, without the base's land (drawn dashed).
ROLLER_GUIDED = {f"{model}, roller-guided": (f"cage.model={model}", "bearing.cage_guidance=rollers")
                 for model in ("penalty", "constraint")}

#: Table columns: (key, heading, scale applied to the summary value).
COLUMNS = (
    ("model", "cage model", None),
    ("cage_slip", "cage slip [%]", 100.0),
    ("max_pocket_force", "max pocket force [N]", 1.0),
    ("max_roller_load", "max roller load [N]", 1.0),
    ("inner_ring_displacement", "inner-ring displacement [µm]", 1e6),
    ("max_cage_excursion", "max cage eccentricity [µm]", 1e6),
    ("wall_time_s", "wall time [s]", 1.0),
    ("steps", "steps", None),
    ("force_evaluations", "force evaluations", None),
    ("energy_balance_error", "energy balance error [-]", 1.0),
)


@dataclass
class ModelRun:
    """One case's run and its summary (see :func:`bearing_mbs.runner.summarize`); ``model`` is the case's label."""

    model: str
    spec: object
    scene: object
    result: object
    summary: dict


def run(overrides: tuple[str, ...] = (), base: str | Path = BASE,
        cases: dict[str, tuple[str, ...]] | None = None) -> tuple[list[dict], list[ModelRun]]:
    """Run ``base`` once per case of ``cases`` (default :data:`CASES`; ``overrides`` apply to all); returns
    the table rows (one dict per case, keyed as :data:`COLUMNS`, values in SI) and the runs."""
    runs = []
    for label, selection in (CASES if cases is None else cases).items():
        spec = load_spec(base, [*overrides, *selection])
        scene, result = run_spec(spec)
        runs.append(ModelRun(label, spec, scene, result, summarize(spec, scene, result)))
    return [table_row(r) for r in runs], runs


def table_row(run: ModelRun) -> dict:
    """The comparison quantities of one run (SI units); ``max_cage_excursion`` is the summary's
    ``max_cage_eccentricity``, the largest distance of the cage centre from the axis over the run (None
    without a cage)."""
    row = {key: run.summary.get(key) for key, _, _ in COLUMNS if key != "max_cage_excursion"}
    row["model"] = run.model
    row["max_cage_excursion"] = run.summary.get("max_cage_eccentricity")
    row["status"] = run.summary["status"]
    row["warnings"] = run.summary.get("warnings") or []
    return row


def markdown_table(rows: list[dict]) -> str:
    """The rows as a Markdown table in the units of the headings."""
    lines = ["| " + " | ".join(heading for _, heading, _ in COLUMNS) + " |",
             "|" + "|".join("---" if scale is None else "---:" for _, _, scale in COLUMNS) + "|"]
    for row in rows:
        lines.append("| " + " | ".join(_cell(row[key], scale) for key, _, scale in COLUMNS) + " |")
    return "\n".join(lines) + "\n"


def write_csv(rows: list[dict], path: Path) -> Path:
    """The rows as CSV, in the units of the headings."""
    with path.open("w", newline="") as handle:
        writer = csv.writer(handle)
        writer.writerow([heading for _, heading, _ in COLUMNS])
        for row in rows:
            writer.writerow(["" if row[key] is None else row[key] if scale is None else row[key] * scale
                             for key, _, scale in COLUMNS])
    return path


def plot_cage_slip(runs: list[ModelRun], path: Path) -> Path:
    """Cage slip [%] of every model against time [s] in one plot."""
    figure, axis = _figure((7.0, 3.8))
    for n, r in enumerate(runs):
        axis.plot(r.result.time, 100 * cage_slip_series(r.spec, r.scene, r.result), _line_style(r),
                  color=f"C{n}", linewidth=0.9, label=f"{r.model} (mean {100 * r.summary['cage_slip']:.3g} %)")
    start = r.result.time[window(r.spec, r.result)][0]
    axis.axvspan(start, r.result.time[-1], color="grey", alpha=0.12, linewidth=0, label="analysis window")
    axis.axhline(0.0, color="grey", linewidth=0.6)
    axis.set_xlabel("time [s]")
    axis.set_ylabel("cage slip 1 − ω_c/ω_c,epi [%]")
    axis.set_title(f"{runs[0].spec.scenario.name}: cage slip by cage model")
    axis.grid(True, alpha=0.3)
    axis.legend(fontsize="small")
    return _save(figure, path)


def plot_roller_loads(runs: list[ModelRun], path: Path) -> Path:
    """Mean inner-raceway roller load [N] against orbital angle [deg] over the analysis window, per model."""
    figure, axis = _figure((7.0, 3.8))
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
    return _save(figure, path)


def main(argv: list[str] | None = None) -> list[dict]:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--base", default=str(BASE), help="base scenario TOML")
    parser.add_argument("--out", default=str(OUT), help="directory for the table and figures")
    parser.add_argument("--set", action="append", default=[], metavar="SECTION.KEY=VALUE",
                        help="override a field of the base scenario (repeatable)")
    args = parser.parse_args(argv)
    logging.basicConfig(level=logging.WARNING)
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    rows, runs = run(tuple(args.set), args.base, {**CASES, **ROLLER_GUIDED})
    table = markdown_table(rows)
    (out / "cage_models.md").write_text(table)
    write_csv(rows, out / "cage_models.csv")
    plot_cage_slip(runs, out / "cage_models_slip.png")
    plot_roller_loads(runs, out / "cage_models_loads.png")
    print(table)
    for row in rows:
        for warning in row["warnings"]:
            print(f"warning ({row['model']}): {warning}")
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


def _figure(size):
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure

    figure = Figure(figsize=size)
    FigureCanvasAgg(figure)
    return figure, figure.add_subplot()


def _save(figure, path: Path) -> Path:
    figure.tight_layout()
    figure.savefig(path, dpi=100)
    return path


if __name__ == "__main__":
    main()
