r"""The rigid, isoviscous oil film between a cylinder and a plane: wedge and squeeze together.

A cylinder of radius R [m] and length l [m] at the gap :math:`h_0` [m] from a plane sees the film
:math:`h = h_0 + x^2/2R` (:math:`h_0 \ll R`). Its surfaces move along the plane at the mean (entrainment) speed
u [m/s] relative to the gap's narrowest point, and the gap closes at :math:`\dot h_0` [m/s]. Reynolds' equation,
:math:`\mathrm d/\mathrm dx\,(h^3 p') = 12\eta(u\,\mathrm dh/\mathrm dx + \dot h_0)`, with the oil's viscosity η
[Pa s] and Reynolds' outlet condition (:math:`p = p' = 0` where the film cavitates, at :math:`x_c`; ambient pressure
far upstream) integrates once to

.. math:: \frac{h^3 p'}{12\eta} = u\,(h - h_c) + \dot h_0\,(x - x_c).

With :math:`x = a\xi`, :math:`a = (2Rh_0)^{1/2}`, :math:`\xi = \tan\varphi`, every integral of the pressure is
elementary in φ; the outlet :math:`\varphi_c` is the root of :math:`p(x_c) = 0`, which depends only on the
direction :math:`\chi = \mathrm{atan2}(\dot h_0 a/h_0,\,|u|)` of the motion (:data:`OUTLET`, tabulated once by
bisection, refined by Newton's method where it is used). The film's load on the cylinder, its Poiseuille
(pressure-flow) shear summed over both surfaces :math:`f_P = \int h p'\,\mathrm dx`, and the limits our
integration reproduces:

* pure rolling (:math:`\dot h_0 = 0`): :math:`\xi_c = 0.4751`, :math:`W = 4.895\,\eta u R l/h_0`,
  :math:`f_P = 12 \times 0.5422\,\eta u l\,(2R/h_0)^{1/2}` (H. M. Martin, "Lubrication of gear teeth",
  Engineering 102 (1916) 119–121);
* pure approach (:math:`u = 0`, :math:`\dot h_0 < 0`): no cavitation, :math:`p = -6\eta\dot h_0 R/h^2` and
  :math:`W = 3\sqrt2\,\pi\,\eta\,l\,(R/h_0)^{3/2}(-\dot h_0)`;
* pure separation: the pressure would be negative everywhere; the film cavitates and carries nothing.

Together (a roller spinning in a pocket while it strikes the bar) the outlet moves: downstream as the gap closes
(the pressure zone grows), upstream as it opens. Superposing the two limits instead errs by 25 % at
:math:`\dot h_0 = -0.01u` and 60 % at :math:`+0.01u` for :math:`h_0 = 10` µm, R = 12.5 mm, which is why the
outlet is solved.

The sliding speed Δu [m/s] between the surfaces shears the film too (Couette): over a flooded plane of half-width X
[m] the force on the moving surface is :math:`-\eta\,\Delta u\,l\int_{-X}^{X}\mathrm dx/h =
-2\eta\,\Delta u\,l\,(a/h_0)\arctan(X/a)`, :math:`-\pi\eta\,\Delta u\,l\,(2R/h_0)^{1/2}` on an unbounded one.
Flooded is an upper bound: a pocket in an oil–air mixture is partly starved, and past the outlet the film runs in
streamers. The pressure integrals are taken over the unbounded plane: their integrands fall off within a few a of
the narrowest point, and where a approaches X the film is thick and its load small.

Functions are ``register_jitable`` (compiled inline by the contact-pair kernel, plain Python elsewhere) and take
scalars or arrays. Units SI.
"""

from __future__ import annotations

import numpy as np
from numba import types
from numba.extending import overload, register_jitable

_HALF_PI = 0.5 * np.pi


