"""Exudyn's cost per Newton iteration on the lubricated seed bearing, and each option that cuts it (issue 30, item 3):
``benchmarks/out/exudyn_overhead.json``.

1. **Where an iteration's time goes** (generalized-alpha, analytic Jacobian, h = 1e-5 s, 20 ms): the CPU time inside
   the force user function, the Jacobian user function and the step monitor (each timed around its call), the rest
   being Exudyn's own work (residual of bodies and joints, linear solves, the pybind11 crossings); and the floor of a
   crossing: a trivial force function over 51 coordinates in Exudyn's generalized-alpha.
2. **Options that keep the results** (to rounding, or to Newton's tolerance for the linear solver), each switched
   back to what it replaced in the same process, interleaved, the faster of ``REPEATS`` runs (CPU time of the process:
   the machine is shared, and Exudyn runs on one thread), 10 ms at 1e-5 and 2e-5 s: the kernels called through their
   compiled entry points (against numba's dispatcher), the step monitor's power taken from the force connector
   (against a fresh evaluation), the joints' forces from the multipliers (against ``GetObjectOutput`` per joint),
   the weights as the force object's constant vector (against a ``LoadMassProportional`` per body), the forces
   returned as a list (against an array), Eigen's sparse LU (against Exudyn's dense inverse and Eigen's dense LU).
3. **Newton settings, which change the error**: one revolution (0.04 s) each, with the cage-speed, slip and roller-load
   errors against the scenario's fine reference (bench_revolution.py's), next to the reference engine's
   generalized-α at the same steps.
"""

from __future__ import annotations

import contextlib
import math
import time

import numpy as np
from bench_revolution import REVOLUTION, TARGET_ERROR, exudyn, fine_reference, reference, spec_of

from bearing_mbs.engines import simulate
from bearing_mbs.engines.exudyn import connectors, engine
from bearing_mbs.studies.convergence import errors

from common import write

#: Runs of each A/B variant; the smallest CPU time counts.
REPEATS = 5
#: The A/B window [s] (from the start) and the steps [s] it is measured at.
WINDOW = 0.01
STEPS = (1e-5, 2e-5)
#: The breakdown's step [s] and window [s].
BREAKDOWN_STEP, BREAKDOWN_WINDOW = 1e-5, 0.02


def cpu_run(scene, solver, end_time):
    """A run and its CPU time [s]."""
    start = time.process_time()
    result = simulate(scene, solver, end_time)
    return result, time.process_time() - start


# ---- 2. what each option replaced, switched back on for the A/B ----

def _dispatcher(function, *args):
    return function  # numba's dispatcher: matches the argument types on every call


def _joint_outputs(self):
    import exudyn as exu

    kinds = exu.OutputVariableType
    return [float(np.linalg.norm(self.mbs.GetObjectOutput(
        joint, kinds.Force if "Distance" in self.mbs.GetObject(joint)["objectType"] else kinds.ForceLocal)))
        for joint in self.joints]


def _linear_solver(name):
    import exudyn as exu

    original = engine._simulation_settings

    def settings(exu_module, solver_settings, end_time):
        simulation = original(exu_module, solver_settings, end_time)
        simulation.linearSolver.solverType = getattr(exu.LinearSolverType, name)
        return simulation

    return [(engine, "_simulation_settings", settings)]


def _gravity_loads():
    original = engine._add_force_elements

    def add(mbs, scene, packed, reference_state, latched, settings, nodes, bodies):
        added = original(mbs, scene, packed, reference_state, latched, settings, nodes, bodies)
        engine._add_gravity_loads(mbs, scene, bodies)
        return added

    return [(engine, "_weights", lambda scene: np.zeros(3 * len(scene.bodies))), (engine, "_add_force_elements", add)]


def _array_forces():
    listed = connectors.ForceConnector.__call__

    def call(self, mbs, t, item_number, q, q_t):
        listed(self, mbs, t, item_number, q, q_t)
        return self._forces

    return [(connectors.ForceConnector, "__call__", call)]


