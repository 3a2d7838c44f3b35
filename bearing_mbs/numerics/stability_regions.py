r"""Stability regions of the explicit integrators on the linear test equation :math:`\ddot q = \alpha q + \beta\dot q`.

A linearised mode with :math:`\alpha = -\omega^2`, :math:`\beta = -2\sigma` (a pure decay: :math:`\alpha = 0`,
:math:`\beta = -\lambda`) is stable under a step :math:`h` when:

* Runge–Kutta methods, acting on :math:`(q, \dot q)`: :math:`|R(hs)| \le 1` for both roots :math:`s` of
  :math:`s^2 - \beta s - \alpha`, with the stability polynomial :math:`R(z) = 1 + \sum_{k \ge 1} z^k\,
  b^T A^{k-1}\mathbb 1` of the tableau (E. Hairer, G. Wanner, Solving Ordinary Differential Equations II, §IV.2).
  On the negative real axis RK4 reaches :math:`h\lambda = 2.785`, DOPRI5 3.307; on the imaginary axis RK4 reaches
  :math:`h\omega = 2\sqrt2` (:func:`axis_limits`).
* The reference engine's second-order schemes, through their amplification matrices: the central difference
  (:math:`v_{n+1} = v_n + h f(q_n, v_n)`, :math:`q_{n+1} = q_n + h v_{n+1}`): :math:`h\omega < 2`,
  :math:`h\lambda < 2`; velocity Verlet (forces at the predicted velocity :math:`v_n + h a_n`, reused as the next
  step's start): :math:`h\omega < 2`, but :math:`h\lambda < 1` for a pure decay (its amplification matrix has
  the eigenvalue −1 at :math:`h\lambda = 1`).

Implicit methods (generalized-alpha, trapezoidal) have no limit on this test (:data:`IMPLICIT`).
"""

from __future__ import annotations

import functools
import math

import numpy as np

from bearing_mbs.engines.reference.tableaus import TABLEAUS
from bearing_mbs.numerics.exudyn_tableaus import EXUDYN_TABLEAUS, SHARED_WITH_REFERENCE
from bearing_mbs.spec import methods
from bearing_mbs.spec.methods import EXUDYN, REFERENCE


def _matrix(rows, weights) -> tuple[np.ndarray, np.ndarray]:
    """(A, b) arrays of a tableau given as rows below the diagonal."""
    a = np.zeros((len(weights), len(weights)))
    for i, row in enumerate(rows):
        a[i, : len(row)] = row
    return a, np.array(weights, dtype=float)


#: Explicit Runge–Kutta tableaus (A, b) by "engine/method".
RK_TABLEAUS: dict[str, tuple[np.ndarray, np.ndarray]] = {
    **{methods.key(EXUDYN, name): _matrix(*tableau) for name, tableau in EXUDYN_TABLEAUS.items()},
    **{methods.key(REFERENCE, name): (tableau.a, tableau.b) for name, tableau in TABLEAUS.items()},
    **{methods.key(EXUDYN, name): (TABLEAUS[name].a, TABLEAUS[name].b) for name in SHARED_WITH_REFERENCE},
}
#: The reference engine's central difference and velocity Verlet.
_CENTRAL_DIFFERENCE = methods.CENTRAL_DIFFERENCE.key(REFERENCE)
_VELOCITY_VERLET = methods.VELOCITY_VERLET.key(REFERENCE)
#: Second-order schemes of the reference engine, checked through their amplification matrices.
SECOND_ORDER = (_CENTRAL_DIFFERENCE, _VELOCITY_VERLET)
#: Methods with no stability limit on the linear test equation: Exudyn's implicit ones (the catalogue's).
IMPLICIT = tuple(method.key(EXUDYN) for method in methods.ENGINE_METHODS[EXUDYN] if method.implicit)
#: Methods with no formula here (Exudyn's velocity Verlet and DVERK6 are not Butcher-tableau solvers we could
#: check).
UNKNOWN = (methods.VELOCITY_VERLET.key(EXUDYN), methods.DVERK6.key(EXUDYN))

#: Slack on |amplification| <= 1 for round-off [-].
_TOLERANCE = 1e-9


