"""The registered force-element kinds, in evaluation order. Adding a kind: its module, and one entry here (or
``FORCE_ELEMENTS.register(element)`` from outside the package)."""

from __future__ import annotations

from bearing_mbs.core.force_element import ForceElementRegistry
from bearing_mbs.elements import contact_pairs, drags, loads, servos

#: Contact pairs first (their per-pair state and outputs), then loads, drives and drags.
FORCE_ELEMENTS = ForceElementRegistry((contact_pairs.ELEMENT, loads.ELEMENT, servos.ELEMENT, drags.ELEMENT))