#: option -> (what the option replaced, patched back in), with its description.
OPTIONS = {
    "as_built": ([], "every option on (the engine as it is)"),
    "dispatcher": ([(connectors, "compiled", _dispatcher), (engine, "compiled", _dispatcher)],
                   "kernels called through numba's dispatcher instead of their compiled entry points"),
    "monitor_evaluates_power": ([(connectors.ForceConnector, "power_at", lambda self, t, q, v: None)],
                                "the step monitor evaluates the forces for the energy audit again"),
    "joint_outputs": ([(engine._JointForces, "__call__", _joint_outputs)],
                      "joint forces from GetObjectOutput per joint instead of the multipliers"),
    "gravity_loads": (None, "a LoadMassProportional per body instead of the force object's constant vector"),
    "array_return": (None, "the force function returns a numpy array instead of a list"),
    "exudyn_dense_inverse": (None, "Exudyn's default linear solver (EXUdense: dense inverse)"),
    "eigen_dense_lu": (None, "Eigen's dense LU with partial pivoting"),
    "all_replaced": (None, "every option replaced at once: the engine before issue 30"),
}


def _patches(option):
    factories = {"gravity_loads": _gravity_loads, "array_return": _array_forces,
                 "exudyn_dense_inverse": lambda: _linear_solver("EXUdense"),
                 "eigen_dense_lu": lambda: _linear_solver("EigenDense")}
    if option == "all_replaced":
        return [patch for name in OPTIONS if name not in ("as_built", "all_replaced", "eigen_dense_lu")
                for patch in _patches(name)]
    patches = OPTIONS[option][0]
    return factories[option]() if patches is None else patches


@contextlib.contextmanager
def patched(patches):
    saved = [(owner, name, getattr(owner, name)) for owner, name, _ in patches]
    for owner, name, value in patches:
        setattr(owner, name, value)
    try:
        yield
    finally:
        for owner, name, value in saved:
            setattr(owner, name, value)


def options_ab(step: float) -> dict:
    spec, scene = spec_of("lubricated", exudyn(step))
    for option in OPTIONS:  # warm-up: compilation and caches
        with patched(_patches(option)):
            simulate(scene, spec.solver, 2e-4)
    best = {}
    for _ in range(REPEATS):
        for option in OPTIONS:
            with patched(_patches(option)):
                result, cpu = cpu_run(scene, spec.solver, WINDOW)
            if option not in best or cpu < best[option][1]:
                best[option] = (result, cpu)
    built, built_cpu = best["as_built"]
    figures = {}
    for option, (result, cpu) in best.items():
        stats = result.stats
        figures[option] = {
            "description": OPTIONS[option][1], "status": result.status, "cpu_time_s": cpu,
            "cost_over_as_built": cpu / built_cpu, "newton_iterations": stats.newton_iterations,
            "jacobian_evaluations": stats.jacobian_evaluations, "force_evaluations": stats.force_evaluations,
            "cpu_microseconds_per_force_evaluation": cpu / stats.force_evaluations * 1e6,
            "largest_velocity_difference_to_as_built": float(np.abs(result.velocity - built.velocity).max()),
        }
    return figures


# ---- 1. the breakdown of an iteration ----

def breakdown() -> dict:
    spec, scene = spec_of("lubricated", exudyn(BREAKDOWN_STEP))
    spent: dict[str, list] = {}

    def timed(owner, name, key):
        original = getattr(owner, name)

        def call(*args):
            start = time.process_time()
            value = original(*args)
            spent.setdefault(key, [0.0, 0])
            spent[key][0] += time.process_time() - start
            spent[key][1] += 1
            return value

        return owner, name, call

    simulate(scene, spec.solver, 2e-4)
    with patched([timed(connectors.ForceConnector, "__call__", "force_user_function"),
                  timed(connectors.JacobianConnector, "__call__", "jacobian_user_function"),
                  timed(engine._StepMonitor, "__call__", "step_monitor")]):
        result, cpu = cpu_run(scene, spec.solver, BREAKDOWN_WINDOW)
    stats = result.stats
    parts = {key: {"calls": calls, "cpu_time_s": seconds, "microseconds_per_call": seconds / calls * 1e6,
                   "microseconds_per_force_evaluation": seconds / stats.force_evaluations * 1e6}
             for key, (seconds, calls) in spent.items()}
    rest = cpu - sum(seconds for seconds, _ in spent.values())
    parts["exudyn_and_crossings"] = {"cpu_time_s": rest,
                                     "microseconds_per_force_evaluation": rest / stats.force_evaluations * 1e6}
    kernel = _kernel_alone(scene)
    return {"step_s": BREAKDOWN_STEP, "window_s": BREAKDOWN_WINDOW, "cpu_time_s": cpu, "steps": stats.steps,
            "newton_iterations": stats.newton_iterations, "jacobian_evaluations": stats.jacobian_evaluations,
            "force_evaluations": stats.force_evaluations,
            "cpu_microseconds_per_force_evaluation": cpu / stats.force_evaluations * 1e6,
            "parts": parts, "kernel_alone_microseconds": kernel, "crossing_floor": crossing_floor()}


