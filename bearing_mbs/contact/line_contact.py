r"""Roller–raceway line contact: Palmgren's law, its slice form, and two contacts in series.

All functions are pure. The scalar ones use NumPy ufuncs only and are ``register_jitable`` (compiled inline
when a numba kernel calls them, plain Python everywhere else), like :mod:`.normal`; they also work on arrays.
:func:`sliced_contact` sums over slices and is plain NumPy.

Palmgren's line-contact law
---------------------------
For a steel roller on a steel raceway with effective (straight) contact length :math:`l`, Palmgren's
empirical fit gives the elastic approach of the two bodies

.. math:: \delta\,[\mathrm{mm}] = 3.84\cdot10^{-5}\,\frac{Q[\mathrm N]^{0.9}}{l[\mathrm{mm}]^{0.8}},

per contact (one raceway). Inverting, :math:`Q = c\,\delta^{10/9} l^{8/9}` with
:math:`c = (3.84\cdot10^{-5})^{-10/9} = 8.07\cdot10^{4}\ \mathrm{N\,mm^{-2}}` (Harris rounds it to
:math:`8.06\cdot10^4`). In SI units, with :math:`\delta_{mm} = 10^3\delta` and :math:`l_{mm} = 10^3 l`,

.. math:: Q = K\,\delta^{10/9}, \qquad K = c\,(10^{3})^{10/9 + 8/9}\, l^{8/9} = 8.07\cdot10^{10}\,
          \mathrm{N\,m^{-2}}\;l^{8/9}\quad [\mathrm{N/m^{10/9}},\ l\ \text{in m}],

since :math:`10/9 + 8/9 = 2`. :data:`PALMGREN_COEFFICIENT` is the constant :math:`8.07\cdot10^{10}` N/m²
computed from 3.84e-5 without rounding, so :func:`palmgren_approach` (the formula as printed) and
:func:`palmgren_stiffness` invert each other to round-off. For :math:`l = 55` mm,
:math:`K = 6.1\cdot10^9\ \mathrm{N/m^{10/9}}`.

Slice form (document 003, eq. 14)
---------------------------------
A roller of effective length :math:`L_e` is cut into :math:`N` slices of width :math:`w = L_e/N`; slice
:math:`k` at abscissa :math:`z_k` carries :math:`Q_k = C_f\,\Delta d_k^{\,n}\,w` with the interference
:math:`\Delta d_k = \delta + \alpha z_k - h_k` (eq. 12; :math:`h_k` the crown drops). Document 003 does not
give :math:`C_f`. We choose it so that an uncrowned, untilted roller (:math:`\Delta d_k = \delta`) gives the
whole-roller law :math:`Q = K\delta^n` exactly, for every :math:`N`:

.. math:: C_f = K / L_e, \qquad\text{for Palmgren } C_f = 8.07\cdot10^{10}\,L_e^{-1/9}\ [\mathrm{N/m^{19/9}}].

(:math:`C_f` depends on the whole length through :math:`L_e^{-1/9}`; it is a constant of the roller, not of
the slice.) The moment about the roller centre is :math:`M = \sum_k Q_k z_k` (eqs. 15–16).

Two contacts in series
----------------------
A roller between two raceways with laws :math:`Q = K_i\delta_i^n` and :math:`Q = K_o\delta_o^n` (same
exponent, same load :math:`Q` when no body force acts on the roller) has
:math:`\delta_i + \delta_o = Q^{1/n}(K_i^{-1/n} + K_o^{-1/n})`, i.e.

.. math:: Q = K_{eq}\,(\delta_i + \delta_o)^n,\qquad K_{eq} = \left(K_i^{-1/n} + K_o^{-1/n}\right)^{-n}.

For equal laws :math:`K_{eq} = K/2^n` and each contact takes half the approach. The tangent stiffnesses
then combine as :math:`k = k_i k_o/(k_i + k_o)`, the scalar form of document 003 eq. 7.

References
----------
* A. Palmgren, *Ball and Roller Bearing Engineering*, 3rd ed., S. H. Burbank, Philadelphia, 1959.
* T. A. Harris, M. N. Kotzalas, *Essential Concepts of Bearing Technology* (Rolling Bearing Analysis,
  5th ed., vol. 1), CRC Press, 2006: ch. 6 (line-contact deformation, :math:`K = 8.06\cdot10^4 l^{8/9}`) and
  ch. 7 (series combination of inner and outer contacts).
* S. Pater, T. Mitran, A. Cocaina, "Calculul matricii de rigiditate a rulmentilor radiali", Univ. of Oradea
  (document 003), eqs. 12–16; its errata and the slice-law constant: ``docs/quasistatic.md``.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np
from numba.extending import register_jitable

from bearing_mbs.contact.normal import elastic_energy, elastic_force

#: Palmgren's exponent n = 10/9 of the line-contact law Q = K δⁿ [-].
PALMGREN_EXPONENT = 10.0 / 9.0
#: Palmgren's compliance 3.84e-5 [mm N^-0.9 mm^0.8] in δ[mm] = 3.84e-5 Q^0.9 / l[mm]^0.8.
PALMGREN_COMPLIANCE_MM = 3.84e-5
#: c (10³)² = (3.84e-5)^(-10/9) · 10⁶ ≈ 8.07e10 [N/m²]: K = c l^(8/9) in SI units.
PALMGREN_COEFFICIENT = PALMGREN_COMPLIANCE_MM ** (-PALMGREN_EXPONENT) * 1e6


@register_jitable
def palmgren_stiffness(length):
    r"""Palmgren's line-contact stiffness :math:`K = 8.07\cdot10^{10}\,l^{8/9}` [N/m^(10/9)].

    ``length``: effective contact length :math:`l` [m] > 0. One roller–raceway contact, steel on steel.
    """
    return PALMGREN_COEFFICIENT * length ** (8.0 / 9.0)


@register_jitable
def palmgren_approach(load, length):
    r"""Palmgren's formula as printed, in SI units: elastic approach :math:`\delta` [m] of one contact.

    :math:`\delta = 10^{-3}\cdot 3.84\cdot10^{-5}\,Q^{0.9}/(10^3 l)^{0.8}` for load :math:`Q` [N] >= 0 and
    effective length :math:`l` [m] > 0.
    """
    return 1e-3 * PALMGREN_COMPLIANCE_MM * np.maximum(load, 0.0) ** 0.9 / (1e3 * length) ** 0.8


@register_jitable
def slice_coefficient(stiffness, length):
    r"""Slice coefficient :math:`C_f = K/L_e` [N/m^(n+1)] of eq. 14, so that :math:`\sum_k C_f\delta^n w = K\delta^n`.

    ``stiffness``: whole-roller law :math:`K` [N/m^n]; ``length``: effective length :math:`L_e` [m].
    """
    return stiffness / length


@register_jitable
def palmgren_slice_coefficient(length):
    r"""Palmgren's slice coefficient :math:`C_f = 8.07\cdot10^{10}\,L_e^{-1/9}` [N/m^(19/9)]."""
    return slice_coefficient(palmgren_stiffness(length), length)


