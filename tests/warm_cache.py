"""Compile the engines' kernels into numba's on-disk cache before the test workers start (``make test``).

Every scene made of the package's own force elements has the same compiled types, so a short run of the seed
bearing compiles what all the tests' runs use: ``explicit`` the reference engine's driver for its explicit methods,
``implicit`` the one for generalized-α, ``exudyn`` the force and Jacobian kernels Exudyn's compiled connector calls.
Without it, both test workers would compile the same driver at the same time, each for a minute or more.

``python tests/warm_cache.py explicit exudyn`` runs those warm-ups in this process; :func:`warm` runs groups of them
in parallel processes (tests/conftest.py, in the xdist controller only). A warm-up that fails is reported and
otherwise ignored: the tests then compile for themselves and report the failure where it belongs.
"""

from __future__ import annotations

import subprocess
import sys
import time
from pathlib import Path

SCENARIO = Path(__file__).resolve().parents[1] / "scenarios" / "seed_hss_steady.toml"
#: A few steps of each engine (the kernels, not the run, are the point).
SHORT_RUN = ["scenario.end_time=2e-4", "analysis.start=0", "solver.output_interval=1e-4"]
SOLVERS = {
    "explicit": ["solver.engine=reference", "solver.reference.method=rk4"],
    "implicit": ["solver.engine=reference", "solver.reference.method=generalized_alpha"],
    "exudyn": ["solver.engine=exudyn", "solver.exudyn.method=generalized_alpha", "solver.exudyn.connector=compiled",
               "solver.exudyn.jacobian=analytic"],
}
#: Process groups of about equal compile time on two cores: the explicit driver and Exudyn's kernels, and the
#: implicit driver (docs/engines.md, "Compilation").
GROUPS = (("explicit", "exudyn"), ("implicit",))


def run(name: str) -> None:
    from bearing_mbs.engines import simulate
    from bearing_mbs.models import build_scene, load_spec

    spec = load_spec(SCENARIO, [*SOLVERS[name], *SHORT_RUN])
    simulate(build_scene(spec), spec.solver, 2e-4)


def warm(groups=GROUPS, write=sys.stderr.write) -> None:
    """Run each group of warm-ups in a process of its own, all at once, and wait for them."""
    started = time.perf_counter()
    processes = [subprocess.Popen([sys.executable, __file__, *group], stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                                  text=True) for group in groups]
    for group, process in zip(groups, processes):
        output, _ = process.communicate()
        if process.returncode != 0:
            write(f"warm_cache: {'+'.join(group)} failed (the tests will compile for themselves):\n{output[-2000:]}\n")
    write(f"warm_cache: kernels compiled or loaded in {time.perf_counter() - started:.0f} s\n")


if __name__ == "__main__":
    for argument in sys.argv[1:]:
        run(argument)
