"""Property: ``bearing-mbs run`` on any valid scenario of the ``bearing`` model (the caged cylindrical roller bearing)
runs to a status or refuses the input by name, never a traceback (tests/no_traceback.py says what is checked).

Each example starts from a shipped bearing scenario in one of its variants (lubricated or dry) and overrides keys
with ``--set``, drawn over their documented range (docs/scenario-format.md, docs/bearing.md and
bearing_mbs/models/cylindrical_roller/spec.py), with their edges:

* the geometry: a preset as it is, a preset with some keys replaced, or a whole bearing drawn without a preset
  (3 to 60 rollers, pitch diameters of 1.05 to 40 roller diameters, either raceway description from the largest
  preload to the largest clearance, the cage anywhere in the rollers' span, on the pitch circle among others, every
  guidance and land clearance, the supported mass up to its limit, materials);
* the cage model, the drive (speed servo with constant, ramp and table profiles up to the pitch-speed limit and
  backwards, either initial state, the gear train with its torques and angles), the load (every profile, up to
  4 C0, any direction), the lubricant (presets and oils of their own, temperatures over the fit's range, every drag
  model, the land and pocket films), the contact groups (every normal law, stiffness model and friction law, EHL
  traction and its parameters), the analysis window, gravity;
* both engines with every integration method, tolerances, spectral radii, connectors and Jacobians.

Runs are kept short (at most 2 ms of simulated time and about 400 steps): a short run still goes through loading,
validation, build, the engine, the metrics, the checks and the summary, which is what is tested.
"""

from __future__ import annotations

import math
import tempfile
from pathlib import Path

from hypothesis import assume, example, given
from hypothesis import strategies as st

from bearing_mbs.models import build_scene, spec_from_mapping
from bearing_mbs.models.cylindrical_roller.spec import (
    CLEARANCE_LIMIT,
    LOAD_LIMIT,
    PITCH_SPEED_LIMIT,
    PRELOAD_LIMIT,
    PRESETS,
    SUPPORTED_MASS_LIMIT,
)
from bearing_mbs.numerics.advisor import advise
from bearing_mbs.spec import SpecError, read_scenario, read_toml
from bearing_mbs.spec.solver import EXUDYN_METHODS, REFERENCE_METHODS

from cases import SCENARIOS
from no_traceback import DELETE, PROFILE, log_uniform, overrides, run_command, toml_document, uniform, with_changes

BASES = ("seed_hss_steady", "seed_hss_startup", "seed_hss_load_drop", "seed_hss_emergency_stop",
         "seed_hss_gear_driven", "cage_models", "static_check")
VARIANTS = {"seed_hss_steady": ("lubricated", "dry"), "seed_hss_startup": ("lubricated", "dry"),
            "seed_hss_load_drop": ("lubricated", "dry"), "seed_hss_emergency_stop": ("lubricated", "dry"),
            "seed_hss_gear_driven": ("lubricated", "dry")}
#: At most this many steps of a fixed-step method (each example must take well under a second), and of the
#: central difference's step in contact.
STEPS, CONTACT_STEPS = 400, 2000
OILS = ("iso_vg_220_mineral", "iso_vg_320_mineral", "iso_vg_220_pao", "iso_vg_320_pao")
GROUPS = ("inner_race", "outer_race", "pocket", "land", "roller")


def drawn_geometry(draw) -> tuple[dict, dict]:
    """({bearing.key: value}, the numbers the other draws need: D_w, D_pw, Z, L_w)."""
    d_w = draw(log_uniform(1e-3, 0.2))
    h = d_w * draw(log_uniform(1e-4, 0.3))
    pitch = max(d_w * draw(log_uniform(1.05, 40.0)), 1.2 * (d_w + 2 * h))  # three rollers fit
    ratio = (d_w + 2 * h) / pitch
    most = max(3, int(math.pi / math.asin(ratio))) if ratio < 1 else 3
    rollers = most + 1 if most < 60 and draw(st.integers(0, 9)) == 0 else draw(st.integers(3, min(most, 60)))
    length = d_w * draw(log_uniform(0.2, 5.0))
    clearance = d_w * draw(st.one_of(st.just(0.0), uniform(-PRELOAD_LIMIT, CLEARANCE_LIMIT),
                                     st.sampled_from([-PRELOAD_LIMIT, CLEARANCE_LIMIT])))
    bearing = {"rollers": rollers, "roller_diameter": d_w, "roller_length": length,
               "pocket_clearance": h,
               "cage_diameter": pitch + d_w * draw(st.one_of(st.just(0.0), uniform(-1.0, 1.0, low_open=True,
                                                                                     high_open=True, margin=1e-6))),
               "cage_thickness": d_w * draw(log_uniform(1e-2, 1.0)),
               "cage_width": length * draw(log_uniform(0.5, 2.0)),
               "ring_width": length * draw(log_uniform(0.5, 3.0))}
    inner = pitch - d_w - clearance / 2
    bearing["inner_ring_bore"] = inner * draw(uniform(0.0, 1.0, low_open=True, high_open=True, margin=1e-3))
    if draw(st.booleans()):
        bearing.update(pitch_diameter=pitch, diametral_clearance=clearance)
    else:
        bearing.update(inner_race_diameter=inner, outer_race_diameter=pitch + d_w + clearance / 2)
    return bearing, {"d_w": d_w, "pitch": pitch, "rollers": rollers, "length": length}


