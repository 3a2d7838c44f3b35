"""The Exudyn engine's rigid bodies in three dimensions: a spatial scene as Exudyn nodes and bodies, run by one of
Exudyn's solvers.

* bodies: ``NodeRigidBodyRotVecLG`` (position and rotation vector, for Exudyn's Lie-group integrators) +
  ``ObjectRigidBody`` with the principal moments as the inertia; the node's velocity coordinates are ṙ in the world
  frame and ω in the body frame, as in :mod:`bearing_mbs.core.spatial`;
* force elements (forces, moments, springs, raceway contacts): one ``ObjectGenericODE2`` over all nodes whose force
  user function calls the compiled kernel both engines use (:func:`bearing_mbs.elements.spatial.spatial_forces`);
  its generalized forces on a Lie-group node's rotation coordinates are the moment in the body frame (measured:
  the same motion as a body-fixed ``LoadTorqueVector``); gravity: ``LoadMassProportional`` per body, only when it is
  non-zero;
* methods: RK4 (Exudyn's RK44 with Lie-group integration of the rotations) or generalized-α (Exudyn's Lie-group
  generalized-α, spectral radius ``spectral_radius``);
* output: the node's position, velocity, rotation matrix and local angular velocity at the output instants, read
  after each accepted step (a ``PostStepUserFunction``), and the slice loads evaluated there; the rotation matrix
  becomes a quaternion with scipy, its sign kept continuous.
"""

from __future__ import annotations

import contextlib
import io
import math

import numpy as np
from scipy.spatial.transform import Rotation

from bearing_mbs.core.failures import Failure
from bearing_mbs.core.interrupt import StopRequest
from bearing_mbs.core.progress import ProgressMeter
from bearing_mbs.core.spatial import SpatialScene, SpatialSeries, check_times, nonfinite_message, stopped_message
from bearing_mbs.elements.spatial import latch, new_work, spatial_generalized_forces
from bearing_mbs.engines.diagnosis import output_grid
from bearing_mbs.engines.run import progress_meter, stop_request, timed_run
from bearing_mbs.spec import methods

#: The methods that run spatial scenes (Exudyn's solver of each: ``Method.exudyn``).
SPATIAL_METHODS = (methods.RK4, methods.GENERALIZED_ALPHA)


def simulate_spatial_exudyn(scene: SpatialScene, step: float, end_time: float, output_interval: float,
                            method: methods.Method = methods.RK4, spectral_radius: float = 0.9,
                            newton_tolerance: float = 1e-10, progress: ProgressMeter | None = None,
                            stop: StopRequest | None = None) -> SpatialSeries:
    """Run ``scene`` from 0 to ``end_time`` [s] with Exudyn's ``method`` in equal steps of at most
    ``step`` [s], output at the first step on or after each output instant (every ``output_interval`` [s]; the
    series holds the times of the steps, which are the instants when the step divides the interval); ``progress`` is
    updated and ``stop`` looked at at every output instant (a set request ends the run there, keeping the
    output)."""
    import exudyn as exu

    check_times(step, end_time, output_interval)
    if method not in SPATIAL_METHODS:
        raise ValueError(f"method must be one of {[m.name for m in SPATIAL_METHODS]}, got "
                         f"{getattr(method, 'name', method)!r}")
    times = output_grid(end_time, output_interval)
    container = exu.SystemContainer()
    mbs = container.AddSystem()
    nodes, forces = _add_bodies(mbs, scene)
    progress, stop = progress_meter(progress), stop_request(stop)
    recorder = _Recorder(mbs, exu, nodes, times, scene, step, forces, progress, stop)
    mbs.SetPostStepUserFunction(recorder)
    mbs.Assemble()
    recorder.start(np.array([body.orientation for body in scene.bodies]))

    settings = exu.SimulationSettings()
    settings.solution.file.write = False
    ti = settings.timeIntegration
    ti.verboseMode = 0
    ti.endTime = end_time
    ti.numberOfSteps = math.ceil(end_time / step * (1 - 1e-9))
    ti.explicit.useLieGroupIntegration = True
    ti.generalizedAlpha.spectralRadius = spectral_radius
    ti.newton.relativeTolerance = newton_tolerance
    ti.newton.absoluteTolerance = newton_tolerance
    with timed_run(progress, end_time, f"{scene.name} (exudyn {method.name}, three dimensions)") as clock:
        try:
            with contextlib.redirect_stdout(io.StringIO()):  # Exudyn's console notes (its warning on the allocations
                # of the Python force function each step, which is how user functions work)
                solved = mbs.SolveDynamic(settings, solverType=getattr(exu.DynamicSolverType, method.exudyn))
            detail = ""
        except Exception as error:  # noqa: BLE001 (Exudyn raises when a solver gives up)
            solved, detail = False, str(error)
    steps = int(mbs.sys["dynamicSolver"].it.currentStepIndex) - 1
    series = recorder.series()
    if not solved and recorder.failure == Failure.NONE:
        recorder.stop_with(Failure.SOLVER_FAILED, f"t = {recorder.time:.6g} s: Exudyn's {method.name} stopped "
                                                  f"({detail or 'no message'}). Likely fix: a smaller step than "
                                                  f"{step:.3g} s")
    return SpatialSeries(*series, steps, recorder.message, clock.wall_time_s, recorder.failure)


