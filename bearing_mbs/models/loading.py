"""Scenario files to validated specs: the model named in ``[scenario]`` chooses the spec class."""

from __future__ import annotations

import copy
from pathlib import Path

from bearing_mbs.models.registry import MODELS
from bearing_mbs.spec import Spec, SpecError, apply_override, from_mapping, parse_override, read_toml


def load_spec(path: str | Path, overrides: list[str] = ()) -> Spec:
    """Read a TOML scenario file, apply ``section.key=value`` overrides, validate everything."""
    if isinstance(overrides, str):
        raise SpecError("overrides", overrides, "a list of 'section.key=value' strings, not one string")
    data = read_toml(path)
    for text in overrides:
        keys, value = parse_override(text)
        apply_override(data, keys, value)
    return spec_from_mapping(data)


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
