r"""The film's effective temperature: friction heat carried away by the oil flow (``journal.thermal = "effective"``).

The classical effective-temperature method of journal-bearing design (A. A. Raimondi, J. Boyd, ASLE Trans. 1
(1958); Shigley's *Mechanical Engineering Design*, ch. 12): the film works at one viscosity, that of the mean of
the oil's inlet and outlet temperatures, and all the friction power P_f leaves with the flow Q through the bearing
(adiabatic: none is conducted into the journal or the housing, which puts the rise on the high side):

.. math:: T_\mathrm{eff} = T_\mathrm{in} + \tfrac12\,\Delta T, \qquad
          \Delta T = \frac{P_f(\mu(T_\mathrm{eff}))}{\rho\,c_p\,Q(\mu(T_\mathrm{eff}))}.

μ(T) is the oil's ASTM D341 line (:mod:`bearing_mbs.contact.lubricant`), ρ its density at the inlet. As the oil
warms, friction falls and the pressure-fed flow grows, so g(T) = T − T_in − ΔT(T)/2 rises monotonically from
g(T_in) ≤ 0: one root, found by Brent's method (scipy) between the inlet temperature and the top of the oil's fit.
"""

from __future__ import annotations

from dataclasses import dataclass

from scipy.optimize import brentq

#: Tolerance of the effective temperature [K].
TEMPERATURE_TOLERANCE = 1e-6


@dataclass(frozen=True)
class EffectiveFilm:
    """The heat balance's solution: ``temperature`` T_eff [°C], ``rise`` ΔT [K] from inlet to outlet,
    ``viscosity`` μ(T_eff) [Pa s]; None where T_eff would lie beyond the oil's fit (``highest`` [°C])."""

    temperature: float | None
    rise: float | None
    viscosity: float | None
    highest: float


def effective_film(oil, friction_and_flow) -> EffectiveFilm:
    """Solve the heat balance for the oil section ``oil`` (:class:`~.spec.OilSection`); ``friction_and_flow(μ)``
    returns the film's friction power [W] and its flow [m³/s] at viscosity μ [Pa s]."""
    lubricant, inlet = oil.lubricant(), oil.inlet_temperature
    capacity = lubricant.density(inlet) * oil.specific_heat

    def rise(temperature):
        power, flow = friction_and_flow(lubricant.dynamic_viscosity(temperature))
        return power / (capacity * flow)

    def imbalance(temperature):
        return temperature - inlet - rise(temperature) / 2

    highest = lubricant.temperature_range[1]
    if imbalance(highest) < 0:
        return EffectiveFilm(None, None, None, highest)
    temperature = inlet if imbalance(inlet) >= 0 else brentq(imbalance, inlet, highest, xtol=TEMPERATURE_TOLERANCE)
    return EffectiveFilm(temperature, 2 * (temperature - inlet), lubricant.dynamic_viscosity(temperature), highest)
