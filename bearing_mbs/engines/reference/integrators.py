r"""The driver of the compiled reference engine: from output instant to output instant with any method.

:func:`integrate` chooses each step (equal steps per output interval for the fixed-step methods, the adaptive
step for ``dopri5`` and generalized-α, all landing exactly on the output instants), takes it with the method's
functions (:mod:`~bearing_mbs.engines.reference.central_difference`,
:mod:`~bearing_mbs.engines.reference.velocity_verlet`, :mod:`~bearing_mbs.engines.reference.runge_kutta`,
:mod:`~bearing_mbs.engines.reference.generalized_alpha`), projects the candidate state onto the constraints,
applies the run guards (non-finite state, speed limit, penetration), accepts the step, updates the pairs' state once
per accepted step, and stores the decimated output.

How it is laid out for numba (what the first run compiles and what a step costs, docs/engines.md "Compilation"):

* the forces are compiled once per driver, in :func:`~bearing_mbs.engines.reference.dynamics.accelerations`, a
  function of its own that every method and the Python side call;
* a compiled function that is inlined (``inline="always"``) takes arrays and numbers, not bundles: inlining copies
  each argument, and a copied bundle that lives across a call to a compiled function costs a reference count of
  every array in it per call (about 1 µs for a bearing's hundred arrays, measured). So the explicit methods'
  evaluations are called here, with this function's own arguments, between the array updates the method modules
  inline; the Runge–Kutta stages and generalized-α's step are compiled functions that receive the bundles as
  arguments;
* a call passes a flag a compiled function branches on as a plain boolean (``bool(ready)``, or the numpy booleans
  of :mod:`~bearing_mbs.engines.reference.dynamics`): numba compiles a separate copy of a function for each literal
  ``True`` or ``False`` it receives.
"""

from __future__ import annotations

import math

import numba

from bearing_mbs.contact.state import advance_pair_state
from bearing_mbs.engines.reference.central_difference import (
    central_difference_positions,
    central_difference_step_size,
    central_difference_velocity,
)
from bearing_mbs.engines.reference.codes import (
    BLOWUP,
    CENTRAL_DIFFERENCE,
    EVALUATIONS,
    NONFINITE,
    PENETRATION,
    PROJECTION_FAILED,
    RUNGE_KUTTA,
    RUNNING,
    STEPS,
    VELOCITY_VERLET,
)
from bearing_mbs.engines.reference.constraints import length_scale, project_positions, project_velocities
from bearing_mbs.engines.reference.copies import copy_into
from bearing_mbs.engines.reference.dynamics import COMPLETE, CONSTRAINED, PARTIAL, accelerations
from bearing_mbs.engines.reference.generalized_alpha import generalized_alpha_step, keep_accepted, take_back
from bearing_mbs.engines.reference.runge_kutta import reuse_last_stage, runge_kutta_acceptance, runge_kutta_stages
from bearing_mbs.engines.reference.velocity_verlet import velocity_verlet_drift, velocity_verlet_kick

#: How far beyond the step an output instant may be and still be landed on in that step (not a sliver after it).
LANDING_SLACK = 1e-9

#: Largest constraint violation [× the constraints' length scale] a projection may leave.
PROJECTION_ACCEPTANCE = 1e-10
#: Step attempts a call of :func:`integrate` makes with a method that sets its own step (adaptive, generalized-α)
#: before it returns mid-interval, so that the engine's loop sees a stop request (Ctrl-C, SIGTERM) and reports
#: progress even where the step has collapsed: a Newton iteration that converges only at a tiny fraction of the
#: nominal step takes that tiny step, doubles back and fails again, and one output interval could take hours.
ATTEMPTS_PER_CALL = 2000


