"""Property: whatever mapping reaches the spec loader, it loads or raises the package's SpecError, never anything
else (a TypeError, a KeyError, a ZeroDivisionError, a traceback a user cannot read).

Two generators, for every registered model (each starts from a shipped scenario of its model):

* *mutations* of a valid scenario: values replaced at random paths by values of random type and size (NaN,
  ±inf, huge and negative numbers, booleans, strings, lists, tables), keys removed, unknown keys added, whole
  sections replaced;
* *shapes*: random nested tables of random keys and values under a valid ``[scenario]`` header.

At least 500 examples of each per model in the default run.
"""

from __future__ import annotations

import copy

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from bearing_mbs.models import MODELS, spec_from_mapping
from bearing_mbs.spec import SpecError, read_scenario

from cases import SCENARIOS

#: A shipped scenario of every registered model.
BASES = {"cylindrical_roller": "seed_hss_steady.toml", "balls": "seed_case5.toml",
         "slewing_bearing": "seed_slewing_pitch.toml", "journal_bearing": "seed_hybrid_journal.toml", "rotor": "seed_rotor_unbalance.toml"}
EXAMPLES = 500

scalars = st.one_of(
    st.none(), st.booleans(), st.integers(min_value=-10**30, max_value=10**30),
    st.floats(allow_nan=True, allow_infinity=True), st.text(max_size=12),
    st.sampled_from([0, -1, 1e-300, 1e300, "", "none", "palmgren", "penalty", "exudyn", "rk4"]),
)
values = st.recursive(scalars, lambda inner: st.one_of(st.lists(inner, max_size=4),
                                                       st.dictionaries(st.text(max_size=8), inner, max_size=4)),
                      max_leaves=8)


def _base(model: str) -> dict:
    return read_scenario(SCENARIOS / BASES[model])


def _paths(data, prefix=()):
    """Every path to a value of the nested mapping (tables and list items included)."""
    items = data.items() if isinstance(data, dict) else enumerate(data) if isinstance(data, list) else ()
    for key, value in items:
        yield (*prefix, key)
        yield from _paths(value, (*prefix, key))


def _loads_or_refuses(data) -> None:
    try:
        spec_from_mapping(data)
    except SpecError:
        pass


def test_every_model_has_a_base():
    assert set(BASES) >= set(MODELS) - {"throw"}


@st.composite
def mutated(draw, model):
    data = copy.deepcopy(_base(model))
    for _ in range(draw(st.integers(min_value=1, max_value=4))):
        paths = list(_paths(data))
        if not paths:  # every table removed: nothing left to mutate
            break
        path = draw(st.sampled_from(paths))
        parent = data
        for key in path[:-1]:
            parent = parent[key]
        action = draw(st.sampled_from(["replace", "replace", "replace", "remove", "add"]))
        if action == "replace":
            parent[path[-1]] = draw(values)
        elif action == "remove" and isinstance(parent, dict):
            del parent[path[-1]]
        elif isinstance(parent, dict):
            parent[draw(st.text(min_size=1, max_size=8))] = draw(values)
    return data


@st.composite
def shaped(draw, model):
    data = {"scenario": {"name": "random", "model": model, "end_time": draw(st.floats(1e-6, 1.0))}}
    data.update(draw(st.dictionaries(st.sampled_from(["solver", "bearing", "contact", "load", "drive", "cage",
                                                      "balls", "box", "analysis", "lubricant", "convergence",
                                                      "constraints", "junk"]), values, max_size=5)))
    return data


@pytest.mark.parametrize("model", sorted(BASES))
@settings(max_examples=EXAMPLES, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(data=st.data())
def test_mutated_scenarios_load_or_raise_the_spec_error(model, data):
    _loads_or_refuses(data.draw(mutated(model)))


@pytest.mark.parametrize("model", sorted(BASES))
@settings(max_examples=EXAMPLES, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(data=st.data())
def test_random_shapes_load_or_raise_the_spec_error(model, data):
    _loads_or_refuses(data.draw(shaped(model)))
