r"""The reference engine's rigid bodies in three dimensions (:mod:`.spatial_rates`): the classical Runge–Kutta method
with the orientation as a unit quaternion, projected back onto the unit sphere after each step, or Lie-group
generalized-α (:mod:`.spatial_alpha`), the implicit method for stiff contacts.

RK4 leaves |p| = 1 to O(h⁵) per step; normalising p afterwards is the projection onto that constraint (as the planar
engine projects its constraints) and keeps the method's fourth order. A Lie-group Runge–Kutta method (Munthe-Kaas)
would stay on the sphere without it, at the price of the exponential map's derivative in every stage.
"""

from __future__ import annotations

import math

import numba
import numpy as np

from bearing_mbs.core.failures import Failure
from bearing_mbs.core.interrupt import StopRequest
from bearing_mbs.core.progress import ProgressMeter
from bearing_mbs.core.spatial import SpatialScene, SpatialSeries, check_times, nonfinite_message, stopped_message
from bearing_mbs.elements.spatial import latch, new_work
from bearing_mbs.engines.diagnosis import output_grid
from bearing_mbs.engines.reference.codes import EVALUATIONS, JACOBIANS, NEWTON_ITERATIONS, REJECTED, STEP_UNDERFLOW
from bearing_mbs.engines.reference.integrators import equal_steps
from bearing_mbs.engines.reference.spatial_alpha import alpha_span, alpha_start, new_carry
from bearing_mbs.engines.reference.spatial_rates import (
    ANGULAR_VELOCITY,
    ORIENTATION,
    POSITION,
    VELOCITY,
    SpatialBodies,
    spatial_rates,
)
from bearing_mbs.engines.reference.tableaus import RK4
from bearing_mbs.engines.run import progress_meter, stop_request, timed_run
from bearing_mbs.spec import methods

#: The methods that run spatial scenes on this engine.
SPATIAL_METHODS = (methods.RK4, methods.GENERALIZED_ALPHA)


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
                               method: methods.Method = methods.RK4, spectral_radius: float = 0.9,
                               tolerance: float = 1e-8, progress: ProgressMeter | None = None,
                               stop: StopRequest | None = None) -> SpatialSeries:
    """Run ``scene`` from 0 to ``end_time`` [s] with ``method`` (RK4, or generalized-α of high-frequency spectral
    radius ``spectral_radius`` and Newton tolerance ``tolerance``, :mod:`.spatial_alpha`) in equal steps of at most
    ``step`` [s] within each output interval, output every ``output_interval`` [s]; ``progress`` is updated and
    ``stop`` looked at at every output instant (a set request ends the run there, keeping the output)."""
    check_times(step, end_time, output_interval)
    if method not in SPATIAL_METHODS:
        raise ValueError(f"method must be one of {[m.name for m in SPATIAL_METHODS]}, got "
                         f"{getattr(method, 'name', method)!r}")
    if not 0.0 <= spectral_radius <= 1.0:
        raise ValueError(f"spectral_radius must be in [0, 1], got {spectral_radius!r}")
    if not 0.0 < tolerance < 1.0:
        raise ValueError(f"tolerance must be in (0, 1), got {tolerance!r}")
    implicit = method == methods.GENERALIZED_ALPHA
    times = output_grid(end_time, output_interval)
    y = np.array([[*b.position, *b.orientation, *b.velocity, *b.angular_velocity] for b in scene.bodies])
    bodies = SpatialBodies(np.array([b.mass for b in scene.bodies]), np.array([b.inertia for b in scene.bodies]),
                           np.array(scene.gravity))
    packed = scene.packed()
    work, rates, energy = new_work(len(scene.bodies), packed), np.empty_like(y), np.zeros(2)
    carry, counters = new_carry(y), np.zeros(5, dtype=np.int64)
    if implicit:
        alpha_start(y, bodies, packed, work, carry)
    states, loads = np.empty((times.size, *y.shape)), np.empty((times.size, *packed.race_positions.shape))
    friction = np.empty_like(loads)
    flange_loads = np.empty((times.size, packed.flange_roller.size))
    works, stored = np.empty((times.size, 2)), np.empty(times.size)
    steps, message, failure, reached = 0, "", Failure.NONE, times.size
    progress, stop = progress_meter(progress), stop_request(stop)
    with timed_run(progress, end_time, f"{scene.name} (reference {method.name}, three dimensions)") as clock:
        for k in range(times.size):
            if k > 0 and implicit:
                taken, status = alpha_span(y, energy, bodies, packed, work, carry, times[k] - times[k - 1], step,
                                           spectral_radius, tolerance, counters)
                steps += taken
                if status == STEP_UNDERFLOW:
                    message = (f"t = {times[k - 1]:.6g} s: Newton's iteration of generalized-α failed at every step "
                               f"down to the shortest; likely fix: a step below {step:.3g} s or a spectral radius "
                               f"below {spectral_radius:g}")
                    failure, reached = Failure.STEP_UNDERFLOW, k
                    break
            elif k > 0:
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
                         clock.wall_time_s, failure, int(counters[REJECTED]), int(counters[NEWTON_ITERATIONS]),
                         int(counters[JACOBIANS]), int(counters[EVALUATIONS]))
