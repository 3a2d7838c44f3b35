"""What a user describes: validated frozen dataclasses, loaded from TOML scenario files.

Every field documents its unit and valid range; construction raises :class:`SpecError` naming the field
(its dotted path when loaded from a file), the value and what is allowed. See ``docs/scenario-format.md``.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path

from .balls import BallSpec, BoxSpec, ConstraintSpec
from .contact import ContactSpec
from .fields import SpecError, non_negative, one_of, positive, require
from .loading import apply_override, from_mapping, parse_override, read_toml, to_mapping
from .solver import ExudynSolver, ReferenceSolver, SolverSpec

MODELS = ("balls",)


@dataclass(frozen=True)
class Scenario:
    """``[scenario]``: name; model (``balls``); end_time [s] > 0; gravity [m/s²] >= 0, acting along −y;
    description: free text."""

    name: str
    model: str
    end_time: float
    gravity: float = 9.81
    description: str = ""

    def __post_init__(self):
        one_of("model", self.model, MODELS)
        positive("end_time", self.end_time)
        non_negative("gravity", self.gravity)


@dataclass(frozen=True)
class ContactGroups:
    """``[contact]``: one :class:`ContactSpec` per group of pairs. balls model: ``wall`` (ball–floor and
    ball–wall) and ``ball`` (ball–ball)."""

    wall: ContactSpec = field(default_factory=ContactSpec)
    ball: ContactSpec = field(default_factory=ContactSpec)


@dataclass(frozen=True)
class Spec:
    """A whole scenario file."""

    scenario: Scenario
    solver: SolverSpec = field(default_factory=SolverSpec)
    contact: ContactGroups = field(default_factory=ContactGroups)
    balls: tuple[BallSpec, ...] = ()
    box: BoxSpec | None = None
    constraints: tuple[ConstraintSpec, ...] = ()

    def __post_init__(self):
        if self.scenario.model == "balls":
            require(len(self.balls) > 0, "balls", [], "the balls model needs at least one [[balls]] entry")
            for i, constraint in enumerate(self.constraints):
                for j, body in enumerate(constraint.bodies):
                    require(
                        0 <= body < len(self.balls),
                        f"constraints.{i}.bodies.{j}",
                        body,
                        f"must be a ball index in 0..{len(self.balls) - 1}",
                    )


def load_spec(path: str | Path, overrides: list[str] = ()) -> Spec:
    """Read a TOML scenario file, apply ``section.key=value`` overrides, validate everything."""
    data = read_toml(path)
    for text in overrides:
        keys, value = parse_override(text)
        apply_override(data, keys, value)
    return from_mapping(Spec, data)


def spec_from_mapping(data: dict) -> Spec:
    return from_mapping(Spec, data)


__all__ = [
    "BallSpec",
    "BoxSpec",
    "ConstraintSpec",
    "ContactGroups",
    "ContactSpec",
    "ExudynSolver",
    "ReferenceSolver",
    "Scenario",
    "SolverSpec",
    "Spec",
    "SpecError",
    "load_spec",
    "spec_from_mapping",
    "to_mapping",
]
