"""``make bench``: run every benchmark; each writes its JSON under benchmarks/out/."""

from __future__ import annotations

import importlib
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))

BENCHMARKS = ["bench_force_evaluation", "bench_kernel_cost", "bench_revolution", "bench_engines", "bench_exudyn_overhead",
              "bench_lubricated", "bench_sweep", "bench_study", "bench_journal", "bench_spatial"]

if __name__ == "__main__":
    for name in sys.argv[1:] or BENCHMARKS:
        print(f"== {name}")
        importlib.import_module(name).main()
