"""The registered force-element kinds, in evaluation order. Adding a kind inside the package: its module, an entry
in :data:`BUILT_IN` and the matching call in :func:`add_built_in_forces`, side by side below. From outside the
package: ``FORCE_ELEMENTS.register(element)``, nothing else."""

from __future__ import annotations

import numba

from bearing_mbs.core.force_element import ForceElementRegistry
from bearing_mbs.elements import contact_pairs, drags, journal_bearings, loads, servos, slewing_bearings, unbalances

#: Contact pairs first (their per-pair state and outputs), then loads, drives, drags, slewing bearings, journal
#: bearings and unbalances.
BUILT_IN = (contact_pairs.ELEMENT, loads.ELEMENT, servos.ELEMENT, drags.ELEMENT, slewing_bearings.ELEMENT,
            journal_bearings.ELEMENT, unbalances.ELEMENT)
FORCE_ELEMENTS = ForceElementRegistry(BUILT_IN)


@numba.njit(cache=True, inline="always")
def add_built_in_forces(elements, t, q, v, latched, forces, pair_out, power, complete):
    """The compiled forces of the built-in kinds, ``elements[0:7]`` in the order of :data:`BUILT_IN`.

    Written out call by call: numba cannot loop over a tuple of different types, and a generic unrolling
    (:func:`bearing_mbs.elements.assembly.add_element_forces`, used for kinds registered from outside) costs
    several times the compile time of these direct, inlined calls.
    """
    contact_pairs.add_forces(elements[0], t, q, v, latched, forces, pair_out, power, complete)
    loads.add_forces(elements[1], t, q, v, latched, forces, pair_out, power, complete)
    servos.add_forces(elements[2], t, q, v, latched, forces, pair_out, power, complete)
    drags.add_forces(elements[3], t, q, v, latched, forces, pair_out, power, complete)
    slewing_bearings.add_forces(elements[4], t, q, v, latched, forces, pair_out, power, complete)
    journal_bearings.add_forces(elements[5], t, q, v, latched, forces, pair_out, power, complete)
    unbalances.add_forces(elements[6], t, q, v, latched, forces, pair_out, power, complete)


@numba.njit(cache=True, inline="always")
def add_built_in_jacobians(elements, t, q, v, latched, pair_out, force_position, force_velocity):
    """The analytic Jacobians of the built-in kinds, ``elements[0:7]`` in the order of :data:`BUILT_IN`
    (``ForceElement.add_jacobian``)."""
    contact_pairs.add_jacobian(elements[0], t, q, v, latched, pair_out, force_position, force_velocity)
    loads.add_jacobian(elements[1], t, q, v, latched, pair_out, force_position, force_velocity)
    servos.add_jacobian(elements[2], t, q, v, latched, pair_out, force_position, force_velocity)
    drags.add_jacobian(elements[3], t, q, v, latched, pair_out, force_position, force_velocity)
    slewing_bearings.add_jacobian(elements[4], t, q, v, latched, pair_out, force_position, force_velocity)
    journal_bearings.add_jacobian(elements[5], t, q, v, latched, pair_out, force_position, force_velocity)
    unbalances.add_jacobian(elements[6], t, q, v, latched, pair_out, force_position, force_velocity)
