"""Scenario files to validated specs: the model named in ``[scenario]`` chooses the spec class."""

from __future__ import annotations

import copy
from pathlib import Path

from bearing_mbs.models.registry import MODELS
from bearing_mbs.spec import Spec, SpecError, from_mapping, read_scenario


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
    model = scenario.get("model")
    if not isinstance(model, str) or model not in MODELS:
        raise SpecError("scenario.model", model, f"must be one of {', '.join(MODELS)}")
    data = {key: value for key, value in copy.deepcopy(data).items() if value not in ([], {})}
    return from_mapping(MODELS[model].spec, MODELS[model].prepare(data))
