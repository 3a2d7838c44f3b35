r"""How oil reaches a recess: the restrictor between the supply pressure :math:`p_s` and the recess pressure P.

Each restrictor gives the inflow :math:`q(P)` [m³/s] and its slope :math:`dq/dP`; the Reynolds solver balances it
against the film's outflow (document 001, eqs. 5.1–5.3, hydraulic Ohm's law ΔP = qR):

* capillary (laminar Hagen–Poiseuille tube of length l and bore d): :math:`q = (p_s - P)/R_c`,
  :math:`R_c = 128\,l\,\mu/(\pi d^4)`;
* orifice (sharp-edged, discharge coefficient :math:`C_d`):
  :math:`q = C_d\,\tfrac{\pi d^2}{4}\sqrt{2(p_s - P)/\rho}`, i.e. :math:`\Delta p = 8\rho q^2/(\pi^2 d^4 C_d^2)`;
* constant flow (a flow-control valve): :math:`q = Q_0`;
* direct supply (no restrictor, a supply groove): P = :math:`p_s`.

A capillary is laminar and fully developed only if it is long compared with its bore: W. B. Rowe, *Hydrostatic,
Aerostatic and Hybrid Bearing Design*, Butterworth-Heinemann 2012, §3 recommends l/d ≥ 20 (the entry length
0.06 Re d then stays a small part of l for Re ≲ 300), and Re = 4ρq/(πμd) < 2000. :data:`CAPILLARY_MIN_ASPECT` is
that bound; :func:`capillary_reynolds` checks the flow afterwards.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

#: The smallest capillary length / bore ratio accepted (Rowe 2012: l/d ≥ 20 for laminar, developed flow).
CAPILLARY_MIN_ASPECT = 20.0


def capillary_resistance(length: float, diameter: float, viscosity: float) -> float:
    """R_c = 128 l μ / (π d⁴) [Pa s/m³] of a capillary of length l [m] and bore d [m] for viscosity μ [Pa s]."""
    return 128.0 * length * viscosity / (math.pi * diameter**4)


def capillary_bore(length: float, flow: float, drop: float, viscosity: float) -> float:
    """d = (128 l μ q / (π Δp))^{1/4} [m]: the bore of a capillary l [m] long that passes q [m³/s] at the drop Δp
    [Pa] (the inverse of :func:`capillary_resistance`)."""
    return (128.0 * length * viscosity * flow / (math.pi * drop)) ** 0.25


def capillary_reynolds(flow: float, diameter: float, viscosity: float, density: float) -> float:
    """Re = 4ρq/(πμd) of the flow q [m³/s] through a tube of bore d [m]."""
    return 4.0 * density * abs(flow) / (math.pi * viscosity * diameter)


@dataclass(frozen=True)
class Capillary:
    """A capillary ``length`` [m] long with bore ``diameter`` [m]."""

    length: float
    diameter: float

    def __post_init__(self):
        for name in ("length", "diameter"):
            value = getattr(self, name)
            if not (math.isfinite(value) and value > 0):
                raise ValueError(f"{name} = {value!r}: must be a finite number > 0")
        if self.length < CAPILLARY_MIN_ASPECT * self.diameter:
            raise ValueError(f"length = {self.length!r}: a capillary of bore {self.diameter:g} m must be at least "
                             f"{CAPILLARY_MIN_ASPECT:g} bores long ({CAPILLARY_MIN_ASPECT * self.diameter:g} m) "
                             "for laminar, developed flow")

    def inflow(self, supply: float, pressure: float, viscosity: float, density: float) -> tuple[float, float]:
        resistance = capillary_resistance(self.length, self.diameter, viscosity)
        return (supply - pressure) / resistance, -1.0 / resistance

    @classmethod
    def passing(cls, flow: float, drop: float, viscosity: float, length: float) -> Capillary:
        """The capillary of this ``length`` [m] that passes ``flow`` [m³/s] at the pressure ``drop`` [Pa]."""
        return cls(length, capillary_bore(length, flow, drop, viscosity))


@dataclass(frozen=True)
class Orifice:
    """A sharp-edged orifice of bore ``diameter`` [m] and ``discharge_coefficient`` C_d in (0, 1]."""

    diameter: float
    discharge_coefficient: float = 0.6

    def __post_init__(self):
        if not (math.isfinite(self.diameter) and self.diameter > 0):
            raise ValueError(f"diameter = {self.diameter!r}: must be a finite number > 0")
        if not 0 < self.discharge_coefficient <= 1:
            raise ValueError(f"discharge_coefficient = {self.discharge_coefficient!r}: must be in (0, 1]")

    def inflow(self, supply: float, pressure: float, viscosity: float, density: float) -> tuple[float, float]:
        """q and dq/dP; the square root is rounded off below 1e-6 of the supply pressure so that Newton's
        slope stays finite at P = p_s."""
        area = self.discharge_coefficient * math.pi * self.diameter**2 / 4
        drop = supply - pressure
        floor = 1e-6 * max(abs(supply), 1.0)
        root = math.sqrt(max(abs(drop), floor))
        flow = area * math.copysign(math.sqrt(2 * abs(drop) / density), drop)
        return flow, -area * math.sqrt(2 / density) / (2 * root)

    @classmethod
    def passing(cls, flow: float, drop: float, density: float, discharge_coefficient: float = 0.6) -> Orifice:
        """The orifice that passes ``flow`` [m³/s] at the pressure ``drop`` [Pa]: q = C_d (π d²/4) √(2Δp/ρ)
        solved for d."""
        area = flow / (discharge_coefficient * math.sqrt(2 * drop / density))
        return cls(math.sqrt(4 * area / math.pi), discharge_coefficient)


@dataclass(frozen=True)
class ConstantFlow:
    """A flow-control valve delivering ``flow`` [m³/s] whatever the recess pressure."""

    flow: float

    def __post_init__(self):
        if not (math.isfinite(self.flow) and self.flow > 0):
            raise ValueError(f"flow = {self.flow!r}: must be a finite number > 0")

    def inflow(self, supply: float, pressure: float, viscosity: float, density: float) -> tuple[float, float]:
        return self.flow, 0.0


@dataclass(frozen=True)
class DirectSupply:
    """No restrictor: the recess is held at the supply pressure (a supply groove)."""

    def inflow(self, supply: float, pressure: float, viscosity: float, density: float) -> tuple[float, float]:
        raise TypeError("a directly supplied recess has a fixed pressure, not an inflow law")


def feeds_oil(kind: type, supply_pressure: float) -> bool:
    """Whether a recess fed through a restrictor of this ``kind`` (class) from ``supply_pressure`` [Pa] brings oil
    into the film: held at its supply pressure (a groove), fed a constant flow, or fed from above ambient."""
    return issubclass(kind, DirectSupply | ConstantFlow) or supply_pressure > 0


#: Restrictor kinds by their ``restrictor`` name in a scenario.
RESTRICTORS = {"capillary": Capillary, "orifice": Orifice, "constant_flow": ConstantFlow, "none": DirectSupply}
