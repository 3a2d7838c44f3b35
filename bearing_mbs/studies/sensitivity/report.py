"""The study report: a Markdown page with the SALib indices and their confidence intervals, the Morris
μ*–σ and Sobol bar figures, scatter plots of every output against every parameter, and the table of runs
(``runs.csv``, all columns; the first rows inline)."""

from __future__ import annotations

import math
import re
from pathlib import Path

import matplotlib.ticker
import numpy as np
import pandas as pd

from bearing_mbs.core.status import worst_status
from bearing_mbs.io.figures import new_figure, save_figure
from bearing_mbs.studies.sensitivity.analysis import Indices
from bearing_mbs.studies.sensitivity.study import Study

REPORT_FILE = "report.md"
RUNS_FILE = "runs.csv"
#: Runs listed inline in the report (all are in runs.csv).
INLINE_RUNS = 20
#: Resolution of the report's figures [dots per inch].
FIGURE_DPI = 110

_HEADINGS = {
    "morris": {"mu_star": "μ*", "mu_star_conf": "± (μ*)", "mu": "μ", "sigma": "σ"},
    "sobol": {"S1": "S1", "S1_conf": "± (S1)", "ST": "ST", "ST_conf": "± (ST)"},
    "rbd_fast": {"S1": "S1", "S1_conf": "± (S1)"},
}


def write_report(study: Study, table: pd.DataFrame, indices: dict[str, Indices], directory,
                 figures: bool = True, title_level: int = 1) -> Path:
    """Write ``report.md``, ``runs.csv``, one CSV of indices per output and the figures into
    ``directory``; return the report's path. ``title_level``: Markdown level of the title (2 to embed)."""
    directory = Path(directory)
    directory.mkdir(parents=True, exist_ok=True)
    _atomic_csv(table, directory / RUNS_FILE)
    h = "#" * title_level
    lines = [f"{h} Sensitivity study `{study.name}`", ""]
    if study.description:
        lines += [study.description, ""]
    lines += _overview(study, table)
    lines += [f"{h}# Parameters", "", "| parameter | distribution | bounds or values |", "|---|---|---|"]
    for p in study.parameters:
        support = ", ".join(f"{v:.4g}" for v in p.values) if p.values is not None else \
            ", ".join(f"{v:.4g}" for v in p.salib_bounds)
        lines.append(f"| `{p.name}` | {p.distribution if p.values is None else 'values'} | {support} |")
    lines.append("")
    for output in study.outputs:
        lines += [f"{h}# Output `{output}`", ""]
        result = indices.get(output)
        if result is not None:
            lines += _indices_section(study, result, directory, figures)
        if figures:
            name = _scatter_figure(study, table, output, directory)
            lines += [f"![{output} against the parameters]({name})", ""]
    lines += _runs_section(study, table, h)
    path = directory / REPORT_FILE
    temporary = path.with_name(path.name + ".part")
    temporary.write_text("\n".join(lines) + "\n")
    temporary.replace(path)
    return path


def _overview(study: Study, table: pd.DataFrame) -> list[str]:
    m = study.method
    design = {"grid": "full-factorial grid", "latin": f"Latin hypercube, N = {m.samples}",
              "morris": f"Morris, N = {m.samples} trajectories, p = {m.levels} levels",
              "sobol": f"Sobol'–Saltelli, N = {m.samples}" + (", second order" if m.second_order else "")}
    runs = table.drop_duplicates("key")
    counts = runs["status"].value_counts()
    failed_checks = sorted({name for names in runs.get("failed_checks", ()) for name in names.split(", ") if name})
    statuses = ", ".join(f"{counts[s]} {s}" for s in ("success", "suspect", "failed", "interrupted", "error", "missing")
                         if s in counts)
    cost = float(np.nansum(runs["wall_time_s"].astype(float)))
    analysis = "none (table and scatter plots)" if m.analyzer == "none" else \
        f"{m.analyzer}, {100 * m.conf_level:g} % confidence intervals from {m.resamples} bootstrap resamples"
    return [
        "| | |", "|---|---|",
        f"| model | {study.model.describe()} |",
        f"| sampling | {design[m.sampler]} |",
        f"| analysis | {analysis} |",
        f"| seed | {study.seed} |",
        f"| runs | {len(table)} samples, {len(runs)} distinct runs: {statuses} |",
        f"| status | {worst_status(runs['status'])} (the worst run's; docs/status.md)"
        + (f"; failed checks: {', '.join(failed_checks)}" if failed_checks else "") + " |",
        f"| cost | {cost:.4g} s of run time summed over the workers |",
        "",
    ]


def _indices_section(study: Study, result: Indices, directory: Path, figures: bool) -> list[str]:
    lines = []
    if result.result is None:
        return [f"No {result.analyzer} indices: {result.note}.", ""]
    df = result.to_df()
    _atomic_csv(df, directory / f"indices_{_slug(result.output)}.csv")
    headings = _HEADINGS[result.analyzer]
    lines += ["| parameter | " + " | ".join(headings[c] for c in df.columns) + " |",
              "|---" * (len(df.columns) + 1) + "|"]
    for name, row in df.iterrows():
        lines.append(f"| `{name}` | " + " | ".join(_fmt(row[c]) for c in df.columns) + " |")
    lines.append("")
    if result.note:
        lines += [f"Note: {result.note}.", ""]
    second = result.second_order_df()
    if second is not None:
        lines += ["| pair | S2 | ± (S2) |", "|---|---|---|"]
        lines += [f"| `{r.parameter}` × `{r['with']}` | {_fmt(r.S2)} | {_fmt(r.S2_conf)} |"
                  for _, r in second.iterrows()]
        lines.append("")
    if result.analyzer == "morris":
        lines += ["μ*: mean absolute elementary effect, in the output's unit per normalised input range; "
                  "σ: their standard deviation (σ/μ* near or above 1: non-linear or interacting).", ""]
    if figures:
        name = (_morris_figure if result.analyzer == "morris" else _bar_figure)(result, directory)
        lines += [f"![{result.analyzer} indices of {result.output}]({name})", ""]
    return lines


