r"""Ball–groove point contact: Hertz's elliptical solution, and Houpert's explicit formulas.

Exact Hertz solution (H. Hertz 1881; in the form of T. A. Harris, M. N. Kotzalas, *Essential Concepts of Bearing
Technology*, 5th ed., 2006, ch. 6). Two bodies touch with principal curvatures :math:`\rho_{1I}, \rho_{1II}`
(body 1) and :math:`\rho_{2I}, \rho_{2II}` (body 2) [1/m], convex positive, concave negative. With the curvature
sum :math:`\Sigma\rho` and difference :math:`F(\rho) = [(\rho_{1I}-\rho_{1II}) + (\rho_{2I}-\rho_{2II})]/\Sigma\rho`,
the ratio :math:`\kappa = a/b \ge 1` of the contact ellipse solves

.. math:: F(\rho) = \frac{(\kappa^2 + 1)\,\mathcal E - 2\,\mathcal K}{(\kappa^2 - 1)\,\mathcal E},

with :math:`\mathcal K, \mathcal E` the complete elliptic integrals of modulus :math:`e^2 = 1 - 1/\kappa^2`; then

.. math:: a = \left(\frac{6\kappa^2\mathcal E Q}{\pi\Sigma\rho E'}\right)^{1/3},\quad
          b = \left(\frac{6\mathcal E Q}{\pi\kappa\Sigma\rho E'}\right)^{1/3},\quad
          p_{max} = \frac{3Q}{2\pi a b},\qquad \frac{2}{E'} = \frac{1-\nu_1^2}{E_1} + \frac{1-\nu_2^2}{E_2}.

Houpert's formulas for a ball of diameter :math:`D_w` in a groove of conformity :math:`s = D_w/(2R_c)`, straight in
the rolling direction (L. Houpert, "An engineering approach to Hertzian contact elasticity—Part I", J. Tribol.
123 (2001) 582–588; as printed in document 002, eqs. 13–15, with N, mm, MPa):

.. math:: a = 1.3085\,(1-s)^{-0.4091} c,\quad b = 1.1687\,(1-s)^{0.1974} c,\quad
          c = \left(\frac{1-\nu^2}{E}\,\frac{D_w}{2}\,Q\right)^{1/3},\qquad
          p_{max} = 1805\,(1-s)^{0.2117}\,Q^{1/3}/D_w^{2/3}\ \ (\text{steel}).

Functions take and return SI units (N, m, Pa).
"""

from __future__ import annotations

import math
from typing import NamedTuple

from scipy.optimize import brentq
from scipy.special import ellipe, ellipkm1

RINGS = ("inner", "outer")


class EllipticalContact(NamedTuple):
    """Semi-axes a ≥ b [m] of the contact ellipse and the largest pressure [Pa]."""

    a: float
    b: float
    p_max: float


#: The largest ellipse ratio a/b :func:`ellipse_ratio` resolves (1 − F(ρ) ≈ 1e-29 there).
MAX_ELLIPSE_RATIO = 1e15


def ellipse_ratio(curvature_difference: float) -> float:
    """κ = a/b ≥ 1 for the curvature difference F(ρ) in [0, 1) (module docstring)."""
    if not 0.0 <= curvature_difference < 1.0:
        raise ValueError(f"curvature difference F(rho) = {curvature_difference!r} must be in [0, 1)")
    if curvature_difference == 0.0:
        return 1.0

    def mismatch(log_kappa):
        kappa = math.exp(log_kappa)
        p = 1.0 / kappa**2  # 1 − m: K(m) through ellipkm1(1 − m), exact where m rounds to 1 (κ > 1e8)
        big_e, big_k = ellipe(1.0 - p), ellipkm1(p)
        return ((kappa**2 + 1) * big_e - 2 * big_k) / ((kappa**2 - 1) * big_e) - curvature_difference

    # F(ρ) → 1 as κ → ∞ (a groove that fits the ball across, κ = 1e6 at 1 − F = 3e-11)
    return math.exp(brentq(mismatch, 1e-9, math.log(MAX_ELLIPSE_RATIO), xtol=1e-14, rtol=1e-14))


