r"""The quasi-static solution of a bearing scenario: what ``bearing-mbs stiffness`` writes.

A ``bearing`` scenario is turned into the inputs of
:func:`bearing_mbs.models.cylindrical_roller.quasistatic.solve_radial`:

* **rollers**: :meth:`bearing_mbs.models.cylindrical_roller.quasistatic.RollerSet.from_geometry` (Palmgren raceway
  laws, the same clearance and roller mass as the dynamic model). When the scenario's raceway laws are not Palmgren's
  (``stiffness_model = "given"`` or ``"document"``, or non-steel materials), the rollers get the scenario's
  :math:`K, n` instead, and ``raceway_law`` in the summary says so.
* **load**: ``[load] radial`` at ``[load] angle`` on the inner ring (for ``step`` and ``table`` profiles too:
  use ``--set load.radial=...`` for another level), plus the inner ring's weight
  :math:`m_i g` along −y when ``[scenario] gravity`` > 0 (:math:`m_i` includes ``supported_mass``):
  :func:`carried_load`, the one place that adds the weight, for the step advisor's linearisation too. The
  rollers' and the cage's weights are left out: the rollers pass theirs to the outer ring (at most
  :math:`m_r g` ≈ 2 N per roller for the seed bearing) and a roller-guided cage hangs on the rollers.
* **speed**: the drive's steady speed (:func:`bearing_mbs.models.cylindrical_roller.drivetrain.steady_speed`:
  ``[drive] speed_rpm``, the end of a ramp, the last entry of a table) for the rollers' centrifugal force
  :math:`F_c = m_r (D_{pw}/2)\omega_c^2`; 0 gives none.
* **roller phase**: roller 0 sits on the load line (``first_roller_angle`` = the load's direction), the
  configuration of the largest roller load that a turning bearing passes through.

The summary's ``status`` and ``checks`` (:func:`stiffness_checks`; docs/status.md) say whether its numbers can be
used.
"""

from __future__ import annotations

import math
from dataclasses import replace
from pathlib import Path

import numpy as np

from bearing_mbs.core.checks import Check, equilibrium_residual, lower_bound, upper_bound
from bearing_mbs.core.status import status_entries, status_note
from bearing_mbs.core.topology import Group
from bearing_mbs.io.json import json_safe, rounded, write_json
from bearing_mbs.models.cylindrical_roller.build import group_law
from bearing_mbs.models.cylindrical_roller.drivetrain import RPM, steady_speed
from bearing_mbs.models.cylindrical_roller.geometry import BearingGeometry
from bearing_mbs.models.cylindrical_roller.quasistatic import RollerSet, plot_load_distribution, solve_radial
from bearing_mbs.models.cylindrical_roller.spec import static_load_rating
from bearing_mbs.spec import Spec, SpecError

SUMMARY_FILE = "summary.json"
FIGURE_FILE = "load_distribution.png"
#: Fewest loaded rollers for a 2×2 stiffness: one roller resists the ring only along its own line, so the stiffness
#: across it is zero and the matrix singular.
MIN_LOADED_ROLLERS = 2
#: Largest load over the ISO 76 static load rating C0 (:func:`~.spec.static_load_rating`) [-]: at C0 the most loaded
#: contact of a roller bearing reaches 4000 MPa and deforms permanently by 1e-4 of the roller diameter; beyond it
#: the raceways yield, which Palmgren's elastic law leaves out.
MAX_STATIC_LOAD_RATIO = 1.0


def require_bearing(spec: Spec) -> None:
    if spec.scenario.model != "cylindrical_roller":
        raise SpecError("scenario.model", spec.scenario.model,
                        "the quasi-static solver needs model = 'cylindrical_roller'")


def ring_weight(spec: Spec) -> float:
    """Weight of the inner ring and its supported mass [N], 0 without gravity."""
    return spec.scenario.gravity * BearingGeometry.from_spec(spec.bearing).inner_ring_mass


