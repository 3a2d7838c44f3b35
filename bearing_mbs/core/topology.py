"""Which body and which pair is which: the layout a model's builder knows, kept for everything downstream.

A builder fills a :class:`Topology` with named index arrays (body *roles* and pair *groups*); it travels with
the scene and the result, so analysis, the step advisor, figures and studies find the inner ring, the cage, the
rollers and the raceway pairs by index, never by matching names. A group's array may have more than one axis
(the bearing's pockets are (Z, 4): four pocket edges per roller), and rows then follow the roller order.

The names are typed constants: :class:`Role` for bodies, :class:`Group` for pairs. They are string enums, so a
topology written to JSON and read back, or a key spelled as text, is the same key; a misspelt member fails at
import, where a misspelt string would find nothing. They live here, in the core, so that a study or an engine can
name a role without importing a model's package. The built-in models' roles are listed; a :class:`Topology` takes
any string, so a model added from outside names its own.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field
from enum import StrEnum

import numpy as np


class Role(StrEnum):
    """Body roles of the models' topologies."""

    INNER_RING = "inner_ring"  # the roller bearing's driven inner ring
    CAGE = "cage"
    ROLLERS = "rollers"  # the roller bearing's Z rollers, in roller order
    BALLS = "balls"  # the balls model's free balls
    ROTOR = "rotor"  # the rotor model's journal
    BLADE_ROOT = "blade_root"  # the slewing-bearing pitch model's blade root


class Group(StrEnum):
    """Contact-pair groups of the models' topologies."""

    INNER_RACE = "inner_race"  # roller on the inner raceway, one per roller
    OUTER_RACE = "outer_race"  # roller on the outer raceway, one per roller
    POCKET = "pocket"  # roller on its pocket's edges, (Z, 4)
    POCKET_FILM = "pocket_film"  # roller on its pocket walls' oil films, (Z, 2)
    ROLLER = "roller"  # neighbouring rollers of a full-complement bearing
    LAND = "land"  # the cage on its guiding land
    WALL = "wall"  # the balls model's ball on a wall
    BALL = "ball"  # the balls model's ball on ball


def _frozen(arrays: Mapping) -> dict[str, np.ndarray]:
    frozen = {}
    for name, indices in arrays.items():
        array = np.array(indices, dtype=np.int64)
        array.setflags(write=False)
        frozen[str(name)] = array
    return frozen


@dataclass(frozen=True)
class Topology:
    """Named index arrays into the scene's bodies (``bodies``) and contact pairs (``pairs``).

    Absent roles and groups are simply missing (a full-complement bearing has no ``cage``); use :meth:`body`
    for a role of exactly one body and :meth:`group` for a group that may be empty.
    """

    bodies: Mapping[str, np.ndarray] = field(default_factory=dict)
    pairs: Mapping[str, np.ndarray] = field(default_factory=dict)

    def __post_init__(self):
        object.__setattr__(self, "bodies", _frozen(self.bodies))
        object.__setattr__(self, "pairs", _frozen(self.pairs))

    def __eq__(self, other) -> bool:
        return isinstance(other, Topology) and self.to_dict() == other.to_dict()

    def __hash__(self) -> int:
        return hash(repr(self.to_dict()))

    def body(self, role: str) -> int:
        """The index of the one body with this role; KeyError if the scene has none."""
        indices = self.bodies[role]
        if indices.size != 1:
            raise ValueError(f"role {role!r} has {indices.size} bodies, not one")
        return int(indices.ravel()[0])

    def has(self, role: str) -> bool:
        return role in self.bodies and self.bodies[role].size > 0

    def role(self, role: str) -> np.ndarray:
        """Body indices of a role (empty if absent)."""
        return self.bodies.get(role, np.zeros(0, dtype=np.int64))

    def group(self, name: str) -> np.ndarray:
        """Pair indices of a group (empty if absent)."""
        return self.pairs.get(name, np.zeros(0, dtype=np.int64))

    def check(self, body_count: int, pair_count: int) -> None:
        """Every index refers to an existing body or pair."""
        for what, arrays, count in (("body", self.bodies, body_count), ("pair", self.pairs, pair_count)):
            for name, indices in arrays.items():
                if indices.size and not (0 <= indices.min() and indices.max() < count):
                    raise ValueError(f"topology: {what} group {name!r} refers to an index outside 0..{count - 1}")

    def to_dict(self) -> dict:
        """Plain lists, for JSON."""
        return {"bodies": {k: v.tolist() for k, v in self.bodies.items()},
                "pairs": {k: v.tolist() for k, v in self.pairs.items()}}

    @classmethod
    def from_dict(cls, data: Mapping) -> Topology:
        return cls(bodies=data.get("bodies", {}), pairs=data.get("pairs", {}))
