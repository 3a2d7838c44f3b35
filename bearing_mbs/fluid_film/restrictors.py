r"""How oil reaches a recess: the restrictor between the supply pressure :math:`p_s` and the recess pressure P.

Each restrictor gives the inflow :math:`q(P)` [m³/s] and its slope :math:`dq/dP`; the Reynolds solver balances it
against the film's outflow (document 001, eqs. 5.1–5.3, hydraulic Ohm's law ΔP = qR):

* capillary (laminar Hagen–Poiseuille tube of length l and bore d): :math:`q = (p_s - P)/R_c`,
  :math:`R_c = 128\,l\,\mu/(\pi d^4)`; optionally with its entrance loss, the Hagenbach-type kinetic term
  :math:`p_s - P = R_c q + K\,\rho\bar u^2/2`, :math:`\bar u = 4q/(\pi d^2)`: the pressure that accelerates the
  oil from the supply to the developed parabolic profile and pays the entry region's extra wall shear. For a laminar
  tube K = K(∞) = 1.25 (R. K. Shah, "A correlation for laminar hydrodynamic entry length solutions for circular and
  noncircular ducts", J. Fluids Eng. 100 (1978) 177–179: the incremental pressure-drop number of the circular tube);
  relative to the Poiseuille drop it is K Re d/(64 l): 7 % and 15 % for document 001's printed capillary at
  C = 0.035 and 0.07 mm (Re = 119 and 260 at 0 rpm, ε = 0.25);
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


def capillary_bore(length: float, flow: float, drop: float, viscosity: float, density: float = 0.0,
                   entrance_loss: float = 0.0) -> float:
    """d [m] of a capillary l [m] long that passes q [m³/s] at the drop Δp [Pa]: the inverse of R_c q + K ρ ū²/2,
    both of whose terms scale as d⁻⁴, d⁴ = (128 l μ q/π + 8 K ρ q²/π²)/Δp (oil of ``viscosity`` [Pa s] and
    ``density`` [kg/m³]; K the ``entrance_loss``)."""
    return ((128.0 * length * viscosity * flow / math.pi + 8.0 * entrance_loss * density * flow**2 / math.pi**2)
            / drop) ** 0.25


def capillary_reynolds(flow: float, diameter: float, viscosity: float, density: float) -> float:
    """Re = 4ρq/(πμd) of the flow q [m³/s] through a tube of bore d [m]."""
    return 4.0 * density * abs(flow) / (math.pi * viscosity * diameter)


#: Shah's (1978) incremental pressure-drop number K(∞) of laminar flow entering a circular tube [-].
SHAH_ENTRANCE_LOSS = 1.25


@dataclass(frozen=True)
class Capillary:
    """A capillary ``length`` [m] long with bore ``diameter`` [m] and ``entrance_loss`` coefficient K [-] >= 0 (0:
    Hagen–Poiseuille alone, linear; :data:`SHAH_ENTRANCE_LOSS` for a laminar tube's entry)."""

    length: float
    diameter: float
    entrance_loss: float = 0.0

    def __post_init__(self):
        for name in ("length", "diameter"):
            value = getattr(self, name)
            if not (math.isfinite(value) and value > 0):
                raise ValueError(f"{name} = {value!r}: must be a finite number > 0")
        if not (math.isfinite(self.entrance_loss) and self.entrance_loss >= 0):
            raise ValueError(f"entrance_loss = {self.entrance_loss!r}: must be a finite number >= 0")
        if self.length < CAPILLARY_MIN_ASPECT * self.diameter:
            raise ValueError(f"length = {self.length!r}: a capillary of bore {self.diameter:g} m must be at least "
                             f"{CAPILLARY_MIN_ASPECT:g} bores long ({CAPILLARY_MIN_ASPECT * self.diameter:g} m) "
                             "for laminar, developed flow")

    @property
    def linear(self) -> bool:
        """Whether the inflow is linear in the recess pressure (no entrance loss)."""
        return self.entrance_loss == 0

    def kinetic(self, density: float) -> float:
        """a [Pa s²/m⁶] of the entrance loss a q|q| = K ρ ū²/2, ū = 4q/(πd²)."""
        return 8.0 * self.entrance_loss * density / (math.pi**2 * self.diameter**4)

    def inflow(self, supply: float, pressure: float, viscosity: float, density: float) -> tuple[float, float]:
        """q and dq/dP from R_c q + a q|q| = p_s − P (the root of the quadratic taken in its cancellation-free
        form)."""
        resistance = capillary_resistance(self.length, self.diameter, viscosity)
        drop, kinetic = supply - pressure, self.kinetic(density)
        flow = 2.0 * drop / (resistance + math.sqrt(resistance**2 + 4.0 * kinetic * abs(drop)))
        return flow, -1.0 / (resistance + 2.0 * kinetic * abs(flow))


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


def is_linear(restrictor) -> bool:
    """Whether ``restrictor``'s inflow is linear (affine) in the recess pressure: the film is then linear in its
    sources (the force map's superposition, the solver's single solve)."""
    return isinstance(restrictor, ConstantFlow | DirectSupply) or (isinstance(restrictor, Capillary)
                                                                   and restrictor.linear)


def feeds_oil(kind: type, supply_pressure: float) -> bool:
    """Whether a recess fed through a restrictor of this ``kind`` (class) from ``supply_pressure`` [Pa] brings oil
    into the film: held at its supply pressure (a groove), fed a constant flow, or fed from above ambient."""
    return issubclass(kind, DirectSupply | ConstantFlow) or supply_pressure > 0


#: Restrictor kinds by their ``restrictor`` name in a scenario.
RESTRICTORS = {"capillary": Capillary, "orifice": Orifice, "constant_flow": ConstantFlow, "none": DirectSupply}
