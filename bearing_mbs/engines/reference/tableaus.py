"""Explicit Runge–Kutta methods as data: a Butcher tableau, checked on construction.

References: classic RK4 (Kutta 1901); Dormand–Prince 5(4) (J. R. Dormand, P. J. Prince, "A family of
embedded Runge–Kutta formulae", J. Comput. Appl. Math. 6 (1980) 19–26), coefficients as published there
and in Hairer, Nørsett & Wanner, Solving ODEs I, table 5.2.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from bearing_mbs.spec import methods


@dataclass(frozen=True)
class ButcherTableau:
    """Explicit RK method: stages ``a`` (strictly lower triangular), weights ``b``, nodes ``c``.

    ``b_error`` are the weights of the embedded solution (empty for fixed-step methods); ``order`` is the
    order of ``b`` (from the method's entry in :mod:`bearing_mbs.spec.methods`, which also holds the order of the
    embedded pair's error estimate, read by the step-size controller). ``fsal``: the last stage
    is evaluated at the new solution and can serve as the next step's first stage.
    """

    name: str
    a: np.ndarray
    b: np.ndarray
    c: np.ndarray
    order: int
    b_error: np.ndarray = field(default_factory=lambda: np.zeros(0))
    fsal: bool = False

    def __post_init__(self):
        s = self.b.size
        if self.a.shape != (s, s) or self.c.size != s:
            raise ValueError(f"{self.name}: a must be {s}×{s} and c of length {s}")
        if np.any(np.triu(self.a) != 0):
            raise ValueError(f"{self.name}: a must be strictly lower triangular (explicit method)")
        if not np.allclose(self.a.sum(axis=1), self.c, atol=1e-14):
            raise ValueError(f"{self.name}: row sums of a must equal c")
        if not np.isclose(self.b.sum(), 1.0, atol=1e-14):
            raise ValueError(f"{self.name}: weights b must sum to 1")
        if self.b_error.size and not np.isclose(self.b_error.sum(), 1.0, atol=1e-14):
            raise ValueError(f"{self.name}: embedded weights must sum to 1")
        if self.fsal and not (np.allclose(self.a[-1], self.b) and self.c[-1] == 1.0):
            raise ValueError(f"{self.name}: FSAL needs the last row of a equal to b and c = 1")

    @property
    def adaptive(self) -> bool:
        return self.b_error.size > 0


RK4 = ButcherTableau(
    name=methods.RK4.name,
    a=np.array([[0, 0, 0, 0], [0.5, 0, 0, 0], [0, 0.5, 0, 0], [0, 0, 1, 0]], dtype=float),
    b=np.array([1 / 6, 1 / 3, 1 / 3, 1 / 6]),
    c=np.array([0, 0.5, 0.5, 1.0]),
    order=methods.RK4.order,
)

DOPRI5 = ButcherTableau(
    name=methods.DOPRI5.name,
    a=np.array(
        [
            [0, 0, 0, 0, 0, 0, 0],
            [1 / 5, 0, 0, 0, 0, 0, 0],
            [3 / 40, 9 / 40, 0, 0, 0, 0, 0],
            [44 / 45, -56 / 15, 32 / 9, 0, 0, 0, 0],
            [19372 / 6561, -25360 / 2187, 64448 / 6561, -212 / 729, 0, 0, 0],
            [9017 / 3168, -355 / 33, 46732 / 5247, 49 / 176, -5103 / 18656, 0, 0],
            [35 / 384, 0, 500 / 1113, 125 / 192, -2187 / 6784, 11 / 84, 0],
        ]
    ),
    b=np.array([35 / 384, 0, 500 / 1113, 125 / 192, -2187 / 6784, 11 / 84, 0]),
    c=np.array([0, 1 / 5, 3 / 10, 4 / 5, 8 / 9, 1, 1]),
    order=methods.DOPRI5.order,
    b_error=np.array([5179 / 57600, 0, 7571 / 16695, 393 / 640, -92097 / 339200, 187 / 2100, 1 / 40]),
    fsal=True,
)

#: Reference-engine method name → tableau, for the Runge–Kutta methods.
TABLEAUS = {tableau.name: tableau for tableau in (RK4, DOPRI5)}