def carried_load(applied, ring_mass: float, gravity) -> np.ndarray:
    """(F_x, F_y) [N] the rollers carry: the ``applied`` load on the inner ring [N] (shape (2,) or a stack
    (..., 2)) plus the weight ``ring_mass`` [kg] × ``gravity`` (g_x, g_y) [m/s²] of the ring and its supported
    mass."""
    return np.asarray(applied, dtype=float) + ring_mass * np.asarray(gravity, dtype=float)


def quasi_static_load(spec: Spec, applied=None) -> np.ndarray:
    """(F_x, F_y) [N] the rollers carry: the applied radial load (default ``[load]``) plus the ring's weight."""
    if applied is None:
        angle = math.radians(spec.load.angle)
        applied = (spec.load.radial * math.cos(angle), spec.load.radial * math.sin(angle))
    ring_mass = BearingGeometry.from_spec(spec.bearing).inner_ring_mass
    return carried_load(applied, ring_mass, (0.0, -spec.scenario.gravity))


def quasi_static_rollers(spec: Spec, first_roller_angle: float = 0.0):
    """The scenario's bearing as a :class:`bearing_mbs.models.cylindrical_roller.quasistatic.RollerSet`, and the
    raceway-law label (``"palmgren"``, or ``"scenario"`` when the scenario's raceway laws replace Palmgren's)."""
    require_bearing(spec)
    geometry = BearingGeometry.from_spec(spec.bearing)
    rollers = replace(RollerSet.from_geometry(geometry), first_roller_angle=float(first_roller_angle))
    laws = {side: group_law(spec, geometry, group) for side, group in (("inner", Group.INNER_RACE),
                                                                  ("outer", Group.OUTER_RACE))}
    same = all(math.isclose(laws[side].stiffness, getattr(rollers, f"{side}_stiffness"), rel_tol=1e-12)
               and laws[side].exponent == getattr(rollers, f"{side}_exponent") for side in laws)
    if same:
        return rollers, "palmgren"
    return replace(rollers, inner_stiffness=laws["inner"].stiffness, inner_exponent=laws["inner"].exponent,
                   outer_stiffness=laws["outer"].stiffness, outer_exponent=laws["outer"].exponent), "scenario"


def solve_scenario(spec: Spec, applied=None, *, speed: float | None = None, first_roller_angle: float | None = None):
    """:func:`~bearing_mbs.models.cylindrical_roller.quasistatic.solve_radial` for the scenario: returns the solution
    and the law label.

    ``applied``: (F_x, F_y) [N] instead of ``[load]``; ``speed`` [rad/s] instead of the drive's;
    ``first_roller_angle`` [rad] instead of the load line.
    """
    load = quasi_static_load(spec, applied)
    if first_roller_angle is None:
        first_roller_angle = math.atan2(load[1], load[0]) if np.any(load) else 0.0
    rollers, law = quasi_static_rollers(spec, first_roller_angle)
    return solve_radial(rollers, load, shaft_speed=steady_speed(spec.drive) if speed is None else speed), law


def stiffness_summary(spec: Spec, solution, law: str) -> dict:
    """summary.json of ``bearing-mbs stiffness``: SI units (its ``units`` map), angles in degrees from +x towards +y
    in [0, 360) (the convention of every output)."""
    angles = np.mod(np.degrees(solution.roller_angles), 360.0)
    summary = {
        "scenario": spec.scenario.name,
        **status_entries(stiffness_checks(spec, solution)),
        "model": "quasi-static planar (solve_radial)",
        "raceway_law": law,
        "inner_stiffness": solution.rollers.inner_stiffness,
        "inner_exponent": solution.rollers.inner_exponent,
        "outer_stiffness": solution.rollers.outer_stiffness,
        "outer_exponent": solution.rollers.outer_exponent,
        "diametral_clearance": solution.rollers.diametral_clearance,
        "load": [float(v) for v in solution.load],
        "applied_radial_load": spec.load.radial,
        "applied_load_angle_deg": float(np.mod(spec.load.angle, 360.0)),
        "ring_weight": ring_weight(spec),
        "shaft_speed_rpm": solution.shaft_speed / RPM,
        "centrifugal_force": solution.centrifugal_force,
        "first_roller_angle_deg": float(np.mod(np.degrees(solution.rollers.first_roller_angle), 360.0)),
        "radial_displacement": float(np.hypot(*solution.displacement)),
        "displacement": [float(v) for v in solution.displacement],
        "roller_loads": [{"angle_deg": float(a), "load_N": float(q), "outer_load_N": float(qo)}
                         for a, q, qo in zip(angles, solution.inner_loads, solution.outer_loads)],
        "max_roller_load": solution.max_roller_load,
        "loaded_zone_half_angle_deg": float(np.degrees(solution.loaded_zone_half_angle)),
        "stiffness_matrix": [[float(v) for v in row] for row in solution.stiffness],
        "iterations": solution.iterations,
        "residual": solution.residual,
    }
    summary["units"] = {key: unit for key, unit in STIFFNESS_UNITS.items() if key in summary}
    return summary


