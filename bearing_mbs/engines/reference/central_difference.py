r"""The central difference with a variable step, the primary document's scheme (its eqs. 56 and 58).

With the backward velocity :math:`v_i = (s_i - s_{i-1})/h_i`, the position update
:math:`s_{i+1} = s_i + (s_i - s_{i-1})\,h_{i+1}/h_i + f(s_i, v_i)\,h_{i+1}^2` reads
:math:`s_{i+1} = s_i + v_i h_{i+1} + f(s_i, v_i)\,h_{i+1}^2`, and the new velocity is again the backward
difference :math:`v_{i+1} = (s_{i+1} - s_i)/h_{i+1}`. Second order for velocity-independent forces, first
order once damping or friction make f depend on the lagged velocity. The step is ``step``, or
``contact_step`` while any pair penetrates. One force evaluation per step; the work is integrated with the
rectangle rule, :math:`W \mathrel{+}= h P(s_i, v_i)`.
"""

from __future__ import annotations

import numba
import numpy as np


@numba.njit(cache=True, inline="always")
def central_difference_step_size(controls, latched):
    """The wanted step [s]: ``contact_step`` while any pair penetrates (latched approach speed > 0), if set."""
    if controls.contact_step > 0.0:
        for k in range(latched.size):
            if latched[k] > 0.0:
                return controls.contact_step
    return controls.step


@numba.njit(cache=True, inline="always")
def central_difference_positions(q, v, a, h, q_new):
    """Positions at t + h into ``q_new``, from the acceleration a at (q, v) (the driver evaluates it and integrates
    the work, h times the power at (q, v)). The velocity follows after the constraint projection
    (:func:`central_difference_velocity`)."""
    for i in range(q.size):
        q_new[i] = q[i] + h * v[i] + h * h * a[i]


@numba.njit(cache=True, inline="always")
def central_difference_velocity(q, q_new, h, v_new):
    """The backward difference v_new = (q_new − q)/h."""
    for i in range(q.size):
        v_new[i] = (q_new[i] - q[i]) / h


def backward_difference_start(v: np.ndarray, acceleration: np.ndarray, step: float, times: np.ndarray) -> None:
    """Second-order start, in place: the backward velocity v₀ − h₀a₀/2 (Taylor), with h₀ the first step
    [s] of the first output interval, which makes the scheme exact for constant acceleration. The
    document's start (v₀ itself) costs an O(h) error even in free fall."""
    first = times[1] - times[0]
    h0 = first / np.ceil(first / step * (1 - 1e-9))
    v -= 0.5 * h0 * acceleration
