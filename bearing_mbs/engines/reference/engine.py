"""Python side of the reference engine: packs the scene, runs the compiled driver in chunks (for the
progress meter), and turns its status into a :class:`~bearing_mbs.core.failures.Failure` and a message
(:mod:`bearing_mbs.engines.diagnosis`)."""

from __future__ import annotations

import time

import numpy as np

from bearing_mbs.contact.kernel import N_PAIR_OUTPUTS
from bearing_mbs.contact.state import initial_pair_state
from bearing_mbs.core.failures import Failure
from bearing_mbs.core.interrupt import StopRequest
from bearing_mbs.core.progress import ProgressMeter, notice_if_slow
from bearing_mbs.core.result import Result, Stats
from bearing_mbs.core.scene import Scene
from bearing_mbs.elements import has_analytic_jacobian, pack_scene
from bearing_mbs.engines.diagnosis import failure_message, output_grid
from bearing_mbs.engines.reference.block_elimination import BlockSystem, block_system
from bearing_mbs.engines.reference.bundles import (
    Controls,
    State,
    new_implicit_carry,
    new_output,
    new_runge_kutta_stages,
    new_verlet_carry,
    new_workspace,
    runge_kutta_tableau,
)
from bearing_mbs.engines.reference.central_difference import backward_difference_start
from bearing_mbs.engines.reference.codes import (
    CENTRAL_DIFFERENCE,
    EVALUATIONS,
    GENERALIZED_ALPHA,
    JACOBIANS,
    METHOD_CODES,
    NEWTON_ITERATIONS,
    REJECTED,
    RUNNING,
    STEPS,
)
from bearing_mbs.engines.reference.dynamics import accelerations
from bearing_mbs.engines.reference.integrators import integrate
from bearing_mbs.engines.reference.step_control import step_controller
from bearing_mbs.engines.reference.tableaus import TABLEAUS
from bearing_mbs.spec.solver import SolverSpec

#: What a user reads while the driver compiles (the first run after an install or a change of the kernels).
COMPILING = ("compiling the reference engine's driver (once after an install or a source change: about 30 s for the "
             "explicit methods, 1 min for generalized-alpha; later runs load it from the cache)")

#: Wall time [s] of one compiled chunk between two looks at the progress meter and the stop request.
_CHUNK_WALL_TIME = 0.2


def _free_counts(scene: Scene) -> list[int]:
    return [sum(body.free) for body in scene.bodies]


def constraint_system(scene: Scene) -> BlockSystem:
    """The system of the constraint accelerations and projections: bodies coupled by the constraints."""
    constraints = [(c.body_a, c.body_b) for c in scene.constraints]
    return block_system(len(scene.bodies), (), constraints, _free_counts(scene))


def newton_system(scene: Scene) -> BlockSystem:
    """Generalized-α's Newton system: bodies coupled by the pairs, the two-body force elements and the
    constraints; every body with every other where a force kind has no analytic Jacobian (the forward differences
    may couple what its items do not name)."""
    bodies = range(len(scene.bodies))
    couplings = [(a, b) for a in bodies for b in bodies]
    if has_analytic_jacobian(scene):
        couplings = [(item.body_a, item.body_b) for item in (*scene.pairs, *scene.forces) if hasattr(item, "body_a")]
    constraints = [(c.body_a, c.body_b) for c in scene.constraints]
    return block_system(len(scene.bodies), couplings, constraints, _free_counts(scene))


