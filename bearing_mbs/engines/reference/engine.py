"""Python side of the reference engine: packs the scene, runs the compiled driver in chunks (for the
progress meter and the stop request), and turns its status into a :class:`~bearing_mbs.core.failures.Failure` and
a message (:mod:`bearing_mbs.engines.diagnosis`). The run's frame, the output a stopped run keeps and the
:class:`~bearing_mbs.core.result.Result` are both engines' (:mod:`bearing_mbs.engines.run`)."""

from __future__ import annotations

import time
from typing import NamedTuple

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
from bearing_mbs.engines.run import Series, assemble_result, progress_meter, stop_request, timed_run
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
    """Run ``scene`` from 0 to ``end_time`` [s] with the reference engine's settings of ``solver``: compile the
    driver, record the initial state, step in chunks until the end, a failure or a stop request, and keep what
    was computed (see :func:`bearing_mbs.engines.simulate`)."""
    settings = solver.reference
    progress, stop = progress_meter(progress), stop_request(stop)
    packed = pack_scene(scene)
    q, v = scene.initial_state()
    latched, events, bounds = initial_pair_state(packed.pairs, solver.penetration_limit)
    state = State(q, v, latched, events, np.zeros(2))
    times = output_grid(end_time, solver.output_interval)
    driver = _driver(scene, solver, packed, state, bounds, times)

    with notice_if_slow(COMPILING):
        driver.advance(0.0, -1.0, settings.step, 1)  # compile (or load from cache) outside the timed region
    output = driver.output
    series = Series(output.t, output.q, output.v, output.pairs, output.work, output.constraints)
    *initial, initial_acceleration = _state_row(scene, packed, state, 0.0)
    for buffer, value in zip(series, initial):
        buffer[0] = value
    if driver.method == CENTRAL_DIFFERENCE:
        backward_difference_start(v, initial_acceleration, settings.step, times)

    with timed_run(progress, end_time, f"{scene.name} (reference {settings.method})") as clock:
        t, h_adaptive, index, status, culprit = _run_in_chunks(driver, times, settings.step, stop, progress)

    failure = Failure(status)
    message = failure_message(failure, scene, solver, t, culprit, q, v, latched, h_adaptive, step_advice)
    if failure == Failure.INTERRUPTED:  # stopped at an output instant: keep the instants computed
        series = series.kept(index)
    elif failure != Failure.NONE:  # keep the state where the run stopped
        series = series.kept(index, _state_row(scene, packed, state, t)[:6])
    stats = _stats(output.counters, driver.method, clock.wall_time_s)
    return assemble_result("reference", settings, scene, series, events, stats, failure, message, spec)


class _Driver(NamedTuple):
    """The compiled driver's arguments that stay the same over a run: the method (code, adaptive), the packed
    scene, the Runge–Kutta tableau, the controls, the state and the bundles it works in (each kind of method gets
    its own carries, the other kind's are None: see :func:`~.integrators.integrate`), and the output."""

    method: int
    adaptive: bool
    packed: object
    tableau: object
    controls: Controls
    state: State
    verlet: object
    stages: object
    implicit: object
    workspace: object
    output: object

    def advance(self, t: float, t_stop: float, h_adaptive: float, index: int):
        """Step from t towards t_stop [s] (-1: compile only), from output instant ``index`` on: see
        :func:`~.integrators.integrate` for what it returns."""
        return integrate(self.method, self.adaptive, self.packed, self.tableau, self.controls, self.state,
                         self.verlet, self.stages, self.implicit, self.workspace, self.output, t, t_stop, h_adaptive,
                         index)


def _driver(scene: Scene, solver: SolverSpec, packed, state: State, bounds, times: np.ndarray) -> _Driver:
    """The driver of ``solver.reference``'s method on ``scene``, its output buffers allocated for ``times``."""
    settings = solver.reference
    n, pair_count, constraint_count = scene.coordinate_count, len(scene.pairs), len(scene.constraints)
    output = new_output(times, n, pair_count, N_PAIR_OUTPUTS, constraint_count)
    method = METHOD_CODES[settings.method]
    tableau = runge_kutta_tableau(TABLEAUS.get(settings.method))
    controls = Controls(float(settings.step), float(settings.contact_step or 0.0), float(settings.tolerance),
                        float(solver.speed_limit), bounds, float(settings.spectral_radius), has_analytic_jacobian(scene),
                        step_controller(settings.entry))
    if method == GENERALIZED_ALPHA:
        implicit, verlet, stages = new_implicit_carry(n, newton_system(scene)), None, None
    else:
        implicit, verlet, stages = None, new_verlet_carry(n), new_runge_kutta_stages(tableau.b.size, n)
    workspace = new_workspace(n, pair_count, N_PAIR_OUTPUTS, constraint_system(scene))
    return _Driver(method, settings.adaptive, packed, tableau, controls, state, verlet, stages, implicit, workspace,
                   output)


def _state_row(scene: Scene, packed, state: State, t: float) -> tuple:
    """The state at t as an output row (the initial state, or the state where a run stopped), and its
    acceleration."""
    n = scene.coordinate_count
    acceleration, scratch = np.empty(n), new_workspace(n, len(scene.pairs), N_PAIR_OUTPUTS, constraint_system(scene))
    accelerations(packed, t, state.q, state.v, state.latched, acceleration, scratch, True, True)
    return (t, state.q.copy(), state.v.copy(), scratch.pair_out, state.work.copy(), scratch.constraint_forces,
            acceleration)


def _run_in_chunks(driver: _Driver, times: np.ndarray, step: float, stop: StopRequest, progress: ProgressMeter):
    """Run the driver from the first output instant to the last in chunks of about :data:`_CHUNK_WALL_TIME`,
    updating the meter and looking at the stop request between two; a request left unanswered ends the run as
    ``INTERRUPTED`` at the last instant reached. Returns (t, h_adaptive, index, status, culprit) as the driver
    does."""
    t, h_adaptive, index, status, culprit = 0.0, step, 1, RUNNING, -1
    samples = 1  # output intervals per chunk, grown until a chunk takes about _CHUNK_WALL_TIME
    while index < times.size and not stop.is_set():
        chunk_started = time.perf_counter()
        t, h_adaptive, index, status, culprit = driver.advance(t, times[min(index + samples, times.size) - 1],
                                                               h_adaptive, index)
        progress.update(t)
        if status != RUNNING:
            break
        elapsed = time.perf_counter() - chunk_started
        samples = max(1, min(4 * samples, int(samples * _CHUNK_WALL_TIME / max(elapsed, 1e-6))))
    if status == RUNNING and index < times.size:
        status = int(Failure.INTERRUPTED)
    return t, h_adaptive, index, status, culprit


def _stats(counters: np.ndarray, method: int, wall_time_s: float) -> Stats:
    """The run's cost from the driver's counters; Newton's counts for generalized-α only."""
    implicit_counts = {}
    if method == GENERALIZED_ALPHA:
        implicit_counts = {"newton_iterations": int(counters[NEWTON_ITERATIONS]),
                           "jacobian_evaluations": int(counters[JACOBIANS])}
    return Stats(steps=int(counters[STEPS]), rejected_steps=int(counters[REJECTED]),
                 force_evaluations=int(counters[EVALUATIONS]), wall_time_s=wall_time_s, **implicit_counts)
