"""Throughput of a sensitivity sweep on a local Dask cluster: 2 workers against 1 worker on the same 20 runs.

The runs are seed_case2 (a ball dropped on a floor, reference engine, velocity Verlet) over a Latin
hypercube of restitution and contact stiffness. Each worker first runs the base case once, so the
compiled kernels are loaded before the clock starts; the time covers planning, submitting, evaluating
and storing all 20 runs (cluster start-up excluded, reported separately). The machine's load average is
recorded too: other processes competing for the CPUs distort the 2-worker figure.

    .venv/bin/python benchmarks/bench_sweep.py [--runs 20] [--step 2e-6]

writes ``benchmarks/out/sweep_throughput.json``.
"""

from __future__ import annotations

import argparse
import datetime
import json
import logging
import os
import sys
import tempfile
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from common import machine

ROOT = Path(__file__).resolve().parents[1]
OUT = ROOT / "benchmarks" / "out" / "sweep_throughput.json"


def study(runs: int, step: float):
    from bearing_mbs.studies.sensitivity import (
        Method,
        Parameter,
        SimulationModel,
        Study,
    )

    model = SimulationModel(str(ROOT / "scenarios" / "seed_case2.toml"),
                            ("solver.reference.method=velocity_verlet", f"solver.reference.step={step!r}"))
    return Study("bench_sweep", model,
                 [Parameter("contact.wall.restitution", (0.5, 0.95)),
                  Parameter("contact.wall.stiffness", (2e6, 2e7), "logunif")],
                 ("restitution_effective", "max_penetration"), Method("latin", analyzer="none", samples=runs),
                 seed=2024)


def warm_up(model, inputs) -> float:
    """Run the base case once in this worker (loads the compiled kernels); its wall time [s]."""
    start = time.perf_counter()
    model.evaluate(inputs)
    return time.perf_counter() - start


def measure(the_study, workers: int) -> dict:
    from bearing_mbs.studies.sensitivity import (
        EvaluationStats,
        connect,
        evaluate,
        sample,
    )

    X = sample(the_study)
    base = the_study.model.canonical(the_study.model.base())
    started = time.perf_counter()
    with connect(workers=workers) as client, tempfile.TemporaryDirectory() as out:
        startup = time.perf_counter() - started
        warm = client.run(warm_up, the_study.model, base)
        stats = EvaluationStats()
        start = time.perf_counter()
        table = evaluate(the_study, X, out, client, stats=stats)
        wall = time.perf_counter() - start
    assert (table["status"] == "success").all() and stats.evaluated == len(X)
    run_time = float(table["wall_time_s"].sum())
    return {
        "workers": workers,
        "runs": int(stats.evaluated),
        "wall_s": wall,
        "runs_per_s": stats.evaluated / wall,
        "mean_run_s": run_time / stats.evaluated,
        "run_time_sum_s": run_time,
        "cluster_start_s": startup,
        "warm_up_s": sorted(warm.values()),
    }


def main(argv: list[str] = ()) -> dict:
    """Run the benchmark (``argv``: command-line options; none when called by ``run_all.py``)."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", type=int, default=20)
    parser.add_argument("--step", type=float, default=2e-6, help="reference-engine step [s]")
    parser.add_argument("--out", type=Path, default=OUT)
    args = parser.parse_args(list(argv))
    logging.basicConfig(level=logging.WARNING)
    import distributed  # noqa: F401  (sets its own log levels on import)

    logging.getLogger("distributed").setLevel(logging.WARNING)
    the_study = study(args.runs, args.step)
    load_before = os.getloadavg()
    results = [measure(the_study, workers) for workers in (1, 2)]
    load_after = os.getloadavg()
    one, two = results
    report = {
        "benchmark": "sweep_throughput",
        "description": __doc__.splitlines()[0],
        "case": {"scenario": "scenarios/seed_case2.toml", "method": "velocity_verlet", "step_s": args.step,
                 "sampler": "latin", "parameters": the_study.names, "runs": args.runs},
        "results": results,
        "speedup_2_over_1": two["runs_per_s"] / one["runs_per_s"],
        "parallel_efficiency": two["runs_per_s"] / one["runs_per_s"] / 2,
        "machine": machine(),  # benchmarks/common.py: platform, CPUs, versions, load average
        # other processes on the machine compete with the workers: a 1-minute load near or above the CPU
        # count before the run makes the 2-worker figure meaningless
        "load_average_1_5_15min": {"before": load_before, "after": load_after},
        "date": datetime.datetime.now(datetime.UTC).isoformat(timespec="seconds"),
    }
    args.out.parent.mkdir(parents=True, exist_ok=True)
    args.out.write_text(json.dumps(report, indent=2) + "\n")
    print(f"1 worker: {one['runs_per_s']:.3g} runs/s; 2 workers: {two['runs_per_s']:.3g} runs/s; "
          f"speedup {report['speedup_2_over_1']:.2f} -> {args.out}")
    return report


if __name__ == "__main__":
    main(sys.argv[1:])
