r"""Quasi-static load distribution of a four-point-contact slewing bearing, with rigid or flexible rings.

Model (the analytical model document 002 builds on: each ball as two tension-only springs on the diagonals
between the raceway curvature centres; J. Aguirrebeitia, R. Avilés, I. Fernández de Bustos, M. Abasolo, "Calculation
of general static load-carrying capacity for the design of four-contact-point slewing bearings", J. Mech. Des. 132
(2010) 064501). Ball j sits at azimuth ψ_j = 2πj/N on the pitch circle of radius R = D_pw/2. In the section at
ψ_j, in (radial, axial) coordinates, diagonal d = ±1 joins the two curvature centres across the ball; unloaded
they are A₀ = 2R_c − D_w apart along e_d = (cos α₀, d sin α₀). The inner ring moves by x = (δ_r, δ_a, θ): a radial
shift along the x axis (ψ = 0) [m], an axial shift [m] and a tilt about the y axis [rad] (the outer ring is held).
At ball j the centres then sit at

.. math:: s_d = A_0 e_d + (\delta_r\cos\psi_j,\ \delta_a + \theta R\cos\psi_j),

and the diagonal carries Q = K (|s_d| − A₀)^{3/2} when the centres have moved apart (|s_d| > A₀), nothing
otherwise, along s_d at the contact angle α = atan2(|s_z|, s_r). K is the two Hertz contacts of the diagonal in
series (:func:`diagonal_stiffness`). The bearing carries the load
(F_r, F_a, M) = Σ_j Σ_d Bᵀ Q ŝ_d with B = [[cos ψ, 0, 0], [0, 1, R cos ψ]] (rows s_r, s_z), and its stiffness is
the Jacobian of that sum, written analytically (∂f/∂s = Q′ ŝŝᵀ + (Q/|s|)(I − ŝŝᵀ)).

:func:`solve` finds x for a load by Newton's method with a backtracking line search (the same style as the radial
roller solver of document 003), with any of the three coordinates imposed instead (an imposed axial displacement
gives a load–deflection curve). Flexible rings (:mod:`.flexible`) add each ball's ring-sector displacements,
relaxed at every x; the outer Newton loop is the same.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from bearing_mbs.contact.line_contact import reduced_modulus
from bearing_mbs.contact.point_contact import ball_groove_curvatures, hertz_stiffness
from bearing_mbs.elements.slewing_bearings import bearing_state
from bearing_mbs.models.slewing_bearing.flexible import FlexibleRings, NotConverged, flexible_state
from bearing_mbs.models.slewing_bearing.geometry import ball_count
from bearing_mbs.spec import SpecError

#: Coordinates of the inner ring: radial shift [m], axial shift [m], tilt [rad].
COORDINATES = ("radial", "axial", "tilt")


def diagonal_stiffness(ball_diameter: float, conformity: float, pitch_diameter: float, contact_angle: float,
                       youngs_modulus: float, poisson_ratio: float) -> float:
    """K [N/m^1.5] of one diagonal: the ball's inner-ring and outer-ring Hertz contacts in series,
    (K_i^{-2/3} + K_o^{-2/3})^{-3/2}, each from the exact solution with the raceway's curvature."""
    modulus = reduced_modulus(youngs_modulus, poisson_ratio, youngs_modulus, poisson_ratio)
    k_inner, k_outer = (hertz_stiffness(ball_groove_curvatures(ball_diameter, conformity, pitch_diameter,
                                                               contact_angle, ring), modulus)
                        for ring in ("inner", "outer"))
    return (k_inner ** (-2 / 3) + k_outer ** (-2 / 3)) ** -1.5


@dataclass(frozen=True)
class SlewingBearing:
    """A four-point-contact ball bearing with rigid rings.

    pitch_diameter D_pw [m]; ball_diameter D_w [m]; conformity s = D_w/(2 R_c) in (0.5, 1); contact_angle α₀
    [rad] in (0, π/2); balls N (default trunc(π D_pw/D_w)); stiffness K [N/m^1.5] of a diagonal (default: Hertz,
    steel E = 200 GPa, ν = 0.3).
    """

    pitch_diameter: float
    ball_diameter: float
    conformity: float
    contact_angle: float
    balls: int | None = None
    stiffness: float | None = None

    def __post_init__(self):
        if not self.pitch_diameter > 0:
            raise SpecError("pitch_diameter", self.pitch_diameter, "> 0 [m]")
        if not 0 < self.ball_diameter:
            raise SpecError("ball_diameter", self.ball_diameter, "> 0 [m]")
        if not 0.5 < self.conformity < 1:
            raise SpecError("conformity", self.conformity, "in (0.5, 1): the groove radius between D_w/2 and D_w")
        if not 0 < self.contact_angle < math.pi / 2:
            raise SpecError("contact_angle", math.degrees(self.contact_angle), "in (0, 90) degrees")
        fit = ball_count(self.pitch_diameter, self.ball_diameter)
        if self.balls is None:
            object.__setattr__(self, "balls", fit)
        if not 1 <= self.balls <= fit:
            raise SpecError("balls", self.balls, f"in [1, {fit}]: that many balls of {self.ball_diameter:g} m fit "
                                                 f"side by side on a pitch circle of {self.pitch_diameter:g} m")
        if self.stiffness is None:
            object.__setattr__(self, "stiffness", diagonal_stiffness(self.ball_diameter, self.conformity,
                                                                     self.pitch_diameter, self.contact_angle,
                                                                     200e9, 0.3))

    @property
    def centre_distance(self) -> float:
        """A₀ = 2R_c − D_w [m], the distance of the curvature centres across an unloaded ball."""
        return self.ball_diameter / self.conformity - self.ball_diameter

    @property
    def azimuths(self) -> np.ndarray:
        return 2 * math.pi * np.arange(self.balls) / self.balls