@register_jitable
def _integrals(phi, s, c):
    r"""The pressure integrals from −∞ to :math:`\xi = \tan\varphi`: :math:`J_k = \int\xi^k/(1+\xi^2)^3`
    (k = 0…3) and :math:`K_k = \int\xi^k/(1+\xi^2)^2` (k = 0…2), with s = sin φ and c = cos φ, which every caller
    also needs: the double angles come from them (:math:`\sin2\varphi = 2sc`, :math:`\sin4\varphi =
    2\sin2\varphi\,(c^2 - s^2)`, within a few units of rounding of the sines'), two sines fewer in each of the
    outlet's Newton steps, which are most of a film's cost."""
    double = 2.0 * s * c  # sin 2φ
    quadruple = 2.0 * double * (c * c - s * s)  # sin 4φ
    j0 = 3.0 * phi / 8.0 + double / 4.0 + quadruple / 32.0 + 3.0 * np.pi / 16.0
    j1 = -c**4 / 4.0
    j2 = phi / 8.0 - quadruple / 32.0 + np.pi / 16.0
    j3 = (s**4 - 1.0) / 4.0
    k0 = phi / 2.0 + double / 4.0 + np.pi / 4.0
    k1 = -c * c / 2.0
    k2 = phi / 2.0 - double / 4.0 + np.pi / 4.0
    return j0, j1, j2, j3, k0, k1, k2


def _outlet_condition(phi, chi):
    r""":math:`p(x_c)\cos^2\varphi_c` up to a positive factor: positive upstream of the outlet, negative past it."""
    s, c = np.sin(phi), np.cos(phi)
    j0, j1, j2, _, _, _, _ = _integrals(phi, s, c)
    return np.cos(chi) * (j2 * c * c - s * s * j0) + np.sin(chi) * (j1 * c * c - s * c * j0)


def _outlet_table(points: int = 2049, halvings: int = 60) -> tuple[np.ndarray, np.ndarray]:
    """φ_c on a grid of χ in [−π/2, π/2], by bisection (φ_c = −π/2: no pressure zone; π/2: no cavitation)."""
    chi = np.linspace(-_HALF_PI, _HALF_PI, points)
    low, high = np.full(points, -_HALF_PI), np.full(points, _HALF_PI)
    for _ in range(halvings):
        middle = 0.5 * (low + high)
        upstream = _outlet_condition(middle, chi) > 0.0
        low, high = np.where(upstream, middle, low), np.where(upstream, high, middle)
    outlet = 0.5 * (low + high)
    outlet[0] = _HALF_PI  # pure approach: the condition is 0 only at φ = π/2
    return chi, outlet


#: (χ grid, φ_c) [rad]: the outlet against the direction of the motion.
DIRECTION, OUTLET = _outlet_table()


def _tabulated_outlet(chi):
    """φ_c [rad] of the table at the direction χ, interpolated linearly (``np.interp``); scalars or arrays."""
    return np.interp(chi, DIRECTION, OUTLET)


@overload(_tabulated_outlet)
def _tabulated_outlet_compiled(chi):
    """Compiled :func:`_tabulated_outlet`: for a scalar χ, the table's segment from its uniform spacing, then
    ``np.interp``'s own choice of segment and arithmetic, so the value is ``np.interp``'s; numba's ``np.interp`` of a
    scalar (a bisection and an output array) costs as much as the outlet's four Newton steps."""
    if not isinstance(chi, types.Float):
        return lambda chi: np.interp(chi, DIRECTION, OUTLET)
    first, spacing, last = DIRECTION[0], DIRECTION[1] - DIRECTION[0], DIRECTION.size - 1

    def lookup(chi):
        if np.isnan(chi):
            return chi
        if chi >= DIRECTION[last]:
            return OUTLET[last]
        if chi < first:
            return OUTLET[0]
        j = min(int((chi - first) / spacing), last - 1)
        while chi < DIRECTION[j]:  # np.interp's segment: DIRECTION[j] <= χ < DIRECTION[j + 1]
            j -= 1
        while chi >= DIRECTION[j + 1]:
            j += 1
        if chi == DIRECTION[j]:
            return OUTLET[j]
        slope = (OUTLET[j + 1] - OUTLET[j]) / (DIRECTION[j + 1] - DIRECTION[j])
        return slope * (chi - DIRECTION[j]) + OUTLET[j]

    return lookup