def _kernel_alone(scene) -> float:
    """The force kernel's own time per evaluation [µs] at the scene's start, in a compiled loop (no crossing)."""
    import numba

    from bearing_mbs.contact.kernel import N_PAIR_OUTPUTS
    from bearing_mbs.elements import element_forces, pack_scene

    @numba.njit
    def loop(elements, q, v, latched, forces, pairs, count):
        total = 0.0
        for _ in range(count):
            total += element_forces(elements, 0.0, q, v, latched, forces, pairs, False)[1]
        return total

    q, _ = scene.initial_state()
    v = np.array([b.velocity for b in scene.bodies], dtype=float).ravel()
    args = (pack_scene(scene).elements, q, v, np.zeros(len(scene.pairs)), np.empty(q.size),
            np.empty((len(scene.pairs), N_PAIR_OUTPUTS)))
    loop(*args, 1)
    count = 2000
    best = math.inf
    for _ in range(3):
        start = time.process_time()
        loop(*args, count)
        best = min(best, (time.process_time() - start) / count * 1e6)
    return best


def crossing_floor(bodies: int = 17, steps: int = 20000) -> dict:
    """A trivial force function over ``bodies`` planar bodies in Exudyn's generalized-alpha, against no function:
    the CPU time [µs] of one call (returning a preallocated array), and with the two list conversions our
    connector makes."""
    import exudyn as exu
    from exudyn.itemInterface import NodeRigidBody2D, ObjectGenericODE2, ObjectRigidBody2D

    n = 3 * bodies
    zeros = np.zeros(n)

    def trivial(mbs, t, item, q, q_t):
        return zeros

    def converting(mbs, t, item, q, q_t):
        np.asarray(q), np.asarray(q_t)
        return zeros

    def run(function):
        container = exu.SystemContainer()
        mbs = container.AddSystem()
        nodes = [mbs.AddNode(NodeRigidBody2D(referenceCoordinates=[i, 0, 0], initialVelocities=[0, 0, 1]))
                 for i in range(bodies)]
        for node in nodes:
            mbs.AddObject(ObjectRigidBody2D(nodeNumber=node, mass=1.0, inertia=1.0))
        if function is not None:
            mbs.AddObject(ObjectGenericODE2(nodeNumbers=nodes, massMatrix=np.zeros((n, n)), forceUserFunction=function))
        mbs.Assemble()
        settings = exu.SimulationSettings()
        settings.solution.file.write = False
        settings.timeIntegration.numberOfSteps = steps
        settings.timeIntegration.endTime = steps * 1e-5
        settings.timeIntegration.verboseMode = 0
        start = time.process_time()
        mbs.SolveDynamic(settings)
        iterations = mbs.sys["dynamicSolver"].it.newtonStepsCount
        return time.process_time() - start, iterations + steps  # a call per iteration and per step's start

    none, _ = min(run(None) for _ in range(2))
    trivial_time, calls = min(run(trivial) for _ in range(2))
    converting_time, _ = min(run(converting) for _ in range(2))
    return {"coordinates": n, "calls": calls,
            "microseconds_per_call": (trivial_time - none) / calls * 1e6,
            "microseconds_per_call_with_list_conversions": (converting_time - none) / calls * 1e6}


# ---- 3. Newton's settings, at equal error ----

def _newton(**changes):
    def apply(simulation):
        for name, value in changes.items():
            setattr(simulation.timeIntegration.newton, name, value)
    return apply


#: name -> (engine overrides, Exudyn Newton settings changed or None)
NEWTON = {
    **{f"exudyn_{step:g}_tolerance_{tolerance:g}": (exudyn(step) + [f"solver.exudyn.tolerance={tolerance}"], None)
       for step in STEPS for tolerance in (1e-6, 1e-4, 1e-3)},
    **{f"exudyn_{step:g}_jacobian_every_step": (exudyn(step), _newton(modifiedNewtonJacUpdatePerStep=True))
       for step in STEPS},
    "exudyn_2e-05_full_newton": (exudyn(2e-5), _newton(useModifiedNewton=False)),
    "exudyn_2e-05_contractivity_0.2": (exudyn(2e-5), _newton(modifiedNewtonContractivity=0.2)),
    **{f"exudyn_{step:g}_increment_criterion_1e-8": (
        exudyn(step), _newton(residualMode=1, relativeTolerance=1e-8, absoluteTolerance=1e-8)) for step in STEPS},
    # more numerical damping (ρ∞ = 0.5 instead of 0.9): fewer Jacobian updates, on either engine
    **{f"exudyn_{step:g}_tolerance_0.001_rho_0.5": (
        exudyn(step, tolerance=1e-3) + ["solver.exudyn.spectral_radius=0.5"], None) for step in (2e-5, 3e-5)},
    **{f"reference_{step:g}": (reference("generalized_alpha", step, 1e-6), None) for step in STEPS},
    **{f"reference_{step:g}_rho_0.5": (
        reference("generalized_alpha", step, 1e-6) + ["solver.reference.spectral_radius=0.5"], None)
       for step in (2e-5, 3e-5)},
}


