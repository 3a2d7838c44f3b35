"""Cost of one force evaluation and of one Newton matrix of the lubricated seed bearing, on the reference engine.

Scene: ``scenarios/seed_hss_steady.toml``, variant lubricated (EHL traction and rolling resistance with shear
heating on the raceways, churning drags, the cage on its land film, the constraint cage), at the document's zero
clearance (``bearing.diametral_clearance=0``), run 10 ms with the reference engine's generalized-α at 2e-5 s so
that the contacts are loaded; every figure is measured at the state reached there.

Figures (best of :data:`REPEATS` loops of many calls inside one compiled function, so no Python call is counted):

* ``forces_partial`` / ``forces_complete``: :func:`~bearing_mbs.engines.reference.dynamics.accelerations` as a
  Newton iteration / a Jacobian formation calls it (forces of every element, M⁻¹F + g, no constraint solve);
* ``element_jacobian``: the analytic ∂F/∂q, ∂F/∂v of every element (after a complete evaluation);
* ``constraint_rows``, ``assemble_constraints``, ``subtract_stiffness``, ``factor``: the block elimination's parts
  of the Newton matrix;
* ``form_newton_matrix``: all of it, as generalized-α forms it (the complete evaluation included);
* ``newton_iteration``: one iteration's evaluation, residual and block solve.

Seconds per call. The machine is shared: compare ratios of interleaved runs, not seconds across runs. With
``--baseline DIR`` (a checkout of the package to compare with, e.g. ``git worktree add /tmp/base <commit>``) the
figures are measured in :data:`ROUNDS` rounds, each running this script's measurement once on DIR's package and once
on this one, in that order, in processes of their own (numba compiles each package's code apart); each figure is
the best over the rounds, and ``ratio`` is baseline over this checkout.
"""

from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
import time
from pathlib import Path

import numba
import numpy as np

from bearing_mbs.contact.state import initial_pair_state
from bearing_mbs.elements import element_jacobian, pack_scene
from bearing_mbs.engines.diagnosis import output_grid
from bearing_mbs.engines.reference.block_elimination import assemble_constraints, factor, subtract_stiffness
from bearing_mbs.engines.reference.bundles import State
from bearing_mbs.engines.reference.codes import COUNTERS, RUNNING
from bearing_mbs.engines.reference.constraints import constraint_rows
from bearing_mbs.engines.reference.dynamics import COMPLETE, PARTIAL, UNCONSTRAINED, accelerations
from bearing_mbs.engines.reference.engine import _driver
from bearing_mbs.engines.reference.generalized_alpha import (
    coefficients,
    form_newton_matrix,
    newton_increment,
    newton_residual,
)
from bearing_mbs.models import build_scene, load_spec

from common import SCENARIOS, write

#: The loaded state: the scene's time [s] when the figures are measured, and the step [s] that takes it there.
LOADED_AT, STEP = 0.01, 2e-5
OVERRIDES = ["scenario.variant=lubricated", "bearing.diametral_clearance=0", "solver.engine=reference",
             "solver.reference.method=generalized_alpha", f"solver.reference.step={STEP}",
             "solver.reference.tolerance=1e-6", f"scenario.end_time={LOADED_AT}", "solver.output_interval=1e-3"]
#: Loops of calls per figure (the fastest counts) and calls per loop; rounds of baseline and this checkout.
REPEATS, CALLS, ROUNDS = 7, 2000, 3
#: This checkout's root (the package's parent).
ROOT = Path(__file__).resolve().parents[1]


# The timing loops are compiled in each run, not cached: a cached caller keeps the package functions it was compiled
# with (numba checks its own file only), and would time the code before an edit.
@numba.njit
def _forces(packed, t, q, v, latched, workspace, complete, calls):
    for _ in range(calls):
        accelerations(packed, t, q, v, latched, workspace.acceleration, workspace, complete, UNCONSTRAINED)


@numba.njit
def _jacobian(packed, t, q, v, latched, workspace, carry, calls):
    for _ in range(calls):
        element_jacobian(packed.elements, t, q, v, latched, workspace.pair_out, carry.stiffness, carry.damping)


@numba.njit
def _constraint_rows(packed, q, v, carry, calls):
    for _ in range(calls):
        constraint_rows(packed.constraints, q, v, carry.constraint_gap, carry.constraint_rows,
                        carry.constraint_residual)


@numba.njit
def _assemble(packed, carry, calls):
    for _ in range(calls):
        assemble_constraints(carry.newton, packed.inverse_mass, carry.constraint_rows, packed.constraints.body_a,
                             packed.constraints.body_b)


@numba.njit
def _subtract(packed, carry, slope_q, slope_v, calls):
    for _ in range(calls):
        subtract_stiffness(carry.newton, packed.inverse_mass, carry.stiffness, carry.damping, slope_q, slope_v)


@numba.njit
def _factor(packed, carry, slope_q, slope_v, calls):
    """Assembly and factoring: the factor works in place, so each call starts from an assembled matrix."""
    for _ in range(calls):
        assemble_constraints(carry.newton, packed.inverse_mass, carry.constraint_rows, packed.constraints.body_a,
                             packed.constraints.body_b)
        subtract_stiffness(carry.newton, packed.inverse_mass, carry.stiffness, carry.damping, slope_q, slope_v)
        factor(carry.newton)


@numba.njit
def _form(packed, t, q, v, latched, slope_q, slope_v, workspace, carry, counters, calls):
    for _ in range(calls):
        form_newton_matrix(packed, True, t, q, v, latched, slope_q, slope_v, workspace, carry, counters)


