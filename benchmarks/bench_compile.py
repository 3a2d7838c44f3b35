"""The first-run compile time of each family of compiled kernels, as a fresh install meets it.

Each family is compiled in a fresh Python process with an empty numba cache (``NUMBA_CACHE_DIR`` a new empty
directory), and its compile time is the first call's time less that of an identical second call (which runs the
same work from the compiled code): both as wall time and as the process's CPU time (less sensitive to other load
on a shared machine; numba compiles on one thread). The families:

* ``force_kernels`` — the force kernels as Exudyn's connectors call them from Python:
  :func:`~bearing_mbs.elements.element_forces` and :func:`~bearing_mbs.elements.element_jacobian`;
* ``reference_explicit`` — the reference engine's first run with an explicit method (``rk4``: the explicit
  methods share one driver) on the seed bearing, the time a user waits before the first step;
* ``reference_implicit`` — the same with ``generalized_alpha`` (its own driver);
* ``journal_film`` — the fluid-film kernels of a journal bearing (the film's force and its Jacobian; the film of a
  lubricated contact pair is part of ``force_kernels``);
* ``outside_kind_explicit`` — the explicit driver for a scene with a force kind registered from outside the
  package (a spring, as in ``tests/isolated_force_element.py``): every function the scene's types reach compiles
  again for it.

Each family also lists the compiled functions that took longest (numba's ``numba:compile`` events, nested
compiles included in their caller's figure).

With ``--before``, ``run_time`` compares the cost per step of compiled runs (:data:`RUN_TIME_CASES`: the seed
bearing's two models with RK4, its lubricated model with generalized-α, the document's case 4 with its central
difference) on the two checkouts: each case's wall time per step, best of ``--run-time-repeat`` runs in processes
that alternate between the checkouts (so a change of the machine's load falls on both), and the ratio after/before.

``--before DIR`` also measures the families on another checkout (its root on ``PYTHONPATH``: e.g. ``git archive``
of the base commit unpacked into DIR), and the report puts the two side by side. ``--repeat N`` measures each N
times and reports every figure and the smallest. Never used as a test: timings are only reported.
"""

from __future__ import annotations

import argparse
import json
import math
import os
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
FAMILIES = ("force_kernels", "reference_explicit", "reference_implicit", "journal_film", "outside_kind_explicit")
#: The seed bearing's run: a few steps, output every 1e-4 s (compilation dominates the first call).
SEED_RUN = ["scenario.end_time=0.0002", "analysis.start=0", "solver.output_interval=0.0001"]
#: How many of a family's compiled functions its report lists.
LISTED = 12
#: name -> (scenario, overrides, simulated time [s]): compiled runs whose cost per step is compared.
RUN_TIME_CASES = {
    "seed_lubricated_rk4": ("seed_hss_steady.toml", ["solver.reference.method=rk4", "solver.reference.step=1e-7",
                                                     "analysis.start=0"], 2e-3),
    "seed_dry_rk4": ("seed_hss_steady.toml", ["scenario.variant=dry", "solver.reference.method=rk4",
                                              "solver.reference.step=1e-7", "analysis.start=0"], 2e-3),
    "seed_lubricated_generalized_alpha": ("seed_hss_steady.toml", ["solver.reference.method=generalized_alpha",
                                                                   "solver.reference.step=1e-5", "analysis.start=0"],
                                          0.02),
    "case4_central_difference": ("seed_case4.toml", ["solver.reference.step=1e-6"], 0.05),
}
#: Runs of each case in one process (the fastest counts).
RUNS_PER_PROCESS = 3


# ---------------------------------------------------------------------------------------------------- the child
def _listen():
    """Record numba's compile events; returns a function giving [(seconds, function)] longest first."""
    from numba.core import event

    listener = event.RecordingListener()
    event.register("numba:compile", listener)

    def longest():
        started, spans = {}, []
        for stamp, e in listener.buffer:
            key = (str(e.data.get("dispatcher")), str(e.data.get("args")))
            if e.is_start:
                started[key] = stamp
            elif key in started:
                name = getattr(e.data.get("dispatcher"), "py_func", None)
                label = f"{name.__module__}.{name.__qualname__}" if name else key[0]
                spans.append((stamp - started.pop(key), label))
        return [{"function": label, "wall_s": round(seconds, 2)} for seconds, label in sorted(spans, reverse=True)]

    return longest


