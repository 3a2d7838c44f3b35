r"""The reference engine's equations of motion in three dimensions: the Newton–Euler equations of rigid bodies
whose orientation is a unit quaternion, which its explicit (:mod:`.spatial`) and implicit (:mod:`.spatial_alpha`)
methods integrate.

Per body the state is (r, p, ṙ, ω): centre of mass [m], orientation quaternion (scalar first), velocity [m/s],
body-frame angular velocity [rad/s] (:mod:`bearing_mbs.core.spatial`). The rates are

.. math::
    \dot p = \tfrac12\, p \otimes (0, \omega), \quad m \ddot r = m g + F, \quad
    I \dot\omega = M - \omega \times I \omega

with I = diag(I₁, I₂, I₃), F the force (world frame) and M the moment about the centre (body frame) of the scene's
force elements (Euler's equations).
"""

from __future__ import annotations

from typing import NamedTuple

import numba
import numpy as np

from bearing_mbs.core.rotations import rotation_from_quaternion
from bearing_mbs.elements.spatial import spatial_forces

#: The columns of a body's state: r (3), p (4), ṙ (3), ω (3).
POSITION, ORIENTATION, VELOCITY, ANGULAR_VELOCITY = 0, 3, 7, 10


class SpatialBodies(NamedTuple):
    """The bodies' constants: mass [kg] (N,), principal moments of inertia [kg m²] (N, 3), gravity [m/s²] (3,)."""

    mass: np.ndarray
    inertia: np.ndarray
    gravity: np.ndarray


@numba.njit(cache=True)
def spatial_rates(y, bodies, packed, work, rates):
    """The rates of the states ``y`` (N, 13) into ``rates`` (N, 13): the kinematics and the Newton–Euler equations
    under the scene's force elements (:func:`bearing_mbs.elements.spatial.spatial_forces`) and gravity. Returns the
    force elements' (supplied, dissipated) power [W] and stored energy [J]."""
    count = y.shape[0]
    for b in range(count):
        rotation_from_quaternion(y[b, 3], y[b, 4], y[b, 5], y[b, 6], work.rotation[b])
    powers = spatial_forces(packed, y[:, POSITION:ORIENTATION], y[:, VELOCITY:ANGULAR_VELOCITY],
                            y[:, ANGULAR_VELOCITY:], work)
    for b in range(count):
        w, x, yq, z = y[b, 3], y[b, 4], y[b, 5], y[b, 6]
        a, c2, c3 = y[b, 10], y[b, 11], y[b, 12]
        i1, i2, i3 = bodies.inertia[b, 0], bodies.inertia[b, 1], bodies.inertia[b, 2]
        for k in range(3):
            rates[b, POSITION + k] = y[b, VELOCITY + k]
            rates[b, VELOCITY + k] = bodies.gravity[k] + work.force[b, k] / bodies.mass[b]
        rates[b, 3] = 0.5 * (-x * a - yq * c2 - z * c3)  # ½ p ⊗ (0, ω)
        rates[b, 4] = 0.5 * (w * a + yq * c3 - z * c2)
        rates[b, 5] = 0.5 * (w * c2 + z * a - x * c3)
        rates[b, 6] = 0.5 * (w * c3 + x * c2 - yq * a)
        rates[b, 10] = (work.moment[b, 0] + (i2 - i3) * c2 * c3) / i1  # Euler's equations
        rates[b, 11] = (work.moment[b, 1] + (i3 - i1) * c3 * a) / i2
        rates[b, 12] = (work.moment[b, 2] + (i1 - i2) * a * c2) / i3
    return powers
