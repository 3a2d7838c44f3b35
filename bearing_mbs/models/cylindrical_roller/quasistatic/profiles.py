r"""Crown (profile) drops of rollers and raceways along the roller axis.

A profile gives the drop :math:`h(z) \ge 0` [m] of a body's surface below its straight generatrix at the
axial abscissa :math:`z` [m] from the roller centre; the sliced contact subtracts the drops of both bodies
from the interference (document 003 eq. 12). All profiles are even in :math:`z` and convex, so a roller that
can be placed between the raceways without touching them is recognised by the sliced model as loose.

* :class:`Flat`: :math:`h = 0` (an uncrowned, "cylindrical" generatrix).
* :class:`CircularCrown`: a straight central part of length :math:`L_r` blended into arcs of radius
  :math:`R` (document 003 eq. 13, with its missing square restored):

  .. math:: h(z) = R - \sqrt{R^2 - (|z| - L_r/2)^2}\quad\text{for } |z| \ge L_r/2,\ \text{else } 0.

  The printed eq. 13 reads :math:`R - \sqrt{R - (z - L_r/2)^2}`, which is not a length and is not even in
  :math:`z` (the errata in ``docs/quasistatic.md``). The drop is continuous with a continuous slope at
  :math:`|z| = L_r/2`.
* :class:`LogarithmicCrown`: Lundberg's logarithmic profile with the Johns–Gohar / Fujiwara–Kawase
  end-drop modification,

  .. math:: h(z) = A\,\ln\frac{1}{1 - \left(1 - e^{-h_m/A}\right)(2z/L)^2},\qquad |z| < L/2,

  which has :math:`h(\pm L/2) = h_m` and tends to Lundberg's :math:`A\ln[1/(1 - (2z/L)^2)]` as
  :math:`h_m \to \infty` (``end_drop=None``). Lundberg's scale for a design load :math:`Q_d` on a length
  :math:`L` is :math:`A = 2Q_d/(\pi L E^*)`, :math:`1/E^* = (1-\nu_1^2)/E_1 + (1-\nu_2^2)/E_2`
  (:meth:`LogarithmicCrown.lundberg`): the profile that makes the pressure of that load uniform along the
  length, without edge stress peaks.

References
----------
* S. Pater, T. Mitran, A. Cocaina, document 003, eq. 13 (errata: ``docs/quasistatic.md``).
* G. Lundberg, "Elastische Berührung zweier Halbräume", Forschung auf dem Gebiete des Ingenieurwesens 10
  (1939) 201–211.
* P. M. Johns, R. Gohar, "Roller bearings under radial and eccentric loads", Tribology International 14
  (1981) 131–136.
* H. Fujiwara, T. Kawase, "Logarithmic profiles of rollers in roller bearings and optimization of the
  profiles", NTN Technical Review 75 (2007) 140–148 (in Japanese: Trans. JSME C 72 (2006)).
* T. A. Harris, M. N. Kotzalas, *Advanced Concepts of Bearing Technology*, CRC Press, 2006, ch. 1
  (profiled rollers, slicing).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from bearing_mbs.spec.fields import non_negative, positive, require


@dataclass(frozen=True)
class Flat:
    """Uncrowned generatrix: :math:`h(z) = 0`."""

    def drop(self, z) -> np.ndarray:
        """Drop [m] at abscissae z [m]."""
        return np.zeros_like(np.asarray(z, dtype=float))

    def check_length(self, field: str, length: float) -> None:
        """Every length is acceptable."""


@dataclass(frozen=True)
class CircularCrown:
    r"""Circular crown: radius :math:`R` [m] > 0 of the end arcs; straight_length :math:`L_r` [m] >= 0 of the
    straight central part (0: a fully crowned generatrix)."""

    radius: float
    straight_length: float = 0.0

    def __post_init__(self):
        positive("radius", self.radius)
        non_negative("straight_length", self.straight_length)

    def drop(self, z) -> np.ndarray:
        """Drop [m] at abscissae z [m], eq. 13 corrected."""
        overhang = np.maximum(np.abs(np.asarray(z, dtype=float)) - 0.5 * self.straight_length, 0.0)
        return self.radius - np.sqrt(self.radius**2 - overhang**2)

    def check_length(self, field: str, length: float) -> None:
        """The arcs must reach the ends of a contact of this length: :math:`R \\ge (L - L_r)/2`."""
        overhang = 0.5 * (length - self.straight_length)
        require(
            self.radius >= overhang,
            f"{field}.radius",
            self.radius,
            f"must be >= (L_e - L_r)/2 = {overhang:g} m so that the crown arc spans the roller's effective length",
        )


@dataclass(frozen=True)
class LogarithmicCrown:
    r"""Logarithmic crown: scale :math:`A` [m] > 0; length :math:`L` [m] > 0 over which the profile is defined
    (at least the roller's effective length); end_drop :math:`h_m` [m] > 0 at :math:`z = \pm L/2`, or None
    for Lundberg's unbounded profile."""

    scale: float
    length: float
    end_drop: float | None = None

    def __post_init__(self):
        positive("scale", self.scale)
        positive("length", self.length)
        if self.end_drop is not None:
            positive("end_drop", self.end_drop)

    @classmethod
    def lundberg(
        cls, design_load: float, length: float, contact_modulus: float, end_drop: float | None = None
    ) -> LogarithmicCrown:
        r"""Lundberg's scale :math:`A = 2Q_d/(\pi L E^*)` for design load :math:`Q_d` [N] > 0, length
        :math:`L` [m] and contact modulus :math:`E^*` [Pa] > 0 (:math:`1.15\cdot10^{11}` for steel on steel)."""
        positive("design_load", design_load)
        positive("length", length)
        positive("contact_modulus", contact_modulus)
        return cls(2.0 * design_load / (math.pi * length * contact_modulus), length, end_drop)

    def drop(self, z) -> np.ndarray:
        r"""Drop [m] at abscissae :math:`|z| \le L/2` [m] (:math:`|z| = L/2` only with an end drop).

        Evaluated as :math:`-A\ln[(1-\xi^2) + e^{-h_m/A}\xi^2]`, :math:`\xi = 2z/L`, with ``logaddexp`` so
        that a large :math:`h_m/A` neither underflows nor loses the end drop.
        """
        xi = 2.0 * np.abs(np.asarray(z, dtype=float)) / self.length
        with np.errstate(divide="ignore"):
            straight = np.log((1.0 - xi) * (1.0 + xi))
            if self.end_drop is None:
                return 0.0 - self.scale * straight
            return 0.0 - self.scale * np.logaddexp(straight, -self.end_drop / self.scale + 2.0 * np.log(xi))

    def check_length(self, field: str, length: float) -> None:
        """The profile must be defined over the effective length: :math:`L \\ge L_e`."""
        require(
            self.length >= length,
            f"{field}.length",
            self.length,
            f"must be >= the effective roller length {length:g} m",
        )
