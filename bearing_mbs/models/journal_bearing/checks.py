"""The checks a journal bearing's static solution is held to (``bearing-mbs journal``; docs/status.md lists them).

Each says whether the solved numbers can be used: the grid's error on the load, the range of eccentricity where a
rigid, smooth, isoviscous film holds, the minimum film against a published design criterion, the peak pressure
against the isoviscous assumption, the solver's mass balance, the laminar bounds of the film and the capillaries,
and, for a mass-conserving film, how far its load lies from Gümbel's.
"""

from __future__ import annotations

import math

import numpy as np

from bearing_mbs.core.checks import Check, lower_bound, upper_bound
from bearing_mbs.fluid_film.journal import FILM_COLLAPSE, FilmGrid
from bearing_mbs.fluid_film.restrictors import Capillary, capillary_reynolds
from bearing_mbs.fluid_film.reynolds import FilmNotConverged, FilmSolution, solve_film

#: Largest estimated error of the load from the grid [-]: 2 %, below the 5 % by which document 001's solvers and
#: the digest's finite-volume solution differ (docs/fluid-film.md), so that the grid is not the largest error.
GRID_ERROR_BOUND = 0.02
#: The grid's error is estimated from a second solve on a grid of twice the cells in each direction while that has at
#: most this many cells (the default 240 × 60 grid refined: 0.2 s with Gümbel's condition, about 1 s with JFO, on a
#: 2-core machine), on one of half the cells in each direction otherwise.
REFINED_CELLS_LIMIT = 4 * 240 * 60
#: Order of convergence assumed by the Richardson estimate: 1. The scheme is second order where the film is smooth,
#: but the recess edges and the cavitation boundary fall between cells: the observed order is 1.3 at 0 rpm
#: (docs/fluid-film.md, grid convergence) and 1.3–2 at 1000 rpm; the low end keeps the estimate on the safe side.
ASSUMED_ORDER = 1.0
#: A load below this fraction of the pressure's integral ∫p dA is zero by symmetry (a centred journal between
#: symmetric recesses); the grid's error is then taken relative to that fraction of the integral.
LOAD_FLOOR = 1e-6
#: Trumpler's minimum film for journal bearings, h_min >= 0.0002 in + 0.00004 in per inch of journal diameter
#: (P. R. Trumpler, "Design of Film Bearings", Macmillan 1966; as quoted in Budynas & Nisbett, Shigley's Mechanical
#: Engineering Design, ch. 12): a film that covers the surfaces' finish, form and alignment errors. In SI: a constant
#: [m] plus a fraction of the diameter [-].
TRUMPLER_FILM, TRUMPLER_FILM_PER_DIAMETER = 0.0002 * 0.0254, 0.00004
#: Pressure–viscosity coefficient α [1/Pa] of a mineral oil (Barus: μ(p) = μ₀ exp(αp); 1–3e-8 1/Pa for mineral oils,
#: B. J. Hamrock, S. R. Schmid, B. O. Jacobson, "Fundamentals of Fluid Film Lubrication", 2nd ed. 2004, ch. 4).
PRESSURE_VISCOSITY = 2e-8
#: Largest peak pressure [Pa] of the isoviscous film: where Barus' law doubles the viscosity, ln 2 / α = 35 MPa. Beyond
#: it the film near its minimum is far stiffer than the solver's; it is also of the order of the compressive yield
#: of white metal (babbitt) bearing linings at 20 °C (ASTM B23: 30–40 MPa).
MAX_PRESSURE = math.log(2.0) / PRESSURE_VISCOSITY
#: Largest relative mass-balance error of the film [-]: the finite-volume scheme conserves mass to round-off
#: (1e-13 measured, docs/fluid-film.md); more means an ill-conditioned solve.
MASS_BALANCE_BOUND = 1e-8
#: Largest relative difference of the mass-conserving (JFO) load from Gümbel's [-] where both run: Reynolds' rupture
#: condition, which JFO's film obeys, carries 14 % more than the half-Sommerfeld film at L/D = 1, ε = 0.6 (Raimondi
#: and Boyd 1958; docs/fluid-film.md); beyond a quarter the load depends on the cavitation model more than on the
#: grid or the film's other assumptions.
CAVITATION_SPREAD_BOUND = 0.25
#: Laminar bounds: capillary Re = 4ρq/(πμd) (Rowe 2012) and the film's Taylor number Ta = ρΩRC/μ · sqrt(C/R) < 41.3
#: (Taylor vortices; Hamrock, Schmid & Jacobson 2004, ch. 3).
CAPILLARY_REYNOLDS_LIMIT, TAYLOR_LIMIT = 2000.0, 41.3


