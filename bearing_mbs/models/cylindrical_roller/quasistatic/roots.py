"""Roots of monotone scalar functions, many at once: Newton's method safeguarded by bisection.

The function is non-increasing on a bracket ``[lower, upper]`` with ``f(lower) >= 0 >= f(upper)``. Each
iteration takes the Newton step and falls back to bisection when the step leaves the current bracket or the
derivative vanishes (``rtsafe``, Press et al., *Numerical Recipes*, 3rd ed., 2007, §9.4). The bracket
shrinks at every iteration, so the loop cannot diverge, and converges quadratically once Newton takes over.
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np

from bearing_mbs.models.cylindrical_roller.quasistatic.rollers import ConvergenceError


def decreasing_root(
    func: Callable[[np.ndarray], tuple[np.ndarray, np.ndarray]],
    lower: np.ndarray,
    upper: np.ndarray,
    start: np.ndarray,
    *,
    tolerance: float,
    max_iterations: int,
    field: str,
    what: str,
    residual_scale: Callable[[np.ndarray], np.ndarray] | None = None,
) -> tuple[np.ndarray, int]:
    r"""Solve :math:`f(x) = 0` element-wise for a non-increasing :math:`f`; returns ``(x, iterations)``.

    ``func(x)`` returns :math:`(f, f')` with the shape of ``x``. ``start`` is clipped into the bracket.
    Converged where the Newton or bisection step is below ``tolerance`` times the bracket's initial width
    (times :math:`|x|` when larger), or :math:`f = 0`. Raises :class:`ConvergenceError` (``field``) after
    ``max_iterations``; the reported residual is :math:`\max|f|` times ``residual_scale`` if given.
    """
    lower = np.array(lower, dtype=float)
    upper = np.array(upper, dtype=float)
    x = np.clip(np.array(start, dtype=float), lower, upper)
    width = upper - lower
    active = width > 0.0
    for iteration in range(1, max_iterations + 1):
        value, slope = func(x)
        lower = np.where(value > 0.0, x, lower)
        upper = np.where(value < 0.0, x, upper)
        with np.errstate(divide="ignore", invalid="ignore"):
            newton = x - value / slope
        inside = (slope < 0.0) & (newton > lower) & (newton < upper)
        candidate = np.where(inside, newton, 0.5 * (lower + upper))
        step = np.abs(candidate - x)
        done = (value == 0.0) | (step <= tolerance * np.maximum(width, np.abs(x)))
        x = np.where(active & (value != 0.0), candidate, x)
        active &= ~done
        if not active.any():
            return x, iteration
    value, _ = func(x)
    residual = float(np.max(np.abs(value) * (1.0 if residual_scale is None else residual_scale(x))))
    raise ConvergenceError(field, max_iterations, residual, tolerance, what, "relative to the step")
