"""The stability suite's variations of a bearing scenario (:data:`CASES`, :mod:`bearing_mbs.studies.stability`):
contact stiffness ×0.01 to ×100, v_reg 0.1 to 1e-4 m/s, restitution 0.1 and 1, speed to 10 000 rpm, zero and 5×
load, preload and 200 µm clearance, Z = 8 and 30, a full complement."""

from __future__ import annotations

import math

from bearing_mbs.core.topology import Group
from bearing_mbs.models.cylindrical_roller.build import group_law
from bearing_mbs.models.cylindrical_roller.geometry import BearingGeometry
from bearing_mbs.models.cylindrical_roller.spec import CONTACT_GROUPS
from bearing_mbs.models.protocol import StabilityCase, StabilitySuite

FORCE_GROUPS = (Group.INNER_RACE, Group.OUTER_RACE, Group.POCKET)  # the groups whose stiffness a case scales


def _contact(data, key, value, groups=CONTACT_GROUPS):
    for group in groups:
        data["contact"][group][key] = value


def _stiffness(factor):
    def change(data, spec):
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
    StabilityCase("nominal", "the base scenario"),
    StabilityCase("stiffness x0.01", "raceway and pocket stiffness x0.01", _stiffness(0.01)),
    StabilityCase("stiffness x0.1", "raceway and pocket stiffness x0.1", _stiffness(0.1)),
    StabilityCase("stiffness x10", "raceway and pocket stiffness x10", _stiffness(10.0)),
    StabilityCase("stiffness x100", "raceway and pocket stiffness x100", _stiffness(100.0)),
    StabilityCase("v_reg 1e-1", "friction regularisation speed 0.1 m/s", lambda d, s: _contact(d, "regularisation_speed", 0.1)),
    StabilityCase("v_reg 1e-3", "friction regularisation speed 1e-3 m/s",
         lambda d, s: _contact(d, "regularisation_speed", 1e-3)),
    StabilityCase("v_reg 1e-4", "friction regularisation speed 1e-4 m/s",
         lambda d, s: _contact(d, "regularisation_speed", 1e-4)),
    StabilityCase("restitution 0.1", "restitution 0.1 (strong contact damping)", lambda d, s: _contact(d, "restitution", 0.1)),
    StabilityCase("restitution 1.0", "restitution 1 (no contact damping)", lambda d, s: _contact(d, "restitution", 1.0)),
    StabilityCase("5000 rpm", "inner ring at 5000 rpm", _speed(5000.0)),
    StabilityCase("10000 rpm", "inner ring at 10 000 rpm", _speed(10000.0)),
    StabilityCase("zero load", "no radial load (the ring's weight only)", _load(0.0)),
    StabilityCase("5x load", "five times the radial load", _load(5.0)),
    StabilityCase("preload", "diametral preload 40 µm", _raceways(clearance=-4e-5)),
    StabilityCase("clearance 200 µm", "diametral clearance 200 µm", _raceways(clearance=2e-4)),
    StabilityCase("Z = 8", "8 rollers", _raceways(rollers=8)),
    StabilityCase("Z = 30", "30 smaller rollers", _raceways(rollers=30, roller_diameter=_thirty_rollers)),
    StabilityCase("full complement", "no cage, rollers side by side", _full_complement),
)
#: The reduced suite of the default tests.
REDUCED_CASES = ("nominal", "stiffness x100", "v_reg 1e-1", "restitution 0.1", "clearance 200 µm")
#: The bearing's stability suite (:class:`~bearing_mbs.models.protocol.StabilitySuite`).
STABILITY = StabilitySuite(cases=CASES, reduced=REDUCED_CASES)