def preset_numbers(name: str) -> dict:
    preset = PRESETS[name]
    pitch = (preset["inner_race_diameter"] + preset["outer_race_diameter"]) / 2
    return {"d_w": preset["roller_diameter"], "pitch": pitch, "rollers": preset["rollers"],
            "length": preset["roller_length"]}


def geometry(draw, base_preset: str) -> tuple[dict, dict]:
    kind = draw(st.sampled_from(["as shipped", "other preset", "preset changed", "drawn"]))
    if kind == "drawn":
        return drawn_geometry(draw)
    name = base_preset if kind == "as shipped" else draw(st.sampled_from(sorted(PRESETS)))
    changes, numbers = {"preset": name}, preset_numbers(name)
    if kind == "preset changed":
        d_w, pitch = numbers["d_w"], numbers["pitch"]
        for key, strategy in (("cage_diameter", st.one_of(st.just(pitch), uniform(pitch - d_w, pitch + d_w,
                                                                                  low_open=True, high_open=True))),
                              ("pocket_clearance", log_uniform(1e-3 * d_w, 0.3 * d_w)),
                              ("cage_thickness", log_uniform(1e-2 * d_w, d_w)),
                              ("roller_length", log_uniform(0.2 * d_w, 5 * d_w))):
            if draw(st.booleans()):
                changes[key] = draw(strategy)
        if draw(st.booleans()):
            changes.update(pitch_diameter=pitch, diametral_clearance=d_w * draw(uniform(-PRELOAD_LIMIT,
                                                                                        CLEARANCE_LIMIT)))
        numbers["length"] = changes.get("roller_length", numbers["length"])
    return changes, numbers


def guidance(draw, d_w: float) -> dict:
    kind = draw(st.sampled_from(["rollers", "inner_land", "outer_land"]))
    changes = {"cage_guidance": kind}
    if kind != "rollers" or draw(st.booleans()):
        changes["land_clearance"] = d_w * draw(uniform(0.0, 1.0, low_open=True, high_open=True, margin=1e-6)
                                               | log_uniform(1e-4, 0.1))
    return changes


def material(draw) -> dict:
    return {"youngs_modulus": draw(log_uniform(1e8, 1e12)), "poisson_ratio": draw(uniform(0.0, 0.5, high_open=True)),
            "density": draw(log_uniform(100.0, 2e4))}


def rpm_limit(pitch: float) -> float:
    return PITCH_SPEED_LIMIT * 60 / (math.pi * pitch)