def _seed_scene(method: str):
    from bearing_mbs.models import build_scene, load_spec

    spec = load_spec(ROOT / "scenarios" / "seed_hss_steady.toml",
                     ["solver.engine=reference", f"solver.reference.method={method}", *SEED_RUN])
    return build_scene(spec), spec.solver


def _family_call(family: str):
    """The family's first call, as a function of no arguments (everything else prepared)."""
    import numpy as np

    if family in ("reference_explicit", "reference_implicit"):
        from bearing_mbs.engines import simulate

        scene, solver = _seed_scene("rk4" if family == "reference_explicit" else "generalized_alpha")

        def run():
            result = simulate(scene, solver, 2e-4)
            assert result.success, result.message
        return run
    if family == "force_kernels":
        from bearing_mbs.contact.kernel import N_PAIR_OUTPUTS
        from bearing_mbs.elements import element_forces, element_jacobian, pack_scene

        scene, _ = _seed_scene("rk4")
        packed = pack_scene(scene)
        q, v = scene.initial_state()
        n = q.size
        latched, forces = np.zeros(packed.pairs.kind.size), np.empty(n)
        pairs, position, velocity = np.empty((latched.size, N_PAIR_OUTPUTS)), np.empty((n, n)), np.empty((n, n))

        def run():  # as the connectors call them (bearing_mbs.engines.exudyn.connectors)
            element_forces(packed.elements, 0.0, q, v, latched, forces, pairs, False)
            element_forces(packed.elements, 0.0, q, v, latched, forces, pairs, True)
            element_jacobian(packed.elements, 0.0, q, v, latched, pairs, position, velocity)
        return run
    if family == "journal_film":
        return _journal_call()
    if family == "outside_kind_explicit":
        return _outside_kind_call()
    raise SystemExit(f"unknown family {family!r}; known: {', '.join(FAMILIES)}")


def _journal_call():
    """The short-bearing film of a 50 mm journal at ε = 0.5 (force and Jacobian, compiled on their own)."""
    import numpy as np

    from bearing_mbs.elements import journal_bearings

    films = journal_bearings.pack([journal_bearings.JournalFilm("film", body=0, count=1, radius=0.025, length=0.02,
                                                                clearance=5e-5, viscosity=0.02)])
    q, v = np.array([2.5e-5, 0.0, 0.0]), np.array([0.0, 0.0, 300.0])
    position, velocity = np.zeros((3, 3)), np.zeros((3, 3))

    def run():
        journal_bearings.film_load(films, 0, q, v)
        journal_bearings.add_jacobian(films, 0.0, q, v, position, velocity)
    return run


def _outside_kind_call():
    """A spring registered from outside the package between two free bodies, run by the reference engine's
    explicit driver (the example of docs/guide-add-a-force-element.md)."""
    from dataclasses import dataclass
    from typing import NamedTuple

    import numba
    import numpy as np

    from bearing_mbs.core.force_element import ForceElement
    from bearing_mbs.core.scene import Body, Scene
    from bearing_mbs.elements import FORCE_ELEMENTS
    from bearing_mbs.engines import simulate
    from bearing_mbs.spec import ReferenceSolver, SolverSpec

    @dataclass(frozen=True)
    class Spring:
        name: str
        body_a: int
        body_b: int
        stiffness: float

    class SpringArrays(NamedTuple):
        body_a: np.ndarray
        body_b: np.ndarray
        stiffness: np.ndarray

    def pack(springs):
        return SpringArrays(np.array([s.body_a for s in springs], dtype=np.int64),
                            np.array([s.body_b for s in springs], dtype=np.int64),
                            np.array([s.stiffness for s in springs]))

    @numba.njit(inline="always")
    def add_spring_forces(parameters, q, forces):
        for j in range(parameters.body_a.size):
            a, b = parameters.body_a[j], parameters.body_b[j]
            dx, dy = q[3 * b] - q[3 * a], q[3 * b + 1] - q[3 * a + 1]
            fx, fy = parameters.stiffness[j] * dx, parameters.stiffness[j] * dy
            forces[3 * a] += fx
            forces[3 * a + 1] += fy
            forces[3 * b] -= fx
            forces[3 * b + 1] -= fy

    if hasattr(ForceElement, "force_arguments"):  # each kind takes the state it needs
        @numba.njit(inline="always")
        def add_forces(parameters, t, q, v, forces, power):
            add_spring_forces(parameters, q, forces)
    else:  # a checkout before: every kind took the contact pairs' state (``--before``)
        @numba.njit(inline="always")
        def add_forces(parameters, t, q, v, latched, forces, pair_out, power, complete):
            add_spring_forces(parameters, q, forces)

    def add_forces_twin(parameters, *arguments):
        raise NotImplementedError

    FORCE_ELEMENTS.register(ForceElement(name="springs", item_type=Spring, parameters=SpringArrays, pack=pack,
                                         add_forces=add_forces, add_forces_twin=add_forces_twin))
    bodies = (Body("a", 2.0, 1e-3, (0.0, 0.0, 0.0)), Body("b", 3.0, 1e-3, (0.101, 0.0, 0.0)))
    scene = Scene("oscillator", bodies, forces=(Spring("spring", 0, 1, 4.0e4),))
    solver = SolverSpec(engine="reference", output_interval=1e-3, reference=ReferenceSolver(method="rk4", step=1e-5))

    def run():
        result = simulate(scene, solver, 2e-3)
        assert result.success, result.message
    return run


