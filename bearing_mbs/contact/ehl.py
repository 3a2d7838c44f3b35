r"""Elastohydrodynamic (EHL) film of a lubricated line contact: Hertz half-width and pressure, central and
minimum film thickness, the inlet-heating reduction and the film parameter Λ.

A roller of effective length :math:`l` [m] pressed on a raceway by :math:`Q` [N] carries the load per unit
length :math:`w = Q/l` [N/m]. With the reduced radius :math:`R` [m] of the two cylinders in the rolling
direction (:func:`reduced_radius`), the reduced modulus :math:`E' = 2/[(1-\nu_1^2)/E_1 + (1-\nu_2^2)/E_2]` [Pa],
the mean entrainment speed :math:`u = (u_1 + u_2)/2` [m/s] of the two surfaces relative to the contact, the
oil's dynamic viscosity :math:`\eta_0` [Pa s] at the inlet temperature and its pressure–viscosity coefficient
:math:`\alpha` [1/Pa], the dimensionless groups are

.. math:: U = \frac{\eta_0 u}{E' R},\qquad G = \alpha E',\qquad W = \frac{w}{E' R},\qquad H = \frac{h}{R}.

Two published fits to numerical isothermal line-contact solutions are offered (``FILM_FORMULAS``):

* ``dowson_higginson``: minimum :math:`H_{min} = 2.65\,U^{0.70} G^{0.54} W^{-0.13}` (D. Dowson, G. R.
  Higginson, *Elasto-Hydrodynamic Lubrication*, SI ed., Pergamon, 1977) with the central film of D. Dowson and
  S. Toyoda (1979), :math:`H_c = 3.06\,U^{0.69} G^{0.56} W^{-0.10}`;
* ``pan_hamrock``: :math:`H_{min} = 1.714\,W^{-0.128} U^{0.694} G^{0.568}`,
  :math:`H_c = 2.922\,W^{-0.166} U^{0.692} G^{0.470}` (P. Pan, B. J. Hamrock, "Simple formulas for performance
  parameters used in elastohydrodynamically lubricated line contacts", J. Tribol. 111 (1989) 246–251).

Inlet shear heating thins the film at high speed. The reduction factor of J. Murch and W. R. D. Wilson ("A
thermal elastohydrodynamic inlet zone analysis", J. Lubr. Technol. 97 (1975) 212–216) for rolling contacts is

.. math:: \phi_T = \frac{3.94}{3.94 + L^{0.62}},\qquad L = \frac{\beta\,\eta_0\,u^2}{k},

with β [1/K] the oil's temperature–viscosity coefficient :math:`-\mathrm d\ln\eta/\mathrm dT` and k [W/(m K)]
its thermal conductivity. The film parameter is :math:`\Lambda = h_{min}/\sigma` with the composite roughness
:math:`\sigma = (\sigma_1^2 + \sigma_2^2)^{1/2}` [m].

The hydrodynamic rolling resistance of the contact, the force :math:`F_R` [N] that the inlet's pressure and
Poiseuille shear put against the rolling of each surface, is R. S. Zhou and M. R. Hoeprich's fit to isothermal,
fully flooded numerical line-contact solutions ("Torque of tapered roller bearings", J. Tribol. 113 (1991)
590–597):

.. math:: F_R = \frac{4.318}{\alpha}\,(G U)^{0.658}\,W^{0.0126}\,R\,l.

It hardly depends on the load (:math:`W^{0.0126}`) and grows as :math:`(\eta_0 u)^{0.658}`, like the film:
it is of the order of :math:`h_c l/\alpha`, the film times the inlet pressure at which the oil's viscosity
runs away. As the load vanishes the contact leaves the elastohydrodynamic regime for the rigid, isoviscous one of
H. M. Martin (1916): with the Reynolds outlet condition the pressure ends at :math:`x = 0.4751\,(2Rh_0)^{1/2}`,
the film carries :math:`w = 4.895\,\eta_0 u R/h_0`, and the Poiseuille shear on the two surfaces,
:math:`\int h\,\mathrm dp/\mathrm dx\,\mathrm dx`, sums to
:math:`F_{R,0} = 12 \times 0.5422\,\eta_0 u l\,(2R/h_0)^{1/2} = 4.159\,(\eta_0 u l Q)^{1/2}`, which vanishes
with the load (our closed-form integration, checked against a numerical solution of Reynolds' equation in the
tests). :func:`rolling_force` takes the smaller of the two, so the force grows continuously from zero as a contact
closes (the fit alone would jump to ~70 % of its value at the first micronewton) and the light contacts, such as
rollers pressed on the outer ring by their centrifugal force alone, get the rigid regime's.

The Hertz line contact (K. L. Johnson, *Contact Mechanics*, 1985, §4.2) has the half-width
:math:`b = (8 w R/\pi E')^{1/2}` and peak pressure :math:`p_h = 2w/(\pi b) = (w E'/2\pi R)^{1/2}`; the mean
pressure is :math:`\bar p = w/(2b) = \pi p_h/4`.

All functions but :func:`reduced_radius` (a build-time helper) are ``register_jitable`` (compiled inline by the
contact-pair kernel, plain Python elsewhere) and take scalars or arrays.
"""

