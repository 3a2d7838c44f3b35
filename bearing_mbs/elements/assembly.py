"""A scene as arrays, and the evaluation of all its forces by looping over the registered force elements.

:func:`pack_scene` packs the contact pairs and every registered force-element kind (registry order) into
:class:`PackedScene`. :func:`element_forces` (compiled; :func:`scene_forces` calls it with a packed scene) and
:func:`scene_forces_twin` (numpy) add the forces of every kind, and :func:`element_jacobian` their analytic
Jacobians, built-in and registered kinds alike through one dispatch (:mod:`bearing_mbs.elements.dispatch`).
Gravity and constraint forces are the engines' business.
"""

from __future__ import annotations

from typing import NamedTuple

import numba
import numpy as np

from bearing_mbs.core.scene import CONSTRAINT_KINDS, Scene
from bearing_mbs.elements import contact_pairs, dispatch
from bearing_mbs.elements.contact_pairs import PairArrays
from bearing_mbs.elements.registry import FORCE_ELEMENTS


class ConstraintArrays(NamedTuple):
    """Constraints as arrays (unused columns of a kind are zero)."""

    kind: np.ndarray  # int64, index into CONSTRAINT_KINDS
    body_a: np.ndarray  # int64
    body_b: np.ndarray  # int64
    length: np.ndarray  # [m], distance constraints
    anchor: np.ndarray  # (C, 2) [m], point-on-line constraints, in a's frame
    direction: np.ndarray  # (C, 2), point-on-line and orbit constraints, unit, in a's frame


class PackedScene(NamedTuple):
    """A scene as flat arrays. Coordinates are ordered body by body: (x, y, θ) of body 0, then body 1, …

    ``elements`` holds the packed parameters of every registered force-element kind, in registry order, with
    empty arrays for a kind the scene does not have (a loop over no items costs nothing, and every scene then
    has the same compiled type: one compilation of the integrators serves them all). The contact pairs come
    first and are also ``pairs`` (the engines update their per-pair state).
    """

    inverse_mass: np.ndarray  # (3N,) 1/m, 1/m, 1/I; 0 on fixed coordinates
    gravity: np.ndarray  # (3N,) gravitational acceleration on free translational coordinates
    pairs: PairArrays
    constraints: ConstraintArrays
    elements: tuple


def _pack_constraints(constraints) -> ConstraintArrays:
    def column(get, dtype=float):
        return np.array([get(c) for c in constraints], dtype=dtype)

    return ConstraintArrays(
        kind=column(lambda c: CONSTRAINT_KINDS.index(type(c)), np.int64),
        body_a=column(lambda c: c.body_a, np.int64),
        body_b=column(lambda c: c.body_b, np.int64),
        length=column(lambda c: getattr(c, "length", 0.0)),
        anchor=column(lambda c: getattr(c, "anchor", (0.0, 0.0))).reshape(-1, 2),
        direction=column(lambda c: getattr(c, "direction", (0.0, 0.0))).reshape(-1, 2),
    )


def pack_scene(scene: Scene) -> PackedScene:
    free = np.array([b.free for b in scene.bodies], dtype=bool).ravel()
    inverse_mass = np.array([[1 / b.mass, 1 / b.mass, 1 / b.inertia] for b in scene.bodies]).ravel() * free
    gravity = np.zeros(scene.coordinate_count)
    gravity[0::3], gravity[1::3] = scene.gravity
    gravity *= free
    for item in scene.forces:
        FORCE_ELEMENTS.of_item(item)  # an unregistered kind is an error, not silently dropped
    dispatch.follow_registry()  # a kind registered since the last scene joins the evaluation
    pairs = contact_pairs.pack(scene.pairs)
    # every registered kind, with no items where the scene has none: one compiled specialisation serves all scenes
    elements = tuple(pairs if element is contact_pairs.ELEMENT else element.pack(scene.items_of(element.item_type))
                     for element in FORCE_ELEMENTS.values())
    return PackedScene(inverse_mass=inverse_mass, gravity=gravity, pairs=pairs,
                       constraints=_pack_constraints(scene.constraints), elements=elements)


