"""Butcher tableaus of Exudyn's explicit solvers, as data: name → (rows of A below the diagonal, weights b).

The coefficients are those Exudyn's own source defines for its explicit solvers (``CSolverExplicit.cpp``,
``ComputeButcherTableau``; the solver types are listed in the Exudyn documentation under
``DynamicSolverType``): explicit Euler, the explicit midpoint rule, Heun's third-order RK33, the classical RK44,
Butcher's 7-stage sixth-order RK67, and the third-order solution of Bogacki–Shampine's ODE23 (P. Bogacki,
L. F. Shampine, "A 3(2) pair of Runge–Kutta formulas", Appl. Math. Lett. 2 (1989) 321–325). Exudyn's DOPRI5 uses
the Dormand–Prince weights of :data:`bearing_mbs.engines.reference.tableaus.DOPRI5`, so it is not repeated here.

Row ``i`` lists :math:`a_{i,0}, \\dots, a_{i,i-1}`; the first row is empty (explicit methods).
"""

from __future__ import annotations

import math

from bearing_mbs.spec import methods

_SQRT5 = math.sqrt(5.0)

#: Exudyn method name → (rows of A, b).
EXUDYN_TABLEAUS: dict[str, tuple[tuple[tuple[float, ...], ...], tuple[float, ...]]] = {
    methods.EXPLICIT_EULER.name: (((),), (1.0,)),
    methods.EXPLICIT_MIDPOINT.name: (((), (0.5,)), (0.0, 1.0)),
    methods.RK33.name: (((), (1 / 3,), (0.0, 2 / 3)), (0.25, 0.0, 0.75)),
    methods.RK4.name: (((), (0.5,), (0.0, 0.5), (0.0, 0.0, 1.0)), (1 / 6, 1 / 3, 1 / 3, 1 / 6)),
    methods.RK67.name: (
        (
            (),
            (0.5 - _SQRT5 / 10,),
            (-_SQRT5 / 10, 0.5 + _SQRT5 / 5),
            (7 * _SQRT5 / 20 - 0.75, _SQRT5 / 4 - 0.25, 1.5 - 7 * _SQRT5 / 10),
            (1 / 12 - _SQRT5 / 60, 0.0, 1 / 6, 7 * _SQRT5 / 60 + 0.25),
            (_SQRT5 / 60 + 1 / 12, 0.0, 0.75 - 5 * _SQRT5 / 12, 1 / 6, -0.5 + 3 * _SQRT5 / 10),
            (1 / 6, 0.0, -55 / 12 + 25 * _SQRT5 / 12, -7 * _SQRT5 / 12 - 25 / 12, 5 - 2 * _SQRT5, 2.5 + _SQRT5 / 2),
        ),
        (1 / 12, 0.0, 0.0, 0.0, 5 / 12, 5 / 12, 1 / 12),
    ),
    methods.ODE23.name: (((), (0.5,), (0.0, 0.75), (2 / 9, 1 / 3, 4 / 9)), (2 / 9, 1 / 3, 4 / 9, 0.0)),
}

#: Exudyn methods whose tableau is the reference engine's of the same name.
SHARED_WITH_REFERENCE = (methods.DOPRI5.name,)
