r"""The reference engine's rigid bodies in three dimensions: the classical Runge–Kutta method on the Newton–Euler
equations with the orientation as a unit quaternion, projected back onto the unit sphere after each step.

Per body the state is (r, p, ṙ, ω): centre of mass [m], orientation quaternion (scalar first), velocity [m/s],
body-frame angular velocity [rad/s] (:mod:`bearing_mbs.core.spatial`). The rates are

.. math::
    \dot r = \dot r, \quad \dot p = \tfrac12\, p \otimes (0, \omega), \quad \ddot r = g, \quad
    I \dot\omega = M - \omega \times I \omega

with I = diag(I₁, I₂, I₃) and M the body-fixed moment (Euler's equations). RK4 leaves |p| = 1 to O(h⁵) per step;
normalising p afterwards is the projection onto that constraint (as the planar engine projects its constraints)
and keeps the method's fourth order. A Lie-group method (Munthe-Kaas) would stay on the sphere without it, at the
price of the exponential map's derivative in every stage.
"""

from __future__ import annotations

import math

import numba
import numpy as np

from bearing_mbs.core.spatial import SpatialScene, SpatialSeries, check_times, nonfinite_message
from bearing_mbs.engines.diagnosis import output_grid
from bearing_mbs.engines.reference.integrators import equal_steps
from bearing_mbs.engines.reference.tableaus import RK4

#: The columns of a body's state: r (3), p (4), ṙ (3), ω (3).
POSITION, ORIENTATION, VELOCITY, ANGULAR_VELOCITY, STATE_SIZE = 0, 3, 7, 10, 13


@numba.njit(cache=True)
def spatial_rates(y, inertia, moments, gravity, rates):
    """The rates of the states ``y`` (N, 13) of free bodies with principal moments ``inertia`` (N, 3) [kg m²] under
    body-fixed ``moments`` (N, 3) [N m] and gravity [m/s²], into ``rates`` (N, 13)."""
    for b in range(y.shape[0]):
        w, x, yq, z = y[b, 3], y[b, 4], y[b, 5], y[b, 6]
        a, c2, c3 = y[b, 10], y[b, 11], y[b, 12]
        i1, i2, i3 = inertia[b, 0], inertia[b, 1], inertia[b, 2]
        for k in range(3):
            rates[b, POSITION + k] = y[b, VELOCITY + k]
            rates[b, VELOCITY + k] = gravity[k]
        rates[b, 3] = 0.5 * (-x * a - yq * c2 - z * c3)  # ½ p ⊗ (0, ω)
        rates[b, 4] = 0.5 * (w * a + yq * c3 - z * c2)
        rates[b, 5] = 0.5 * (w * c2 + z * a - x * c3)
        rates[b, 6] = 0.5 * (w * c3 + x * c2 - yq * a)
        rates[b, 10] = (moments[b, 0] + (i2 - i3) * c2 * c3) / i1  # Euler's equations
        rates[b, 11] = (moments[b, 1] + (i3 - i1) * c3 * a) / i2
        rates[b, 12] = (moments[b, 2] + (i1 - i2) * a * c2) / i3


@numba.njit(cache=True)
def spatial_runge_kutta(y, inertia, moments, gravity, span, step, a, b):
    """Advance ``y`` over ``span`` [s] in equal steps of at most ``step`` [s] of the explicit Runge–Kutta method
    (a, b) (:mod:`~bearing_mbs.engines.reference.tableaus`), each followed by the quaternions' normalisation; returns
    the steps taken."""
    steps = equal_steps(span, step)
    h = span / steps
    stages = np.empty((b.size, *y.shape))
    stage = np.empty_like(y)
    for _ in range(steps):
        for i in range(b.size):
            stage[:] = y
            for j in range(i):
                if a[i, j] != 0.0:
                    stage += h * a[i, j] * stages[j]
            spatial_rates(stage, inertia, moments, gravity, stages[i])
        for i in range(b.size):
            y += h * b[i] * stages[i]
        for body in range(y.shape[0]):
            norm = math.sqrt(y[body, 3] ** 2 + y[body, 4] ** 2 + y[body, 5] ** 2 + y[body, 6] ** 2)
            for k in range(ORIENTATION, VELOCITY):
                y[body, k] /= norm
    return steps


def simulate_spatial_reference(scene: SpatialScene, step: float, end_time: float,
                               output_interval: float) -> SpatialSeries:
    """Run the free bodies of ``scene`` from 0 to ``end_time`` [s] with RK4 steps of at most ``step`` [s] (equal steps
    within each output interval), output every ``output_interval`` [s]."""
    check_times(step, end_time, output_interval)
    times = output_grid(end_time, output_interval)
    y = np.array([[*b.position, *b.orientation, *b.velocity, *b.angular_velocity] for b in scene.bodies])
    inertia = np.array([b.inertia for b in scene.bodies])
    moments, gravity = scene.body_moments(), np.array(scene.gravity)
    states = np.empty((times.size, *y.shape))
    states[0] = y
    steps, message, reached = 0, "", times.size
    for k in range(1, times.size):
        steps += spatial_runge_kutta(y, inertia, moments, gravity, times[k] - times[k - 1], step, RK4.a, RK4.b)
        if not np.isfinite(y).all():
            message, reached = nonfinite_message(scene, np.isfinite(y).all(axis=1), states[k - 1, :, ANGULAR_VELOCITY:],
                                                 times[k], step), k
            break
        states[k] = y
    states = states[:reached]
    return SpatialSeries(times[:reached], states[:, :, POSITION:ORIENTATION], states[:, :, ORIENTATION:VELOCITY],
                         states[:, :, VELOCITY:ANGULAR_VELOCITY], states[:, :, ANGULAR_VELOCITY:], steps, message)
