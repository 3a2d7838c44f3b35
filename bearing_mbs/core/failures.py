"""Why a run stopped early, as data: a typed code in :attr:`bearing_mbs.core.result.Result.failure`.

Code that reacts to a failure compares kinds, never message text (as diffrax's ``RESULTS`` and scipy's
``OdeResult.status``). The message of a result is made from its kind and the state where the run stopped.
The integer values are also the status codes the compiled reference integrator returns; a kind prints as its
name (``print(result.failure)`` gives ``blowup``), and summaries write that name (``failure``).
"""

from __future__ import annotations

import enum


class Failure(enum.IntEnum):
    """The kind of a run's stop. ``NONE``: the run reached its end time."""

    NONE = 0
    #: a coordinate became NaN or infinite
    NONFINITE = 1
    #: a pair penetrated beyond its guard (``solver.penetration_limit`` of its radius)
    PENETRATION = 2
    #: the adaptive step fell below 1e-14 of the time
    STEP_UNDERFLOW = 3
    #: the constraint projection did not converge
    PROJECTION_FAILED = 4
    #: a body moved faster than ``solver.speed_limit``
    BLOWUP = 5
    #: the engine's own solver gave up (Exudyn: Newton's method did not converge, or the solver stopped)
    SOLVER_FAILED = 6
    #: the user stopped the run (SIGINT or SIGTERM); what was computed is kept
    INTERRUPTED = 7

    @property
    def diverged(self) -> bool:
        """The state ran away: the usual remedy is a smaller step or an implicit solver."""
        return self in (Failure.NONFINITE, Failure.BLOWUP)

    @property
    def label(self) -> str:
        """The kind's name as summaries write it: ``none``, ``nonfinite``, ``blowup``…"""
        return self.name.lower()

    def __str__(self) -> str:  # an IntEnum prints as its integer otherwise: a user reads the kind's name
        return self.label

    def __format__(self, spec: str) -> str:
        return format(self.label, spec)