def drive(draw, pitch: float, end: float, has_gear_train: bool) -> dict:
    top = rpm_limit(pitch)
    speed = st.one_of(st.just(0.0), uniform(-top, top), st.sampled_from([top, -top]))
    kind = draw(st.sampled_from(["speed", "speed", "gear_train"]))
    changes = {"drive.kind": kind, "drive.initial_state": draw(st.sampled_from(["rolling", "rest"])),
               "drive.speed_rpm": draw(speed)}
    if draw(st.booleans()):
        changes["drive.servo_time_constant"] = draw(log_uniform(1e-7, 10.0))
    if kind == "gear_train":
        for key, strategy, required in (
                ("pinion_radius", log_uniform(1e-3, 2.0), True), ("gear_radius", log_uniform(1e-3, 5.0), True),
                ("shaft1_inertia", log_uniform(1e-4, 1e5), True), ("shaft2_inertia", log_uniform(1e-4, 1e6), True),
                ("generator_torque", uniform(-1e6, 1e6), True), ("generator_torque_rate", uniform(-1e8, 1e8), True),
                ("rotor_torque", uniform(-1e6, 1e6), True), ("rotor_torque_rate", uniform(-1e8, 1e8), True),
                ("pressure_angle", uniform(0.0, 45.0), False), ("load_share", uniform(0.0, 100.0), False),
                ("mesh_angle", uniform(-720.0, 720.0), False)):
            if (required and not has_gear_train) or draw(st.booleans()):
                changes[f"drive.gear_train.{key}"] = draw(strategy)
        return changes
    profile = draw(st.sampled_from(["constant", "ramp", "table"]))
    changes["drive.profile"] = profile
    if profile == "ramp":
        changes.update({"drive.from_rpm": draw(speed), "drive.start": draw(uniform(0.0, 2 * end)),
                        "drive.duration": draw(st.one_of(st.just(0.0), uniform(0.0, 2 * end)))})
    elif profile == "table":
        times = sorted(draw(st.lists(uniform(0.0, 2 * end), min_size=1, max_size=4)))
        changes.update({"drive.times": times, "drive.speeds_rpm": [draw(speed) for _ in times]})
    return changes


def load(draw, numbers: dict, end: float) -> dict:
    capacity = 44.0 * (1 - numbers["d_w"] / numbers["pitch"]) * numbers["rollers"] * 1e6 * numbers["length"] \
        * numbers["d_w"]  # ISO 76 C0 [N], lengths in mm
    radial = st.one_of(st.just(0.0), uniform(0.0, LOAD_LIMIT * capacity), st.just(LOAD_LIMIT * capacity),
                       log_uniform(1.0, LOAD_LIMIT * capacity))
    profile = draw(st.sampled_from(["constant", "step", "ramp", "table"]))
    changes = {"load.profile": profile, "load.radial": draw(radial), "load.angle": draw(uniform(-720.0, 720.0))}
    if profile in ("step", "ramp"):
        changes.update({"load.start": draw(uniform(0.0, 2 * end)),
                        "load.duration": draw(uniform(0.0, 2 * end, low_open=True))})
    if profile == "step":
        changes["load.final"] = draw(radial)
    if profile in ("constant", "step") and draw(st.booleans()):
        changes["load.ramp_time"] = draw(uniform(0.0, changes.get("load.start", 2 * end)))
    elif profile == "table":
        times = sorted(draw(st.lists(uniform(0.0, 2 * end), min_size=1, max_size=4)))
        changes.update({"load.times": times, "load.values": [draw(radial) for _ in times]})
    return changes


def lubricant(draw) -> dict:
    changes = {}
    if draw(st.booleans()):
        changes["lubricant.oil"] = draw(st.sampled_from(OILS))
    else:
        v40 = draw(log_uniform(2.1e-6, 1e-2))
        changes.update({"lubricant.viscosity_40": v40,
                        "lubricant.viscosity_100": draw(log_uniform(2e-6, min(1e-3, v40 * 0.999)))})
    for key, strategy in (("density_15", uniform(600.0, 1200.0)), ("thermal_expansion", uniform(0.0, 2e-3)),
                          ("pressure_viscosity", uniform(5e-9, 4e-8)), ("thermal_conductivity", uniform(0.05, 0.5)),
                          ("oil_fraction", uniform(0.0, 1.0, low_open=True)), ("viscosity", log_uniform(1e-7, 1e-2)),
                          ("drag_factor", uniform(0.5, 10.0)), ("reference_rpm", log_uniform(1e-3, 1e5)),
                          ("drag_moment", st.one_of(st.just(0.0), log_uniform(1e-6, 1e3)))):
        if draw(st.integers(0, 3)) == 0:
            changes[f"lubricant.{key}"] = draw(strategy)
    changes["lubricant.temperature"] = draw(uniform(-10.0, 120.0))
    changes["lubricant.model"] = draw(st.sampled_from(["palmgren", "churning", "none"]))
    changes["lubricant.land_film"] = draw(st.booleans())
    changes["lubricant.pocket_film"] = draw(st.booleans())
    return changes


