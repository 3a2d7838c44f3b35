r"""Tangential friction laws and the rolling-resistance moment.

Each friction law returns the **regularised sign** :math:`\varphi(v) \in [-1, 1]` of the slip speed
:math:`v` [m/s] (the tangential relative speed of the contact points, body b minus body a); the friction
force on body b is :math:`F_T = -\mu F_N \varphi(v)`. Like :mod:`.normal`, the functions use ufuncs only, so
the numpy twin and the compiled kernel share this source.

``v_reg`` (``regularisation_speed`` [m/s]) sets where each law saturates. Their slopes at zero slip,
:math:`\varphi'(0)\,v_{reg}` in :data:`ZERO_SLIP_SLOPE`, differ; the slope matters because
:math:`\mu F_N \varphi'(0)` is a viscous coefficient that limits explicit time steps
(:math:`h \lesssim 2 m v_{reg}/(\mu Q)`, docs/numerics.md).

References
----------
* Primary document (the 2019 UPV/EHU thesis, docs/bearing.md), annex II: :math:`F_R = \mu F_N\,\mathrm{erf}(2v/\Delta v)`, and
  the dead-zone rule :math:`F_R = \mu F_N\,\mathrm{sign}(v)` for :math:`|v| \ge \Delta v`, else 0 (eq. 23).
* Exudyn ``ObjectContactSphereSphere``: friction proportional to slip up to ``frictionProportionalZone``,
  then Coulomb (our ``linear`` law).
* ``ehl``: lubricated traction, a function of slide-to-roll ratio, pressure and film
  (:mod:`bearing_mbs.contact.traction`); its regularised sign here is the erf of its boundary part.
* E. Pennestrì, V. Rossi, P. Salvini, P. P. Valentini, "Review and comparison of dry friction force
  models", Nonlinear Dyn. 83 (2016) 1785–1801 (tanh and saturated-linear regularisations).
"""

from __future__ import annotations

import math

import numba
import numpy as np
from numba.extending import register_jitable

#: Friction-law names in the order of their integer codes in the compiled kernel.
FRICTION_LAWS = ("none", "erf", "tanh", "linear", "dead_zone", "ehl")


@numba.vectorize(["float64(float64)"], cache=True)
def erf(x):
    """Error function as a ufunc usable both from NumPy and inside numba-compiled code."""
    return math.erf(x)


@register_jitable
def no_friction(slip, regularisation_speed):
    """Frictionless contact: φ = 0."""
    return 0.0 * slip


@register_jitable
def erf_sign(slip, regularisation_speed):
    r"""The annex's form :math:`\varphi = \mathrm{erf}(2v/v_{reg})`; :math:`\varphi(v_{reg}) = 0.995`."""
    return erf(2.0 * slip / regularisation_speed)


@register_jitable
def tanh_sign(slip, regularisation_speed):
    r""":math:`\varphi = \tanh(2v/v_{reg})`; :math:`\varphi(v_{reg}) = 0.964`."""
    return np.tanh(2.0 * slip / regularisation_speed)


@register_jitable
def linear_sign(slip, regularisation_speed):
    r"""Saturated linear :math:`\varphi = \mathrm{clip}(v/v_{reg}, -1, 1)`, as in Exudyn's sphere contact."""
    return np.minimum(np.maximum(slip / regularisation_speed, -1.0), 1.0)


@register_jitable
def dead_zone_sign(slip, regularisation_speed):
    r"""The primary document's rule: :math:`\varphi = \mathrm{sign}(v)` for :math:`|v| \ge \Delta v`, else 0.

    Kept for fidelity to the document (case 3 and 4 scripts); it is discontinuous, so no integrator
    converges at its nominal order with it.
    """
    return np.sign(slip) * (np.abs(slip) >= regularisation_speed)


@register_jitable
def erf_sign_slope(slip, regularisation_speed):
    r""":math:`\varphi'(v) = (4/\sqrt\pi)\,e^{-(2v/v_{reg})^2}/v_{reg}` [s/m] of :func:`erf_sign`."""
    return 4.0 / math.sqrt(math.pi) * np.exp(-((2.0 * slip / regularisation_speed) ** 2)) / regularisation_speed


@register_jitable
def tanh_sign_slope(slip, regularisation_speed):
    r""":math:`\varphi'(v) = 2(1 - \tanh^2(2v/v_{reg}))/v_{reg}` [s/m] of :func:`tanh_sign`."""
    return 2.0 * (1.0 - np.tanh(2.0 * slip / regularisation_speed) ** 2) / regularisation_speed


@register_jitable
def linear_sign_slope(slip, regularisation_speed):
    r""":math:`\varphi'(v) = 1/v_{reg}` inside the saturation, 0 beyond [s/m], of :func:`linear_sign`."""
    return (np.abs(slip) < regularisation_speed) / regularisation_speed


#: Law name → regularised sign function φ(v, v_reg).
FRICTION_SIGN = {
    "none": no_friction,
    "erf": erf_sign,
    "tanh": tanh_sign,
    "linear": linear_sign,
    "dead_zone": dead_zone_sign,
    "ehl": erf_sign,  # its boundary part and its rolling-resistance spin sign; the traction is in .traction
}

#: Law name → :math:`\varphi'(0)\,v_{reg}` (dimensionless slope at zero slip); the dead zone is flat there.
ZERO_SLIP_SLOPE = {
    "none": 0.0,
    "erf": 4.0 / math.sqrt(math.pi),
    "tanh": 2.0,
    "linear": 1.0,
    "dead_zone": 0.0,
    "ehl": 4.0 / math.sqrt(math.pi),  # the boundary part; the film part's slope is the traction's (.traction)
}


@register_jitable
def friction_force(normal_force, friction_coefficient, sign):
    r"""Friction force on body b [N], along the tangent :math:`t`: :math:`F_T = -\mu F_N \varphi`."""
    return -friction_coefficient * normal_force * sign


@register_jitable
def rolling_resistance_moment(normal_force, arm, spin_sign):
    r"""Rolling-resistance moment on body b [N m]: :math:`M_R = -\mu_R F_N \varphi(\omega_{rel} r_b)`.

    The normal force is offset by the arm :math:`\mu_R` [m] ahead of the contact (document task 3), so it
    opposes the relative spin :math:`\omega_{rel} = \omega_b - \omega_a`; body a receives :math:`-M_R`.
    ``spin_sign`` is the pair's friction law applied to the rim speed :math:`\omega_{rel} r_b`, which
    regularises the document's unregularised :math:`\mathrm{sign}(\dot\theta)`.
    """
    return -arm * normal_force * spin_sign
