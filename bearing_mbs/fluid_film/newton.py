r"""The film's balance by Newton's method globalised by a line search: the fall-back of
:func:`.reynolds.solve_film` where its own iterations (the primal–dual active set of the mass-conserving film, the
restrictors' Newton loop) cycle, meet a singular system or do not settle. An orifice's inflow ∝ √|p_s − p| is such a
case: undamped Newton steps on a square root overshoot the root by as much as they started from it, forever.

Full film (Gümbel): the unknowns are the pressures p [Pa], the equations each cell's balance A p + c − q(p) = 0
(:class:`.reynolds._Balance`; q the restrictors' inflow).

Mass-conserving film (JFO): the semismooth Newton method on the Fischer–Burmeister function.
Unknowns: each cell's pressure p ≥ 0 [Pa] and void fraction v = 1 − ϑ ≥ 0, with p v = 0 (M. Giacopini et al.,
J. Tribol. 132 (2010) 041702). Equations: each cell's balance A p + B v + c − q(p) = 0 (:class:`.reynolds._Balance`;
q the restrictors' inflow), and φ(p/P, v) = 0 with the Fischer–Burmeister function
:math:`\varphi(a, b) = a + b - \sqrt{a^2 + b^2}`, zero exactly where a ≥ 0, b ≥ 0 and a b = 0. The pressure is taken
in units of a scale P and each balance row is divided by its own size, so that both halves of F are of order one.
Newton's step on F is damped until the merit Ψ = ½|F|² falls by Armijo's rule (T. De Luca, F. Facchinei,
C. Kanzow, "A semismooth equation approach to the solution of nonlinear complementarity problems", Math. Program. 75
(1996) 407–439); where the Newton matrix is singular the step is Levenberg–Marquardt's. The full film is the same
iteration on the balance alone.
"""

from __future__ import annotations

import warnings
from collections.abc import Callable

import numpy as np
import scipy.sparse as sp
from scipy.sparse.linalg import MatrixRankWarning, spsolve

#: Armijo's sufficient-decrease parameter [-] and the smallest damping of a step tried.
ARMIJO, SMALLEST_DAMPING = 1e-4, 2.0**-40
#: Solved when every scaled equation is below this [-]; or below ROUND_OFF where no step lowers the merit any more
#: (an ill-conditioned system's round-off floor: a relative mass-balance error of 1e-8).
TOLERANCE, ROUND_OFF = 1e-11, 1e-8
#: Newton iterations before giving up.
ITERATIONS = 300
#: Levenberg–Marquardt's regularisation, relative to the largest diagonal entry of JᵀJ.
REGULARISATION = 1e-10
#: φ's gradient (1 − a/r, 1 − b/r) at a = b = 0, where it is not defined: the value along a = b (any element of its
#: generalised gradient will do).
_KINK = 1.0 - 1.0 / np.sqrt(2.0)


