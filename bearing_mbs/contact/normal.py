r"""Normal contact force laws.

Every law is a pure function of the **gap** :math:`g` [m] (positive = clearance, negative = penetration,
:math:`\delta = \max(-g, 0)`), the **gap rate** :math:`\dot g` [m/s] (negative = approaching) and law
parameters. The functions use NumPy ufuncs only, so one source serves two backends:

* the readable numpy twin calls them on arrays (one entry per contact pair);
* the compiled kernel calls them on scalars inside its pair loop (``numba.extending.register_jitable``
  compiles them inline there and leaves them plain Python functions everywhere else).

Hysteresis-damping family
-------------------------
Lankarani–Nikravesh, Hunt–Crossley, Flores and Gonthier share the form

.. math:: F_N = K \delta^n \left(1 + d \, \frac{\dot\delta}{\dot\delta^-}\right), \qquad \dot\delta = -\dot g,

and differ only in the dimensionless damping factor :math:`d(e)` that maps the user's coefficient of
restitution :math:`e` to damping (see :data:`DAMPING_FACTOR`). :math:`\dot\delta^-` is the approach speed
*latched at contact onset*, per pair (the primary document's ``vmin``), so every pair carries state; the
engines update it once per accepted step with :func:`latch_approach_speed`, never inside Runge–Kutta
stages. The force is clamped at zero: the laws model no adhesion.

Approach-speed floor
--------------------
For persistent contacts (a roller entering the load zone) the approach speed at onset can be arbitrarily
small and the damping term :math:`d K\delta^n\dot\delta/\dot\delta^-` arbitrarily stiff. The latched speed
is therefore floored: :math:`\dot\delta^- \ge v_{floor}` (``approach_speed_floor``, default 1 mm/s in
:class:`bearing_mbs.spec.ContactSpec`). Below the floor a law behaves as a viscoelastic contact with
damping coefficient :math:`c = d K \delta^n / v_{floor}`. Impacts faster than the floor are unaffected.

Energy and restitution
----------------------
With :math:`\dot\delta^-` equal to the impact speed :math:`v_0` and :math:`\chi = d`, integrating
:math:`m\dot\delta\,d\dot\delta/d\delta = -K\delta^n(1+\chi\dot\delta/v_0)` over compression and
restitution gives the effective restitution :math:`e^*` implicitly, independent of :math:`K`, :math:`n`
and the mass: :math:`\chi(1+e^*) = \ln[(1+\chi)/(1-\chi e^*)]`. The tests derive their expectations from
this relation; the package itself never uses it.

References
----------
* H. M. Lankarani, P. E. Nikravesh, "A contact force model with hysteresis damping for impact analysis
  of multibody systems", J. Mech. Des. 112 (1990) 369–376.
* K. H. Hunt, F. R. E. Crossley, "Coefficient of restitution interpreted as damping in vibroimpact",
  J. Appl. Mech. 42 (1975) 440–445 (factor 3(1−e)/2 as commonly stated, e.g. Marhefka & Orin 1999).
* P. Flores, M. Machado, M. T. Silva, J. M. Martins, "On the continuous contact force models for soft
  materials in multibody dynamics", Multibody Syst. Dyn. 25 (2011) 357–375 (factor 8(1−e)/(5e)).
* Y. Gonthier, J. McPhee, C. Lange, J.-C. Piedbœuf, "A regularized contact model with asymmetric damping
  and dwell-time dependent friction", Multibody Syst. Dyn. 11 (2004) 209–233 (factor (1−e²)/e).
"""

from __future__ import annotations

import numpy as np
from numba.extending import register_jitable

#: Normal-law names accepted in scenario files, in the order of the documentation.
NORMAL_LAWS = ("power", "lankarani_nikravesh", "hunt_crossley", "flores", "gonthier")


@register_jitable
def penetration(gap):
    r"""Penetration :math:`\delta = \max(-g, 0)` [m]."""
    return np.maximum(-gap, 0.0)


@register_jitable
def hysteresis_force(gap, gap_rate, stiffness, exponent, damping_factor, approach_speed):
    r"""Normal force of the hysteresis-damping family [N].

    .. math:: F_N = \max\left(0,\; K\delta^n\left(1 - d\,\dot g/\dot\delta^-\right)\right)

    the elastic force (:func:`elastic_force`) times the hysteresis factor (:func:`hysteresis_factor`).

    Parameters
    ----------
    gap, gap_rate : gap [m] and its rate [m/s]; contact where ``gap < 0``.
    stiffness : K [N/m^n], > 0.
    exponent : n [-], e.g. 1.5 (Hertz point contact), 10/9 (Palmgren line contact).
    damping_factor : d [-], from :data:`DAMPING_FACTOR`; 0 gives the plain power law.
    approach_speed : reference approach speed [m/s], > 0, from :func:`reference_approach_speed`.
    """
    return np.maximum(
        elastic_force(gap, stiffness, exponent) * hysteresis_factor(gap_rate, damping_factor, approach_speed), 0.0
    )


