"""The Exudyn engine: a scene as Exudyn planar rigid bodies, run by an Exudyn solver.

* bodies: ``NodeRigidBody2D`` + ``ObjectRigidBody2D``; a fixed coordinate is a ground
  ``CoordinateConstraint`` (explicit solvers eliminate it, implicit ones solve it);
* gravity: the weights m g as the constant force vector of the force object below, where there is one (a load per
  body is evaluated at every Newton iteration, docs/engines.md), else ``LoadMassProportional`` per body; only when
  gravity is non-zero;
* contacts, loads and drives: see :mod:`.exudyn_connectors`;
* distance constraints: ``ObjectConnectorDistance``; point-on-line constraints: ``ObjectJointPrismatic2D`` with
  ``constrainRotation=False`` (implicit solvers only: Exudyn's explicit solvers reject joints: measured with
  Exudyn 1.13.6, see docs/engines.md); orbit constraints (the constraint cage): the same joint on a *carrier*,
  a body pinned at the world origin whose angle a ``CoordinateConstraint`` ties to body a's (Exudyn has no joint
  on a line that turns with one body but is anchored elsewhere). The carrier takes half of a's rotational
  inertia and a keeps the other half, so the rotation of the pair is a's exactly;
* per-pair state (latched approach speeds), events, output, the energy audit (trapezoid rule over accepted
  steps) and run guards: a ``PostStepUserFunction``, once per accepted step, calling the same compiled
  :func:`bearing_mbs.contact.state.advance_pair_state` as the reference engine.

Exudyn's console output (printed through Python) is captured into ``result.metadata["exudyn_log"]``.
"""

from __future__ import annotations

import contextlib
import io
import math

import numpy as np

from bearing_mbs.contact.kernel import N_PAIR_OUTPUTS
from bearing_mbs.contact.state import advance_pair_state, initial_pair_state
from bearing_mbs.core.failures import Failure
from bearing_mbs.core.interrupt import StopRequest
from bearing_mbs.core.progress import ProgressMeter, notice_if_slow
from bearing_mbs.core.result import Result, Stats
from bearing_mbs.core.scene import DistanceConstraint, OrbitConstraint, Scene
from bearing_mbs.elements import element_forces, has_analytic_jacobian, pack_scene
from bearing_mbs.engines.diagnosis import failure_message, output_grid, step_fix
from bearing_mbs.engines.exudyn.connectors import (
    ForceConnector,
    JacobianConnector,
    add_native_contacts,
    check_native,
    compiled,
    without_pairs,
)
from bearing_mbs.engines.run import Series, assemble_result, progress_meter, state_guard, stop_request, timed_run
from bearing_mbs.spec.fields import SpecError
from bearing_mbs.spec.solver import SolverSpec

#: The share of a body's rotational inertia it keeps when an orbit constraint gives it a carrier (the carrier
#: takes the rest).
CARRIER_SHARE = 0.5


def check_supported(scene: Scene, solver: SolverSpec) -> None:
    """Reject, before anything runs, what Exudyn cannot do with these settings."""
    settings = solver.exudyn
    if scene.constraints and not settings.implicit:
        raise SpecError("solver.exudyn.method", settings.method,
                        "Exudyn's explicit solvers reject joints; with constraints use generalized_alpha "
                        "or trapezoidal_index2, or the reference engine")
    if settings.connector == "native":
        check_native(scene)


