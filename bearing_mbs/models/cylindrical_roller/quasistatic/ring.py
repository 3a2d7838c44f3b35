r"""Newton–Raphson for the inner-ring displacement under a given load (shared by the planar and sliced models).

The rollers, each in its own equilibrium, exert on the inner ring the generalised force :math:`P(u)` (the
load the ring can carry at displacement :math:`u`) with tangent stiffness :math:`K(u) = \partial P/\partial u`,
symmetric positive semi-definite. Both derive from the potential :math:`\Phi(u) = \sum_j \Phi_j`, the
contact energy of every roller minimised over its own degrees of freedom (and its centrifugal work), so the
equilibrium :math:`P(u) = F` is the minimum of the convex function :math:`\Pi(u) = \Phi(u) - F\cdot u`
(Harris & Kotzalas 2006, ch. 7, solve the same equations by Newton–Raphson without the potential).

Steps:

1. Minimise :math:`\Pi` along the load direction :math:`d` (unit, scaled): :math:`d\cdot(P(a\,d) - F) = 0`
   for the scalar :math:`a`, by bracketed, safeguarded Newton (:func:`.roots.decreasing_root`);
   :math:`d\cdot P(a d)` is non-decreasing in :math:`a` because :math:`K` is positive semi-definite. This
   start has rollers in contact.
2. Full Newton on :math:`u`: :math:`K\,\Delta u = F - P(u)`. The full step is taken when it satisfies the
   Wolfe conditions on :math:`\Pi` (sufficient decrease, or a reduced residual norm, which tolerates
   round-off in :math:`\Pi` near the solution; and a directional derivative reduced by at least 10 %);
   otherwise :math:`\Pi` is minimised along the step as in 1. Where
   :math:`K` is singular (too few rollers in contact to resist some motion, e.g. with clearance, few rollers
   or a large centrifugal force) its eigenvalues are floored (:func:`regularised_solve`), which turns the
   step in those directions into a descent step on :math:`\Pi` until further rollers engage; the step is
   also limited to the current displacement plus the first guess (:data:`STEP_LIMIT`).

Convergence: :math:`\|P - F\| \le` ``tolerance`` :math:`\cdot\max(\|F\|, \sum_j Q_j)`, or a Newton step below
1e-13 of the displacement. The second test ends the loop when the residual is at its round-off floor: with a
clearance much larger than the contact deflection (a light load), the approach :math:`u_r - P_d/2` loses
digits to cancellation, and the attainable relative residual is about :math:`\epsilon\,P_d/\delta`. The
result's ``residual`` reports what was reached.

Coordinates are scaled by ``scale`` (e.g. tilts by half the roller length) so that all components of the
scaled displacement are lengths and all of the scaled force are forces.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Protocol

import numpy as np

from bearing_mbs.models.cylindrical_roller.quasistatic.rollers import ConvergenceError, NewtonSettings
from bearing_mbs.models.cylindrical_roller.quasistatic.roots import decreasing_root

#: Wolfe conditions on the full Newton step: sufficient decrease of Π (ARMIJO) and a directional derivative
#: reduced below CURVATURE times its initial value; otherwise Π is minimised along the step. The second
#: catches steps that are too short, e.g. along a direction no roller resists yet.
ARMIJO = 1e-4
CURVATURE = 0.9
#: Relative accuracy of the line minimisation (it only needs to make progress; Newton does the rest).
LINE_TOLERANCE = 1e-3
MAX_DOUBLINGS = 200
#: Longest Newton step, relative to the current displacement plus the first guess (a crude trust region:
#: with a nearly singular K the floored step can be orders of magnitude too long).
STEP_LIMIT = 1.0
#: A Newton step below this fraction of the displacement is round-off: the loop stops there.
STEP_ROUNDOFF = 1e-13
#: Smallest eigenvalue used in a Newton step, relative to the largest (see :func:`regularised_solve`).
EIGENVALUE_FLOOR = 1e-6


class RingState(Protocol):
    force: np.ndarray  # P(u), shape (m,)
    stiffness: np.ndarray  # K(u), shape (m, m)
    energy: float  # Φ(u) [J]
    load_scale: float  # Σ_j Q_j [N], for the relative tolerance


def solve_ring(
    evaluate: Callable[[np.ndarray], RingState],
    load: np.ndarray,
    scale: np.ndarray,
    first_guess: float,
    settings: NewtonSettings,
) -> tuple[np.ndarray, RingState, int, float]:
    """Displacement u with P(u) = load; returns ``(u, state, iterations, residual)``, residual in scaled [N].

    ``first_guess`` [m] is a rough scaled displacement magnitude along the load that starts the bracket.
    """
    load_scaled = load / scale
    magnitude = float(np.linalg.norm(load_scaled))
    iterations = 0
    u = np.zeros_like(load)
    if magnitude > 0.0:
        direction = load_scaled / magnitude
        a, state, iterations = _minimise_along(evaluate, u, direction, scale, load_scaled, first_guess, settings)
        u = a * direction / scale
    else:
        state = evaluate(u)
    residual = _residual(state, load_scaled, scale)
    tolerance = settings.tolerance * max(magnitude, state.load_scale)
    while residual > tolerance:
        gradient = state.force / scale - load_scaled
        step = -regularised_solve(state.stiffness / np.outer(scale, scale), gradient)
        reach = STEP_LIMIT * (np.linalg.norm(u * scale) + first_guess)
        step *= min(1.0, reach / max(np.linalg.norm(step), np.finfo(float).tiny))
        if np.linalg.norm(step) <= STEP_ROUNDOFF * np.linalg.norm(u * scale):
            break  # the residual is at the round-off level of the approaches (see the module notes)
        if iterations >= settings.max_iterations:
            raise ConvergenceError("max_iterations", iterations, residual, tolerance, "the inner-ring displacement")
        iterations += 1
        trial_u = u + step / scale
        trial = evaluate(trial_u)
        trial_residual = _residual(trial, load_scaled, scale)
        potential, trial_potential = state.energy - load @ u, trial.energy - load @ trial_u
        roundoff = 1e-13 * (abs(state.energy) + abs(load @ u))
        slope, trial_slope = gradient @ step, step @ (trial.force / scale - load_scaled)
        decreases = (
            trial_potential <= potential + ARMIJO * slope + roundoff or trial_residual <= (1 - ARMIJO) * residual
        )
        if not (decreases and trial_slope >= CURVATURE * slope):
            alpha, trial, _ = _minimise_along(evaluate, u, step, scale, load_scaled, 1.0, settings)
            trial_u = u + alpha * step / scale
            trial_residual = _residual(trial, load_scaled, scale)
        u, state, residual = trial_u, trial, trial_residual
        tolerance = settings.tolerance * max(magnitude, state.load_scale)
    return u, state, iterations, residual


def _minimise_along(evaluate, origin, direction, scale, load_scaled, first_step, settings):
    r"""Minimise the convex :math:`\Pi(u_0 + a\,d)` over :math:`a \ge 0` (scaled direction :math:`d`):
    its derivative :math:`h(a) = d\cdot(P - F)` is non-decreasing, so :math:`h(a) = 0` is found by bracketed,
    safeguarded Newton with :math:`h' = d^T K d`. Returns ``(a, state at a, iterations)``."""
    states = {}

    def derivative(a):
        a = float(a)
        states[a] = state = evaluate(origin + a * direction / scale)
        curvature = direction @ (state.stiffness / np.outer(scale, scale)) @ direction
        return np.asarray(-direction @ (state.force / scale - load_scaled)), np.asarray(-curvature)

    upper = max(first_step, np.finfo(float).tiny)
    for _ in range(MAX_DOUBLINGS):
        if derivative(upper)[0] <= 0.0:
            break
        upper *= 2.0
    a, iterations = decreasing_root(
        derivative,
        np.asarray(0.0),
        np.asarray(upper),
        np.asarray(upper),
        tolerance=LINE_TOLERANCE,
        max_iterations=settings.max_iterations,
        field="max_iterations",
        what="the inner-ring displacement along a search direction",
    )
    a = float(a)
    return a, states[a] if a in states else evaluate(origin + a * direction / scale), iterations


def regularised_solve(matrix: np.ndarray, rhs: np.ndarray) -> np.ndarray:
    """Solve with symmetric positive semi-definite ``matrix`` (..., m, m), its eigenvalues floored at
    ``EIGENVALUE_FLOOR`` times the largest (a modified Newton step; exact where the matrix is well conditioned).
    A zero matrix gives a zero step."""
    values, vectors = np.linalg.eigh(matrix)
    largest = np.max(np.abs(values), axis=-1, keepdims=True)
    values = np.where(largest > 0.0, np.maximum(values, EIGENVALUE_FLOOR * largest), np.inf)
    projected = np.einsum("...ji,...j->...i", vectors, rhs) / values
    return np.einsum("...ij,...j->...i", vectors, projected)


def _residual(state: RingState, load_scaled: np.ndarray, scale: np.ndarray) -> float:
    return float(np.linalg.norm(state.force / scale - load_scaled))
