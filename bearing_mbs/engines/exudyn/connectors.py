"""The three ways contact forces reach Exudyn (``[solver.exudyn] connector``).

* ``compiled`` — one ``ObjectGenericODE2`` over all body nodes whose force user function calls the numba
  kernel (:func:`bearing_mbs.elements.element_forces`). Measured fastest (docs/engines.md).
* ``python`` — the same object calling the numpy twin (:func:`bearing_mbs.elements.element_forces_twin`).
* ``native`` — Exudyn's own C++ ``ObjectContactSphereSphere`` per pair, for the normal force only. Its
  Hunt–Crossley model has damping factor 3(1 − e_HC)/2, so ``e_HC = 1 − 2d/3`` reproduces any law of the
  hysteresis family with factor d (for Lankarani–Nikravesh, e_HC = (1 + e²)/2). A circle–line pair becomes
  a sphere of radius :data:`LINE_AS_SPHERE_RADIUS` × r_b tangent to the line below the ball's start; its
  gap differs from the line's by x²/(2R) for a lateral excursion x.

Loads and drives always go through a (compiled or numpy) GenericODE2, added only when a scene has them.
"""

from __future__ import annotations

import math

import numba
import numpy as np

from bearing_mbs.contact.kernel import N_PAIR_OUTPUTS
from bearing_mbs.core.scene import GROUND, Scene
from bearing_mbs.elements import element_forces, element_forces_twin, element_jacobian
from bearing_mbs.spec.fields import SpecError

LINE_AS_SPHERE_RADIUS = 1e6


def native_restitution(damping_factor: float) -> float:
    """Exudyn Hunt–Crossley restitution e_HC with the same damping factor d: e_HC = 1 − 2d/3."""
    return 1.0 - 2.0 * damping_factor / 3.0


def check_native(scene: Scene) -> None:
    """The native connector carries the normal force of the hysteresis family only."""
    for pair in scene.pairs:
        law = pair.law
        if pair.kind == "circle_line" and pair.body_a != GROUND:
            raise SpecError("solver.exudyn.connector", "native",
                            f"represents lines fixed to the ground only, not pair {pair.name!r}")
        if law.friction_law != "none" or law.friction_coefficient > 0 or law.rolling_resistance_arm > 0:
            raise SpecError("solver.exudyn.connector", "native",
                            f"carries normal forces only, but pair {pair.name!r} has friction or rolling "
                            f"resistance; use connector = compiled")
        if not 0 < native_restitution(law.damping_factor) <= 1:
            raise SpecError("solver.exudyn.connector", "native",
                            f"cannot represent pair {pair.name!r}: its damping factor {law.damping_factor:.3g} "
                            f"needs e_HC = 1 - 2d/3 in (0, 1]; use connector = compiled")


def compiled(function, *args):
    """The compiled function of the numba dispatcher ``function`` for the types of ``args`` (loaded from numba's
    cache, or compiled, now). Called directly it skips the dispatcher's matching of the argument types, which
    for the packed kinds' 56 arrays costs about 7 µs of a 20 µs call (docs/engines.md); it still converts every
    argument, so it must be called with arguments of these types. Under ``NUMBA_DISABLE_JIT`` it is the Python
    function itself."""
    if not isinstance(function, numba.core.dispatcher.Dispatcher):
        return function
    return function.compile(tuple(numba.typeof(arg) for arg in args))


class ForceConnector:
    """A force user function over all body nodes, counting its evaluations and keeping the state and power of the
    last one (:meth:`power_at`)."""

    def __init__(self, packed, reference: np.ndarray, latched: np.ndarray, compiled_kernel: bool):
        self.elements, self.reference, self.latched = packed.elements, reference, latched
        self.evaluations = 0
        self.time = math.nan
        self._q = reference.copy()
        self._v = np.zeros_like(reference)
        self._forces = np.empty_like(reference)
        self._pairs = np.empty((packed.pairs.kind.size, N_PAIR_OUTPUTS))
        self.evaluate = (compiled(element_forces, self.elements, 0.0, self._q, self._v, latched, self._forces,
                                  self._pairs, False)
                         if compiled_kernel else element_forces_twin)
        self.power = (0.0, 0.0)

    def __call__(self, mbs, t, item_number, q, q_t):
        self.evaluations += 1
        np.add(self.reference, q, out=self._q)  # Exudyn passes displacements from the reference
        self._v = np.asarray(q_t, dtype=float)
        self.time = t
        self.power = self.evaluate(self.elements, t, self._q, self._v, self.latched, self._forces, self._pairs, False)
        return self._forces.tolist()  # which Exudyn converts faster than an array

    def power_at(self, t: float, q: np.ndarray, v: np.ndarray):
        """The (supplied, dissipated) power [W] of the last evaluation if it was at time t [s] and state (q, v)
        exactly, else None. Exudyn's Newton method ends on a residual at the accepted state, so the step monitor
        finds that state's power here instead of evaluating the forces again."""
        if t == self.time and np.array_equal(q, self._q) and np.array_equal(v, self._v):
            return self.power
        return None