from __future__ import annotations

import numpy as np
from numba.extending import register_jitable

#: Film-thickness formulas in the order of their integer codes in the compiled kernel.
FILM_FORMULAS = ("pan_hamrock", "dowson_higginson")
_PAN_HAMROCK_CODE = FILM_FORMULAS.index("pan_hamrock")

# Coefficient and exponents (of U, G, W) of each formula: (central, minimum), in FILM_FORMULAS order.
_PAN_HAMROCK = ((2.922, 0.692, 0.470, -0.166), (1.714, 0.694, 0.568, -0.128))
_DOWSON_HIGGINSON = ((3.06, 0.69, 0.56, -0.10), (2.65, 0.70, 0.54, -0.13))
#: Zhou–Hoeprich's coefficient and exponents (of GU and W).
_ZHOU_HOEPRICH = (4.318, 0.658, 0.0126)
#: The rigid, isoviscous rolling force's coefficient, F_R,0 = 4.159 (η0 u l Q)^(1/2).
_RIGID_ROLLING = 4.159
#: Murch–Wilson's constants.
_MURCH_WILSON = (3.94, 0.62)


def reduced_radius(radius_a, radius_b, concave):
    r"""R [m] in the rolling direction of a cylinder of radius ``radius_b`` on a convex (``concave`` = 0) or
    concave (1, a hollow raceway of radius ``radius_a`` > radius_b) cylinder: :math:`R = r_a r_b/(r_a \pm r_b)`.
    A flat (radius_a = 0, convex) gives :math:`R = r_b`."""
    flat = radius_a <= 0.0
    sign = 1.0 - 2.0 * concave
    return np.where(flat, radius_b, radius_a * radius_b / np.where(flat, 1.0, radius_a + sign * radius_b))


@register_jitable
def hertz_half_width(load_per_length, radius, modulus):
    """Hertz half-width b [m] of a line contact: load per length [N/m], reduced radius [m] and modulus E' [Pa]."""
    return np.sqrt(8.0 * load_per_length * radius / (np.pi * modulus))


@register_jitable
def hertz_pressure(load_per_length, radius, modulus):
    """Peak Hertz pressure p_h [Pa] of a line contact."""
    return np.sqrt(load_per_length * modulus / (2.0 * np.pi * radius))


@register_jitable
def _film(coefficients, speed, load_per_length, viscosity, pressure_viscosity, modulus, radius):
    c, eu, eg, ew = coefficients
    u_group = viscosity * speed / (modulus * radius)
    w_group = load_per_length / (modulus * radius)
    return radius * c * u_group**eu * (pressure_viscosity * modulus) ** eg * w_group**ew


