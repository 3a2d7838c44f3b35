r"""Velocity Verlet (kick–drift–kick) with a velocity predictor for velocity-dependent forces.

.. math::
    v_{n+1/2} = v_n + \tfrac h2 a_n,\quad q_{n+1} = q_n + h\,v_{n+1/2},\quad
    a_{n+1} = f\bigl(q_{n+1},\, v_{n+1/2} + \tfrac h2 a_n\bigr),\quad v_{n+1} = v_{n+1/2} + \tfrac h2 a_{n+1}

Second order, one force evaluation per step: :math:`a_{n+1}` and its power are kept
(:class:`~bearing_mbs.engines.reference.bundles.VerletCarry`) as the next step's :math:`a_n`. The work is
integrated with the trapezoid rule, :math:`W \mathrel{+}= \tfrac h2 (P_n + P_{n+1})`. The driver
(:mod:`~bearing_mbs.engines.reference.integrators`) evaluates the accelerations between the two functions here.
"""

from __future__ import annotations

import numba


@numba.njit(cache=True, inline="always")
def velocity_verlet_drift(q, v, a, h, q_new, v_new, predicted_v):
    """Half kick and drift: v_{n+1/2} into ``v_new``, q_{n+1} into ``q_new``, and the predicted end velocity
    v_{n+1/2} + h/2 a_n, at which the driver evaluates a_{n+1}, into ``predicted_v``; ``a`` holds a_n."""
    for i in range(q.size):
        v_new[i] = v[i] + 0.5 * h * a[i]  # half kick
        q_new[i] = q[i] + h * v_new[i]  # drift
        predicted_v[i] = v_new[i] + 0.5 * h * a[i]  # predicted end velocity


@numba.njit(cache=True, inline="always")
def velocity_verlet_kick(h, a, v_new, power, supplied, dissipated):
    """The second half kick with a_{n+1} (``a``) into ``v_new``; returns the step's (supplied, dissipated) work [J]
    from a_n's power (``power``, then replaced by a_{n+1}'s, ``supplied`` and ``dissipated`` [W])."""
    for i in range(v_new.size):
        v_new[i] += 0.5 * h * a[i]  # second half kick
    work_supplied = 0.5 * h * (power[0] + supplied)
    work_dissipated = 0.5 * h * (power[1] + dissipated)
    power[0], power[1] = supplied, dissipated
    return work_supplied, work_dissipated
