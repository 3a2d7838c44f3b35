"""Strict conversion between TOML-like mappings and the frozen spec dataclasses.

Unknown keys, missing required keys and wrongly typed values are errors that name the dotted path. A table
given for a field whose default is itself a table (``[bearing.cage_material]``) is merged over that default,
so a partial table changes only the keys it names.
``--set section.key=value`` overrides are applied to the raw mapping before conversion, so they go
through exactly the same validation as the file.

A scenario file may hold named variants of its model: ``[variants.<name>]`` tables of changes to its other
tables, the one named by ``[scenario] variant`` applied when the file is read (:func:`read_scenario`), before the
overrides. A spec holds the model the variant made, not the variant's name.
"""

from __future__ import annotations

import dataclasses
import tomllib
import types
import typing
from pathlib import Path

from bearing_mbs.spec.fields import SpecError

_MISSING = dataclasses.MISSING


def from_mapping(cls, data, path: str = ""):
    """Build dataclass ``cls`` from a mapping, recursively, validating keys and types."""
    if not isinstance(data, dict):
        raise SpecError(path or cls.__name__, data, f"must be a table of {cls.__name__} keys")
    hints = typing.get_type_hints(cls)
    fields = {f.name: f for f in dataclasses.fields(cls)}
    for key in data:
        if key not in fields:
            raise SpecError(_join(path, key), data[key], f"unknown key; allowed keys: {', '.join(fields)}")
    kwargs = {}
    for name, f in fields.items():
        if name in data:
            value = data[name]
            default = _default(f)
            if dataclasses.is_dataclass(default) and isinstance(value, dict):
                value = {**to_mapping(default), **value}  # a partial table keeps the field's other defaults
            kwargs[name] = _convert(hints[name], value, _join(path, name))
        elif f.default is _MISSING and f.default_factory is _MISSING:
            raise SpecError(_join(path, name), None, "required key is missing")
    try:
        return cls(**kwargs)
    except SpecError as error:
        raise error.within(path) from None


def to_mapping(instance) -> dict:
    """Dataclass → plain mapping (tuples as lists, ``None`` left out), the inverse of :func:`from_mapping`."""

    def plain(value):
        if dataclasses.is_dataclass(value):
            return {f.name: plain(getattr(value, f.name)) for f in dataclasses.fields(value)
                    if getattr(value, f.name) is not None}
        if isinstance(value, tuple):
            return [plain(item) for item in value]
        return value

    return plain(instance)


def _default(f: dataclasses.Field):
    if f.default is not _MISSING:
        return f.default
    if f.default_factory is not _MISSING:
        return f.default_factory()
    return None


def _join(path: str, key) -> str:
    return f"{path}.{key}" if path else str(key)


def _convert(hint, value, path):
    origin, args = typing.get_origin(hint), typing.get_args(hint)
    if origin in (typing.Union, types.UnionType):
        options = [a for a in args if a is not type(None)]
        if len(options) == 1:
            return _convert(options[0], value, path)
        for option in options:  # e.g. float | str: first that fits
            try:
                return _convert(option, value, path)
            except SpecError:
                continue
        raise SpecError(path, value, f"must be one of the types {', '.join(o.__name__ for o in options)}")
    if dataclasses.is_dataclass(hint):
        return from_mapping(hint, value, path)
    if origin is tuple:
        if not isinstance(value, (list, tuple)):
            raise SpecError(path, value, "must be an array")
        if len(args) == 2 and args[1] is Ellipsis:
            return tuple(_convert(args[0], item, _join(path, i)) for i, item in enumerate(value))
        if len(value) != len(args):
            raise SpecError(path, value, f"must be an array of {len(args)} values")
        return tuple(_convert(a, item, _join(path, i)) for i, (a, item) in enumerate(zip(args, value)))
    if hint is float:
        if isinstance(value, bool) or not isinstance(value, (int, float)):
            raise SpecError(path, value, "must be a number")
        return float(value)
    if hint is int:
        if isinstance(value, bool) or not isinstance(value, int):
            raise SpecError(path, value, "must be an integer")
        return value
    if hint is bool:
        if not isinstance(value, bool):
            raise SpecError(path, value, "must be true or false")
        return value
    if hint is str:
        if not isinstance(value, str):
            raise SpecError(path, value, "must be a string")
        return value
    raise TypeError(f"unsupported spec field type {hint!r} at {path}")