def newton_settings() -> dict:
    truth = fine_reference("lubricated")
    runs = {}
    prepared = {name: (spec_of("lubricated", overrides), change) for name, (overrides, change) in NEWTON.items()}

    def with_newton(change):
        if change is None:
            return []
        original = engine._simulation_settings

        def settings(exu_module, solver_settings, end_time):
            simulation = original(exu_module, solver_settings, end_time)
            change(simulation)
            return simulation

        return [(engine, "_simulation_settings", settings)]

    for (spec, scene), change in prepared.values():
        with patched(with_newton(change)):
            simulate(scene, spec.solver, 2e-4)
    best = {}
    for _ in range(2):
        for name, ((spec, scene), change) in prepared.items():
            with patched(with_newton(change)):
                start = time.perf_counter()
                result, cpu = cpu_run(scene, spec.solver, REVOLUTION)
                wall = time.perf_counter() - start
            if name not in best or cpu < best[name][1]:
                best[name] = (result, cpu, wall)
    for name, (result, cpu, wall) in best.items():
        (spec, scene), _ = prepared[name]
        norms = errors(spec, scene, result, truth) if result.success else {}
        stats = result.stats
        runs[name] = {"status": result.status, "cpu_time_s_per_revolution": cpu, "wall_time_s_per_revolution": wall,
                      "steps": stats.steps, "newton_iterations": stats.newton_iterations,
                      "jacobian_evaluations": stats.jacobian_evaluations,
                      "force_evaluations": stats.force_evaluations,
                      "cage_speed_error": norms.get("cage_speed", math.nan), "slip_error": norms.get("slips", math.nan),
                      "roller_load_error": norms.get("roller_loads", math.nan)}
        print(name, {k: runs[name][k] for k in ("status", "cpu_time_s_per_revolution", "newton_iterations",
                                                 "cage_speed_error")})
    return runs


def summarize(runs: dict) -> dict:
    """Each engine's cheapest run (CPU time) within the target cage-speed error, and at each reference run's error
    the cheapest Exudyn run as good or better."""
    def cheapest(prefix, error):
        sound = [name for name, run in runs.items() if name.startswith(prefix) and run["status"] == "success"
                 and run["cage_speed_error"] <= error]
        return min(sound, key=lambda name: runs[name]["cpu_time_s_per_revolution"], default=None)

    def ratio(slow, fast):
        if slow is None or fast is None:
            return None
        return runs[slow]["cpu_time_s_per_revolution"] / runs[fast]["cpu_time_s_per_revolution"]

    exudyn_best, reference_best = cheapest("exudyn", TARGET_ERROR), cheapest("reference", TARGET_ERROR)
    at_reference_error = {}
    for name, run in runs.items():
        if name.startswith("reference") and run["status"] == "success":
            match = cheapest("exudyn", run["cage_speed_error"])
            at_reference_error[name] = {"exudyn": match, "exudyn_over_reference": ratio(match, name)}
    return {"target_cage_speed_error": TARGET_ERROR, "exudyn_best": exudyn_best, "reference_best": reference_best,
            "exudyn_best_over_reference_best": ratio(exudyn_best, reference_best),
            "at_each_reference_error": at_reference_error}


def main() -> dict:
    report = {"case": "seed_hss_steady (lubricated, constraint cage), Exudyn generalized-alpha with the analytic "
                      "Jacobian; CPU times of the process (Exudyn runs on one thread), the faster of repeated runs"}
    report["breakdown"] = breakdown()
    write("exudyn_overhead", report)
    report["options"] = {f"{step:g}": options_ab(step) for step in STEPS}
    write("exudyn_overhead", report)
    report["newton"] = newton_settings()
    report["summary"] = summarize(report["newton"])
    write("exudyn_overhead", report)
    return report


if __name__ == "__main__":
    main()