def scene_counts(scene: Scene) -> dict:
    """Item counts, for the 'only what is needed' tests and for reports (gravity counts as a load)."""
    counts = {"bodies": len(scene.bodies), "pairs": len(scene.pairs), "constraints": len(scene.constraints)}
    for element in FORCE_ELEMENTS.values():
        if element is not contact_pairs.ELEMENT:
            counts[element.name] = len(scene.items_of(element.item_type))
    counts["loads"] += 1 if any(scene.gravity) else 0
    counts["sensors"] = len(scene.sensors)
    return counts


@numba.njit(cache=True, inline="always")
def element_forces(elements, t, q, v, latched, forces, pair_out, complete=True):
    """Generalized forces [N, N, N m per body] of the packed kinds ``elements`` (:attr:`PackedScene.elements`),
    written into ``forces``.

    ``pair_out`` (pairs × :data:`~bearing_mbs.contact.kernel.PAIR_OUTPUTS`) receives each pair's outputs.
    Returns (supplied, dissipated) power [W]. ``complete=False`` (inside integration stages) lets kinds skip
    outputs no force needs. Called from Python (Exudyn's force user function), it takes the kinds alone: numba
    unboxes every array of its arguments on each call, and these are the ones the forces need.

    Inlined, with every kind's compiled function, into the reference engine's one compiled function of the
    forces (:func:`bearing_mbs.engines.reference.dynamics.accelerations`): a call that passed the kinds' arrays
    on would count references to each of them on every evaluation.
    """
    forces[:] = 0.0
    power = np.zeros(2)
    dispatch.add_element_forces(elements, t, q, v, latched, forces, pair_out, power, complete)
    return power[0], power[1]


def scene_forces(packed, t, q, v, latched, forces, pair_out, complete=True):
    """:func:`element_forces` of a packed scene, from Python: it calls the compiled function Exudyn's connectors call
    (one compiled copy for every caller in Python, ``complete`` always given)."""
    return element_forces(packed.elements, t, q, v, latched, forces, pair_out, bool(complete))


def has_analytic_jacobian(scene: Scene) -> bool:
    """Whether every force item of ``scene`` is of a kind with an analytic Jacobian (``ForceElement.add_jacobian``,
    built-in or registered), which :func:`element_jacobian` then assembles; the engines differentiate a scene
    with any other kind numerically."""
    return all(FORCE_ELEMENTS.of_item(item).add_jacobian is not None for item in scene.forces)


@numba.njit(cache=True)
def element_jacobian(elements, t, q, v, latched, pair_out, force_position, force_velocity):
    """∂F/∂q and ∂F/∂v (3N × 3N each, overwritten) of the kinds of ``elements`` at (t, q, v), with ``pair_out``
    the pair outputs :func:`element_forces` wrote there (complete) and the latched approach speeds held. For
    scenes with :func:`has_analytic_jacobian` (a kind without an analytic Jacobian adds nothing)."""
    force_position[:, :] = 0.0
    force_velocity[:, :] = 0.0
    dispatch.add_element_jacobians(elements, t, q, v, latched, pair_out, force_position, force_velocity)


def element_forces_twin(elements, t, q, v, latched, forces, pair_out, complete=True):
    """Same contract as :func:`element_forces`, with every kind's numpy twin (always complete)."""
    forces[:] = 0.0
    power = np.zeros(2)
    dispatch.add_element_forces_twin(elements, t, q, v, latched, forces, pair_out, power, True)
    return power[0], power[1]


def scene_forces_twin(packed, t, q, v, latched, forces, pair_out, complete=True):
    """Same contract as :func:`scene_forces`, with every kind's numpy twin (always complete)."""
    return element_forces_twin(packed.elements, t, q, v, latched, forces, pair_out, complete)
