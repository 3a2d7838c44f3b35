"""What a model provides, and the registry that holds the models.

A model turns a validated spec into a scene and its topology (``build``), and turns a result back into what
engineers read (``metrics``, ``figures``). Optional parts (a quasi-static solver, a linearisation for the step
advisor) are attributes of its package that the layers above look up when they need them.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from bearing_mbs.core.registry import Registry
from bearing_mbs.core.result import Result
from bearing_mbs.core.scene import Scene


@dataclass(frozen=True)
class Model:
    """One model.

    * ``name`` — the ``[scenario] model`` value that selects it;
    * ``spec`` — its spec class: a frozen dataclass subclass of :class:`bearing_mbs.spec.Spec` that adds
      ``contact`` (one :class:`~bearing_mbs.spec.ContactSpec` per contact group, with defaults) and the model's
      sections; it validates itself on construction;
    * ``build(spec) -> Scene`` — the scene, with its topology, and only what the case needs;
    * ``metrics(spec, scene, result) -> dict`` — summary entries (JSON-safe numbers, lists and text);
    * ``figures(spec, scene, result, directory) -> list[Path]`` — PNG files;
    * ``prepare(data) -> data`` — fills model-specific defaults into the raw mapping before validation
      (a preset, say); optional;
    * ``linearise(scene)`` — operating point and modes for the step advisor, ``None`` for a scene it does not
      model; optional;
    * ``units`` — the unit of each entry ``metrics`` returns (``"N"``, ``"m/s"``, ``"-"``, ``"deg"``…), written to
      summary.json's ``units`` map;
    * ``warnings(spec, scene, result) -> list[str]`` — what makes the run's numbers meaningless (the runner's
      ``guard_warnings`` check; cheap: it runs for every run); none by default.
    """

    name: str
    spec: type
    build: Callable[[Any], Scene]
    metrics: Callable[[Any, Scene, Result], dict]
    figures: Callable[[Any, Scene, Result, Path], list]
    prepare: Callable[[dict], dict] = field(default=lambda data: data)
    linearise: Callable[[Scene], Any] | None = None
    units: dict = field(default_factory=dict)
    warnings: Callable[[Any, Scene, Result], list] = field(default=lambda spec, scene, result: [])


class ModelRegistry(Registry[Model]):
    """Models by name. :meth:`register` adds one from outside the package (a plug-in, or a test)."""
