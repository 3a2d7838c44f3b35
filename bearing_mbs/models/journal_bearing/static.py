"""``bearing-mbs journal``: the static solution of a journal-bearing scenario, written as ``summary.json`` (SI units,
its ``units`` map) and figures.

At the scenario's eccentricity: load, attitude, flow, friction, recess pressures, the eight dynamic coefficients
and the static stiffness ΔF/Δe (:mod:`bearing_mbs.fluid_film`); along the same direction, the load and static
stiffness against eccentricity; for capillary recesses at zero speed with the eccentricity towards the first
recess, document 001's resistance network beside the full solution. The summary's ``status`` and ``checks``
(:mod:`.checks`; docs/status.md) say whether the numbers can be used.
"""

from __future__ import annotations

import math
from dataclasses import replace
from pathlib import Path

import numpy as np

from bearing_mbs.core.status import status_entries, status_note
from bearing_mbs.fluid_film.coefficients import dynamic_coefficients, static_stiffness
from bearing_mbs.fluid_film.journal import FilmGrid, JournalBearing
from bearing_mbs.fluid_film.network import network_recess_pressures
from bearing_mbs.fluid_film.restrictors import Capillary, capillary_resistance
from bearing_mbs.fluid_film.reynolds import FilmNotConverged, FilmSolution, JournalState, Supply, solve_film
from bearing_mbs.io.figures import new_figure, save_figure
from bearing_mbs.io.json import json_safe, rounded, write_json
from bearing_mbs.models.journal_bearing.checks import (
    journal_checks,
    largest_capillary_reynolds,
    mass_balance_error,
    speed_equilibria,
    taylor_number,
)
from bearing_mbs.models.journal_bearing.spec import JournalSpec
from bearing_mbs.models.journal_bearing.speeds import UNITS as SPEED_UNITS
from bearing_mbs.models.journal_bearing.speeds import coefficients_over_speed, write_table
from bearing_mbs.models.journal_bearing.speeds import plot as plot_speeds
from bearing_mbs.models.journal_bearing.thermal import effective_film
from bearing_mbs.spec.recesses import SIZED_BORE

SUMMARY_FILE = "summary.json"
#: Eccentricity ratios of the load curve.
CURVE_ECCENTRICITIES = (0.05, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9)
UNITS = {"load_capacity": "N", "force": "N", "attitude_angle": "deg", "flow": "m^3/s", "friction_torque": "N m",
         "friction_power": "W", "recess_pressures": "Pa", "recess_flows": "m^3/s", "stiffness": "N/m",
         "damping": "N s/m", "static_stiffness": "N/m", "static_stiffness_per_eccentricity_ratio": "N",
         "min_film_thickness": "m", "max_pressure": "Pa", "load_curve": "-, N, N/m",
         "network_recess_pressures": "Pa", "network_difference": "-", "mass_balance_error": "-",
         "recess_areas": "m^2", "capillary_reynolds": "-", "taylor_number": "-", "design_pressure_ratio": "-",
         "sized_bore": "m", "coefficients_over_speed": SPEED_UNITS}


def bearing_of(spec: JournalSpec) -> tuple[JournalBearing, Supply | None]:
    j = spec.journal
    return j.bearing(), None if j.recesses is None else j.recesses.supply(j.bearing(), j.grid)


def state_at(spec: JournalSpec, eccentricity_ratio: float) -> JournalState:
    j = spec.journal
    e, angle = eccentricity_ratio * j.radial_clearance, math.radians(j.attitude)
    return JournalState((e * math.cos(angle), e * math.sin(angle)), (0.0, 0.0), j.speed)


class TooHot(RuntimeError):
    """The heat balance puts the film beyond the top of its oil's viscosity fit."""


def journal_summary(spec: JournalSpec) -> tuple[dict, FilmSolution, list]:
    """The summary (with its status and checks), the film at the scenario's eccentricity and the load curve; with
    ``thermal = "effective"``, all of them at the heat balance's effective temperature (:mod:`.thermal`)."""
    if spec.journal.thermal == "effective":
        return _effective_summary(spec)
    return _isothermal_summary(spec)


