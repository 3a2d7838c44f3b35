r"""A lubricant's viscosity and density against temperature, and its pressure–viscosity coefficient.

Kinematic viscosity from two measured points by the Walther equation of ASTM D341 (*Standard Practice for
Viscosity–Temperature Equations and Charts for Liquid Petroleum or Hydrocarbon Products*):

.. math:: \log_{10}\log_{10}(\nu + 0.7) = A - B\,\log_{10} T,

ν in mm²/s (cSt), T in kelvin (°C + 273.15), A and B through the points at 40 °C and 100 °C. The fit is a
correlation of measurements: temperatures outside ``temperature_range`` are refused, not extrapolated. Density
falls linearly, :math:`\rho(T) = \rho_{15}\,[1 - \beta_T (T - 15\,^\circ\mathrm C)]`, and the dynamic viscosity is
η = ρν. The pressure–viscosity coefficient α [1/Pa] (Barus, η = η₀ e^{αp}) is a property of the oil, given at
``pressure_viscosity_temperature``; :meth:`Lubricant.pressure_viscosity_at` carries it to another temperature by the
initial slope of Roelands' pressure–viscosity relation (C. J. A. Roelands, *Correlational aspects of the
viscosity–temperature–pressure relationship of lubricating oils*, thesis, TH Delft, 1966; as given in B. J. Hamrock,
*Fundamentals of Fluid Film Lubrication*, 1994, ch. 4),

.. math:: \ln\frac{\eta}{\eta_0} = (\ln\eta_0 + 9.67)\left[\left(1 + \frac{p}{p_r}\right)^z - 1\right],
          \qquad \alpha = \frac{z\,(\ln\eta_0 + 9.67)}{p_r},\qquad p_r = 1.96\cdot10^8\ \mathrm{Pa},

η₀ [Pa s] the viscosity at ambient pressure and temperature T, z the oil's pressure–viscosity index, which Roelands
found nearly independent of temperature (0.4–0.8, about 0.6 for mineral oils). With z held, α falls with the
viscosity as the oil warms: :math:`\alpha(T) = \alpha(T_r)\,(\ln\eta_0(T) + 9.67)/(\ln\eta_0(T_r) + 9.67)`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

#: The Walther offset of ASTM D341 [mm²/s].
WALTHER_OFFSET = 0.7
#: The lowest kinematic viscosity [m²/s] of a point of the fit: ASTM D341's Z = ν + 0.7 holds from 2 mm²/s (below it
#: the standard adds terms; below 0.3 mm²/s log log Z is not defined at all).
WALTHER_LOWEST = 2e-6
#: Kelvin of 0 °C.
ZERO_CELSIUS = 273.15
#: Roelands' constants: ln of his limiting viscosity 6.31e-5 Pa s (negated) and his reference pressure p_r [Pa].
ROELANDS_LOG_VISCOSITY, ROELANDS_PRESSURE = 9.67, 1.96e8


class LubricantError(ValueError):
    """A lubricant value out of its range: ``field``, ``value`` and what is ``allowed``."""

    def __init__(self, field: str, value, allowed: str):
        super().__init__(f"{field} = {value!r}: {allowed}")
        self.field, self.value, self.allowed = field, value, allowed


@dataclass(frozen=True)
class Lubricant:
    """An oil: kinematic viscosity_40 and viscosity_100 [m²/s] at 40 and 100 °C (viscosity_100 < viscosity_40);
    density_15 [kg/m³] at 15 °C; thermal_expansion β_T [1/K] of the density; pressure_viscosity α [1/Pa] at
    pressure_viscosity_temperature [°C] (default 60, inside temperature_range); temperature_range (low, high) [°C]
    where its viscosity fit holds; thermal_conductivity k [W/(m K)]; name and
    source (where the values come from).
    """

    name: str
    viscosity_40: float
    viscosity_100: float
    density_15: float = 870.0
    thermal_expansion: float = 6.4e-4
    pressure_viscosity: float = 2.0e-8
    temperature_range: tuple[float, float] = (-10.0, 120.0)
    thermal_conductivity: float = 0.13
    source: str = ""
    pressure_viscosity_temperature: float = 60.0

    def __post_init__(self):
        def refuse(field, value, allowed):
            raise LubricantError(field, value, allowed)

        for field, low, high, unit in (("viscosity_40", WALTHER_LOWEST, 1e-2, "m²/s"),
                                       ("viscosity_100", WALTHER_LOWEST, 1e-3, "m²/s"),
                                       ("density_15", 600.0, 1200.0, "kg/m³"), ("thermal_expansion", 0.0, 2e-3, "1/K"),
                                       ("pressure_viscosity", 5e-9, 4e-8, "1/Pa"),
                                       ("thermal_conductivity", 0.05, 0.5, "W/(m K)")):
            value = getattr(self, field)
            if not (isinstance(value, (int, float)) and math.isfinite(value) and low <= value <= high):
                refuse(field, value, f"must be in [{low:g}, {high:g}] {unit}")
        if not self.viscosity_100 < self.viscosity_40:
            refuse("viscosity_100", self.viscosity_100, f"must be < viscosity_40 = {self.viscosity_40:g} m²/s")
        low, high = self.temperature_range
        if not (-60.0 <= low < high <= 200.0):
            refuse("temperature_range", self.temperature_range, "(low, high) with -60 <= low < high <= 200 °C")
        reference = self.pressure_viscosity_temperature
        if not (isinstance(reference, (int, float)) and math.isfinite(reference) and low <= reference <= high):
            refuse("pressure_viscosity_temperature", reference, f"must be in the fit's range [{low:g}, {high:g}] °C")

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
            raise LubricantError("temperature", temperature, f"must be in [{low:g}, {high:g}] °C, where the "
                                 f"viscosity fit of {self.name} holds (no extrapolation)")
        a, b = self._walther()
        return (10 ** (10 ** (a - b * math.log10(temperature + ZERO_CELSIUS))) - WALTHER_OFFSET) * 1e-6

    def density(self, temperature: float) -> float:
        """ρ [kg/m³] at ``temperature`` [°C]."""
        return self.density_15 * (1 - self.thermal_expansion * (temperature - 15.0))

    def dynamic_viscosity(self, temperature: float) -> float:
        """η = ρν [Pa s] at ``temperature`` [°C]."""
        return self.density(temperature) * self.kinematic_viscosity(temperature)

    def pressure_viscosity_at(self, temperature: float) -> float:
        """α [1/Pa] at ``temperature`` [°C]: ``pressure_viscosity`` carried from its temperature by Roelands'
        initial slope at a constant index z (module docstring)."""
        def roelands(t):
            return math.log(self.dynamic_viscosity(t)) + ROELANDS_LOG_VISCOSITY

        return self.pressure_viscosity * roelands(temperature) / roelands(self.pressure_viscosity_temperature)

    def roelands_index(self) -> float:
        """Roelands' pressure–viscosity index z [-] that ``pressure_viscosity`` implies at its temperature."""
        eta = self.dynamic_viscosity(self.pressure_viscosity_temperature)
        return self.pressure_viscosity * ROELANDS_PRESSURE / (math.log(eta) + ROELANDS_LOG_VISCOSITY)

    def temperature_viscosity(self, temperature: float) -> float:
        r"""β = −d ln η/dT [1/K] at ``temperature`` [°C]: a central difference over ±0.5 K, one-sided at the ends
        of ``temperature_range``."""
        low, high = self.temperature_range
        a, b = max(temperature - 0.5, low), min(temperature + 0.5, high)
        return -(math.log(self.dynamic_viscosity(b)) - math.log(self.dynamic_viscosity(a))) / (b - a)


