"""Python driver of the reference engine: packs the scene, runs the compiled loop in chunks (for the
progress meter), and turns status codes into messages that name the time, the pair and a likely fix."""

from __future__ import annotations

import time

import numpy as np

from bearing_mbs.contact.kernel import N_PAIR_OUTPUTS
from bearing_mbs.contact.state import initial_pair_state, penetration_bounds
from bearing_mbs.core.progress import ProgressMeter
from bearing_mbs.core.failures import Failure
from bearing_mbs.core.result import Result, Stats
from bearing_mbs.core.scene import Scene
from bearing_mbs.spec.solver import SolverSpec
from bearing_mbs.engines.reference import integrators as ig
from bearing_mbs.engines.reference.tableaus import TABLEAUS
from bearing_mbs.elements import pack_scene, scene_forces

_CHUNKS = 100
_NO_TABLEAU = (np.zeros((0, 0)), np.zeros(0), np.zeros(0), np.zeros(0), 0, False)
COORDINATE_NAMES = ("x", "y", "theta")


def output_grid(end_time: float, interval: float) -> np.ndarray:
    """Output instants 0, Δ, 2Δ, …, ending exactly at end_time."""
    count = int(np.floor(end_time / interval * (1 + 1e-12)))
    grid = np.arange(count + 1) * interval
    return grid if np.isclose(grid[-1], end_time, rtol=1e-12, atol=0) else np.append(grid, end_time)


def simulate_reference(scene: Scene, solver: SolverSpec, end_time: float, progress: ProgressMeter | None = None,
                       spec: dict | None = None) -> Result:
    settings = solver.reference
    progress = progress or ProgressMeter()
    packed = pack_scene(scene)
    n, pair_count = scene.coordinate_count, len(scene.pairs)
    q, v = scene.initial_state()
    latched, events, bounds = initial_pair_state(packed.pairs, solver.penetration_limit)

    times = output_grid(end_time, solver.output_interval)
    constraint_count = len(scene.constraints)
    out_t = np.full(times.size, np.nan)
    out_q, out_v = np.full((times.size, n), np.nan), np.full((times.size, n), np.nan)
    out_pairs = np.full((times.size, pair_count, N_PAIR_OUTPUTS), np.nan)
    out_work = np.full((times.size, 2), np.nan)
    out_constraints = np.full((times.size, constraint_count), np.nan)
    work = np.zeros(2)
    counters = np.zeros(3, dtype=np.int64)
    verlet_acc, verlet_power, verlet_ready = np.zeros(n), np.zeros(2), np.zeros(1, dtype=np.int64)

    method = ig.METHOD_CODES[settings.method]
    tableau = TABLEAUS.get(settings.method)
    tab = (tableau.a, tableau.b, tableau.c, tableau.b_error, tableau.error_order, tableau.fsal) if tableau else _NO_TABLEAU
    contact_step = settings.contact_step or 0.0

    def run(t, t_stop, h_adaptive, index):
        return ig.integrate(method, packed, *tab, q, v, latched, events, work, bounds, solver.speed_limit, t, t_stop,
                            settings.step, contact_step, settings.tolerance, h_adaptive, times, index, out_t, out_q,
                            out_v, out_pairs, out_work, out_constraints, counters, verlet_acc, verlet_power,
                            verlet_ready)

    run(0.0, -1.0, settings.step, 1)  # compile (or load from cache) outside the timed region

    def record(index, t):
        """The state at t as output row ``index`` (initial state, or the state where a run stopped)."""
        acc, forces = np.empty(n), np.empty(n)
        pair_out, constraint_forces = np.empty((pair_count, N_PAIR_OUTPUTS)), np.empty(constraint_count)
        ig.accelerations(packed, t, q, v, latched, acc, forces, pair_out, constraint_forces, True)
        return t, q.copy(), v.copy(), pair_out, work.copy(), constraint_forces, acc

    out_t[0], out_q[0], out_v[0], out_pairs[0], out_work[0], out_constraints[0], initial_acceleration = record(0, 0.0)
    if method == ig.CENTRAL_DIFFERENCE:
        _backward_difference_start(v, initial_acceleration, settings, times)

    progress.start(end_time, f"{scene.name} (reference {settings.method})")
    t, h_adaptive, index, status, culprit = 0.0, settings.step, 1, ig.RUNNING, -1
    started = time.perf_counter()
    try:
        for chunk_end in np.linspace(0, times.size - 1, min(_CHUNKS, times.size - 1) + 1)[1:].round().astype(int):
            t, h_adaptive, index, status, culprit = run(t, times[chunk_end], h_adaptive, index)
            progress.update(t)
            if status != ig.RUNNING:
                break
    finally:
        wall = time.perf_counter() - started
        progress.close()

    stats = Stats(steps=int(counters[ig.STEPS]), rejected_steps=int(counters[ig.REJECTED]),
                  force_evaluations=int(counters[ig.EVALUATIONS]), wall_time_s=wall)
    series = [out_t, out_q, out_v, out_pairs, out_work, out_constraints]
    message = ""
    if status != ig.RUNNING:
        message = _failure_message(scene, solver, status, culprit, t, q, v, latched, h_adaptive)
        final = record(index, t)[:6]  # keep the state where the run stopped
        series = [np.concatenate([a[:index], np.asarray(b)[None]]) for a, b in zip(series, final)]
    out_t, out_q, out_v, out_pairs, out_work, out_constraints = series
    return Result(
        engine="reference", method=settings.method, step=settings.step, time=out_t, position=out_q,
        velocity=out_v, pair_output=out_pairs, constraint_forces=out_constraints, work=out_work, events=events,
        body_names=tuple(b.name for b in scene.bodies), pair_names=tuple(p.name for p in scene.pairs),
        stats=stats, failure=Failure(status), message=message, spec=spec, topology=scene.topology,
    )