def taylor_number(journal) -> float:
    """Ta = ρ Ω R C/μ · sqrt(C/R) [-] of the ``[journal]`` section's film."""
    radius, clearance = journal.diameter / 2, journal.radial_clearance
    return (journal.oil_density * abs(journal.speed) * radius * clearance / journal.oil_viscosity
            * math.sqrt(clearance / radius))


def largest_capillary_reynolds(journal, film: FilmSolution, supply) -> float | None:
    """The largest Reynolds number [-] of the recesses' capillaries (None without capillaries)."""
    if supply is None or not isinstance(supply.restrictor, Capillary):
        return None
    return max(capillary_reynolds(q, supply.restrictor.diameter, journal.oil_viscosity, journal.oil_density)
               for q in film.supply_flows)


def trumpler_film(diameter: float) -> float:
    """Trumpler's smallest allowed film [m] for a journal of ``diameter`` [m]."""
    return TRUMPLER_FILM + TRUMPLER_FILM_PER_DIAMETER * diameter


def mass_balance_error(journal, film: FilmSolution) -> float:
    """|supply − edge outflow − growth of the film| [-], relative to the largest of the flows and the Couette flow
    Ω R C L/2 that the journal drags round (a plain journal's supply and end flows are zero)."""
    imbalance = abs(film.supply_flow - film.edge_outflow - film.volume_rate)
    couette = abs(journal.speed) * journal.diameter / 2 * journal.radial_clearance * journal.length / 2
    scale = max(abs(film.supply_flow), abs(film.edge_outflow), couette)
    return imbalance / scale if scale > 0 else 0.0


