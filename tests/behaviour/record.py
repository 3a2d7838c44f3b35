"""Record the behaviour the restructuring must keep: summaries and result arrays of fixed runs.

Run ``python tests/behaviour/record.py`` only when a change alters the numbers on purpose (a physics
change), and say so in the commit. ``tests/test_behaviour_unchanged.py`` replays the runs through the
command line, the one interface that stays fixed, and compares.
"""

from __future__ import annotations

import hashlib
import json
import sys
import tempfile
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
SCENARIOS = HERE.parents[1] / "scenarios"
RECORD = HERE / "record.json"
ARRAYS = HERE / "arrays.npz"
RESULT_ARRAYS = ("time", "position", "velocity", "pair_output", "constraint_forces", "work", "events")
#: Summary entries that measure the machine, not the model.
UNSTABLE_KEYS = ("wall_time_s",)

#: name -> (command, scenario, extra arguments). Cases 4 and 5 and the penalty-cage bearing are chaotic beyond
#: about 0.3 s and 10 ms, so their windows are shorter than that. The seed HSS runs are the document's dry model
#: (the scenarios' variant "dry"; their default is lubricated). Exudyn's runs differentiate numerically, as when they
#: were recorded (the analytic Jacobian solves the same steps to Newton's tolerance, not bit for bit).
DRY = ["--set", "scenario.variant=dry"]
HSS = [*DRY, "--set", "scenario.end_time=0.004", "--set", "analysis.start=0.001"]
NUMERICAL = ["--set", "solver.exudyn.jacobian=numerical"]
RUNS = {
    "seed_case1": ("run", "seed_case1.toml", []),
    "seed_case2": ("run", "seed_case2.toml", []),
    "seed_case3": ("run", "seed_case3.toml", []),
    "seed_case4": ("run", "seed_case4.toml", ["--set", "scenario.end_time=0.03"]),
    "seed_case5": ("run", "seed_case5.toml", ["--set", "scenario.end_time=0.03"]),
    "hss_steady_exudyn": ("run", "seed_hss_steady.toml", [*HSS, *NUMERICAL, "--engine", "exudyn"]),
    "hss_steady_reference": ("run", "seed_hss_steady.toml", [*HSS, "--engine", "reference"]),
    "hss_startup_exudyn": ("run", "seed_hss_startup.toml", [*HSS, *NUMERICAL, "--engine", "exudyn"]),
    "hss_startup_reference": ("run", "seed_hss_startup.toml", [*HSS, "--engine", "reference"]),
    "stiffness": ("stiffness", "seed_hss_steady.toml", DRY),
}


def execute(name: str, directory: Path) -> tuple[dict, dict[str, np.ndarray]]:
    """Run one entry through the command line; return its summary (machine-dependent keys removed) and arrays."""
    from bearing_mbs.cli import main

    command, scenario, extra = RUNS[name]
    out = directory / name
    args = [command, str(SCENARIOS / scenario), "--out", str(out), "--no-figures", *extra]
    if command == "run":
        args.append("--quiet")
    code = main(args)
    summary = json.loads((out / "summary.json").read_text())
    summary = {k: v for k, v in summary.items() if k not in UNSTABLE_KEYS}
    summary["exit_code"] = code
    arrays = {}
    if command == "run":
        with np.load(out / "result.npz", allow_pickle=False) as data:
            arrays = {key: data[key] for key in RESULT_ARRAYS}
    return summary, arrays


def digest(array: np.ndarray) -> str:
    return hashlib.sha256(np.ascontiguousarray(array).tobytes()).hexdigest()


def main() -> None:
    names = sys.argv[1:] or list(RUNS)
    record = json.loads(RECORD.read_text()) if RECORD.exists() else {}
    stored = dict(np.load(ARRAYS)) if ARRAYS.exists() else {}
    with tempfile.TemporaryDirectory() as tmp:
        for name in names:
            summary, arrays = execute(name, Path(tmp))
            record[name] = {"summary": summary, "sha256": {k: digest(a) for k, a in arrays.items()}}
            stored.update({f"{name}/{k}": a for k, a in arrays.items()})
            print(name, summary.get("status"), {k: a.shape for k, a in arrays.items()})
    RECORD.write_text(json.dumps(record, indent=1, sort_keys=True) + "\n")
    np.savez_compressed(ARRAYS, **stored)


if __name__ == "__main__":
    main()
