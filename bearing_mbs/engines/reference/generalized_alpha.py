r"""Generalized-α (Chung & Hulbert 1993, in the form of Arnold & Brüls 2007) with Newton's method on the force
elements' analytic Jacobian, fixed-step (``generalized_alpha``) or error-controlled (``generalized_alpha_adaptive``).

For :math:`\ddot q = f(t, q, v)` (:func:`~bearing_mbs.engines.reference.dynamics.accelerations`: forces,
gravity, index-1 constraint forces), with the auxiliary accelerations :math:`\tilde a`:

.. math::
    (1-\alpha_m)\tilde a_{n+1} + \alpha_m \tilde a_n = (1-\alpha_f) a_{n+1} + \alpha_f a_n,\quad
    q_{n+1} = q_n + h v_n + h^2(\tfrac12 - \beta)\tilde a_n + h^2\beta\,\tilde a_{n+1},\quad
    v_{n+1} = v_n + h(1-\gamma)\tilde a_n + h\gamma\,\tilde a_{n+1},\quad a_{n+1} = f(t_{n+1}, q_{n+1}, v_{n+1})

with :math:`\alpha_m = (2\rho_\infty - 1)/(\rho_\infty + 1)`, :math:`\alpha_f = \rho_\infty/(\rho_\infty + 1)`,
:math:`\gamma = \tfrac12 + \alpha_f - \alpha_m`, :math:`\beta = \tfrac14(\gamma + \tfrac12)^2`: second order,
unconditionally stable on linear problems, damping the unresolved high frequencies to the spectral radius
:math:`\rho_\infty` (``spectral_radius``) and no others to first order.

**Why this method.** A roller bearing's contacts are stiff modes far above the motion of interest: the method
must step over them stably and damp them, and each step must be cheap. Generalized-α solves one n × n Newton
system per step; SDIRK solves one per stage (three to five per step), Radau IIA one of size 3n. Their higher
orders buy little here: contact onsets are kinks that bring every method down to about first or second order
(``docs/numerics.md``). It is also the method of Exudyn's implicit solver, so the two engines' implicit runs
cross-check each other independently (different code, same scheme).

**Newton.** The unknowns are :math:`a = a_{n+1}` and the constraints' multipliers λ; :math:`q_{n+1}` and
:math:`v_{n+1}` are linear in a with slopes :math:`\beta' = h^2\beta(1-\alpha_f)/(1-\alpha_m)` and
:math:`\gamma' = h\gamma(1-\alpha_f)/(1-\alpha_m)`. The residuals :math:`r = a - M^{-1}(F + G^T\lambda) - g`
(gravity g) and :math:`r_\lambda = G a - \gamma` (the index-1 constraints, as
:mod:`~bearing_mbs.engines.reference.constraints` writes them) have the Jacobian

.. math::
    \begin{bmatrix} M - \beta' K - \gamma' C & -G^T \\ G & 0 \end{bmatrix}

(rows of r scaled by M), with :math:`K = \partial F/\partial q` and :math:`C = \partial F/\partial v`
(:func:`bearing_mbs.elements.element_jacobian`); the terms in :math:`\partial G/\partial q` are left out (they
scale with the forces, not with their stiffness). With the multipliers as unknowns, an iteration evaluates the
forces alone, without the constraint solve of an explicit method's evaluation; converged, a and λ are the index-1
accelerations of the new state. A scene with a force element registered from outside, which has no analytic
Jacobian, gets K and C by forward differences of its forces (2n evaluations). The matrix is sparse in the bodies
and is factored by :mod:`~bearing_mbs.engines.reference.block_elimination`, body block by body block, so its cost
grows linearly with the rollers. It is formed and factored when the step changes (modified Newton) and again when
Newton stalls. The iteration stops when the iterate's error, estimated from the last increment Δ and the observed
contraction θ = ‖Δ_k‖/‖Δ_{k−1}‖ as θ/(1−θ)‖Δ_k‖ (the geometric tail of a contracting iteration: Hairer & Wanner
1996, §IV.8, eq. 8.10), or the increment itself, is below :data:`NEWTON_FRACTION` of every coordinate's tolerance
scale in position and velocity (the first iteration has no θ and stops on its increment alone). A modified Newton
iteration contracts by θ ≈ 0.05 on the seed bearing, so the estimate saves about one iteration per step against
the increment alone (3.9 → 3.0 iterations per step at 2e-5 s, docs/numerics.md).

**Error and step control** (``generalized_alpha_adaptive``). The local error of the positions is estimated as
:math:`e = (\beta - \tfrac16) h^2 (a_{n+1} - a_n)` (Zienkiewicz & Xie 1991, the Newmark family's leading term
:math:`(\beta - \tfrac16) h^3 \dddot q`); its RMS norm, each coordinate scaled by tolerance·(1 + max(|q_n|,
|q_{n+1}|)), must be ≤ 1, and the step-size controller (:mod:`~bearing_mbs.engines.reference.step_control`, with
the method's settings from the catalogue: an error of order 2, growth at most 2×) proposes the next step, capped by
``step``. A step whose Newton iteration fails, or whose new state the constraint projection refuses
(:func:`take_back`), is retried at :data:`NEWTON_RETRY` of it, in both forms; the fixed-step form then grows its step by :data:`RECOVERY` per step back to the nominal one, as Exudyn's does. J is
reused from step to step while Newton converges fast and the step stays within :data:`REUSE_RATIO` of the one it
was formed for. The work is integrated
with the trapezoid rule over the step's end powers.
"""