def _backward_difference_start(v, acceleration, settings, times):
    """Second-order start of the central difference: the backward velocity v₀ − h₀a₀/2 (Taylor), which
    makes the scheme exact for constant acceleration. The document's start (v₀ itself) costs an O(h)
    error even in free fall."""
    first = times[1] - times[0]
    h0 = first / np.ceil(first / settings.step * (1 - 1e-9))
    v -= 0.5 * h0 * acceleration


def _failure_message(scene, solver, status, culprit, t, q, v, latched, h) -> str:
    step = solver.reference.step
    if status in (ig.NONFINITE, ig.BLOWUP):
        return diverged_message(scene, solver, t, culprit, q, v, latched, step, blown_up=status == ig.BLOWUP)
    if status == ig.PENETRATION:
        return penetration_message(scene, solver, t, culprit, q, v, step)
    if status == ig.STEP_UNDERFLOW:
        return (f"t = {t:.6g} s: the adaptive step fell to {h:.3g} s. Likely fix: loosen the tolerance "
                f"(now {solver.reference.tolerance:g}) or raise the friction regularisation speed.")
    return (f"t = {t:.6g} s: the constraint projection did not converge. Likely fix: reduce the step "
            f"(now {step:g} s).")


def diverged_message(scene, solver, t, coordinate, q, v, latched, step, blown_up) -> str:
    """A run diverged: name the body, the most engaged pair (smallest gap) in the last good state, a fix."""
    body = scene.bodies[coordinate // 3].name
    what = (f"moves faster than speed_limit = {solver.speed_limit:g} m/s" if blown_up
            else f"({COORDINATE_NAMES[coordinate % 3]}) became non-finite")
    culprit = ""
    if scene.pairs:
        pair_out = np.empty((len(scene.pairs), N_PAIR_OUTPUTS))
        scene_forces(pack_scene(scene), t, q, v, latched, np.empty_like(q), pair_out)
        k = int(np.argmin(pair_out[:, 0]))
        culprit = (f" The most engaged pair in the last good state was {scene.pairs[k].name!r} "
                   f"(gap {pair_out[k, 0]:.3g} m, normal force {pair_out[k, 3]:.3g} N).")
    return (f"t = {t:.6g} s: body {body!r} {what}; the run diverged.{culprit} Likely fix: reduce the step "
            f"(now {step:g} s) below the explicit stability limit, or use Exudyn's generalized-alpha solver.")


def penetration_message(scene, solver, t, k, q, v, step) -> str:
    pair = scene.pairs[k]
    depth = -_gap_of(scene, k, q, v)
    bound = penetration_bounds(pack_scene(scene).pairs, solver.penetration_limit)[k]
    return (f"t = {t:.6g} s: pair {pair.name!r} penetrates {depth:.3g} m, beyond the guard of {bound:.3g} m "
            f"(penetration_limit = {solver.penetration_limit:g} of the radius). Likely fix: reduce the step "
            f"(now {step:g} s) so the contact is resolved, or raise the stiffness (K = {pair.law.stiffness:.3g}).")


def _gap_of(scene, k, q, v):
    from bearing_mbs.contact import twin

    return float(twin.pair_geometry(pack_scene(scene).pairs, q, v)[0][k])
