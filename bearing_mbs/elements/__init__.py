"""Force elements: one module per kind (contact pairs, loads, velocity servos, drags), registered once in
:data:`FORCE_ELEMENTS`; :mod:`.assembly` packs a scene and evaluates all its forces and their Jacobians, every kind
through one dispatch (:mod:`.dispatch`).

Protocol: :mod:`bearing_mbs.core.force_element`. A worked example of adding a kind: ``docs/guide-add-a-force-element.md``.
"""

from bearing_mbs.elements.assembly import (
    PackedScene,
    element_forces,
    element_forces_twin,
    element_jacobian,
    has_analytic_jacobian,
    pack_scene,
    scene_counts,
    scene_forces,
    scene_forces_twin,
)
from bearing_mbs.elements.drags import Drag
from bearing_mbs.elements.loads import Load
from bearing_mbs.elements.registry import FORCE_ELEMENTS
from bearing_mbs.elements.servos import VelocityServo

__all__ = ["FORCE_ELEMENTS", "Drag", "Load", "PackedScene", "VelocityServo", "element_forces", "element_forces_twin",
           "element_jacobian", "has_analytic_jacobian", "pack_scene", "scene_counts", "scene_forces",
           "scene_forces_twin"]
