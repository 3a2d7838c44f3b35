r"""Cage slip against radial load at 1500 rpm, penalty and constraint cage: does the cage skid more as the load falls?

Field measurements on wind-turbine high-speed-shaft bearings and the skidding literature say it does: the
rollers and cage are slowed by load-independent drag, while the traction that drives them scales with the load
(the primary document's motivation; Jain & Hunt 2011, Jain 2012, Han, Li & Chu 2018, refs. [25, 26, 28] there).
In the model the load-independent drag is Palmgren's M0 on the rollers (``[lubricant]``,
:mod:`bearing_mbs.lubrication`).

``run()`` simulates ``seed_hss_steady.toml`` (cage guided on the outer-ring land) at each load of :data:`LOADS`
with one cage model (the base's, or the one ``overrides`` set) and returns one row per load; ``sweep()`` does so
for every cage model of :data:`CAGES`; ``main()`` sweeps both, draws cage slip against load (log axes) and writes
the table. The write-up is docs/skidding.md. The total radial load on the bearing is the applied load plus the
weight of the inner ring and its supported shaft mass (454 N for the seed preset with 40 kg).

The penalty cage's slip averaged over a window of duration T is only resolved to about
:func:`pocket_play_resolution`: the cage may shift by the pocket clearance H relative to the rollers, an angle of
about 2H/(D_pw/2), whatever the true slip. The constraint cage has no play (resolution 0).

    python scenarios/skidding_vs_load.py        # both cages, 5 loads; writes docs/figures/skidding_vs_load.{png,csv}
    python scenarios/skidding_vs_load.py --cages constraint --loads 68000,2000,200 \
        --set scenario.end_time=0.1 --set analysis.start=0.05 --out out/skid
"""

from __future__ import annotations

import argparse
import csv
import logging
from pathlib import Path

import numpy as np

from bearing_mbs.models.cylindrical_roller.metrics import window
from bearing_mbs.models.cylindrical_roller.figures import cage_slip_series
from bearing_mbs.models.cylindrical_roller.geometry import BearingGeometry
from bearing_mbs.runner import run_spec, summarize
from bearing_mbs.models import load_spec

BASE = Path(__file__).with_name("seed_hss_steady.toml")
OUT = Path(__file__).resolve().parents[1] / "docs" / "figures"
NOMINAL_LOAD = 68000.0
#: Radial loads [N]: nominal, down to 0.3 % of it.
LOADS = (68000.0, 6800.0, 2000.0, 680.0, 200.0)
#: Cage models swept by :func:`sweep`, each with the overrides that select it. Both cages are guided on the
#: outer-ring land, as in the base scenario (a machined brass "MA" cage); the constraint cage never reaches it.
CAGES = {
    "penalty": ("cage.model=penalty",),
    "constraint": ("cage.model=constraint",),
}
#: A longer run than the base file's, so that the window resolves the penalty cage's slip to ~0.1 %.
LONG_WINDOW = ("scenario.end_time=0.3", "analysis.start=0.1")
#: A load counts as settled when the means of its window's two halves differ by less than the pocket-play
#: resolution of a half window (penalty cage) plus this fraction of the window mean.
SETTLED_FRACTION = 0.2


def run(loads=LOADS, overrides: tuple[str, ...] = LONG_WINDOW, base: str | Path = BASE) -> list[dict]:
    """One row per radial load [N] (keys: :data:`COLUMNS`): loads, cage slip (window mean and its two halves) [-],
    the resolution of the window [-], largest inner-raceway slip ratio [-], largest roller and pocket force [N],
    largest cage eccentricity [m], cost and status. ``overrides`` apply to every load (e.g. the cage model)."""
    rows = []
    for load in loads:
        spec = load_spec(base, [*overrides, f"load.radial={load}"])
        scene, result = run_spec(spec)
        rows.append(sweep_row(spec, scene, result))
    return rows


def sweep(loads=LOADS, cages: dict[str, tuple[str, ...]] | None = None, overrides: tuple[str, ...] = LONG_WINDOW,
          base: str | Path = BASE) -> dict[str, list[dict]]:
    """:func:`run` for each cage model of ``cages`` (default :data:`CAGES`): {cage model: rows}."""
    cages = CAGES if cages is None else cages
    return {name: run(loads, (*overrides, *selection), base) for name, selection in cages.items()}


def sweep_row(spec, scene, result) -> dict:
    summary = summarize(spec, scene, result)
    mask = window(spec, result)
    slip = cage_slip_series(spec, scene, result)[mask]
    first, second = (float(np.nanmean(half)) for half in np.array_split(slip, 2))
    duration = float(result.time[mask][-1] - result.time[mask][0])
    tolerance = pocket_play_resolution(spec, duration / 2) + SETTLED_FRACTION * abs(summary["cage_slip"])
    return {
        "cage_model": spec.cage.model,
        "radial_load": spec.load.radial,
        "total_load": total_radial_load(spec),
        "load_fraction": spec.load.radial / NOMINAL_LOAD,
        "cage_slip": summary["cage_slip"],
        "cage_slip_first_half": first,
        "cage_slip_second_half": second,
        "resolution": pocket_play_resolution(spec, duration),
        "settled": bool(abs(first - second) <= tolerance),
        "max_roller_slip_inner": summary["max_roller_slip_inner"],
        "max_roller_load": summary["max_roller_load"],
        "max_pocket_force": summary["max_pocket_force"],
        "max_cage_eccentricity": summary["max_cage_eccentricity"],
        "wall_time_s": summary["wall_time_s"],
        "steps": summary["steps"],
        "status": summary["status"],
        "warnings": "; ".join(summary.get("warnings") or ()),
    }