@register_jitable
def hysteresis_factor(gap_rate, damping_factor, approach_speed):
    r"""The factor :math:`1 + d\,\dot\delta/\dot\delta^- = 1 - d\,\dot g/\dot\delta^-` multiplying :math:`K\delta^n`."""
    return 1.0 - damping_factor * gap_rate / approach_speed


@register_jitable
def hysteresis_force_slopes(gap, gap_rate, stiffness, exponent, damping_factor, latched, floor):
    r"""(∂F_N/∂g, ∂F_N/∂ġ) of :func:`hysteresis_force` at a penetrating gap (g < 0), with the pair's latched
    approach speed held (:func:`reference_approach_speed`): :math:`-nK\delta^{n-1}(1 - d\dot g/\dot\delta^-)` and
    :math:`-K\delta^n d/\dot\delta^-`; the second is 0 while the approach is not latched and faster than the floor
    (then :math:`\dot\delta^- = -\dot g` and the factor is 1 + d). Both 0 where the force is 0."""
    approach = reference_approach_speed(latched, gap_rate, floor)
    factor = hysteresis_factor(gap_rate, damping_factor, approach)
    depth = penetration(gap)
    if depth <= 0.0 or factor <= 0.0:
        return 0.0, 0.0
    elastic = stiffness * depth**exponent
    rate_slope = 0.0 if (latched <= 0.0 and -gap_rate > floor) else -elastic * damping_factor / approach
    return -exponent * stiffness * depth ** (exponent - 1.0) * factor, rate_slope


@register_jitable
def elastic_force(gap, stiffness, exponent):
    r"""Conservative part :math:`K\delta^n` [N] (the power law :math:`F = K\delta^n`)."""
    return stiffness * penetration(gap) ** exponent


@register_jitable
def elastic_energy(gap, stiffness, exponent):
    r"""Potential energy :math:`K\delta^{n+1}/(n+1)` [J] stored by the conservative part."""
    return stiffness * penetration(gap) ** (exponent + 1.0) / (exponent + 1.0)


@register_jitable
def reference_approach_speed(latched, gap_rate, floor):
    r"""Approach speed used by the damping term [m/s].

    The latched value if the pair has one (``latched > 0``); otherwise, before the engine latches it at the
    end of the first penetrating step, the current approach speed :math:`-\dot g`. Both are floored at
    ``floor``.
    """
    return latched + (latched <= 0.0) * np.maximum(-gap_rate, floor)


@register_jitable
def latch_approach_speed(gap, gap_rate, latched, floor):
    """Per-pair state after an accepted step [m/s]: latched at onset, kept while in contact, 0 when apart."""
    return (gap < 0.0) * reference_approach_speed(latched, gap_rate, floor)


@register_jitable
def damping_factor_power(restitution):
    """Plain power law K δⁿ: no damping, whatever the restitution."""
    return 0.0 * restitution


@register_jitable
def damping_factor_lankarani_nikravesh(restitution):
    r"""Lankarani–Nikravesh (1990): :math:`d = 3(1-e^2)/4`."""
    return 0.75 * (1.0 - restitution**2)


@register_jitable
def damping_factor_hunt_crossley(restitution):
    r"""Hunt–Crossley (1975): :math:`d = 3(1-e)/2`."""
    return 1.5 * (1.0 - restitution)


@register_jitable
def damping_factor_flores(restitution):
    r"""Flores et al. (2011): :math:`d = 8(1-e)/(5e)`."""
    return 8.0 * (1.0 - restitution) / (5.0 * restitution)


@register_jitable
def damping_factor_gonthier(restitution):
    r"""Gonthier et al. (2004): :math:`d = (1-e^2)/e`."""
    return (1.0 - restitution**2) / restitution


#: Law name → function of the restitution coefficient e ∈ (0, 1] returning the damping factor d.
DAMPING_FACTOR = {
    "power": damping_factor_power,
    "lankarani_nikravesh": damping_factor_lankarani_nikravesh,
    "hunt_crossley": damping_factor_hunt_crossley,
    "flores": damping_factor_flores,
    "gonthier": damping_factor_gonthier,
}