def contact(draw, group: str) -> dict:
    prefix = f"contact.{group}."
    changes = {}
    model = draw(st.sampled_from(["palmgren", "given", "document"]))
    changes[prefix + "stiffness_model"] = model
    if model == "given":
        changes.update({prefix + "stiffness": draw(log_uniform(1e3, 1e14)),
                        prefix + "exponent": draw(uniform(1.0, 3.0))})
    law = draw(st.sampled_from(["none", "erf", "tanh", "linear", "dead_zone", "ehl"]))
    changes[prefix + "friction_law"] = law
    for key, strategy in (("normal_law", st.sampled_from(["power", "lankarani_nikravesh", "hunt_crossley", "flores",
                                                          "gonthier"])),
                          ("restitution", uniform(0.0, 1.0, low_open=True)),
                          ("approach_speed_floor", log_uniform(1e-6, 10.0)),
                          ("friction_coefficient", uniform(0.0, 2.0)),
                          ("regularisation_speed", log_uniform(1e-6, 10.0))):
        if draw(st.booleans()):
            changes[prefix + key] = draw(strategy)
    if law == "none":  # the raceways' shipped arm needs a friction law
        changes[prefix + "rolling_resistance_arm"] = 0.0
    elif draw(st.booleans()):
        changes[prefix + "rolling_resistance_arm"] = draw(st.one_of(st.just(0.0), log_uniform(1e-8, 1e-2)))
    if law != "ehl":  # the lubricated variant's raceways have it
        changes[prefix + "ehl_rolling_resistance"] = False
    else:
        for key, strategy in (("film_formula", st.sampled_from(["pan_hamrock", "dowson_higginson"])),
                              ("thermal_reduction", st.booleans()), ("roughness", log_uniform(1e-9, 1e-5)),
                              ("eyring_stress", log_uniform(1e5, 1e8)), ("shear_modulus", log_uniform(1e6, 1e10)),
                              ("limiting_shear_coefficient", uniform(0.01, 0.2)),
                              ("ehl_rolling_resistance", st.booleans())):
            if draw(st.booleans()):
                changes[prefix + key] = draw(strategy)
        if draw(st.booleans()):
            a = draw(uniform(-0.2, 0.2))
            changes.update({prefix + "traction_model": "curve",
                            prefix + "traction_curve": [a, draw(log_uniform(1e-2, 1e3)), draw(log_uniform(1e-2, 1e3)),
                                                        -a + draw(uniform(-1e-3, 1e-3))]})
    return changes


def solver(draw, end: float) -> dict:
    engine = draw(st.sampled_from(["reference", "exudyn"]))
    methods = REFERENCE_METHODS if engine == "reference" else tuple(EXUDYN_METHODS)
    method = draw(st.sampled_from(methods))
    outputs = draw(st.integers(1, 20))
    steps = draw(st.integers(outputs if engine == "exudyn" else 1, STEPS))
    step = end / steps
    changes = {"solver.engine": engine, f"solver.{engine}.method": method, f"solver.{engine}.step": step,
               "solver.output_interval": end / outputs}
    if draw(st.booleans()):
        changes[f"solver.{engine}.tolerance"] = draw(log_uniform(1e-12, 0.5))
    if draw(st.booleans()):
        changes[f"solver.{engine}.spectral_radius"] = draw(uniform(0.0, 1.0))
    if engine == "reference" and method == "central_difference" and draw(st.booleans()):
        # the step in contact (rollers always are): at most CONTACT_STEPS steps in all
        changes["solver.reference.contact_step"] = step * draw(uniform(min(1.0, steps / CONTACT_STEPS), 1.0))
    if engine == "exudyn":
        # the numpy connector costs a few ms per evaluation: drawn less often
        changes["solver.exudyn.connector"] = draw(st.sampled_from(["compiled"] * 8 + ["python", "native"]))
        changes["solver.exudyn.jacobian"] = draw(st.sampled_from(["analytic", "analytic", "numerical"]))
    if draw(st.integers(0, 3)) == 0:
        changes["solver.penetration_limit"] = draw(uniform(0.0, 1.0, low_open=True))
    if draw(st.integers(0, 3)) == 0:
        changes["solver.speed_limit"] = draw(log_uniform(1.0, 1e4))
    return changes