def stiffness_checks(spec: Spec, solution) -> list[Check]:
    """The checks of a quasi-static solution (docs/status.md): the equilibrium reached, enough rollers loaded for a
    stiffness matrix, the load within the elastic range."""
    load = float(np.hypot(*solution.load))
    scale = max(load, float(np.sum(solution.inner_loads)))
    loaded = int(np.count_nonzero(solution.inner_loads > 0))
    rating = static_load_rating(spec.bearing)
    largest_load = MAX_STATIC_LOAD_RATIO * rating
    return [
        equilibrium_residual(solution.residual / scale if scale > 0 else 0.0,
                             f"the inner ring's equilibrium was reached only to {solution.residual:.3g} N on "
                             f"{load:.4g} N. Likely fix: a smaller bearing.diametral_clearance, or a larger load"),
        lower_bound("rollers_in_contact", loaded, MIN_LOADED_ROLLERS, "count",
                    f"{loaded} roller(s) carry the load: the ring has no stiffness across the load line. Likely fix: "
                    "less clearance (bearing.diametral_clearance <= 0 loads half the rollers) or a larger load.radial"),
        upper_bound("static_load_ratio", load / rating, MAX_STATIC_LOAD_RATIO, "-",
                    f"the load is {load / rating:.3g} times the bearing's static load rating C0 = {rating:.4g} N (ISO "
                    "76): the most loaded contact exceeds 4000 MPa and the raceways yield, which the elastic law "
                    f"leaves out. Likely fix: load.radial <= {largest_load:.4g} N"),
    ]


#: Units of the stiffness summary's entries.
STIFFNESS_UNITS = {
    "inner_stiffness": "N/m^n", "inner_exponent": "-", "outer_stiffness": "N/m^n", "outer_exponent": "-",
    "diametral_clearance": "m", "load": "N", "applied_radial_load": "N", "applied_load_angle_deg": "deg",
    "ring_weight": "N", "shaft_speed_rpm": "rpm", "centrifugal_force": "N", "first_roller_angle_deg": "deg",
    "radial_displacement": "m", "displacement": "m", "roller_loads": "angle_deg: deg, load_N: N, outer_load_N: N",
    "max_roller_load": "N", "loaded_zone_half_angle_deg": "deg", "stiffness_matrix": "N/m", "iterations": "count",
    "residual": "N",
}


def write_stiffness(spec: Spec, directory: str | Path, figures: bool = True) -> dict:
    """Solve the scenario quasi-statically; write ``summary.json`` and ``load_distribution.png`` to ``directory``."""
    solution, law = solve_scenario(spec)
    summary = stiffness_summary(spec, solution, law)
    directory = Path(directory)
    directory.mkdir(parents=True, exist_ok=True)
    summary = rounded(json_safe(summary))
    write_json(directory / SUMMARY_FILE, summary)
    if figures:
        speed = f", {summary['shaft_speed_rpm']:.4g} rpm" if solution.shaft_speed else ""
        plot_load_distribution(solution, directory / FIGURE_FILE,
                               title=f"{spec.scenario.name}: F = {np.hypot(*solution.load):.4g} N{speed}",
                               note=status_note(summary))
    return summary
