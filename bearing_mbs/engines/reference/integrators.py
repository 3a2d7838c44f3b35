r"""The reference engine's compiled time-stepping loop and its four methods.

State: positions q and velocities v (3 per body), the pairs' latched approach speeds, and the event log.
Each method is one stepping function; :func:`integrate` drives any of them from output time to output
time, updates per-pair state once per accepted step, applies the constraint projection and the run guards,
and stores decimated output.

Methods
-------
``central_difference``
    The primary document's variable-step scheme (eq. 58 of the digest),
    :math:`s_{i+1} = s_i + (s_i - s_{i-1})\,h_{i+1}/h_i + f(s_i, \dot s_i)\,h_{i+1}^2` with the backward
    velocity :math:`\dot s_i = (s_i - s_{i-1})/h_i` (eq. 56), written with :math:`v_i = \dot s_i` so that
    :math:`s_{i+1} = s_i + v_i h_{i+1} + f h_{i+1}^2`. Second order for velocity-independent forces, first
    order once damping or friction make f depend on the lagged velocity. The step is ``step``, or
    ``contact_step`` while any pair penetrates. Reported velocities are the backward differences.
``velocity_verlet``
    Kick–drift–kick with a velocity predictor for velocity-dependent forces,
    :math:`a_{n+1} = f(q_{n+1}, v_n + h a_n)`: second order, one force evaluation per step.
``rk4``, ``dopri5``
    Explicit Runge–Kutta on (q, v) with the tableaus of :mod:`.tableaus`; ``dopri5`` adapts its step with
    the embedded 4th-order estimate (RMS norm, relative and absolute tolerance both ``tolerance``).

Energy audit: the work supplied by loads and drives and the work dissipated by the contacts are integrated
with each method's own quadrature (the RK weights over the stages, the trapezoid rule for velocity Verlet,
the rectangle rule for the central difference), so the audit is as accurate as the motion.
"""

from __future__ import annotations

import math

import numba
import numpy as np

from bearing_mbs.elements import scene_forces
from bearing_mbs.contact.state import advance_pair_state
from bearing_mbs.engines.reference.constraints import (
    add_constraint_accelerations,
    length_scale,
    project_positions,
    project_velocities,
)

CENTRAL_DIFFERENCE, VELOCITY_VERLET, RUNGE_KUTTA = 0, 1, 2
METHOD_CODES = {"central_difference": CENTRAL_DIFFERENCE, "velocity_verlet": VELOCITY_VERLET,
                "rk4": RUNGE_KUTTA, "dopri5": RUNGE_KUTTA}

# Status codes returned by integrate().
RUNNING, NONFINITE, PENETRATION, STEP_UNDERFLOW, PROJECTION_FAILED, BLOWUP = 0, 1, 2, 3, 4, 5
# Counter slots.
STEPS, REJECTED, EVALUATIONS = 0, 1, 2


@numba.njit(cache=True, inline="always")
def accelerations(packed, t, q, v, latched, a, forces, pair_out, constraint_forces, complete=False):
    """a = M⁻¹ f(t, q, v) + gravity, made consistent with the constraints (their forces [N] into
    ``constraint_forces``). Returns (supplied, dissipated) power [W]. ``complete``: also the velocity-level
    outputs of pairs apart (output instants only; see :func:`bearing_mbs.elements.scene_forces`)."""
    supplied, dissipated = scene_forces(packed, t, q, v, latched, forces, pair_out, complete)
    for i in range(q.size):
        a[i] = packed.inverse_mass[i] * forces[i] + packed.gravity[i]
    if packed.constraints.kind.size > 0:
        constraint_forces[:] = add_constraint_accelerations(packed.constraints, packed.inverse_mass, q, v, a)
    return supplied, dissipated


@numba.njit(cache=True)
def _rk_step(packed, tab_a, tab_b, tab_c, t, h, q, v, latched, kq, kv, kp, first_ready,
             q_new, v_new, stage_q, stage_v, forces, pair_out, constraint_forces, counters):
    """One explicit RK step on (q, v): stages into kq (velocities), kv (accelerations) and kp (powers),
    result into q_new, v_new. With ``first_ready`` the first stage f(t, q, v) is already in place."""
    stages, n = tab_b.size, q.size
    for i in range(stages):
        if i == 0 and first_ready:
            continue
        for m in range(n):  # explicit loops: array expressions would allocate temporaries every stage
            position, velocity = q[m], v[m]
            for j in range(i):
                position += h * tab_a[i, j] * kq[j, m]
                velocity += h * tab_a[i, j] * kv[j, m]
            stage_q[m], stage_v[m] = position, velocity
            kq[i, m] = velocity
        kp[i, 0], kp[i, 1] = accelerations(packed, t + tab_c[i] * h, stage_q, stage_v, latched, kv[i], forces,
                                           pair_out, constraint_forces)
        counters[EVALUATIONS] += 1
    for m in range(n):
        position, velocity = q[m], v[m]
        for i in range(stages):
            position += h * tab_b[i] * kq[i, m]
            velocity += h * tab_b[i] * kv[i, m]
        q_new[m], v_new[m] = position, velocity