@register_jitable
def power_law_force(approach, stiffness, exponent):
    r"""Contact load :math:`Q = K\,\max(\delta, 0)^n` [N] for approach :math:`\delta` [m] (positive = overlap)."""
    return elastic_force(-approach, stiffness, exponent)


@register_jitable
def power_law_stiffness(approach, stiffness, exponent):
    r"""Tangent stiffness :math:`dQ/d\delta = nK\delta^{n-1}` for :math:`\delta > 0`, else 0 [N/m]; n >= 1."""
    return (approach > 0.0) * exponent * stiffness * np.maximum(approach, 0.0) ** (exponent - 1.0)


@register_jitable
def power_law_energy(approach, stiffness, exponent):
    r"""Stored energy :math:`K\max(\delta,0)^{n+1}/(n+1)` [J], whose derivative is :func:`power_law_force`."""
    return elastic_energy(-approach, stiffness, exponent)


@register_jitable
def series_stiffness(inner_stiffness, outer_stiffness, exponent):
    r"""Equivalent law of two power-law contacts in series: :math:`K_{eq} = (K_i^{-1/n} + K_o^{-1/n})^{-n}`.

    Both contacts carry the same load :math:`Q = K_{eq}(\delta_i + \delta_o)^n`. Stiffnesses in
    [N/m^n], both with exponent ``n`` [-].
    """
    return (inner_stiffness ** (-1.0 / exponent) + outer_stiffness ** (-1.0 / exponent)) ** (-exponent)


@register_jitable
def series_inner_share(inner_stiffness, outer_stiffness, exponent):
    r"""Fraction :math:`\delta_i/(\delta_i + \delta_o) = K_i^{-1/n}/(K_i^{-1/n} + K_o^{-1/n})` of the total approach."""
    inner = inner_stiffness ** (-1.0 / exponent)
    return inner / (inner + outer_stiffness ** (-1.0 / exponent))


class SlicedContact(NamedTuple):
    r"""Resultants of a sliced line contact and their partial derivatives.

    ``force`` :math:`Q = \sum Q_k` [N]; ``moment`` :math:`M = \sum Q_k z_k` [N m];
    ``force_approach`` :math:`\partial Q/\partial\delta` [N/m]; ``force_tilt``
    :math:`\partial Q/\partial\alpha = \partial M/\partial\delta` [N/rad]; ``moment_tilt``
    :math:`\partial M/\partial\alpha` [N m/rad]; ``energy`` :math:`\sum C_f w\,\Delta d_k^{n+1}/(n+1)` [J];
    ``slice_forces`` :math:`Q_k` [N], one column per slice.
    """

    force: np.ndarray
    moment: np.ndarray
    force_approach: np.ndarray
    force_tilt: np.ndarray
    moment_tilt: np.ndarray
    energy: np.ndarray
    slice_forces: np.ndarray