def simulate_reference(scene: Scene, solver: SolverSpec, end_time: float, progress: ProgressMeter | None = None,
                       spec: dict | None = None, stop: StopRequest | None = None,
                       step_advice: str | None = None) -> Result:
    settings = solver.reference
    progress = progress or ProgressMeter()
    stop = stop or StopRequest()
    packed = pack_scene(scene)
    n, pair_count, constraint_count = scene.coordinate_count, len(scene.pairs), len(scene.constraints)
    q, v = scene.initial_state()
    latched, events, bounds = initial_pair_state(packed.pairs, solver.penetration_limit)
    state = State(q, v, latched, events, np.zeros(2))

    times = output_grid(end_time, solver.output_interval)
    output = new_output(times, n, pair_count, N_PAIR_OUTPUTS, constraint_count)
    method = METHOD_CODES[settings.method]
    tableau = runge_kutta_tableau(TABLEAUS.get(settings.method))
    controls = Controls(float(settings.step), float(settings.contact_step or 0.0), float(settings.tolerance),
                        float(solver.speed_limit), bounds, float(settings.spectral_radius), has_analytic_jacobian(scene),
                        step_controller(settings.entry))
    # each kind of method gets its own carries, the other kind's are None (see integrate)
    if method == GENERALIZED_ALPHA:
        implicit, verlet, stages = new_implicit_carry(n, newton_system(scene)), None, None
    else:
        implicit, verlet, stages = None, new_verlet_carry(n), new_runge_kutta_stages(tableau.b.size, n)
    workspace = new_workspace(n, pair_count, N_PAIR_OUTPUTS, constraint_system(scene))

    def run(t, t_stop, h_adaptive, index):
        return integrate(method, settings.adaptive, packed, tableau, controls, state, verlet, stages, implicit,
                         workspace, output, t, t_stop, h_adaptive, index)

    with notice_if_slow(COMPILING):
        run(0.0, -1.0, settings.step, 1)  # compile (or load from cache) outside the timed region

    def record(t):
        """The state at t as an output row (initial state, or the state where a run stopped), and its
        acceleration."""
        acceleration, scratch = np.empty(n), new_workspace(n, pair_count, N_PAIR_OUTPUTS, constraint_system(scene))
        accelerations(packed, t, q, v, latched, acceleration, scratch, True, True)
        return t, q.copy(), v.copy(), scratch.pair_out, state.work.copy(), scratch.constraint_forces, acceleration

    series = [output.t, output.q, output.v, output.pairs, output.work, output.constraints]
    *initial, initial_acceleration = record(0.0)
    for buffer, value in zip(series, initial):
        buffer[0] = value
    if method == CENTRAL_DIFFERENCE:
        backward_difference_start(v, initial_acceleration, settings.step, times)

    progress.start(end_time, f"{scene.name} (reference {settings.method})")
    t, h_adaptive, index, status, culprit = 0.0, settings.step, 1, RUNNING, -1
    started = time.perf_counter()
    samples = 1  # output intervals per chunk, grown until a chunk takes about _CHUNK_WALL_TIME
    try:
        while index < times.size and not stop.is_set():
            chunk_started = time.perf_counter()
            t, h_adaptive, index, status, culprit = run(t, times[min(index + samples, times.size) - 1], h_adaptive,
                                                        index)
            progress.update(t)
            if status != RUNNING:
                break
            elapsed = time.perf_counter() - chunk_started
            samples = max(1, min(4 * samples, int(samples * _CHUNK_WALL_TIME / max(elapsed, 1e-6))))
        if status == RUNNING and index < times.size:
            status = int(Failure.INTERRUPTED)
    finally:
        wall = time.perf_counter() - started
        progress.close()

    counters = output.counters
    implicit_counts = {}
    if method == GENERALIZED_ALPHA:
        implicit_counts = {"newton_iterations": int(counters[NEWTON_ITERATIONS]),
                           "jacobian_evaluations": int(counters[JACOBIANS])}
    stats = Stats(steps=int(counters[STEPS]), rejected_steps=int(counters[REJECTED]),
                  force_evaluations=int(counters[EVALUATIONS]), wall_time_s=wall, **implicit_counts)
    failure = Failure(status)
    message = failure_message(failure, scene, solver, t, culprit, q, v, latched, h_adaptive, step_advice)
    if failure == Failure.INTERRUPTED:  # stopped at an output instant: keep the instants computed
        series = [a[:index] for a in series]
    elif failure != Failure.NONE:
        final = record(t)[:6]  # keep the state where the run stopped
        series = [np.concatenate([a[:index], np.asarray(b)[None]]) for a, b in zip(series, final)]
    out_t, out_q, out_v, out_pairs, out_work, out_constraints = series
    return Result(
        engine="reference", method=settings.method, step=settings.step, time=out_t, position=out_q,
        velocity=out_v, pair_output=out_pairs, constraint_forces=out_constraints, work=out_work, events=events,
        body_names=tuple(b.name for b in scene.bodies), pair_names=tuple(p.name for p in scene.pairs),
        stats=stats, failure=failure, message=message, spec=spec, topology=scene.topology,
    )
