"""The rigid, isoviscous film between a cylinder and a plane (bearing_mbs/fluid_film/cylinder_plane.py).

References, none from the code under test:

* H. M. Martin (Engineering 102, 1916, 119-121): a rolling cylinder's film with the Reynolds outlet condition
  carries W = 4.896 eta u R l / h0 (the value quoted by B. J. Hamrock, S. R. Schmid, B. O. Jacobson, Fundamentals
  of Fluid Film Lubrication, 2nd ed., 2004, ch. 8, as 2.45 eta (u_a + u_b) R / h0 per unit length); to 1e-3;
* an independent numerical solution of Reynolds' equation, d/dx(h^3 p') = 12 eta (u h' + dh0/dt), by finite
  volumes over +-10^4 (2 R h0)^1/2, its outlet (p = p' = 0, Swift-Stieber) found as the farthest one whose film has
  no negative pressure (searched, not assumed): load and Couette integral to 1e-4, Poiseuille shear to 2e-3 (its
  grid error: 5e-4, halving when the nodes double);
* pure approach without cavitation, the exact pressure p = -6 eta (dh0/dt) R / h^2 integrated by quadrature.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.integrate import quad
from scipy.linalg import solve_banded

from bearing_mbs.fluid_film.cylinder_plane import film_forces

VISCOSITY, RADIUS, LENGTH, GAP = 0.1, 0.0125, 0.0275, 1e-5
SPAN = math.sqrt(2 * RADIUS * GAP)


def reynolds(entrainment, gap_rate, nodes=20001, reach=1e-4):
    """(load, Poiseuille shear sum int h p' dx, int dx/h) per unit length of the film, by finite volumes on the
    nodes x = (2 R h0)^1/2 tan(phi), phi uniform to within ``reach`` of +-pi/2 (x to +-10^4 spans, so that the
    slowly decaying tails of h p' and 1/h are inside). The inlet is upstream of the entrainment: a negative one is
    the mirror image."""
    if entrainment < 0:
        load, shear, inverse_gap = reynolds(-entrainment, gap_rate, nodes, reach)
        return load, -shear, inverse_gap
    x = SPAN * np.tan(np.linspace(-np.pi / 2 + reach, np.pi / 2 - reach, nodes))
    h = GAP + x**2 / (2 * RADIUS)
    width = np.diff(x)
    conductance = (0.5 * (h[1:] + h[:-1])) ** 3 / width  # h^3 / dx at the cell faces
    volume = np.zeros(nodes)
    volume[1:-1] = 0.5 * (x[2:] - x[:-2])
    right = 12 * VISCOSITY * (entrainment * x / RADIUS + gap_rate) * volume

    def pressure_to(outlet):
        """The film pressurised from the inlet to node ``outlet`` (p = 0 there and at the inlet)."""
        pressure = np.zeros(nodes)
        inner = np.arange(1, outlet)
        if inner.size:
            bands = np.zeros((3, inner.size))
            bands[1] = -(conductance[inner - 1] + conductance[inner])
            bands[0, 1:] = conductance[inner[:-1]]
            bands[2, :-1] = conductance[inner[1:] - 1]
            pressure[inner] = solve_banded((1, 1), bands, right[inner])
        return pressure

    # Swift-Stieber: the outlet is the farthest one whose film has no negative pressure (nearer ones leave the
    # film with a pressure gradient at its end, farther ones with p < 0); found by bisection on the node
    def positive(pressure):
        return pressure.min() >= -1e-12 * np.abs(pressure).max()

    lowest, highest = 1, nodes - 1
    if positive(pressure_to(highest)):
        lowest = highest
    while highest - lowest > 1:
        middle = (lowest + highest) // 2
        lowest, highest = (middle, highest) if positive(pressure_to(middle)) else (lowest, middle)
    pressure = np.maximum(pressure_to(lowest), 0.0)
    load = np.trapezoid(pressure, x)
    shear = np.sum(0.5 * (h[1:] + h[:-1]) * np.diff(pressure))  # int h dp
    return load, shear, np.trapezoid(1 / h, x)


@pytest.mark.parametrize("entrainment, gap_rate", [
    (1.0, 0.0),        # Martin's rolling film
    (1.0, -1e-3),      # a roller closing on the plane while it spins: the outlet moves downstream
    (1.0, -1e-2),
    (1.0, 1e-3),       # and opening
    (1.0, 5e-3),
    (0.3, -3e-2),      # squeeze-dominated
    (-1.0, -1e-3),     # the mirror image: the same load
])
def test_the_film_matches_a_numerical_reynolds_solution(entrainment, gap_rate):
    load, shear, inverse_gap = reynolds(entrainment, gap_rate)
    w, couette, poiseuille = film_forces(VISCOSITY, entrainment, 0.7, gap_rate, RADIUS, LENGTH, np.inf, GAP)
    assert w == pytest.approx(load * LENGTH, rel=1e-4)
    assert poiseuille == pytest.approx(shear * LENGTH, rel=2e-3)
    assert couette == pytest.approx(-VISCOSITY * 0.7 * LENGTH * inverse_gap, rel=1e-4)  # over the flooded gap


def test_the_couette_shear_of_a_bounded_plane():
    """Over a plane of half-width X the Couette force is -eta du l int_-X^X dx/h (quadrature, 1e-10)."""
    width = 2e-3
    exact = quad(lambda x: 1 / (GAP + x**2 / (2 * RADIUS)), -width, width, epsabs=0, epsrel=1e-13)[0]
    couette = film_forces(VISCOSITY, 1.0, 0.7, 0.0, RADIUS, LENGTH, width, GAP)[1]
    assert couette == pytest.approx(-VISCOSITY * 0.7 * LENGTH * exact, rel=1e-10)


def test_martins_rolling_film():
    w, _, _ = film_forces(VISCOSITY, 2.0, 0.0, 0.0, RADIUS, LENGTH, np.inf, GAP)
    assert w / (VISCOSITY * 2.0 * RADIUS * LENGTH / GAP) == pytest.approx(4.896, rel=1e-3)


def test_pure_approach_carries_the_uncavitated_squeeze_load():
    rate = -2e-3
    exact = quad(lambda x: -6 * VISCOSITY * rate * RADIUS / (GAP + x**2 / (2 * RADIUS))**2, -np.inf, np.inf)[0]
    w, couette, poiseuille = film_forces(VISCOSITY, 0.0, 0.0, rate, RADIUS, LENGTH, np.inf, GAP)
    assert w == pytest.approx(exact * LENGTH, rel=1e-9)
    assert couette == 0.0 and poiseuille == 0.0


def test_pure_separation_carries_nothing():
    assert film_forces(VISCOSITY, 0.0, 0.0, 1e-3, RADIUS, LENGTH, np.inf, GAP)[0] == 0.0


def test_the_arrays_give_the_scalars():
    """The numpy twin calls the same function on arrays."""
    rates = np.array([-1e-2, 0.0, 2e-3])
    arrays = film_forces(VISCOSITY, np.full(3, 1.5), np.full(3, 0.2), rates, RADIUS, LENGTH, 2e-3, np.full(3, GAP))
    for i, rate in enumerate(rates):
        scalars = film_forces(VISCOSITY, 1.5, 0.2, rate, RADIUS, LENGTH, 2e-3, GAP)
        assert [a[i] for a in arrays] == pytest.approx(scalars, rel=1e-14)
