"""A journal bearing's coefficients over speed as a ROSS bearing element.

ROSS (``ross-rotordynamics``, https://github.com/petrobras/ross; an optional extra here: ``pip install -e .[ross]``,
with ``plotly<6``, which ROSS 2.3 imports) takes a fluid-film bearing as its eight coefficients against speed:
``ross.BearingElement(n, kxx, cxx, kyy=…, kxy=…, kyx=…, cyy=…, cxy=…, cyx=…, frequency=…)`` with the frequencies in
rad/s, interpolated between them. Its convention is ours (:mod:`bearing_mbs.fluid_film.coefficients`): the bearing's
force on the journal is −K x − C ẋ, x and y in the plane of the journal's centre, the journal turning from +x towards
+y. The rows are those of ``bearing-mbs journal`` with ``journal.coefficient_speeds_rpm`` (``coefficients_over_speed``
of its summary: ``speed_rpm``, ``stiffness`` and ``damping`` as 2 × 2 lists, [[xx, xy], [yx, yy]]).
"""

from __future__ import annotations

import json
import math
from pathlib import Path


def bearing_element(rows: list[dict], node: int, tag: str | None = None):
    """A ``ross.BearingElement`` at shaft ``node`` with the coefficients of ``rows`` (every row needs its
    equilibrium: a speed without one has no coefficients)."""
    try:
        import ross
    except ImportError as error:
        raise ImportError("ROSS is an optional extra: pip install -e '.[ross]' (ross-rotordynamics 2.3 with "
                          "plotly<6)") from error
    missing = [row["speed_rpm"] for row in rows if row.get("stiffness") is None]
    if not rows or missing:
        raise ValueError(f"coefficients_over_speed: every speed needs its coefficients (none at {missing} rpm)"
                         if rows else "coefficients_over_speed: no rows")
    rows = sorted(rows, key=lambda row: row["speed_rpm"])

    def entry(kind, i, j):
        return [row[kind][i][j] for row in rows]

    return ross.BearingElement(
        n=node, kxx=entry("stiffness", 0, 0), kxy=entry("stiffness", 0, 1), kyx=entry("stiffness", 1, 0),
        kyy=entry("stiffness", 1, 1), cxx=entry("damping", 0, 0), cxy=entry("damping", 0, 1),
        cyx=entry("damping", 1, 0), cyy=entry("damping", 1, 1),
        frequency=[row["speed_rpm"] * math.pi / 30 for row in rows], tag=tag)


def bearing_element_from_summary(summary: str | Path, node: int, tag: str | None = None):
    """:func:`bearing_element` from the ``summary.json`` of ``bearing-mbs journal``."""
    return bearing_element(json.loads(Path(summary).read_text())["coefficients_over_speed"], node, tag)