def _add_bodies(mbs, scene: SpatialScene) -> tuple[list, _Forces]:
    """One Lie-group rigid-body node and body per scene body (reference coordinates zero, so that a node's
    coordinates are r and φ themselves), the force elements' object and the weights; returns the nodes and the
    forces."""
    from exudyn.itemInterface import (
        LoadMassProportional,
        MarkerBodyMass,
        NodeRigidBodyRotVecLG,
        ObjectGenericODE2,
        ObjectRigidBody,
    )

    nodes = []
    for body in scene.bodies:
        w, x, y, z = body.orientation
        rotation_vector = Rotation.from_quat([x, y, z, w]).as_rotvec()
        node = mbs.AddNode(NodeRigidBodyRotVecLG(referenceCoordinates=[0.0] * 6,
                                                 initialCoordinates=[*body.position, *rotation_vector],
                                                 initialVelocities=[*body.velocity, *body.angular_velocity]))
        item = mbs.AddObject(ObjectRigidBody(nodeNumber=node, mass=body.mass, inertia=[*body.inertia, 0, 0, 0]))
        if any(scene.gravity):
            mbs.AddLoad(LoadMassProportional(markerNumber=mbs.AddMarker(MarkerBodyMass(bodyNumber=item)),
                                             loadVector=list(scene.gravity)))
        nodes.append(node)
    forces = _Forces(scene)
    if scene.has_forces:
        size = 6 * len(nodes)
        mbs.AddObject(ObjectGenericODE2(nodeNumbers=nodes, massMatrix=np.zeros((size, size)),
                                        forceUserFunction=forces))
    return nodes, forces


class _Forces:
    """The force user function of the generic ODE2 object (and the slice loads of its last evaluation)."""

    def __init__(self, scene: SpatialScene):
        self.packed = scene.packed()
        self.work = new_work(len(scene.bodies), self.packed)
        self.out = np.empty(6 * len(scene.bodies))
        self.powers = (0.0, 0.0, 0.0)  # supplied, dissipated [W], stored [J] of the last evaluation

    def evaluate(self, q, q_t) -> np.ndarray:
        """The generalized forces at (q, q̇); the powers and stored energy into ``self.powers``."""
        self.powers = spatial_generalized_forces(self.packed, np.asarray(q, dtype=float),
                                                 np.asarray(q_t, dtype=float), self.work, self.out)
        return self.out

    def __call__(self, mbs, t, item_number, q, q_t):
        return self.evaluate(q, q_t).tolist()

    @property
    def loads(self) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """The slice loads [N], the slices' friction power [W] and the flange loads [N] of the last evaluation."""
        return self.work.slice_loads.copy(), self.work.slice_friction.copy(), self.work.flange_loads.copy()