def _effective_summary(spec: JournalSpec) -> tuple[dict, FilmSolution, list]:
    j = spec.journal
    bearing, supply = bearing_of(spec)  # the restrictors as built (or sized) at the inlet temperature
    state = state_at(spec, j.eccentricity_ratio)

    def friction_and_flow(viscosity):  # (a grid holds its bearing, viscosity included: one per viscosity)
        film = solve_film(replace(bearing, viscosity=viscosity), state, supply, j.grid, j.cavitation)
        return film.friction_power, film.supply_flow

    effective = effective_film(j.oil, friction_and_flow)
    if effective.temperature is None:
        raise TooHot(f"the heat balance puts the film above {effective.highest:g} °C, the top of the oil's viscosity "
                     "fit. Likely fix: a cooler journal.oil.inlet_temperature, a lower journal.speed_rpm or a larger "
                     "journal.radial_clearance")
    recesses = j.recesses
    if recesses.design_pressure_ratio is not None:  # keep the bore sized at the inlet temperature
        recesses = replace(recesses, design_pressure_ratio=None,
                           **{SIZED_BORE[recesses.restrictor]: supply.restrictor.diameter})
    film_spec = replace(spec, journal=replace(j, viscosity=effective.viscosity, density=j.oil_density, oil=None,
                                              thermal="isothermal", recesses=recesses))
    summary, film, curve = _isothermal_summary(film_spec)
    summary.update(rounded(json_safe({
        "thermal": "effective", "inlet_temperature": j.oil.inlet_temperature,
        "effective_temperature": effective.temperature, "temperature_rise": effective.rise,
        "inlet_viscosity": j.oil_viscosity, "effective_viscosity": effective.viscosity})))
    summary["units"].update({"inlet_temperature": "degC", "effective_temperature": "degC", "temperature_rise": "K",
                             "inlet_viscosity": "Pa s", "effective_viscosity": "Pa s"})
    return summary, film, curve


def _isothermal_summary(spec: JournalSpec) -> tuple[dict, FilmSolution, list]:
    j = spec.journal
    bearing, supply = bearing_of(spec)
    grid = FilmGrid.build(bearing, *j.grid)

    def solve(state):
        return solve_film(bearing, state, supply, grid, j.cavitation)

    def force(state):
        return solve(state).force

    state = state_at(spec, j.eccentricity_ratio)
    film = solve(state)
    stiffness, damping = dynamic_coefficients(force, state, j.radial_clearance)
    curve = [(eps, solve(state_at(spec, eps)).load_capacity, static_stiffness(force, state_at(spec, eps),
                                                                            j.radial_clearance))
             for eps in CURVE_ECCENTRICITIES]
    stiff = static_stiffness(force, state, j.radial_clearance)
    h_min = float(grid.land_film(grid.theta, state.eccentricity).min())
    checks = journal_checks(spec, bearing, supply, grid, state, film, h_min)
    speeds = coefficients_over_speed(force, j.radial_clearance, j.static_load, j.coefficient_speeds_rpm)
    if speeds:
        checks.append(speed_equilibria(speeds))
    summary = {
        "scenario": spec.scenario.name, "model": spec.scenario.model, **status_entries(checks),
        "cavitation": j.cavitation,
        "grid": list(j.grid), "eccentricity_ratio": j.eccentricity_ratio, "speed_rpm": j.speed_rpm,
        "load_capacity": film.load_capacity, "force": film.force.tolist(), "attitude_angle": film.attitude_angle,
        "flow": film.supply_flow if supply is not None else film.edge_outflow,
        "friction_torque": film.friction_torque, "friction_power": film.friction_power,
        "recess_pressures": film.recess_pressures.tolist(), "recess_flows": film.supply_flows.tolist(),
        "recess_areas": grid.recess_areas.tolist(),
        "stiffness": stiffness.tolist(), "damping": damping.tolist(), "static_stiffness": stiff,
        "static_stiffness_per_eccentricity_ratio": stiff * j.radial_clearance,
        "min_film_thickness": h_min, "max_pressure": float(film.load_pressure.max()),
        "mass_balance_error": mass_balance_error(j, film),
        "load_curve": [list(row) for row in curve],
        "taylor_number": taylor_number(j),
    }
    if speeds:
        summary["coefficients_over_speed"] = speeds
    if j.recesses is not None and j.recesses.design_pressure_ratio is not None:
        summary["design_pressure_ratio"] = j.recesses.design_pressure_ratio
        summary["sized_bore"] = {SIZED_BORE[j.recesses.restrictor]: supply.restrictor.diameter}
    reynolds = largest_capillary_reynolds(j, film, supply)
    if reynolds is not None:
        summary["capillary_reynolds"] = reynolds
    summary.update(_network(spec, bearing, supply, film))
    summary["units"] = {key: unit for key, unit in UNITS.items() if key in summary}
    return rounded(json_safe(summary)), film, curve


