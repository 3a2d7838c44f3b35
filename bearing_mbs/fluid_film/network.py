r"""Document 001's resistance network for the recess pressures of a capillary-fed multi-recess journal bearing.

Eqs. 11.1–11.2 of document 001 (E. Ucin Gurrutxaga, UPV/EHU 2016), with its printed errata corrected (the sign
of the flow to the next recess, the (1,1) entry and row 4's capillary). Recess i (centred at
:math:`\alpha_i = 2\pi(i-1)/n` from the thinnest film, :math:`h = C(1 - \varepsilon\cos\alpha)`) balances

.. math:: \frac{p_s - p_i}{R_c} = \frac{p_i}{R^{(0)}_i} + \frac{p_i - p_{i-1}}{R_{i-1,i}}
          + \frac{p_i - p_{i+1}}{R_{i,i+1}},

with the axial outflow over both lands of width a (integrated over the whole pitch, which overstates it) and the
circumferential flow across the land of angular width θ between recesses:

.. math:: R^{(0)}_i = \frac{12\,a\,\mu}{D\,C^3\int_{\pi(2i-3)/n}^{\pi(2i-1)/n}(1-\varepsilon\cos\alpha)^3\,d\alpha},
          \qquad R_{i,i+1} = \frac{6\,\mu\,\theta\,D}{(L - 2a)\,C^3\,[1 - \varepsilon\cos(\pi(2i-1)/n)]^3}.

Valid at low speed and with the eccentricity towards recess 1. It is a fast estimate; the Reynolds solver
(:mod:`.reynolds`) is the reference, and docs/fluid-film.md gives the difference.
"""

from __future__ import annotations

import math

import numpy as np
from scipy.integrate import quad

from bearing_mbs.fluid_film.journal import JournalBearing


def network_recess_pressures(bearing: JournalBearing, eccentricity_ratio: float, supply_pressure: float,
                             capillary_resistance: float) -> tuple[np.ndarray, float]:
    """(p_i [Pa] of each recess, total supply flow [m³/s]) from the network, eccentricity towards recess 1."""
    recesses = bearing.recesses
    n, eps = recesses.count, eccentricity_ratio
    land_width = (bearing.length - recesses.axial_length) / 2
    land_angle = 2 * math.pi / n - math.radians(recesses.angular_width)
    mu, diameter, clearance = bearing.viscosity, bearing.diameter, bearing.radial_clearance
    index = np.arange(1, n + 1)
    cubes = [quad(lambda a: (1 - eps * math.cos(a)) ** 3, math.pi * (2 * i - 3) / n, math.pi * (2 * i - 1) / n)[0]
             for i in index]
    axial = 12 * land_width * mu / (diameter * clearance**3 * np.array(cubes))
    across = 6 * mu * land_angle * diameter / (recesses.axial_length * clearance**3
                                               * (1 - eps * np.cos(math.pi * (2 * index - 1) / n)) ** 3)
    matrix = np.diag(1 / capillary_resistance + 1 / axial + 1 / across + 1 / np.roll(across, 1))
    for i in range(n):
        matrix[i, (i + 1) % n] -= 1 / across[i]
        matrix[i, (i - 1) % n] -= 1 / across[(i - 1) % n]
    pressures = np.linalg.solve(matrix, np.full(n, supply_pressure / capillary_resistance))
    return pressures, float(np.sum((supply_pressure - pressures) / capillary_resistance))