@numba.njit(cache=True)
def _error_norm(tab_b, tab_e, h, q, v, q_new, v_new, kq, kv, tolerance):
    """RMS of the embedded error estimate over (q, v), scaled by tolerance·(1 + max|y|)."""
    n = q.size
    total = 0.0
    for k in range(n):
        eq = 0.0
        ev = 0.0
        for i in range(tab_b.size):
            eq += (tab_b[i] - tab_e[i]) * kq[i, k]
            ev += (tab_b[i] - tab_e[i]) * kv[i, k]
        sq = tolerance * (1.0 + max(abs(q[k]), abs(q_new[k])))
        sv = tolerance * (1.0 + max(abs(v[k]), abs(v_new[k])))
        total += (h * eq / sq) ** 2 + (h * ev / sv) ** 2
    return math.sqrt(total / (2 * n))


@numba.njit(cache=True)
def integrate(method, packed, tab_a, tab_b, tab_c, tab_e, error_order, fsal,
              q, v, latched, events, work, penetration_bound, speed_limit, t, t_stop, step, contact_step,
              tolerance, h_adaptive, output_times, output_index, out_t, out_q, out_v, out_pairs, out_work,
              out_constraints, counters, acc, power, verlet_ready):
    """Advance from t to t_stop (an output time), writing outputs on the way.

    ``work`` holds the cumulative (supplied, dissipated) work [J]. ``acc``, ``power`` and ``verlet_ready``
    carry velocity Verlet's last acceleration and power between calls, so chunks and output instants do not
    change its result. Returns (t, h_adaptive, output_index, status, culprit): ``culprit`` is the offending
    pair (penetration) or coordinate (non-finite state, blow-up), −1 otherwise. On a stop, q and v hold the
    last good state.
    """
    n = q.size
    adaptive = tab_e.size > 0
    stages = tab_b.size
    kq = np.zeros((max(stages, 1), n))
    kv = np.zeros((max(stages, 1), n))
    kp = np.zeros((max(stages, 1), 2))
    q_new, v_new = np.empty(n), np.empty(n)
    stage_q, stage_v = np.empty(n), np.empty(n)
    forces = np.empty(n)
    pair_out = np.empty(out_pairs.shape[1:])
    constraint_forces = np.empty(out_constraints.shape[1])
    output_acc = np.empty(n)
    # kq[0], kv[0], kp[0] (RK) or acc, power (velocity Verlet) hold f at the current state
    first_ready = method == VELOCITY_VERLET and verlet_ready[0] == 1
    status, culprit = RUNNING, -1
    has_constraints = packed.constraints.kind.size > 0
    scale = length_scale(packed.constraints, q) if has_constraints else 1.0

    while output_index < output_times.size and output_times[output_index] <= t_stop * (1 + 1e-15):
        t_target = output_times[output_index]
        steps_left, nominal = 0, 0.0  # fixed-step methods split each output interval into equal steps
        while t < t_target:
            if adaptive:
                h = min(h_adaptive, t_target - t)
                landing = h == t_target - t
            else:
                wanted = step
                if method == CENTRAL_DIFFERENCE and contact_step > 0.0 and np.any(latched > 0.0):
                    wanted = contact_step
                if steps_left == 0 or wanted != nominal:
                    nominal, t_base, taken = wanted, t, 0
                    steps_left = math.ceil((t_target - t) / nominal * (1.0 - 1e-9))
                    h = (t_target - t) / steps_left
                landing = steps_left == 1

            if method == CENTRAL_DIFFERENCE:
                supplied, dissipated = accelerations(packed, t, q, v, latched, acc, forces, pair_out,
                                                     constraint_forces)
                counters[EVALUATIONS] += 1
                for i in range(n):
                    q_new[i] = q[i] + h * v[i] + h * h * acc[i]
                step_work_supplied, step_work_dissipated = h * supplied, h * dissipated
            elif method == VELOCITY_VERLET:
                if not first_ready:
                    power[0], power[1] = accelerations(packed, t, q, v, latched, acc, forces, pair_out,
                                                       constraint_forces)
                    counters[EVALUATIONS] += 1
                for i in range(n):
                    v_new[i] = v[i] + 0.5 * h * acc[i]  # half kick
                    q_new[i] = q[i] + h * v_new[i]  # drift
                    stage_v[i] = v_new[i] + 0.5 * h * acc[i]  # predicted end velocity
                supplied, dissipated = accelerations(packed, t + h, q_new, stage_v, latched, acc, forces, pair_out,
                                                     constraint_forces)
                counters[EVALUATIONS] += 1
                for i in range(n):
                    v_new[i] += 0.5 * h * acc[i]
                step_work_supplied = 0.5 * h * (power[0] + supplied)
                step_work_dissipated = 0.5 * h * (power[1] + dissipated)
                power[0], power[1] = supplied, dissipated
                first_ready = True
            else:
                _rk_step(packed, tab_a, tab_b, tab_c, t, h, q, v, latched, kq, kv, kp, first_ready,
                         q_new, v_new, stage_q, stage_v, forces, pair_out, constraint_forces, counters)
                first_ready = True  # the first stage depends on the state only, not on h
                if adaptive:
                    error = _error_norm(tab_b, tab_e, h, q, v, q_new, v_new, kq, kv, tolerance)
                    factor = min(5.0, max(0.2, 0.9 * error ** (-1.0 / (error_order + 1)))) if error > 0 else 5.0
                    if not error <= 1.0:  # also rejects a NaN error
                        counters[REJECTED] += 1
                        h_adaptive = h * factor if math.isfinite(error) else 0.2 * h
                        if h_adaptive < 1e-14 * max(1.0, abs(t)):
                            status = STEP_UNDERFLOW
                            break
                        continue
                    proposal = max(h * factor, h_adaptive) if landing else h * factor
                    h_adaptive = min(proposal, step)
                step_work_supplied = step_work_dissipated = 0.0
                for i in range(stages):
                    step_work_supplied += h * tab_b[i] * kp[i, 0]
                    step_work_dissipated += h * tab_b[i] * kp[i, 1]
                first_ready = fsal  # after acceptance, only an FSAL last stage is f at the new state

            if has_constraints:
                violation = project_positions(packed.constraints, packed.inverse_mass, q_new, scale)
                if not violation <= 1e-10 * scale:
                    status = PROJECTION_FAILED
                    break
                if method != CENTRAL_DIFFERENCE:  # its velocity is the backward difference below
                    project_velocities(packed.constraints, packed.inverse_mass, q_new, v_new)
                first_ready = False
            if method == CENTRAL_DIFFERENCE:
                for i in range(n):
                    v_new[i] = (q_new[i] - q[i]) / h

            for i in range(n):
                if status == RUNNING and not (math.isfinite(q_new[i]) and math.isfinite(v_new[i])):
                    status, culprit = NONFINITE, i
            for body in range(n // 3):
                if status == RUNNING and v_new[3 * body] ** 2 + v_new[3 * body + 1] ** 2 > speed_limit**2:
                    status, culprit = BLOWUP, 3 * body
            if status != RUNNING:
                break
            q[:] = q_new
            v[:] = v_new
            work[0] += step_work_supplied
            work[1] += step_work_dissipated
            if adaptive:
                t = t_target if landing else t + h
            else:
                steps_left -= 1
                taken += 1
                t = t_target if landing else t_base + taken * h
            counters[STEPS] += 1
            changed, worst = advance_pair_state(packed.pairs, q, v, t, latched, events, penetration_bound)
            if changed:
                first_ready = False
            if worst >= 0:
                status, culprit = PENETRATION, worst
                break
            if method == RUNGE_KUTTA and first_ready:
                kq[0, :] = kq[stages - 1]
                kv[0, :] = kv[stages - 1]
                kp[0, :] = kp[stages - 1]

        if status != RUNNING:
            break
        out_t[output_index] = t
        out_q[output_index] = q
        out_v[output_index] = v
        accelerations(packed, t, q, v, latched, output_acc, forces, pair_out, constraint_forces, True)
        out_pairs[output_index] = pair_out
        out_work[output_index] = work
        out_constraints[output_index] = constraint_forces
        output_index += 1
    verlet_ready[0] = 1 if (method == VELOCITY_VERLET and first_ready) else 0
    return t, h_adaptive, output_index, status, culprit
