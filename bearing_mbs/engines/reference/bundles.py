"""State bundles of the compiled reference engine: small NamedTuples of arrays that numba passes by value.

Every array is updated in place, so a bundle made once in Python carries its contents from one call of the
driver (one chunk of output instants) to the next.

* :class:`State` — what is integrated: positions q [m, m, rad per body], velocities v [m/s, m/s, rad/s],
  the pairs' latched approach speeds [m/s], the event log and the cumulative work [J];
* :class:`Controls` — the run's step, tolerance and guards;
* :class:`RungeKuttaTableau` — a Butcher tableau as arrays (:mod:`bearing_mbs.engines.reference.tableaus`);
* :class:`VerletCarry`, :class:`RungeKuttaStages`, :class:`ImplicitCarry` — each method's memory between steps;
* :class:`Workspace` — scratch arrays of one step;
* :class:`Output` — the output instants, the buffers of decimated output and the run counters.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

from bearing_mbs.engines.reference.block_elimination import BlockSystem
from bearing_mbs.engines.reference.codes import COUNTERS
from bearing_mbs.engines.reference.step_control import StepController
from bearing_mbs.engines.reference.tableaus import ButcherTableau


class State(NamedTuple):
    """The integrated state: q, v (3 per body), latched approach speeds [m/s] and event log of the pairs,
    cumulative (supplied, dissipated) work [J]."""

    q: np.ndarray
    v: np.ndarray
    latched: np.ndarray
    events: np.ndarray
    work: np.ndarray


class Controls(NamedTuple):
    """step [s]: the fixed step, or the first and largest adaptive step. contact_step [s]: the central
    difference's step while a pair penetrates (0: none). tolerance: relative and absolute tolerance of the
    adaptive step and the Newton tolerance of generalized-α. speed_limit [m/s] and penetration_bound (per pair) [m]:
    the run guards. spectral_radius: generalized-α's ρ∞. analytic_jacobian: every force element of the scene has
    an analytic Jacobian (else generalized-α differentiates numerically). step_controller: an adaptive method's
    (:mod:`~bearing_mbs.engines.reference.step_control`)."""

    step: float
    contact_step: float
    tolerance: float
    speed_limit: float
    penetration_bound: np.ndarray
    spectral_radius: float
    analytic_jacobian: bool
    step_controller: StepController


class RungeKuttaTableau(NamedTuple):
    """An explicit Runge–Kutta method as arrays: stage coefficients a (s × s), weights b, nodes c, embedded
    weights b_error (empty: fixed step) and the FSAL property (the order of the error estimate is the step-size
    controller's, :mod:`bearing_mbs.engines.reference.step_control`)."""

    a: np.ndarray
    b: np.ndarray
    c: np.ndarray
    b_error: np.ndarray
    fsal: bool


#: The tableau argument of the methods that have none.
NO_TABLEAU = RungeKuttaTableau(np.zeros((0, 0)), np.zeros(0), np.zeros(0), np.zeros(0), False)


def runge_kutta_tableau(tableau: ButcherTableau | None) -> RungeKuttaTableau:
    """The compiled form of ``tableau`` (:data:`NO_TABLEAU` for None)."""
    if tableau is None:
        return NO_TABLEAU
    return RungeKuttaTableau(tableau.a, tableau.b, tableau.c, tableau.b_error, tableau.fsal)


class VerletCarry(NamedTuple):
    """Velocity Verlet's memory: the last acceleration a(q, v) and (supplied, dissipated) power [W];
    ``ready[0] == 1`` when they belong to the current state."""

    acceleration: np.ndarray
    power: np.ndarray
    ready: np.ndarray


class RungeKuttaStages(NamedTuple):
    """The stages k_i of an explicit Runge–Kutta step, one row per stage: velocities (dq/dt), accelerations
    (dv/dt) and (supplied, dissipated) power [W]."""

    velocity: np.ndarray
    acceleration: np.ndarray
    power: np.ndarray


class ImplicitCarry(NamedTuple):
    """Generalized-α's memory and scratch: the current state's acceleration a_n and auxiliary acceleration ã_n,
    its (supplied, dissipated) power [W], ``ready[0] == 1`` when they belong to the current state,
    ``started[0] == 1`` once ã holds history; the Newton unknown and increment, the base forces of the forward
    differences, the step [s] the Newton matrix was formed for (inf: none yet), the factored Newton matrix
    (:class:`~bearing_mbs.engines.reference.block_elimination.BlockSystem`), the constraint rows it was formed
    with (C × 6), the constraints' multipliers [N] (Newton's iterate and the accepted state's), the constraint
    rows, gaps [m] and residual of the iterate, ∂F/∂q, ∂F/∂v (n × n each), and a copy of the accepted state's
    acceleration, auxiliary acceleration, power and multipliers, to take a step back that the projection refuses."""

    acceleration: np.ndarray
    auxiliary: np.ndarray
    power: np.ndarray
    ready: np.ndarray
    started: np.ndarray
    unknown: np.ndarray
    increment: np.ndarray
    base: np.ndarray
    matrix_step: np.ndarray
    newton: BlockSystem
    constraint_rows: np.ndarray
    multiplier: np.ndarray
    accepted_multiplier: np.ndarray
    current_rows: np.ndarray
    constraint_gap: np.ndarray
    constraint_residual: np.ndarray
    stiffness: np.ndarray
    damping: np.ndarray
    kept_acceleration: np.ndarray
    kept_auxiliary: np.ndarray
    kept_power: np.ndarray
    kept_multiplier: np.ndarray


class Workspace(NamedTuple):
    """Scratch of one step: the candidate state (q_new, v_new), a stage state, an acceleration, the
    generalized forces, the pairs' outputs, the constraint forces [N] and the system that solves for them
    (:class:`~bearing_mbs.engines.reference.block_elimination.BlockSystem` of the constraints)."""

    q_new: np.ndarray
    v_new: np.ndarray
    stage_q: np.ndarray
    stage_v: np.ndarray
    acceleration: np.ndarray
    forces: np.ndarray
    pair_out: np.ndarray
    constraint_forces: np.ndarray
    constraint_system: BlockSystem


class Output(NamedTuple):
    """Output instants ``times`` [s] and one row per instant of t, q, v, pair outputs, work and constraint
    forces; ``counters``: accepted steps, rejected steps, force evaluations, Newton iterations, Jacobians (slots
    in :mod:`bearing_mbs.engines.reference.codes`)."""

    times: np.ndarray
    t: np.ndarray
    q: np.ndarray
    v: np.ndarray
    pairs: np.ndarray
    work: np.ndarray
    constraints: np.ndarray
    counters: np.ndarray


def new_output(times: np.ndarray, coordinate_count: int, pair_count: int, pair_outputs: int,
               constraint_count: int) -> Output:
    """Output buffers for ``times``, filled with NaN (rows a stopped run never reached stay NaN)."""
    size = times.size
    return Output(times, np.full(size, np.nan), np.full((size, coordinate_count), np.nan),
                  np.full((size, coordinate_count), np.nan), np.full((size, pair_count, pair_outputs), np.nan),
                  np.full((size, 2), np.nan), np.full((size, constraint_count), np.nan),
                  np.zeros(COUNTERS, dtype=np.int64))


def new_workspace(coordinate_count: int, pair_count: int, pair_outputs: int, constraint_system: BlockSystem) \
        -> Workspace:
    n = coordinate_count
    return Workspace(np.empty(n), np.empty(n), np.empty(n), np.empty(n), np.empty(n), np.empty(n),
                     np.empty((pair_count, pair_outputs)), np.empty(constraint_system.owner.size), constraint_system)


def new_verlet_carry(coordinate_count: int) -> VerletCarry:
    return VerletCarry(np.zeros(coordinate_count), np.zeros(2), np.zeros(1, dtype=np.int64))


def new_implicit_carry(coordinate_count: int, newton: BlockSystem) -> ImplicitCarry:
    n = coordinate_count
    c = newton.owner.size
    return ImplicitCarry(np.zeros(n), np.zeros(n), np.zeros(2), np.zeros(1, dtype=np.int64),
                         np.zeros(1, dtype=np.int64), np.zeros(n), np.zeros(n), np.zeros(n), np.full(1, np.inf),
                         newton, np.zeros((c, 6)), np.zeros(c), np.zeros(c), np.zeros((c, 6)), np.zeros(c), np.zeros(c),
                         np.zeros((n, n)), np.zeros((n, n)), np.zeros(n), np.zeros(n), np.zeros(2), np.zeros(c))


def new_runge_kutta_stages(stage_count: int, coordinate_count: int) -> RungeKuttaStages:
    """Stage arrays for ``stage_count`` stages (at least one row, so every method has the same types)."""
    rows = max(stage_count, 1)
    return RungeKuttaStages(np.zeros((rows, coordinate_count)), np.zeros((rows, coordinate_count)),
                            np.zeros((rows, 2)))
