r"""Shear heating of an oil film between isothermal walls: the Couette flow's Nahme reduction of the shear stress.

Plane Couette flow of a film of thickness h [m] between two walls at the same temperature :math:`T_0`, sliding at
the relative speed U [m/s], in an oil whose viscosity falls exponentially with temperature,
:math:`\mu = \mu_0 e^{-\beta (T - T_0)}` (β [1/K] the temperature–viscosity coefficient, k [W/(m K)] the oil's
thermal conductivity, heat carried to the walls by conduction across the film). The stress τ is uniform across the
film; the energy balance :math:`k T'' = -\tau^2/\mu(T)` with :math:`T = T_0` at both walls has the closed-form
solution (H. Nahme, "Beiträge zur hydrodynamischen Theorie der Lagerreibung", Ing.-Arch. 11 (1940) 191–209;
J. Gavis and R. L. Laurence, "Viscous heating in plane and circular flow between moving surfaces", Ind. Eng.
Chem. Fundam. 7 (1968) 232–239; our derivation, checked against a numerical solution of the boundary-value problem in the tests):

.. math:: \frac{\tau}{\tau_{iso}} = \frac{x}{\sinh x},\qquad \sinh\frac{x}{2} = \sqrt{\frac{Na}{8}},\qquad
          Na = \frac{\beta\,\mu_0 U^2}{k},

with :math:`\tau_{iso} = \mu_0 U/h` the isothermal stress and Na the Nahme (Nahme–Griffith) number: 1 − Na/12 for
a cool film, 0.86 at Na = 2, 0.57 at Na = 10, 0.24 at Na = 50. Written with the film's own dissipation
:math:`\tau_{iso} U` instead, :math:`Na = \beta\,\tau_{iso} U h/k`, which is how :mod:`.traction` applies it to a
non-Newtonian (Eyring) film: the heating of the stress the film would carry isothermally, in the form exact for a
Newtonian one.

``register_jitable``: the compiled contact kernel calls it inline; scalars.
"""

from __future__ import annotations

import math

from numba.extending import register_jitable

#: Below this x = 2 asinh(√(Na/8)) the reduction is taken from its series (1 − x²/6, slope −x²/6): the closed form
#: loses digits to cancellation there.
_SERIES_BELOW = 1e-4


@register_jitable
def nahme_reduction(nahme):
    r"""(τ/τ_iso, d ln(τ/τ_iso)/d ln Na) [-] of the Couette film at Nahme number Na >= 0 (module docstring):
    :math:`x/\sinh x` and :math:`\tanh(x/2)\,(1/x - \coth x)`, in (0, 1] and (−1, 0]."""
    if nahme <= 0.0:
        return 1.0, 0.0
    x = 2.0 * math.asinh(math.sqrt(nahme / 8.0))
    if x < _SERIES_BELOW:
        return 1.0 - x * x / 6.0, -x * x / 6.0
    decay = math.exp(-x)
    reduction = 2.0 * x * decay / (1.0 - decay * decay)  # x/sinh x without overflow
    return reduction, math.tanh(0.5 * x) * (1.0 / x - 1.0 / math.tanh(x))
