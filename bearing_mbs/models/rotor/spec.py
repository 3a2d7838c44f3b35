"""A ``rotor`` scenario: ``[scenario]`` (``model = "rotor"``), ``[rotor]``, ``[bearing]`` (with an optional
``[bearing.recesses]``) and ``[drive]`` (docs/fluid-film.md). A rigid rotor in its cylindrical mode on identical
journal bearings, plain or hybrid; gravity along −y."""

from __future__ import annotations

import math
from dataclasses import dataclass, replace

from bearing_mbs.elements.journal_bearings import SOURCES
from bearing_mbs.fluid_film.force_map import MAPPED_RESTRICTORS
from bearing_mbs.fluid_film.journal import MAX_CELLS, JournalBearing
from bearing_mbs.fluid_film.restrictors import RESTRICTORS
from bearing_mbs.fluid_film.reynolds import Supply
from bearing_mbs.spec import Spec
from bearing_mbs.spec.fields import finite, in_range, non_negative, one_of, positive, require
from bearing_mbs.spec.recesses import RecessSection

#: The ``[scenario] model`` value of a rotor scenario.
MODEL_NAME = "rotor"


@dataclass(frozen=True)
class RotorSection:
    """``[rotor]``: mass [kg] > 0 and polar_inertia [kg m²] > 0 of the rigid rotor; bearings >= 1 identical journal
    bearings share its weight; unbalance m_u r_u [kg m] >= 0 (0: none); initial_offset (x, y) [m] of the journal
    from its static equilibrium at the start speed (a small one excites whirl)."""

    mass: float
    polar_inertia: float
    bearings: int = 2
    unbalance: float = 0.0
    initial_offset: tuple[float, float] = (0.0, 0.0)

    def __post_init__(self):
        positive("mass", self.mass)
        positive("polar_inertia", self.polar_inertia)
        require(isinstance(self.bearings, int) and self.bearings >= 1, "bearings", self.bearings, "an integer >= 1")
        non_negative("unbalance", self.unbalance)
        require(len(self.initial_offset) == 2, "initial_offset", list(self.initial_offset), "[x, y] in m")
        for i, value in enumerate(self.initial_offset):
            finite(f"initial_offset.{i}", value)


@dataclass(frozen=True)
class BearingSection:
    """``[bearing]`` (each of the rotor's bearings): diameter D [m] > 0, length L [m] > 0, radial_clearance C [m] in
    (0, D/2), viscosity μ [Pa s] > 0; force ``short`` (Ocvirk's closed form) or ``map`` (the Reynolds solution
    tabulated on grid = [n_theta, n_z] cells, Gümbel cavitation, :mod:`bearing_mbs.fluid_film.force_map`);
    recesses (``[bearing.recesses]``, :class:`~bearing_mbs.spec.recesses.RecessSection`), optional: a hybrid
    bearing, with force ``map`` and a capillary or a directly supplied recess (restrictor ``none``)."""

    diameter: float
    length: float
    radial_clearance: float
    viscosity: float
    force: str = "short"
    grid: tuple[int, int] = (120, 30)
    recesses: RecessSection | None = None

    def __post_init__(self):
        positive("diameter", self.diameter)
        positive("length", self.length)
        in_range("radial_clearance", self.radial_clearance, 0.0, self.diameter / 2, "m", low_open=True, high_open=True)
        positive("viscosity", self.viscosity)
        one_of("force", self.force, SOURCES)
        require(len(self.grid) == 2 and all(isinstance(n, int) and n >= 4 for n in self.grid), "grid",
                list(self.grid), "[n_theta, n_z], integers >= 4")
        require(self.grid[0] * self.grid[1] <= MAX_CELLS, "grid", list(self.grid),
                f"at most {MAX_CELLS} cells (n_theta × n_z)")
        if self.recesses is not None:
            require(self.force == "map", "force", self.force,
                    "'map' for a recessed bearing (Ocvirk's short bearing has no recesses)")
            mapped = [name for name, kind in RESTRICTORS.items() if issubclass(kind, MAPPED_RESTRICTORS)]
            require(self.recesses.restrictor in mapped, "recesses.restrictor", self.recesses.restrictor,
                    f"one of {', '.join(mapped)}: the force map superposes the film's sources, which needs a "
                    "restrictor linear in the recess pressure")
            require(self.recesses.capillary_entrance_loss == 0, "recesses.capillary_entrance_loss",
                    self.recesses.capillary_entrance_loss, "0 with the force map (the entrance loss makes the "
                    "capillary's inflow nonlinear, and the map superposes the film's sources)")
            self.recesses.check_fits(self.bore(), self.grid)

    def bore(self) -> JournalBearing:
        """The bore without its recesses."""
        return JournalBearing(self.diameter, self.length, self.radial_clearance, self.viscosity)

    def bearing(self) -> JournalBearing:
        """The bore and its recesses."""
        return replace(self.bore(), recesses=None if self.recesses is None else self.recesses.recesses())

    def supply(self) -> Supply | None:
        """The recesses' supply (sized on the grid for a design pressure ratio), None for a plain bearing."""
        return None if self.recesses is None else self.recesses.supply(self.bearing(), self.grid)

    @property
    def hydrostatic(self) -> bool:
        """Whether the bearing carries load at rest (its recesses are fed)."""
        return self.recesses is not None and self.recesses.feeds_oil


@dataclass(frozen=True)
class DriveSection:
    """``[drive]``: the rotor's speed follows start_rpm → speed_rpm [rpm] linearly over ramp_time [s] (0: constant
    speed_rpm; a long ramp is a speed sweep), through a velocity servo of gain [N m s/rad] > 0. Plain journal
    bearings carry no load at rest, so start_rpm > 0 unless the bearings' recesses are fed."""

    speed_rpm: float
    start_rpm: float | None = None
    ramp_time: float = 0.0
    gain: float = 100.0

    def __post_init__(self):
        in_range("speed_rpm", self.speed_rpm, 0.0, 1e6, "rpm", low_open=True)
        if self.start_rpm is not None:
            in_range("start_rpm", self.start_rpm, 0.0, 1e6, "rpm")
        non_negative("ramp_time", self.ramp_time)
        positive("gain", self.gain)

    @property
    def start_speed(self) -> float:
        """Ω at t = 0 [rad/s]."""
        return (self.speed_rpm if self.start_rpm is None else self.start_rpm) * math.pi / 30


@dataclass(frozen=True)
class RotorSpec(Spec):
    """A ``rotor`` scenario."""

    rotor: RotorSection | None = None
    bearing: BearingSection | None = None
    drive: DriveSection | None = None

    def __post_init__(self):
        super().__post_init__()
        require(self.scenario.model == MODEL_NAME, "scenario.model", self.scenario.model, f"{MODEL_NAME!r}")
        for name in ("rotor", "bearing", "drive"):
            require(getattr(self, name) is not None, name, None, f"a [{name}] section")
        require(self.drive.ramp_time <= self.scenario.end_time, "drive.ramp_time", self.drive.ramp_time,
                f"<= scenario.end_time = {self.scenario.end_time:g} s")
        require(self.drive.start_speed > 0 or self.bearing.hydrostatic, "drive.start_rpm", self.drive.start_rpm,
                "> 0: plain journal bearings carry no load at rest (fed recesses do)")