def parse_override(text: str) -> tuple[list[str], object]:
    """``'contact.wall.stiffness=6e6'`` → (['contact', 'wall', 'stiffness'], 6e6).

    The value is read as a TOML value (numbers, booleans, arrays, quoted strings); anything that is not
    valid TOML is taken as a bare string, so ``solver.engine=exudyn`` works without quotes.
    """
    if "=" not in text:
        raise SpecError(text, None, "an override must look like section.key=value")
    path, raw = text.split("=", 1)
    keys = [k.strip() for k in path.strip().split(".")]
    if not all(keys):
        raise SpecError(path, raw, "the path must be dotted keys like section.key")
    try:
        value = tomllib.loads(f"value = {raw.strip()}")["value"]
    except tomllib.TOMLDecodeError:
        value = raw.strip()
    return keys, value


def apply_override(data: dict, keys: list[str], value) -> None:
    """Set ``value`` at the dotted ``keys`` of a raw mapping; list items are addressed by index."""
    node = data
    for depth, key in enumerate(keys[:-1]):
        where = ".".join(keys[: depth + 1])
        if isinstance(node, list):
            if not key.isdigit() or int(key) >= len(node):
                raise SpecError(where, key, f"must be an index in 0..{len(node) - 1}")
            node = node[int(key)]
        else:
            node = node.setdefault(key, {})
        if not isinstance(node, (dict, list)):
            raise SpecError(where, node, "is a value, not a section")
    last = keys[-1]
    if isinstance(node, list):
        if not last.isdigit() or int(last) >= len(node):
            raise SpecError(".".join(keys), value, f"index must be in 0..{len(node) - 1}")
        node[int(last)] = value
    else:
        node[last] = value


def read_scenario(path: str | Path, overrides: list[str] = ()) -> dict:
    """A scenario file as a raw mapping: its variant (``[scenario] variant``, which an override may choose) applied,
    then the ``section.key=value`` overrides. ``[variants]`` and ``variant`` are gone from the result."""
    if isinstance(overrides, str):
        raise SpecError("overrides", overrides, "a list of 'section.key=value' strings, not one string")
    data = read_toml(path)
    changes = [parse_override(text) for text in overrides]
    variants = data.pop("variants", {})
    scenario = data.get("scenario") if isinstance(data.get("scenario"), dict) else {}
    name = scenario.pop("variant", None)
    for keys, value in changes:
        if keys == ["scenario", "variant"]:
            name = value
    if name is not None:
        if not isinstance(variants, dict) or not isinstance(variants.get(name), dict):
            names = ", ".join(variants) if isinstance(variants, dict) and variants else "the file has none"
            raise SpecError("scenario.variant", name, f"must name one of the file's [variants] tables ({names})")
        for keys, value in _leaves(variants[name]):
            apply_override(data, keys, value)
    for keys, value in changes:
        if keys != ["scenario", "variant"]:
            apply_override(data, keys, value)
    return data


def _leaves(table: dict, keys: tuple[str, ...] = ()):
    """(dotted keys, value) of every value of a nested table that is not itself a table."""
    for key, value in table.items():
        if isinstance(value, dict) and value:
            yield from _leaves(value, (*keys, key))
        else:
            yield [*keys, key], value


def read_toml(path: str | Path) -> dict:
    path = Path(path)
    if path.is_dir():
        raise SpecError("scenario file", str(path), "a TOML file; this is a directory")
    try:
        with path.open("rb") as handle:
            return tomllib.load(handle)
    except FileNotFoundError:
        raise SpecError("scenario file", str(path), "file not found") from None
    except OSError as error:
        raise SpecError("scenario file", str(path), f"a readable file ({error.strerror})") from None
    except tomllib.TOMLDecodeError as error:
        raise SpecError("scenario file", str(path), f"is not valid TOML: {error}") from None