class _Recorder:
    """PostStepUserFunction: a finite state after every step, the work (trapezoid rule over the accepted steps, as
    the planar engine integrates it), the bodies' states at the output instants."""

    def __init__(self, mbs, exu, nodes: list, times: np.ndarray, scene: SpatialScene, step: float, forces: _Forces,
                 progress: ProgressMeter, stop: StopRequest):
        self.mbs, self.nodes, self.times, self.scene, self.step, self.forces = mbs, nodes, times, scene, step, forces
        self.progress, self.stop = progress, stop
        self.time, self.message, self.failure = 0.0, "", Failure.NONE
        kinds = exu.OutputVariableType
        self.kinds = (kinds.Position, kinds.Velocity, kinds.RotationMatrix, kinds.AngularVelocityLocal)
        self.rows: list[tuple] = []
        self.margin = 1e-6 * (times[1] - times[0]) if times.size > 1 else 0.0
        self.work, self.power = np.zeros(2), np.zeros(2)  # supplied, dissipated [J]; the last step's powers [W]
        self.last_time = 0.0

    def start(self, orientations: np.ndarray) -> None:
        """The initial row (the forces evaluated at the initial state, the quaternions' signs those of
        ``orientations`` (N, 4))."""
        self.forces.evaluate(*self._state())
        self.power = np.array(self.forces.powers[:2])
        self.record(0.0, orientations)

    def _state(self) -> tuple[np.ndarray, np.ndarray]:
        """The system's coordinates and velocities now: per node (r, φ) and (ṙ, ω)."""
        data = self.mbs.systemData
        return np.asarray(data.GetODE2Coordinates()), np.asarray(data.GetODE2Coordinates_t())

    def record(self, t: float, previous: np.ndarray | None = None):
        """Store the current state at t [s], with the loads of the forces' evaluation there (the caller's); the
        quaternions' signs follow ``previous`` (N, 4), else the last row's."""
        position, velocity, matrix, omega = (
            np.array([self.mbs.GetNodeOutput(node, kind) for node in self.nodes]) for kind in self.kinds)
        xyzw = Rotation.from_matrix(matrix.reshape(-1, 3, 3)).as_quat()
        quaternion = np.column_stack([xyzw[:, 3], xyzw[:, :3]])
        reference = previous if previous is not None else self.rows[-1][2]
        quaternion *= np.where(np.sum(quaternion * reference, axis=1) < 0, -1.0, 1.0)[:, None]
        self.rows.append((t, position, quaternion, velocity, omega, *self.forces.loads, self.work.copy(),
                          self.forces.powers[2]))

    def __call__(self, mbs, t) -> bool:
        """After each accepted step: the guard on a finite state, output at the output instants. Returns False to
        stop Exudyn."""
        self.time = t
        q, q_t = self._state()
        finite = np.isfinite(np.column_stack([q.reshape(-1, 6), q_t.reshape(-1, 6)])).all(axis=1)  # per node
        if not finite.all():
            return self.stop_with(Failure.NONFINITE, nonfinite_message(self.scene, finite, self.rows[-1][4], t,
                                                                       self.step))
        self.forces.evaluate(q, q_t)  # once per accepted step: the work, the latches, the output's loads
        latch(self.forces.work)  # the contacts' latched approach speeds, once per accepted step
        power = np.array(self.forces.powers[:2])
        self.work += 0.5 * (t - self.last_time) * (self.power + power)
        self.power, self.last_time = power, t
        if len(self.rows) < self.times.size and t >= self.times[len(self.rows)] - self.margin:
            self.record(t)
            self.progress.update(t)
            if self.stop.is_set() and len(self.rows) < self.times.size:
                return self.stop_with(Failure.INTERRUPTED, stopped_message(t))
        return True

    def stop_with(self, failure: Failure, message: str) -> bool:
        """Record why the run stops; returns False, which tells Exudyn to stop after this step."""
        self.failure, self.message = failure, message
        return False

    def series(self) -> tuple[np.ndarray, ...]:
        """The times (T,) recorded, the position, orientation, velocity and angular velocity (T, N, ·), the slice
        loads and friction power (T, C, S), the flange loads (T, F), the work (T, 2) and the stored energy (T,)."""
        return tuple(np.array([row[k] for row in self.rows]) for k in range(10))
