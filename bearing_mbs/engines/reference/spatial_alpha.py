r"""The reference engine's implicit method in three dimensions: generalized-α in its Lie-group form (Brüls, Cardona &
Arnold 2012, "Lie group generalized-α time integration of constrained flexible multibody systems", Mech. Mach.
Theory 48, 121–137), fixed-step, with Newton's method on a Jacobian by forward differences.

Per body the velocities are v = (ṙ, ω) (ṙ in the world frame, ω in the body frame) and their rates v̇ = (r̈, ω̇); the
configuration (r, p) moves by increments in the body's frame, so that the orientation p stays a unit quaternion
without a constraint. With the auxiliary accelerations a:

.. math::
    (1-\alpha_m) a_{n+1} + \alpha_m a_n = (1-\alpha_f) \dot v_{n+1} + \alpha_f \dot v_n,\quad
    \Delta_n = v_n + h(\tfrac12 - \beta) a_n + h\beta\, a_{n+1},\\
    r_{n+1} = r_n + h \Delta_n^{r},\quad p_{n+1} = p_n \otimes \exp(h \Delta_n^{\omega}/2),\quad
    v_{n+1} = v_n + h(1-\gamma) a_n + h\gamma\, a_{n+1},\quad
    \dot v_{n+1} = f(r_{n+1}, p_{n+1}, v_{n+1})

with f the Newton–Euler equations (:func:`.spatial.spatial_rates`) and the coefficients of the planar method
(:func:`.generalized_alpha.coefficients`): second order, the unresolved high frequencies (the contacts' stiff modes)
damped to the spectral radius ρ∞. Lie-group generalized-α is also Exudyn's implicit method on its rotation-vector
nodes, so the two engines' implicit runs cross-check each other (different code, same scheme).

**Newton.** The unknowns are x = v̇_{n+1}; the configuration and velocities move with x at the slopes
β' = h²β(1−α_f)/(1−α_m) and γ' = hγ(1−α_f)/(1−α_m). The residual R(x) = x − f(state(x)) has the Jacobian
∂R/∂x = I − M⁻¹(β' K T + γ' C) (stiffness K, damping C, the exponential map's tangent T, the gyroscopic terms), which
is formed by forward differences of R itself, so that all of it is in, the tangent included. Each body's six columns
come from evaluations of the force elements that touch that body alone (``SpatialWork.active``): a roller's contacts
are a few of the bearing's, so a Jacobian costs about seven evaluations of each element for each body it touches
(about 20 full evaluations for a caged bearing) rather than 6N + 1. It is inverted once (the system is small and
dense: 6N coordinates) and serves the iterations (modified Newton) until Newton stalls or the step changes by more
than :data:`~.generalized_alpha.REUSE_RATIO`. The iteration's stopping rule, its limits and the retry at a shorter
step are the planar method's (:mod:`.generalized_alpha`): each increment of a position below
:data:`~.generalized_alpha.NEWTON_FRACTION` of tolerance·(1 + |r|), of a rotation below that of tolerance [rad], of
a velocity below that of tolerance·(1 + |v|). The work is integrated with the trapezoid rule over the steps' end
powers; the contacts' latched approach speeds advance once per accepted step.
"""

from __future__ import annotations

from typing import NamedTuple

import numba
import numpy as np

from bearing_mbs.core.rotations import turned_quaternion
from bearing_mbs.elements.spatial import latch
from bearing_mbs.engines.reference.codes import (
    EVALUATIONS,
    JACOBIANS,
    NEWTON_ITERATIONS,
    REJECTED,
    RUNNING,
    STEP_UNDERFLOW,
)
from bearing_mbs.engines.reference.generalized_alpha import (
    CONTRACTIVITY,
    DIFFERENCE_STEP,
    ITERATIONS_PER_JACOBIAN,
    JACOBIANS_PER_STEP,
    NEWTON_FRACTION,
    NEWTON_RETRY,
    RECOVERY,
    REUSE_RATIO,
    coefficients,
)
from bearing_mbs.engines.reference.integrators import equal_steps
from bearing_mbs.engines.reference.spatial_rates import VELOCITY, spatial_rates
from bearing_mbs.engines.reference.step_control import underflows

#: The configuration's move [m or rad] of a forward difference's column (at least DIFFERENCE_STEP of the rate).
DIFFERENCE_MOVE = 1e-10


