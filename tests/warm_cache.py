"""Compile the engines' kernels into numba's on-disk cache before the test workers start (``make test``).

Every scene made of the package's own force elements has the same compiled types, so a short run of the seed
bearing compiles what all the tests' runs use: ``explicit`` the reference engine's driver for its explicit methods,
``implicit`` the one for generalized-α, ``exudyn`` the force and Jacobian kernels Exudyn's compiled connector calls,
``spatial`` the three-dimensional bearing's force kernel and the reference engine's RK4 and generalized-α for it (one
scene type serves every spatial test) and the force function Exudyn's spatial scenes call.
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
#: Process groups, all at once on two cores: the explicit driver and Exudyn's kernels (about 57 s), the implicit
#: driver (60 s: docs/engines.md, "Compilation"), the spatial kernels (40 s); three processes share the cores, so
#: the warm-up takes about half their sum, where each test worker would otherwise compile the spatial kernels itself.
GROUPS = (("explicit", "exudyn"), ("implicit",), ("spatial",))


def run(name: str) -> None:
    from bearing_mbs.engines import simulate
    from bearing_mbs.models import build_scene, load_spec

    if name == "spatial":
        return run_spatial()
    spec = load_spec(SCENARIO, [*SOLVERS[name], *SHORT_RUN])
    simulate(build_scene(spec), spec.solver, 2e-4)


def run_spatial() -> None:
    """A few steps of the seed bearing in three dimensions on each spatial method of both engines."""
    from bearing_mbs.engines.exudyn.spatial import simulate_spatial_exudyn
    from bearing_mbs.engines.reference.spatial import simulate_spatial_reference
    from bearing_mbs.models import load_spec
    from bearing_mbs.models.cylindrical_roller.spatial import build_spatial_bearing
    from bearing_mbs.spec import methods

    scene = build_spatial_bearing(load_spec(SCENARIO, ["cage.model=penalty"]), slices=2).scene
    for method in (methods.RK4, methods.GENERALIZED_ALPHA):
        simulate_spatial_reference(scene, 1e-6, 2e-6, 1e-6, method=method)
    simulate_spatial_exudyn(scene, 1e-6, 2e-6, 1e-6)


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