from __future__ import annotations

import math

import numba
import numpy as np

from bearing_mbs.elements import element_jacobian
from bearing_mbs.engines.reference.block_elimination import assemble_constraints, factor, solve, subtract_stiffness
from bearing_mbs.engines.reference.codes import (
    EVALUATIONS,
    JACOBIANS,
    NEWTON_ITERATIONS,
    REJECTED,
    RUNNING,
    STEP_UNDERFLOW,
)
from bearing_mbs.engines.reference.constraints import constraint_rows, times_rows
from bearing_mbs.engines.reference.copies import copy_into
from bearing_mbs.engines.reference.dynamics import (
    COMPLETE,
    CONSTRAINED,
    PARTIAL,
    UNCONSTRAINED,
    accelerations,
)
from bearing_mbs.engines.reference.step_control import control_step, underflows

#: Newton stops when every increment is below this fraction of its coordinate's tolerance scale.
NEWTON_FRACTION = 0.1
#: Newton iterations with one Jacobian before it is formed again, and the Jacobians one step may form.
ITERATIONS_PER_JACOBIAN, JACOBIANS_PER_STEP = 8, 4
#: J is formed again when an iteration shrinks the increment by less than this factor.
CONTRACTIVITY = 0.9
#: J of a step h' serves a step h with 1/REUSE_RATIO ≤ h/h' ≤ REUSE_RATIO (Newton's test guards the result).
REUSE_RATIO = 1.4
#: The relative perturbation of the forward differences (elements without an analytic Jacobian).
DIFFERENCE_STEP = 1e-7
#: A step whose Newton iteration fails is retried at this fraction of it [-].
NEWTON_RETRY = 0.5
#: After a retry, the fixed-step form grows its step by this factor per accepted step, up to the nominal one [-].
RECOVERY = 2.0


@numba.njit(cache=True)
def coefficients(spectral_radius):
    """(α_m, α_f, γ, β) of generalized-α with high-frequency spectral radius ρ∞ (Chung & Hulbert 1993)."""
    alpha_m = (2.0 * spectral_radius - 1.0) / (spectral_radius + 1.0)
    alpha_f = spectral_radius / (spectral_radius + 1.0)
    gamma = 0.5 + alpha_f - alpha_m
    return alpha_m, alpha_f, gamma, 0.25 * (gamma + 0.5) ** 2


