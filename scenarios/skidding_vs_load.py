r"""Cage slip against radial load at 1500 rpm: does the cage skid more as the load falls?

Field measurements on wind-turbine high-speed-shaft bearings and the skidding literature say it does: the
rollers and cage are slowed by load-independent drag, while the traction that drives them scales with the load
(the primary document's motivation; Jain & Hunt 2011, Jain 2012, Han, Li & Chu 2018, refs. [25, 26, 28] there).
``run()`` simulates ``seed_hss_steady.toml`` at each load of :data:`LOADS` and returns one row per load;
``main()`` also draws cage slip against load (log axis) and writes the table. The write-up is docs/skidding.md.

The cage is guided on the outer-ring land (:data:`RETAINED_CAGE`): guided by the rollers only, the penalty cage
leaves the bearing within 0.1–0.3 s (docs/cage-models.md). The total radial load on the bearing is the applied
load plus the weight of the inner ring and its supported shaft mass (454 N for the seed preset with 40 kg).

Cage slip averaged over a window of duration T is only resolved to about :func:`pocket_play_resolution`: the cage
may shift by the pocket clearance H relative to the rollers, an angle of about 2H/D_pw, whatever the true slip.
A load counts as settled when the two halves of its window agree to within that resolution.

    python scenarios/skidding_vs_load.py                 # writes docs/figures/skidding_vs_load.png
    python scenarios/skidding_vs_load.py --loads 68000,2000,340 --set scenario.end_time=0.1 --set analysis.start=0.05
"""

from __future__ import annotations

import argparse
import csv
import logging
from pathlib import Path

import numpy as np

from bearing_mbs.analysis.bearing import window
from bearing_mbs.figures_bearing import cage_slip_series
from bearing_mbs.geometry import BearingGeometry
from bearing_mbs.runner import run_spec, summarize
from bearing_mbs.spec import load_spec

BASE = Path(__file__).with_name("seed_hss_steady.toml")
OUT = Path(__file__).resolve().parents[1] / "docs" / "figures"
NOMINAL_LOAD = 68000.0
#: Radial loads [N]: nominal down to 0.5 % of it.
LOADS = (68000.0, 6800.0, 2000.0, 680.0, 340.0)
#: An outer-land-guided cage (a machined brass "MA" cage), which stays in the bearing.
RETAINED_CAGE = ("bearing.cage_guidance=outer_land", "bearing.land_clearance=5e-4")
#: A longer run than the base file's, so that the window resolves cage slip to ~0.1 %.
LONG_WINDOW = ("scenario.end_time=0.3", "analysis.start=0.1")


def run(loads=LOADS, overrides: tuple[str, ...] = LONG_WINDOW, base: str | Path = BASE) -> list[dict]:
    """One row per radial load [N]: loads, cage slip (window mean and its two halves) [-], the resolution of the
    window [-], largest inner-raceway slip ratio [-], largest pocket force [N], cost and status."""
    rows = []
    for load in loads:
        spec = load_spec(base, [*RETAINED_CAGE, *overrides, f"load.radial={load}"])
        scene, result = run_spec(spec)
        rows.append(sweep_row(spec, scene, result))
    return rows


