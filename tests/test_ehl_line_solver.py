"""The numerical EHL line contact (bearing_mbs.fluid_film.ehl_line) and, against it, the film formulas of
bearing_mbs.contact.ehl.

The solver is checked first against two closed forms that owe nothing to it: Martin's rigid, isoviscous film
(w = 4.895 η0 u R/h0, H. M. Martin, Engineering 102 (1916) 119-121) and Hertz's dry pressure (K. L. Johnson,
Contact Mechanics, 1985, eq. 4.43), then for grid convergence. The formulas are then compared with it over the
seed bearing's raceway contacts (docs/ehl-line-contact.md has the table).

Tolerance of the formulas. No statement of their accuracy could be found: searches of the documentation, web-page
and code corpora for Pan & Hamrock (J. Tribol. 111 (1989) 246-251), Hamrock's textbook (Fundamentals of Fluid
Film Lubrication, 1994/2004) and Dowson & Higginson/Dowson & Toyoda turned up the formulas but neither the
papers' error bands nor their parameter ranges. The tolerance is therefore taken from the known spread of the
published fits themselves: on the contacts of Hamrock's roller bearing the two minimum-film fits agree within
10 % and the two central-film fits differ by up to 32 % (tests/test_ehl.py); two fits of the same isothermal
problem that far apart cannot both be closer than half of it to the truth. We allow 15 % on the minimum film and
20 % on the central film, in the formulas' own regime (elastic-piezoviscous, below).
"""

from __future__ import annotations

import math
import tomllib
from pathlib import Path

import numpy as np
import pytest

from bearing_mbs.contact import ehl
from bearing_mbs.contact.line_contact import reduced_modulus
from bearing_mbs.contact.lubricant import PRESETS as OILS
from bearing_mbs.fluid_film.ehl_line import (
    MARTIN,
    LineContact,
    LineContactSolution,
    LineSettings,
    solve_line_contact,
)
from bearing_mbs.models.cylindrical_roller.geometry import BearingGeometry
from bearing_mbs.models.cylindrical_roller.spec import PRESETS as BEARINGS
from bearing_mbs.models.cylindrical_roller.spec import BearingSpec

SCENARIO = Path(__file__).resolve().parents[1] / "scenarios" / "seed_hss_steady.toml"

#: Formula tolerances (relative; see the module docstring for their source).
MINIMUM_TOLERANCE, CENTRAL_TOLERANCE = 0.15, 0.20
#: Moes's load parameter M = W (2U)^(-1/2) from which a contact is taken to be in the formulas' elastic-
#: piezoviscous regime (pressure near Hertz's, film thinner than the elastic scale b^2/R). Below M ~ 1 the
#: Hertz zone has not formed and the film tends to the rigid regimes (M -> 0: Martin's).
EHL_REGIME_M = 2.0
#: Light contacts: below this M the contact is in the rigid regime.
RIGID_REGIME_M = 0.1


# --- the seed bearing's contacts, from the package ----------------------------------------------------------------

def _seed():
    scenario = tomllib.loads(SCENARIO.read_text())
    spec = BearingSpec(**BEARINGS[scenario["bearing"]["preset"]])
    geometry = BearingGeometry.from_spec(spec)
    oil = OILS[scenario["variants"]["lubricated"]["lubricant"]["oil"]]
    steel = spec.ring_material
    modulus = reduced_modulus(steel.youngs_modulus, steel.poisson_ratio, spec.roller_material.youngs_modulus,
                              spec.roller_material.poisson_ratio)  # E' = 2 E*
    return scenario, geometry, oil, modulus


