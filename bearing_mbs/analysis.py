"""Quantities engineers read, computed from a result, its scene and spec (no engine imports).

Each model's own metrics are in its package (``models/<name>/metrics.py``); these are the common ones.
"""

from __future__ import annotations

import numpy as np

from bearing_mbs.core.result import Result
from bearing_mbs.core.scene import Scene
from bearing_mbs.elements import FORCE_ELEMENTS, pack_scene


def energy(scene: Scene, result: Result) -> dict[str, np.ndarray]:
    """Kinetic, gravitational and elastic energy [J] at the output instants, and their total. The elastic energy
    is what the force elements store (the contact pairs' deformation, a spring's), each kind computing its own."""
    mass = np.array([[b.mass, b.mass, b.inertia] for b in scene.bodies]).ravel()
    kinetic = 0.5 * np.sum(mass * result.velocity**2, axis=1)
    gx, gy = scene.gravity
    masses = np.array([b.mass for b in scene.bodies])
    potential = -np.sum(masses * (gx * result.position[:, 0::3] + gy * result.position[:, 1::3]), axis=1)
    elastic = np.zeros_like(kinetic)
    for parameters in pack_scene(scene).elements:
        stored = FORCE_ELEMENTS.of_parameters(type(parameters)).potential_energy(
            parameters, result.position, result.pair_output)
        if stored is not None:
            elastic = elastic + stored
    return {"kinetic": kinetic, "potential": potential, "elastic": elastic, "total": kinetic + potential + elastic}


def max_penetration(result: Result) -> float:
    """Largest penetration of any pair at any output instant [m]."""
    if result.pair_output.size == 0:
        return 0.0
    return float(max(0.0, -np.nanmin(result.pair_series("gap"))))


def first_impact(result: Result) -> int | None:
    """Index of the pair that touches first, or None."""
    times = result.events[:, 0]
    return None if np.all(np.isnan(times)) else int(np.nanargmin(times))


def restitution_effective(result: Result) -> float | None:
    """First rebound speed over impact speed of the first pair to touch (engine events, per step)."""
    k = first_impact(result)
    if k is None or np.isnan(result.events[k, 3]):
        return None
    return float(result.events[k, 3] / result.events[k, 1])


def constraint_violation(scene: Scene, result: Result) -> np.ndarray:
    """(T, C) distance-constraint violation | |c_b − c_a| − L | [m]."""
    columns = []
    for c in scene.constraints:
        if not hasattr(c, "length"):
            continue
        a, b = result.position[:, 3 * c.body_a : 3 * c.body_a + 2], result.position[:, 3 * c.body_b : 3 * c.body_b + 2]
        columns.append(np.abs(np.linalg.norm(b - a, axis=1) - c.length))
    return np.column_stack(columns) if columns else np.zeros((result.time.size, 0))


#: The energy audit a run must close to be ``success`` (docs/status.md) [-]. The explicit methods close it to
#: 1e-10…1e-3 at their advised steps and generalized-alpha (ρ∞ = 0.9, numerically dissipative) to about 1e-3 on
#: the shipped scenarios (docs/verification.md); a step well above a stability limit leaves 0.1–1.
ENERGY_AUDIT_BOUND = 1e-2


def energy_balance_error(scene: Scene, result: Result) -> float:
    """Largest |ΔE − W_supplied + W_dissipated| over the run, relative to the energy that flowed.

    ΔE is the change of kinetic + gravitational + elastic energy; the works are integrated by the engine step
    by step. The energy that flowed is the largest of the works and of the changes of each form of energy (a
    falling body converts potential into kinetic energy with no work done). A correct run closes the balance
    to the integrator's accuracy.
    """
    forms = energy(scene, result)
    total = forms["total"]
    supplied, dissipated = result.work[:, 0], result.work[:, 1]
    imbalance = (total - total[0]) - supplied + dissipated
    changes = [np.abs(values - values[0]).max() for values in forms.values()]
    flow = max(np.abs(supplied).max(), np.abs(dissipated).max(), *changes, 1e-300)
    return float(np.abs(imbalance).max() / flow)
