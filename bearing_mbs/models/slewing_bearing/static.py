"""``bearing-mbs slewing``: the quasi-static load distribution of a slewing-bearing scenario, written as
``summary.json`` (SI units, its ``units`` map) and figures.

* with a load: the inner ring's displacement, the ball loads and contact angles around the ring, the largest
  ball load and contact pressure (exact Hertz, :mod:`bearing_mbs.contact.point_contact`), the 3×3 stiffness;
* with ``axial_displacements``: the axial load–deflection curve, drawn with the engineering formula (3) of
  document 002 for comparison (with flexible rings, the rigid rings' curve beside it).

The summary's ``status`` and ``checks`` (docs/status.md) say whether the numbers can be used: enough balls to hold
the ring, the equilibrium reached, the contact pressure within the elastic range.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np

from bearing_mbs.contact.line_contact import reduced_modulus
from bearing_mbs.contact.point_contact import ball_groove_curvatures, hertz_contact
from bearing_mbs.core.checks import Check, equilibrium_residual, lower_bound, upper_bound
from bearing_mbs.core.status import status_entries, status_note
from bearing_mbs.io.json import json_safe, rounded, write_json
from bearing_mbs.models.slewing_bearing.figures import plot_axial_curve, plot_ball_loads
from bearing_mbs.models.slewing_bearing.flexible import FlexibleRings
from bearing_mbs.models.slewing_bearing.load_distribution import Distribution, NotConverged, SlewingBearing, solve
from bearing_mbs.models.slewing_bearing.spec import SlewingSpec
from bearing_mbs.spec import SpecError

SUMMARY_FILE = "summary.json"
#: Fewest balls that hold a ring in all its degrees of freedom: balls at three azimuths or more, not on one diameter
#: (with fewer, the ring tilts freely about the line through them; the planar model's stiffness is singular).
MIN_BALLS = 3
#: Largest contact pressure [Pa] of the elastic (Hertz) contacts: ISO 76's static load rating of ball bearings
#: (other than self-aligning) is the load at 4200 MPa, where the permanent deformation of ball and raceway is about
#: 1e-4 of the ball diameter; beyond it the raceways yield, which the elastic model leaves out.
MAX_CONTACT_PRESSURE = 4200e6
UNITS = {"displacement": "m, m, rad", "load": "N, N, N m", "stiffness": "each entry's own unit",
         "axial_curve": "m, N", "max_ball_load": "N", "max_contact_pressure": "Pa", "ball_loads": "N",
         "contact_angles": "deg", "azimuths": "deg", "balls": "count", "diagonal_stiffness": "N/m^1.5",
         "rigid_axial_curve": "m, N", "rigid_ball_loads": "N", "rigid_contact_angles": "deg",
         "finite_element_axial_curve": "m, N", "state_displacement": "m, m, rad",
         "rigid_displacement": "m, m, rad"}
#: The bearing's loads and coordinates, for the names and units of the stiffness's entries ∂load/∂coordinate.
LOADS = (("radial_force", "N"), ("axial_force", "N"), ("moment", "N m"))
COORDINATES = (("radial", "m"), ("axial", "m"), ("tilt", "rad"))
#: The finite-element axial curve of the thesis's validation (I. Fernández Apezteguia, bachelor's thesis, UPV/EHU
#: 2019: a sector of inner ring, ball and outer ring in ANSYS, frictional contacts, the inner ring clamped at its
#: bolted face and the outer ring displaced through its own; forces read as kN): displacement [m], force [N]. It
#: belongs to the bearing of :data:`VALIDATION_BEARING` (D_pw [m], D_w [m], conformity).
FINITE_ELEMENT_AXIAL_CURVE = tuple((0.042e-3 * n, force * 1e3) for n, force in enumerate(
    (277, 787, 1485, 2340, 3346, 4503, 5801, 7241, 8834, 10558), start=1))
VALIDATION_BEARING = (1.5, 0.035, 0.943)


def bearing_of(spec: SlewingSpec) -> SlewingBearing:
    """The bearing of the scenario's ``[slewing]`` section (an error names the section's field)."""
    s = spec.slewing
    try:
        return SlewingBearing(s.pitch_diameter, s.ball_diameter, s.conformity, spec.contact_angle_rad, s.balls)
    except SpecError as error:
        raise error.within("slewing") from None


def rings_of(spec: SlewingSpec) -> FlexibleRings | None:
    """The flexible rings of the scenario, or None for rigid rings."""
    s = spec.slewing
    return FlexibleRings.of(s.pitch_diameter, s.mount, s.coefficients, s.coupling) if s.rings == "flexible" else None


def largest_pressure(spec: SlewingSpec, state: Distribution) -> float:
    """The largest contact pressure [Pa] over the balls' inner and outer contacts (exact Hertz at each loaded
    contact's angle)."""
    s = spec.slewing
    modulus = reduced_modulus(s.youngs_modulus, s.poisson_ratio, s.youngs_modulus, s.poisson_ratio)
    k, d = np.unravel_index(int(np.argmax(state.ball_loads)), state.ball_loads.shape)
    load = state.ball_loads[k, d]
    if load <= 0:
        return 0.0
    return max(hertz_contact(load, ball_groove_curvatures(s.ball_diameter, s.conformity, s.pitch_diameter,
                                                          state.contact_angles[k, d], ring), modulus).p_max
               for ring in ("inner", "outer"))