def seed_contacts() -> dict[str, LineContact]:
    """The seed bearing's raceway contacts at the corners and middle of its operating range: ISO VG 320 mineral oil
    at 40/60/80 °C, inner ring at 1800/1400/1000 rpm, roller loads from the centrifugal force alone (outer raceway)
    to Stribeck's most loaded roller 4.08 F_r/Z under the scenario's 68 kN (inner raceway), and their geometric
    mean. Entrainment speed u = (D_pw^2 - D_w^2) ω_i/(4 D_pw) (no slip, outer ring fixed)."""
    scenario, geometry, oil, modulus = _seed()
    d_w, pitch, length = geometry.roller_diameter, geometry.pitch_diameter, geometry.roller_length
    radius = {"inner": ehl.reduced_radius(geometry.inner_race_diameter / 2, d_w / 2, 0),
              "outer": ehl.reduced_radius(geometry.outer_race_diameter / 2, d_w / 2, 1)}
    heaviest = 4.08 * scenario["load"]["radial"] / geometry.rollers
    contacts = {}
    for temperature, rpm in ((40.0, 1800.0), (60.0, 1400.0), (80.0, 1000.0)):
        omega = rpm * math.pi / 30
        speed = (pitch**2 - d_w**2) * omega / (4 * pitch)
        centrifugal = geometry.roller_mass * pitch / 2 * geometry.epicyclic_cage_speed(omega) ** 2
        for level, (race, load) in zip(("light", "middle", "heavy"),
                                       (("outer", centrifugal), ("inner", math.sqrt(centrifugal * heaviest)),
                                        ("inner", heaviest))):
            contacts[f"{temperature:.0f}C-{rpm:.0f}rpm-{level}"] = LineContact(
                speed=speed, load=load / length, viscosity=oil.dynamic_viscosity(temperature),
                pressure_viscosity=oil.pressure_viscosity, reduced_modulus=modulus, radius=float(radius[race]))
    return contacts


@pytest.fixture(scope="module")
def seed_solutions() -> dict[str, LineContactSolution]:
    return {name: solve_line_contact(contact) for name, contact in seed_contacts().items()}


def formula_films(contact: LineContact, formula: str) -> tuple[float, float]:
    code = ehl.FILM_FORMULAS.index(formula)
    central, minimum = ehl.film_thickness(code, contact.speed, contact.load, contact.viscosity,
                                          contact.pressure_viscosity, contact.reduced_modulus, contact.radius)
    return float(central), float(minimum)


# --- the solver against closed forms ------------------------------------------------------------------------------

def test_martins_rigid_isoviscous_film():
    """Rigid (E' -> infinity: 1e15 Pa), isoviscous, incompressible: the load carried at the gap h0 is Martin's
    4.895 η0 u R/h0 with the Reynolds outlet condition, and the film ruptures at x = 0.4751 (2 R h0)^(1/2).
    With the inlet 60 pressure-zone widths upstream (the cut-off inlet costs -0.6 % at the default 20 widths,
    -0.3 % at 40) and 100 nodes per width, the solver's h0 is within 0.3 % of Martin's (measured -0.2 %). The
    last full node is within 5 % of Martin's rupture point (measured 0.460 against 0.4751: the pressure ends as
    (x_c - x)^2, so its last nodes are near zero)."""
    contact = LineContact(speed=5.0, load=2000.0, viscosity=0.1, pressure_viscosity=0.0, reduced_modulus=1e15,
                          radius=0.012, compressible=False)
    solution = solve_line_contact(contact, LineSettings(nodes=100, inlet=60))
    martin = MARTIN * contact.viscosity * contact.speed * contact.radius / contact.load
    assert solution.minimum_film == pytest.approx(martin, rel=3e-3)
    assert solution.central_film == pytest.approx(solution.minimum_film, rel=1e-6)  # rigid: narrowest at x = 0
    full = solution.x[solution.pressure > 0]
    assert full[-1] / math.sqrt(2 * contact.radius * solution.minimum_film) == pytest.approx(0.4751, rel=0.05)
    assert abs(solution.load_error) < 1e-9