@numba.njit(cache=True, inline="always")
def check_state(q, v, speed_limit):
    """Run guards on a candidate state: (``NONFINITE``, first non-finite coordinate), else (``BLOWUP``, first
    coordinate of the first body whose centre moves faster than ``speed_limit`` [m/s]), else (``RUNNING``, −1)."""
    for i in range(q.size):
        if not (math.isfinite(q[i]) and math.isfinite(v[i])):
            return NONFINITE, i
    for body in range(q.size // 3):
        if v[3 * body] ** 2 + v[3 * body + 1] ** 2 > speed_limit**2:
            return BLOWUP, 3 * body
    return RUNNING, -1


@numba.njit(cache=True, inline="always")
def equal_steps(span, step):
    """How many equal steps of at most ``step`` cover ``span`` [s] (a span a rounding error over a whole number of
    steps takes that number)."""
    return math.ceil(span / step * (1.0 - 1e-9))


@numba.njit(cache=True, inline="always")
def record_output(packed, index, t, state, workspace, output):
    """Store the state at output instant ``index``, with the pairs' complete outputs and the constraint forces."""
    output.t[index] = t
    copy_into(output.q[index], state.q)
    copy_into(output.v[index], state.v)
    accelerations(packed, t, state.q, state.v, state.latched, workspace.acceleration, workspace, COMPLETE, CONSTRAINED)
    copy_into(output.pairs[index], workspace.pair_out)
    copy_into(output.work[index], state.work)
    copy_into(output.constraints[index], workspace.constraint_forces)


@numba.njit(cache=True)
def integrate(method, adaptive, packed, tableau, controls, state, verlet, stages, implicit, workspace, output, t,
              t_stop, h_adaptive, output_index):
    """Advance ``state`` from t to t_stop (an output instant) with the method of code ``method``, writing the
    output instants from ``output_index`` on; a method that sets its own step returns after
    :data:`ATTEMPTS_PER_CALL` step attempts, mid-interval, and resumes where it left off.

    ``adaptive``: the method controls its step. ``verlet`` and ``implicit`` carry velocity Verlet's and
    generalized-α's last acceleration and power between calls, so chunks and output instants do not change
    their results. ``implicit`` is None for the explicit methods, ``verlet`` and ``stages`` for generalized-α:
    numba prunes the branches of a None argument, so each kind of method compiles a driver without the other's
    code (compiling both into one would double the first run's compile time). Returns (t, h_adaptive, output_index,
    status, culprit): ``status`` is a
    :class:`~bearing_mbs.core.failures.Failure` code, ``culprit`` the offending pair (penetration) or coordinate
    (non-finite state, blow-up), −1 otherwise. On a stop, the state is the last good one.
    """
    q, v = state.q, state.v
    q_new, v_new = workspace.q_new, workspace.v_new
    # velocity Verlet's or generalized-α's carry, or the first Runge–Kutta stage, holds F at the current state
    # (passed on as bool(ready): a literal False would compile a second copy of the step functions)
    ready, stepping = False, adaptive  # the step is h_adaptive (generalized-α's also after a retry)
    if verlet is not None:
        ready = method == VELOCITY_VERLET and verlet.ready[0] == 1
    if implicit is not None:
        ready = implicit.ready[0] == 1
        stepping = True
    status, culprit = RUNNING, -1
    has_constraints = packed.constraints.kind.size > 0
    scale = length_scale(packed.constraints, q) if has_constraints else 1.0

    attempts, paused = 0, False
    while output_index < output.times.size and output.times[output_index] <= t_stop * (1 + 1e-15):
        t_target = output.times[output_index]
        steps_left, nominal = 0, 0.0  # fixed-step methods split each output interval into equal steps
        while t < t_target:
            if stepping:
                attempts += 1
                if attempts > ATTEMPTS_PER_CALL:  # return mid-interval; the next call resumes at t, h_adaptive
                    paused = True
                    break
                # land on the output instant, also when rounding left it a hair beyond one step
                landing = t_target - t <= h_adaptive * (1.0 + LANDING_SLACK)
                h = t_target - t if landing else h_adaptive
                if implicit is not None and not adaptive and not landing:
                    # fixed-step generalized-α: equal steps to the output instant; a step that does not divide the
                    # interval would alternate with a short landing step, and each change forms Newton's matrix
                    h = (t_target - t) / equal_steps(t_target - t, h_adaptive)
            else:
                wanted = controls.step
                if method == CENTRAL_DIFFERENCE:
                    wanted = central_difference_step_size(controls, state.latched)
                if steps_left == 0 or wanted != nominal:
                    nominal, t_base, taken = wanted, t, 0
                    steps_left = equal_steps(t_target - t, nominal)
                    h = (t_target - t) / steps_left
                landing = steps_left == 1

            if implicit is not None:
                if has_constraints:
                    keep_accepted(implicit)
                status, accepted, h_adaptive, work_supplied, work_dissipated = generalized_alpha_step(
                    packed, controls, adaptive, t, h, landing, h_adaptive, state, implicit, bool(ready), workspace,
                    output.counters)
                if status != RUNNING:
                    break
                ready = True  # a rejected step leaves the carry as it was; an accepted one holds the new state's
                if not accepted:
                    continue
            if verlet is not None:  # the explicit methods
                if method == CENTRAL_DIFFERENCE:
                    supplied, dissipated = accelerations(packed, t, q, v, state.latched, workspace.acceleration,
                                                         workspace, PARTIAL, CONSTRAINED)
                    output.counters[EVALUATIONS] += 1
                    central_difference_positions(q, v, workspace.acceleration, h, q_new)
                    work_supplied, work_dissipated = h * supplied, h * dissipated
                elif method == VELOCITY_VERLET:
                    a, power, predicted_v = verlet.acceleration, verlet.power, workspace.stage_v
                    if not ready:  # a(q, v) and its power
                        power[0], power[1] = accelerations(packed, t, q, v, state.latched, a, workspace, PARTIAL,
                                                           CONSTRAINED)
                        output.counters[EVALUATIONS] += 1
                    velocity_verlet_drift(q, v, a, h, q_new, v_new, predicted_v)
                    supplied, dissipated = accelerations(packed, t + h, q_new, predicted_v, state.latched, a,
                                                         workspace, PARTIAL, CONSTRAINED)
                    output.counters[EVALUATIONS] += 1
                    work_supplied, work_dissipated = velocity_verlet_kick(h, a, v_new, power, supplied, dissipated)
                    ready = True
                else:
                    runge_kutta_stages(packed, tableau, t, h, state, stages, bool(ready), workspace, output.counters)
                    status, accepted, h_adaptive, work_supplied, work_dissipated = runge_kutta_acceptance(
                        tableau, controls, t, h, landing, h_adaptive, q, v, q_new, v_new, stages, output.counters)
                    if status != RUNNING:
                        break
                    if not accepted:
                        ready = True  # the first stage depends on the state only, not on h
                        continue
                    ready = tableau.fsal  # after acceptance, only an FSAL last stage is F at the new state

            if has_constraints:
                violation = project_positions(packed.constraints, packed.inverse_mass, q_new, scale,
                                              workspace.constraint_system)
                if not violation <= PROJECTION_ACCEPTANCE * scale:
                    if implicit is not None:  # too long a step for the projection: retried shorter, as Newton's failure
                        shorter = take_back(implicit, t, h, output.counters)
                        if shorter > 0.0:
                            h_adaptive, ready = shorter, True
                            continue
                    status = PROJECTION_FAILED
                    break
                if method != CENTRAL_DIFFERENCE:  # its velocity is the backward difference below
                    project_velocities(packed.constraints, packed.inverse_mass, q_new, v_new,
                                       workspace.constraint_system)
                # the carry's F is at the state before projection: explicit methods evaluate again; generalized-α
                # keeps its converged acceleration (the projection moves q by the step's drift, far below the
                # Newton tolerance's effect on it)
                ready = implicit is not None and ready
            if method == CENTRAL_DIFFERENCE:
                central_difference_velocity(q, q_new, h, v_new)

            status, culprit = check_state(q_new, v_new, controls.speed_limit)
            if status != RUNNING:
                break
            copy_into(q, q_new)
            copy_into(v, v_new)
            state.work[0] += work_supplied
            state.work[1] += work_dissipated
            if stepping:
                t = t_target if landing else t + h
            else:
                steps_left -= 1
                taken += 1
                t = t_target if landing else t_base + taken * h
            output.counters[STEPS] += 1
            changed, worst = advance_pair_state(packed.pairs, q, v, t, state.latched, state.events,
                                                controls.penetration_bound)
            if changed:
                ready = False
            if worst >= 0:
                status, culprit = PENETRATION, worst
                break
            if stages is not None:
                if method == RUNGE_KUTTA and ready:
                    reuse_last_stage(stages)

        if status != RUNNING or paused:
            break
        record_output(packed, output_index, t, state, workspace, output)
        output_index += 1
    if verlet is not None:
        verlet.ready[0] = 1 if (method == VELOCITY_VERLET and ready) else 0
    if implicit is not None:
        implicit.ready[0] = 1 if ready else 0
    return t, h_adaptive, output_index, status, culprit