def sliced_contact(approach, tilt, positions, drops, width, coefficient, exponent) -> SlicedContact:
    r"""Eqs. 12, 14–16 of document 003 with analytic derivatives.

    .. math::
        \Delta d_k = \delta + \alpha z_k - h_k,\quad Q_k = C_f\,\max(\Delta d_k, 0)^n\,w,\quad
        Q = \sum_k Q_k,\quad M = \sum_k Q_k z_k,

    and, with the slice stiffness :math:`q_k = nC_f\Delta d_k^{n-1}w`,
    :math:`\partial Q/\partial\delta = \sum q_k`, :math:`\partial Q/\partial\alpha = \partial M/\partial\delta
    = \sum q_k z_k`, :math:`\partial M/\partial\alpha = \sum q_k z_k^2` (a symmetric 2×2 tangent matrix).

    Parameters
    ----------
    approach : :math:`\delta` [m], the approach at the roller centre (positive = overlap); any shape S.
    tilt : :math:`\alpha` [rad], the relative tilt of the two bodies in the contact plane; shape S.
    positions : slice abscissae :math:`z_k` [m] from the roller centre, shape (N,).
    drops : summed crown drops :math:`h_k` [m] of the two bodies at :math:`z_k`, shape (N,) or S + (N,).
    width : slice width :math:`w` [m]. coefficient : :math:`C_f` [N/m^(n+1)]. exponent : n >= 1 [-].
    """
    approach = np.asarray(approach, dtype=float)
    tilt = np.asarray(tilt, dtype=float)
    interference = approach[..., None] + tilt[..., None] * positions - drops
    compressed = np.maximum(interference, 0.0)
    slice_forces = coefficient * width * compressed**exponent
    slice_stiffness = (interference > 0.0) * exponent * coefficient * width * compressed ** (exponent - 1.0)
    energy = power_law_energy(interference, coefficient * width, exponent)
    return SlicedContact(
        force=slice_forces.sum(axis=-1),
        moment=(slice_forces * positions).sum(axis=-1),
        force_approach=slice_stiffness.sum(axis=-1),
        force_tilt=(slice_stiffness * positions).sum(axis=-1),
        moment_tilt=(slice_stiffness * positions**2).sum(axis=-1),
        energy=energy.sum(axis=-1),
        slice_forces=slice_forces,
    )


@register_jitable
def contact_modulus(youngs_1, poisson_1, youngs_2, poisson_2):
    r"""Contact modulus :math:`E^* = [(1-\nu_1^2)/E_1 + (1-\nu_2^2)/E_2]^{-1}` [Pa] of two bodies in contact.

    The name and symbol are K. L. Johnson's (*Contact Mechanics*, 1985, eq. 4.22), the modulus of Hertz's dry
    contact; the EHL theory's reduced modulus is twice it (:func:`reduced_modulus`).

    Palmgren's law is a fit for steel on steel. For other pairs (a bronze cage on a steel roller) we scale
    its stiffness by :math:`E^*/E^*_{steel}`: to first order the line-contact approach is inversely
    proportional to :math:`E^*` (Johnson, §5.6), an approximation documented where it is used.
    """
    return 1.0 / ((1.0 - poisson_1**2) / youngs_1 + (1.0 - poisson_2**2) / youngs_2)


@register_jitable
def reduced_modulus(youngs_1, poisson_1, youngs_2, poisson_2):
    r"""Reduced modulus :math:`E' = 2E^* = 2/[(1-\nu_1^2)/E_1 + (1-\nu_2^2)/E_2]` [Pa] of two bodies in contact.

    The name and symbol of elastohydrodynamic lubrication (D. Dowson, G. R. Higginson, *Elasto-hydrodynamic
    Lubrication*, 1966; B. J. Hamrock, *Fundamentals of Fluid Film Lubrication*, 1994, where E′ is called the
    effective elastic modulus): the film formulas' groups U, G, W and Hertz's half-width as written with E′ (the
    ball–groove contact of :mod:`bearing_mbs.contact.point_contact` too). Twice :func:`contact_modulus`; the
    doubling is exact in binary floating point.
    """
    return 2.0 * contact_modulus(youngs_1, poisson_1, youngs_2, poisson_2)


#: Young's modulus [Pa] of bearing steel (100Cr6), the material of Palmgren's fit.
STEEL_YOUNGS_MODULUS = 208e9
#: Poisson's ratio [-] of bearing steel.
STEEL_POISSON_RATIO = 0.3
#: :math:`E^*` [Pa] of bearing steel on bearing steel, the reference of Palmgren's fit.
STEEL_CONTACT_MODULUS = contact_modulus(STEEL_YOUNGS_MODULUS, STEEL_POISSON_RATIO, STEEL_YOUNGS_MODULUS,
                                        STEEL_POISSON_RATIO)