@pytest.mark.parametrize("load", [1.0e6, 1.5e6])
def test_heavy_load_gives_hertz_pressure(load):
    """At Moes's M = 94 and 140 (p_h = 1.7 and 2.1 GPa, U = 7e-12) the pressure is Hertz's p_h (1 - X^2)^(1/2)
    within 2 % of p_h over |X| <= 0.8, away from the inlet and the outlet spike (measured 0.55 % and 0.33 %),
    and the film is nearly flat there (max/min of H over |X| <= 0.8 below 1.1)."""
    contact = LineContact(speed=1.0 if load == 1.0e6 else 2.0, load=load, viscosity=0.02 if load == 1.0e6 else 0.01,
                          pressure_viscosity=2.2e-8, reduced_modulus=2.2857e11, radius=0.0125)
    assert contact.moes[0] > 90
    x, pressure, film = solve_line_contact(contact).dimensionless
    core = np.abs(x) <= 0.8
    assert np.max(np.abs(pressure[core] - np.sqrt(1 - x[core] ** 2))) < 0.02
    assert np.max(film[core]) / np.min(film[core]) < 1.1


def _changes(contact, nodes):
    films = [solve_line_contact(contact, LineSettings(nodes=n)) for n in nodes]
    central = np.array([f.central_film for f in films])
    minimum = np.array([f.minimum_film for f in films])
    return np.abs(np.diff(central) / central[1:]), np.abs(np.diff(minimum) / minimum[1:])


def test_grid_convergence_of_the_films():
    """Halving the grid spacing (50 -> 100 nodes per Hertz half-width, 198 -> 395 nodes) on the seed bearing's
    most loaded contact (M = 9.5, L = 19) changes H_c and H_min by less than 1 % (measured 0.43 % and 0.61 %)."""
    central, minimum = _changes(seed_contacts()["80C-1000rpm-heavy"], (50, 100))
    assert central[0] < 0.01 and minimum[0] < 0.01, f"changes of H_c {central}, H_min {minimum}"


@pytest.mark.slow
def test_grid_convergence_continues():
    """100 -> 200 nodes per half-width changes them less again (measured 0.11 % and 0.21 %; 200 -> 400:
    0.03 % and 0.08 %, about 4 minutes)."""
    central, minimum = _changes(seed_contacts()["80C-1000rpm-heavy"], (50, 100, 200))
    assert central[1] < central[0] and minimum[1] < minimum[0], f"changes of H_c {central}, H_min {minimum}"
    assert central[1] < 0.003 and minimum[1] < 0.003


# --- the formulas against the solver -------------------------------------------------------------------------------

def test_seed_contacts_span_the_stated_range():
    """The map covers the seed bearing's raceway contacts: U = 7.7e-11 .. 1.2e-9, G = 5029, W = 3.1e-7 .. 1.3e-4
    (Moes M = 0.023 .. 9.5, L = 18 .. 35); roller loads 55 N (centrifugal, 1000 rpm) .. 18.5 kN over 55 mm,
    u = 6.1 .. 10.9 m/s, η0 = 0.040 .. 0.28 Pa s, R = 11.2 mm (inner) and 13.8 mm (outer)."""
    groups = np.array([c.groups for c in seed_contacts().values()])
    moes = np.array([c.moes for c in seed_contacts().values()])
    assert groups[:, 0].min() == pytest.approx(7.7e-11, rel=0.02) and groups[:, 0].max() == pytest.approx(1.2e-9, rel=0.02)
    assert groups[:, 1] == pytest.approx(5029, rel=1e-3)
    assert groups[:, 2].min() == pytest.approx(3.1e-7, rel=0.02) and groups[:, 2].max() == pytest.approx(1.3e-4, rel=0.02)
    assert moes[:, 0].min() < RIGID_REGIME_M and moes[:, 0].max() > EHL_REGIME_M


