"""The services the study layer and the runner lend a model's studies (:class:`~bearing_mbs.models.protocol.
StudyServices`): a model sits below them, so its studies are handed these rather than importing them."""

from __future__ import annotations

from bearing_mbs.models import build_scene, load_spec
from bearing_mbs.models.protocol import StudyServices
from bearing_mbs.runner import run_spec, summarize
from bearing_mbs.studies.common import with_overrides

#: The one set of services: scenario loading, spec variations, scenes, runs and their summaries.
SERVICES = StudyServices(load_spec=load_spec, with_overrides=with_overrides, build_scene=build_scene,
                         run_spec=run_spec, summarize=summarize)
