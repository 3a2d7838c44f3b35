"""The Exudyn engine's shortcuts around its user functions change no result (docs/engines.md, "Exudyn's cost per
Newton iteration").

References and tolerances:
* the joints' reaction forces read from Exudyn's Lagrange multipliers against Exudyn's own force output of each
  joint (``Force`` of a distance connector, ``ForceLocal`` of a prismatic joint), at every output instant of case 5
  (a distance constraint) and of the lubricated seed bearing's constraint cage (15 prismatic joints): equal to
  1e-14 relative (measured: identical, and 4e-16);
* the step monitor's power, taken from the force connector's last evaluation at the accepted state, against a
  fresh evaluation of the compiled kernel at that state: the energy audit (work supplied and dissipated) and every
  output identical, bit for bit, and the shortcut taken at every accepted step;
* the compiled functions called without numba's type dispatch return what the dispatcher returns, bit for bit;
* gravity, carried as the force object's constant vector where there is one and as a load per body where there is
  none, against free fall's closed form y = y0 + v0 t − g t²/2: generalized-alpha integrates a constant
  acceleration exactly, so to 1e-12 m (rounding of 0.5 m over 200 steps).
"""

from __future__ import annotations

import numpy as np
import pytest

from bearing_mbs.core.scene import GROUND, Body, ContactPair, Scene
from bearing_mbs.elements import element_forces, pack_scene
from bearing_mbs.engines import simulate
from bearing_mbs.engines.exudyn import connectors, engine
from bearing_mbs.models import build_scene, load_spec
from bearing_mbs.models.building import pair_law
from bearing_mbs.spec import ContactSpec, ExudynSolver, SolverSpec

from cases import SCENARIOS, seed_spec

#: The lubricated seed bearing (constraint cage: 15 prismatic joints on a carrier), 2 ms at generalized-alpha's step.
BEARING = ["solver.engine=exudyn", "solver.exudyn.method=generalized_alpha", "solver.exudyn.step=2e-5",
           "scenario.end_time=0.002", "analysis.start=0.001", "solver.output_interval=1e-4"]
#: Case 5: two balls joined by a distance constraint, on Exudyn's generalized-alpha.
CASE5 = ["solver.engine=exudyn", "solver.exudyn.method=generalized_alpha", "solver.exudyn.step=2e-6",
         "scenario.end_time=0.01"]


def bearing():
    spec = load_spec(SCENARIOS / "seed_hss_steady.toml", BEARING)
    return spec, build_scene(spec)


@pytest.mark.parametrize("which", ["case5", "bearing"])
def test_joint_forces_from_the_multipliers_equal_exudyns_joint_outputs(which, monkeypatch):
    import exudyn as exu

    spec = seed_spec(5, CASE5) if which == "case5" else bearing()[0]
    scene = build_scene(spec)
    pairs = []
    read = engine._JointForces.__call__

    def compared(self):
        forces = read(self)
        kinds = exu.OutputVariableType
        outputs = [np.linalg.norm(self.mbs.GetObjectOutput(
            joint, kinds.Force if "Distance" in self.mbs.GetObject(joint)["objectType"] else kinds.ForceLocal))
            for joint in self.joints]
        pairs.append((forces, outputs))
        return forces

    monkeypatch.setattr(engine._JointForces, "__call__", compared)
    result = simulate(scene, spec.solver, spec.scenario.end_time)
    assert result.success, result.message
    forces, outputs = np.array([p[0] for p in pairs]), np.array([p[1] for p in pairs])
    assert forces.shape == (result.time.size - 1, len(scene.constraints))  # every row after the initial one
    assert outputs.max() > 0  # the joints carry load
    np.testing.assert_allclose(forces, outputs, rtol=1e-14, atol=0)


def test_the_monitors_power_shortcut_changes_nothing(monkeypatch):
    spec, scene = bearing()
    taken = []
    power_at = connectors.ForceConnector.power_at

    def counted(self, t, q, v):
        power = power_at(self, t, q, v)
        taken.append(power is not None)
        return power

    monkeypatch.setattr(connectors.ForceConnector, "power_at", counted)
    shortcut = simulate(scene, spec.solver, spec.scenario.end_time)
    monkeypatch.setattr(connectors.ForceConnector, "power_at", lambda self, t, q, v: None)
    evaluated = simulate(scene, spec.solver, spec.scenario.end_time)
    assert shortcut.success and evaluated.success
    assert len(taken) >= shortcut.stats.steps and all(taken)  # every accepted step (and Exudyn's call at t = 0)
    assert shortcut.work[-1, 1] > 0  # the contacts dissipate
    for name in ("work", "position", "velocity", "pair_output", "constraint_forces"):
        np.testing.assert_array_equal(getattr(shortcut, name), getattr(evaluated, name), err_msg=name)


def test_a_compiled_function_called_directly_returns_what_the_dispatcher_returns():
    _, scene = bearing()
    packed = pack_scene(scene)
    q, _ = scene.initial_state()
    v = np.array([b.velocity for b in scene.bodies], dtype=float).ravel()
    latched = np.zeros(len(scene.pairs))
    outputs = [(np.empty(q.size), np.empty((len(scene.pairs), connectors.N_PAIR_OUTPUTS))) for _ in range(2)]
    args = (packed.elements, 0.001, q, v, latched)
    direct = connectors.compiled(element_forces, *args, *outputs[0], True)(*args, *outputs[0], True)
    dispatched = element_forces(*args, *outputs[1], True)
    assert direct == dispatched and np.abs(outputs[0][0]).max() > 0
    np.testing.assert_array_equal(outputs[0][0], outputs[1][0])
    np.testing.assert_array_equal(outputs[0][1], outputs[1][1])


@pytest.mark.parametrize("with_force_object", [True, False])
def test_free_fall_on_exudyn_matches_its_closed_form(with_force_object):
    g, y0, v0, end = 9.81, 0.5, 1.0, 0.2
    ball = Body("ball", 0.1, 1e-5, (0.0, y0, 0.0), (0.0, v0, 0.0))
    # a floor far below, never reached: it makes the engine build its force object
    floor = ContactPair("ball-floor", "circle_line", GROUND, 0, pair_law(ContactSpec()), radius_b=0.01,
                        anchor=(0.0, -10.0))
    scene = Scene("free_fall", (ball,), (floor,) if with_force_object else (), gravity=(0.0, -g))
    solver = SolverSpec(engine="exudyn", output_interval=1e-2,
                        exudyn=ExudynSolver(method="generalized_alpha", step=1e-3, tolerance=1e-10))
    result = simulate(scene, solver, end)
    assert result.success, result.message
    t = result.time
    np.testing.assert_allclose(result.position[:, 1], y0 + v0 * t - 0.5 * g * t**2, rtol=0, atol=1e-12)
    np.testing.assert_allclose(result.velocity[:, 1], v0 - g * t, rtol=0, atol=1e-12)
    assert t[-1] == pytest.approx(end)