@pytest.mark.parametrize("formula", ehl.FILM_FORMULAS)
def test_formulas_hold_their_tolerance_in_the_ehl_regime(seed_solutions, formula):
    """Where the seed contacts are elastic-piezoviscous (M >= 2: the three most loaded, M = 2.7, 5.3, 9.5) each
    formula's films are within the tolerances of the module docstring (15 % minimum, 20 % central). Measured:
    Pan-Hamrock central -12 .. -13 %, minimum -9 %; Dowson-Toyoda central +14 .. +15 %, Dowson-Higginson minimum
    -0.4 .. -1.7 %."""
    checked = 0
    for name, solution in seed_solutions.items():
        if solution.contact.moes[0] < EHL_REGIME_M:
            continue
        central, minimum = formula_films(solution.contact, formula)
        assert central == pytest.approx(solution.central_film, rel=CENTRAL_TOLERANCE), name
        assert minimum == pytest.approx(solution.minimum_film, rel=MINIMUM_TOLERANCE), name
        checked += 1
    assert checked == 3


@pytest.mark.parametrize("formula", ehl.FILM_FORMULAS)
def test_light_contacts_are_outside_the_formulas_regime(seed_solutions, formula):
    """Rollers pressed on the outer raceway by their centrifugal force alone (W = 3-10e-7, M = 0.02-0.03) are in
    the rigid regime, outside any EHL fit: the solved film is at least Martin's rigid, isoviscous film (elasticity
    and piezoviscosity only thicken it; 0.99 of it allows for the cut-off inlet, -0.6 % in the rigid test) and
    the formulas give 12-20 % of it (measured). Asserted: below 30 %."""
    light = [s for s in seed_solutions.values() if s.contact.moes[0] < RIGID_REGIME_M]
    assert len(light) == 3
    for solution in light:
        c = solution.contact
        assert solution.minimum_film >= 0.99 * MARTIN * c.viscosity * c.speed * c.radius / c.load
        central, minimum = formula_films(c, formula)
        assert central < 0.3 * solution.central_film and minimum < 0.3 * solution.minimum_film


@pytest.mark.parametrize("formula", ehl.FILM_FORMULAS)
def test_transition_contacts(seed_solutions, formula):
    """Between the regimes (0.1 <= M < 2: the middle loads, 1.0-1.8 kN per roller, M = 0.26-0.52) the formulas
    still give the minimum film within 15 % (measured -11 .. +5 %), but both over-estimate the central film
    (measured Pan-Hamrock +5 .. +17 %, Dowson-Toyoda +17 .. +27 %): the film there is nearly parallel (central
    and minimum within 1 %), not the EHL's horseshoe the fits describe. Asserted: that sign and that minimum."""
    middle = [s for s in seed_solutions.values() if RIGID_REGIME_M <= s.contact.moes[0] < EHL_REGIME_M]
    assert len(middle) == 3
    for solution in middle:
        central, minimum = formula_films(solution.contact, formula)
        assert central > solution.central_film
        assert minimum == pytest.approx(solution.minimum_film, rel=MINIMUM_TOLERANCE)


def test_refuses_bad_input():
    good = {"speed": 5.0, "load": 1e5, "viscosity": 0.1, "pressure_viscosity": 2e-8, "reduced_modulus": 2.3e11, "radius": 0.01}
    for field, value in (("speed", 0.0), ("load", -1.0), ("viscosity", math.nan), ("reduced_modulus", math.inf),
                         ("radius", "0.01"), ("pressure_viscosity", -1e-8), ("viscosity_law", "eyring")):
        with pytest.raises(ValueError):
            LineContact(**{**good, field: value})
    with pytest.raises(ValueError):
        LineContact(**{**good, "viscosity": 1e-5})  # below Roelands's η∞
    for field, value in (("nodes", 5), ("inlet", 1.0), ("outlet", 1.0), ("tolerance", 0.0), ("iterations", 0.5)):
        with pytest.raises(ValueError):
            LineSettings(**{field: value})
    with pytest.raises(TypeError):
        solve_line_contact("not a contact")