@register_jitable
def _outlet_terms(phi, chi):
    """(C, C_φ, C_χ) of the outlet condition at (φ, χ); scalars or arrays."""
    s, c = np.sin(phi), np.cos(phi)
    j0, j1, j2, _, _, _, _ = _integrals(phi, s, c)
    along, across = np.cos(chi), np.sin(chi)
    first, second = j2 * c * c - s * s * j0, j1 * c * c - s * c * j0
    by_phi = -2.0 * s * c * (j2 + j0) * along - (2.0 * s * c * j1 + (c * c - s * s) * j0) * across
    return along * first + across * second, by_phi, -across * first + along * second


@register_jitable
def _outlet_angle(chi):
    """φ_c at χ: the table's value refined by four Newton steps on the outlet condition (to rounding; scalars or
    arrays); at the table's ends, where the condition's slope vanishes (no pressure zone) or φ_c = π/2 (no
    cavitation), the table's value stands."""
    phi = _tabulated_outlet(chi)
    for _ in range(4):
        condition, by_phi, _ = _outlet_terms(phi, chi)
        usable = (np.abs(np.cos(phi)) > 1e-6) * (np.abs(by_phi) > 1e-300)
        phi = phi - usable * condition / (by_phi + (1 - usable))
    return phi


@register_jitable
def outlet(chi):
    r"""(φ_c [rad], dφ_c/dχ) at the direction χ (scalar): :func:`_outlet_angle` and, by implicit differentiation
    of the outlet condition C(φ, χ) = cos χ (J₂c² − s²J₀) + sin χ (J₁c² − scJ₀) = 0, −C_χ/C_φ with
    :math:`C_\varphi = -2sc(J_2 + J_0)\cos\chi - (2scJ_1 + (c^2 - s^2)J_0)\sin\chi`; 0 at the table's ends."""
    phi = _outlet_angle(chi)
    _, by_phi, by_chi = _outlet_terms(phi, chi)
    if abs(np.cos(phi)) <= 1e-6 or abs(by_phi) <= 1e-300:
        return phi, 0.0
    return phi, -by_chi / by_phi


@register_jitable
def film_forces(viscosity, entrainment, sliding, gap_rate, radius, length, half_width, gap):
    r"""(load W [N] pushing the cylinder off the plane, Couette force [N] on the cylinder along the sliding,
    Poiseuille shear :math:`f_P` [N], signed as u) of the film at gap :math:`h_0` > 0 [m], entrainment speed u
    [m/s], sliding speed Δu [m/s] of the cylinder's surface over the plane's (of half-width X [m], ``np.inf`` for
    an unbounded one) and closing rate :math:`\dot h_0` [m/s]. :math:`f_P` resists the entrainment: with the load,
    it dissipates :math:`u f_P - \dot h_0 W = \int h^3 p'^2/12\eta\,\mathrm dx \ge 0` (by parts, with
    :math:`p(x_c) = 0`)."""
    span = np.sqrt(2.0 * radius * gap)
    squeeze = gap_rate * span / gap
    speed = np.sqrt(entrainment * entrainment + squeeze * squeeze)
    chi = np.arctan2(squeeze, np.abs(entrainment))
    phi = _outlet_angle(chi)
    s, c = np.sin(phi), np.cos(phi)
    j0, j1, j2, j3, k0, k1, k2 = _integrals(phi, s, c)
    along, across = np.cos(chi), np.sin(chi)
    load = -24.0 * viscosity * radius * length / gap * speed * (
        along * (j3 + s * s * c * c / 4.0) + across * (j2 + s * c**3 / 4.0))
    # the Poiseuille shear, (K2 − ξ_c² K0) and (K1 − ξ_c K0) written over cos² φ_c: 0 where no cavitation (φ_c = π/2)
    cos2 = np.maximum(c * c, 1e-300)
    shear = (along * (k2 * c * c - s * s * k0) + across * (k1 * c * c - s * c * k0)) / cos2
    poiseuille = (c * c > 1e-12) * 12.0 * viscosity * length * span / gap * speed * shear
    couette = -2.0 * viscosity * length * sliding * span / gap * np.arctan(half_width / span)
    return np.maximum(load, 0.0), couette, np.sign(entrainment) * np.maximum(poiseuille, 0.0)


