"""The fluid-film journal-bearing library against closed forms, a published design table and conservation laws.

References and tolerances are stated at each test; none of the expected values comes from the solver.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from bearing_mbs.fluid_film import closed_forms
from bearing_mbs.fluid_film.coefficients import dynamic_coefficients
from bearing_mbs.fluid_film.journal import JournalBearing, Recesses
from bearing_mbs.fluid_film.network import network_recess_pressures
from bearing_mbs.fluid_film.restrictors import Capillary, ConstantFlow, Orifice, capillary_resistance
from bearing_mbs.fluid_film.reynolds import JournalState, Supply, solve_film

# Document 001, Table 2: 75 mm bore and length, 4 recesses 45° × 60 mm × 1 mm, capillary 20 mm × 0.6 mm,
# ρ = 860 kg/m³, μ = 0.028 Pa s.
D, L, MU, RHO = 0.075, 0.075, 0.028, 860.0
SEED_RECESSES = Recesses(count=4, angular_width=45.0, axial_length=0.060, depth=0.001)
SEED_CAPILLARY = Capillary(length=0.020, diameter=0.0006)
OMEGA = 1000 * 2 * math.pi / 60


def seed_bearing(clearance=35e-6):
    return JournalBearing(D, L, clearance, MU, RHO, SEED_RECESSES)


def test_capillary_resistance_of_document_001():
    """Digest §1.5, by hand: R = 128·0.020·0.028/(π·0.0006⁴) = 1.761e11 Pa s/m³ (4 digits)."""
    assert capillary_resistance(0.020, 0.0006, 0.028) == pytest.approx(1.761e11, rel=5e-4)


def test_slot_of_constant_film_gives_the_parallel_plate_resistance_and_a_linear_pressure():
    """A circumferential groove at p_s between two axial lands of width B, centred journal, no rotation: each land
    is a slot of length πD and constant film h, R = 12 μ B/(h³ πD) (document 001, eq. 5.22), exact for the
    finite-volume scheme; the land pressure falls linearly from p_s to 0."""
    h, groove, supply = 50e-6, 0.035, 2e5
    bearing = JournalBearing(D, L, h, MU, RHO, Recesses(1, 360.0, groove, 0.001))
    film = solve_film(bearing, JournalState(), Supply(supply), grid=(16, 30))  # faces on the groove edges
    land = (L - groove) / 2
    slot = 12 * MU * land / (h**3 * math.pi * D)
    assert film.supply_flow == pytest.approx(2 * supply / slot, rel=1e-12)
    assert film.edge_outflow == pytest.approx(2 * supply / slot, rel=1e-12)
    z = film.grid.z
    on_land = np.abs(z) > groove / 2
    linear = supply * (1 - (np.abs(z[on_land]) - groove / 2) / land)
    np.testing.assert_allclose(film.pressure[0, on_land], linear, rtol=1e-10)


@pytest.mark.parametrize("eccentricity_ratio", [0.25, 0.5, 0.75])
def test_short_bearing_limit(eccentricity_ratio):
    """Ocvirk's short bearing (closed_forms docstring; Hamrock, Schmid & Jacobson 2004, ch. 10) is the L/D → 0 limit.
    Load ratio at L/D = 0.1 within 4 % (the digest's own FD gives 0.995/0.987/0.963 at L/D = 0.107), at L/D = 0.05
    within 1 %, and closer to 1 at 0.05 than at 0.1; attitude within 0.6° at 0.05."""
    ratios = {}
    for slenderness in (0.1, 0.05):
        bearing = JournalBearing(D, slenderness * D, 35e-6, MU)
        film = solve_film(bearing, JournalState((eccentricity_ratio * 35e-6, 0.0), speed=OMEGA), grid=(240, 30))
        components = closed_forms.short_bearing_components(eccentricity_ratio, OMEGA, D / 2, slenderness * D, 35e-6,
                                                           MU)
        ratios[slenderness] = film.load_capacity / math.hypot(*components)
        attitude = closed_forms.attitude_angle(components)
    assert abs(ratios[0.1] - 1) < 0.04
    assert abs(ratios[0.05] - 1) < 0.01
    assert abs(ratios[0.05] - 1) < abs(ratios[0.1] - 1)
    assert film.attitude_angle == pytest.approx(attitude, abs=0.6)


def test_long_bearing_limit_with_the_gumbel_condition():
    """Sommerfeld's long bearing with Gümbel's condition (closed_forms docstring) is the L/D → ∞ limit: the load ratio
    grows towards 1 as 1 − c·D/L; extrapolated from L/D = 4 and 8 it is 1 within 2 %, and the attitude approaches
    the closed form's 69.8° at ε = 0.5 (within 1° at L/D = 8)."""
    ratios = []
    for slenderness in (2, 4, 8):
        bearing = JournalBearing(D, slenderness * D, 35e-6, MU)
        film = solve_film(bearing, JournalState((0.5 * 35e-6, 0.0), speed=OMEGA), grid=(180, 60))
        components = closed_forms.long_bearing_components(0.5, OMEGA, D / 2, slenderness * D, 35e-6, MU)
        ratios.append(film.load_capacity / math.hypot(*components))
    assert ratios[0] < ratios[1] < ratios[2] < 1
    assert 2 * ratios[2] - ratios[1] == pytest.approx(1.0, abs=0.02)
    assert film.attitude_angle == pytest.approx(closed_forms.attitude_angle(components), abs=1.0)


# A. A. Raimondi, J. Boyd, "A solution for the finite journal bearing and its application to analysis and design",
# ASLE Trans. 1 (1958) 159–209, full (360°) bearing, Reynolds boundary condition, oil fed at the thickest film:
# (ε, Sommerfeld number S, attitude φ [deg]), as reprinted in Shigley's Mechanical Engineering Design (table of
# Raimondi and Boyd's full-bearing performance).
RAIMONDI_BOYD = {
    1.0: [(0.2, 0.631, 74.02), (0.4, 0.264, 63.10), (0.6, 0.121, 50.58), (0.8, 0.0446, 36.24), (0.9, 0.0188, 26.45)],
    0.5: [(0.2, 2.03, 74.94), (0.4, 0.779, 61.45), (0.6, 0.319, 48.14), (0.8, 0.0923, 33.31), (0.9, 0.0313, 23.66)],
}


@pytest.mark.parametrize("slenderness", [1.0, 0.5])
def test_raimondi_and_boyd_full_bearing(slenderness):
    """Mass-conserving cavitation (its rupture obeys Reynolds' condition) with an ambient axial groove one cell wide at
    the thickest film reproduces the table: S within 3 %, attitude within 1°."""
    n_theta = 180
    groove = Recesses(1, 360 / n_theta, slenderness * D, 0.001)
    bearing = JournalBearing(D, slenderness * D, 35e-6, MU, RHO, groove)
    for eps, sommerfeld, attitude in RAIMONDI_BOYD[slenderness]:
        film = solve_film(bearing, JournalState((-eps * 35e-6, 0.0), speed=OMEGA), Supply(0.0), grid=(n_theta, 40),
                          cavitation="jfo")
        number = closed_forms.sommerfeld_number(film.load_capacity, OMEGA, D / 2, slenderness * D, 35e-6, MU)
        assert number == pytest.approx(sommerfeld, rel=0.03), eps
        assert film.attitude_angle == pytest.approx(attitude, abs=1.0), eps


def test_a_mass_conserving_film_without_an_oil_source_is_refused():
    """A plain bore (or recesses fed through restrictors from 0 Pa) has no oil source: the mass-conserving film would
    starve to a load of about 1e-10 N; it is refused (ValueError) instead of returned."""
    plain = JournalBearing(D, D, 35e-6, MU, RHO)
    with pytest.raises(ValueError):
        solve_film(plain, JournalState((0.6 * 35e-6, 0.0), speed=OMEGA), cavitation="jfo")
    with pytest.raises(ValueError):
        solve_film(seed_bearing(), JournalState((0.6 * 35e-6, 0.0), speed=OMEGA), Supply(0.0, SEED_CAPILLARY),
                   cavitation="jfo")


@pytest.mark.parametrize("cavitation", ["gumbel", "jfo"])
@pytest.mark.parametrize("speed", [0.0, OMEGA])
@pytest.mark.parametrize("restrictor", [SEED_CAPILLARY, Orifice(0.00045, 0.6), ConstantFlow(5e-6)])
def test_mass_conservation(cavitation, speed, restrictor):
    """Restrictor inflow = end outflow + growth of the oil in the gap, to 1e-8 relative; with a squeeze velocity too."""
    for rate in ((0.0, 0.0), (2e-5, -1e-5)):
        film = solve_film(seed_bearing(), JournalState((0.4 * 35e-6, 0.1 * 35e-6), rate, speed),
                          Supply(1e6, restrictor), cavitation=cavitation)
        inflows = [restrictor.inflow(1e6, p, MU, RHO)[0] for p in film.recess_pressures]
        np.testing.assert_allclose(film.supply_flows, inflows, rtol=1e-8)
        assert film.supply_flow == pytest.approx(film.edge_outflow + film.volume_rate, rel=1e-8)


def test_centred_four_recess_bearing_is_symmetric():
    """Centred, not turning: equal recess pressures (1e-12) and no net force (1e-9 of p_s × projected area)."""
    film = solve_film(seed_bearing(), JournalState(), Supply(1e6, SEED_CAPILLARY))
    np.testing.assert_allclose(film.recess_pressures, film.recess_pressures[0], rtol=1e-12)
    assert film.load_capacity < 1e-9 * 1e6 * D * L


def test_petroff_torque_of_a_centred_journal():
    """Petroff: T = 2π μ Ω R³ L / C for a centred plain journal (uniform shear μΩR/C), to 1e-12."""
    film = solve_film(JournalBearing(D, L, 35e-6, MU), JournalState(speed=OMEGA))
    assert film.friction_torque == pytest.approx(closed_forms.petroff_torque(OMEGA, D / 2, L, 35e-6, MU), rel=1e-12)


@pytest.mark.parametrize("clearance", [35e-6, 70e-6])
def test_grid_convergence_of_the_hydrostatic_load(clearance):
    """Document 001's case at ε = 0.25, 0 rpm: the load on 120×30, 240×60 and 480×120 grids converges with an
    observed order ≥ 1 (the recess corners are singular), and the 240×60 grid (the command's default) is within
    0.5 % of the Richardson extrapolation."""
    loads = [solve_film(seed_bearing(clearance), JournalState((0.25 * clearance, 0.0)), Supply(1e6, SEED_CAPILLARY),
                        grid=grid).load_capacity for grid in ((120, 30), (240, 60), (480, 120))]
    order = math.log2((loads[0] - loads[1]) / (loads[1] - loads[2]))
    extrapolated = loads[2] + (loads[2] - loads[1]) / (2**order - 1)
    assert order > 1.0, f"observed order {order:.2f}"
    assert loads[1] == pytest.approx(extrapolated, rel=5e-3), f"observed order {order:.2f}"


def test_document_network_matches_the_digest():
    """Digest §1.5: the printed network, errata corrected, gives centred recess pressures 0.739 MPa (C = 0.035 mm)
    and 0.262 MPa (C = 0.07 mm) at p_s = 1 MPa; the Reynolds solver gives more (the network overstates the axial
    outflow), by 5–25 %."""
    resistance = capillary_resistance(0.020, 0.0006, MU)
    for clearance, expected in ((35e-6, 0.739e6), (70e-6, 0.262e6)):
        pressures, _ = network_recess_pressures(seed_bearing(clearance), 0.0, 1e6, resistance)
        np.testing.assert_allclose(pressures, expected, rtol=2e-3)
        film = solve_film(seed_bearing(clearance), JournalState(), Supply(1e6, SEED_CAPILLARY))
        assert 1.05 < film.recess_pressures[0] / pressures[0] < 1.25


def test_short_bearing_coefficients_match_the_closed_form():
    """K and C of the solver at L/D = 0.05, ε = 0.5, 1000 rpm against those of Ocvirk's dynamic closed form
    (closed_forms.short_bearing_force, an independent formula), within 3 % of the largest entry; and the linear model
    K Δe predicts the solver's own force change for a diagonal step of 0.2 % C to 1 %."""
    clearance, length = 35e-6, 0.05 * D
    bearing = JournalBearing(D, length, clearance, MU)
    state = JournalState((0.5 * clearance, 0.0), speed=OMEGA)

    def solver(s):
        return solve_film(bearing, s, grid=(240, 20)).force

    def closed(s):
        return np.array(closed_forms.short_bearing_force(*s.eccentricity, *s.eccentricity_rate, s.speed, D / 2,
                                                         length, clearance, MU))

    stiffness, damping = dynamic_coefficients(solver, state, clearance)
    stiffness_0, damping_0 = dynamic_coefficients(closed, state, clearance)
    assert np.abs(stiffness - stiffness_0).max() < 0.03 * np.abs(stiffness_0).max()
    assert np.abs(damping - damping_0).max() < 0.03 * np.abs(damping_0).max()
    step = 2e-3 * clearance * np.array([1.0, 1.0]) / math.sqrt(2)
    change = solver(JournalState(tuple(np.array(state.eccentricity) + step), speed=OMEGA)) - solver(state)
    np.testing.assert_allclose(change, -stiffness @ step, rtol=1e-2)


def test_dynamic_short_bearing_reduces_to_the_steady_closed_form():
    """With no squeeze velocity the quadrature of the dynamic short bearing equals the steady closed form (1e-9)."""
    force = closed_forms.short_bearing_force(0.0, 0.6 * 35e-6, 0.0, 0.0, OMEGA, D / 2, 0.01, 35e-6, MU)
    f_n, f_t = closed_forms.short_bearing_components(0.6, OMEGA, D / 2, 0.01, 35e-6, MU)
    np.testing.assert_allclose(force, [-f_t, f_n], rtol=1e-9)


@pytest.mark.parametrize("make", [
    lambda: solve_film(JournalBearing(D, L, 35e-6, MU), JournalState((35e-6, 0.0))),
    lambda: JournalBearing(D, L, 35e-6, MU, RHO, Recesses(4, 95.0, 0.06, 0.001)),
    lambda: JournalBearing(D, L, 35e-6, MU, RHO, Recesses(4, 45.0, 0.08, 0.001)),
    lambda: Capillary(length=0.005, diameter=0.0006),
    lambda: solve_film(JournalBearing(D, L, 35e-6, MU), JournalState(), cavitation="reynolds"),
])
def test_bad_input_is_refused(make):
    """Eccentricity ratio 1, overlapping or over-long recesses, a capillary shorter than 20 bores, an unknown
    cavitation model."""
    with pytest.raises(ValueError):
        make()


def test_a_fed_mass_conserving_film_lies_above_gumbel_as_raimondi_and_boyd_say():
    """L/D = 1, ε = 0.6, an ambient groove one cell wide at the thickest film: Raimondi and Boyd's S = 0.121
    (Reynolds' condition) within 3 %, and 10–20 % above Gümbel's half-Sommerfeld load (measured +14 %): JFO's film
    extends past θ = π, where Gümbel's ends."""
    n_theta = 180
    bearing = JournalBearing(D, D, 35e-6, MU, RHO, Recesses(1, 360 / n_theta, D, 0.001))
    state = JournalState((-0.6 * 35e-6, 0.0), speed=OMEGA)
    jfo = solve_film(bearing, state, Supply(0.0), grid=(n_theta, 40), cavitation="jfo").load_capacity
    gumbel = solve_film(bearing, state, Supply(0.0), grid=(n_theta, 40), cavitation="gumbel").load_capacity
    assert closed_forms.sommerfeld_number(jfo, OMEGA, D / 2, D, 35e-6, MU) == pytest.approx(0.121, rel=0.03)
    assert 1.10 < jfo / gumbel < 1.20