def grid_error(bearing, state, supply, grid: FilmGrid, cavitation: str, film: FilmSolution) -> tuple[float, list]:
    """(estimated relative error of the load on ``grid`` [-], the other grid [n_theta, n_z]): Richardson's estimate
    from a second solve on a grid twice as fine in each direction (half as fine beyond :data:`REFINED_CELLS_LIMIT`),
    at the order :data:`ASSUMED_ORDER`; the error of the force vector relative to the load."""
    n_theta, n_z = grid.n_theta, grid.n_z
    refine = 4 * n_theta * n_z <= REFINED_CELLS_LIMIT
    other = (2 * n_theta, 2 * n_z) if refine else (max(4, n_theta // 2), max(4, n_z // 2))
    other_film = solve_film(bearing, state, supply, FilmGrid.build(bearing, *other), cavitation)
    ratio = math.sqrt(max(n_theta * n_z, other[0] * other[1]) / min(n_theta * n_z, other[0] * other[1]))
    growth = ratio ** ASSUMED_ORDER
    difference = float(np.linalg.norm(film.force - other_film.force))
    # the finer grid's error is difference / (r^p − 1); the coarser one's adds the difference itself
    error = difference * growth / (growth - 1) if refine else difference / (growth - 1)
    integral = float(film.load_pressure.sum()) * grid.cell_area
    scale = max(film.load_capacity, LOAD_FLOOR * integral)
    return (error / scale if scale > 0 else 0.0), list(other)


def cavitation_spread(bearing, state, supply, grid: FilmGrid, film: FilmSolution) -> float | None:
    """|W_JFO / W_Gümbel − 1| [-] of a mass-conserving ``film`` (None for a Gümbel film or a load of nothing; NaN
    where Gümbel's film does not settle)."""
    if film.cavitation != "jfo":
        return None
    try:
        gumbel = solve_film(bearing, state, supply, grid, "gumbel").load_capacity
    except FilmNotConverged:
        return math.nan
    return abs(film.load_capacity / gumbel - 1) if gumbel > 0 else None


def journal_checks(spec, bearing, supply, grid: FilmGrid, state, film: FilmSolution, h_min: float) -> list[Check]:
    """The checks of the static solution ``film`` of the scenario ``spec`` on ``grid`` (see the module notes)."""
    j = spec.journal
    finer = [2 * grid.n_theta, 2 * grid.n_z]
    try:
        error, other = grid_error(bearing, state, supply, grid, j.cavitation, film)
        found = f"estimated against a {other[0]} × {other[1]} grid, is {100 * error:.3g} %"
    except FilmNotConverged as stopped:  # the scenario's own film is kept; only the estimate is missing
        error, found = None, f"could not be estimated: the second grid's film did not settle ({stopped})"
    checks = [upper_bound("grid_convergence", error, GRID_ERROR_BOUND, "-",
                          f"the load's error on the {grid.n_theta} × {grid.n_z} grid, {found}. Likely fix: "
                          f"journal.grid = {finer} (each doubling divides the error by about two)")]
    checks.append(upper_bound("eccentricity_ratio", j.eccentricity_ratio, FILM_COLLAPSE, "-",
                              f"at ε = {j.eccentricity_ratio:g} the film is {100 * (1 - j.eccentricity_ratio):.3g} % "
                              "of the clearance: asperities, form errors and elastic deflection, which a rigid smooth "
                              "film leaves out, decide the load. Likely fix: journal.eccentricity_ratio <= "
                              f"{FILM_COLLAPSE:g} (the load curve gives the load up to 0.9)"))
    smallest = trumpler_film(j.diameter)
    largest_eps = 1 - smallest / j.radial_clearance
    fix = (f"journal.eccentricity_ratio <= {largest_eps:.3g} at this clearance" if largest_eps > 0 else
           f"a journal.radial_clearance above {smallest / (1 - j.eccentricity_ratio):.3g} m at this eccentricity")
    checks.append(lower_bound("min_film_thickness", h_min, smallest, "m",
                              f"the smallest film, {1e6 * h_min:.3g} µm, is below Trumpler's {1e6 * smallest:.3g} µm "
                              f"for a {1e3 * j.diameter:g} mm journal: the surfaces' finish and alignment errors may "
                              f"touch. Likely fix: {fix}"))
    peak = float(film.load_pressure.max())
    checks.append(upper_bound("max_pressure", peak, MAX_PRESSURE, "Pa",
                              f"at {peak / 1e6:.4g} MPa Barus' law puts the oil's viscosity at "
                              f"{_viscosity_factor(peak):.3g} times the input's: the isoviscous film does not hold. "
                              f"Likely fix: a journal.eccentricity_ratio below {j.eccentricity_ratio:g}, or a longer "
                              "or larger bearing for this load"))
    balance = mass_balance_error(j, film)
    checks.append(upper_bound("mass_balance", balance, MASS_BALANCE_BOUND, "-",
                              "the film's inflow and outflow do not balance: the linear solve is ill-conditioned (a "
                              f"film spanning many decades of h³). Likely fix: journal.grid = {finer} or a lower "
                              "journal.eccentricity_ratio"))
    taylor = taylor_number(j)
    laminar_speed = abs(j.speed_rpm) * TAYLOR_LIMIT / taylor if taylor > 0 else math.inf
    checks.append(upper_bound("taylor_number", taylor, TAYLOR_LIMIT, "-",
                              "Taylor vortices: the laminar film model does not hold. Likely fix: journal.speed_rpm "
                              f"below {laminar_speed:.4g} rpm, or a smaller journal.radial_clearance"))
    spread = cavitation_spread(bearing, state, supply, grid, film)
    if spread is not None:
        checks.append(upper_bound("cavitation_spread", spread, CAVITATION_SPREAD_BOUND, "-",
                                  f"the mass-conserving load differs from Gümbel's by {100 * spread:.3g} % (NaN: "
                                  "Gümbel's film did not settle): here the "
                                  "load depends on how the film ruptures and reforms more than on anything else the "
                                  "solver resolves (the JFO film is the mass-conserving one; treat the load as "
                                  "uncertain by that much). Likely fix: none in the solver; a measurement or a "
                                  "supply at the film's thickest point decides"))
    reynolds = largest_capillary_reynolds(j, film, supply)
    if reynolds is not None:
        length = j.recesses.capillary_length * reynolds / CAPILLARY_REYNOLDS_LIMIT
        checks.append(upper_bound("capillary_reynolds", reynolds, CAPILLARY_REYNOLDS_LIMIT, "-",
                                  "a capillary's flow is not laminar; its resistance law does not hold. Likely fix: "
                                  f"journal.recesses.capillary_length of about {length:.3g} m (the flow, and so Re, "
                                  "falls as the capillary lengthens)"))
    return checks


def _viscosity_factor(pressure: float) -> float:
    """exp(α p) [-], Barus' viscosity ratio at ``pressure`` [Pa] (inf where it overflows)."""
    try:
        return math.exp(PRESSURE_VISCOSITY * pressure)
    except OverflowError:
        return math.inf


def speed_equilibria(rows: list[dict]) -> Check:
    """Every speed of ``journal.coefficient_speeds_rpm`` found its equilibrium under the static load."""
    missing = [row["speed_rpm"] for row in rows if row["eccentricity"] is None]
    return upper_bound("speed_equilibria", len(missing), 0, "count",
                       f"no equilibrium under journal.static_load at {missing} rpm. Likely fix: a smaller static_load "
                       "or a higher speed (the film must carry it inside the clearance)")
