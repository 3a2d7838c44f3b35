"""Ball–groove contact and geometry of document 002 (slewing bearings).

References:
* the thesis's Table 2: N = trunc(π D_pw/D_w) for D_pw = 0.5 … 2.5 m, D_w = 35 mm: 44, 89, 134, 179, 224 (exact);
* its eqs. 6–10 with Table 1's ratios: G = 1.75 mm, T = 64.75 mm, H = 85.25 mm, H₁ = 42.625 mm,
  H₂ = 32.625 mm (to 1e-12);
* its contact case (eqs. 13–15, E = 200 GPa, ν = 0.3, s = 0.943, D_w = 35 mm, p_max = 4200 MPa): Houpert gives
  Q = 95 191 N and a = 8.298 mm (as printed, to the printed digits), b = 1.304 mm (the thesis prints 1.1304; 1.304
  is what its own formula gives, and what 1.5 Q/(π a b) = 4200 MPa needs);
* the exact Hertz solution: for two equal spheres it is the closed form a = (3QR/(4E*))^{1/3} with R = R₁/2 and
  E* = E/(2(1 − ν²)) and the approach δ = a²/R (Johnson, Contact Mechanics, 1985, eqs. 4.22–4.23), to 1e-9; for the ball in a straight groove,
  the case Houpert's fits describe, Houpert and Hertz agree to 0.5 % on a, b and p_max (measured: +0.40 %,
  −0.04 %, −0.36 %; Houpert's paper states the accuracy of its fits, which this test does not quote);
* the raceway's curvature in the rolling direction at D_pw = 1.5 m, α = 45° moves a and b by under 1.5 %.
"""

from __future__ import annotations

import math

import pytest

from bearing_mbs.contact.line_contact import reduced_modulus
from bearing_mbs.contact.point_contact import (
    ball_groove_curvatures,
    hertz_approach,
    hertz_contact,
    houpert_contact,
    houpert_load_at_pressure,
)
from bearing_mbs.models.slewing_bearing.geometry import RingSection, ball_count, groove_radius

D_W, CONFORMITY, E, NU = 0.035, 0.943, 200e9, 0.3


@pytest.mark.parametrize("pitch, balls", [(0.5, 44), (1.0, 89), (1.5, 134), (2.0, 179), (2.5, 224)])
def test_ball_count_matches_table_2(pitch, balls):
    assert ball_count(pitch, D_W) == balls


def test_ring_section_from_the_design_ratios():
    section = RingSection.from_ratios(D_W)
    expected = (1.75e-3, 0.06475, 0.08525, 0.042625, 0.032625)
    actual = (section.gap, section.width, section.height, section.height_1, section.height_2)
    assert actual == pytest.approx(expected, rel=1e-12)
    assert groove_radius(D_W, CONFORMITY) == pytest.approx(18.558e-3, rel=1e-4)


def test_houpert_reproduces_the_documents_contact_case():
    load = houpert_load_at_pressure(4200e6, D_W, CONFORMITY)
    assert load == pytest.approx(95_191.07, abs=0.01)
    contact = houpert_contact(load, D_W, CONFORMITY, E, NU)
    assert contact.a == pytest.approx(8.298e-3, abs=0.5e-6)
    assert contact.b == pytest.approx(1.304e-3, abs=0.5e-6)
    assert contact.p_max == pytest.approx(4200e6, rel=1e-12)
    assert 1.5 * load / (math.pi * contact.a * contact.b) == pytest.approx(4200e6, rel=1e-3)


def test_exact_hertz_for_two_spheres_is_the_closed_form():
    radius, load = 0.01, 1000.0
    sphere = 1 / radius
    contact = hertz_contact(load, (sphere, sphere, sphere, sphere), reduced_modulus(E, NU, E, NU))
    star = E / (2 * (1 - NU**2))
    closed = (3 * load * (radius / 2) / (4 * star)) ** (1 / 3)
    assert contact.a == pytest.approx(closed, rel=1e-9) and contact.b == pytest.approx(closed, rel=1e-9)
    assert contact.p_max == pytest.approx(3 * load / (2 * math.pi * closed**2), rel=1e-9)
    approach = hertz_approach(load, (sphere, sphere, sphere, sphere), reduced_modulus(E, NU, E, NU))
    assert approach == pytest.approx(closed**2 / (radius / 2), rel=1e-9)  # δ = a²/R (Johnson eq. 4.23)


def test_houpert_agrees_with_exact_hertz_in_a_straight_groove():
    load = houpert_load_at_pressure(4200e6, D_W, CONFORMITY)
    houpert = houpert_contact(load, D_W, CONFORMITY, E, NU)
    hertz = hertz_contact(load, ball_groove_curvatures(D_W, CONFORMITY), reduced_modulus(E, NU, E, NU))
    for name in ("a", "b", "p_max"):
        assert getattr(hertz, name) == pytest.approx(getattr(houpert, name), rel=5e-3), name


@pytest.mark.parametrize("ring", ["inner", "outer"])
def test_the_raceway_curvature_is_a_small_correction_at_1_5_m(ring):
    load = houpert_load_at_pressure(4200e6, D_W, CONFORMITY)
    modulus = reduced_modulus(E, NU, E, NU)
    straight = hertz_contact(load, ball_groove_curvatures(D_W, CONFORMITY), modulus)
    curved = hertz_contact(load, ball_groove_curvatures(D_W, CONFORMITY, 1.5, math.radians(45), ring), modulus)
    assert curved.a == pytest.approx(straight.a, rel=1.5e-2) and curved.b == pytest.approx(straight.b, rel=1.5e-2)
    assert (curved.b < straight.b) == (ring == "inner")  # a convex raceway narrows the contact
