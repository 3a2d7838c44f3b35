r"""The step-size controller of every adaptive method of the reference engine (``dopri5``,
``generalized_alpha_adaptive``), in the manner of scipy's and diffrax's controllers.

A method computes its error norm err (RMS over the coordinates, each scaled by its tolerance: ≤ 1 accepts) and
asks :func:`control_step`: the step is accepted when err ≤ 1, and the next one is

.. math::
    h_\mathrm{next} = h\,\min\bigl(f_\max,\ \max(f_\min,\ s\,\mathrm{err}^{-1/(p+1)})\bigr)

(safety s, factors f_min and f_max, p the order of the method's error estimate: :class:`StepController`, set per
method from the catalogue, :class:`bearing_mbs.spec.methods.StepControl`), capped by the largest step; a step
whose error is not finite is retried at f_min·h. A step that only shortened to land on an output instant does
not shorten the next. Whatever shrinks a step (a rejection, a failed Newton iteration) checks it against
:data:`UNDERFLOW` with :func:`underflows`.
"""

from __future__ import annotations

import math
from typing import NamedTuple

import numba

#: A step below this fraction of max(1 s, |t|) cannot advance t in double precision any more: the run stops
#: (``STEP_UNDERFLOW``) [-].
UNDERFLOW = 1e-14


class StepController(NamedTuple):
    """The controller of one adaptive method, as numba takes it: safety s, min_factor, max_factor [-] and the
    error exponent 1/(p+1) [-]. A fixed-step method gets :data:`NO_CONTROLLER` (never read)."""

    safety: float
    min_factor: float
    max_factor: float
    error_exponent: float


NO_CONTROLLER = StepController(0.0, 0.0, 0.0, 0.0)


def step_controller(method) -> StepController:
    """The controller of ``method`` (a :class:`bearing_mbs.spec.methods.Method`), :data:`NO_CONTROLLER` for a
    method without step control in the reference engine."""
    control = method.step_control
    if control is None:
        return NO_CONTROLLER
    return StepController(float(control.safety), float(control.min_factor), float(control.max_factor),
                          1.0 / (method.error_order + 1))


@numba.njit(cache=True, inline="always")
def underflows(h, t):
    """The step h [s] is too short to advance t [s] (:data:`UNDERFLOW`)."""
    return h < UNDERFLOW * max(1.0, abs(t))


@numba.njit(cache=True, inline="always")
def step_factor(controller, error):
    """The factor on the step for the error norm ``error``: safety·err^(−1/(p+1)) clipped to
    [min_factor, max_factor]; max_factor for a zero error (or NaN, which the caller rejects)."""
    if error > 0:
        return min(controller.max_factor,
                   max(controller.min_factor, controller.safety * error ** (-controller.error_exponent)))
    return controller.max_factor


@numba.njit(cache=True, inline="always")
def control_step(controller, error, t, h, landing, h_adaptive, largest):
    """Accept or reject the step h [s] from t [s] with error norm ``error``; ``landing``: h was shortened to land
    on an output instant, ``h_adaptive`` [s]: the step it was shortened from, ``largest`` [s]: the cap.

    Returns (accepted, underflow, h_next): a rejected step (error > 1 or not finite) gives the shorter step to
    retry with, ``underflow`` when it is too short (:func:`underflows`); an accepted one the next step, kept at
    least ``h_adaptive`` when it only shortened to land.
    """
    factor = step_factor(controller, error)
    if not error <= 1.0:  # also rejects a NaN error
        h_next = h * factor if math.isfinite(error) else controller.min_factor * h
        return False, underflows(h_next, t), h_next
    proposal = max(h * factor, h_adaptive) if landing else h * factor
    return True, False, min(proposal, largest)
