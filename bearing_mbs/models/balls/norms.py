"""The balls model's norm for a work–precision study (:mod:`bearing_mbs.studies.convergence`): ``positions``,
max |Δx|, |Δy| of every ball's centre over the smallest ball radius, from the start."""

from __future__ import annotations

import numpy as np

from bearing_mbs.models.protocol import ErrorNorms


def errors(spec, scene, run, reference, mask) -> dict:
    """``positions`` of ``run`` against ``reference`` over ``mask``, relative to the smallest ball radius."""
    translational = np.concatenate([[3 * i, 3 * i + 1] for i in range(len(scene.bodies))])
    scale = min(ball.radius for ball in spec.balls)
    delta = run.position[mask][:, translational] - reference.position[mask][:, translational]
    return {"positions": float(np.abs(delta).max() / scale)}


#: The balls' norm: positions only.
ERROR_NORMS = ErrorNorms(names=("positions",), errors=errors)