def _runs_section(study: Study, table: pd.DataFrame, h: str) -> list[str]:
    columns = [*study.names, *study.outputs, "status", "failed_checks", "attempts", "wall_time_s", "key"]
    columns = [c for c in columns if c in table.columns]
    lines = [f"{h}# Runs", "", f"Table of runs: [`{RUNS_FILE}`]({RUNS_FILE}) ({len(table)} rows). "
             f"First {min(INLINE_RUNS, len(table))}:", "",
             "| sample | " + " | ".join(f"`{c}`" if c in study.names or c in study.outputs else c for c in columns)
             + " |", "|---" * (len(columns) + 1) + "|"]
    for sample, row in table.head(INLINE_RUNS).iterrows():
        cells = [row["key"][:12] if c == "key" else _fmt(row[c]) for c in columns]
        lines.append(f"| {sample} | " + " | ".join(cells) + " |")
    lines.append("")
    errors = table[table["status"].isin(("error", "failed"))].drop_duplicates("key")
    if len(errors):
        lines += [f"{len(errors)} run(s) ended in an error or failed:", ""]
        lines += [f"- `{r['key'][:12]}` ({r['status']}): {r['error']}" for _, r in errors.head(INLINE_RUNS).iterrows()]
        lines.append("")
    return lines


def _morris_figure(result: Indices, directory: Path) -> str:
    from SALib.plotting.morris import covariance_plot

    fig, ax = new_figure(figsize=(6, 5))
    covariance_plot(ax, result.result)
    ax.errorbar(result.result["mu_star"], result.result["sigma"], xerr=result.result["mu_star_conf"],
                fmt="none", ecolor="0.5", lw=1)
    for name, x, y in zip(result.names, result.result["mu_star"], result.result["sigma"]):
        ax.annotate(name, (x, y), textcoords="offset points", xytext=(4, 4), fontsize=8)
    ax.set_xlim(0, 1.3 * max(np.max(result.result["mu_star"]), 1e-300))
    ax.set_title(f"Morris: {result.output}")
    return save_figure(fig, directory / f"morris_{_slug(result.output)}.png", dpi=FIGURE_DPI).name


def _bar_figure(result: Indices, directory: Path) -> str:
    from SALib.plotting.bar import plot as barplot

    fig, ax = new_figure(figsize=(1.2 * len(result.names) + 3, 4))
    barplot(result.to_df(), ax=ax)
    ax.set_title(f"{result.analyzer}: {result.output}")
    ax.tick_params(axis="x", labelrotation=20)
    return save_figure(fig, directory / f"{result.analyzer}_{_slug(result.output)}.png", dpi=FIGURE_DPI).name


def _scatter_figure(study: Study, table: pd.DataFrame, output: str, directory: Path) -> str:
    n = len(study.parameters)
    columns = min(n, 4)
    rows = math.ceil(n / columns)
    fig, axes = new_figure(rows, columns, figsize=(3.2 * columns, 2.8 * rows), squeeze=False, sharey=True)
    ok = table["status"].isin(("success", "suspect"))
    suspect = table["status"] == "suspect"
    for ax, p in zip(axes.ravel(), study.parameters):
        ax.scatter(table.loc[ok, p.name], table.loc[ok, output], s=8, c="k")
        if suspect.any():
            ax.scatter(table.loc[suspect, p.name], table.loc[suspect, output], s=14, facecolors="none",
                       edgecolors="C1", label="suspect")
        if (~ok).any():
            ax.scatter(table.loc[~ok, p.name], np.zeros(int((~ok).sum())), s=12, c="r", marker="x")
        if p.distribution == "logunif":
            ax.set_xscale("log")
            ax.xaxis.set_minor_formatter(matplotlib.ticker.NullFormatter())
        ax.tick_params(labelsize=7)
        ax.set_xlabel(p.name, fontsize=8)
    for ax in axes[:, 0]:
        ax.set_ylabel(output)
    for ax in axes.ravel()[n:]:
        ax.set_visible(False)
    fig.suptitle(f"{study.name}: {output}" + (" (x at 0: runs without a value)" if (~ok).any() else "")
                 + (" (orange rings: suspect runs)" if suspect.any() else ""))
    return save_figure(fig, directory / f"scatter_{_slug(output)}.png", dpi=FIGURE_DPI).name


def _fmt(value) -> str:
    if isinstance(value, (float, np.floating)):
        return "–" if not np.isfinite(value) else f"{value:.4g}"
    return str(value)


def _slug(name: str) -> str:
    return re.sub(r"[^A-Za-z0-9_.-]+", "_", name)


def _atomic_csv(df: pd.DataFrame, path: Path) -> None:
    temporary = path.with_name(path.name + ".part")
    df.to_csv(temporary)
    temporary.replace(path)
