r"""A lubricant's viscosity and density against temperature, and its pressure–viscosity coefficient.

Kinematic viscosity from two measured points by the Walther equation of ASTM D341 (*Standard Practice for
Viscosity–Temperature Equations and Charts for Liquid Petroleum or Hydrocarbon Products*):

.. math:: \log_{10}\log_{10}(\nu + 0.7) = A - B\,\log_{10} T,

ν in mm²/s (cSt), T in kelvin (°C + 273.15), A and B through the points at 40 °C and 100 °C. The fit is a
correlation of measurements: temperatures outside ``temperature_range`` are refused, not extrapolated. Density
falls linearly, :math:`\rho(T) = \rho_{15}\,[1 - \beta_T (T - 15\,^\circ\mathrm C)]`, and the dynamic viscosity is
η = ρν. The pressure–viscosity coefficient α [1/Pa] (Barus, η = η₀ e^{αp}) is a property of the oil, given at
the operating temperature.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

#: The Walther offset of ASTM D341 [mm²/s].
WALTHER_OFFSET = 0.7
#: Kelvin of 0 °C.
ZERO_CELSIUS = 273.15


@dataclass(frozen=True)
class Lubricant:
    """An oil: kinematic viscosity_40 and viscosity_100 [m²/s] at 40 and 100 °C (viscosity_100 < viscosity_40);
    density_15 [kg/m³] at 15 °C; thermal_expansion β_T [1/K] of the density; pressure_viscosity α [1/Pa];
    temperature_range (low, high) [°C] where its viscosity fit holds; name and source (where the values come from).
    """

    name: str
    viscosity_40: float
    viscosity_100: float
    density_15: float = 870.0
    thermal_expansion: float = 6.4e-4
    pressure_viscosity: float = 2.0e-8
    temperature_range: tuple[float, float] = (-10.0, 120.0)
    source: str = ""

    def __post_init__(self):
        def refuse(field, value, allowed):
            raise ValueError(f"{field} = {value!r}: {allowed}")

        for field, low, high in (("viscosity_40", 1e-6, 1e-2), ("viscosity_100", 1e-7, 1e-3),
                                 ("density_15", 600.0, 1200.0), ("thermal_expansion", 0.0, 2e-3),
                                 ("pressure_viscosity", 5e-9, 4e-8)):
            value = getattr(self, field)
            if not (isinstance(value, (int, float)) and math.isfinite(value) and low <= value <= high):
                refuse(field, value, f"must be in [{low:g}, {high:g}]")
        if not self.viscosity_100 < self.viscosity_40:
            refuse("viscosity_100", self.viscosity_100, f"must be < viscosity_40 = {self.viscosity_40:g} m²/s")
        low, high = self.temperature_range
        if not (-60.0 <= low < high <= 200.0):
            refuse("temperature_range", self.temperature_range, "(low, high) with -60 <= low < high <= 200 °C")

    def _walther(self) -> tuple[float, float]:
        points = [(40.0, self.viscosity_40), (100.0, self.viscosity_100)]
        (x1, y1), (x2, y2) = [(math.log10(t + ZERO_CELSIUS), math.log10(math.log10(nu * 1e6 + WALTHER_OFFSET)))
                              for t, nu in points]
        slope = (y1 - y2) / (x2 - x1)
        return y1 + slope * x1, slope

    def kinematic_viscosity(self, temperature: float) -> float:
        """ν [m²/s] at ``temperature`` [°C] (ASTM D341); outside ``temperature_range``: ValueError."""
        low, high = self.temperature_range
        if not (math.isfinite(temperature) and low <= temperature <= high):
            raise ValueError(f"temperature = {temperature!r}: must be in [{low:g}, {high:g}] °C, where the "
                             f"viscosity fit of {self.name} holds (no extrapolation)")
        a, b = self._walther()
        return (10 ** (10 ** (a - b * math.log10(temperature + ZERO_CELSIUS))) - WALTHER_OFFSET) * 1e-6

    def density(self, temperature: float) -> float:
        """ρ [kg/m³] at ``temperature`` [°C]."""
        return self.density_15 * (1 - self.thermal_expansion * (temperature - 15.0))

    def dynamic_viscosity(self, temperature: float) -> float:
        """η = ρν [Pa s] at ``temperature`` [°C]."""
        return self.density(temperature) * self.kinematic_viscosity(temperature)
