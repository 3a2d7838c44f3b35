"""Figures and tables of docs/numerics.md from a work–precision study's ``convergence.csv``.

``bearing-mbs numerics-report STUDY_DIR --name NAME --out docs/figures [--norms cage_speed,slips]
[--document-step 5.56e-7]`` runs :func:`run` on the directory of a ``bearing-mbs convergence`` study.

A run is **sound** when its slips are converged: its slip-ratio error against the reference stays below
:func:`sound_slip_bound`, ``SOUND_SLIPS`` (1e-4) or ``SLIP_FRACTION`` (1 %) of the reference's largest slip ratio,
whichever is larger (the study's ``summary.json`` gives that slip). Where the slips are small (the dry seed bearing,
5.1e-5 over 5–15 ms) the absolute bound decides; where they are large (the lubricated one: rollers slip by up to 6 % entering the
load zone), 1e-4 would ask for 0.16 % of the slip itself, more than is asked of the cage speed. Runs above an
explicit method's friction stability limit are bounded but not sound: their slip is a spurious skidding cycle,
however small their cage-speed error. On the dry seed bearing the two groups are far apart (slip errors of 6.9e-5
and below against 1.3e-4 and above).
The report gives, for each target, the cheapest setting and the cheapest sound one,
and the speed-up of the cheapest sound setting over the document's scheme (the reference engine's central
difference) at equal error.
"""

from __future__ import annotations

import csv
import json
import logging
import math
from pathlib import Path

from bearing_mbs.io.figures import new_figure, save_figure
from bearing_mbs.spec import SpecError
from bearing_mbs.spec.methods import CENTRAL_DIFFERENCE

log = logging.getLogger(__name__)

#: Largest slip-ratio error of a sound run [-], and as a fraction of the largest slip ratio where that is larger.
SOUND_SLIPS, SLIP_FRACTION = 1e-4, 1e-2


def sound_slip_bound(largest_slip: float) -> float:
    """The largest slip-ratio error of a sound run [-] where the reference's largest slip ratio is
    ``largest_slip``."""
    return max(SOUND_SLIPS, SLIP_FRACTION * largest_slip)
DOCUMENT = ("reference", CENTRAL_DIFFERENCE.name)
LABELS = {"cage_speed": "mean cage speed error [-]", "slips": "slip ratio error [-]",
          "roller_loads": "roller load error [-]", "positions": "position error [-]"}


def read(directory: str | Path) -> list[dict]:
    """The successful runs of a study's ``convergence.csv``, with their errors as floats and ``sound`` set."""
    table = Path(directory) / "convergence.csv"
    if not table.is_file():
        raise SpecError("study", str(directory), "has no convergence.csv (run bearing-mbs convergence into it first)")
    with table.open(newline="") as handle:
        rows = [r for r in csv.DictReader(handle) if r["status"] == "success"]
    summary = Path(directory) / "summary.json"
    largest = json.loads(summary.read_text()).get("reference_largest_slip", 0.0) if summary.is_file() else 0.0
    bound = sound_slip_bound(largest)
    for r in rows:
        for key in ("wall_time_s", "cage_speed", "slips", "roller_loads", "positions"):
            r[key] = float(r[key]) if r[key] else math.nan
        r["sound"] = not r["slips"] > bound  # no slips (balls model): nothing can skid
        r["setting"] = f"h = {float(r['step']):.3g} s" if r["step"] else f"tol = {float(r['tolerance']):.0e}"
    return rows


def cheapest(rows, norm: str, target: float, sound_only: bool) -> dict | None:
    reaching = [r for r in rows if r[norm] <= target and (r["sound"] or not sound_only)]
    return min(reaching, key=lambda r: r["wall_time_s"], default=None)


def speed_ups(rows, norm: str) -> list[dict]:
    """For every sound run of the document's scheme: the cheapest sound run of another method at equal or smaller
    error, and the ratio of their wall times."""
    answer = []
    for document in sorted((r for r in rows if (r["engine"], r["solver"]) == DOCUMENT and r["sound"]),
                           key=lambda r: r["wall_time_s"]):
        others = [r for r in rows
                  if (r["engine"], r["solver"]) != DOCUMENT and r["sound"] and r[norm] <= document[norm]]
        best = min(others, key=lambda r: r["wall_time_s"], default=None)
        answer.append({"document": document, "best": best,
                       "speed_up": None if best is None else document["wall_time_s"] / best["wall_time_s"]})
    return answer


