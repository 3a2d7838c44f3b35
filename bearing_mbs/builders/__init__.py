"""Spec → scene builders. Each includes only what its case needs."""

from ..scene import Scene
from ..spec import Spec
from .balls import build_balls_scene
from .bearing import build_bearing_scene

BUILDERS = {"balls": build_balls_scene, "bearing": build_bearing_scene}


def build_scene(spec: Spec) -> Scene:
    """The scene of a validated spec, for its model."""
    return BUILDERS[spec.scenario.model](spec)


__all__ = ["BUILDERS", "build_scene"]