@numba.njit(cache=True, inline="always")
def form_newton_matrix(packed, analytic, t, q, v, latched, slope_q, slope_v, workspace, carry, counters):
    """Newton's matrix at (t, q, v) (mass less β' ∂F/∂q + γ' ∂F/∂v, bordered by the constraints' G: the module's
    docstring), formed as the sparse system of :mod:`~bearing_mbs.engines.reference.block_elimination` and
    factored into ``carry.newton``; the G it used into ``carry.constraint_rows``."""
    n = q.size
    stiffness, damping = carry.stiffness, carry.damping
    if analytic:  # the complete pair outputs the Jacobian reads
        accelerations(packed, t, q, v, latched, workspace.acceleration, workspace, COMPLETE, UNCONSTRAINED)
        counters[EVALUATIONS] += 1
        element_jacobian(packed.elements, t, q, v, latched, workspace.pair_out, stiffness, damping)
    else:  # forward differences of the forces: a registered kind without an analytic Jacobian
        base, shifted = carry.base, workspace.forces
        accelerations(packed, t, q, v, latched, workspace.acceleration, workspace, PARTIAL, UNCONSTRAINED)
        counters[EVALUATIONS] += 1
        copy_into(base, shifted)
        for j in range(2 * n):
            column = j % n
            x = q if j < n else v
            saved = x[column]
            delta = DIFFERENCE_STEP * max(1.0, abs(saved))
            x[column] = saved + delta
            accelerations(packed, t, q, v, latched, workspace.acceleration, workspace, PARTIAL, UNCONSTRAINED)
            counters[EVALUATIONS] += 1
            x[column] = saved
            target = stiffness if j < n else damping
            for i in range(n):
                target[i, column] = (shifted[i] - base[i]) / delta
    constraints = packed.constraints  # the iterate's gap and residual arrays serve as scratch here
    constraint_rows(constraints, q, v, carry.constraint_gap, carry.constraint_rows, carry.constraint_residual)
    assemble_constraints(carry.newton, packed.inverse_mass, carry.constraint_rows, constraints.body_a,
                         constraints.body_b)
    subtract_stiffness(carry.newton, packed.inverse_mass, stiffness, damping, slope_q, slope_v)
    factor(carry.newton)


@numba.njit(cache=True)
def newton_increment(packed, carry, residual, constraint_residual):
    """Newton's increments of the accelerations, into ``carry.increment``, and of the multipliers, added to
    ``carry.multiplier``: the factored system solved with −M r on the free coordinates, −r on the fixed ones and
    −r_λ on the constraints (``residual`` r, ``constraint_residual`` r_λ: see :func:`newton_residual`)."""
    n, system = residual.size, carry.newton
    right_hand_side = system.right_hand_side
    for i in range(n):
        w = packed.inverse_mass[i]
        right_hand_side[i] = -residual[i] / w if w > 0.0 else -residual[i]
    for k in range(constraint_residual.size):
        right_hand_side[n + k] = -constraint_residual[k]
    solve(system)
    copy_into(carry.increment, right_hand_side[:n])
    for k in range(constraint_residual.size):
        carry.multiplier[k] += right_hand_side[n + k]


@numba.njit(cache=True)
def newton_residual(packed, carry, free, q, v):
    """r = a − M⁻¹(F + Gᵀλ) − g into ``free`` (which holds M⁻¹F + g at (q, v) on entry) and r_λ = G a − γ into
    ``carry.constraint_residual``, for the iterate a = ``carry.unknown``, λ = ``carry.multiplier``."""
    a, constraints = carry.unknown, packed.constraints
    for i in range(a.size):
        free[i] = a[i] - free[i]
    if constraints.kind.size == 0:
        return
    rows = carry.current_rows
    constraint_rows(constraints, q, v, carry.constraint_gap, rows, carry.constraint_residual)
    for k in range(constraints.kind.size):
        for side in range(2):
            body = constraints.body_a[k] if side == 0 else constraints.body_b[k]
            for d in range(3):
                i = 3 * body + d
                free[i] -= packed.inverse_mass[i] * rows[k, 3 * side + d] * carry.multiplier[k]
        carry.constraint_residual[k] = times_rows(constraints, rows, a, k) - carry.constraint_residual[k]


