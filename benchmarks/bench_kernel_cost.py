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

Seconds per call. The machine is shared: compare ratios of runs in one process, or interleaved processes (A, B, A,
B), not seconds across runs.
"""

from __future__ import annotations

import time

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
#: Loops of calls per figure (the fastest counts) and calls per loop.
REPEATS, CALLS = 7, 2000


@numba.njit(cache=True)
def _forces(packed, t, q, v, latched, workspace, complete, calls):
    for _ in range(calls):
        accelerations(packed, t, q, v, latched, workspace.acceleration, workspace, complete, UNCONSTRAINED)


@numba.njit(cache=True)
def _jacobian(packed, t, q, v, latched, workspace, carry, calls):
    for _ in range(calls):
        element_jacobian(packed.elements, t, q, v, latched, workspace.pair_out, carry.stiffness, carry.damping)


@numba.njit(cache=True)
def _constraint_rows(packed, q, v, carry, calls):
    for _ in range(calls):
        constraint_rows(packed.constraints, q, v, carry.constraint_gap, carry.constraint_rows,
                        carry.constraint_residual)


@numba.njit(cache=True)
def _assemble(packed, carry, calls):
    for _ in range(calls):
        assemble_constraints(carry.newton, packed.inverse_mass, carry.constraint_rows, packed.constraints.body_a,
                             packed.constraints.body_b)


@numba.njit(cache=True)
def _subtract(packed, carry, slope_q, slope_v, calls):
    for _ in range(calls):
        subtract_stiffness(carry.newton, packed.inverse_mass, carry.stiffness, carry.damping, slope_q, slope_v)


@numba.njit(cache=True)
def _factor(packed, carry, slope_q, slope_v, calls):
    """Assembly and factoring: the factor works in place, so each call starts from an assembled matrix."""
    for _ in range(calls):
        assemble_constraints(carry.newton, packed.inverse_mass, carry.constraint_rows, packed.constraints.body_a,
                             packed.constraints.body_b)
        subtract_stiffness(carry.newton, packed.inverse_mass, carry.stiffness, carry.damping, slope_q, slope_v)
        factor(carry.newton)


@numba.njit(cache=True)
def _form(packed, t, q, v, latched, slope_q, slope_v, workspace, carry, counters, calls):
    for _ in range(calls):
        form_newton_matrix(packed, True, t, q, v, latched, slope_q, slope_v, workspace, carry, counters)


@numba.njit(cache=True)
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


def main() -> dict:
    scene, driver, t = loaded_bearing()
    figures = measure(driver, t)
    loaded = int(np.sum(driver.workspace.pair_out[:, 0] < 0.0))
    report = {
        "unit": "seconds per call",
        "scene": {"scenario": "seed_hss_steady", "overrides": OVERRIDES, "loaded_at_s": t,
                  "coordinates": scene.coordinate_count, "pairs": len(scene.pairs), "pairs_in_contact": loaded,
                  "constraints": len(scene.constraints)},
        "repeats": REPEATS,
        "calls": CALLS,
        "figures": figures,
    }
    write("kernel_cost", report)
    return report


if __name__ == "__main__":
    main()