def child(family: str) -> None:
    """Measure one family in this (fresh) process; print its figures as JSON on the last line."""
    wall, cpu = time.perf_counter(), time.process_time()
    longest = _listen()
    import bearing_mbs.engines  # noqa: F401 (numba, numpy, exudyn and the package: the import's cost)

    figures = {"import_wall_s": time.perf_counter() - wall, "import_cpu_s": time.process_time() - cpu}
    run = _family_call(family)
    for call in ("first", "second"):
        wall, cpu = time.perf_counter(), time.process_time()
        run()
        figures[f"{call}_call_wall_s"], figures[f"{call}_call_cpu_s"] = time.perf_counter() - wall, \
            time.process_time() - cpu
    figures["compile_wall_s"] = figures["first_call_wall_s"] - figures["second_call_wall_s"]
    figures["compile_cpu_s"] = figures["first_call_cpu_s"] - figures["second_call_cpu_s"]
    figures["longest_compiles"] = longest()[:LISTED]
    print(json.dumps(figures))


def run_time_child() -> None:
    """Wall time per step [µs] of each run-time case, best of :data:`RUNS_PER_PROCESS` (compiled beforehand)."""
    from bearing_mbs.engines import simulate
    from bearing_mbs.models import build_scene, load_spec

    figures = {}
    for name, (scenario, overrides, end_time) in RUN_TIME_CASES.items():
        spec = load_spec(ROOT / "scenarios" / scenario, ["solver.engine=reference", f"scenario.end_time={end_time}",
                                                         "solver.output_interval=1e-4", *overrides])
        scene = build_scene(spec)
        simulate(scene, spec.solver, 2e-4)  # compiled or loaded from the cache
        best = math.inf
        for _ in range(RUNS_PER_PROCESS):
            result = simulate(scene, spec.solver, end_time)
            assert result.success, result.message
            best = min(best, result.stats.wall_time_s / result.stats.steps * 1e6)
        figures[name] = best
    print(json.dumps(figures))


# --------------------------------------------------------------------------------------------------- the parent
def measure(family: str, tree: Path) -> dict:
    """One family compiled by a fresh process on the sources of ``tree``, with an empty numba cache."""
    with tempfile.TemporaryDirectory(prefix="numba-cache-") as cache:
        environment = {**os.environ, "NUMBA_CACHE_DIR": cache, "PYTHONPATH": str(tree)}
        run = subprocess.run([sys.executable, str(Path(__file__).resolve()), "--child", family], env=environment,
                             capture_output=True, text=True, cwd=tree, check=False)
    if run.returncode != 0:
        raise RuntimeError(f"{family} on {tree} failed:\n{run.stderr[-3000:]}")
    return json.loads(run.stdout.strip().splitlines()[-1])


