"""Record the behaviour the code must keep: summaries and result arrays of fixed runs.

    python tests/behaviour/record.py                  # re-record every run
    python tests/behaviour/record.py NAME [NAME ...]  # re-record these runs only
    python tests/behaviour/record.py --compare [NAME ...]
        # replay, write nothing, print each run's largest deviation per unit as a fraction of its tolerance

Re-record only when a change alters the numbers on purpose (a physics change, or a summary that gains or loses an
entry), and say so in the commit. ``tests/test_behaviour_unchanged.py`` replays the runs through the command line,
the one interface that stays fixed, and compares them by the rule of ``compare.py`` (README.md in this folder).
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

#: name -> (command, scenario, extra arguments). Each window ends before the run's horizon, where a perturbation of
#: one unit in the last place (one ulp) of an input has grown to the tolerance (README.md: the figures): cases 4 and 5
#: at 0.03 s (no contact yet); case 3 at 0.5 s, in the flight after its first landing (its slip sits on the dead
#: zone's edge, and the second landing near 0.55 s turns a one-ulp difference into 6e-4 of its speeds); the start-up
#: of the penalty-cage bearing at 3 ms (from 3 to 4 ms a one-ulp difference grows 5-30-fold, and Exudyn's on a libm
#: without FMA reaches 0.95 of the tolerance). The seed HSS runs are the document's dry model (the scenarios' variant
#: "dry"; their default is lubricated). Exudyn's runs differentiate numerically, as when they were recorded (the
#: analytic Jacobian solves the same steps to Newton's tolerance, not bit for bit).
DRY = ["--set", "scenario.variant=dry"]
HSS = [*DRY, "--set", "scenario.end_time=0.004", "--set", "analysis.start=0.001"]
STARTUP = [*DRY, "--set", "scenario.end_time=0.003", "--set", "analysis.start=0.001"]
NUMERICAL = ["--set", "solver.exudyn.jacobian=numerical"]
RUNS = {
    "seed_case1": ("run", "seed_case1.toml", []),
    "seed_case2": ("run", "seed_case2.toml", []),
    "seed_case3": ("run", "seed_case3.toml", ["--set", "scenario.end_time=0.5"]),
    "seed_case4": ("run", "seed_case4.toml", ["--set", "scenario.end_time=0.03"]),
    "seed_case5": ("run", "seed_case5.toml", ["--set", "scenario.end_time=0.03"]),
    "hss_steady_exudyn": ("run", "seed_hss_steady.toml", [*HSS, *NUMERICAL, "--engine", "exudyn"]),
    "hss_steady_reference": ("run", "seed_hss_steady.toml", [*HSS, "--engine", "reference"]),
    "hss_startup_exudyn": ("run", "seed_hss_startup.toml", [*STARTUP, *NUMERICAL, "--engine", "exudyn"]),
    "hss_startup_reference": ("run", "seed_hss_startup.toml", [*STARTUP, "--engine", "reference"]),
    "stiffness": ("stiffness", "seed_hss_steady.toml", DRY),
}


def execute(name: str, directory: Path, extra: tuple[str, ...] = ()) -> tuple[dict, dict[str, np.ndarray]]:
    """Run one entry through the command line (with ``extra`` arguments appended, e.g. a perturbation); return its
    summary (machine-dependent keys removed, the exit code added) and its result arrays."""
    from bearing_mbs.cli import main

    command, scenario, arguments = RUNS[name]
    out = directory / name
    args = [command, str(SCENARIOS / scenario), "--out", str(out), "--no-figures", *arguments, *extra]
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


def recorded(name: str) -> tuple[dict, dict[str, np.ndarray]]:
    """The recorded summary and arrays of one run."""
    summary = json.loads(RECORD.read_text())[name]["summary"]
    with np.load(ARRAYS) as data:
        arrays = {key.split("/", 1)[1]: data[key] for key in data.files if key.split("/", 1)[0] == name}
    return summary, arrays


def record(names: list[str]) -> None:
    entries = json.loads(RECORD.read_text()) if RECORD.exists() else {}
    stored = dict(np.load(ARRAYS)) if ARRAYS.exists() else {}
    with tempfile.TemporaryDirectory() as tmp:
        for name in names:
            summary, arrays = execute(name, Path(tmp))
            entries[name] = {"summary": summary, "sha256": {k: digest(a) for k, a in arrays.items()}}
            stored = {k: a for k, a in stored.items() if not k.startswith(f"{name}/")}
            stored.update({f"{name}/{k}": a for k, a in arrays.items()})
            print(name, summary.get("status"), {k: a.shape for k, a in arrays.items()})
    RECORD.write_text(json.dumps(entries, indent=1, sort_keys=True) + "\n")
    np.savez_compressed(ARRAYS, **stored)


def report(names: list[str]) -> None:
    """Replay and print, per run, the largest deviation of each unit as a fraction of its tolerance."""
    from compare import Mismatch, compare, worst_by_unit

    with tempfile.TemporaryDirectory() as tmp:
        for name in names:
            summary, arrays = execute(name, Path(tmp))
            try:
                worst = worst_by_unit(compare(summary, arrays, *recorded(name)))
            except Mismatch as mismatch:
                print(f"{name}: MISMATCH {mismatch}")
                continue
            top = max(worst.values(), key=lambda d: d.ratio)
            print(f"{name}: worst {top.ratio:.2g} of the tolerance ({top.where} [{top.unit}]); per unit: "
                  + ", ".join(f"{u} {d.ratio:.1e}" for u, d in sorted(worst.items())))


def main() -> None:
    from bearing_mbs.core.numba_cache import invalidate_if_stale

    invalidate_if_stale()
    arguments = sys.argv[1:]
    if arguments[:1] == ["--compare"]:
        report(arguments[1:] or list(RUNS))
    else:
        record(arguments or list(RUNS))


if __name__ == "__main__":
    main()
