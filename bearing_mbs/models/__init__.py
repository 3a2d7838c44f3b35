"""Models: each is one package under ``models/`` that says how a spec becomes a scene and what its results
mean. A model is registered once, in :data:`MODELS`; nothing outside its package knows its layout.

See :class:`~bearing_mbs.models.protocol.Model` for what a model provides and ``docs/guide-add-a-model.md``
for a worked example.
"""

from bearing_mbs.models.loading import load_spec, spec_from_mapping
from bearing_mbs.models.protocol import Model, ModelRegistry
from bearing_mbs.models.registry import MODELS, build_scene

__all__ = ["MODELS", "Model", "ModelRegistry", "build_scene", "load_spec", "spec_from_mapping"]
