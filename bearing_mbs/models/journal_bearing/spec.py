"""A ``journal_bearing`` scenario: ``[scenario]`` (``model = "journal_bearing"``) and ``[journal]``, with an optional
``[journal.recesses]`` table. ``bearing-mbs journal`` solves it statically (docs/fluid-film.md)."""

from __future__ import annotations

import math
from dataclasses import dataclass, replace

from bearing_mbs.contact.lubricant import Lubricant, LubricantError
from bearing_mbs.fluid_film.journal import MAX_CELLS, JournalBearing
from bearing_mbs.fluid_film.reynolds import CAVITATION
from bearing_mbs.spec import Spec, SpecError
from bearing_mbs.spec.fields import finite, in_range, one_of, positive, require
from bearing_mbs.spec.recesses import RecessSection

#: The ``[scenario] model`` value of a journal-bearing scenario.
MODEL_NAME = "journal_bearing"

#: Thermal models of the film: at the oil's inlet viscosity, or at the heat balance's effective temperature.
THERMAL = ("isothermal", "effective")
#: The oil's density [kg/m³] when the scenario gives neither ``density`` nor an oil (document 001, Table 2).
DENSITY = 860.0

@dataclass(frozen=True)
class OilSection:
    """``[journal.oil]``: the oil by its viscosity–temperature line (ASTM D341's Walther equation through the
    kinematic viscosity_40 and viscosity_100 [m²/s] at 40 and 100 °C, :mod:`bearing_mbs.contact.lubricant`),
    density_15 [kg/m³] at 15 °C and its thermal_expansion [1/K], specific_heat c_p [J/(kg K)] (document 001: 2000),
    and the inlet_temperature [°C] at which it enters the bearing, within the fit's range."""

    viscosity_40: float
    viscosity_100: float
    density_15: float = 870.0
    thermal_expansion: float = 6.4e-4
    specific_heat: float = 2000.0
    inlet_temperature: float = 40.0

    def __post_init__(self):
        positive("specific_heat", self.specific_heat)
        try:
            self.lubricant().kinematic_viscosity(self.inlet_temperature)
        except LubricantError as error:
            field = "inlet_temperature" if error.field == "temperature" else error.field
            raise SpecError(field, error.value, error.allowed) from None

    def lubricant(self) -> Lubricant:
        return Lubricant("the scenario's oil", self.viscosity_40, self.viscosity_100, self.density_15,
                         self.thermal_expansion, source="[journal.oil]")