def run_time(trees: dict, repeat: int) -> dict:
    """Cost per step of each case on each checkout, processes alternating between them; best of ``repeat``."""
    caches = {label: tempfile.mkdtemp(prefix=f"numba-cache-{label}-") for label in trees}
    each = {label: [] for label in trees}
    for _ in range(repeat):
        for label, tree in trees.items():
            environment = {**os.environ, "NUMBA_CACHE_DIR": caches[label], "PYTHONPATH": str(tree)}
            run = subprocess.run([sys.executable, str(Path(__file__).resolve()), "--run-time-child"], env=environment,
                                 capture_output=True, text=True, cwd=tree, check=False)
            if run.returncode != 0:
                raise RuntimeError(f"run time on {tree} failed:\n{run.stderr[-3000:]}")
            each[label].append(json.loads(run.stdout.strip().splitlines()[-1]))
    report = {"unit": "microseconds per step (wall), best of all runs", "runs_per_checkout": repeat * RUNS_PER_PROCESS,
              "cases": {}}
    for name in RUN_TIME_CASES:
        entry = {label: min(r[name] for r in runs) for label, runs in each.items()}
        entry.update({f"{label}_each": [round(r[name], 3) for r in runs] for label, runs in each.items()})
        if "before" in entry:
            entry["ratio_after_to_before"] = entry["after"] / entry["before"]
        report["cases"][name] = entry
        print(f"{name:36s} " + "  ".join(f"{label} {entry[label]:8.3f} us" for label in trees)
              + (f"  ratio {entry['ratio_after_to_before']:.3f}" if "before" in entry else ""), flush=True)
    return report


def summary(runs: list[dict]) -> dict:
    """Every repeat's compile time and the smallest (the least disturbed by other load)."""
    return {"compile_cpu_s": min(r["compile_cpu_s"] for r in runs),
            "compile_wall_s": min(r["compile_wall_s"] for r in runs),
            "compile_cpu_s_each": [round(r["compile_cpu_s"], 2) for r in runs],
            "compile_wall_s_each": [round(r["compile_wall_s"], 2) for r in runs],
            "import_cpu_s": min(r["import_cpu_s"] for r in runs),
            "longest_compiles": min(runs, key=lambda r: r["compile_cpu_s"])["longest_compiles"]}


def main(argv: list[str] | None = None) -> dict:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--before", type=Path, help="a checkout of the base commit, measured too")
    parser.add_argument("--before-label", default="f36a354", help="what --before is (a commit)")
    parser.add_argument("--repeat", type=int, default=1)
    parser.add_argument("--families", default=",".join(FAMILIES), help="comma-separated; empty: none")
    parser.add_argument("--run-time-repeat", type=int, default=3, help="processes per checkout (0: skip)")
    parser.add_argument("--child", help=argparse.SUPPRESS)
    parser.add_argument("--run-time-child", action="store_true", help=argparse.SUPPRESS)
    arguments = parser.parse_args(argv)
    if arguments.child:
        child(arguments.child)
        return {}
    if arguments.run_time_child:
        run_time_child()
        return {}
    from common import write

    trees = {"after": ROOT, **({"before": arguments.before.resolve()} if arguments.before else {})}
    report = {"method": "fresh process, empty NUMBA_CACHE_DIR; compile = first call - identical second call",
              "before_commit": arguments.before_label if arguments.before else None, "families": {}}
    for family in filter(None, arguments.families.split(",")):
        entry = {}
        for label, tree in trees.items():
            runs = [measure(family, tree) for _ in range(arguments.repeat)]
            entry[label] = summary(runs)
            print(f"{family:24s} {label:6s} compile cpu {entry[label]['compile_cpu_s']:7.1f} s "
                  f"(each {entry[label]['compile_cpu_s_each']}), wall {entry[label]['compile_wall_s']:7.1f} s",
                  flush=True)
        if "before" in entry:
            entry["cpu_ratio_after_to_before"] = entry["after"]["compile_cpu_s"] / entry["before"]["compile_cpu_s"]
        report["families"][family] = entry
    if arguments.before and arguments.run_time_repeat:
        report["run_time"] = run_time(trees, arguments.run_time_repeat)
    write("compile", report)
    return report


if __name__ == "__main__":
    if "--child" not in sys.argv:
        sys.path.insert(0, str(Path(__file__).resolve().parent))
    main()