def slewing_summary(spec: SlewingSpec) -> tuple[dict, list[Distribution]]:
    """The summary (with ``status`` and ``checks``, docs/status.md) and the solved states (none when the solver
    did not converge: the summary is then ``failed`` and says why)."""
    bearing = bearing_of(spec)
    rings = rings_of(spec)
    summary = {"scenario": spec.scenario.name, "balls": bearing.balls, "diagonal_stiffness": bearing.stiffness,
               "rings": spec.slewing.rings}
    if rings is not None:
        summary["mount"], summary["coupling"] = spec.slewing.mount, spec.slewing.coupling
    count = lower_bound("ball_count", bearing.balls, MIN_BALLS, "count",
                        f"{bearing.balls} ball(s) cannot hold the ring: it tilts freely about the line through them. "
                        f"Likely fix: slewing.balls >= {MIN_BALLS} (or leave it out: as many as fit, "
                        f"{ball_count_that_fits(spec)})")
    try:
        checks, states = _solve(spec, bearing, rings, summary)
    except NotConverged as error:
        summary = {"scenario": spec.scenario.name, **status_entries([count], f"{error}. Likely fix: "
                                                                    f"slewing.balls >= {MIN_BALLS}, a smaller load"
                                                                    + (" or rings = 'rigid'" if rings else "")),
                   **summary}
        return rounded(json_safe(summary)), []
    summary = {"scenario": spec.scenario.name, **status_entries([count, *checks]), **summary}
    summary["units"] = {key: unit for key, unit in UNITS.items() if key in summary}
    return rounded(json_safe(summary)), states


def ball_count_that_fits(spec: SlewingSpec) -> int:
    """The balls that fit side by side on the pitch circle (the default of ``slewing.balls``)."""
    from bearing_mbs.models.slewing_bearing.geometry import ball_count

    return ball_count(spec.slewing.pitch_diameter, spec.slewing.ball_diameter)