def solve_balance(pressure_flux: sp.spmatrix, fill_flux: sp.spmatrix, constant: np.ndarray,
                  inflow: Callable[[np.ndarray], tuple[np.ndarray, np.ndarray]], fixed: np.ndarray,
                  fixed_pressure: float, start: np.ndarray, scale: float,
                  cavitating: bool) -> tuple[np.ndarray, np.ndarray] | None:
    """(p [Pa], v [-]) of every unknown, or None if Newton's method does not get there in :data:`ITERATIONS`.

    ``inflow(p) -> (q, dq/dp)`` of every unknown (zero on the lands); ``fixed`` unknowns (recesses held at the
    supply pressure) are ``fixed_pressure`` [Pa] with v = 0; ``start`` [Pa] is the first pressure field and ``scale``
    [Pa] > 0 the pressure unit P. ``cavitating``: the mass-conserving film (p ≥ 0, v ≥ 0, p v = 0; the start's
    negative part dropped), else the full film (v = 0, p of any sign)."""
    a = (np.maximum(start, 0.0) if cavitating else np.asarray(start, dtype=float).copy()) / scale
    v = np.zeros_like(a)
    a[fixed] = fixed_pressure / scale
    pressure_flux, fill_flux = sp.csr_matrix(pressure_flux), sp.csr_matrix(fill_flux)
    slope = inflow(a * scale)[1]
    size = (abs(pressure_flux).sum(axis=1).A1 + np.abs(slope)) * scale + abs(fill_flux).sum(axis=1).A1 \
        + np.abs(constant)
    rows = 1.0 / np.where(size > 0, size, 1.0)

    def residual(a, v):
        q, _ = inflow(a * scale)
        balance = rows * (pressure_flux @ (a * scale) + fill_flux @ v + constant - q)
        balance[fixed] = a[fixed] - fixed_pressure / scale
        if not cavitating:
            return balance
        complementarity = a + v - np.hypot(a, v)
        complementarity[fixed] = v[fixed]
        return np.concatenate([balance, complementarity])

    free = sp.diags((~fixed).astype(float))
    pinned = sp.diags(fixed.astype(float))

    def solution(a, v):
        if not cavitating:
            return np.where(fixed, fixed_pressure, a * scale), v
        full = (a >= v) | fixed  # each cell on its side of φ = 0, where round-off leaves both a little above 0
        return np.where(fixed, fixed_pressure, np.where(full, np.maximum(a, 0.0) * scale, 0.0)), \
            np.where(full, 0.0, np.maximum(v, 0.0))

    merit = 0.5 * np.sum(residual(a, v) ** 2)
    for _ in range(ITERATIONS):
        f = residual(a, v)
        if np.abs(f).max() <= TOLERANCE:
            return solution(a, v)
        _, slope = inflow(a * scale)
        balance_by_a = free @ sp.diags(rows) @ (pressure_flux - sp.diags(slope)) * scale + pinned
        if cavitating:
            radius = np.hypot(a, v)
            by_a = np.where(radius > 0, 1.0 - a / np.where(radius > 0, radius, 1.0), _KINK)
            by_v = np.where(radius > 0, 1.0 - v / np.where(radius > 0, radius, 1.0), _KINK)
            jacobian = sp.bmat([[balance_by_a, free @ sp.diags(rows) @ fill_flux],
                                [sp.diags(np.where(fixed, 0.0, by_a)), sp.diags(np.where(fixed, 1.0, by_v))]])
            step = _newton_step(jacobian.tocsc(), f)
        else:
            step = np.concatenate([_newton_step(balance_by_a.tocsc(), f), np.zeros_like(v)])
        a, v, merit, found = _line_search(residual, a, v, step, merit)
        if not found:
            return solution(a, v) if np.abs(f).max() <= ROUND_OFF else None
    return None


def _line_search(residual, a, v, step, merit):
    """(a, v, merit, True) after the longest step of 1, 1/2, 1/4, ... that lowers the merit ½|F|² by Armijo's rule,
    or (…, False) if none down to :data:`SMALLEST_DAMPING` does."""
    damping = 1.0
    while damping >= SMALLEST_DAMPING:
        trial_a, trial_v = a + damping * step[: a.size], v + damping * step[a.size:]
        trial = 0.5 * np.sum(residual(trial_a, trial_v) ** 2)
        if np.isfinite(trial) and trial <= (1.0 - 2.0 * ARMIJO * damping) * merit:
            return trial_a, trial_v, trial, True
        damping /= 2
    return a, v, merit, False


def _newton_step(jacobian: sp.csc_matrix, f: np.ndarray) -> np.ndarray:
    """Newton's step −J⁻¹F, or Levenberg–Marquardt's −(JᵀJ + λI)⁻¹JᵀF where J is singular."""
    with warnings.catch_warnings():
        warnings.simplefilter("error", MatrixRankWarning)
        try:
            step = spsolve(jacobian, -f)
            if np.all(np.isfinite(step)):
                return step
        except MatrixRankWarning:
            pass
    normal = (jacobian.T @ jacobian).tocsc()
    regularisation = REGULARISATION * max(normal.diagonal().max(), np.finfo(float).tiny)
    return spsolve(normal + regularisation * sp.identity(f.size, format="csc"), -(jacobian.T @ f))
