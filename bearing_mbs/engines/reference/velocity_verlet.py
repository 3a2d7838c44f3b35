r"""Velocity Verlet (kick–drift–kick) with a velocity predictor for velocity-dependent forces.

.. math::
    v_{n+1/2} = v_n + \tfrac h2 a_n,\quad q_{n+1} = q_n + h\,v_{n+1/2},\quad
    a_{n+1} = f\bigl(q_{n+1},\, v_{n+1/2} + \tfrac h2 a_n\bigr),\quad v_{n+1} = v_{n+1/2} + \tfrac h2 a_{n+1}

Second order, one force evaluation per step: :math:`a_{n+1}` and its power are kept
(:class:`~bearing_mbs.engines.reference.bundles.VerletCarry`) as the next step's :math:`a_n`. The work is
integrated with the trapezoid rule, :math:`W \mathrel{+}= \tfrac h2 (P_n + P_{n+1})`.
"""

from __future__ import annotations

import numba

from bearing_mbs.engines.reference.codes import EVALUATIONS
from bearing_mbs.engines.reference.dynamics import accelerations


@numba.njit(cache=True, inline="always")
def velocity_verlet_step(packed, t, h, state, carry, ready, workspace, counters):
    """The state at t + h into ``workspace.q_new``, ``workspace.v_new``; returns the step's (supplied,
    dissipated) work [J]. ``ready``: ``carry`` already holds a(q, v) and the power of the current state.
    Afterwards ``carry`` holds those of the new state."""
    q, v, latched = state.q, state.v, state.latched
    a, power = carry.acceleration, carry.power
    q_new, v_new, predicted_v = workspace.q_new, workspace.v_new, workspace.stage_v
    if not ready:
        power[0], power[1] = accelerations(packed, t, q, v, latched, a, workspace)
        counters[EVALUATIONS] += 1
    for i in range(q.size):
        v_new[i] = v[i] + 0.5 * h * a[i]  # half kick
        q_new[i] = q[i] + h * v_new[i]  # drift
        predicted_v[i] = v_new[i] + 0.5 * h * a[i]  # predicted end velocity
    supplied, dissipated = accelerations(packed, t + h, q_new, predicted_v, latched, a, workspace)
    counters[EVALUATIONS] += 1
    for i in range(q.size):
        v_new[i] += 0.5 * h * a[i]  # second half kick
    work_supplied = 0.5 * h * (power[0] + supplied)
    work_dissipated = 0.5 * h * (power[1] + dissipated)
    power[0], power[1] = supplied, dissipated
    return work_supplied, work_dissipated
