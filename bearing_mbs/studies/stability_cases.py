"""The solvers the stability suite probes (:mod:`bearing_mbs.studies.stability`): the full and the reduced suite's
(engine, method) pairs, their convergence orders, and which are adaptive or implicit. The cases it varies are the
model's (:attr:`bearing_mbs.models.Model.stability`)."""

from __future__ import annotations

#: (engine, method) of the full suite, and of the reduced one.
SOLVERS = (
    ("reference", "central_difference"), ("reference", "velocity_verlet"), ("reference", "rk4"),
    ("reference", "dopri5"), ("exudyn", "generalized_alpha"), ("exudyn", "rk4"), ("exudyn", "dopri5"),
)
REDUCED_SOLVERS = (("reference", "central_difference"), ("reference", "velocity_verlet"), ("reference", "rk4"),
                   ("exudyn", "generalized_alpha"))

#: Convergence orders, for the energy audit's convergence check (adaptive methods: order 1 in the tolerance).
ORDERS = {("reference", "central_difference"): 1, ("reference", "velocity_verlet"): 2, ("reference", "rk4"): 4,
          ("exudyn", "rk4"): 4, ("exudyn", "generalized_alpha"): 2, ("exudyn", "trapezoidal_index2"): 2,
          ("exudyn", "velocity_verlet"): 2, ("exudyn", "rk33"): 3, ("exudyn", "rk67"): 6}

ADAPTIVE = {("reference", "dopri5"), ("exudyn", "dopri5"), ("exudyn", "ode23"), ("exudyn", "dverk6")}
IMPLICIT = {("exudyn", "generalized_alpha"), ("exudyn", "trapezoidal_index2")}
