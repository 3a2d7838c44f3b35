"""Shared helpers for benchmarks: machine information and JSON output under benchmarks/out/."""

from __future__ import annotations

import json
import os
import platform
import sys
import time
from importlib import metadata
from pathlib import Path

from bearing_mbs.core.numba_cache import invalidate_if_stale

#: The repository's scenario files.
SCENARIOS = Path(__file__).resolve().parents[1] / "scenarios"
invalidate_if_stale()  # the benchmarks are an entry point: check numba's cache once, before anything compiles

OUT = Path(__file__).resolve().parent / "out"


def machine() -> dict:
    """What the figures were measured on."""
    versions = {}
    for package in ("numpy", "numba", "exudyn", "scipy", "dask", "distributed", "SALib"):
        try:
            versions[package] = metadata.version(package)
        except metadata.PackageNotFoundError:
            pass
    return {
        "platform": platform.platform(),
        "processor": platform.processor() or platform.machine(),
        "cpu_count": os.cpu_count(),
        "affinity_cpus": len(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity") else None,
        "python": sys.version.split()[0],
        "versions": versions,
        "load_average": os.getloadavg() if hasattr(os, "getloadavg") else None,
        "date": time.strftime("%Y-%m-%dT%H:%M:%S%z"),
    }


def write(name: str, figures: dict) -> Path:
    """Write benchmarks/out/<name>.json with the figures and the machine information."""
    OUT.mkdir(exist_ok=True)
    path = OUT / f"{name}.json"
    path.write_text(json.dumps({"benchmark": name, "machine": machine(), **figures}, indent=2) + "\n")
    print(f"wrote {path}")
    return path


def best_of(function, repeats: int = 3) -> float:
    """Smallest wall time [s] of ``repeats`` calls (the least disturbed by other load)."""
    times = []
    for _ in range(repeats):
        start = time.perf_counter()
        function()
        times.append(time.perf_counter() - start)
    return min(times)
