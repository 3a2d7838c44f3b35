"""JSON files: strict JSON (non-finite numbers become ``null``), written atomically."""

from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np

#: Significant digits a summary writes for a float: beyond them the numbers are round-off or solver noise.
DIGITS = 8


def json_safe(value):
    """``value`` with every non-finite float (NaN, ±inf) replaced by ``None``, recursively through dicts, lists
    and tuples (tuples become lists); numpy scalars and arrays become Python numbers and lists."""
    if isinstance(value, np.ndarray):
        return json_safe(value.tolist())
    if isinstance(value, np.generic):
        value = value.item()
    if isinstance(value, float) and not math.isfinite(value):
        return None
    if isinstance(value, dict):
        return {key: json_safe(item) for key, item in value.items()}
    if isinstance(value, (list, tuple)):
        return [json_safe(item) for item in value]
    return value


def rounded(value, digits: int = DIGITS):
    """``value`` with every float rounded to ``digits`` significant digits, through dicts and lists."""
    if isinstance(value, float) and math.isfinite(value) and value != 0.0:
        return round(value, digits - 1 - math.floor(math.log10(abs(value))))
    if isinstance(value, dict):
        return {key: rounded(item, digits) for key, item in value.items()}
    if isinstance(value, list):
        return [rounded(item, digits) for item in value]
    return value


def write_json(path: str | Path, data) -> Path:
    """Write ``data`` (through :func:`json_safe`) to ``path`` as indented JSON; a crash never leaves a half-written
    file (the text goes to ``path.part`` first, then replaces ``path``). Returns the path."""
    path = Path(path)
    temporary = path.with_name(path.name + ".part")
    temporary.write_text(json.dumps(json_safe(data), indent=2, allow_nan=False) + "\n")
    temporary.replace(path)
    return path