def simulate_exudyn(scene: Scene, solver: SolverSpec, end_time: float, progress: ProgressMeter | None = None,
                    spec: dict | None = None, stop: StopRequest | None = None,
                    step_advice: str | None = None) -> Result:
    """Run ``scene`` from 0 to ``end_time`` [s] with Exudyn's settings of ``solver``: build the system (bodies,
    constraints, force elements), watch every accepted step (:class:`_StepMonitor`), solve, and keep what was
    computed (see :func:`bearing_mbs.engines.simulate`)."""
    import exudyn as exu

    check_supported(scene, solver)
    settings = solver.exudyn
    progress = progress_meter(progress)
    packed = pack_scene(scene)
    reference, _ = scene.initial_state()
    latched, events, bounds = initial_pair_state(packed.pairs, solver.penetration_limit)

    container = exu.SystemContainer()  # holds the system: keep it alive while the system runs
    mbs = container.AddSystem()
    nodes, bodies = _add_bodies(mbs, scene)
    joints = _add_constraints(mbs, scene, nodes, bodies)
    connector, jacobian = _add_force_elements(mbs, scene, packed, reference, latched, settings, nodes, bodies)
    # the compiled connector evaluates what the monitor evaluates (the python one the twin, the native one no pairs)
    same_forces = connector if settings.connector == "compiled" else None
    monitor = _StepMonitor(scene, packed, reference, latched, events, bounds, end_time, solver, progress,
                           _JointForces(mbs, joints), stop_request(stop), step_advice, same_forces)
    mbs.SetPostStepUserFunction(monitor)
    mbs.Assemble()

    solved, exudyn_log, wall_time_s = _solve(mbs, exu, settings, end_time, progress, scene, solver, monitor,
                                             step_advice)
    stats = _stats(mbs, connector, settings.connector == "native", wall_time_s)
    if not solved and monitor.failure == Failure.NONE:
        monitor.fail(Failure.SOLVER_FAILED, _solver_failure(scene, solver, monitor.time, _last_line(exudyn_log),
                                                            step_advice))
    series = Series.from_rows(monitor.rows)
    if monitor.failure != Failure.NONE:  # keep the state where the run stopped
        series = series.kept(len(monitor.rows), monitor.stop_row())
    metadata = {"connector": settings.connector, "jacobian": _jacobian_used(settings, jacobian),
                "jacobian_user_evaluations": jacobian.evaluations if jacobian else 0, "exudyn_log": exudyn_log,
                "exudyn_version": exu.__version__}
    return assemble_result("exudyn", settings, scene, series, events, stats, monitor.failure, monitor.message, spec,
                           metadata)


def _add_bodies(mbs, scene: Scene) -> tuple[list, list]:
    """One rigid body per scene body (a body with an orbit constraint keeps :data:`CARRIER_SHARE` of its rotational
    inertia), its fixed coordinates tied to the ground; returns the nodes and the bodies."""
    from exudyn.itemInterface import (
        MarkerNodeCoordinate,
        NodePointGround,
        NodeRigidBody2D,
        ObjectConnectorCoordinate,
        ObjectRigidBody2D,
    )

    carried = {c.body_a for c in scene.constraints if isinstance(c, OrbitConstraint)}
    inertia = [b.inertia * (CARRIER_SHARE if i in carried else 1.0) for i, b in enumerate(scene.bodies)]
    nodes = [mbs.AddNode(NodeRigidBody2D(referenceCoordinates=list(b.position), initialVelocities=list(b.velocity)))
             for b in scene.bodies]
    bodies = [mbs.AddObject(ObjectRigidBody2D(nodeNumber=node, mass=b.mass, inertia=j))
              for node, b, j in zip(nodes, scene.bodies, inertia)]

    ground_marker = None
    for node, body in zip(nodes, scene.bodies):
        for c in range(3):
            if not body.free[c]:
                if ground_marker is None:
                    ground_node = mbs.AddNode(NodePointGround())
                    ground_marker = mbs.AddMarker(MarkerNodeCoordinate(nodeNumber=ground_node, coordinate=0))
                marker = mbs.AddMarker(MarkerNodeCoordinate(nodeNumber=node, coordinate=c))
                mbs.AddObject(ObjectConnectorCoordinate(markerNumbers=[ground_marker, marker]))
    return nodes, bodies


def _weights(scene: Scene) -> np.ndarray:
    """The bodies' weights as generalized forces (m g_x, m g_y, 0 per body) [N]."""
    return np.array([[b.mass * scene.gravity[0], b.mass * scene.gravity[1], 0.0] for b in scene.bodies]).ravel()


