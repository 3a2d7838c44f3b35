"""The stability suite's variations of a bearing scenario (:data:`CASES`) and the solvers it probes."""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass

from bearing_mbs.core.topology import Group
from bearing_mbs.spec import Spec

CONTACT_GROUPS = (Group.INNER_RACE, Group.OUTER_RACE, Group.POCKET, Group.LAND, Group.ROLLER)
FORCE_GROUPS = (Group.INNER_RACE, Group.OUTER_RACE, Group.POCKET)  # the groups whose stiffness a case scales


@dataclass(frozen=True)
class Case:
    """A variation of the base scenario: ``change`` edits its mapping (a copy) in place."""

    name: str
    description: str
    change: Callable[[dict, Spec], None] = lambda data, spec: None


def _contact(data, key, value, groups=CONTACT_GROUPS):
    for group in groups:
        data["contact"][group][key] = value


def _stiffness(factor):
    def change(data, spec):
        from bearing_mbs.models.cylindrical_roller.build import group_law
        from bearing_mbs.models.cylindrical_roller.geometry import BearingGeometry

        geometry = BearingGeometry.from_spec(spec.bearing)
        for group in FORCE_GROUPS:
            law = group_law(spec, geometry, group)
            data["contact"][group].update(stiffness_model="given", stiffness=factor * law.stiffness,
                                          exponent=law.exponent)
    return change


def _raceways(clearance=None, rollers=None, roller_diameter=None, pocket_clearance=None):
    """Change the raceway description to pitch diameter and clearance (so the other numbers follow)."""
    def change(data, spec):
        bearing = data["bearing"]
        for key in ("inner_race_diameter", "outer_race_diameter"):
            bearing.pop(key, None)
        bearing["pitch_diameter"] = spec.bearing.pitch
        bearing["diametral_clearance"] = spec.bearing.clearance if clearance is None else clearance
        if rollers is not None:
            bearing["rollers"] = rollers
        if roller_diameter is not None:
            bearing["roller_diameter"] = roller_diameter(spec)
        if pocket_clearance is not None:
            bearing["pocket_clearance"] = pocket_clearance
    return change


def _speed(rpm):
    def change(data, spec):
        data["drive"].update(kind="speed", profile="constant", speed_rpm=rpm)
    return change


def _load(factor):
    def change(data, spec):
        data["load"]["radial"] = factor * spec.load.radial
    return change


def _thirty_rollers(spec):
    """A roller diameter that lets 30 rollers and their pockets fit: 80 % of the chord, less the pocket play."""
    chord = spec.bearing.pitch * math.sin(math.pi / 30)
    return math.floor((0.8 * chord - 2 * spec.bearing.pocket_clearance) * 1e4) / 1e4


def _full_complement(data, spec):
    """No cage, and as many rollers as fit on the pitch circle with 0.4 mm or more between neighbours."""
    d_w = spec.bearing.roller_diameter
    rollers = int(math.pi / math.asin((d_w + 4e-4) / spec.bearing.pitch))
    _raceways(rollers=rollers, pocket_clearance=1e-4)(data, spec)
    data["cage"]["model"] = "none"


CASES = (
    Case("nominal", "the base scenario"),
    Case("stiffness x0.01", "raceway and pocket stiffness x0.01", _stiffness(0.01)),
    Case("stiffness x0.1", "raceway and pocket stiffness x0.1", _stiffness(0.1)),
    Case("stiffness x10", "raceway and pocket stiffness x10", _stiffness(10.0)),
    Case("stiffness x100", "raceway and pocket stiffness x100", _stiffness(100.0)),
    Case("v_reg 1e-1", "friction regularisation speed 0.1 m/s", lambda d, s: _contact(d, "regularisation_speed", 0.1)),
    Case("v_reg 1e-3", "friction regularisation speed 1e-3 m/s",
         lambda d, s: _contact(d, "regularisation_speed", 1e-3)),
    Case("v_reg 1e-4", "friction regularisation speed 1e-4 m/s",
         lambda d, s: _contact(d, "regularisation_speed", 1e-4)),
    Case("restitution 0.1", "restitution 0.1 (strong contact damping)", lambda d, s: _contact(d, "restitution", 0.1)),
    Case("restitution 1.0", "restitution 1 (no contact damping)", lambda d, s: _contact(d, "restitution", 1.0)),
    Case("5000 rpm", "inner ring at 5000 rpm", _speed(5000.0)),
    Case("10000 rpm", "inner ring at 10 000 rpm", _speed(10000.0)),
    Case("zero load", "no radial load (the ring's weight only)", _load(0.0)),
    Case("5x load", "five times the radial load", _load(5.0)),
    Case("preload", "diametral preload 40 µm", _raceways(clearance=-4e-5)),
    Case("clearance 200 µm", "diametral clearance 200 µm", _raceways(clearance=2e-4)),
    Case("Z = 8", "8 rollers", _raceways(rollers=8)),
    Case("Z = 30", "30 smaller rollers", _raceways(rollers=30, roller_diameter=_thirty_rollers)),
    Case("full complement", "no cage, rollers side by side", _full_complement),
)
CASE_NAMES = tuple(case.name for case in CASES)
#: The reduced suite of the default tests.
REDUCED_CASES = ("nominal", "stiffness x100", "v_reg 1e-1", "restitution 0.1", "clearance 200 µm")

#: (engine, method) of the full suite, and of the reduced one.
SOLVERS = (
    ("reference", "central_difference"), ("reference", "velocity_verlet"), ("reference", "rk4"),
    ("reference", "dopri5"), ("exudyn", "generalized_alpha"), ("exudyn", "rk4"), ("exudyn", "dopri5"),
)
REDUCED_SOLVERS = (("reference", "central_difference"), ("reference", "velocity_verlet"), ("reference", "rk4"),
                   ("exudyn", "generalized_alpha"))

#: Convergence orders, for the energy audit's convergence check (adaptive methods: order 1 in the tolerance).
ORDERS = {("reference", "central_difference"): 1, ("reference", "velocity_verlet"): 2, ("reference", "rk4"): 4,
          ("exudyn", "rk4"): 4, ("exudyn", "generalized_alpha"): 2, ("exudyn", "trapezoidal_index2"): 2,
          ("exudyn", "velocity_verlet"): 2, ("exudyn", "rk33"): 3, ("exudyn", "rk67"): 6}

ADAPTIVE = {("reference", "dopri5"), ("exudyn", "dopri5"), ("exudyn", "ode23"), ("exudyn", "dverk6")}
IMPLICIT = {("exudyn", "generalized_alpha"), ("exudyn", "trapezoidal_index2")}
