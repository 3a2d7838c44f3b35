"""The film solver's globalised Newton fall-back (bearing_mbs/fluid_film/newton.py): where the active set cycles or
an orifice's Newton loop does not settle, the film is still solved, and solved right.

References, none from the code under test:

* Raimondi and Boyd's full-bearing table (as in tests/test_fluid_film.py, the same tolerances: S within 3 %,
  attitude within 1°), with the fall-back forced on the same grooved bearing, and the active set's own solution
  of the same discrete problem (1e-8: both solve it to round-off);
* conservation of mass (supply = end outflow + growth of the oil in the gap, 1e-8 relative) and the complementarity
  conditions p ≥ 0, ϑ ≤ 1, p (1 − ϑ) = 0 on a bearing whose active set cycles (found by the no-traceback property
  test), and on an orifice-fed one whose Newton loop did not settle;
* Lund's step: the coefficients' tests in tests/test_film_coefficients.py.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from bearing_mbs.fluid_film import closed_forms, reynolds
from bearing_mbs.fluid_film.journal import JournalBearing, Recesses
from bearing_mbs.fluid_film.restrictors import Capillary, Orifice
from bearing_mbs.fluid_film.reynolds import JournalState, Supply, solve_film

D, MU, RHO, CLEARANCE = 0.075, 0.028, 860.0, 35e-6
OMEGA = 1000 * 2 * math.pi / 60
#: (ε, Sommerfeld number S, attitude φ [deg]) of Raimondi and Boyd's full bearing, L/D = 1 (Shigley's reprint).
RAIMONDI_BOYD = [(0.6, 0.121, 50.58), (0.8, 0.0446, 36.24)]


def grooved_bearing(n_theta: int) -> JournalBearing:
    """Raimondi and Boyd's full bearing, L/D = 1, with an ambient axial groove one cell wide at the thickest film."""
    return JournalBearing(D, D, CLEARANCE, MU, RHO, Recesses(1, 360 / n_theta, D, 0.001))


@pytest.mark.parametrize("eps, sommerfeld, attitude", RAIMONDI_BOYD)
def test_the_fall_back_reproduces_raimondi_and_boyd(eps, sommerfeld, attitude, monkeypatch):
    n_theta, state = 180, JournalState((-eps * CLEARANCE, 0.0), speed=OMEGA)
    active_set = solve_film(grooved_bearing(n_theta), state, Supply(0.0), grid=(n_theta, 40), cavitation="jfo")
    monkeypatch.setattr(reynolds, "MAX_ITERATIONS", 0)  # straight to the fall-back
    film = solve_film(grooved_bearing(n_theta), state, Supply(0.0), grid=(n_theta, 40), cavitation="jfo")
    number = closed_forms.sommerfeld_number(film.load_capacity, OMEGA, D / 2, D, CLEARANCE, MU)
    assert number == pytest.approx(sommerfeld, rel=0.03)
    assert film.attitude_angle == pytest.approx(attitude, abs=1.0)
    np.testing.assert_allclose(film.force, active_set.force, rtol=1e-8)


def conserves_and_complements(film) -> None:
    assert film.supply_flow == pytest.approx(film.edge_outflow + film.volume_rate, rel=1e-8)
    assert np.all(film.pressure >= 0) and np.all(film.fill <= 1 + 1e-12)
    assert np.all((film.pressure == 0) | (np.abs(1 - film.fill) <= 1e-12))


def test_a_cycling_active_set_is_solved(monkeypatch):
    """Eleven capillary-fed recesses in a wide clearance, turning slowly (drawn by the property test): the active set
    returns to an earlier set; the fall-back solves the film and conserves its mass."""
    bearing = JournalBearing(2.0, 2.0, 0.01999953948828325, 1e-06, 1.2571280542864416,
                             Recesses(11, 27.467541152585603, 1.4525752442643955, 0.1, 0.0))
    state = JournalState((0.004447406576078068, 1.9999539488284344e-05), speed=0.10471975511965977)
    used = []
    fall_back = reynolds._globalised
    monkeypatch.setattr(reynolds, "_globalised", lambda *args: used.append(1) or fall_back(*args))
    film = solve_film(bearing, state, Supply(1000.0, Capillary(0.15401972043002685, 7.700986021501342e-05)),
                      grid=(37, 9), cavitation="jfo")
    assert used  # it did cycle
    conserves_and_complements(film)


def test_an_orifice_at_its_supply_pressure_is_solved():
    """A wide orifice feeding recesses that sit near the supply pressure (√ of a vanishing drop): the undamped Newton
    loop does not settle; the fall-back conserves mass."""
    bearing = JournalBearing(1.8244897653268675, 0.018244897653268675, 0.013704721558690408, 1.0, RHO,
                             Recesses(10, 30.178938250339367, 0.00729795906130747, 0.1, -360.0))
    state = JournalState((0.88853337657467 * bearing.radial_clearance, 0.0), speed=-1e6 * math.pi / 30)
    film = solve_film(bearing, state, Supply(1000.0, Orifice(0.01, 1.0)), grid=(26, 5), cavitation="jfo")
    conserves_and_complements(film)