def _add_gravity_loads(mbs, scene: Scene, bodies: list) -> None:
    """Gravity as one ``LoadMassProportional`` per body (where no force object carries the weights)."""
    from exudyn.itemInterface import LoadMassProportional, MarkerBodyMass

    for body in bodies:
        marker = mbs.AddMarker(MarkerBodyMass(bodyNumber=body))
        mbs.AddLoad(LoadMassProportional(markerNumber=marker, loadVector=[*scene.gravity, 0.0]))


def _add_constraints(mbs, scene: Scene, nodes: list, bodies: list) -> list:
    """The scene's constraints as Exudyn joints (see the module's docstring); returns the joints, whose reaction
    forces are the result's constraint forces."""
    from exudyn.itemInterface import (
        MarkerBodyPosition,
        MarkerBodyRigid,
        ObjectConnectorDistance,
        ObjectJointPrismatic2D,
    )

    carriers: dict[int, int] = {}
    joints = []
    for constraint in scene.constraints:
        if isinstance(constraint, DistanceConstraint):
            markers = [mbs.AddMarker(MarkerBodyPosition(bodyNumber=bodies[i], localPosition=[0, 0, 0]))
                       for i in (constraint.body_a, constraint.body_b)]
            joints.append(mbs.AddObject(ObjectConnectorDistance(markerNumbers=markers, distance=constraint.length)))
        else:  # the centre of b on a line of a (or of a's carrier): (p_a − c_b)·n = 0 with n normal to the line
            orbit = isinstance(constraint, OrbitConstraint)
            if orbit and constraint.body_a not in carriers:
                carriers[constraint.body_a] = _add_carrier(mbs, scene, nodes, constraint.body_a)
            holder = carriers[constraint.body_a] if orbit else bodies[constraint.body_a]
            on_line = mbs.AddMarker(MarkerBodyRigid(bodyNumber=holder,
                                                    localPosition=[0, 0, 0] if orbit else [*constraint.anchor, 0]))
            centre = mbs.AddMarker(MarkerBodyRigid(bodyNumber=bodies[constraint.body_b], localPosition=[0, 0, 0]))
            dx, dy = constraint.direction
            joints.append(mbs.AddObject(ObjectJointPrismatic2D(markerNumbers=[centre, on_line], axisMarker0=[1, 0, 0],
                                                               normalMarker1=[-dy, dx, 0], constrainRotation=False)))
    return joints


def _add_carrier(mbs, scene: Scene, nodes: list, index: int) -> int:
    """The carrier of body ``index``: pinned at the world origin, turning with the body, with the rest of its
    rotational inertia (1 − :data:`CARRIER_SHARE`); returns the carrier's body."""
    from exudyn.itemInterface import (
        MarkerNodeCoordinate,
        NodePointGround,
        NodeRigidBody2D,
        ObjectConnectorCoordinate,
        ObjectRigidBody2D,
    )

    body = scene.bodies[index]
    node = mbs.AddNode(NodeRigidBody2D(referenceCoordinates=[0.0, 0.0, body.position[2]],
                                       initialVelocities=[0.0, 0.0, body.velocity[2]]))
    carrier = mbs.AddObject(ObjectRigidBody2D(nodeNumber=node, mass=body.mass,
                                              inertia=body.inertia * (1 - CARRIER_SHARE)))
    ground = mbs.AddMarker(MarkerNodeCoordinate(nodeNumber=mbs.AddNode(NodePointGround()), coordinate=0))
    for c in range(2):  # pinned at the origin
        mbs.AddObject(ObjectConnectorCoordinate(markerNumbers=[
            ground, mbs.AddMarker(MarkerNodeCoordinate(nodeNumber=node, coordinate=c))]))
    mbs.AddObject(ObjectConnectorCoordinate(markerNumbers=[  # turning with the body
        mbs.AddMarker(MarkerNodeCoordinate(nodeNumber=nodes[index], coordinate=2)),
        mbs.AddMarker(MarkerNodeCoordinate(nodeNumber=node, coordinate=2))]))
    return carrier