# Typical wind-turbine gear oils. ν40: the ISO 3448 grade midpoint. ν100: typical of mineral (viscosity index
# about 95) and polyalphaolefin (PAO, about 150) gear oils of the grade, as printed in manufacturers' data sheets
# (e.g. Mobilgear 600 XP 320: 320 and 24.1 cSt; Mobil SHC Gear 320 WT and Castrol Optigear Synthetic X 320 list
# 34-38 cSt at 100 °C). α: mineral oils 1.8-2.4e-8 1/Pa, PAOs 1.3-1.7e-8 1/Pa between 40 and 100 °C (P. W. Gold
# et al., "Viscosity-pressure-temperature behaviour of mineral and synthetic oils", J. Synth. Lubr. 18 (2001)
# 51-79), taken at 60 °C (our choice: inside the band, at the seed scenarios' oil temperature; Roelands' index z
# then follows, 0.59 for the mineral oils and 0.40-0.42 for the PAOs, in Roelands' 0.4-0.8). Densities at 15 °C and
# conductivities are typical values of the two base-oil families.
PRESETS = {
    "iso_vg_220_mineral": Lubricant("ISO VG 220 mineral gear oil", 220e-6, 19.0e-6, density_15=895.0,
                                    pressure_viscosity=2.1e-8, source="ISO 3448 grade; typical VI 95 mineral oil"),
    "iso_vg_320_mineral": Lubricant("ISO VG 320 mineral gear oil", 320e-6, 24.0e-6, density_15=900.0,
                                    pressure_viscosity=2.2e-8, source="ISO 3448 grade; typical VI 95 mineral oil"),
    "iso_vg_220_pao": Lubricant("ISO VG 220 PAO gear oil", 220e-6, 25.0e-6, density_15=855.0,
                                pressure_viscosity=1.5e-8, thermal_conductivity=0.14,
                                source="ISO 3448 grade; typical VI 150 PAO"),
    "iso_vg_320_pao": Lubricant("ISO VG 320 PAO gear oil", 320e-6, 34.0e-6, density_15=860.0,
                                pressure_viscosity=1.5e-8, thermal_conductivity=0.14,
                                source="ISO 3448 grade; typical VI 150 PAO"),
}