@numba.njit(cache=True)
def keep_accepted(carry):
    """Copy the accepted state's memory (acceleration, auxiliary acceleration, power, multipliers) aside."""
    copy_into(carry.kept_acceleration, carry.acceleration)
    copy_into(carry.kept_auxiliary, carry.auxiliary)
    copy_into(carry.kept_power, carry.power)
    copy_into(carry.kept_multiplier, carry.accepted_multiplier)


@numba.njit(cache=True)
def take_back(carry, t, h, counters):
    """Undo an accepted step that a later check refused (the constraint projection): the memory of
    :func:`keep_accepted` restored, the step counted as rejected. Returns the step to retry with, NEWTON_RETRY of
    ``h`` [s], or 0 when that would not advance t."""
    copy_into(carry.acceleration, carry.kept_acceleration)
    copy_into(carry.auxiliary, carry.kept_auxiliary)
    copy_into(carry.power, carry.kept_power)
    copy_into(carry.accepted_multiplier, carry.kept_multiplier)
    counters[REJECTED] += 1
    shorter = NEWTON_RETRY * h
    return 0.0 if underflows(shorter, t) else shorter


@numba.njit(cache=True, inline="always")
def _state_of(a, fixed_q, fixed_v, slope_q, slope_v, q, v):
    """q_{n+1} = fixed_q + slope_q a and v_{n+1} = fixed_v + slope_v a of the iterate a, into q, v."""
    for i in range(a.size):
        q[i] = fixed_q[i] + slope_q * a[i]
        v[i] = fixed_v[i] + slope_v * a[i]