def _add_force_elements(mbs, scene: Scene, packed, reference: np.ndarray, latched: np.ndarray, settings,
                        nodes: list, bodies: list):
    """The contacts (Exudyn's own with the native connector) and every other force element, through our compiled
    kernels in one generic ODE2 object, compiled here, outside the timed region, which also carries the weights;
    gravity loads where there is no such object. Returns the force connector and the Jacobian connector (None where
    not used)."""
    from exudyn.itemInterface import ObjectGenericODE2, ObjectGround

    n = scene.coordinate_count
    connector = jacobian = None
    native = settings.connector == "native"
    if native:
        add_native_contacts(mbs, scene, bodies, mbs.AddObject(ObjectGround()) if scene.pairs else -1)
    force_scene = without_pairs(packed) if native else packed
    if (scene.pairs and not native) or scene.forces:
        # the other force elements next to native contacts go through the compiled kernel
        with notice_if_slow("compiling the force kernels for Exudyn (once after an install or a source change, "
                            "about 5 s; later runs load them from the cache)"):
            # the kernels are compiled (or loaded) here, outside the timed region
            connector = ForceConnector(force_scene, reference, latched,
                                       compiled_kernel=settings.connector != "python")
            if settings.implicit and settings.jacobian == "analytic" and has_analytic_jacobian(scene):
                jacobian = JacobianConnector(connector)
        mbs.AddObject(ObjectGenericODE2(nodeNumbers=nodes, massMatrix=np.zeros((n, n)), forceUserFunction=connector,
                                        jacobianUserFunction=jacobian or 0,
                                        forceVector=_weights(scene) if any(scene.gravity) else []))
    elif any(scene.gravity):
        _add_gravity_loads(mbs, scene, bodies)
    return connector, jacobian


def _solve(mbs, exu, settings, end_time: float, progress: ProgressMeter, scene: Scene, solver: SolverSpec,
           monitor: _StepMonitor, step_advice: str | None) -> tuple[bool, str, float]:
    """Exudyn's solver over [0, ``end_time``], its console output captured; an exception (a solver that gives up)
    is a ``SOLVER_FAILED`` stop unless the monitor stopped the run first. Returns whether it solved, the console
    output and the wall time [s]."""
    simulation = _simulation_settings(exu, settings, end_time)
    log = io.StringIO()
    solved = False
    with timed_run(progress, end_time, f"{scene.name} (exudyn {settings.method}, {settings.connector})") as clock:
        try:
            with contextlib.redirect_stdout(log):  # Exudyn prints through Python
                solved = mbs.SolveDynamic(simulation, solverType=getattr(exu.DynamicSolverType, settings.entry.exudyn))
        except Exception as error:  # noqa: BLE001 (Exudyn raises when a solver gives up)
            solved = False
            if monitor.failure == Failure.NONE:
                monitor.fail(Failure.SOLVER_FAILED, _solver_failure(scene, solver, monitor.time, str(error),
                                                                    step_advice))
    return solved, log.getvalue(), clock.wall_time_s


def _stats(mbs, connector, native: bool, wall_time_s: float) -> Stats:
    """The run's cost from Exudyn's solver counters and the connector's force evaluations (None with the native
    connector, whose contacts Exudyn evaluates uncounted)."""
    iteration = mbs.sys["dynamicSolver"].it
    return Stats(
        steps=int(iteration.currentStepIndex) - 1,  # Exudyn counts from 1
        rejected_steps=int(iteration.rejectedAutomaticStepSizeSteps),
        force_evaluations=None if native else connector.evaluations if connector else 0,
        newton_iterations=int(iteration.newtonStepsCount),
        jacobian_evaluations=int(iteration.newtonJacobiCount),
        wall_time_s=wall_time_s,
    )