@register_jitable
def film_thickness(formula, speed, load_per_length, viscosity, pressure_viscosity, modulus, radius):
    """(central, minimum) isothermal film thickness [m] of formula code ``formula`` (index into FILM_FORMULAS)
    at entrainment speed u [m/s] >= 0 and load per length w [N/m] > 0; both 0 at u = 0."""
    table = _PAN_HAMROCK if formula == _PAN_HAMROCK_CODE else _DOWSON_HIGGINSON
    central = _film(table[0], speed, load_per_length, viscosity, pressure_viscosity, modulus, radius)
    minimum = _film(table[1], speed, load_per_length, viscosity, pressure_viscosity, modulus, radius)
    return central, minimum


@register_jitable
def _rolling_regimes(speed, load_per_length, viscosity, pressure_viscosity, modulus, radius, length):
    """(Zhou–Hoeprich's, the rigid isoviscous) rolling force [N]: the two regimes :func:`rolling_force` chooses
    between."""
    c, e_gu, e_w = _ZHOU_HOEPRICH
    u_group = viscosity * speed / (modulus * radius)
    w_group = load_per_length / (modulus * radius)
    elastic = c / pressure_viscosity * (pressure_viscosity * modulus * u_group) ** e_gu * w_group**e_w * radius * length
    rigid = _RIGID_ROLLING * np.sqrt(viscosity * speed * load_per_length) * length
    return elastic, rigid


@register_jitable
def rolling_force(speed, load_per_length, viscosity, pressure_viscosity, modulus, radius, length):
    """The isothermal hydrodynamic rolling force F_R [N] of a line contact of length l [m] at entrainment speed
    u [m/s] >= 0 and load per length w [N/m] >= 0: Zhou–Hoeprich's, or the rigid, isoviscous one where that is
    smaller (light loads); 0 at u = 0 or w = 0."""
    elastic, rigid = _rolling_regimes(speed, load_per_length, viscosity, pressure_viscosity, modulus, radius, length)
    return np.minimum(elastic, rigid)


@register_jitable
def thermal_loading(speed, viscosity, temperature_viscosity, conductivity):
    r"""Murch–Wilson's thermal loading :math:`L = \beta\eta_0 u^2/k` [-]."""
    return temperature_viscosity * viscosity * speed * speed / conductivity


@register_jitable
def thermal_reduction(loading):
    r"""Murch–Wilson's film reduction :math:`\phi_T = 3.94/(3.94 + L^{0.62})` in (0, 1]."""
    a, e = _MURCH_WILSON
    return a / (a + loading**e)


@register_jitable
def thermal_reduction_slope(loading):
    r""":math:`\mathrm d\ln\phi_T/\mathrm d\ln L = -0.62\,L^{0.62}/(3.94 + L^{0.62})` of :func:`thermal_reduction`."""
    a, e = _MURCH_WILSON
    return -e * loading**e / (a + loading**e)


@register_jitable
def film_thickness_exponents(formula):
    """(central's, minimum's) exponents of the speed u and of the load w in :func:`film_thickness`: the slopes
    d ln h/d ln u and d ln h/d ln w of the formula with code ``formula``, as ((u, w), (u, w))."""
    table = _PAN_HAMROCK if formula == _PAN_HAMROCK_CODE else _DOWSON_HIGGINSON
    return (table[0][1], table[0][3]), (table[1][1], table[1][3])


@register_jitable
def rolling_force_exponents(speed, load_per_length, viscosity, pressure_viscosity, modulus, radius, length):
    """d ln F_R/d ln u and d ln F_R/d ln w of :func:`rolling_force`: Zhou–Hoeprich's 0.658 and 0.0126 where it
    is the smaller, the rigid regime's 1/2 and 1/2 elsewhere."""
    _, e_gu, e_w = _ZHOU_HOEPRICH
    elastic, rigid = _rolling_regimes(speed, load_per_length, viscosity, pressure_viscosity, modulus, radius, length)
    return (e_gu, e_w) if elastic < rigid else (0.5, 0.5)


@register_jitable
def film_parameter(minimum_film, roughness):
    r"""Λ = h_min/σ [-], σ [m] the composite rms roughness of the two surfaces."""
    return minimum_film / roughness
