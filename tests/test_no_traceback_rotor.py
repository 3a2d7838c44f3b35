"""Property: ``bearing-mbs run`` on any valid rotor scenario (a rigid rotor on journal bearings) runs to a status or
refuses the input by name, never a traceback (tests/no_traceback.py says what is checked).

Drawn over the documented range of every key (docs/scenario-format.md, "Rotor scenarios", and
bearing_mbs/models/rotor/spec.py): the rotor's mass and polar inertia, 1 to 8 bearings, unbalance, an initial offset
of up to twice the clearance, the bearing's bore, length, clearance (up to D/2), viscosity, both film forces (the
map on small grids: each map solves Reynolds' equation at every node), speeds up to 1e6 rpm with or without a ramp,
the servo gain, gravity, and either engine with every integration method. Runs are short (at most 20 ms and about
300 steps).
"""

from __future__ import annotations

import math

from hypothesis import example, given
from hypothesis import strategies as st

from bearing_mbs.spec.solver import EXUDYN_METHODS, REFERENCE_METHODS

from no_traceback import PROFILE, log_uniform, run_command, solver_table, uniform

STEPS = 300
RPM = 1e6  # drive speeds in (0, 1e6] rpm


def solver(draw, end: float, engine: str, method: str) -> dict:
    table = solver_table(draw, end, engine, method, STEPS)
    if engine == "exudyn":
        table["exudyn"]["connector"] = draw(st.sampled_from(["compiled", "compiled", "python"]))
    if draw(st.integers(0, 3)) == 0:
        table["speed_limit"] = draw(log_uniform(1e-3, 1e4))
    return table


#: Adaptive explicit methods: their step follows the stiffest mode, whatever the scenario's step.
ADAPTIVE_EXPLICIT = {("reference", "dopri5"), ("exudyn", "ode23"), ("exudyn", "dopri5")}
#: Steps an adaptive explicit run may need (estimated) before its end time is shortened: a stiff film on a light
#: rotor is valid input, but would run for hours (and the reference engine looks at its stop request only between
#: output instants).
ADAPTIVE_STEPS = 2e4
#: Margin on the films' stiffness and damping at ε = 0 for the film at its equilibrium and the ramp's speeds [-].
FILM_MARGIN = 30.0


def fastest_rate(bearing: dict, rotor: dict, drive: dict, speed_rpm: float) -> float:
    """A generous estimate [1/s] of the rotor's fastest mode: on its films √(K/m) and c/m with Ocvirk's stiffness
    μΩRL³/C³ and squeeze damping πμRL³/(2C³) at ε = 0, times :data:`FILM_MARGIN`; the speed servo's gain over the
    polar inertia (for the test's cost only)."""
    scale = rotor["bearings"] * bearing["viscosity"] * bearing["diameter"] / 2 * bearing["length"] ** 3 \
        / bearing["radial_clearance"] ** 3 * FILM_MARGIN
    return max(math.sqrt(scale * speed_rpm * math.pi / 30 / rotor["mass"]), scale * math.pi / 2 / rotor["mass"],
               drive["gain"] / rotor["polar_inertia"])


@st.composite
def rotor_scenarios(draw) -> dict:
    diameter = draw(log_uniform(1e-3, 1.0))
    clearance = diameter * draw(uniform(0.0, 0.5, low_open=True, high_open=True, margin=1e-6)
                                | log_uniform(1e-5, 1e-2))
    bearing = {"diameter": diameter, "length": diameter * draw(log_uniform(1e-2, 10.0)),
               "radial_clearance": clearance, "viscosity": draw(log_uniform(1e-5, 10.0)),
               "force": draw(st.sampled_from(["short", "short", "map"]))}
    if bearing["force"] == "map" or draw(st.booleans()):
        bearing["grid"] = [draw(st.integers(4, 16)), draw(st.integers(4, 8))]
    speed = draw(st.one_of(log_uniform(1.0, RPM), st.just(RPM)))
    drive = {"speed_rpm": speed, "gain": draw(log_uniform(1e-3, 1e6))}
    if draw(st.booleans()):
        drive["start_rpm"] = draw(st.one_of(log_uniform(1.0, RPM), st.just(RPM)))
    bearings = draw(st.integers(1, 8))
    # a weight the films can carry at the start speed, mostly (Ocvirk's load at ε = 0.5, about μΩRL³/C²/2): a
    # heavier rotor finds no equilibrium and is refused (drive.start_rpm)
    start = drive.get("start_rpm", speed) * math.pi / 30
    capacity = bearing["viscosity"] * start * diameter / 2 * bearing["length"] ** 3 / clearance**2 / 2
    heavy = draw(st.integers(0, 9)) == 0
    mass = draw(log_uniform(1e-2, 1e5)) if heavy else min(max(capacity * bearings / 9.81, 1e-3), 1e6) \
        * draw(log_uniform(1e-3, 1.0))
    rotor = {"mass": mass, "polar_inertia": draw(log_uniform(1e-6, 1e4)), "bearings": bearings,
             "unbalance": draw(st.one_of(st.just(0.0), log_uniform(1e-9, 1.0))),
             # from the equilibrium: small offsets mostly, now and then one past the clearance (refused)
             "initial_offset": [draw(uniform(-0.2 * clearance, 0.2 * clearance) if draw(st.integers(0, 9))
                                     else uniform(-2 * clearance, 2 * clearance)) for _ in range(2)]}
    engine = draw(st.sampled_from(["reference", "exudyn"]))
    method = draw(st.sampled_from(REFERENCE_METHODS if engine == "reference" else tuple(EXUDYN_METHODS)))
    end = draw(log_uniform(1e-4, 2e-2))
    if (engine, method) in ADAPTIVE_EXPLICIT:
        end = min(end, ADAPTIVE_STEPS / fastest_rate(bearing, rotor, drive, max(speed, drive.get("start_rpm", 0.0))))
    if "start_rpm" in drive:
        drive["ramp_time"] = draw(st.one_of(st.just(0.0), uniform(0.0, end)))
    return {"scenario": {"name": "drawn_rotor", "model": "rotor", "end_time": end,
                         "gravity": draw(st.one_of(st.just(9.81), uniform(0.0, 100.0)))},
            "solver": solver(draw, end, engine, method), "rotor": rotor, "bearing": bearing, "drive": drive}


#: The seed rotor (scenarios/seed_rotor_unbalance.toml), 10 ms.
SEED = {"scenario": {"name": "seed_rotor", "model": "rotor", "end_time": 0.01},
        "solver": {"engine": "exudyn", "output_interval": 1e-4, "exudyn": {"method": "generalized_alpha", "step": 1e-4}},
        "rotor": {"mass": 100.0, "polar_inertia": 0.2, "bearings": 2, "unbalance": 1e-3},
        "bearing": {"diameter": 0.05, "length": 0.025, "radial_clearance": 50e-6, "viscosity": 0.01, "force": "short"},
        "drive": {"speed_rpm": 6000.0, "gain": 200.0}}


@PROFILE
@given(rotor_scenarios())
@example(SEED)
def test_rotor_runs_to_a_status_or_refuses_by_name(drawn):
    run_command("run", drawn, None, "--quiet")