def _simulation_settings(exu, settings, end_time):
    s = exu.SimulationSettings()
    # Eigen's sparse LU instead of Exudyn's default dense inverse: 0.24 ms less per Jacobian update of the lubricated
    # seed bearing (87 unknowns), and a singular matrix is still reported (docs/engines.md)
    s.linearSolver.solverType = exu.LinearSolverType.EigenSparse
    s.solution.file.write = False
    s.show.computationTime = False
    s.show.statistics = False
    ti = s.timeIntegration
    ti.verboseMode = 0
    ti.endTime = end_time
    ti.numberOfSteps = max(1, math.ceil(end_time / settings.step * (1 - 1e-12)))
    ti.discontinuous.useRecommendedStepSize = False  # else contacts shrink the step to 1e-8 s (docs/engines.md)
    ti.explicit.computeEndOfStepAccelerations = False  # saves one force evaluation per step
    # Implicit solvers halve the step where Newton fails (stick-slip transitions, contact onsets) and recover;
    # on smooth problems the step stays the requested one.
    ti.adaptiveStep = True
    ti.automaticStepSize = settings.adaptive
    ti.absoluteTolerance = settings.tolerance
    ti.relativeTolerance = settings.tolerance
    ti.minimumStepSize = min(1e-14, 1e-6 * settings.step)  # below the largest step, however short (a 1e-16 s step)
    ti.generalizedAlpha.spectralRadius = settings.spectral_radius
    ti.newton.relativeTolerance = settings.tolerance
    return s


def _jacobian_used(settings, jacobian) -> str | None:
    """How the force elements were differentiated: None for explicit methods."""
    if not settings.implicit:
        return None
    return "analytic" if jacobian else "numerical"


class _JointForces:
    """The magnitudes of the joints' reaction forces [N]: the norm of each joint's Lagrange multipliers, read in one
    call from Exudyn's algebraic coordinates. Equal to the norm of each joint's force output (``Force`` of a
    distance connector, ``ForceLocal`` of a prismatic joint) to rounding (measured: identical for distance
    connectors, within 4e-16 relative for prismatic joints); reading each joint's output instead costs about 6 µs
    per joint and output row (docs/engines.md); the norms are taken in one reduction (a norm per joint cost about 3 µs,
    a third of the step monitor's time at 5e-5 s under a profiler)."""

    def __init__(self, mbs, joints: list):
        self.mbs, self.joints = mbs, joints
        self._order = self._starts = None  # the joints' algebraic coordinates, known once the system is assembled

    def __call__(self) -> np.ndarray:
        if not self.joints:
            return np.zeros(0)
        data = self.mbs.systemData
        if self._order is None:
            indices = [np.asarray(data.GetObjectLTGAE(joint), dtype=int) for joint in self.joints]
            self._order = np.concatenate(indices)
            self._starts = np.cumsum([0] + [index.size for index in indices[:-1]])
        multipliers = np.asarray(data.GetAECoordinates())[self._order]
        return np.sqrt(np.add.reduceat(multipliers * multipliers, self._starts))


def _solver_failure(scene, solver, t, detail, step_advice=None) -> str:
    settings = solver.exudyn
    what = "Newton's method did not converge" if settings.implicit else "the solver stopped"
    hint = ""
    if settings.implicit and any(p.law.friction_law == "dead_zone" for p in scene.pairs):
        hint = " The dead_zone friction law is discontinuous, which Newton's method cannot follow: use erf."
    return (f"t = {t:.6g} s: Exudyn's {settings.method} failed: {what} ({detail}). Likely fix: "
            f"{step_fix(solver, step_advice)}.{hint}")


def _last_line(text: str) -> str:
    lines = [line.strip() for line in text.splitlines() if line.strip()]
    return lines[-1] if lines else "no message"


