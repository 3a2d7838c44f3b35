"""The toy force-element kind that ``tests/test_guide_force_element.py`` adds inside a copy of the package, as
``docs/guide-add-a-force-element.md`` tells: an isotropic linear spring-damper from a body's centre to a fixed
anchor, F = −k (r − r₀) − c ṙ on x and y. This file is the module's text (``MODULE``) and the run the test makes
of it in the copy (``__main__``); it is never imported from the package under test.
"""

MODULE_NAME = "anchor_springs"

MODULE = '''"""Anchor springs: an isotropic linear spring-damper from a body's centre to a fixed point,
F = −k (r − r₀) − c ṙ [N] on x and y (the toy kind of docs/guide-add-a-force-element.md)."""

from __future__ import annotations

from dataclasses import dataclass
from typing import NamedTuple

import numba
import numpy as np

from bearing_mbs.core.force_element import ForceElement


@dataclass(frozen=True)
class AnchorSpring:
    """stiffness [N/m] >= 0 and damping [N s/m] >= 0 pulling the centre of ``body`` to ``anchor`` (x, y) [m]."""

    name: str
    body: int
    stiffness: float
    damping: float
    anchor: tuple[float, float] = (0.0, 0.0)


class AnchorSpringArrays(NamedTuple):
    body: np.ndarray  # (S,) int64
    stiffness: np.ndarray  # (S,) [N/m]
    damping: np.ndarray  # (S,) [N s/m]
    anchor: np.ndarray  # (S, 2) [m]


def pack(springs) -> AnchorSpringArrays:
    return AnchorSpringArrays(body=np.array([s.body for s in springs], dtype=np.int64),
                              stiffness=np.array([s.stiffness for s in springs], dtype=float),
                              damping=np.array([s.damping for s in springs], dtype=float),
                              anchor=np.array([s.anchor for s in springs], dtype=float).reshape(-1, 2))


@numba.njit(cache=True, inline="always")
def add_forces(parameters, t, q, v, forces, power):
    springs = parameters
    for j in range(springs.body.size):
        for c in range(2):
            i = 3 * springs.body[j] + c
            forces[i] -= springs.stiffness[j] * (q[i] - springs.anchor[j, c]) + springs.damping[j] * v[i]
            power[1] += springs.damping[j] * v[i] * v[i]


def add_forces_twin(springs, t, q, v, forces, power):
    body_forces, positions, velocities = forces.reshape(-1, 3), q.reshape(-1, 3), v.reshape(-1, 3)
    for j, body in enumerate(springs.body):
        body_forces[body, :2] -= (springs.stiffness[j] * (positions[body, :2] - springs.anchor[j])
                                  + springs.damping[j] * velocities[body, :2])
        power[1] += springs.damping[j] * velocities[body, :2] @ velocities[body, :2]


@numba.njit(cache=True, inline="always")
def add_jacobian(parameters, t, q, v, force_position, force_velocity):
    """∂F/∂q = −k and ∂F/∂v = −c on the body's x and y."""
    springs = parameters
    for j in range(springs.body.size):
        for c in range(2):
            i = 3 * springs.body[j] + c
            force_position[i, i] -= springs.stiffness[j]
            force_velocity[i, i] -= springs.damping[j]


def potential_energy(springs, position, pair_output):
    stretch = position.reshape(position.shape[0], -1, 3)[:, springs.body, :2] - springs.anchor
    return np.sum(0.5 * springs.stiffness[:, None] * stretch**2, axis=(1, 2))


ELEMENT = ForceElement(name="anchor_springs", item_type=AnchorSpring, parameters=AnchorSpringArrays, pack=pack,
                       add_forces=add_forces, add_forces_twin=add_forces_twin, potential_energy=potential_energy,
                       add_jacobian=add_jacobian)
'''

#: The damped oscillator: mass [kg], stiffness [N/m], damping [N s/m], start offset [m], simulated time [s].
M, K, C, X0, END = 2.0, 8.0e3, 6.0, 1e-3, 0.2


def exact_offset(t):
    """x(t) of m ẍ + c ẋ + k x = 0 from x(0) = X0 at rest (underdamped): X0 e^(−ζωt) (cos ω_d t + ζω/ω_d sin ω_d t)."""
    import numpy as np

    omega, zeta = np.sqrt(K / M), C / (2.0 * np.sqrt(K * M))
    damped = omega * np.sqrt(1.0 - zeta**2)
    return X0 * np.exp(-zeta * omega * t) * (np.cos(damped * t) + zeta * omega / damped * np.sin(damped * t))


def run() -> dict:
    """Run the toy on both engines' generalized-α with the analytic Jacobian, and on the reference engine's once
    more with the toy registered without it (its forward differences); count the calls of the toy's functions (a
    profile hook on their code: no change to the code under test). Prints a JSON report."""
    import dataclasses
    import json
    import sys

    import numpy as np

    import bearing_mbs
    from bearing_mbs.core.scene import Body, Scene
    from bearing_mbs.elements import FORCE_ELEMENTS, has_analytic_jacobian
    from bearing_mbs.elements.anchor_springs import AnchorSpring, add_forces, add_jacobian
    from bearing_mbs.engines import simulate
    from bearing_mbs.spec import ExudynSolver, ReferenceSolver, SolverSpec

    scene = Scene("anchored", (Body("mass", M, 1e-3, (X0, 0.0, 0.0)),),
                  forces=(AnchorSpring("spring", 0, K, C),))
    solvers = {
        "reference": SolverSpec(engine="reference", output_interval=1e-3, reference=ReferenceSolver(
            method="generalized_alpha", step=1e-4, tolerance=1e-10)),
        "exudyn": SolverSpec(engine="exudyn", output_interval=1e-3, exudyn=ExudynSolver(
            method="generalized_alpha", step=1e-4, tolerance=1e-10, jacobian="analytic")),
    }
    solvers["reference_without_jacobian"] = solvers["reference"]
    codes = {getattr(add_forces, "py_func", add_forces).__code__: "forces",
             getattr(add_jacobian, "py_func", add_jacobian).__code__: "jacobian"}
    report = {"package": bearing_mbs.__file__, "kinds": list(FORCE_ELEMENTS),
              "analytic": has_analytic_jacobian(scene), "runs": {}}
    for engine, solver in solvers.items():
        if engine == "reference_without_jacobian":
            element = FORCE_ELEMENTS[MODULE_NAME]
            FORCE_ELEMENTS.unregister(MODULE_NAME)
            FORCE_ELEMENTS.register(dataclasses.replace(element, add_jacobian=None))
        calls = {"forces": 0, "jacobian": 0}

        def count(frame, event, argument, calls=calls):
            if event == "call" and frame.f_code in codes:
                calls[codes[frame.f_code]] += 1

        sys.setprofile(count)
        try:
            result = simulate(scene, solver, END)
        finally:
            sys.setprofile(None)
        stats = result.stats
        report["runs"][engine] = {
            "success": bool(result.success), "message": result.message, "calls": calls,
            "force_evaluations": stats.force_evaluations, "jacobian_evaluations": stats.jacobian_evaluations,
            "jacobian": result.metadata.get("jacobian"), "analytic": has_analytic_jacobian(scene),
            "jacobian_user_evaluations": result.metadata.get("jacobian_user_evaluations"),
            "offset_error": float(np.max(np.abs(result.position[:, 0] - exact_offset(result.time)))),
            "lateral": float(np.max(np.abs(result.position[:, 1:3]))),
        }
    print(json.dumps(report))
    return report


if __name__ == "__main__":
    run()
