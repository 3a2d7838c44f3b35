"""The stability suite's report: the summary (advisor against measured limits), the Markdown table, the heat
map and the advised-against-measured figure."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np

from bearing_mbs.io.figures import new_figure, save_figure
from bearing_mbs.studies.table import number


def summarize(rows: list[dict]) -> dict:
    """Counts, and the fraction of explicit cells whose measured limit is within a factor of 2 of the advice."""
    measured = [r for r in rows if r["kind"] == "explicit" and number(r["ratio"]) > 0]
    within = [r for r in measured if 0.5 <= number(r["ratio"]) <= 2.0]
    return {
        "cells": len(rows),
        "explicit_cells_measured": len(measured),
        "within_factor_2": len(within),
        "fraction_within_factor_2": len(within) / len(measured) if measured else None,
        "outside_factor_2": [f"{r['case']} / {r['engine']} {r['solver']}: {number(r['ratio']):.3g}"
                             for r in measured if r not in within],
        "failing_cells": [f"{r['case']} / {r['engine']} {r['solver']}: {r['verdict']}" for r in rows
                          if not r["verdict"].startswith("pass")],
    }


def cell_text(r: dict) -> str:
    """One cell of the overview: measured/advised for explicit methods, the passing step or tolerance otherwise,
    or why nothing passed."""
    if not r["verdict"].startswith("pass"):
        return r["verdict"].replace("unknown: ", "not run: ")
    if r["kind"] == "explicit":
        return f"{number(r['ratio']):.2f}" + (" (top)" if "ladder top" in r["verdict"] else "")
    prefix = "h" if r["kind"] == "implicit" else "tol"
    return f"{prefix} {_fmt(r['largest_pass'])}" + (" (top)" if "ladder top" in r["verdict"] else "")


def overview(rows: list[dict]) -> str:
    """Cases × solvers in one table (see :func:`cell_text`)."""
    cases = list(dict.fromkeys(r["case"] for r in rows))
    solvers = list(dict.fromkeys((r["engine"], r["solver"]) for r in rows))
    cells = {(r["case"], (r["engine"], r["solver"])): cell_text(r) for r in rows}
    lines = ["| case | " + " | ".join(f"{e} {m}" for e, m in solvers) + " |",
             "|---|" + "---|" * len(solvers)]
    for case in cases:
        lines.append(f"| {case} | " + " | ".join(cells.get((case, s), "") for s in solvers) + " |")
    return "\n".join(lines)


def markdown(summary: dict, rows: list[dict]) -> str:
    lines = [
        f"# Stability suite: {summary['scenario']}", "",
        "Overview: measured / advised stability limit for fixed-step explicit methods (rungs of √2, so 0.71, 1, "
        "1.41 …); the largest passing step of generalized-alpha (h) and the largest passing tolerance of adaptive "
        "methods (tol); otherwise the verdict. (top): the top of the ladder passed too.", "",
        overview(rows), "",
        "Largest passing step against the advisor's estimated stability limit (explicit methods; rungs of √2 from "
        "the advice), the step (generalized-alpha) or tolerance (adaptive methods) that passes, and why the next "
        "one fails.", "",
        "| case | engine | solver | probe [ms] | advised limit [s] | largest passing | measured / advised | "
        "fails at | reason | verdict |",
        "|---|---|---|---:|---:|---:|---:|---:|---|---|",
    ]
    for r in rows:
        ratio = number(r["ratio"])
        lines.append(
            f"| {r['case']} | {r['engine']} | {r['solver']} | {1e3 * number(r['probe_time']):.2g} | "
            f"{_fmt(r['advised_limit'])} | {_fmt(r['largest_pass'])} | "
            f"{'' if math.isnan(ratio) else f'{ratio:.2f}'} | {_fmt(r['first_fail'])} | {r['fail_reason']} | "
            f"{r['verdict']} |")
    fraction = summary["fraction_within_factor_2"]
    lines += ["", f"Advisor within a factor of 2 of the measured limit: {summary['within_factor_2']} of "
              f"{summary['explicit_cells_measured']} explicit cells"
              + (f" ({100 * fraction:.0f} %)." if fraction is not None else ".")]
    if summary["outside_factor_2"]:
        lines.append("Outside: " + "; ".join(summary["outside_factor_2"]) + ".")
    return "\n".join(lines) + "\n"


def heat_map(rows: list[dict], path: Path, title: str) -> Path:
    """Cases × solvers. Explicit cells: log2(measured/advised) on a diverging scale; others: pass or fail."""
    from matplotlib.colors import TwoSlopeNorm
    from matplotlib.patches import Rectangle

    cases = list(dict.fromkeys(r["case"] for r in rows))
    solvers = list(dict.fromkeys(f"{r['engine']}\n{r['solver']}" for r in rows))
    values = np.full((len(cases), len(solvers)), np.nan)
    fig, axis = new_figure(figsize=(1.3 * len(solvers) + 3, 0.42 * len(cases) + 1.8))
    norm = TwoSlopeNorm(vmin=-2.0, vcenter=0.0, vmax=2.0)
    for r in rows:
        i, j = cases.index(r["case"]), solvers.index(f"{r['engine']}\n{r['solver']}")
        ratio = number(r["ratio"])
        if r["kind"] == "explicit" and ratio > 0:
            values[i, j] = math.log2(ratio)
            text = f"{ratio:.2g}"
        else:
            passed = r["verdict"].startswith("pass")
            colour = "#c7e9c0" if passed else "#d9d9d9" if r["verdict"].startswith("unknown") else "#fcbba1"
            axis.add_patch(Rectangle((j - 0.5, i - 0.5), 1, 1, color=colour))
            if r["kind"] == "implicit" and passed:
                text = f"h {_fmt(r['largest_pass'])}"
            elif r["kind"] == "adaptive" and passed:
                text = f"tol {_fmt(r['largest_pass'])}"
            elif r["verdict"].startswith("unknown"):
                text = "not run (budget)"
            else:
                text = r["verdict"].replace("fail: ", "")[:22]
        axis.text(j, i, text, ha="center", va="center", fontsize=7)
    image = axis.imshow(np.ma.masked_invalid(values), cmap="RdBu", norm=norm, aspect="auto")
    axis.set_xticks(range(len(solvers)), solvers, fontsize=7)
    axis.set_yticks(range(len(cases)), cases, fontsize=8)
    axis.set_xlim(-0.5, len(solvers) - 0.5)
    axis.set_ylim(len(cases) - 0.5, -0.5)
    bar = fig.colorbar(image, ax=axis, fraction=0.04)
    bar.set_label("log2(measured / advised limit)")
    axis.set_title(title, fontsize=9)
    return save_figure(fig, path)


def advised_figure(rows: list[dict], path: Path, name: str) -> Path:
    """The advisor's limit beside the measured one, every explicit cell: the band is the factor of 2."""
    fig, axis = new_figure(figsize=(6, 5))
    cells = [r for r in rows if r["kind"] == "explicit" and number(r["ratio"]) > 0]
    markers = dict(zip(sorted({f"{r['engine']} {r['solver']}" for r in cells}), "osD^v<>"))
    for label, marker in markers.items():
        points = [(number(r["advised_limit"]), number(r["largest_pass"])) for r in cells
                  if f"{r['engine']} {r['solver']}" == label]
        axis.loglog(*zip(*points), marker, label=label, alpha=0.75, markerfacecolor="none")
    if cells:
        low = min(number(r["advised_limit"]) for r in cells) / 3
        high = max(number(r["advised_limit"]) for r in cells) * 3
        line = np.array([low, high])
        axis.loglog(line, line, "k-", lw=0.8, label="measured = advised")
        axis.fill_between(line, line / 2, 2 * line, color="0.85", zorder=0, label="factor of 2")
    axis.set_xlabel("advised stability limit [s]")
    axis.set_ylabel("largest passing step, measured [s]")
    axis.set_title(f"{name}: step advisor against the stability suite", fontsize=9)
    axis.grid(True, which="both", alpha=0.3)
    axis.legend(fontsize=7)
    return save_figure(fig, path)


def _fmt(value) -> str:
    figure = number(value)
    return "" if math.isnan(figure) else f"{figure:.3g}"
