r"""Derived bearing geometry, masses, inertias and epicyclic kinematics (one place for these formulas).

Conventions (also those of :mod:`bearing_mbs.models.cylindrical_roller.quasistatic`): the inner raceway diameter is
:math:`d_i = D_{pw} - D_w - P_d/2` and the outer :math:`d_o = D_{pw} + D_w + P_d/2`, so :math:`D_{pw}` is their
mean and :math:`P_d` the diametral clearance (negative: preload). Roller k sits at azimuth
:math:`\psi_k = 2\pi k/Z` (the document's :math:`2\pi(k-1)/Z`, counted from 0).

Pocket edges (document eq. 45, with the denominator corrected to :math:`D_{pw} D_c/2`): the points P and Q of
pocket k lie on the cage circle :math:`D_c` at :math:`\psi_k \pm \gamma` with

.. math:: \cos\gamma = \frac{(D_{pw}/2)^2 + (D_c/2)^2 - (D_w/2 + H)^2}{D_{pw} D_c / 2},

so a centred roller is exactly :math:`H` from each edge. Edges on one circle outside the roller centres hold
the cage round the circle but hardly radially: a roller-guided cage drifts out of the bearing. Real pocket
bars wrap the roller on both sides of the pitch circle, so we add the mirror edges P', Q' on the circle
:math:`2D_{pw} - D_c` inside it (same construction), and the pocket holds its roller from both sides.

Epicyclic (no-slip) kinematics with the outer ring fixed: cage speed
:math:`\omega_c = \omega_i (1 - D_w/D_{pw})/2`, roller spin (absolute) :math:`\omega_r = -\omega_c D_{pw}/D_w`; each
roller orbiting at :math:`\omega_c` feels the centrifugal force :math:`F_c = m_r (D_{pw}/2)\,\omega_c^2` (T. A. Harris,
M. N. Kotzalas, Essential Concepts of Bearing Technology, 5th ed., 2006, ch. 10).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from bearing_mbs.models.cylindrical_roller.spec import (
    BearingSpec,
    diametral_clearance,
    inner_race_diameter,
    outer_race_diameter,
    pocket_angle_cosine,
)
from bearing_mbs.spec import SpecError


@dataclass(frozen=True)
class RacewayLayout:
    """The rolling set as its raceway contacts hold it: ``rollers`` Z rollers of radius ``roller_radius`` r between
    the inner and outer raceways of radii ``inner_radius`` r_i and ``outer_radius`` r_o [m].

    The one layout of the bearing: :attr:`BearingGeometry.raceways` gives it to the builder, which sets the raceway
    pairs' radii from it, and whatever reads a built scene (the linearisation, the skidding balance) recovers the
    same numbers from those pairs (:meth:`of_pairs`) instead of deriving them again.
    """

    rollers: int
    roller_radius: float
    inner_radius: float
    outer_radius: float

    @classmethod
    def of_pairs(cls, rollers: int, inner_pair, outer_pair) -> RacewayLayout:
        """The layout of a scene from a roller's inner-raceway pair (roller b on ring a) and outer-raceway pair."""
        return cls(rollers, inner_pair.radius_b, inner_pair.radius_a, outer_pair.radius_a)

    @property
    def roller_diameter(self) -> float:
        """D_w = 2r [m]."""
        return 2 * self.roller_radius

    @property
    def pitch_diameter(self) -> float:
        """D_pw [m]: the mean of the raceway diameters, r_i + r_o."""
        return self.inner_radius + self.outer_radius

    @property
    def clearance(self) -> float:
        """Diametral clearance P_d [m] (negative: preload), :func:`.spec.diametral_clearance`."""
        return diametral_clearance(2 * self.inner_radius, 2 * self.outer_radius, self.roller_diameter)

    def epicyclic_cage_speed(self, inner_speed):
        """ω_c [rad/s] at inner-ring speed ω_i, see :func:`epicyclic_cage_speed`."""
        return epicyclic_cage_speed(inner_speed, self.roller_diameter, self.pitch_diameter)

    def epicyclic_spin_in_cage(self, inner_speed):
        """The rollers' spin relative to the cage [rad/s], −(ω_i − ω_c) r_i/r at the epicyclic ω_c: rolling
        without slip on both raceways."""
        return -(inner_speed - self.epicyclic_cage_speed(inner_speed)) * self.inner_radius / self.roller_radius