def sweep_row(spec, scene, result) -> dict:
    summary = summarize(spec, scene, result)
    mask = window(spec, result)
    slip = cage_slip_series(spec, scene, result)[mask]
    first, second = np.array_split(slip, 2)
    duration = float(result.time[mask][-1] - result.time[mask][0])
    half_resolution = pocket_play_resolution(spec, duration / 2)
    return {
        "radial_load": spec.load.radial,
        "total_load": total_radial_load(spec),
        "load_fraction": spec.load.radial / NOMINAL_LOAD,
        "cage_slip": summary["cage_slip"],
        "cage_slip_first_half": float(np.nanmean(first)),
        "cage_slip_second_half": float(np.nanmean(second)),
        "resolution": pocket_play_resolution(spec, duration),
        "settled": bool(abs(np.nanmean(first) - np.nanmean(second)) <= half_resolution),
        "max_roller_slip_inner": summary["max_roller_slip_inner"],
        "max_pocket_force": summary["max_pocket_force"],
        "wall_time_s": summary["wall_time_s"],
        "steps": summary["steps"],
        "status": summary["status"],
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
    resolution of the window."""
    ordered = sorted(rows, key=lambda row: -row["radial_load"])
    slips = np.array([row["cage_slip"] for row in ordered])
    return {
        "monotone": bool(np.all(np.diff(slips) > 0)),
        "ratio": float(slips[-1] / slips[0]) if slips[0] != 0 else float("inf"),
        "margin": float((slips[-1] - slips[0]) / max(row["resolution"] for row in ordered))
        if any(row["resolution"] for row in ordered) else float("inf"),
    }


def plot_slip_against_load(rows: list[dict], path: Path) -> Path:
    """Cage slip [%] against total radial load [N] (log axis), with the halves of each window as a bar and the
    window's resolution as a band around zero; the largest inner-raceway slip ratio below."""
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure

    rows = sorted(rows, key=lambda row: row["total_load"])
    load = np.array([row["total_load"] for row in rows])
    slip = 100 * np.array([row["cage_slip"] for row in rows])
    halves = 100 * np.array([[row["cage_slip_first_half"], row["cage_slip_second_half"]] for row in rows])
    resolution = 100 * max(row["resolution"] for row in rows)
    figure = Figure(figsize=(6.5, 5.5))
    FigureCanvasAgg(figure)
    cage, rollers = figure.subplots(2, 1, sharex=True)
    cage.fill_between([load.min() / 2, load.max() * 2], -resolution, resolution, color="grey", alpha=0.15,
                      linewidth=0, label=f"pocket-play resolution (±{resolution:.2g} %)")
    cage.vlines(load, halves.min(axis=1), halves.max(axis=1), color="C0", alpha=0.5, label="window halves")
    cage.plot(load, slip, "o-", color="C0", label="window mean")
    cage.axhline(0.0, color="grey", linewidth=0.6)
    cage.set_ylabel("cage slip [%]")
    cage.legend(fontsize="small", loc="upper left")
    rollers.plot(load, [row["max_roller_slip_inner"] or np.nan for row in rows], "s-", color="C3")
    rollers.set_ylabel("largest inner-raceway\nslip ratio [-]")
    rollers.set_xlabel("total radial load on the bearing [N] (applied + inner-ring and shaft weight)")
    rollers.set_xscale("log")
    rollers.set_xlim(load.min() / 1.5, load.max() * 1.5)
    for axis in (cage, rollers):
        axis.grid(True, which="both", alpha=0.3)
    cage.set_title("seed HSS bearing at 1500 rpm: cage slip against load")
    figure.tight_layout()
    figure.savefig(path, dpi=100)
    return path


COLUMNS = ("radial_load", "total_load", "load_fraction", "cage_slip", "cage_slip_first_half",
           "cage_slip_second_half", "resolution", "settled", "max_roller_slip_inner", "max_pocket_force",
           "wall_time_s", "steps", "status")


def main(argv: list[str] | None = None) -> list[dict]:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--loads", default=",".join(f"{x:g}" for x in LOADS), help="radial loads [N], comma-separated")
    parser.add_argument("--out", default=str(OUT), help="directory for skidding_vs_load.png and .csv")
    parser.add_argument("--set", action="append", default=None, metavar="SECTION.KEY=VALUE",
                        help=f"override a field of the base scenario (repeatable; default: {' '.join(LONG_WINDOW)})")
    args = parser.parse_args(argv)
    logging.basicConfig(level=logging.WARNING)
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    rows = run([float(x) for x in args.loads.split(",")], tuple(args.set) if args.set else LONG_WINDOW)
    with (out / "skidding_vs_load.csv").open("w", newline="") as handle:
        writer = csv.DictWriter(handle, COLUMNS)
        writer.writeheader()
        writer.writerows(rows)
    plot_slip_against_load(rows, out / "skidding_vs_load.png")
    print("| radial load [N] | total load [N] | cage slip [%] | halves [%] | resolution [%] | settled | "
          "max inner slip ratio | max pocket force [N] | wall [s] |")
    print("|---:|---:|---:|---:|---:|---|---:|---:|---:|")
    for row in rows:
        print(f"| {row['radial_load']:g} | {row['total_load']:.0f} | {100 * row['cage_slip']:.3f} | "
              f"{100 * row['cage_slip_first_half']:.3f}, {100 * row['cage_slip_second_half']:.3f} | "
              f"{100 * row['resolution']:.3f} | {'yes' if row['settled'] else 'no'} | "
              f"{row['max_roller_slip_inner'] or float('nan'):.3g} | {row['max_pocket_force']:.0f} | "
              f"{row['wall_time_s']:.1f} |")
    print("trend:", trend(rows))
    return rows


if __name__ == "__main__":
    main()