@register_jitable
def film_force_slopes(viscosity, entrainment, sliding, gap_rate, radius, length, half_width, gap):
    r"""Derivatives of :func:`film_forces`: (∂W, ∂F_c, ∂f_P), each a 4-tuple over (h₀, ḣ₀, u, Δu), scalars. With
    :math:`q = \dot h_0 (2R/h_0)^{1/2}` and the outlet φ_c(χ) of the tabulated direction χ (its slope on the
    table's segment), :math:`W = -(24\eta R l/h_0)(|u| A + q B)` with :math:`A = J_3 + s^2c^2/4`,
    :math:`B = J_2 + sc^3/4` (:math:`A' = sc/2`, :math:`B' = c^2/4`), and
    :math:`f_P = \mathrm{sign}(u)\,12\eta l (2R/h_0)^{1/2}(|u|P + qQ)` with :math:`P = K_2 - \xi_c^2K_0`,
    :math:`Q = K_1 - \xi_cK_0` (:math:`P' = -2sK_0/c^3`, :math:`Q' = -K_0/c^2`)."""
    root = np.sqrt(2.0 * radius / gap)  # span/h
    squeeze = gap_rate * root
    magnitude = abs(entrainment)
    speed2 = magnitude * magnitude + squeeze * squeeze
    chi = np.arctan2(squeeze, magnitude)
    phi, outlet_slope = outlet(chi)
    s, c = np.sin(phi), np.cos(phi)
    j0, j1, j2, j3, k0, k1, k2 = _integrals(phi, s, c)
    chi_u = -squeeze / speed2 if speed2 > 0.0 else 0.0
    chi_q = magnitude / speed2 if speed2 > 0.0 else 0.0
    sign = np.sign(entrainment)
    load_scale = 24.0 * viscosity * radius * length / gap
    a_term, b_term = j3 + s * s * c * c / 4.0, j2 + s * c**3 / 4.0
    load = -load_scale * (magnitude * a_term + squeeze * b_term)
    load_slopes = (0.0, 0.0, 0.0, 0.0)  # tuples, not arrays: the Jacobian calls this once per pair
    if load > 0.0:
        along_phi = magnitude * s * c / 2.0 + squeeze * c * c / 4.0
        load_u = -load_scale * (a_term + along_phi * outlet_slope * chi_u)
        load_q = -load_scale * (b_term + along_phi * outlet_slope * chi_q)
        load_slopes = (-load / gap - load_q * squeeze / (2.0 * gap), load_q * root, sign * load_u, 0.0)
    shear_slopes = (0.0, 0.0, 0.0, 0.0)
    if c * c > 1e-12:
        p_term, q_term = k2 - s * s / (c * c) * k0, k1 - s / c * k0
        shear_scale = 12.0 * viscosity * length * root
        shear = shear_scale * (magnitude * p_term + squeeze * q_term)
        if shear > 0.0:
            along_phi = magnitude * (-2.0 * s * k0 / c**3) + squeeze * (-k0 / (c * c))
            shear_u = shear_scale * (p_term + along_phi * outlet_slope * chi_u)
            shear_q = shear_scale * (q_term + along_phi * outlet_slope * chi_q)
            shear_slopes = (sign * (-shear / (2.0 * gap) - shear_q * squeeze / (2.0 * gap)), sign * shear_q * root,
                            shear_u, 0.0)  # ∂/∂u: sign(u)² = 1
    span = root * gap
    angle = np.arctan(half_width / span)
    angle_slope = -1.0 / (span * span / half_width + half_width)  # d angle/d span: 0 on an unbounded plane
    couette_slopes = (-2.0 * viscosity * length * sliding * (-root / (2.0 * gap) * angle
                                                              + root * angle_slope * span / (2.0 * gap)),
                      0.0, 0.0, -2.0 * viscosity * length * root * angle)
    return load_slopes, couette_slopes, shear_slopes
