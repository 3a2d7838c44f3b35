"""The registered models. Adding a model: its package, and one entry in :data:`MODELS` (or
``MODELS.register(model)`` from outside the package)."""

from __future__ import annotations

from bearing_mbs.core.scene import Scene
from bearing_mbs.models.balls import MODEL as BALLS
from bearing_mbs.models.cylindrical_roller import MODEL as CYLINDRICAL_ROLLER
from bearing_mbs.models.journal_bearing import MODEL as JOURNAL_BEARING
from bearing_mbs.models.protocol import ModelRegistry
from bearing_mbs.models.rotor import MODEL as ROTOR
from bearing_mbs.models.slewing_bearing import MODEL as SLEWING_BEARING

#: Every model by its ``[scenario] model`` name.
MODELS = ModelRegistry((BALLS, CYLINDRICAL_ROLLER, SLEWING_BEARING, JOURNAL_BEARING, ROTOR))


def build_scene(spec) -> Scene:
    """The scene of a validated spec, built by its model."""
    return MODELS[spec.scenario.model].build(spec)
