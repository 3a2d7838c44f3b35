r"""The roller set of a radial cylindrical roller bearing, the Newton settings, and the solver errors.

Geometry and clearance convention
---------------------------------
The pitch diameter is the mean of the raceway diameters, and the diametral clearance :math:`P_d`
(negative = preload, an interference fit of the rollers) is split equally between the two raceways:

.. math:: d_i = D_{pw} - D_w - P_d/2,\qquad d_o = D_{pw} + D_w + P_d/2,\qquad P_d = d_o - d_i - 2D_w,

so each roller–raceway pair of a centred bearing has the clearance :math:`J_b = P_d/4` (document 003's
"jocul initial inel-rola", eq. 11). For a rigid roller in line with inner-ring displacement :math:`(x, y)`
the total radial approach at azimuth :math:`\psi_j` is Harris's

.. math:: \delta_j = x\cos\psi_j + y\sin\psi_j - P_d/2 = \delta_{i,j} + \delta_{o,j}.

Rollers are equally spaced, roller :math:`j` at :math:`\psi_j = \psi_0 + 2\pi j/Z`, angles measured from
the x axis towards y. The outer ring is fixed; the load acts on the inner ring.

Kinematics of the cage (outer ring fixed, zero contact angle, rolling without slip):
:math:`\omega_c = \tfrac12\,\omega_i\,(1 - D_w/D_{pw})`, and each roller feels the centrifugal force
:math:`F_c = m_r\,(D_{pw}/2)\,\omega_c^2` (Harris & Kotzalas 2006, ch. 10); both formulas live in
:mod:`bearing_mbs.models.cylindrical_roller.geometry`.

References
----------
* T. A. Harris, M. N. Kotzalas, *Essential Concepts of Bearing Technology*, 5th ed., CRC Press, 2006,
  ch. 2 (clearance), ch. 7 (load distribution), ch. 10 (high-speed operation).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from bearing_mbs.contact.line_contact import PALMGREN_EXPONENT, palmgren_stiffness
from bearing_mbs.models.cylindrical_roller.geometry import (
    BearingGeometry,
    epicyclic_cage_speed,
    roller_centrifugal_force,
    roller_mass,
)
from bearing_mbs.models.cylindrical_roller.spec import CLEARANCE_LIMIT, PRELOAD_LIMIT, STEEL, require_rollers_fit
from bearing_mbs.spec.fields import SpecError, finite, in_range, non_negative, positive, require

#: Largest number of rollers accepted [-].
MAX_ROLLERS = 1000


def _integer(field: str, value, low: int, high: int) -> None:
    is_int = isinstance(value, (int, np.integer)) and not isinstance(value, bool)
    require(is_int and low <= value <= high, field, value, f"must be an integer in [{low}, {high}]")


@dataclass(frozen=True)
class RollerSet:
    r"""Rollers, raceways and contact laws of a radial cylindrical roller bearing (quasi-static model).

    rollers: :math:`Z`, integer in [3, 1000]. pitch_diameter: :math:`D_{pw}` [m] > 0.
    roller_diameter: :math:`D_w` [m] > 0, with :math:`D_w < D_{pw}\sin(\pi/Z)` so that neighbouring rollers
    do not overlap on the pitch circle (this implies :math:`Z D_w < \pi D_{pw}`).
    roller_length: effective contact length :math:`l` [m] > 0 (Palmgren's :math:`l`, ISO 281's
    :math:`L_{we}`); the sliced model cuts this length into slices.
    diametral_clearance: :math:`P_d` [m], in :math:`[-0.002 D_w, 0.05 D_w]` (the limits of
    :mod:`bearing_mbs.models.cylindrical_roller.spec`); negative is a preload.
    roller_mass: :math:`m_r` [kg] >= 0; None gives a solid steel cylinder
    :math:`\rho\pi D_w^2 l/4` with the density of ``STEEL`` (the primary document's formula).
    first_roller_angle: :math:`\psi_0` [rad], azimuth of roller 0 from the x axis.
    inner_stiffness, outer_stiffness: :math:`K` [N/m^n] > 0 of the roller–raceway laws
    :math:`Q = K\delta^n`; None gives Palmgren's :math:`K(l)` (then the exponent must be 10/9).
    inner_exponent, outer_exponent: :math:`n` [-] in [1, 3], default 10/9.
    """

    rollers: int
    pitch_diameter: float
    roller_diameter: float
    roller_length: float
    diametral_clearance: float = 0.0
    roller_mass: float | None = None
    first_roller_angle: float = 0.0
    inner_stiffness: float | None = None
    inner_exponent: float = PALMGREN_EXPONENT
    outer_stiffness: float | None = None
    outer_exponent: float = PALMGREN_EXPONENT

    def __post_init__(self):
        _integer("rollers", self.rollers, 3, MAX_ROLLERS)
        positive("pitch_diameter", self.pitch_diameter)
        positive("roller_diameter", self.roller_diameter)
        positive("roller_length", self.roller_length)
        require_rollers_fit("roller_diameter", self.roller_diameter, self.rollers, self.pitch_diameter,
                            self.roller_diameter, "D_w")
        in_range(
            "diametral_clearance",
            self.diametral_clearance,
            -PRELOAD_LIMIT * self.roller_diameter,
            CLEARANCE_LIMIT * self.roller_diameter,
            "m",
        )
        if self.roller_mass is None:
            mass = roller_mass(STEEL.density, self.roller_diameter, self.roller_length)
            object.__setattr__(self, "roller_mass", mass)
        non_negative("roller_mass", self.roller_mass)
        finite("first_roller_angle", self.first_roller_angle)
        for side in ("inner", "outer"):
            stiffness, exponent = f"{side}_stiffness", f"{side}_exponent"
            in_range(exponent, getattr(self, exponent), 1.0, 3.0, "-")
            if getattr(self, stiffness) is None:
                require(
                    getattr(self, exponent) == PALMGREN_EXPONENT,
                    exponent,
                    getattr(self, exponent),
                    f"must be 10/9 when {stiffness} is left to Palmgren's law; give {stiffness} for another exponent",
                )
                object.__setattr__(self, stiffness, float(palmgren_stiffness(self.roller_length)))
            positive(stiffness, getattr(self, stiffness))

    @classmethod
    def from_geometry(cls, geometry: BearingGeometry) -> RollerSet:
        """The dynamic model's bearing for the quasi-static solver: the same clearance and roller mass,
        Palmgren raceway laws."""
        return cls(rollers=geometry.rollers, pitch_diameter=geometry.pitch_diameter,
                   roller_diameter=geometry.roller_diameter, roller_length=geometry.roller_length,
                   diametral_clearance=geometry.clearance, roller_mass=geometry.roller_mass)

    @property
    def roller_angles(self) -> np.ndarray:
        r"""Azimuths :math:`\psi_j = \psi_0 + 2\pi j/Z` [rad], shape (Z,)."""
        return self.first_roller_angle + 2.0 * np.pi * np.arange(self.rollers) / self.rollers

    @property
    def contact_clearance(self) -> float:
        r"""Clearance of each roller–raceway pair in the centred bearing, :math:`J_b = P_d/4` [m]."""
        return self.diametral_clearance / 4.0

    def cage_speed(self, shaft_speed: float) -> float:
        r"""Epicyclic cage speed :math:`\omega_c = \tfrac12\omega_i(1 - D_w/D_{pw})` [rad/s], outer ring fixed."""
        return epicyclic_cage_speed(shaft_speed, self.roller_diameter, self.pitch_diameter)

    def centrifugal_force(self, shaft_speed: float) -> float:
        r"""Roller centrifugal force :math:`F_c = m_r(D_{pw}/2)\,\omega_c^2` [N] at inner-ring speed [rad/s]."""
        return roller_centrifugal_force(self.roller_mass, self.pitch_diameter, self.cage_speed(shaft_speed))


@dataclass(frozen=True)
class NewtonSettings:
    r"""Tolerances and iteration limits of the Newton–Raphson loops.

    tolerance: relative force residual of the inner-ring equilibrium [-] in (0, 1e-3]:
    :math:`\|\sum_j f_j - F\| \le \text{tolerance}\cdot\max(\|F\|, \sum_j Q_j)`.
    max_iterations: outer (inner-ring) Newton iterations, integer in [1, 1000].
    roller_tolerance: relative residual of each roller's equilibrium [-] in (0, 1e-6].
    roller_max_iterations: per-roller Newton iterations, integer in [1, 1000].
    """

    tolerance: float = 1e-10
    max_iterations: int = 50
    roller_tolerance: float = 1e-13
    roller_max_iterations: int = 100

    def __post_init__(self):
        in_range("tolerance", self.tolerance, 0.0, 1e-3, "-", low_open=True)
        _integer("max_iterations", self.max_iterations, 1, 1000)
        in_range("roller_tolerance", self.roller_tolerance, 0.0, 1e-6, "-", low_open=True)
        _integer("roller_max_iterations", self.roller_max_iterations, 1, 1000)


class ConvergenceError(SpecError):
    """A Newton–Raphson loop stopped at its iteration limit; ``field`` names the limit that was reached.

    ``iterations`` and ``residual`` [N] are the loop's last values; ``tolerance`` is the one it missed
    (described by ``tolerance_text``).
    """

    def __init__(self, field: str, iterations: int, residual: float, tolerance: float, what: str,
                 tolerance_text: str = "N"):
        self.iterations, self.residual, self.tolerance = iterations, residual, tolerance
        super().__init__(
            field,
            iterations,
            f"Newton–Raphson on {what} stopped after {iterations} iterations with residual {residual:.3e} N "
            f"(tolerance {tolerance:.3e} {tolerance_text}); raise {field}, loosen the tolerance, or check that "
            "the load can be carried",
        )


def check_vector(field: str, value, size: int) -> np.ndarray:
    """``value`` as a float array of ``size`` finite numbers, or a :class:`SpecError` naming ``field``."""
    try:
        array = np.asarray(value, dtype=float)
    except (TypeError, ValueError):
        raise SpecError(field, value, f"must be {size} numbers") from None
    require(array.shape == (size,), field, value, f"must be {size} numbers")
    require(bool(np.all(np.isfinite(array))), field, value, "must be finite numbers")
    return array


def check_speed(shaft_speed) -> float:
    """The inner-ring speed [rad/s] as a finite float."""
    finite("shaft_speed", shaft_speed)
    return float(shaft_speed)


class RollerLoads:
    """Properties shared by the planar and sliced solutions, which both hold the ring's generalised force
    ``load``, the inner-contact roller loads ``inner_loads`` [N], the ``rollers`` and the ``shaft_speed``."""

    @property
    def force(self) -> np.ndarray:
        """Alias of ``load``, the ring's generalised force [N] (used by the ring solver)."""
        return self.load

    @property
    def load_scale(self) -> float:
        return float(self.inner_loads.sum())

    @property
    def centrifugal_force(self) -> float:
        """Roller centrifugal force F_c [N]."""
        return self.rollers.centrifugal_force(self.shaft_speed)

    @property
    def max_roller_load(self) -> float:
        """Largest inner-contact load [N] (the load a roller carries from the ring; outer = inner + F_c)."""
        return float(self.inner_loads.max())

    @property
    def loaded(self) -> np.ndarray:
        """Rollers whose inner contact carries load, boolean (Z,)."""
        return self.inner_loads > 0.0
