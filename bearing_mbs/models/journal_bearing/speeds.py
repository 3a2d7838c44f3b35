"""The eight dynamic coefficients over a list of speeds, each at the journal's equilibrium under a static load
(``journal.coefficient_speeds_rpm``, ``journal.static_load``): the speed-dependent K and C a rotordynamics code
takes for a bearing (ROSS's ``BearingElement`` among them). Written as the summary's ``coefficients_over_speed``,
``coefficients.csv`` and ``coefficients.png``."""

from __future__ import annotations

import csv
import math
from pathlib import Path

import numpy as np

from bearing_mbs.fluid_film.coefficients import dynamic_coefficients
from bearing_mbs.fluid_film.equilibrium import film_equilibrium
from bearing_mbs.fluid_film.reynolds import JournalState
from bearing_mbs.io.figures import new_figure, save_figure

ENTRIES = ("xx", "xy", "yx", "yy")
COLUMNS = ("speed_rpm", "eccentricity_x", "eccentricity_y", "eccentricity_ratio",
           *(f"k{e}" for e in ENTRIES), *(f"c{e}" for e in ENTRIES))
UNITS = "rpm; eccentricity m, m, -; stiffness N/m; damping N s/m"


def coefficients_over_speed(force, clearance: float, load, speeds_rpm) -> list[dict]:
    """Per speed [rpm]: the equilibrium (x, y) [m] of ``force(state)`` under ``load`` (F_x, F_y) [N], its
    eccentricity ratio, and K [N/m], C [N s/m] there; ``eccentricity`` None where no equilibrium was found."""
    rows = []
    for rpm in speeds_rpm:
        speed = rpm * math.pi / 30
        centre = film_equilibrium(force, clearance, load, speed)
        if centre is None:
            rows.append({"speed_rpm": rpm, "eccentricity": None, "eccentricity_ratio": None, "stiffness": None,
                         "damping": None})
            continue
        stiffness, damping = dynamic_coefficients(force, JournalState(tuple(centre), (0.0, 0.0), speed), clearance)
        rows.append({"speed_rpm": rpm, "eccentricity": centre.tolist(),
                     "eccentricity_ratio": float(np.hypot(*centre) / clearance), "stiffness": stiffness.tolist(),
                     "damping": damping.tolist()})
    return rows


def write_table(rows: list[dict], path: str | Path) -> Path:
    """``coefficients.csv``: one line per speed (the columns of :data:`COLUMNS`; empty where no equilibrium)."""
    with open(path, "w", newline="") as handle:
        writer = csv.writer(handle)
        writer.writerow(COLUMNS)
        for row in rows:
            if row["eccentricity"] is None:
                writer.writerow([row["speed_rpm"]] + [""] * (len(COLUMNS) - 1))
                continue
            writer.writerow([row["speed_rpm"], *row["eccentricity"], row["eccentricity_ratio"],
                             *np.ravel(row["stiffness"]), *np.ravel(row["damping"])])
    return Path(path)


def plot(rows: list[dict], title: str, path: str | Path, note=None) -> Path:
    figure, (stiffness, damping) = new_figure(2, 1, figsize=(7, 6), sharex=True)
    found = [row for row in rows if row["eccentricity"] is not None]
    speeds = [row["speed_rpm"] for row in found]
    for k, entry in enumerate(ENTRIES):
        stiffness.plot(speeds, [np.ravel(row["stiffness"])[k] / 1e6 for row in found], "o-", label=f"k_{entry}")
        damping.plot(speeds, [np.ravel(row["damping"])[k] / 1e3 for row in found], "o-", label=f"c_{entry}")
    stiffness.set_ylabel("stiffness [N/µm]")
    damping.set_ylabel("damping [N s/mm]")
    damping.set_xlabel("speed [rpm]")
    for axis in (stiffness, damping):
        axis.grid(True, alpha=0.3)
        axis.legend(fontsize=8, ncol=4)
    stiffness.set_title(f"{title}: coefficients at the equilibrium under the static load")
    return save_figure(figure, path, status_note=note)
