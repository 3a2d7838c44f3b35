"""The registered force-element kinds, in evaluation order. Adding a kind inside the package: its module and its
entry in :data:`BUILT_IN`. From outside the package: ``FORCE_ELEMENTS.register(element)``, nothing else. Both
reach the engines through the same dispatch (:mod:`bearing_mbs.elements.dispatch`)."""

from __future__ import annotations

from bearing_mbs.core.force_element import ForceElementRegistry
from bearing_mbs.elements import contact_pairs, drags, journal_bearings, loads, servos, slewing_bearings, unbalances

#: Contact pairs first (their per-pair state and outputs), then loads, drives, drags, slewing bearings, journal
#: bearings and unbalances.
BUILT_IN = (contact_pairs.ELEMENT, loads.ELEMENT, servos.ELEMENT, drags.ELEMENT, slewing_bearings.ELEMENT,
            journal_bearings.ELEMENT, unbalances.ELEMENT)
FORCE_ELEMENTS = ForceElementRegistry(BUILT_IN)