@dataclass(frozen=True)
class Distribution:
    """The state at inner-ring displacement x = (δ_r [m], δ_a [m], θ [rad]): ``load`` (F_r [N], F_a [N], M [N m])
    and its ``stiffness`` ∂load/∂x (3×3, SI); per ball and diagonal (N, 2): ``ball_loads`` Q [N] and
    ``contact_angles`` α [rad]; ``azimuths`` ψ [rad]; with flexible rings, ``sector_coordinates`` η (N, m): each
    ball's ring-sector coordinates (:mod:`.flexible`)."""

    displacement: np.ndarray
    load: np.ndarray
    stiffness: np.ndarray
    ball_loads: np.ndarray
    contact_angles: np.ndarray
    azimuths: np.ndarray
    sector_coordinates: np.ndarray | None = None


def evaluate(bearing: SlewingBearing, displacement, rings: FlexibleRings | None = None,
             sector_coordinates=None) -> Distribution:
    """Ball loads, the bearing's load and its analytic stiffness at the inner-ring ``displacement``; rigid rings
    (the equations' one owner is :func:`bearing_mbs.elements.slewing_bearings.bearing_state`, which the force
    element uses too) or flexible ``rings``, relaxed from ``sector_coordinates`` (:func:`.flexible.flexible_state`)."""
    x = np.array([float(v) for v in displacement])
    if rings is not None:
        load, stiffness, ball_loads, angles, local = flexible_state(bearing, rings, x, sector_coordinates)
        return Distribution(x, load, stiffness, ball_loads, angles, bearing.azimuths, local)
    load, stiffness, ball_loads, angles = bearing_state(bearing.balls, bearing.pitch_diameter / 2,
                                                        bearing.centre_distance, bearing.contact_angle,
                                                        bearing.stiffness, x)
    return Distribution(x, load, stiffness, ball_loads, angles, bearing.azimuths)


#: The largest residual, relative to the load's scale, that :func:`solve` accepts where Newton's steps stop lowering
#: it (the round-off of the ball forces' sum; measured 2e-10 for 1 N on soft rings at a 4° contact angle).
ROUND_OFF_FLOOR = 1e-8


def solve(bearing: SlewingBearing, load=(0.0, 0.0, 0.0), imposed: dict | None = None, tolerance: float = 1e-12,
          iterations: int = 100, rings: FlexibleRings | None = None) -> Distribution:
    """The inner-ring displacement that carries ``load`` = (F_r [N], F_a [N], M [N m]), with the coordinates named
    in ``imposed`` ({"radial" | "axial" | "tilt": value}) held at their values instead (their load entries are
    then outputs). Newton's method on the free coordinates, backtracking on the residual; converged when the
    residual is below ``tolerance`` × the largest of the load and the ball loads' sum, or below
    :data:`ROUND_OFF_FLOOR` × that where no step lowers it. ``rings``: flexible rings (default rigid). Raises
    :class:`NotConverged` otherwise."""
    imposed = dict(imposed or {})
    for name in imposed:
        if name not in COORDINATES:
            raise SpecError("imposed", name, f"one of {', '.join(COORDINATES)}")
    free = np.array([name not in imposed for name in COORDINATES])
    target = np.asarray(load, dtype=float)
    x = np.array([imposed.get(name, 0.0) for name in COORDINATES])
    if not free.any() or not np.any(target[free]):
        return evaluate(bearing, x, rings)  # everything imposed, or nothing to carry: the rings stay where they are
    # start with an axial (or radial) approach that loads some balls, so that the Jacobian is not singular
    x[free] += 1e-3 * bearing.centre_distance
    local = None
    for _ in range(iterations):
        state = evaluate(bearing, x, rings, local)
        local = state.sector_coordinates
        residual = (state.load - target)[free]
        scale = max(np.abs(target).max(), state.ball_loads.sum(), 1.0)
        if np.abs(residual).max() <= tolerance * scale:
            return state
        jacobian = state.stiffness[np.ix_(free, free)]
        step = np.linalg.lstsq(jacobian, -residual, rcond=None)[0]
        norm, factor = np.abs(residual).max(), 1.0
        while factor > 1e-6:
            trial = x.copy()
            trial[free] += factor * step
            if np.abs((evaluate(bearing, trial, rings, local).load - target)[free]).max() < norm:
                break
            factor /= 2
        else:  # no step lowers the residual: at the round-off floor of the ball forces' sum, done
            if norm <= ROUND_OFF_FLOOR * scale:
                return state
        x = trial
    raise NotConverged(f"the load distribution did not converge in {iterations} iterations (residual {norm:.3g})")
