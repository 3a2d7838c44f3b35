"""The solvers the stability suite probes (:mod:`bearing_mbs.studies.stability`): the full and the reduced suite's
(engine, method) pairs, their convergence orders, and which are adaptive or implicit. The cases it varies are the
model's (:attr:`bearing_mbs.models.Model.stability`)."""

from __future__ import annotations

from bearing_mbs.spec import methods as m

#: (engine, method) of the full suite, and of the reduced one.
SOLVERS = (
    ("reference", m.CENTRAL_DIFFERENCE.name), ("reference", m.VELOCITY_VERLET.name), ("reference", m.RK4.name),
    ("reference", m.DOPRI5.name), ("exudyn", m.GENERALIZED_ALPHA.name), ("exudyn", m.RK4.name),
    ("exudyn", m.DOPRI5.name),
)
REDUCED_SOLVERS = (("reference", m.CENTRAL_DIFFERENCE.name), ("reference", m.VELOCITY_VERLET.name),
                   ("reference", m.RK4.name), ("exudyn", m.GENERALIZED_ALPHA.name))

#: Convergence orders (the catalogue's), for the energy audit's convergence check (adaptive methods and the pairs
#: not listed: order 1 in the tolerance or step).
ORDERS = {(engine, method.name): method.order for engine, method in (
    ("reference", m.CENTRAL_DIFFERENCE), ("reference", m.VELOCITY_VERLET), ("reference", m.RK4), ("exudyn", m.RK4),
    ("exudyn", m.GENERALIZED_ALPHA), ("exudyn", m.TRAPEZOIDAL_INDEX2), ("exudyn", m.VELOCITY_VERLET),
    ("exudyn", m.RK33), ("exudyn", m.RK67))}

ADAPTIVE = {("reference", m.DOPRI5.name), ("exudyn", m.DOPRI5.name), ("exudyn", m.ODE23.name),
            ("exudyn", m.DVERK6.name)}
IMPLICIT = {("exudyn", m.GENERALIZED_ALPHA.name), ("exudyn", m.TRAPEZOIDAL_INDEX2.name)}
