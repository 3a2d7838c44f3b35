"""The oil at its operating temperature: evaluated once per build and handed to every part of the scene that
needs it (the drags, the starvation factor, the pocket and land films, the lubricated-traction rows).

``[lubricant]`` names an oil (a preset or its own two viscosities, :meth:`LubricantSpec.lubricant`) and one
operating temperature; the spec validates them. :func:`operating_oil` is the one place that carries the oil to that
temperature (:class:`~bearing_mbs.contact.lubricant.Lubricant`: ASTM D341 viscosity, linear density, Roelands'
pressure–viscosity slope), so that no builder helper rebuilds the lubricant or chooses its own temperature or
pressure–viscosity model.
"""

from __future__ import annotations

from dataclasses import dataclass

from bearing_mbs.models.cylindrical_roller.spec import LubricantSpec

#: Kinematic viscosity [m²/s] Palmgren's M_0 takes when ``[lubricant]`` gives neither a viscosity nor an oil at a
#: temperature (an ISO VG 32 oil at 40 °C).
DEFAULT_PALMGREN_VISCOSITY = 32e-6


@dataclass(frozen=True)
class OperatingOil:
    """The oil's properties at the operating temperature [SI]; the oil's are None when ``[lubricant]`` names no
    oil or no temperature.

    ``density`` ρ [kg/m³], ``kinematic_viscosity`` ν [m²/s], ``dynamic_viscosity`` η = ρν [Pa s],
    ``pressure_viscosity`` α [1/Pa] by ``pressure_viscosity_model`` (the oil's own, or carried to the temperature by
    Roelands' slope), ``temperature_viscosity`` β = −d ln η/dT [1/K], ``thermal_conductivity`` k [W/(m K)];
    ``palmgren_viscosity`` ν [m²/s] for Palmgren's M_0: the given ``viscosity``, else the oil's, else
    :data:`DEFAULT_PALMGREN_VISCOSITY`.
    """

    palmgren_viscosity: float
    density: float | None = None
    kinematic_viscosity: float | None = None
    dynamic_viscosity: float | None = None
    pressure_viscosity: float | None = None
    temperature_viscosity: float | None = None
    thermal_conductivity: float | None = None


def operating_oil(lubricant: LubricantSpec) -> OperatingOil:
    """The oil of ``[lubricant]`` at its operating temperature (the module docstring)."""
    oil, temperature = lubricant.lubricant(), lubricant.temperature
    if oil is None or temperature is None:
        given = lubricant.viscosity if lubricant.viscosity is not None else DEFAULT_PALMGREN_VISCOSITY
        return OperatingOil(palmgren_viscosity=given)
    kinematic = oil.kinematic_viscosity(temperature)
    roelands = lubricant.pressure_viscosity_model == "roelands"
    return OperatingOil(
        palmgren_viscosity=lubricant.viscosity if lubricant.viscosity is not None else kinematic,
        density=oil.density(temperature),
        kinematic_viscosity=kinematic,
        dynamic_viscosity=oil.dynamic_viscosity(temperature),
        pressure_viscosity=oil.pressure_viscosity_at(temperature) if roelands else oil.pressure_viscosity,
        temperature_viscosity=oil.temperature_viscosity(temperature),
        thermal_conductivity=oil.thermal_conductivity,
    )