@dataclass(frozen=True)
class JournalSection:
    """``[journal]``: diameter D [m] > 0 and length L [m] > 0 of the bore; radial_clearance C [m] in (0, D/2);
    speed_rpm [rpm] of the journal (counter-clockwise positive; 0: hydrostatic); viscosity μ [Pa s] > 0 and density
    ρ [kg/m³] > 0 (default 860), or instead an ``oil`` ([journal.oil], its values at its inlet temperature); thermal
    ``isothermal`` (the film at the oil's inlet viscosity) or ``effective`` (the film at the effective temperature
    of the heat balance, :mod:`.thermal`: needs [journal.oil] and recesses, whose flow carries the heat);
    coefficient_speeds_rpm [rpm], optional: the speeds at which the eight coefficients are also given, each at the
    journal's equilibrium under static_load [F_x, F_y] [N] (the steady force on the journal, e.g. [0, −W] for a
    weight W); eccentricity_ratio ε = e/C in [0, 1) and attitude [deg], the direction of the journal centre's
    displacement from +x (the first recess is centred at its first_angle), for the static solve; cavitation
    ``gumbel`` (half-Sommerfeld) or ``jfo`` (mass-conserving: it needs an oil source, recesses fed from a supply
    pressure > 0, a constant flow or a supply groove); grid = [n_theta, n_z] cells, each >= 4, fine enough that
    every recess holds a cell centre."""

    diameter: float
    length: float
    radial_clearance: float
    viscosity: float | None = None
    speed_rpm: float = 0.0
    density: float | None = None
    eccentricity_ratio: float = 0.0
    attitude: float = 0.0
    cavitation: str = "gumbel"
    grid: tuple[int, int] = (240, 60)
    recesses: RecessSection | None = None
    oil: OilSection | None = None
    thermal: str = "isothermal"
    coefficient_speeds_rpm: tuple[float, ...] = ()
    static_load: tuple[float, float] = (0.0, 0.0)

    def __post_init__(self):
        positive("diameter", self.diameter)
        positive("length", self.length)
        in_range("radial_clearance", self.radial_clearance, 0.0, self.diameter / 2, "m", low_open=True, high_open=True)
        if self.oil is None:
            require(self.viscosity is not None, "viscosity", None, "> 0 [Pa s], or a [journal.oil] table")
            positive("viscosity", self.viscosity)
            if self.density is not None:
                positive("density", self.density)
        else:
            for name in ("viscosity", "density"):
                require(getattr(self, name) is None, name, getattr(self, name),
                        "left out with [journal.oil]: the oil's value at its inlet temperature is used")
        in_range("speed_rpm", self.speed_rpm, -1e6, 1e6, "rpm")
        one_of("thermal", self.thermal, THERMAL)
        for k, rpm in enumerate(self.coefficient_speeds_rpm):
            in_range(f"coefficient_speeds_rpm.{k}", rpm, -1e6, 1e6, "rpm")
        require(len(self.static_load) == 2, "static_load", list(self.static_load), "[F_x, F_y] [N]")
        for k, force in enumerate(self.static_load):
            finite(f"static_load.{k}", force)
        require(not (self.coefficient_speeds_rpm and self.thermal == "effective"), "coefficient_speeds_rpm",
                list(self.coefficient_speeds_rpm), "[] with thermal = 'effective' (the effective temperature is the "
                "scenario's operating point's, not each speed's)")
        if self.thermal == "effective":
            require(self.oil is not None, "thermal", self.thermal,
                    "'isothermal' unless a [journal.oil] gives the viscosity against temperature")
            require(self.recesses is not None, "thermal", self.thermal,
                    "'isothermal' for a plain bore: the heat balance needs the oil flow through the bearing "
                    "([journal.recesses] with a supply)")
        in_range("eccentricity_ratio", self.eccentricity_ratio, 0.0, 1.0, "-", high_open=True)
        in_range("attitude", self.attitude, -360.0, 360.0, "deg")
        one_of("cavitation", self.cavitation, CAVITATION)
        require(len(self.grid) == 2 and all(isinstance(n, int) and n >= 4 for n in self.grid), "grid",
                list(self.grid), "[n_theta, n_z], integers >= 4")
        require(self.grid[0] * self.grid[1] <= MAX_CELLS, "grid", list(self.grid),
                f"at most {MAX_CELLS} cells (n_theta × n_z)")
        if self.recesses is not None:
            self.recesses.check_fits(self.bore(), self.grid)
        if self.cavitation == "jfo":
            r = self.recesses
            require(r is not None and r.feeds_oil, "cavitation",
                    self.cavitation, "'gumbel' unless the film has an oil source: the mass-conserving film fixes how "
                    "much oil it holds from what enters it, and with none (a plain bore, or recesses whose restrictors "
                    "feed from a supply pressure of 0) every cavitated film with ϑh constant along the bore solves it "
                    "alike; give [journal.recesses] with supply_pressure > 0, a constant flow, or a supply groove "
                    "(restrictor = 'none', 0 Pa for an ambient groove)")

    @property
    def oil_viscosity(self) -> float:
        """μ [Pa s] of the isothermal film: ``viscosity``, or the oil's at its inlet temperature."""
        if self.oil is None:
            return self.viscosity
        return self.oil.lubricant().dynamic_viscosity(self.oil.inlet_temperature)

    @property
    def oil_density(self) -> float:
        """ρ [kg/m³]: ``density`` (default 860), or the oil's at its inlet temperature."""
        if self.oil is None:
            return DENSITY if self.density is None else self.density
        return self.oil.lubricant().density(self.oil.inlet_temperature)

    def bore(self) -> JournalBearing:
        """The bore without its recesses."""
        return JournalBearing(self.diameter, self.length, self.radial_clearance, self.oil_viscosity, self.oil_density)

    def bearing(self) -> JournalBearing:
        """The bore and its recesses (without their supply)."""
        return replace(self.bore(), recesses=None if self.recesses is None else self.recesses.recesses())

    @property
    def speed(self) -> float:
        """Ω [rad/s]."""
        return self.speed_rpm * 2 * math.pi / 60


@dataclass(frozen=True)
class JournalSpec(Spec):
    """A ``journal_bearing`` scenario."""

    journal: JournalSection | None = None

    def __post_init__(self):
        super().__post_init__()
        require(self.scenario.model == MODEL_NAME, "scenario.model", self.scenario.model, f"{MODEL_NAME!r}")
        require(self.journal is not None, "journal", None, "a [journal] section")
