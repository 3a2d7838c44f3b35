"""``[*.recesses]``: the recesses of a hybrid journal bearing and how oil reaches them, shared by the models that
carry journal bearings (``journal_bearing``'s ``[journal.recesses]``, ``rotor``'s ``[bearing.recesses]``)."""

from __future__ import annotations

from dataclasses import dataclass, replace

from bearing_mbs.fluid_film.design import sized_capillary, sized_capillary_bore, sized_orifice
from bearing_mbs.fluid_film.journal import FilmGrid, JournalBearing, Recesses
from bearing_mbs.fluid_film.restrictors import (
    CAPILLARY_MIN_ASPECT,
    RESTRICTORS,
    Capillary,
    ConstantFlow,
    DirectSupply,
    Orifice,
    feeds_oil,
)
from bearing_mbs.fluid_film.reynolds import Supply
from bearing_mbs.spec.fields import in_range, non_negative, one_of, positive, require

#: What each restrictor needs besides the supply pressure.
RESTRICTOR_KEYS = {"capillary": ("capillary_length", "capillary_diameter"), "orifice": ("orifice_diameter",),
                   "constant_flow": ("flow",), "none": ()}
#: The bore a design pressure ratio sizes, by restrictor.
SIZED_BORE = {"capillary": "capillary_diameter", "orifice": "orifice_diameter"}