def stability_polynomial(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    r"""Coefficients :math:`c_k` of :math:`R(z) = \sum_k c_k z^k` of an explicit Runge–Kutta tableau."""
    ones = np.ones(b.size)
    coefficients, power = [1.0], ones
    for _ in range(b.size):
        coefficients.append(float(b @ power))
        power = a @ power
    return np.array(coefficients)


@functools.cache
def _polynomial(method: str) -> np.ndarray:
    return stability_polynomial(*RK_TABLEAUS[method])


def _first_exit(low: float, high: float, inside, points: int = 800) -> float:
    """Largest x in [low, high] before ``inside(x)`` (vectorised) first turns False on a geometric grid, refined
    on finer grids (relative precision ~1e-9); inf if it never does, 0 if it already fails at ``low``."""
    grid = np.geomspace(low, high, points)
    for _ in range(5):
        outside = np.flatnonzero(~inside(grid))
        if outside.size == 0:
            return math.inf if grid[-1] >= high else float(grid[-1])
        k = int(outside[0])
        if k == 0:
            return 0.0 if grid[0] <= low else float(grid[0])
        grid = np.linspace(grid[k - 1], grid[k], 100)
    return float(grid[0])


def rk_ray_limit(method: str, angle: float) -> float:
    """Largest r with |R(ρ e^{iθ})| <= 1 for all ρ <= r (θ = ``angle`` [rad], π is the negative real axis)."""
    coefficients = _polynomial(method)[::-1]
    direction = complex(math.cos(angle), math.sin(angle))

    def inside(radius):
        return np.abs(np.polyval(coefficients, radius * direction)) <= 1.0 + _TOLERANCE

    return _first_exit(1e-3, 20.0, inside)


def amplification_matrix(method: str, h, alpha: float, beta: float) -> np.ndarray:
    r"""One step of a reference second-order scheme on :math:`\ddot q = \alpha q + \beta\dot q`, as a matrix
    (a stack of matrices for an array of steps ``h`` [s])."""
    h = np.asarray(h, dtype=float)
    one = np.ones_like(h)
    if method == _CENTRAL_DIFFERENCE:  # state (q, v)
        rows = [[1 + h * h * alpha, h + h * h * beta], [h * alpha, 1 + h * beta]]
    elif method == _VELOCITY_VERLET:  # state (q, v, a): a is the stored acceleration
        a1 = [alpha * one, alpha * h + beta, alpha * h * h / 2 + beta * h]
        rows = [[one, h, h * h / 2], [h * a1[0] / 2, 1 + h * a1[1] / 2, h / 2 + h * a1[2] / 2], a1]
    else:
        raise ValueError(f"{method!r} is not a second-order scheme of the reference engine")
    return np.moveaxis(np.array([[np.broadcast_to(x, h.shape) for x in row] for row in rows]), (0, 1), (-2, -1))


@functools.lru_cache(maxsize=4096)
def mode_limit(method: str, alpha: float, beta: float) -> float:
    r"""Largest stable step [s] of ``method`` on :math:`\ddot q = \alpha q + \beta\dot q` (inf: no limit);
    ``alpha`` [1/s²], ``beta`` [1/s]."""
    roots = np.roots([1.0, -beta, -alpha])
    scale = float(np.max(np.abs(roots)))
    if scale == 0.0:
        return math.inf
    if method in RK_TABLEAUS:
        return min(rk_ray_limit(method, math.atan2(s.imag, s.real)) / abs(s) for s in roots
                   if abs(s) > 1e-12 * scale)
    if method in SECOND_ORDER:
        def inside(x):
            radius = np.abs(np.linalg.eigvals(amplification_matrix(method, x / scale, alpha, beta))).max(axis=-1)
            return radius <= 1.0 + _TOLERANCE

        return _first_exit(1e-3, 20.0, inside, points=400) / scale
    raise ValueError(f"no stability formula for {method!r}")


def axis_limits(method: str) -> dict:
    """hλ on the negative real axis (a pure decay) and hω on the imaginary axis (an undamped oscillation) [-]."""
    return {"real": mode_limit(method, 0.0, -1.0), "imaginary": mode_limit(method, -1.0, 0.0)}
