"""Scenario files to validated specs: the model named in ``[scenario]`` chooses the spec class."""

from __future__ import annotations

import copy
import warnings
from pathlib import Path

from bearing_mbs.models.registry import MODELS
from bearing_mbs.spec import Spec, SpecError, from_mapping, read_scenario

#: Former ``[scenario] model`` names, each with the name it has now; the old name is read with a FutureWarning.
RENAMED_MODELS = {"bearing": "cylindrical_roller"}


def load_spec(path: str | Path, overrides: list[str] = ()) -> Spec:
    """Read a TOML scenario file, apply its variant and the ``section.key=value`` overrides, validate everything."""
    return spec_from_mapping(read_scenario(path, overrides))


def spec_from_mapping(data: dict) -> Spec:
    """Validate a raw mapping (as read from TOML) into the spec class of its model."""
    scenario = data.get("scenario")
    if "study" in data and scenario is None:
        raise SpecError("scenario file", "[study]", "a scenario (with [scenario]); this is a sensitivity study: run "
                                                    "it with `bearing-mbs sweep`")
    if not isinstance(scenario, dict):
        raise SpecError("scenario", scenario, "a [scenario] table with name, model and end_time is required")
    model = current_model_name(scenario.get("model"), warn=True)
    if not isinstance(model, str) or model not in MODELS:
        raise SpecError("scenario.model", model, f"must be one of {', '.join(MODELS)}")
    data = {key: value for key, value in copy.deepcopy(data).items() if value not in ([], {})}
    data["scenario"]["model"] = model
    return from_mapping(MODELS[model].spec, MODELS[model].prepare(data))


def current_model_name(name, warn: bool = False):
    """The model's name now: ``name`` itself, or the name a former one (:data:`RENAMED_MODELS`) has now, with a
    FutureWarning when ``warn``. Anything else (not a string, an unknown name) is returned as it is."""
    if not isinstance(name, str) or name not in RENAMED_MODELS:
        return name
    renamed = RENAMED_MODELS[name]
    if warn:
        warnings.warn(f"scenario.model = {name!r} is now called {renamed!r} (the name of its package); the old name "
                      f"will be refused in a later version", FutureWarning, stacklevel=3)
    return renamed
