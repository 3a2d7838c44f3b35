"""Integer codes shared by the compiled reference engine: methods, run status and counter slots.

numba cannot take an enum member cheaply, so the run status inside compiled code is a plain int equal to
``int(Failure.X)`` of :class:`bearing_mbs.core.failures.Failure`; the Python side turns it back into the enum.
"""

from __future__ import annotations

from bearing_mbs.core.failures import Failure
from bearing_mbs.spec import methods

#: Method codes: the driver dispatches on them to each method's step function.
CENTRAL_DIFFERENCE, VELOCITY_VERLET, RUNGE_KUTTA, GENERALIZED_ALPHA = 0, 1, 2, 3
#: The code of each method of the catalogue (:mod:`bearing_mbs.spec.methods`) the reference engine runs, by name.
METHOD_CODES = {method.name: code for method, code in (
    (methods.CENTRAL_DIFFERENCE, CENTRAL_DIFFERENCE), (methods.VELOCITY_VERLET, VELOCITY_VERLET),
    (methods.RK4, RUNGE_KUTTA), (methods.DOPRI5, RUNGE_KUTTA), (methods.GENERALIZED_ALPHA, GENERALIZED_ALPHA),
    (methods.GENERALIZED_ALPHA_ADAPTIVE, GENERALIZED_ALPHA))}

#: Run status returned by the compiled driver (``RUNNING``: no failure so far).
RUNNING = int(Failure.NONE)
NONFINITE = int(Failure.NONFINITE)
PENETRATION = int(Failure.PENETRATION)
STEP_UNDERFLOW = int(Failure.STEP_UNDERFLOW)
PROJECTION_FAILED = int(Failure.PROJECTION_FAILED)
BLOWUP = int(Failure.BLOWUP)
SOLVER_FAILED = int(Failure.SOLVER_FAILED)

#: Slots of the run counters (int64 array): accepted steps, rejected steps, force evaluations, and the implicit
#: method's Newton iterations and Jacobians.
STEPS, REJECTED, EVALUATIONS, NEWTON_ITERATIONS, JACOBIANS = 0, 1, 2, 3, 4
COUNTERS = 5