@dataclass(frozen=True)
class RecessSection:
    """count >= 1 recesses of angular_width [deg] (together less than 360°; one recess of 360° is a circumferential
    groove) by axial_length [m] (<= the bearing length), depth [m] > 0, the first centred at first_angle [deg];
    supply_pressure [Pa] >= 0 through a restrictor: ``capillary`` (capillary_length, capillary_diameter [m], at least
    20 bores long; capillary_entrance_loss K [-] >= 0, default 0: the kinetic entry term K ρ ū²/2, 1.25 for a laminar
    tube, :mod:`bearing_mbs.fluid_film.restrictors`), ``orifice`` (orifice_diameter [m], discharge_coefficient in (0, 1]), ``constant_flow`` (flow
    [m³/s] per recess) or ``none`` (the recess is held at the supply pressure: a supply groove);
    design_pressure_ratio β in (0, 1), optional, with a capillary or an orifice: its bore is then sized so that the
    centred recesses sit at β × supply_pressure (:mod:`bearing_mbs.fluid_film.design`), and capillary_diameter or
    orifice_diameter must be left out."""

    count: int
    angular_width: float
    axial_length: float
    depth: float
    supply_pressure: float
    restrictor: str = "capillary"
    first_angle: float = 0.0
    capillary_length: float | None = None
    capillary_diameter: float | None = None
    capillary_entrance_loss: float = 0.0
    orifice_diameter: float | None = None
    discharge_coefficient: float = 0.6
    flow: float | None = None
    design_pressure_ratio: float | None = None

    def __post_init__(self):
        require(isinstance(self.count, int) and self.count >= 1, "count", self.count, "an integer >= 1")
        widest = 360.0 if self.count == 1 else 360.0 / self.count
        in_range("angular_width", self.angular_width, 0.0, widest, "deg", low_open=True, high_open=self.count > 1)
        positive("axial_length", self.axial_length)
        positive("depth", self.depth)
        non_negative("supply_pressure", self.supply_pressure)
        one_of("restrictor", self.restrictor, tuple(RESTRICTORS))
        in_range("first_angle", self.first_angle, -360.0, 360.0, "deg")
        sized = None
        if self.design_pressure_ratio is not None:
            in_range("design_pressure_ratio", self.design_pressure_ratio, 0.0, 1.0, "-", low_open=True, high_open=True)
            require(self.restrictor in SIZED_BORE, "design_pressure_ratio", self.design_pressure_ratio,
                    f"only with restrictor = 'capillary' or 'orifice' (here {self.restrictor!r})")
            require(self.supply_pressure > 0, "design_pressure_ratio", self.design_pressure_ratio,
                    "only with supply_pressure > 0 (a ratio of nothing sizes nothing)")
            sized = SIZED_BORE[self.restrictor]
            require(getattr(self, sized) is None, sized, getattr(self, sized),
                    "left out with design_pressure_ratio: the bore is sized for it")
        for name in RESTRICTOR_KEYS[self.restrictor]:
            if name == sized:
                continue
            require(getattr(self, name) is not None, name, None, f"required by restrictor = {self.restrictor!r}")
            positive(name, getattr(self, name))
        in_range("discharge_coefficient", self.discharge_coefficient, 0.0, 1.0, "-", low_open=True)
        non_negative("capillary_entrance_loss", self.capillary_entrance_loss)
        require(self.capillary_entrance_loss == 0 or self.restrictor == "capillary", "capillary_entrance_loss",
                self.capillary_entrance_loss, f"0 with restrictor = {self.restrictor!r} (it is a capillary's)")
        if self.restrictor == "capillary" and sized is None:
            require(self.capillary_length >= CAPILLARY_MIN_ASPECT * self.capillary_diameter, "capillary_length",
                    self.capillary_length, f">= {CAPILLARY_MIN_ASPECT:g} × capillary_diameter = "
                    f"{CAPILLARY_MIN_ASPECT * self.capillary_diameter:g} m (laminar, developed flow)")

    def recesses(self) -> Recesses:
        return Recesses(self.count, self.angular_width, self.axial_length, self.depth, self.first_angle)

    @property
    def feeds_oil(self) -> bool:
        """Whether the restrictors bring oil into the film (:func:`~bearing_mbs.fluid_film.restrictors.feeds_oil`)."""
        return feeds_oil(RESTRICTORS[self.restrictor], self.supply_pressure)

    def check_fits(self, bore: JournalBearing, grid: tuple[int, int]) -> None:
        """SpecError (fields relative to the bearing's section) unless these recesses fit the plain ``bore`` on
        ``grid``: they are no longer than it, every recess holds a cell centre (a recess of no cell has no balance: a
        singular system), and a capillary sized for the design pressure ratio is long enough for laminar, developed
        flow."""
        require(self.axial_length <= bore.length, "recesses.axial_length", self.axial_length,
                f"<= length = {bore.length:g} m")
        bearing = replace(bore, recesses=self.recesses())
        empty = [k + 1 for k, area in enumerate(FilmGrid.build(bearing, *grid).recess_areas) if area == 0]
        n_theta, n_z = grid
        require(not empty, "grid", list(grid),
                f"cells fine enough that every recess holds a cell centre: recess {empty[0] if empty else ''} "
                f"({self.angular_width:g} deg × {self.axial_length:g} m) holds none of the cells of "
                f"{360 / n_theta:g} deg × {bearing.length / n_z:g} m; refine the grid")
        if self.design_pressure_ratio is None or self.restrictor != "capillary":
            return
        ratio = self.design_pressure_ratio
        diameter = sized_capillary_bore(bearing, self.supply_pressure, ratio, self.capillary_length, grid,
                                        self.capillary_entrance_loss)
        require(self.capillary_length >= CAPILLARY_MIN_ASPECT * diameter, "recesses.design_pressure_ratio", ratio,
                f"a ratio whose capillary (bore {diameter:g} m) is at least {CAPILLARY_MIN_ASPECT:g} bores long: a "
                f"capillary_length >= {CAPILLARY_MIN_ASPECT * diameter:g} m, or another ratio")

    def supply(self, bearing: JournalBearing, grid: tuple[int, int]) -> Supply:
        """The recesses' supply through their restrictors, sized on ``grid`` for the design pressure ratio if one
        is given."""
        if self.design_pressure_ratio is not None:
            ratio, pressure = self.design_pressure_ratio, self.supply_pressure
            restrictor = (sized_capillary(bearing, pressure, ratio, self.capillary_length, grid,
                                          self.capillary_entrance_loss)
                          if self.restrictor == "capillary" else
                          sized_orifice(bearing, pressure, ratio, self.discharge_coefficient, grid))
            return Supply(pressure, restrictor)
        restrictor = {"capillary": lambda: Capillary(self.capillary_length, self.capillary_diameter,
                                                     self.capillary_entrance_loss),
                      "orifice": lambda: Orifice(self.orifice_diameter, self.discharge_coefficient),
                      "constant_flow": lambda: ConstantFlow(self.flow), "none": DirectSupply}[self.restrictor]()
        return Supply(self.supply_pressure, restrictor)
