"""An append-only CSV table of study runs: one row per finished run, flushed at once, read back on resume."""

from __future__ import annotations

import csv
import math
from pathlib import Path

import numpy as np


def text(value) -> str:
    """A cell: '' for None, the exact repr of a float, str otherwise."""
    if value is None:
        return ""
    return repr(float(value)) if isinstance(value, (float, np.floating)) else str(value)


def number(value) -> float:
    """A cell read back as a float (NaN where it is empty or not a number)."""
    try:
        return float(value)
    except (TypeError, ValueError):
        return math.nan


def read_rows(path: Path) -> list[dict]:
    """Every row written so far (none if the table does not exist yet)."""
    if not path.exists():
        return []
    with path.open(newline="") as handle:
        return list(csv.DictReader(handle))


def append_row(path: Path, row: dict, columns) -> None:
    """Append one row (a header first for a new table) and flush it, so a killed study keeps it."""
    new = not path.exists()
    with path.open("a", newline="") as handle:
        writer = csv.DictWriter(handle, fieldnames=columns)
        if new:
            writer.writeheader()
        writer.writerow({k: text(v) for k, v in row.items()})
        handle.flush()