class AlphaCarry(NamedTuple):
    """What generalized-α carries from step to step (N bodies): the rates v̇_n and auxiliary accelerations a_n (N, 6)
    (translation, then rotation), the end powers of the last step (supplied, dissipated) [W] (2,), Newton's inverse
    matrix (6N, 6N) and the step it was formed for [s] (1,); and its scratch: the iterate x, the
    parts of the increments and velocities that do not depend on x, two residuals (N, 6), the iterate's state and
    rates (N, 13)."""

    rate: np.ndarray
    auxiliary: np.ndarray
    power: np.ndarray
    inverse: np.ndarray
    matrix_step: np.ndarray
    unknown: np.ndarray
    fixed_move: np.ndarray
    fixed_velocity: np.ndarray
    residual: np.ndarray
    shifted: np.ndarray
    state: np.ndarray
    rates: np.ndarray


def new_carry(y: np.ndarray) -> AlphaCarry:
    """The :class:`AlphaCarry` of the states ``y`` (N, 13), its rates not yet started (see :func:`alpha_start`)."""
    n = y.shape[0]
    six = lambda: np.zeros((n, 6))
    return AlphaCarry(six(), six(), np.zeros(2), np.zeros((6 * n, 6 * n)), np.zeros(1), six(), six(), six(), six(),
                      six(), np.empty_like(y), np.empty_like(y))


@numba.njit(cache=True)
def alpha_start(y, bodies, packed, work, carry):
    """The rates at the initial state as v̇_0 and a_0, and its powers (the method's start)."""
    powers = spatial_rates(y, bodies, packed, work, carry.rates)
    for b in range(y.shape[0]):
        for k in range(6):
            carry.rate[b, k] = carry.auxiliary[b, k] = carry.rates[b, VELOCITY + k]
    carry.power[0], carry.power[1] = powers[0], powers[1]


@numba.njit(cache=True)
def _state_of(y, carry, slope_q, slope_v):
    """The state of the iterate x = ``carry.unknown`` into ``carry.state``: r and p moved by the increments
    fixed_move + β' x from ``y``'s, the velocities fixed_velocity + γ' x."""
    x, move, state = carry.unknown, carry.fixed_move, carry.state
    for b in range(y.shape[0]):
        for k in range(3):
            state[b, k] = y[b, k] + move[b, k] + slope_q * x[b, k]
        state[b, 3], state[b, 4], state[b, 5], state[b, 6] = turned_quaternion(
            y[b, 3], y[b, 4], y[b, 5], y[b, 6], move[b, 3] + slope_q * x[b, 3], move[b, 4] + slope_q * x[b, 4],
            move[b, 5] + slope_q * x[b, 5])
        for k in range(6):
            state[b, VELOCITY + k] = carry.fixed_velocity[b, k] + slope_v * x[b, k]


@numba.njit(cache=True)
def _residual(y, bodies, packed, work, carry, slope_q, slope_v, out):
    """R(x) = x − f(state(x)) into ``out`` (N, 6); returns the force elements' powers and stored energy."""
    _state_of(y, carry, slope_q, slope_v)
    powers = spatial_rates(carry.state, bodies, packed, work, carry.rates)
    for b in range(y.shape[0]):
        for k in range(6):
            out[b, k] = carry.unknown[b, k] - carry.rates[b, VELOCITY + k]
    return powers


@numba.njit(cache=True)
def _form_inverse(y, bodies, packed, work, carry, slope_q, slope_v, counters):
    """Newton's matrix ∂R/∂x at the iterate by forward differences, body by body with only the elements that touch
    the body (the module's docstring), inverted into ``carry.inverse``; False when it is singular (the step is then
    retried shorter)."""
    n = y.shape[0]
    x, base, shifted, active = carry.unknown, carry.residual, carry.shifted, work.active
    matrix = np.empty((6 * n, 6 * n))
    for j in range(n):
        active[:] = False
        active[j] = True
        _residual(y, bodies, packed, work, carry, slope_q, slope_v, base)
        for k in range(6):
            saved = x[j, k]
            delta = max(DIFFERENCE_MOVE / slope_q, DIFFERENCE_STEP * abs(saved))
            x[j, k] = saved + delta
            _residual(y, bodies, packed, work, carry, slope_q, slope_v, shifted)
            x[j, k] = saved
            for i in range(n):
                for m in range(6):
                    matrix[6 * i + m, 6 * j + k] = (shifted[i, m] - base[i, m]) / delta
        counters[EVALUATIONS] += 7
    active[:] = True
    counters[JACOBIANS] += 1
    try:
        carry.inverse[:] = np.linalg.inv(matrix)
    except Exception:  # noqa: BLE001 (numba raises LinAlgError on a singular matrix and binds no exception)
        return False
    return True


