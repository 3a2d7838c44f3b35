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

**Newton.** The unknown is :math:`a = a_{n+1}`; :math:`q_{n+1}` and :math:`v_{n+1}` are linear in it with
slopes :math:`\beta' = h^2\beta(1-\alpha_f)/(1-\alpha_m)` and :math:`\gamma' = h\gamma(1-\alpha_f)/(1-\alpha_m)`.
The residual :math:`r(a) = a - f(q(a), v(a))` has the Jacobian
:math:`J = I - P M^{-1}(\beta' K + \gamma' C)`, with :math:`K = \partial F/\partial q` and
:math:`C = \partial F/\partial v` (:func:`bearing_mbs.elements.element_jacobian`) and the constraints'
projection :math:`P M^{-1} = M^{-1} - M^{-1}G^T(GM^{-1}G^T)^{-1}GM^{-1}` (the terms in :math:`\partial G/\partial
q` are left out: they scale with the forces, not with their stiffness). A scene with a force element registered
from outside, which has no analytic Jacobian, gets J by forward differences of f (2n evaluations). J is formed and
inverted at the start of each step (modified Newton) and again when Newton stalls; the iteration stops when
every coordinate's increment of position and velocity is below :data:`NEWTON_FRACTION` of its tolerance scale.

**Error and step control** (``generalized_alpha_adaptive``). The local error of the positions is estimated as
:math:`e = (\beta - \tfrac16) h^2 (a_{n+1} - a_n)` (Zienkiewicz & Xie 1991, the Newmark family's leading term
:math:`(\beta - \tfrac16) h^3 \dddot q`); its RMS norm, each coordinate scaled by tolerance·(1 + max(|q_n|,
|q_{n+1}|)), must be ≤ 1, and the next step is :math:`h \min(2, \max(0.2, 0.9\,\mathrm{err}^{-1/3}))`, capped by
``step``. A step whose Newton iteration fails is retried at half of it, in both forms; the fixed-step form
then doubles its step back to the nominal one, as Exudyn's does. J is reused from step to step while Newton
converges fast and the step stays within :data:`REUSE_RATIO` of the one it was formed for. The work is integrated
with the trapezoid rule over the step's end powers.
"""

from __future__ import annotations

import math

import numba
import numpy as np

from bearing_mbs.elements import element_jacobian
from bearing_mbs.engines.reference.codes import (
    EVALUATIONS,
    JACOBIANS,
    NEWTON_ITERATIONS,
    REJECTED,
    RUNNING,
    STEP_UNDERFLOW,
)
from bearing_mbs.engines.reference.constraints import constraint_rows
from bearing_mbs.engines.reference.dynamics import accelerations

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


@numba.njit(cache=True)
def coefficients(spectral_radius):
    """(α_m, α_f, γ, β) of generalized-α with high-frequency spectral radius ρ∞ (Chung & Hulbert 1993)."""
    alpha_m = (2.0 * spectral_radius - 1.0) / (spectral_radius + 1.0)
    alpha_f = spectral_radius / (spectral_radius + 1.0)
    gamma = 0.5 + alpha_f - alpha_m
    return alpha_m, alpha_f, gamma, 0.25 * (gamma + 0.5) ** 2


@numba.njit(cache=True)  # not inlined: one compiled copy of the force kernels serves every call below
def _evaluate(packed, t, q, v, latched, a, workspace, counters, complete=False):
    counters[EVALUATIONS] += 1
    return accelerations(packed, t, q, v, latched, a, workspace.forces, workspace.pair_out,
                         workspace.constraint_forces, complete)


@numba.njit(cache=True)
def _projected_inverse_mass(packed, q, v):
    """P M⁻¹ (n × n) of a scene with constraints: the inverse mass, less what the constraints take."""
    n, count = q.size, packed.constraints.kind.size
    residual, gamma = np.empty(count), np.empty(count)
    rows = np.empty((count, n))
    constraint_rows(packed.constraints, q, v, residual, rows, gamma)
    weighted = rows * packed.inverse_mass  # G M⁻¹
    return np.diag(packed.inverse_mass) - weighted.T @ np.linalg.solve(weighted @ rows.T, weighted)


@numba.njit(cache=True)
def newton_matrix_inverse(packed, analytic, t, q, v, latched, slope_q, slope_v, workspace, carry, counters):
    """J⁻¹ with J = I − (β' ∂f/∂q + γ' ∂f/∂v) at (t, q, v), into ``carry.inverse``."""
    n = q.size
    jacobian = carry.jacobian
    if analytic:  # the complete pair outputs the Jacobian reads
        _evaluate(packed, t, q, v, latched, workspace.acceleration, workspace, counters, True)
        element_jacobian(packed.elements, t, q, v, latched, workspace.pair_out, carry.stiffness, carry.damping)
        stiffness = slope_q * carry.stiffness + slope_v * carry.damping
        if packed.constraints.kind.size > 0:
            jacobian[:, :] = -(_projected_inverse_mass(packed, q, v) @ stiffness)
        else:  # M⁻¹ is diagonal: scale the rows
            for i in range(n):
                jacobian[i, :] = -packed.inverse_mass[i] * stiffness[i, :]
    else:  # forward differences of f: a registered kind without an analytic Jacobian
        base, shifted = carry.base, workspace.acceleration
        _evaluate(packed, t, q, v, latched, base, workspace, counters)
        for j in range(2 * n):
            column = j % n
            x = q if j < n else v
            saved = x[column]
            delta = DIFFERENCE_STEP * max(1.0, abs(saved))
            x[column] = saved + delta
            _evaluate(packed, t, q, v, latched, shifted, workspace, counters)
            x[column] = saved
            slope = slope_q if j < n else slope_v
            for i in range(n):
                jacobian[i, column] = (jacobian[i, column] if j >= n else 0.0) - slope * (shifted[i] - base[i]) / delta
    for i in range(n):
        jacobian[i, i] += 1.0
    carry.inverse[:, :] = np.linalg.inv(jacobian)


@numba.njit(cache=True, inline="always")
def _state_of(workspace, carry, slope_q, slope_v):
    """q_{n+1}, v_{n+1} of the current iterate a = ``carry.unknown``, into ``workspace.q_new``, ``workspace.v_new``."""
    for i in range(carry.unknown.size):
        workspace.q_new[i] = workspace.stage_q[i] + slope_q * carry.unknown[i]
        workspace.v_new[i] = workspace.stage_v[i] + slope_v * carry.unknown[i]


@numba.njit(cache=True, inline="always")
def _form_at(packed, controls, t, h, state, carry, workspace, counters, slope_q, slope_v):
    """J⁻¹ at the current iterate (q, v of ``carry.unknown``), for steps of h."""
    _state_of(workspace, carry, slope_q, slope_v)
    newton_matrix_inverse(packed, controls.analytic_jacobian, t + h, workspace.q_new, workspace.v_new, state.latched,
                          slope_q, slope_v, workspace, carry, counters)
    carry.matrix_step[0] = h
    counters[JACOBIANS] += 1


@numba.njit(cache=True)
def generalized_alpha_step(packed, controls, error_control, t, h, landing, h_adaptive, state, carry, ready, workspace,
                           counters):
    """One attempt of a step from t to t + h into ``workspace.q_new``, ``workspace.v_new``; ``ready``: ``carry``
    holds a(q, v) and the power of the current state. ``landing``: t + h is an output instant; ``h_adaptive``
    [s]: the current adaptive step.

    Returns (status, accepted, h_adaptive, work_supplied, work_dissipated). An accepted step leaves the new
    state's acceleration, auxiliary acceleration and power in ``carry``; a rejected one leaves ``carry`` as it
    was, with a smaller ``h_adaptive`` (``STEP_UNDERFLOW`` below 1e-14 of t). ``error_control``: accept by the
    error estimate and propose the next step from it (else by Newton's convergence alone).
    """
    q, v, latched = state.q, state.v, state.latched
    q_new, v_new, f = workspace.q_new, workspace.v_new, workspace.acceleration
    a_old, auxiliary, power, a, increment = carry.acceleration, carry.auxiliary, carry.power, carry.unknown, \
        carry.increment
    n = q.size
    tolerance = controls.tolerance
    if not ready:
        power[0], power[1] = _evaluate(packed, t, q, v, latched, a_old, workspace, counters)
        if carry.started[0] == 0:  # ã_0 = a_0
            auxiliary[:] = a_old
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
    supplied = dissipated = 0.0
    formed, converged = 0, False
    if not 1.0 / REUSE_RATIO <= h / carry.matrix_step[0] <= REUSE_RATIO:  # J of another step: form it
        _form_at(packed, controls, t, h, state, carry, workspace, counters, slope_q, slope_v)
        formed = 1
    while True:
        previous = np.inf
        for _ in range(ITERATIONS_PER_JACOBIAN):
            _state_of(workspace, carry, slope_q, slope_v)
            supplied, dissipated = _evaluate(packed, t + h, q_new, v_new, latched, f, workspace, counters)
            for i in range(n):
                f[i] = a[i] - f[i]  # the residual
            increment[:] = -(carry.inverse @ f)
            size = 0.0
            for i in range(n):
                a[i] += increment[i]
                size = max(size, abs(slope_q * increment[i]) / (tolerance * (1.0 + abs(q_new[i]))),
                           abs(slope_v * increment[i]) / (tolerance * (1.0 + abs(v_new[i]))))
            counters[NEWTON_ITERATIONS] += 1
            if size <= NEWTON_FRACTION:
                converged = True
                break
            if not size <= CONTRACTIVITY * previous:  # too slow, diverging or not finite
                break
            previous = size
        if converged or formed == JACOBIANS_PER_STEP:
            break
        if not math.isfinite(size):
            a[:] = a_old  # back to the predictor
        _form_at(packed, controls, t, h, state, carry, workspace, counters, slope_q, slope_v)
        formed += 1
    _state_of(workspace, carry, slope_q, slope_v)  # the state of the converged a, its last increment included
    if not converged:  # retry at half the step
        counters[REJECTED] += 1
        h_adaptive = 0.5 * h
        return (STEP_UNDERFLOW if h_adaptive < 1e-14 * max(1.0, abs(t)) else RUNNING), False, h_adaptive, 0.0, 0.0
    if not error_control:  # back towards the nominal step after a retry
        h_adaptive = min(2.0 * h_adaptive, controls.step)
    else:
        total = 0.0
        for i in range(n):
            error = abs(beta - 1.0 / 6.0) * h * h * (a[i] - a_old[i])
            total += (error / (tolerance * (1.0 + max(abs(q[i]), abs(q_new[i]))))) ** 2
        error = math.sqrt(total / n)
        factor = min(2.0, max(0.2, 0.9 * error ** (-1.0 / 3.0))) if error > 0 else 2.0
        if not error <= 1.0:
            counters[REJECTED] += 1
            h_adaptive = h * factor if math.isfinite(error) else 0.2 * h
            return (STEP_UNDERFLOW if h_adaptive < 1e-14 * max(1.0, abs(t)) else RUNNING), False, h_adaptive, 0.0, \
                0.0
        proposal = max(h * factor, h_adaptive) if landing else h * factor
        h_adaptive = min(proposal, controls.step)
    work_supplied = 0.5 * h * (power[0] + supplied)
    work_dissipated = 0.5 * h * (power[1] + dissipated)
    for i in range(n):
        auxiliary[i] = ((1.0 - alpha_f) * a[i] + alpha_f * a_old[i] - alpha_m * auxiliary[i]) / (1.0 - alpha_m)
        a_old[i] = a[i]
    power[0], power[1] = supplied, dissipated
    return RUNNING, True, h_adaptive, work_supplied, work_dissipated