@numba.njit
def _iteration(packed, t, q, v, latched, workspace, carry, calls):
    for _ in range(calls):
        accelerations(packed, t, q, v, latched, workspace.acceleration, workspace, PARTIAL, UNCONSTRAINED)
        newton_residual(packed, carry, workspace.acceleration, q, v)
        newton_increment(packed, carry, workspace.acceleration, carry.constraint_residual)


def loaded_bearing():
    """(scene, driver) with the driver's state at :data:`LOADED_AT` (the engine's own driver, run there)."""
    spec = load_spec(SCENARIOS / "seed_hss_steady.toml", OVERRIDES)
    scene = build_scene(spec)
    packed = pack_scene(scene)
    q, v = scene.initial_state()
    latched, events, bounds = initial_pair_state(packed.pairs, spec.solver.penetration_limit)
    state = State(q, v, latched, events, np.zeros(2))
    times = output_grid(LOADED_AT, spec.solver.output_interval)
    driver = _driver(scene, spec.solver, packed, state, bounds, times)
    t, h, index = 0.0, STEP, 1
    while index < times.size:
        t, h, index, status, _ = driver.advance(t, times[-1], h, index)
        if status != RUNNING:
            raise RuntimeError(f"the run to the loaded state stopped with status {status} at t = {t}")
    return scene, driver, t


def timed(function, *arguments) -> float:
    """Best of :data:`REPEATS` loops of ``function(*arguments, CALLS)``, per call [s]."""
    function(*arguments, 1)  # compile or load
    best = np.inf
    for _ in range(REPEATS):
        start = time.perf_counter()
        function(*arguments, CALLS)
        best = min(best, time.perf_counter() - start)
    return best / CALLS


def measure(driver, t) -> dict:
    """Seconds per call of each figure (module docstring) at the driver's state."""
    packed, state, workspace, carry = driver.packed, driver.state, driver.workspace, driver.implicit
    q, v, latched = state.q.copy(), state.v.copy(), state.latched.copy()
    alpha_m, alpha_f, gamma, beta = coefficients(driver.controls.spectral_radius)
    share = (1.0 - alpha_f) / (1.0 - alpha_m)
    slope_q, slope_v = STEP * STEP * beta * share, STEP * gamma * share
    counters = np.zeros(COUNTERS, dtype=np.int64)
    figures = {
        "forces_partial": timed(_forces, packed, t, q, v, latched, workspace, PARTIAL),
        "forces_complete": timed(_forces, packed, t, q, v, latched, workspace, COMPLETE),
    }
    figures["element_jacobian"] = timed(_jacobian, packed, t, q, v, latched, workspace, carry)
    figures["constraint_rows"] = timed(_constraint_rows, packed, q, v, carry)
    figures["assemble_constraints"] = timed(_assemble, packed, carry)
    figures["subtract_stiffness"] = timed(_subtract, packed, carry, slope_q, slope_v)
    figures["factor"] = timed(_factor, packed, carry, slope_q, slope_v) - figures["assemble_constraints"] \
        - figures["subtract_stiffness"]
    figures["form_newton_matrix"] = timed(_form, packed, t, q, v, latched, slope_q, slope_v, workspace, carry,
                                          counters)
    figures["newton_iteration"] = timed(_iteration, packed, t, q, v, latched, workspace, carry)
    return figures


def figures_here() -> dict:
    """The scene's description and the figures of the package this process imports."""
    scene, driver, t = loaded_bearing()
    figures = measure(driver, t)
    loaded = int(np.sum(driver.workspace.pair_out[:, 0] < 0.0))
    return {"scene": {"scenario": "seed_hss_steady", "overrides": OVERRIDES, "loaded_at_s": t,
                      "coordinates": scene.coordinate_count, "pairs": len(scene.pairs), "pairs_in_contact": loaded,
                      "constraints": len(scene.constraints)},
            "figures": figures}


def figures_of(root: Path) -> dict:
    """:func:`figures_here` in a process of its own on the package under ``root``."""
    environment = {**os.environ, "PYTHONPATH": str(root)}
    done = subprocess.run([sys.executable, __file__, "--figures-only"], env=environment, check=True,
                          capture_output=True, text=True)
    return json.loads(done.stdout.splitlines()[-1])


def main(argv: list[str] | None = None) -> dict:
    """Measure (``argv``: the command line's arguments; none from ``make bench``) and write the JSON."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--baseline", type=Path, help="a checkout of the package to compare with")
    parser.add_argument("--figures-only", action="store_true", help=argparse.SUPPRESS)
    arguments = parser.parse_args([] if argv is None else argv)
    if arguments.figures_only:
        print(json.dumps(figures_here()))
        return {}
    report = {"unit": "seconds per call", "repeats": REPEATS, "calls": CALLS}
    if arguments.baseline is None:
        report.update(figures_here())
    else:
        runs = {"baseline": [], "this": []}
        for _ in range(ROUNDS):
            runs["baseline"].append(figures_of(arguments.baseline.resolve()))
            runs["this"].append(figures_of(ROOT))
        best = {name: {figure: min(run["figures"][figure] for run in found) for figure in found[0]["figures"]}
                for name, found in runs.items()}
        report.update(scene=runs["this"][0]["scene"], rounds=ROUNDS, figures=best["this"],
                      baseline={"checkout": str(arguments.baseline), "figures": best["baseline"]},
                      ratio={figure: best["baseline"][figure] / best["this"][figure] for figure in best["this"]})
    write("kernel_cost", report)
    return report


if __name__ == "__main__":
    main(sys.argv[1:])
