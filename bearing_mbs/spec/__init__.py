"""What a user describes: validated frozen dataclasses, loaded from TOML scenario files.

Every field documents its unit and valid range; construction raises :class:`SpecError` naming the field
(its dotted path when loaded from a file), the value and what is allowed. See ``docs/scenario-format.md``.
"""

from __future__ import annotations

import copy
from dataclasses import dataclass, field
from pathlib import Path

from .balls import BallSpec, BoxSpec, ConstraintSpec
from .bearing import (
    PRESETS,
    AnalysisSpec,
    BearingSpec,
    CageSpec,
    DriveSpec,
    GearTrainSpec,
    LoadSpec,
    LubricantSpec,
    MaterialSpec,
)
from .contact import ContactSpec
from .convergence import ConvergenceSpec, RunSettings
from .fields import SpecError, non_negative, one_of, positive, require
from .loading import apply_override, from_mapping, parse_override, read_toml, to_mapping
from .solver import ExudynSolver, ReferenceSolver, SolverSpec

MODELS = ("balls", "bearing")

#: Sections each model reads; a section of another model is an error.
MODEL_SECTIONS = {
    "balls": ("balls", "box", "constraints"),
    "bearing": ("bearing", "cage", "drive", "load", "lubricant", "analysis"),
}

#: Contact groups of each model with their defaults; a partial ``[contact.<group>]`` table is merged over them.
# Bearing defaults (docs/bearing.md): Palmgren line contacts, Lankarani–Nikravesh with the approach speed floored
# at 0.1 m/s (a damping ratio near 0.1 in the load zone instead of an overdamped contact), the annex's erf friction
# with μ = 0.1 and v_reg = 0.01 m/s, and on the raceways a rolling-resistance arm of 15 µm (f = μ_R/r ≈ 1.2e-3 for
# the seed roller, the order of catalogue friction coefficients of cylindrical roller bearings, ~0.001).
_SLIDING = ContactSpec(normal_law="lankarani_nikravesh", stiffness_model="palmgren", restitution=0.9,
                       approach_speed_floor=0.1, friction_law="erf", friction_coefficient=0.1, regularisation_speed=0.01)
_RACEWAY = ContactSpec(**{**to_mapping(_SLIDING), "rolling_resistance_arm": 1.5e-5})
CONTACT_GROUPS = {
    "balls": {"wall": ContactSpec(), "ball": ContactSpec()},
    "bearing": {"inner_race": _RACEWAY, "outer_race": _RACEWAY, "pocket": _SLIDING, "land": _SLIDING,
                "roller": _SLIDING},
}


@dataclass(frozen=True)
class Scenario:
    """``[scenario]``: name; model (``balls`` or ``bearing``); end_time [s] > 0; gravity [m/s²] >= 0, acting along −y;
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
    """``[contact]``: one :class:`ContactSpec` per group of pairs (:data:`CONTACT_GROUPS`).

    balls model: ``wall`` (ball–floor and ball–wall) and ``ball`` (ball–ball). bearing model:
    ``inner_race``, ``outer_race``, ``pocket`` (roller–cage), ``land`` (cage–ring land) and ``roller``
    (roller–roller). Loading fills every group of the model, merging a partial table over its default.
    """

    wall: ContactSpec | None = None
    ball: ContactSpec | None = None
    inner_race: ContactSpec | None = None
    outer_race: ContactSpec | None = None
    pocket: ContactSpec | None = None
    land: ContactSpec | None = None
    roller: ContactSpec | None = None


@dataclass(frozen=True)
class Spec:
    """A whole scenario file."""

    scenario: Scenario
    solver: SolverSpec = field(default_factory=SolverSpec)
    contact: ContactGroups = field(default_factory=ContactGroups)
    balls: tuple[BallSpec, ...] = ()
    box: BoxSpec | None = None
    constraints: tuple[ConstraintSpec, ...] = ()
    bearing: BearingSpec | None = None
    cage: CageSpec | None = None
    drive: DriveSpec | None = None
    load: LoadSpec | None = None
    lubricant: LubricantSpec | None = None
    analysis: AnalysisSpec | None = None
    convergence: ConvergenceSpec | None = None

    def __post_init__(self):
        if self.scenario.model == "bearing":
            require(self.bearing is not None, "bearing", None, "the bearing model needs a [bearing] section")
            for name, default in (("cage", CageSpec), ("drive", DriveSpec), ("load", LoadSpec),
                                  ("lubricant", LubricantSpec), ("analysis", AnalysisSpec)):
                if getattr(self, name) is None:
                    object.__setattr__(self, name, default())
            if self.analysis.start is not None:
                require(self.analysis.start < self.scenario.end_time, "analysis.start", self.analysis.start,
                        "must be before scenario.end_time")
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
    return spec_from_mapping(data)


def spec_from_mapping(data: dict) -> Spec:
    """Validate a raw mapping (as read from TOML) into a :class:`Spec`."""
    return from_mapping(Spec, with_model_defaults(data))


def with_model_defaults(data: dict) -> dict:
    """Fill what depends on the model before validation: reject sections and contact groups of other
    models, merge each contact group over its default, and put a bearing preset under ``[bearing]``."""
    data = copy.deepcopy(data)
    model = data.get("scenario", {}).get("model") if isinstance(data.get("scenario"), dict) else None
    if model not in MODELS:
        return data  # the loader reports the bad model
    for other, sections in MODEL_SECTIONS.items():
        for section in sections:
            if other != model and section in data:
                if data[section] in ([], {}):  # an empty section (e.g. written back by to_mapping) is absent
                    del data[section]
                    continue
                raise SpecError(section, "...", f"is a section of the {other} model, not of model {model!r}")
    contact = data.setdefault("contact", {})
    if isinstance(contact, dict):
        groups = CONTACT_GROUPS[model]
        for group, table in contact.items():
            if group not in groups:
                raise SpecError(f"contact.{group}", table, f"is not a contact group of model {model!r}; "
                                f"groups: {', '.join(groups)}")
            if not isinstance(table, dict):
                raise SpecError(f"contact.{group}", table, "must be a table")
        for group, default in groups.items():
            contact[group] = {**to_mapping(default), **contact.get(group, {})}
    bearing = data.get("bearing")
    if isinstance(bearing, dict) and bearing.get("preset"):
        name = bearing["preset"]
        if name not in PRESETS:
            raise SpecError("bearing.preset", name, f"must be one of {', '.join(PRESETS)}")
        given = set(bearing)
        if given & {"pitch_diameter", "diametral_clearance"}:  # the user chose the other raceway description
            bearing.update({k: v for k, v in PRESETS[name].items()
                            if k not in given and k not in ("inner_race_diameter", "outer_race_diameter")})
        else:
            bearing.update({k: v for k, v in PRESETS[name].items() if k not in given})
    return data


__all__ = [
    "AnalysisSpec",
    "BallSpec",
    "BearingSpec",
    "BoxSpec",
    "CageSpec",
    "ConstraintSpec",
    "ContactGroups",
    "ContactSpec",
    "ConvergenceSpec",
    "DriveSpec",
    "ExudynSolver",
    "GearTrainSpec",
    "LoadSpec",
    "LubricantSpec",
    "MaterialSpec",
    "ReferenceSolver",
    "RunSettings",
    "Scenario",
    "SolverSpec",
    "Spec",
    "SpecError",
    "load_spec",
    "spec_from_mapping",
    "to_mapping",
    "with_model_defaults",
]