def _network(spec, bearing, supply, film) -> dict:
    j, r = spec.journal, spec.journal.recesses
    aligned = j.eccentricity_ratio == 0 or math.isclose((j.attitude - r.first_angle) % 360, 0, abs_tol=1e-9) \
        if r is not None else False
    restrictor = getattr(supply, "restrictor", None)
    if not (aligned and isinstance(restrictor, Capillary) and restrictor.linear and j.speed == 0 and r.count > 1):
        return {}
    resistance = capillary_resistance(supply.restrictor.length, supply.restrictor.diameter, j.oil_viscosity)
    pressures, _ = network_recess_pressures(bearing, j.eccentricity_ratio, supply.pressure, resistance)
    return {"network_recess_pressures": pressures.tolist(),
            "network_difference": float(np.max(np.abs(pressures / film.recess_pressures - 1)))}


def write_journal(spec: JournalSpec, directory: str | Path, figures: bool = True) -> dict:
    """Solve the scenario and write ``summary.json`` (and the figures) to ``directory``. A film whose solve does not
    settle (:class:`~bearing_mbs.fluid_film.reynolds.FilmNotConverged`) gives a ``failed`` summary that says why,
    without figures."""
    directory = Path(directory)
    directory.mkdir(parents=True, exist_ok=True)
    try:
        summary, film, curve = journal_summary(spec)
    except (FilmNotConverged, TooHot) as error:
        fix = "" if isinstance(error, TooHot) else ". Likely fix: journal.cavitation = 'gumbel' or a finer journal.grid"
        summary = {"scenario": spec.scenario.name, "model": spec.scenario.model,
                   **status_entries((), f"{error}{fix}")}
        write_json(directory / SUMMARY_FILE, summary)
        return summary
    write_json(directory / SUMMARY_FILE, summary)
    if "coefficients_over_speed" in summary:
        write_table(summary["coefficients_over_speed"], directory / "coefficients.csv")
    if figures:
        note = status_note(summary)
        if "coefficients_over_speed" in summary:
            plot_speeds(summary["coefficients_over_speed"], spec.scenario.name, directory / "coefficients.png", note)
        _plot_pressure(spec, film, directory / "pressure_map.png", note)
        _plot_curve(spec, curve, directory / "load_curve.png", note)
    return summary


def _plot_pressure(spec, film, path, note=None):
    figure, axis = new_figure(figsize=(8, 4))
    grid = film.grid
    image = axis.pcolormesh(np.degrees(grid.theta), grid.z * 1e3, film.load_pressure.T / 1e6, shading="nearest",
                            cmap="viridis")
    figure.colorbar(image, ax=axis, label="pressure [MPa]")
    axis.set_xlabel("θ [deg] (from +x)")
    axis.set_ylabel("z [mm]")
    axis.set_title(f"{spec.scenario.name}: ε = {spec.journal.eccentricity_ratio:g}, "
                   f"{spec.journal.speed_rpm:g} rpm, {film.cavitation}")
    return save_figure(figure, path, status_note=note)


def _plot_curve(spec, curve, path, note=None):
    eps, load, stiffness = np.array(curve).T
    figure, (loads, stiff) = new_figure(2, 1, figsize=(7, 6), sharex=True)
    loads.plot(eps, load, "o-")
    loads.set_ylabel("load capacity [N]")
    stiff.plot(eps, stiffness / 1e6, "o-")
    stiff.set_ylabel("static stiffness ΔF/Δe [N/µm]")
    stiff.set_xlabel("eccentricity ratio ε")
    for axis in (loads, stiff):
        axis.grid(True, alpha=0.3)
    loads.set_title(f"{spec.scenario.name}: C = {spec.journal.radial_clearance * 1e6:g} µm, "
                    f"{spec.journal.speed_rpm:g} rpm")
    return save_figure(figure, path, status_note=note)
