r"""Explicit Runge–Kutta on (q, v) with a Butcher tableau (:mod:`bearing_mbs.engines.reference.tableaus`).

Stages :math:`k_i = F\bigl(t + c_i h,\; y + h\sum_{j<i} a_{ij} k_j\bigr)` with :math:`y = (q, v)` and
:math:`F = (v, a)`; the step :math:`y_{n+1} = y_n + h\sum_i b_i k_i`. ``rk4`` takes the fixed step;
``dopri5`` adapts it with the embedded estimate :math:`h\sum_i (b_i - \hat b_i) k_i`: its RMS norm over (q, v),
each component scaled by tolerance·(1 + max(|y_n|, |y_{n+1}|)), must be ≤ 1, and the step-size controller
(:mod:`~bearing_mbs.engines.reference.step_control`, with the method's settings from the catalogue) proposes the
next step, capped by ``step``. The work is integrated with the weights b over the stages' power,
:math:`W \mathrel{+}= h\sum_i b_i P_i`.
"""

from __future__ import annotations

import math

import numba

from bearing_mbs.engines.reference.codes import EVALUATIONS, REJECTED, RUNNING, STEP_UNDERFLOW
from bearing_mbs.engines.reference.copies import copy_into
from bearing_mbs.engines.reference.dynamics import CONSTRAINED, PARTIAL, accelerations
from bearing_mbs.engines.reference.step_control import control_step


@numba.njit(cache=True)
def runge_kutta_stages(packed, tableau, t, h, state, stages, first_ready, workspace, counters):
    """All stages into ``stages``, the result y_{n+1} into ``workspace.q_new``, ``workspace.v_new``. With
    ``first_ready`` the first stage F(t, y_n) is already in place."""
    a, b, c = tableau.a, tableau.b, tableau.c
    q, v, latched = state.q, state.v, state.latched
    kq, kv, kp = stages.velocity, stages.acceleration, stages.power
    stage_q, stage_v, q_new, v_new = workspace.stage_q, workspace.stage_v, workspace.q_new, workspace.v_new
    stage_count, n = b.size, q.size
    for i in range(stage_count):
        if i == 0 and first_ready:
            continue
        for m in range(n):  # explicit loops: array expressions would allocate temporaries every stage
            position, velocity = q[m], v[m]
            for j in range(i):
                position += h * a[i, j] * kq[j, m]
                velocity += h * a[i, j] * kv[j, m]
            stage_q[m], stage_v[m] = position, velocity
            kq[i, m] = velocity
        kp[i, 0], kp[i, 1] = accelerations(packed, t + c[i] * h, stage_q, stage_v, latched, kv[i], workspace, PARTIAL,
                                           CONSTRAINED)
        counters[EVALUATIONS] += 1
    for m in range(n):
        position, velocity = q[m], v[m]
        for i in range(stage_count):
            position += h * b[i] * kq[i, m]
            velocity += h * b[i] * kv[i, m]
        q_new[m], v_new[m] = position, velocity


@numba.njit(cache=True)
def error_norm(tableau, h, q, v, q_new, v_new, stages, tolerance):
    """RMS over (q, v) of the embedded error estimate, scaled by tolerance·(1 + max|y|)."""
    b, b_error = tableau.b, tableau.b_error
    kq, kv = stages.velocity, stages.acceleration
    n = q.size
    total = 0.0
    for k in range(n):
        error_q = 0.0
        error_v = 0.0
        for i in range(b.size):
            error_q += (b[i] - b_error[i]) * kq[i, k]
            error_v += (b[i] - b_error[i]) * kv[i, k]
        scale_q = tolerance * (1.0 + max(abs(q[k]), abs(q_new[k])))
        scale_v = tolerance * (1.0 + max(abs(v[k]), abs(v_new[k])))
        total += (h * error_q / scale_q) ** 2 + (h * error_v / scale_v) ** 2
    return math.sqrt(total / (2 * n))


@numba.njit(cache=True, inline="always")
def runge_kutta_acceptance(tableau, controls, t, h, landing, h_adaptive, q, v, q_new, v_new, stages, counters):
    """The end of one attempt of a step from (q, v) at t to (``q_new``, ``v_new``) at t + h, its stages done
    (:func:`runge_kutta_stages`, which the driver calls); ``landing``: t + h is an output instant, ``h_adaptive``
    [s]: the current adaptive step.

    Returns (status, accepted, h_adaptive, work_supplied, work_dissipated): a rejected step (error norm > 1
    or not finite) gives a smaller ``h_adaptive`` to retry with, or ``STEP_UNDERFLOW`` when that is too short.
    An accepted step proposes the next ``h_adaptive`` (:func:`~bearing_mbs.engines.reference.step_control.control_step`)
    and returns its (supplied, dissipated) work [J]. Fixed-step tableaus always accept.
    """
    if tableau.b_error.size > 0:
        error = error_norm(tableau, h, q, v, q_new, v_new, stages, controls.tolerance)
        accepted, underflow, h_adaptive = control_step(controls.step_controller, error, t, h, landing, h_adaptive,
                                                       controls.step)
        if not accepted:
            counters[REJECTED] += 1
            return (STEP_UNDERFLOW if underflow else RUNNING), False, h_adaptive, 0.0, 0.0
    work_supplied = work_dissipated = 0.0
    for i in range(tableau.b.size):
        work_supplied += h * tableau.b[i] * stages.power[i, 0]
        work_dissipated += h * tableau.b[i] * stages.power[i, 1]
    return RUNNING, True, h_adaptive, work_supplied, work_dissipated


@numba.njit(cache=True, inline="always")
def reuse_last_stage(stages):
    """FSAL: the last stage, F at the accepted state, becomes the next step's first stage."""
    last = stages.power.shape[0] - 1
    copy_into(stages.velocity[0], stages.velocity[last])
    copy_into(stages.acceleration[0], stages.acceleration[last])
    copy_into(stages.power[0], stages.power[last])
