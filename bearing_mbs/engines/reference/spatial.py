r"""The reference engine's rigid bodies in three dimensions: the classical Runge–Kutta method on the Newton–Euler
equations with the orientation as a unit quaternion, projected back onto the unit sphere after each step.

Per body the state is (r, p, ṙ, ω): centre of mass [m], orientation quaternion (scalar first), velocity [m/s],
body-frame angular velocity [rad/s] (:mod:`bearing_mbs.core.spatial`). The rates are

.. math::
    \dot p = \tfrac12\, p \otimes (0, \omega), \quad m \ddot r = m g + F, \quad
    I \dot\omega = M - \omega \times I \omega

with I = diag(I₁, I₂, I₃), F the force (world frame) and M the moment about the centre (body frame) of the scene's
force elements (Euler's equations). RK4 leaves |p| = 1 to O(h⁵) per step;
normalising p afterwards is the projection onto that constraint (as the planar engine projects its constraints)
and keeps the method's fourth order. A Lie-group method (Munthe-Kaas) would stay on the sphere without it, at the
price of the exponential map's derivative in every stage.
"""

from __future__ import annotations

import math
from typing import NamedTuple

import numba
import numpy as np

from bearing_mbs.core.failures import Failure
from bearing_mbs.core.interrupt import StopRequest
from bearing_mbs.core.progress import ProgressMeter
from bearing_mbs.core.rotations import rotation_from_quaternion
from bearing_mbs.core.spatial import SpatialScene, SpatialSeries, check_times, nonfinite_message, stopped_message
from bearing_mbs.elements.spatial import latch, new_work, spatial_forces
from bearing_mbs.engines.diagnosis import output_grid
from bearing_mbs.engines.reference.integrators import equal_steps
from bearing_mbs.engines.reference.tableaus import RK4
from bearing_mbs.engines.run import progress_meter, stop_request, timed_run

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


@numba.njit(cache=True)
def spatial_runge_kutta(y, energy, bodies, packed, work, span, step, a, b):
    """Advance ``y`` over ``span`` [s] in equal steps of at most ``step`` [s] of the explicit Runge–Kutta method
    (a, b) (:mod:`~bearing_mbs.engines.reference.tableaus`), each followed by the quaternions' normalisation, and the
    work (supplied, dissipated) [J] in ``energy`` with the same stages; returns the steps taken."""
    steps = equal_steps(span, step)
    h = span / steps
    stages = np.empty((b.size, *y.shape))
    powers = np.empty((b.size, 2))
    stage = np.empty_like(y)
    for _ in range(steps):
        for i in range(b.size):
            stage[:] = y
            for j in range(i):
                if a[i, j] != 0.0:
                    stage += h * a[i, j] * stages[j]
            powers[i, 0], powers[i, 1], _ = spatial_rates(stage, bodies, packed, work, stages[i])
            if i == 0:  # at the accepted state: the contacts' latched approach speeds advance (elements.spatial)
                latch(work)
        for i in range(b.size):
            y += h * b[i] * stages[i]
            energy[0] += h * b[i] * powers[i, 0]
            energy[1] += h * b[i] * powers[i, 1]
        for body in range(y.shape[0]):
            norm = math.sqrt(y[body, 3] ** 2 + y[body, 4] ** 2 + y[body, 5] ** 2 + y[body, 6] ** 2)
            for k in range(ORIENTATION, VELOCITY):
                y[body, k] /= norm
    return steps


def simulate_spatial_reference(scene: SpatialScene, step: float, end_time: float, output_interval: float,
                               progress: ProgressMeter | None = None, stop: StopRequest | None = None) -> SpatialSeries:
    """Run ``scene`` from 0 to ``end_time`` [s] with RK4 steps of at most ``step`` [s] (equal steps within each output
    interval), output every ``output_interval`` [s]; ``progress`` is updated and ``stop`` looked at at every output
    instant (a set request ends the run there, keeping the output)."""
    check_times(step, end_time, output_interval)
    times = output_grid(end_time, output_interval)
    y = np.array([[*b.position, *b.orientation, *b.velocity, *b.angular_velocity] for b in scene.bodies])
    bodies = SpatialBodies(np.array([b.mass for b in scene.bodies]), np.array([b.inertia for b in scene.bodies]),
                           np.array(scene.gravity))
    packed = scene.packed()
    work, rates, energy = new_work(len(scene.bodies), packed), np.empty_like(y), np.zeros(2)
    states, loads = np.empty((times.size, *y.shape)), np.empty((times.size, *packed.race_positions.shape))
    friction = np.empty_like(loads)
    flange_loads = np.empty((times.size, packed.flange_roller.size))
    works, stored = np.empty((times.size, 2)), np.empty(times.size)
    steps, message, failure, reached = 0, "", Failure.NONE, times.size
    progress, stop = progress_meter(progress), stop_request(stop)
    with timed_run(progress, end_time, f"{scene.name} (reference rk4, three dimensions)") as clock:
        for k in range(times.size):
            if k > 0:
                steps += spatial_runge_kutta(y, energy, bodies, packed, work, times[k] - times[k - 1], step, RK4.a,
                                             RK4.b)
            if not np.isfinite(y).all():
                message, failure, reached = nonfinite_message(scene, np.isfinite(y).all(axis=1),
                                                              states[k - 1, :, ANGULAR_VELOCITY:], times[k], step), \
                    Failure.NONFINITE, k
                break
            *_, stored[k] = spatial_rates(y, bodies, packed, work, rates)  # the contact loads of this instant
            states[k], loads[k], flange_loads[k], works[k] = y, work.slice_loads, work.flange_loads, energy
            friction[k] = work.slice_friction
            progress.update(times[k])
            if stop.is_set() and k + 1 < times.size:
                message, failure, reached = stopped_message(times[k]), Failure.INTERRUPTED, k + 1
                break
    states = states[:reached]
    return SpatialSeries(times[:reached], states[:, :, POSITION:ORIENTATION], states[:, :, ORIENTATION:VELOCITY],
                         states[:, :, VELOCITY:ANGULAR_VELOCITY], states[:, :, ANGULAR_VELOCITY:], loads[:reached],
                         friction[:reached], flange_loads[:reached], works[:reached], stored[:reached], steps, message,
                         clock.wall_time_s, failure)
