"""Property: ``bearing-mbs slewing`` (the static solution) and ``bearing-mbs run`` (a pitch bearing's blade root in
time) on any valid slewing-bearing scenario run to a status or refuse the input by name, never a traceback
(tests/no_traceback.py says what is checked).

Drawn over the documented range of every key (docs/scenario-format.md, "Slewing-bearing scenarios", and
bearing_mbs/models/slewing_bearing/spec.py): pitch diameters of 5 cm to 20 m with balls of 2e-3 pitch diameters
(about 1600 balls) to nearly one (and, refused, wider), conformity in (0.5, 1), contact angles in (0, 90) deg, the number of balls up to what fits and one more,
the elastic constants, rigid and flexible rings with both mounts and both coefficient sets, loads of either sign
in any combination or an imposed axial displacement curve, and the blade root's mass, inertia, damping, gust and
ramp with either engine and every integration method. Runs are short (at most 0.5 s and about 300 steps).
"""

from __future__ import annotations

import math

from hypothesis import example, given
from hypothesis import strategies as st

from bearing_mbs.spec.solver import EXUDYN_METHODS, REFERENCE_METHODS

from no_traceback import PROFILE, log_uniform, run_command, solver_table, uniform

#: At most this many steps of a fixed-step method.
STEPS = 300
FORCE = 1e8  # [N]: loads are drawn up to this (a 10 m slewing bearing carries tens of MN)


def load(draw) -> dict:
    if draw(st.integers(0, 4)) == 0:
        return {"axial_displacements": draw(st.lists(uniform(-1e-2, 1e-2), min_size=1, max_size=6))}
    table = {}
    for key, scale in (("axial", FORCE), ("radial", FORCE), ("moment", FORCE * 5)):
        if draw(st.booleans()):
            table[key] = draw(st.one_of(uniform(-scale, scale), log_uniform(1.0, scale),
                                        log_uniform(1.0, scale).map(lambda x: -x)))
    if not any(table.values()):
        table["axial"] = draw(log_uniform(1.0, FORCE))
    return table


def solver(draw, end: float) -> dict:
    engine = draw(st.sampled_from(["reference", "exudyn"]))
    method = draw(st.sampled_from(REFERENCE_METHODS if engine == "reference" else tuple(EXUDYN_METHODS)))
    return solver_table(draw, end, engine, method, STEPS)


@st.composite
def slewing_scenarios(draw) -> tuple[str, dict]:
    """(command, scenario)."""
    pitch = draw(log_uniform(0.05, 20.0))
    # from about 1600 balls (a static solve per ball stays cheap) to one nearly as wide as the pitch circle; and
    # now and then wider (refused: ball_diameter < pitch_diameter)
    ratio = st.one_of(log_uniform(2e-3, 0.5), uniform(0.5, 1.0, high_open=True))
    ball = pitch * (1.5 if draw(st.integers(0, 19)) == 0 else draw(ratio))
    slewing = {"pitch_diameter": pitch, "ball_diameter": ball,
               "conformity": draw(uniform(0.5, 1.0, low_open=True, high_open=True, margin=1e-6)),
               "contact_angle": draw(uniform(0.0, 90.0, low_open=True, high_open=True, margin=1e-6)),
               "youngs_modulus": draw(log_uniform(1e9, 1e12)), "poisson_ratio": draw(uniform(0.0, 0.5, high_open=True))}
    most = math.floor(math.pi * pitch / ball)
    if draw(st.booleans()):
        slewing["balls"] = most + 1 if draw(st.integers(0, 9)) == 0 else draw(st.integers(1, max(1, most)))
    rings = draw(st.sampled_from(["rigid", "flexible"]))
    slewing["rings"] = rings
    if draw(st.booleans()):
        slewing["mount"] = draw(st.sampled_from(["free", "fixed"]))
        # as printed, the free rings' matrices are refused (two errata): drawn now and then
        slewing["coefficients"] = draw(st.sampled_from(["corrected"] * 3 + ["as_printed"]))
        slewing["coupling"] = draw(st.sampled_from(["structural", "full_matrix"]))
    end = draw(log_uniform(1e-3, 0.5))
    scenario = {"scenario": {"name": "drawn_slewing", "model": "slewing_bearing", "end_time": end,
                             "gravity": draw(st.one_of(st.just(9.81), uniform(0.0, 100.0)))},
                "slewing": slewing, "load": load(draw)}
    command = "slewing"
    if rings == "rigid" and "axial_displacements" not in scenario["load"] and draw(st.booleans()):
        scenario["pitch"] = {"blade_mass": draw(log_uniform(1.0, 1e6)), "blade_inertia": draw(log_uniform(1.0, 1e9)),
                             "damping": draw(st.one_of(st.just(0.0), log_uniform(1e-6, 1.0))),
                             "gust_amplitude": draw(uniform(-FORCE, FORCE)),
                             "gust_period": draw(log_uniform(1e-3, 100.0)),
                             "ramp_time": draw(st.one_of(st.just(0.0), uniform(0.0, 2 * end)))}
        scenario["solver"] = solver(draw, end)
        command = draw(st.sampled_from(["run", "run", "slewing"]))
    return command, scenario


#: The pitch seed bearing, 0.05 s.
PITCH = {"scenario": {"name": "pitch", "model": "slewing_bearing", "end_time": 0.05},
         "slewing": {"pitch_diameter": 1.5, "ball_diameter": 0.035, "conformity": 0.943, "contact_angle": 45.0},
         "load": {"axial": 5e5, "moment": 3e6},
         "pitch": {"blade_mass": 17000.0, "blade_inertia": 2e7, "damping": 2e-3, "gust_amplitude": 1.5e6,
                   "gust_period": 8.0, "ramp_time": 1.0},
         "solver": {"engine": "exudyn", "output_interval": 0.01, "exudyn": {"method": "generalized_alpha",
                                                                          "step": 1e-3}}}


@PROFILE
@given(slewing_scenarios())
@example(("run", PITCH))
@example(("slewing", {**PITCH, "slewing": {**PITCH["slewing"], "balls": 1}}))  # issue 25: one ball
def test_slewing_runs_to_a_status_or_refuses_by_name(drawn):
    command, scenario = drawn
    run_command(command, scenario, None, *(("--quiet",) if command == "run" else ()))

