"""A force element registered from outside the package runs on both engines and closes the energy audit,
with no edit to any engine (the worked example of ``docs/guide-add-a-force-element.md``).

The toy element is a linear spring between the centres of two bodies, F = k (|d| − L) d/|d|.
References, independent of the code under test:

* two free masses joined by a spring oscillate in their separation with ω = √(k/μ), μ = m₁m₂/(m₁ + m₂)
  (any mechanics text, e.g. Goldstein, Classical Mechanics, §3.1 on the two-body problem): the separation
  must follow L + A cos(ωt) to 1e-6 of A;
* momentum conservation: the centre of mass stays where it started, to 1e-12 m;
* the energy audit (kinetic + the spring's potential energy − work of the drag) is constant to 1e-6 of the
  energy that flows, and without the drag the total energy itself is conserved to 1e-6.

Run by ``tests/test_plugin_force_element.py`` in a child process with a numba cache directory of its own:
compiled functions specialised on this module's types must not enter the package's shared on-disk cache, where
a process that cannot import this module (a Dask worker, say) would fail to read them back.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import NamedTuple

import numba
import numpy as np
import pytest

from bearing_mbs.analysis import energy, energy_balance_error
from bearing_mbs.core.force_element import ForceElement
from bearing_mbs.core.scene import Body, Scene
from bearing_mbs.elements import FORCE_ELEMENTS, Drag, has_analytic_jacobian, scene_counts
from bearing_mbs.engines import simulate
from bearing_mbs.spec import ExudynSolver, ReferenceSolver, SolverSpec


@dataclass(frozen=True)
class Spring:
    """A linear spring between the centres of bodies a and b: stiffness [N/m] > 0, rest length [m] >= 0."""

    name: str
    body_a: int
    body_b: int
    stiffness: float
    rest_length: float


class SpringArrays(NamedTuple):
    body_a: np.ndarray
    body_b: np.ndarray
    stiffness: np.ndarray
    rest_length: np.ndarray


def pack(springs) -> SpringArrays:
    return SpringArrays(np.array([s.body_a for s in springs], dtype=np.int64),
                        np.array([s.body_b for s in springs], dtype=np.int64),
                        np.array([s.stiffness for s in springs]), np.array([s.rest_length for s in springs]))


@numba.njit(inline="always")
def add_forces(parameters, t, q, v, forces, power):
    springs = parameters
    for j in range(springs.body_a.size):
        a, b = springs.body_a[j], springs.body_b[j]
        dx, dy = q[3 * b] - q[3 * a], q[3 * b + 1] - q[3 * a + 1]
        length = math.sqrt(dx * dx + dy * dy)
        tension = springs.stiffness[j] * (length - springs.rest_length[j])
        fx, fy = tension * dx / length, tension * dy / length
        forces[3 * a] += fx
        forces[3 * a + 1] += fy
        forces[3 * b] -= fx
        forces[3 * b + 1] -= fy


def add_forces_twin(springs, t, q, v, forces, power):
    body = q.reshape(-1, 3)
    d = body[springs.body_b, :2] - body[springs.body_a, :2]
    length = np.hypot(d[:, 0], d[:, 1])
    pull = (springs.stiffness * (length - springs.rest_length) / length)[:, None] * d
    f = forces.reshape(-1, 3)
    np.add.at(f[:, :2], springs.body_a, pull)
    np.add.at(f[:, :2], springs.body_b, -pull)


@numba.njit(inline="always")
def add_jacobian(parameters, t, q, v, force_position, force_velocity):
    """∂F/∂q of the springs: on a, ∂(T d/|d|)/∂d = k d dᵀ/|d|² + T/|d| (I − d dᵀ/|d|²) times ∂d/∂x_b = I,
    ∂d/∂x_a = −I; b the opposite. No dependence on v."""
    springs = parameters
    for j in range(springs.body_a.size):
        a, b = springs.body_a[j], springs.body_b[j]
        dx, dy = q[3 * b] - q[3 * a], q[3 * b + 1] - q[3 * a + 1]
        length = math.sqrt(dx * dx + dy * dy)
        stretch = springs.stiffness[j] * (length - springs.rest_length[j]) / length
        d = (dx / length, dy / length)
        for r in range(2):
            for c in range(2):
                entry = springs.stiffness[j] * d[r] * d[c] + stretch * ((1.0 if r == c else 0.0) - d[r] * d[c])
                force_position[3 * a + r, 3 * b + c] += entry
                force_position[3 * a + r, 3 * a + c] -= entry
                force_position[3 * b + r, 3 * a + c] += entry
                force_position[3 * b + r, 3 * b + c] -= entry


def potential_energy(springs, position, pair_output):
    body = position.reshape(position.shape[0], -1, 3)
    d = body[:, springs.body_b, :2] - body[:, springs.body_a, :2]
    stretch = np.hypot(d[..., 0], d[..., 1]) - springs.rest_length
    return np.sum(0.5 * springs.stiffness * stretch**2, axis=1)


SPRING = ForceElement(name="springs", item_type=Spring, parameters=SpringArrays, pack=pack, add_forces=add_forces,
                      add_forces_twin=add_forces_twin, potential_energy=potential_energy, add_jacobian=add_jacobian)

M1, M2, K, L, A = 2.0, 3.0, 4.0e4, 0.1, 1e-3  # kg, kg, N/m, m, m


@pytest.fixture(scope="module")
def registered():
    FORCE_ELEMENTS.register(SPRING)
    yield
    FORCE_ELEMENTS.unregister(SPRING.name)


def oscillator(drag: float = 0.0) -> Scene:
    """The two bodies and the spring; a drag [N s/m] on body b (with 0, it adds exactly nothing, and the scenes
    share one compiled specialisation)."""
    bodies = (Body("a", M1, 1e-3, (0.0, 0.0, 0.0)), Body("b", M2, 1e-3, (L + A, 0.0, 0.0)))
    return Scene("oscillator", bodies, forces=(Spring("spring", 0, 1, K, L), Drag("drag", 1, drag)))


SOLVERS = {
    "reference_rk4": SolverSpec(engine="reference", output_interval=1e-3, reference=ReferenceSolver(method="rk4", step=1e-5)),
    "exudyn_rk4": SolverSpec(engine="exudyn", output_interval=1e-3, exudyn=ExudynSolver(method="rk4", step=1e-5)),
    "exudyn_python": SolverSpec(engine="exudyn", output_interval=1e-3,
                                exudyn=ExudynSolver(method="rk4", step=1e-5, connector="python")),
    # implicit: the spring's analytic Jacobian serves the reference engine's generalized-α and Exudyn's analytic
    # Jacobian (a step of 2e-6 s keeps generalized-α's phase error, about (ωh)²ωt/12, below 1e-7 of A)
    "reference_generalized_alpha": SolverSpec(engine="reference", output_interval=1e-3, reference=ReferenceSolver(
        method="generalized_alpha", step=2e-6, tolerance=1e-12)),
    "exudyn_generalized_alpha": SolverSpec(engine="exudyn", output_interval=1e-3, exudyn=ExudynSolver(
        method="generalized_alpha", step=2e-6, tolerance=1e-12, jacobian="analytic")),
}


#: The implicit solvers compile the reference engine's generalized-α driver once more for this module's types
#: (about 2 minutes): they run with the long studies (``make test-slow``).
IMPLICIT = ("reference_generalized_alpha", "exudyn_generalized_alpha")


@pytest.mark.parametrize("solver", [pytest.param(name, marks=pytest.mark.slow) if name in IMPLICIT else name
                                    for name in SOLVERS])
def test_spring_oscillates_at_the_two_body_frequency(registered, solver):
    scene = oscillator()
    result = simulate(scene, SOLVERS[solver], 0.05)
    assert result.success, result.message
    omega = math.sqrt(K * (M1 + M2) / (M1 * M2))
    separation = result.position[:, 3] - result.position[:, 0]
    np.testing.assert_allclose(separation, L + A * np.cos(omega * result.time), rtol=0, atol=1e-6 * A)
    centre = (M1 * result.position[:, 0] + M2 * result.position[:, 3]) / (M1 + M2)
    np.testing.assert_allclose(centre, M2 * (L + A) / (M1 + M2), rtol=0, atol=1e-12)
    total = energy(scene, result)["total"]
    assert np.ptp(total) <= 1e-6 * total[0]
    assert scene_counts(scene)["springs"] == 1
    if solver == "exudyn_generalized_alpha":  # the spring's own Jacobian, not Exudyn's differences
        assert result.metadata["jacobian"] == "analytic" and result.metadata["jacobian_user_evaluations"] > 0
    if solver == "reference_generalized_alpha":  # the engine forms its Jacobian from the kinds' own (the calls
        # are counted in tests/test_guide_force_element.py, where the package runs as Python)
        assert has_analytic_jacobian(scene) and result.stats.jacobian_evaluations > 0


@pytest.mark.parametrize("solver", ["reference_rk4", "exudyn_rk4"])
def test_energy_audit_closes_with_the_spring_and_a_drag(registered, solver):
    scene = oscillator(drag=200.0)
    result = simulate(scene, SOLVERS[solver], 0.05)
    assert result.success, result.message
    assert result.work[-1, 1] > 0.5 * energy(scene, result)["total"][0]  # the drag takes most of the energy
    assert energy_balance_error(scene, result) < 1e-6


@dataclass(frozen=True)
class Magnet:
    name: str
    body: int


def test_an_unregistered_kind_is_refused_before_anything_runs():
    scene = Scene("stray", (Body("a", 1.0, 1.0, (0.0, 0.0, 0.0)),), forces=(Magnet("magnet", 0),))
    with pytest.raises(TypeError):
        simulate(scene, SOLVERS["reference_rk4"], 0.01)