@numba.njit(cache=True)
def generalized_alpha_step(packed, controls, error_control, t, h, landing, h_adaptive, state, carry, ready, workspace,
                           counters):
    """One attempt of a step from t to t + h into ``workspace.q_new``, ``workspace.v_new``; ``ready``: ``carry``
    holds a(q, v) and the power of the current state. ``landing``: t + h is an output instant; ``h_adaptive``
    [s]: the current adaptive step.

    Returns (status, accepted, h_adaptive, work_supplied, work_dissipated). An accepted step leaves the new
    state's acceleration, auxiliary acceleration and power in ``carry``; a rejected one leaves ``carry`` as it
    was, with a smaller ``h_adaptive`` (``STEP_UNDERFLOW`` when that is too short to advance t). ``error_control``:
    accept by the error estimate and propose the next step from it (else by Newton's convergence alone).
    """
    q, v, latched = state.q, state.v, state.latched
    q_new, v_new, f = workspace.q_new, workspace.v_new, workspace.acceleration
    a_old, auxiliary, power, a, increment = carry.acceleration, carry.auxiliary, carry.power, carry.unknown, \
        carry.increment
    n = q.size
    tolerance = controls.tolerance
    multiplier, accepted_multiplier = carry.multiplier, carry.accepted_multiplier
    if not ready:
        power[0], power[1] = accelerations(packed, t, q, v, latched, a_old, workspace, PARTIAL, CONSTRAINED)
        counters[EVALUATIONS] += 1
        copy_into(accepted_multiplier, workspace.constraint_system.right_hand_side[n:])  # its λ (constraints.py)
        if carry.started[0] == 0:  # ã_0 = a_0
            copy_into(auxiliary, a_old)
            carry.started[0] = 1
    alpha_m, alpha_f, gamma, beta = coefficients(controls.spectral_radius)
    share = (1.0 - alpha_f) / (1.0 - alpha_m)  # ∂ã_{n+1}/∂a
    slope_q, slope_v = h * h * beta * share, h * gamma * share
    # the parts of q_{n+1}, v_{n+1} and ã_{n+1} that do not depend on a
    for i in range(n):
        fixed_auxiliary = (alpha_f * a_old[i] - alpha_m * auxiliary[i]) / (1.0 - alpha_m)
        workspace.stage_q[i] = q[i] + h * v[i] + h * h * ((0.5 - beta) * auxiliary[i] + beta * fixed_auxiliary)
        workspace.stage_v[i] = v[i] + h * ((1.0 - gamma) * auxiliary[i] + gamma * fixed_auxiliary)
        a[i] = a_old[i]  # the predictor
    copy_into(multiplier, accepted_multiplier)
    supplied = dissipated = 0.0
    formed, converged = 0, False
    form = not 1.0 / REUSE_RATIO <= h / carry.matrix_step[0] <= REUSE_RATIO  # J of another step: form it
    while True:
        if form:  # J at the current iterate, for steps of h
            _state_of(a, workspace.stage_q, workspace.stage_v, slope_q, slope_v, q_new, v_new)
            form_newton_matrix(packed, controls.analytic_jacobian, t + h, q_new, v_new, latched, slope_q, slope_v,
                               workspace, carry, counters)
            carry.matrix_step[0] = h
            counters[JACOBIANS] += 1
            formed += 1
        previous = np.inf
        for _ in range(ITERATIONS_PER_JACOBIAN):
            _state_of(a, workspace.stage_q, workspace.stage_v, slope_q, slope_v, q_new, v_new)
            # the constraints' multipliers are Newton's unknowns too: no constraint solve per iteration
            supplied, dissipated = accelerations(packed, t + h, q_new, v_new, latched, f, workspace, PARTIAL,
                                                 UNCONSTRAINED)
            counters[EVALUATIONS] += 1
            newton_residual(packed, carry, f, q_new, v_new)
            newton_increment(packed, carry, f, carry.constraint_residual)
            size = 0.0
            for i in range(n):
                a[i] += increment[i]
                size = max(size, abs(slope_q * increment[i]) / (tolerance * (1.0 + abs(q_new[i]))),
                           abs(slope_v * increment[i]) / (tolerance * (1.0 + abs(v_new[i]))))
            counters[NEWTON_ITERATIONS] += 1
            rate = size / previous  # θ; 0 on the first iteration
            if size <= NEWTON_FRACTION or 0.0 < rate < 1.0 and rate / (1.0 - rate) * size <= NEWTON_FRACTION:
                converged = True
                break
            if not size <= CONTRACTIVITY * previous:  # too slow, diverging or not finite
                break
            previous = size
        if converged or formed == JACOBIANS_PER_STEP:
            break
        if not math.isfinite(size):
            copy_into(a, a_old)  # back to the predictor
            copy_into(multiplier, accepted_multiplier)
        form = True
    # the state of the converged a, its last increment included
    _state_of(a, workspace.stage_q, workspace.stage_v, slope_q, slope_v, q_new, v_new)
    if not converged:  # retry at a shorter step
        counters[REJECTED] += 1
        h_adaptive = NEWTON_RETRY * h
        return (STEP_UNDERFLOW if underflows(h_adaptive, t) else RUNNING), False, h_adaptive, 0.0, 0.0
    if not error_control:  # back towards the nominal step after a retry
        h_adaptive = min(RECOVERY * h_adaptive, controls.step)
    else:
        total = 0.0
        for i in range(n):
            error = abs(beta - 1.0 / 6.0) * h * h * (a[i] - a_old[i])
            total += (error / (tolerance * (1.0 + max(abs(q[i]), abs(q_new[i]))))) ** 2
        accepted, underflow, h_adaptive = control_step(controls.step_controller, math.sqrt(total / n), t, h, landing,
                                                       h_adaptive, controls.step)
        if not accepted:
            counters[REJECTED] += 1
            return (STEP_UNDERFLOW if underflow else RUNNING), False, h_adaptive, 0.0, 0.0
    work_supplied = 0.5 * h * (power[0] + supplied)
    work_dissipated = 0.5 * h * (power[1] + dissipated)
    for i in range(n):
        auxiliary[i] = ((1.0 - alpha_f) * a[i] + alpha_f * a_old[i] - alpha_m * auxiliary[i]) / (1.0 - alpha_m)
        a_old[i] = a[i]
    copy_into(accepted_multiplier, multiplier)
    power[0], power[1] = supplied, dissipated
    return RUNNING, True, h_adaptive, work_supplied, work_dissipated