def total_radial_load(spec) -> float:
    """|applied radial load + weight of the inner ring and supported mass| [N] (constant-load scenarios)."""
    geometry = BearingGeometry.from_spec(spec.bearing)
    angle = np.radians(spec.load.angle)
    force = spec.load.radial * np.array([np.cos(angle), np.sin(angle)])
    force[1] -= geometry.inner_ring_mass * spec.scenario.gravity
    return float(np.hypot(*force))


def pocket_play_resolution(spec, duration: float) -> float:
    """Apparent cage slip [-] that the pocket clearance alone can produce over ``duration`` [s]: the cage's angle
    relative to the roller set varies by up to 2H/(D_pw/2), against the epicyclic angle ω_c,epi · duration.
    Zero for the constraint cage (its angle is locked to the rollers) and without a cage."""
    if spec.cage.model != "penalty":
        return 0.0
    geometry = BearingGeometry.from_spec(spec.bearing)
    inner_speed = spec.drive.speed_rpm * 2 * np.pi / 60
    travel = geometry.epicyclic_cage_speed(inner_speed) * duration
    return float(2 * geometry.pocket_clearance / (geometry.pitch_diameter / 2) / travel)


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


def plot_slip_against_load(sweeps: dict[str, list[dict]], path: Path) -> Path:
    """Cage slip [%] against total radial load [N], one curve per cage model (log axes), with the halves of
    each window as a bar and, around the penalty curve, the pocket-play resolution of the window as a band;
    the largest inner-raceway slip ratio below."""
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure

    figure = Figure(figsize=(6.5, 6.0))
    FigureCanvasAgg(figure)
    cage, rollers = figure.subplots(2, 1, sharex=True)
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
    cage.set_title("seed HSS bearing, 1500 rpm, land-guided cage")
    figure.tight_layout()
    figure.savefig(path, dpi=100)
    return path


COLUMNS = ("cage_model", "radial_load", "total_load", "load_fraction", "cage_slip", "cage_slip_first_half",
           "cage_slip_second_half", "resolution", "settled", "max_roller_slip_inner", "max_roller_load",
           "max_pocket_force", "max_cage_eccentricity", "wall_time_s", "steps", "status", "warnings")


def markdown_table(sweeps: dict[str, list[dict]]) -> str:
    """All rows as a Markdown table (slips in %)."""
    lines = ["| cage | radial load [N] | total load [N] | cage slip [%] | window halves [%] | resolution [%] | "
             "settled | largest inner-raceway slip ratio | max roller load [N] | max pocket force [N] | "
             "max cage eccentricity [µm] | wall [s] |",
             "|---|---:|---:|---:|---:|---:|---|---:|---:|---:|---:|---:|"]
    for name, rows in sweeps.items():
        for row in rows:
            lines.append(
                f"| {name} | {row['radial_load']:g} | {row['total_load']:.0f} | {100 * row['cage_slip']:.3g} | "
                f"{100 * row['cage_slip_first_half']:.3g}, {100 * row['cage_slip_second_half']:.3g} | "
                f"{100 * row['resolution']:.3g} | {'yes' if row['settled'] else 'no'} | "
                f"{row['max_roller_slip_inner'] or float('nan'):.3g} | {row['max_roller_load']:.0f} | "
                f"{row['max_pocket_force']:.0f} | {1e6 * (row['max_cage_eccentricity'] or float('nan')):.0f} | "
                f"{row['wall_time_s']:.1f} |")
    return "\n".join(lines) + "\n"


def main(argv: list[str] | None = None) -> dict[str, list[dict]]:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--loads", default=",".join(f"{x:g}" for x in LOADS), help="radial loads [N], comma-separated")
    parser.add_argument("--cages", default=",".join(CAGES),
                        help=f"cage models, comma-separated (of {', '.join(CAGES)})")
    parser.add_argument("--out", default=str(OUT), help="directory for skidding_vs_load.png and .csv")
    parser.add_argument("--set", action="append", default=None, metavar="SECTION.KEY=VALUE",
                        help=f"override a field of the base scenario (repeatable; default: {' '.join(LONG_WINDOW)})")
    args = parser.parse_args(argv)
    logging.basicConfig(level=logging.WARNING)
    unknown = set(args.cages.split(",")) - set(CAGES)
    if unknown:
        parser.error(f"unknown cage model(s) {', '.join(sorted(unknown))}; choose from {', '.join(CAGES)}")
    cages = {name: CAGES[name] for name in args.cages.split(",")}
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    sweeps = sweep([float(x) for x in args.loads.split(",")], cages, tuple(args.set) if args.set else LONG_WINDOW)
    with (out / "skidding_vs_load.csv").open("w", newline="") as handle:
        writer = csv.DictWriter(handle, COLUMNS)
        writer.writeheader()
        for rows in sweeps.values():
            writer.writerows(rows)
    plot_slip_against_load(sweeps, out / "skidding_vs_load.png")
    print(markdown_table(sweeps))
    for name, rows in sweeps.items():
        print(f"trend, {name} cage:", trend(rows))
    return sweeps


if __name__ == "__main__":
    main()