@numba.njit(cache=True)
def alpha_step(y, energy, bodies, packed, work, carry, h, spectral_radius, tolerance, counters):
    """One attempt of a step of h [s] from the states ``y`` (N, 13). Accepted (returns True): ``y``, ``carry`` and
    the work ``energy`` (supplied, dissipated) [J] advanced, the latches too; else all as they were."""
    n = y.shape[0]
    alpha_m, alpha_f, gamma, beta = coefficients(spectral_radius)
    share = (1.0 - alpha_f) / (1.0 - alpha_m)  # ∂a_{n+1}/∂x
    slope_q, slope_v = h * h * beta * share, h * gamma * share
    x, rate, auxiliary = carry.unknown, carry.rate, carry.auxiliary
    for b in range(n):
        for k in range(6):
            fixed_auxiliary = (alpha_f * rate[b, k] - alpha_m * auxiliary[b, k]) / (1.0 - alpha_m)
            v = y[b, VELOCITY + k]
            carry.fixed_move[b, k] = h * v + h * h * ((0.5 - beta) * auxiliary[b, k] + beta * fixed_auxiliary)
            carry.fixed_velocity[b, k] = v + h * ((1.0 - gamma) * auxiliary[b, k] + gamma * fixed_auxiliary)
            x[b, k] = rate[b, k]  # the predictor
    inverse, residual = carry.inverse, carry.residual.reshape(6 * n)
    powers = (0.0, 0.0, 0.0)
    formed, converged, size = 0, False, np.inf
    form = not 1.0 / REUSE_RATIO <= h / carry.matrix_step[0] <= REUSE_RATIO if carry.matrix_step[0] > 0.0 else True
    while True:
        if form:
            formed += 1
            if not _form_inverse(y, bodies, packed, work, carry, slope_q, slope_v, counters):
                carry.matrix_step[0] = 0.0
                break
            carry.matrix_step[0] = h
        previous = first = np.inf
        for _ in range(ITERATIONS_PER_JACOBIAN):
            powers = _residual(y, bodies, packed, work, carry, slope_q, slope_v, carry.residual)
            counters[EVALUATIONS] += 1
            counters[NEWTON_ITERATIONS] += 1
            increment = -(inverse @ residual)
            size = 0.0
            for b in range(n):
                for k in range(6):
                    d = increment[6 * b + k]
                    x[b, k] += d
                    scale = 1.0 + abs(carry.state[b, k]) if k < 3 else 1.0
                    size = max(size, abs(slope_q * d) / (tolerance * scale),
                               abs(slope_v * d) / (tolerance * (1.0 + abs(carry.state[b, VELOCITY + k]))))
            rate_of_contraction = size / previous  # θ; 0 on the first iteration
            if size <= NEWTON_FRACTION or (0.0 < rate_of_contraction < 1.0 and rate_of_contraction
                                           / (1.0 - rate_of_contraction) * size <= NEWTON_FRACTION):
                converged = True
                break
            if not size <= CONTRACTIVITY * previous:  # too slow, diverging or not finite
                break
            if previous == np.inf:
                first = size
            previous = size
        if converged or formed == JACOBIANS_PER_STEP:
            break
        if not size < first:
            x[:] = rate  # diverged (or not finite): back to the predictor
        form = True
    if not converged:
        counters[REJECTED] += 1
        return False
    _state_of(y, carry, slope_q, slope_v)  # the converged iterate's, its last increment included
    y[:] = carry.state
    energy[0] += 0.5 * h * (carry.power[0] + powers[0])
    energy[1] += 0.5 * h * (carry.power[1] + powers[1])
    carry.power[0], carry.power[1] = powers[0], powers[1]
    for b in range(n):
        for k in range(6):
            auxiliary[b, k] = ((1.0 - alpha_f) * x[b, k] + alpha_f * rate[b, k] - alpha_m * auxiliary[b, k]) \
                / (1.0 - alpha_m)
            rate[b, k] = x[b, k]
    latch(work)  # the last evaluation's: at the converged iterate within Newton's tolerance
    return True


@numba.njit(cache=True)
def alpha_span(y, energy, bodies, packed, work, carry, span, step, spectral_radius, tolerance, counters):
    """Advance ``y`` over ``span`` [s] in equal steps of at most ``step`` [s]; a step whose Newton iteration fails
    is retried at NEWTON_RETRY of it, and the step grows back by RECOVERY per accepted step. Returns the steps taken
    and RUNNING, or STEP_UNDERFLOW when a retry would no longer advance t (``y`` then at the last accepted step)."""
    nominal = span / equal_steps(span, step)
    t, h, steps = 0.0, nominal, 0
    while span - t > 1e-9 * nominal:
        h = min(h, span - t)
        if alpha_step(y, energy, bodies, packed, work, carry, h, spectral_radius, tolerance, counters):
            t += h
            steps += 1
            h = min(RECOVERY * h, nominal)
        else:
            h *= NEWTON_RETRY
            if underflows(h, t):
                return steps, STEP_UNDERFLOW
    return steps, RUNNING