class _StepMonitor:
    """PostStepUserFunction: per-pair state, events, output at output instants, guards, progress."""

    def __init__(self, scene, packed, reference, latched, events, bounds, end_time, solver, progress,
                 constraint_forces, stop, step_advice=None, connector=None):
        self.scene, self.packed, self.reference, self.stop = scene, packed, reference, stop
        self.connector = connector  # the compiled force connector, whose last evaluation's power it may reuse
        self.step_advice = step_advice
        self.latched, self.events, self.bounds = latched, events, bounds
        self.solver, self.progress, self.constraint_forces = solver, progress, constraint_forces
        self.output_times = output_grid(end_time, solver.output_interval)
        self.margin = 1e-3 * min(solver.exudyn.step, solver.output_interval)
        self.rows: list[tuple] = []
        self.message, self.failure, self.time = "", Failure.NONE, 0.0
        self.q, self.v = reference.copy(), np.array([b.velocity for b in scene.bodies], dtype=float).ravel()
        self._forces = np.empty(reference.size)
        self._pairs = np.empty((len(latched), N_PAIR_OUTPUTS))
        self._forces_of = {complete: compiled(element_forces, packed.elements, 0.0, self.q, self.v, latched,
                                              self._forces, self._pairs, complete) for complete in (False, True)}
        self._advance = compiled(advance_pair_state, packed.pairs, self.q, self.v, 0.0, latched, events, bounds)
        self.work = np.zeros(2)  # supplied, dissipated [J]
        self._last_power = np.array(self._evaluate(0.0))
        self._progress_every, self._calls = max(1, int(end_time / solver.exudyn.step / 200)), 0
        self._record(0.0, [0.0] * len(scene.constraints))

    def _evaluate(self, t, complete=False):
        return self._forces_of[complete](self.packed.elements, t, self.q, self.v, self.latched, self._forces,
                                         self._pairs, complete)

    def _power(self, t):
        """The (supplied, dissipated) power [W] at the current state: the connector's last evaluation where it was
        at this state (as Exudyn's accepted steps are), else evaluated here."""
        power = self.connector.power_at(t, self.q, self.v) if self.connector is not None else None
        return power if power is not None else self._evaluate(t)

    def _row(self, t, constraint_forces=None) -> tuple:
        """The output row of the current state at t [s] (the pairs' outputs evaluated in full)."""
        self._evaluate(t, complete=True)
        forces = self.constraint_forces() if constraint_forces is None else constraint_forces
        return t, self.q.copy(), self.v.copy(), self._pairs.copy(), self.work.copy(), np.array(forces)

    def _record(self, t, constraint_forces=None):
        self.rows.append(self._row(t, constraint_forces))

    def __call__(self, mbs, t):
        """After each accepted step: the guards, the work (trapezoid rule), the pairs' state, output at the output
        instants, progress and the stop request. Returns False to stop Exudyn after this step."""
        data = mbs.systemData
        q = self.reference + np.asarray(data.GetODE2Coordinates())[: self.reference.size]
        v = np.asarray(data.GetODE2Coordinates_t())[: self.reference.size]
        kind, coordinate = state_guard(q, v, self.solver.speed_limit)
        if kind != Failure.NONE:  # named from the last good state
            return self._stop(kind, t, coordinate, self.q, self.v)
        h = t - self.time
        self.q, self.v, self.time = q, v, t
        power = np.array(self._power(t))  # before the latch update: the forces of the step just taken
        self.work += 0.5 * h * (self._last_power + power)
        self._last_power = power
        _, worst = self._advance(self.packed.pairs, q, v, t, self.latched, self.events, self.bounds)
        if worst >= 0:
            return self._stop(Failure.PENETRATION, t, worst, q, v)
        if len(self.rows) < self.output_times.size and t >= self.output_times[len(self.rows)] - self.margin:
            self._record(t)
        self._calls += 1
        if self._calls % self._progress_every == 0:
            self.progress.update(t)
        if self.stop.is_set():
            return self._stop(Failure.INTERRUPTED, t, -1, q, v)
        return True

    def _stop(self, failure: Failure, t: float, culprit: int, q, v) -> bool:
        """Stop with ``failure`` at t [s], its message made from the state (q, v) and the culprit (coordinate or
        pair)."""
        return self.fail(failure, failure_message(failure, self.scene, self.solver, t, culprit, q, v, self.latched,
                                                  self.solver.exudyn.step, self.step_advice))

    def fail(self, failure: Failure, message: str) -> bool:
        """Record the first stop and its message; returns False, which tells Exudyn to stop after this step."""
        if self.failure == Failure.NONE:
            self.failure, self.message = failure, message
        return False

    def stop_row(self):
        """The output row of the state where the run stopped, or None when the last row already holds it."""
        return self._row(self.time) if self.rows[-1][0] < self.time else None