class JacobianConnector:
    """A Jacobian user function of the same GenericODE2: Exudyn's left-hand side is M q̈ − F, so it returns
    −(f_q ∂F/∂q + f_v ∂F/∂q̇) with Exudyn's factors f_q, f_v (the elements' analytic Jacobians,
    :func:`bearing_mbs.elements.element_jacobian`, at the pair outputs of a complete force evaluation)."""

    def __init__(self, forces: ForceConnector):
        self.forces = forces
        self.evaluations = 0
        n = forces.reference.size
        self._q, self._v = forces.reference.copy(), np.zeros(n)
        self._position, self._velocity, self._matrix = np.empty((n, n)), np.empty((n, n)), np.empty((n, n))
        f = forces
        self._forces = compiled(element_forces, f.elements, 0.0, self._q, self._v, f.latched, f._forces, f._pairs,
                                True)
        self._jacobian = compiled(element_jacobian, f.elements, 0.0, self._q, self._v, f.latched, f._pairs,
                                  self._position, self._velocity)

    def __call__(self, mbs, t, item_number, q, q_t, factor_position, factor_velocity):
        self.evaluations += 1
        f = self.forces
        np.add(f.reference, q, out=self._q)
        v = np.asarray(q_t, dtype=float)
        self._forces(f.elements, t, self._q, v, f.latched, f._forces, f._pairs, True)
        self._jacobian(f.elements, t, self._q, v, f.latched, f._pairs, self._position, self._velocity)
        np.multiply(self._position, -factor_position, out=self._matrix)
        self._matrix -= factor_velocity * self._velocity
        return self._matrix


def without_pairs(packed) -> tuple:
    """The packed scene with no contact pairs (for loads and drives next to native contacts)."""
    empty = type(packed.pairs)(*(np.zeros((0,) + np.shape(column)[1:], dtype=np.asarray(column).dtype)
                                 for column in packed.pairs))
    return packed._replace(pairs=empty, elements=(empty, *packed.elements[1:]))


def add_native_contacts(mbs, scene: Scene, body_objects: list[int], ground_object: int) -> None:
    """One ObjectContactSphereSphere per pair (normal force only)."""
    from exudyn.itemInterface import (
        MarkerBodyRigid,
        NodeGenericData,
        ObjectContactSphereSphere,
    )

    q0, _ = scene.initial_state()
    for pair in scene.pairs:
        law = pair.law
        marker_b = mbs.AddMarker(MarkerBodyRigid(bodyNumber=body_objects[pair.body_b], localPosition=[0, 0, 0]))
        owner = ground_object if pair.body_a == GROUND else body_objects[pair.body_a]
        radius_a, anchor = pair.radius_a, list(pair.anchor)
        if pair.kind == "circle_line":
            # a huge sphere tangent to the line, centred below the ball's start position
            big = LINE_AS_SPHERE_RADIUS * pair.radius_b
            nx, ny = pair.direction
            bx, by = q0[3 * pair.body_b], q0[3 * pair.body_b + 1]
            along = (bx - anchor[0]) * -ny + (by - anchor[1]) * nx
            anchor = [anchor[0] - ny * along - nx * big, anchor[1] + nx * along - ny * big]
            radius_a = big
        marker_a = mbs.AddMarker(MarkerBodyRigid(bodyNumber=owner, localPosition=[*anchor, 0]))
        data = mbs.AddNode(NodeGenericData(initialCoordinates=[1.0, 0, 0, 0], numberOfDataCoordinates=4))
        hollow = pair.kind == "circle_in_circle"
        mbs.AddObject(
            ObjectContactSphereSphere(
                markerNumbers=[marker_b, marker_a] if hollow else [marker_a, marker_b],
                nodeNumber=data,
                spheresRadii=[pair.radius_b, radius_a] if hollow else [radius_a, pair.radius_b],
                isHollowSphere1=hollow,
                contactStiffness=law.stiffness,
                contactStiffnessExponent=law.exponent,
                contactDamping=0.0,
                impactModel=1,
                restitutionCoefficient=native_restitution(law.damping_factor),
                minimumImpactVelocity=law.approach_speed_floor,
            )
        )
