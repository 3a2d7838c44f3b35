"""Integer codes shared by the compiled reference engine: methods, run status and counter slots.

numba cannot take an enum member cheaply, so the run status inside compiled code is a plain int equal to
``int(Failure.X)`` of :class:`bearing_mbs.core.failures.Failure`; the Python side turns it back into the enum.
"""

from __future__ import annotations

from bearing_mbs.core.failures import Failure

#: Method codes: the driver dispatches on them to each method's step function.
CENTRAL_DIFFERENCE, VELOCITY_VERLET, RUNGE_KUTTA = 0, 1, 2
METHOD_CODES = {"central_difference": CENTRAL_DIFFERENCE, "velocity_verlet": VELOCITY_VERLET,
                "rk4": RUNGE_KUTTA, "dopri5": RUNGE_KUTTA}

#: Run status returned by the compiled driver (``RUNNING``: no failure so far).
RUNNING = int(Failure.NONE)
NONFINITE = int(Failure.NONFINITE)
PENETRATION = int(Failure.PENETRATION)
STEP_UNDERFLOW = int(Failure.STEP_UNDERFLOW)
PROJECTION_FAILED = int(Failure.PROJECTION_FAILED)
BLOWUP = int(Failure.BLOWUP)

#: Slots of the run counters (int64 array): accepted steps, rejected steps, force evaluations.
STEPS, REJECTED, EVALUATIONS = 0, 1, 2