@st.composite
def bearing_runs(draw) -> tuple:
    """(shipped scenario, its keys removed, --set changes)."""
    base = draw(st.sampled_from(BASES))
    changes, removed = {}, []
    if base in VARIANTS:
        changes["scenario.variant"] = draw(st.sampled_from(VARIANTS[base]))
    end = draw(log_uniform(1e-5, 2e-3))
    changes["scenario.end_time"] = end
    if draw(st.integers(0, 3)) == 0:
        changes["scenario.gravity"] = draw(uniform(0.0, 100.0))
    bearing, numbers = geometry(draw, "seed-hss")
    if draw(st.booleans()):
        bearing.update(guidance(draw, numbers["d_w"]))
    if draw(st.integers(0, 3)) == 0:
        bearing["supported_mass"] = draw(uniform(0.0, SUPPORTED_MASS_LIMIT))
    for name in ("ring_material", "roller_material", "cage_material"):
        if draw(st.integers(0, 5)) == 0:
            bearing[name] = material(draw)
    if "preset" not in bearing:
        removed.append("bearing.preset")
    changes.update({f"bearing.{key}": value for key, value in bearing.items() if not isinstance(value, dict)})
    changes.update({f"bearing.{key}.{k}": v for key, value in bearing.items() if isinstance(value, dict)
                    for k, v in value.items()})
    if draw(st.booleans()):
        changes["cage.model"] = draw(st.sampled_from(["penalty", "constraint", "none"]))
    if draw(st.booleans()):
        changes.update(drive(draw, numbers["pitch"], end, base == "seed_hss_gear_driven"))
    elif draw(st.booleans()):  # the shipped drive, at a speed inside the limit of the drawn bearing
        changes["drive.speed_rpm"] = draw(uniform(0.0, rpm_limit(numbers["pitch"])))
    if draw(st.booleans()):
        changes.update(load(draw, numbers, end))
    if draw(st.booleans()):
        changes.update(lubricant(draw))
    for group in GROUPS:
        if draw(st.integers(0, 4)) == 0:
            changes.update(contact(draw, group))
    if draw(st.booleans()):
        changes["analysis.start_fraction"] = draw(uniform(0.0, 1.0, high_open=True))
        removed.append("analysis.start")
    else:
        changes["analysis.start"] = draw(uniform(0.0, 2 * end))
    if draw(st.integers(0, 3)) == 0:
        changes["analysis.load_fraction"] = draw(uniform(0.0, 1.0))
    changes.update(solver(draw, end))
    return base, tuple(removed), changes


#: The lubricated seed bearing, 0.2 ms on Exudyn: the shipped settings but for the run's length.
SHORT = {"scenario.end_time": 2e-4, "solver.output_interval": 5e-5, "analysis.start": 1e-4}


@PROFILE
@given(bearing_runs())
# issue 25: a cage on the pitch circle gave the oiled pocket wall no height (ValueError: a pair law's film ... > 0)
@example(("seed_hss_steady", (), {**SHORT, "bearing.cage_diameter": 0.235}))
@example(("seed_hss_steady", (), {**SHORT, "bearing.cage_diameter": 0.235, "cage.model": "penalty"}))
def test_bearing_runs_to_a_status_or_refuses_by_name(drawn):
    base, removed, changes = drawn
    scenario = with_changes(read_toml(SCENARIOS / f"{base}.toml"), dict.fromkeys(removed, DELETE))
    assume(affordable(scenario, changes))
    run_command("run", scenario, changes, "--quiet")


#: Adaptive explicit methods: their step follows the stiffest mode, whatever the scenario's step.
ADAPTIVE_EXPLICIT = {("reference", "dopri5"), ("exudyn", "ode23"), ("exudyn", "dopri5")}
#: Steps an adaptive explicit run may take, estimated from the step advisor's RK4 limit: beyond, the example is left
#: out (valid input, but hours of run: a contact stiffness of 1e14 N/m, a friction regularised over 1e-6 m/s; and
#: the reference engine looks at its stop request only between output instants).
ADAPTIVE_STEPS = 3e4


def affordable(scenario: dict, changes: dict) -> bool:
    """False for an adaptive explicit run the step advisor puts at more than :data:`ADAPTIVE_STEPS` steps."""
    engine = changes.get("solver.engine")  # None: the shipped solver, which is not adaptive explicit
    if (engine, changes.get(f"solver.{engine}.method")) not in ADAPTIVE_EXPLICIT:
        return True
    with tempfile.TemporaryDirectory() as tmp:
        path = Path(tmp) / "scenario.toml"
        path.write_text(toml_document(scenario))
        try:
            spec = spec_from_mapping(read_scenario(path, overrides(changes)[1::2]))
            limit = advise(build_scene(spec)).limit("reference", "rk4")
        except SpecError:
            return True  # refused by name, cheaply
    return limit is None or not limit > 0 or spec.scenario.end_time / limit <= ADAPTIVE_STEPS
