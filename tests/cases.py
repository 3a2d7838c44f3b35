"""Shared factories for verification cases: the same specs and scenes feed tests, benchmarks and docs.

* :func:`seed_spec` — the primary document's five cases, from ``scenarios/seed_caseN.toml``;
* :func:`single_impact_spec` — one normal impact without gravity, for the restitution closed form;
* :func:`ball_in_ring_scene` — a smooth problem (permanent contact, smooth friction) for order tests.
"""

from __future__ import annotations

import math
from pathlib import Path

from bearing_mbs.core.scene import GROUND, Body, ContactPair, Scene
from bearing_mbs.models import load_spec, spec_from_mapping
from bearing_mbs.models.building import pair_law
from bearing_mbs.spec import ContactSpec, Spec

SCENARIOS = Path(__file__).resolve().parents[1] / "scenarios"


def seed_spec(case: int, overrides: list[str] = ()) -> Spec:
    """Spec of the document's case 1–5 (``scenarios/seed_case{case}.toml``), with ``--set``-style overrides."""
    return load_spec(SCENARIOS / f"seed_case{case}.toml", list(overrides))


def single_impact_spec(normal_law: str, exponent: float, restitution: float, *, impact_speed: float = 1.0,
                       solver: dict | None = None) -> Spec:
    """A 0.1 kg, 5 mm ball hitting the floor at ``impact_speed`` [m/s] without gravity (K = 6e6 N/m^n).

    It starts 0.1 mm above the floor; contact lasts a few milliseconds; the run ends at 12 ms, after the
    separation, so the rebound speed is the separation speed.
    """
    radius = 0.005
    return spec_from_mapping({
        "scenario": {"name": f"impact_{normal_law}_{exponent:.3g}_{restitution}", "model": "balls",
                     "end_time": 0.012, "gravity": 0.0},
        "solver": solver or {},
        "box": {"floor": 0.0},
        "contact": {"wall": {"normal_law": normal_law, "stiffness": 6e6, "exponent": exponent,
                             "restitution": restitution}},
        "balls": [{"mass": 0.1, "radius": radius, "position": [0.0, radius + 1e-4], "velocity": [0.0, -impact_speed],
                   "free": ["y"]}],
    })


def ball_in_ring_scene(friction_law: str = "erf") -> Scene:
    """A ball (0.1 kg, r = 10 mm) pressed by gravity into a fixed ring (R = 50 mm), starting 20° from the
    bottom, in contact, at rest.

    It rocks like a pendulum while slipping and rolling. The contact never opens (the penetration stays near
    its static value, about 45 µm), the normal law is the plain power law K δ^1.5 (no latched state) and the
    friction is smooth, so the solution is smooth: the right problem for measuring integrator orders. Friction
    (μ = 0.3, v_reg = 0.05 m/s) and rolling resistance make the forces velocity-dependent.
    """
    mass, radius, ring = 0.1, 0.01, 0.05
    law = pair_law(ContactSpec(normal_law="power", stiffness=1e7, exponent=1.5, friction_law=friction_law,
                               friction_coefficient=0.3, regularisation_speed=0.05, rolling_resistance_arm=1e-4))
    static_penetration = (mass * 10.0 / law.stiffness) ** (1 / law.exponent)
    distance = ring - radius + static_penetration
    angle = math.radians(-90 + 20)
    ball = Body("ball", mass, 0.4 * mass * radius**2, (distance * math.cos(angle), distance * math.sin(angle), 0.0))
    pair = ContactPair("ball-ring", "circle_in_circle", GROUND, 0, law, radius_b=radius, radius_a=ring)
    return Scene("ball_in_ring", (ball,), (pair,), gravity=(0.0, -10.0))


#: Initial state of :func:`dumbbell_spec`: centres (m), centre-of-mass velocity (m/s), rotation rate (rad/s).
DUMBBELL = {"centres": ((0.015, 0.02), (0.02, 0.04)), "velocity": (0.1, 0.2), "rate": 10.0}


def dumbbell_spec(solver: dict, end_time: float = 0.2) -> Spec:
    """Case 5's two balls joined by their rigid distance, tumbling in free flight under gravity (10 m/s²).

    No box: the centre of mass follows a parabola and the connecting vector turns at the constant rate
    ``DUMBBELL['rate']``, a closed form for checking constrained integration.
    """
    (xa, ya), (xb, yb) = DUMBBELL["centres"]
    cx, cy = (xa + xb) / 2, (ya + yb) / 2
    vx, vy = DUMBBELL["velocity"]
    rate = DUMBBELL["rate"]

    def velocity(x, y):  # rigid rotation about the centre of mass
        return [vx - rate * (y - cy), vy + rate * (x - cx)]

    return spec_from_mapping({
        "scenario": {"name": "dumbbell", "model": "balls", "end_time": end_time, "gravity": 10.0},
        "solver": solver,
        "balls": [{"mass": 0.1, "radius": 0.005, "position": [x, y], "velocity": velocity(x, y)}
                  for x, y in DUMBBELL["centres"]],
        "constraints": [{"bodies": [0, 1]}],
    })