def hertz_contact(load: float, curvatures: tuple[float, float, float, float], modulus: float) -> EllipticalContact:
    """The exact Hertz contact under ``load`` [N] of two bodies with principal curvatures (ρ₁I, ρ₁II, ρ₂I, ρ₂II)
    [1/m] (convex > 0) and reduced modulus E' [Pa]
    (:func:`~bearing_mbs.contact.line_contact.reduced_modulus`)."""
    r1i, r1ii, r2i, r2ii = curvatures
    total = r1i + r1ii + r2i + r2ii
    if not total > 0:
        raise ValueError(f"curvature sum {total!r} 1/m must be > 0 (the bodies must be able to touch at a point)")
    kappa = ellipse_ratio(abs((r1i - r1ii) + (r2i - r2ii)) / total)
    big_e = ellipe(1.0 - 1.0 / kappa**2)
    a = (6 * kappa**2 * big_e * load / (math.pi * total * modulus)) ** (1 / 3)
    b = (6 * big_e * load / (math.pi * kappa * total * modulus)) ** (1 / 3)
    return EllipticalContact(a, b, 3 * load / (2 * math.pi * a * b))


def hertz_approach(load: float, curvatures: tuple[float, float, float, float], modulus: float) -> float:
    """The approach δ [m] of the two bodies' far points under ``load`` [N] (Harris & Kotzalas, ch. 6):
    δ = δ* [3Q/(2Σρ) · 2/E']^{2/3} Σρ/2 with δ* = (2𝒦/π) (π/(2κ²ℰ))^{1/3}."""
    total = sum(curvatures)
    r1i, r1ii, r2i, r2ii = curvatures
    kappa = ellipse_ratio(abs((r1i - r1ii) + (r2i - r2ii)) / total)
    p = 1.0 / kappa**2  # 1 − m (ellipkm1: exact where m rounds to 1)
    star = 2 * ellipkm1(p) / math.pi * (math.pi / (2 * kappa**2 * ellipe(1.0 - p))) ** (1 / 3)
    return star * (3 * load / (2 * total) * 2 / modulus) ** (2 / 3) * total / 2


def hertz_stiffness(curvatures: tuple[float, float, float, float], modulus: float) -> float:
    """K [N/m^1.5] of Q = K δ^{3/2} for the contact (:func:`hertz_approach`; K does not depend on the load)."""
    return 1.0 / hertz_approach(1.0, curvatures, modulus) ** 1.5


def ball_groove_curvatures(ball_diameter: float, conformity: float, pitch_diameter: float | None = None,
                           contact_angle: float = 0.0, ring: str = "inner") -> tuple[float, float, float, float]:
    """(ρ₁I, ρ₁II, ρ₂I, ρ₂II) [1/m] of a ball (body 1) in the groove of a ring (body 2): the groove radius
    R_c = D_w/(2s) across; along the rolling direction the raceway radius at the contact,
    (D_pw ∓ D_w cos α)/(2 cos α) (convex on the inner ring, concave on the outer), or straight when
    ``pitch_diameter`` is None. ``contact_angle`` α [rad]."""
    if ring not in RINGS:
        raise ValueError(f"ring must be one of {RINGS}, got {ring!r}")
    ball = 2.0 / ball_diameter
    groove = -2.0 * conformity / ball_diameter
    rolling = 0.0
    if pitch_diameter is not None:
        cosine = math.cos(contact_angle)
        if ring == "inner":
            rolling = 2 * cosine / (pitch_diameter - ball_diameter * cosine)
        else:
            rolling = -2 * cosine / (pitch_diameter + ball_diameter * cosine)
    return (ball, ball, rolling, groove)


def _houpert_factor(load, ball_diameter, youngs_modulus, poisson_ratio):
    """((1 − ν²)/E · D_w/2 · Q)^{1/3} [m]."""
    return ((1 - poisson_ratio**2) / youngs_modulus * ball_diameter / 2 * load) ** (1 / 3)


def houpert_contact(load: float, ball_diameter: float, conformity: float, youngs_modulus: float,
                    poisson_ratio: float) -> EllipticalContact:
    """Houpert's semi-axes [m] and largest pressure [Pa] of a ball in a straight groove (module docstring)."""
    c = _houpert_factor(load, ball_diameter, youngs_modulus, poisson_ratio)
    a = 1.3085 * (1 - conformity) ** -0.4091 * c
    b = 1.1687 * (1 - conformity) ** 0.1974 * c
    p_max = 1805.0 * (1 - conformity) ** 0.2117 * load ** (1 / 3) / (1e3 * ball_diameter) ** (2 / 3) * 1e6
    return EllipticalContact(a, b, p_max)


def houpert_load_at_pressure(p_max: float, ball_diameter: float, conformity: float) -> float:
    """The load Q [N] at which Houpert's largest pressure reaches ``p_max`` [Pa] (steel): the inverse of
    p_max = 1805 (1 − s)^0.2117 Q^{1/3}/D_w^{2/3} (N, mm, MPa)."""
    return (p_max * 1e-6 / (1805.0 * (1 - conformity) ** 0.2117)) ** 3 * (1e3 * ball_diameter) ** 2