@dataclass(frozen=True)
class BearingGeometry:
    """Numbers derived from a :class:`BearingSpec` [SI]."""

    rollers: int
    roller_diameter: float
    roller_length: float
    pitch_diameter: float
    clearance: float
    inner_race_diameter: float
    outer_race_diameter: float
    cage_diameter: float
    cage_thickness: float  # t, the cage ring's radial section [m]
    pocket_clearance: float
    pocket_angle: float  # γ [rad]
    roller_mass: float
    roller_inertia: float
    cage_mass: float
    cage_inertia: float
    inner_ring_mass: float
    inner_ring_inertia: float
    inner_land_radius: float  # on the inner ring, for an inner-land-guided cage [m]
    cage_bore_radius: float
    cage_outer_radius: float
    outer_land_radius: float  # on the outer ring, for an outer-land-guided cage [m]

    def require_cage(self, spec: BearingSpec) -> None:
        """Refuse a cage whose pocket windows leave it no mass (before anything runs)."""
        if self.cage_mass <= 0:
            windows = self.rollers * (self.roller_diameter + 2 * spec.pocket_clearance) * self.roller_length
            raise SpecError("bearing.cage_width", spec.cage_width,
                            f"> {windows / (math.pi * spec.cage_diameter):.4g} m: the {self.rollers} pocket windows "
                            f"(D_w + 2H) × L_w take more than the cage ring, so its mass would be "
                            f"{self.cage_mass:.3g} kg")

    @classmethod
    def from_spec(cls, spec: BearingSpec) -> BearingGeometry:
        z, d_w, length = spec.rollers, spec.roller_diameter, spec.roller_length
        pitch, clearance = spec.pitch, spec.clearance
        d_c, h, t = spec.cage_diameter, spec.pocket_clearance, spec.cage_thickness
        mass = roller_mass(spec.roller_material.density, d_w, length)
        # the cage: an annulus of thickness t and width w around D_c, less Z pocket windows (D_w + 2H) × L_w
        cage_volume = math.pi * d_c * t * spec.cage_width - z * (d_w + 2 * h) * length * t
        cage_mass = spec.cage_material.density * cage_volume
        r_out, r_in = (d_c + t) / 2, (d_c - t) / 2
        inner_race = inner_race_diameter(pitch, d_w, clearance)
        ring_mass = spec.ring_material.density * math.pi * (inner_race**2 - spec.inner_ring_bore**2) / 4 * spec.ring_width
        land = spec.land_clearance or 0.0
        return cls(
            rollers=z,
            roller_diameter=d_w,
            roller_length=length,
            pitch_diameter=pitch,
            clearance=clearance,
            inner_race_diameter=inner_race,
            outer_race_diameter=outer_race_diameter(pitch, d_w, clearance),
            cage_diameter=d_c,
            cage_thickness=t,
            pocket_clearance=h,
            pocket_angle=pocket_angle(pitch, d_c, d_w, h),
            roller_mass=mass,
            roller_inertia=mass * d_w**2 / 8,
            cage_mass=cage_mass,
            cage_inertia=cage_mass * (r_out**2 + r_in**2) / 2,
            inner_ring_mass=ring_mass + spec.supported_mass,
            # ring annulus, plus the supported shaft share as a solid shaft of the bore's diameter
            inner_ring_inertia=(ring_mass * (inner_race**2 + spec.inner_ring_bore**2) / 8
                                + spec.supported_mass * spec.inner_ring_bore**2 / 8),
            inner_land_radius=r_in - land / 2,
            cage_bore_radius=r_in,
            cage_outer_radius=r_out,
            outer_land_radius=r_out + land / 2,
        )

    @property
    def raceways(self) -> RacewayLayout:
        """The rolling set's layout between the raceways (:class:`RacewayLayout`)."""
        return RacewayLayout(self.rollers, self.roller_diameter / 2, self.inner_race_diameter / 2,
                             self.outer_race_diameter / 2)

    @property
    def roller_angles(self) -> np.ndarray:
        """ψ_k = 2πk/Z [rad]."""
        return 2 * np.pi * np.arange(self.rollers) / self.rollers

    def epicyclic_cage_speed(self, inner_speed):
        """ω_c [rad/s] at inner-ring speed ω_i, see :func:`epicyclic_cage_speed`."""
        return epicyclic_cage_speed(inner_speed, self.roller_diameter, self.pitch_diameter)

    def epicyclic_roller_spin(self, inner_speed):
        """Absolute roller spin ω_r = −ω_c D_pw/D_w [rad/s] (no slip at the fixed outer raceway)."""
        return -self.epicyclic_cage_speed(inner_speed) * self.pitch_diameter / self.roller_diameter

    def pocket_points(self, k: int) -> dict[str, tuple[float, float]]:
        """Pocket edges of pocket k in the cage frame [m]: P and Q on the cage circle at ψ_k ± γ (document),
        P_inner and Q_inner on the mirror circle 2D_pw − D_c (ours)."""
        psi = self.roller_angles[k]
        inner_diameter = 2 * self.pitch_diameter - self.cage_diameter
        inner_angle = pocket_angle(self.pitch_diameter, inner_diameter, self.roller_diameter, self.pocket_clearance)
        points = {}
        for suffix, diameter, angle in (("", self.cage_diameter, self.pocket_angle),
                                        ("_inner", inner_diameter, inner_angle)):
            for label, sign in (("P", 1), ("Q", -1)):
                points[label + suffix] = (diameter / 2 * math.cos(psi + sign * angle),
                                          diameter / 2 * math.sin(psi + sign * angle))
        return points


    def pocket_walls(self, k: int) -> dict[str, tuple[tuple[float, float], tuple[float, float]]]:
        """(point, unit normal towards the roller) in the cage frame of pocket k's two flat walls, on the P and on
        the Q side: square to the orbit at the roller's centre and the pocket clearance H from the centred
        roller, as its edges are (:meth:`pocket_points`). Each spans the wall between its two edges, half-width
        :attr:`pocket_wall_half_width`."""
        psi = self.roller_angles[k]
        centre_x, centre_y = self.pitch_diameter / 2 * math.cos(psi), self.pitch_diameter / 2 * math.sin(psi)
        reach = self.roller_diameter / 2 + self.pocket_clearance
        tangent_x, tangent_y = -math.sin(psi), math.cos(psi)
        return {label: ((centre_x + sign * reach * tangent_x, centre_y + sign * reach * tangent_y),
                        (-sign * tangent_x, -sign * tangent_y)) for label, sign in (("P", 1), ("Q", -1))}

    @property
    def pocket_wall_half_width(self) -> float:
        """Half the radial extent [m] of a pocket wall: t/2, half the cage ring's radial thickness t.

        A pocket is a window (D_w + 2H) × L_w cut through the cage ring's section (as the cage's mass counts it),
        so each of its two walls is a face L_w long along the axis and t tall radially: the thickness of the ring
        it is cut through. The film on it is taken centred on the narrowest gap, at the roller's
        centre, as the wall is placed (:meth:`pocket_walls`; this model's pocket wraps the roller on both sides
        of the pitch circle). The span |D_c − D_pw| between the edges P, Q and their mirrors is no height of a
        wall: it is 0 for a cage on the pitch circle, a common design."""
        return self.cage_thickness / 2


def roller_mass(density: float, roller_diameter: float, roller_length: float) -> float:
    """m_r = ρ π D_w² L_w / 4 [kg]: a solid cylinder of density [kg/m³], diameter and length [m]."""
    return density * math.pi * roller_diameter**2 * roller_length / 4


def epicyclic_cage_speed(inner_speed, roller_diameter, pitch_diameter):
    """ω_c = ω_i (1 − D_w/D_pw)/2 [rad/s]: the cage speed of pure rolling with the outer ring fixed."""
    return inner_speed * (1 - roller_diameter / pitch_diameter) / 2


def roller_centrifugal_force(roller_mass, pitch_diameter, orbit_speed):
    """F_c = m_r (D_pw/2) ω_c² [N] of a roller of mass [kg] orbiting on the pitch circle [m] at ω_c [rad/s]."""
    return roller_mass * 0.5 * pitch_diameter * orbit_speed**2


def pocket_angle(pitch_diameter: float, cage_diameter: float, roller_diameter: float, pocket_clearance: float):
    """γ [rad] of document eq. 45 (denominator corrected)."""
    return math.acos(pocket_angle_cosine(pitch_diameter, cage_diameter, roller_diameter, pocket_clearance))