def figure(rows, norms, path: Path, title: str, document_step: float = 1 / 1.8e6) -> Path:
    """Each norm against wall time [s] (log axes), hollow where the slips are not converged, the document's scheme
    at ``document_step`` [s] starred."""
    import matplotlib

    fig, axes = new_figure(1, len(norms), figsize=(6.2 * len(norms), 5), squeeze=False)
    keys = sorted({(r["engine"], r["solver"]) for r in rows})
    colours = dict(zip(keys, matplotlib.rcParams["axes.prop_cycle"].by_key()["color"]))
    for axis, norm in zip(axes[0], norms):
        for key in keys:
            points = sorted((r["wall_time_s"], r[norm], r["sound"]) for r in rows if (r["engine"], r["solver"]) == key
                            and r[norm] > 0)
            if not points:
                continue
            axis.loglog([p[0] for p in points], [p[1] for p in points], "-", color=colours[key], alpha=0.5)
            for sound in (True, False):
                chosen = [p for p in points if p[2] == sound]
                if chosen:
                    axis.loglog([p[0] for p in chosen], [p[1] for p in chosen], "o", color=colours[key],
                                markerfacecolor=colours[key] if sound else "none",
                                label=" ".join(key) if sound or not any(p[2] for p in points) else None)
        document = [r for r in rows if (r["engine"], r["solver"]) == DOCUMENT and r["step"]
                    and abs(float(r["step"]) - document_step) < 1e-9 * document_step]
        for r in document:
            axis.loglog(r["wall_time_s"], r[norm], "*", color="k", markersize=12,
                        label=f"document's scheme and step ({document_step:.3g} s)")
        axis.set_xlabel("wall time [s]")
        axis.set_ylabel(LABELS.get(norm, norm))
        axis.grid(True, which="both", alpha=0.3)
    axes[0][0].legend(fontsize=7)
    note = " (hollow: slips not converged, a spurious skidding cycle)" if not all(r["sound"] for r in rows) else ""
    fig.suptitle(title + note, fontsize=10)
    return save_figure(fig, path)


def markdown(rows, norm: str, targets=(1e-2, 1e-3, 1e-4)) -> str:
    lines = [f"| {norm} target | cheapest setting | its slip error | cheapest sound setting | cost [s] | steps | "
             "force evaluations |", "|---|---|---:|---|---:|---:|---:|"]
    for target in targets:
        any_run, sound = cheapest(rows, norm, target, False), cheapest(rows, norm, target, True)

        def name(r):
            return "none" if r is None else f"{r['engine']} {r['solver']} {r['setting']} ({r['wall_time_s']:.2f} s)"

        if sound is None or any_run is None:
            lines.append(f"| {target:g} | {name(any_run)} | | none | | | |")
            continue
        lines.append(f"| {target:g} | {name(any_run)} | {any_run['slips']:.1e} | {name(sound)} | "
                     f"{sound['wall_time_s']:.2f} | {sound['steps']} | {sound['force_evaluations']} |")
    lines += ["", f"| document's scheme (sound) | its {norm} error | cheapest other sound setting at that error | "
              "speed-up |", "|---|---:|---|---:|"]
    for item in speed_ups(rows, norm):
        d, b = item["document"], item["best"]
        lines.append(f"| central_difference {d['setting']} ({d['wall_time_s']:.2f} s) | {d[norm]:.1e} | "
                     + ("none | |" if b is None else
                        f"{b['engine']} {b['solver']} {b['setting']} ({b['wall_time_s']:.2f} s) | "
                        f"{item['speed_up']:.2f} |"))
    return "\n".join(lines) + "\n"


def run(study: str | Path, name: str, directory: str | Path, norms=("cage_speed", "slips"),
        document_step: float = 1 / 1.8e6) -> str:
    """Write ``work_precision_NAME.png`` and ``work_precision_NAME.md`` (the tables of every norm) into
    ``directory`` from the convergence study in ``study``; returns the tables' Markdown. ``document_step`` [s]:
    the document's step for its scheme, starred in the figure."""
    norms = tuple(norms)
    unknown = [norm for norm in norms if norm not in LABELS]
    if unknown or not norms:
        raise SpecError("norms", ",".join(unknown), f"must be among {', '.join(LABELS)}")
    if not document_step > 0:
        raise SpecError("document_step", document_step, "must be > 0")
    rows = read(study)
    directory = Path(directory)
    directory.mkdir(parents=True, exist_ok=True)
    figure(rows, norms, directory / f"work_precision_{name}.png", name, document_step)
    text = "\n".join(markdown(rows, norm) for norm in norms)
    (directory / f"work_precision_{name}.md").write_text(text)
    log.info("%s: %d successful runs -> %s", name, len(rows), directory)
    return text