def _solve(spec: SlewingSpec, bearing: SlewingBearing, rings, summary: dict) -> tuple[list[Check], list]:
    """Solve the curve or the load case into ``summary``; returns the checks of the solution and the states."""
    load = spec.load
    checks = []
    if load.axial_displacements:
        states = [solve(bearing, imposed={"radial": 0.0, "axial": d, "tilt": 0.0}, rings=rings)
                  for d in load.axial_displacements]
        summary["axial_curve"] = [[d, float(state.load[1])] for d, state in zip(load.axial_displacements, states)]
        if rings is not None:
            summary["rigid_axial_curve"] = [[d, float(solve(bearing, imposed={"radial": 0.0, "axial": d,
                                                                              "tilt": 0.0}).load[1])]
                                            for d in load.axial_displacements]
    else:
        target = np.array([load.radial, load.axial, load.moment])
        states = [solve(bearing, target, rings=rings)]
        summary["displacement"] = states[0].displacement.tolist()
        summary["load"] = states[0].load.tolist()
        scale = max(np.abs(target).max(), states[0].ball_loads.sum())
        checks.append(equilibrium_residual(float(np.abs(states[0].load - target).max() / scale),
                                           "the inner ring's equilibrium was not reached. Likely fix: slewing.balls "
                                           f">= {MIN_BALLS}, or a smaller load"))
    last = max(states, key=lambda state: state.ball_loads.max())
    pressure = largest_pressure(spec, last)
    summary.update({
        "max_ball_load": float(last.ball_loads.max()),
        "max_contact_pressure": pressure,
        "state_displacement": last.displacement.tolist(),
        "stiffness": named_stiffness(last.stiffness),
        "azimuths": np.degrees(last.azimuths).tolist(),
        "ball_loads": last.ball_loads.tolist(),
        "contact_angles": np.degrees(last.contact_angles).tolist(),
    })
    if rings is not None:  # the rigid rings beside: at the same displacement on a curve, at the same load otherwise
        rigid = (solve(bearing, imposed=dict(zip(("radial", "axial", "tilt"), last.displacement)))
                 if load.axial_displacements else solve(bearing, target))
        summary["rigid_displacement"] = rigid.displacement.tolist()
        summary["rigid_ball_loads"] = rigid.ball_loads.tolist()
        summary["rigid_contact_angles"] = np.degrees(rigid.contact_angles).tolist()
    if load.axial_displacements and is_validation_bearing(spec):
        summary["finite_element_axial_curve"] = [list(point) for point in FINITE_ELEMENT_AXIAL_CURVE]
    ratio = MAX_CONTACT_PRESSURE / pressure if pressure > 0 else 1.0
    # Hertz: p ∝ Q^(1/3) and Q ∝ δ^(3/2), so p ∝ δ^(1/2)
    fix = (f"load.axial_displacements up to about {ratio ** 2 * max(load.axial_displacements):.3g} m"
           if load.axial_displacements else f"a load about {ratio ** 3:.3g} times the present one")
    checks.append(upper_bound("contact_pressure", pressure, MAX_CONTACT_PRESSURE, "Pa",
                              f"the most loaded ball's contact reaches {pressure / 1e6:.4g} MPa, beyond ISO 76's "
                              f"{MAX_CONTACT_PRESSURE / 1e6:g} MPa: the raceways yield, which the elastic (Hertz) "
                              f"contacts leave out. Likely fix: {fix}, or a larger slewing.ball_diameter"))
    return checks, states


def named_stiffness(stiffness: np.ndarray) -> dict:
    """The 3×3 stiffness ∂load/∂coordinate as named entries, each with its value and unit."""
    return {f"d_{load}/d_{coordinate}": {"value": float(stiffness[i, j]), "unit": f"{load_unit}/{unit}"}
            for i, (load, load_unit) in enumerate(LOADS) for j, (coordinate, unit) in enumerate(COORDINATES)}


def is_validation_bearing(spec: SlewingSpec) -> bool:
    """Whether the scenario's bearing is the one of the thesis's finite-element validation."""
    s = spec.slewing
    return all(math.isclose(a, b, rel_tol=1e-9) for a, b in zip((s.pitch_diameter, s.ball_diameter, s.conformity),
                                                                 VALIDATION_BEARING))


def write_slewing(spec: SlewingSpec, directory: str | Path, figures: bool = True) -> dict:
    """Solve the scenario and write ``summary.json`` (and the figures) to ``directory``."""
    directory = Path(directory)
    directory.mkdir(parents=True, exist_ok=True)
    summary, states = slewing_summary(spec)
    write_json(directory / SUMMARY_FILE, summary)
    if figures and states:
        note = status_note(summary)
        plot_ball_loads(spec, summary, directory / "ball_loads.png", note)
        if spec.load.axial_displacements:
            plot_axial_curve(spec, summary, directory / "axial_curve.png", note)
    return summary
