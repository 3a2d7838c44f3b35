"""Bad input across every model and file kind, refused before anything runs (docs/status.md).

Each row: a file (a shipped scenario or study, or a small file the test writes) with overrides, and the field the
:class:`~bearing_mbs.spec.SpecError` must name. Loading and building the scene is everything that happens before
a run; no engine is called. The error carries the field, the value and what is allowed (its attributes are
checked, not its wording). The rows cover every case of the trust issue's list (marked "issue"); the command-line
cases are in ``tests/test_bad_input_commands.py``.
"""

from __future__ import annotations

import math

import pytest

from bearing_mbs.models import build_scene, load_spec
from bearing_mbs.spec import SpecError, read_toml
from bearing_mbs.studies.sensitivity import load_study

from cases import SCENARIOS

STEADY, DROP, PAIR = "seed_hss_steady.toml", "seed_case2.toml", "seed_case5.toml"
STUDY = "study_drop_morris.toml"
#: The rows on STEADY change the seed bearing's dry model (its variant "dry"; the file's default is lubricated).
VARIANT = {STEADY: ["scenario.variant=dry"]}

#: name -> (file, overrides, field). ``{tmp}`` files are written by :func:`_file`.
SCENARIO_ROWS = {
    # issue: a directory given as the scenario
    "directory as scenario": (".", [], "scenario file"),
    "missing file": ("no_such.toml", [], "scenario file"),
    "not TOML": ("{tmp}/broken.toml", [], "scenario file"),
    # issue: a study file given to run
    "study file as scenario": (STUDY, [], "scenario file"),
    # issue: a ring bore larger than its raceway
    "bore inside the raceway": (STEADY, ["bearing.inner_ring_bore=0.3"], "bearing.inner_ring_bore"),
    # issue: a cage width that makes the cage's mass negative
    "cage of negative mass": (STEADY, ["bearing.cage_width=0.01"], "bearing.cage_width"),
    # issue: a land clearance of 0.5 m
    "land clearance of 0.5 m": (STEADY, ["bearing.land_clearance=0.5"], "bearing.land_clearance"),
    # issue: exponent given with the Palmgren stiffness model (was ignored)
    "exponent with Palmgren": (STEADY, ["contact.inner_race.exponent=1.5"], "contact.inner_race.exponent"),
    "stiffness with Palmgren": (STEADY, ["contact.pocket.stiffness=1e9"], "contact.pocket.stiffness"),
    # issue: output_interval larger than the end time
    "output interval past the end": (STEADY, ["solver.output_interval=1.0"], "solver.output_interval"),
    # issue: supported_mass 1e30
    "supported mass 1e30": (STEADY, ["bearing.supported_mass=1e30"], "bearing.supported_mass"),
    # issue: speed_rpm 1e9 and a load of 1e12 N
    "speed of 1e9 rpm": (STEADY, ["drive.speed_rpm=1e9"], "drive.speed_rpm"),
    "load of 1e12 N": (STEADY, ["load.radial=1e12"], "load.radial"),
    # issue: truncation by a step longer than the run
    "Exudyn step past the end": (STEADY, ["solver.exudyn.step=1"], "solver.exudyn.step"),
    "Exudyn step past the output interval": (STEADY, ["solver.exudyn.step=2e-4"], "solver.exudyn.step"),
    "reference step past the end": (STEADY, ["solver.engine=reference", "solver.reference.step=1"],
                                    "solver.reference.step"),
    # issue: keys a model does not use
    "unknown bearing key": (STEADY, ["bearing.colour='red'"], "bearing.colour"),
    "bearing section in a balls scenario": (DROP, ["bearing.rollers=15"], "bearing"),
    "balls section in a bearing scenario": (STEADY, ["box.floor=0"], "box"),
    # the shared sections
    "negative end time": (STEADY, ["scenario.end_time=-1"], "scenario.end_time"),
    "unknown model": (STEADY, ["scenario.model='turbine'"], "scenario.model"),
    "a slewing scenario without a blade to run": ("seed_slewing_1500.toml", [], "pitch"),
    "unknown engine": (STEADY, ["solver.engine='abaqus'"], "solver.engine"),
    "unknown reference method": (STEADY, ["solver.reference.method='rk5'"], "solver.reference.method"),
    "unknown Exudyn method": (STEADY, ["solver.exudyn.method='newmark'"], "solver.exudyn.method"),
    "unknown Exudyn Jacobian": (STEADY, ["solver.exudyn.jacobian='exact'"], "solver.exudyn.jacobian"),
    "generalized-alpha spectral radius above 1": (STEADY, ["solver.reference.spectral_radius=1.5"],
                                                  "solver.reference.spectral_radius"),
    "penetration limit above 1": (STEADY, ["solver.penetration_limit=2"], "solver.penetration_limit"),
    "speed limit of 0": (STEADY, ["solver.speed_limit=0"], "solver.speed_limit"),
    "unknown convergence norm": (STEADY, ["convergence.norm='bogus'"], "convergence.norm"),
    # contact laws
    "friction coefficient 3": (STEADY, ["contact.inner_race.friction_coefficient=3"],
                               "contact.inner_race.friction_coefficient"),
    "restitution 0": (STEADY, ["contact.outer_race.restitution=0"], "contact.outer_race.restitution"),
    "unknown friction law": (DROP, ["contact.wall.friction_law='sticky'"], "contact.wall.friction_law"),
    # the bearing's geometry and sections
    "two rollers": (STEADY, ["bearing.rollers=2"], "bearing.rollers"),
    "pockets too wide to fit": (STEADY, ["bearing.pocket_clearance=0.05"], "bearing.rollers"),
    "cage outside the rollers": (STEADY, ["bearing.cage_diameter=0.3"], "bearing.cage_diameter"),
    "clearance of a fifth of a roller": (STEADY, ["bearing.outer_race_diameter=0.265"],
                                         "bearing.outer_race_diameter"),
    "unknown cage model": (STEADY, ["cage.model='wooden'"], "cage.model"),
    "unknown drive": (STEADY, ["drive.kind='belt'"], "drive.kind"),
    "servo time constant 0": (STEADY, ["drive.servo_time_constant=0"], "drive.servo_time_constant"),
    "load angle not a number": (STEADY, ["load.angle=nan"], "load.angle"),
    "negative ramp time": (STEADY, ["load.ramp_time=-1"], "load.ramp_time"),
    "ramp time on a table load": (STEADY, ["load.profile='table'", "load.times=[0, 1]", "load.values=[0, 1]",
                                           "load.ramp_time=0.01"], "load.ramp_time"),
    "window fraction of 1.5": (STEADY, ["analysis.start_fraction=1.5"], "analysis.start_fraction"),
    "window start given twice": (STEADY, ["analysis.start_fraction=0.5"], "analysis.start_fraction"),
    "load fraction 2": (STEADY, ["analysis.load_fraction=2"], "analysis.load_fraction"),
    "drag factor 100": (STEADY, ["lubricant.drag_factor=100"], "lubricant.drag_factor"),
    # the balls model
    "ball without mass": (DROP, ["balls.0.mass=0"], "balls.0.mass"),
    "constraint on a missing ball": (PAIR, ["constraints.0.bodies=[0, 7]"], "constraints.0.bodies.1"),
    # lubricated traction and the oil (skidding issue)
    "ehl without an oil temperature": (STEADY, ["contact.inner_race.friction_law='ehl'"], "lubricant.temperature"),
    "ehl on the pockets": (STEADY, ["contact.pocket.friction_law='ehl'", "lubricant.oil='iso_vg_320_mineral'",
                                    "lubricant.temperature=60"], "contact.pocket.friction_law"),
    "oil below its fit": (STEADY, ["contact.inner_race.friction_law='ehl'", "lubricant.oil='iso_vg_320_mineral'", "lubricant.temperature=-30"],
                          "lubricant.temperature"),
    "oil above its fit": (STEADY, ["lubricant.oil='iso_vg_320_mineral'", "lubricant.temperature=150"],
                          "lubricant.temperature"),
    "unknown oil": (STEADY, ["lubricant.oil='sae_30'"], "lubricant.oil"),
    "unknown drag model": (STEADY, ["lubricant.model='stokes'"], "lubricant.model"),
    "churning without an oil temperature": (STEADY, ["lubricant.model='churning'"], "lubricant.temperature"),
    "no oil in the cavity": (STEADY, ["lubricant.oil='iso_vg_320_mineral'", "lubricant.temperature=60",
                                      "lubricant.model='churning'", "lubricant.oil_fraction=0"], "lubricant.oil_fraction"),
    "more than all oil": (STEADY, ["lubricant.oil_fraction=1.5"], "lubricant.oil_fraction"),
    "land film without an oil temperature": (STEADY, ["lubricant.land_film=true", "bearing.cage_width=0.071"],
                                             "lubricant.temperature"),
    "land film on a roller-guided cage": (STEADY, ["lubricant.land_film=true", "lubricant.oil='iso_vg_320_mineral'",
                                                   "lubricant.temperature=60", "bearing.cage_guidance='rollers'",
                                                   "bearing.cage_width=0.071"], "bearing.cage_guidance"),
    "land film without side rings": (STEADY, ["lubricant.land_film=true", "lubricant.oil='iso_vg_320_mineral'",
                                              "lubricant.temperature=60"], "bearing.cage_width"),
    "temperature without an oil": (STEADY, ["lubricant.temperature=60"], "lubricant.oil"),
    "half an oil": (STEADY, ["lubricant.viscosity_40=3.2e-4", "lubricant.temperature=60"], "lubricant.viscosity_100"),
    "oil thinner cold than hot": (STEADY, ["lubricant.viscosity_40=2e-5", "lubricant.viscosity_100=3e-5"],
                                  "lubricant.viscosity_100"),
    "pressure-viscosity out of range": (STEADY, ["lubricant.oil='iso_vg_320_pao'", "lubricant.pressure_viscosity=1e-6"],
                                        "lubricant.pressure_viscosity"),
    "roughness out of range": (STEADY, ["contact.inner_race.roughness=0.0"], "contact.inner_race.roughness"),
    "eyring stress out of range": (STEADY, ["contact.outer_race.eyring_stress=1e3"], "contact.outer_race.eyring_stress"),
    "limiting shear out of range": (STEADY, ["contact.inner_race.limiting_shear_coefficient=0.5"],
                                    "contact.inner_race.limiting_shear_coefficient"),
    "shear modulus out of range": (STEADY, ["contact.inner_race.shear_modulus=1e12"], "contact.inner_race.shear_modulus"),
    "unknown traction model": (STEADY, ["contact.inner_race.traction_model='magic'"], "contact.inner_race.traction_model"),
    "unknown film formula": (STEADY, ["contact.inner_race.film_formula='grubin'"], "contact.inner_race.film_formula"),
    "traction curve with a jump": (STEADY, ["contact.inner_race.traction_curve=[0.05, 4.0, 40.0, 0.0]"],
                                   "contact.inner_race.traction_curve"),
    "curve model without its curve": (STEADY, ["contact.inner_race.friction_law='ehl'", "contact.inner_race.traction_model='curve'"],
                                      "contact.inner_race.traction_curve"),
    "pocket film without an oil temperature": (STEADY, ["lubricant.pocket_film=true"], "lubricant.temperature"),
    "unknown variant": (STEADY, ["scenario.variant='wet'"], "scenario.variant"),
    "variant of a file without variants": (DROP, ["scenario.variant=dry"], "scenario.variant"),
    "EHL rolling resistance on a dry law": (STEADY, ["contact.inner_race.ehl_rolling_resistance=true"],
                                            "contact.inner_race.ehl_rolling_resistance"),
}

#: name -> (study file, overrides, field).
STUDY_ROWS = {
    # issue: a scenario given to sweep
    "scenario as study": (STEADY, [], "study file"),
    # issue: a sweep output name misspelt
    "misspelt output": (STUDY, ["study.outputs=['restitution_effectve']"], "study.outputs.0"),
    "directory as study": (".", [], "study file"),
}


def _file(name: str, tmp_path) -> str:
    if name.startswith("{tmp}"):
        path = tmp_path / name.removeprefix("{tmp}/")
        path.write_text("[scenario\nname = 'broken'\n")
        return str(path)
    return str(SCENARIOS / name)


def _refused(error: SpecError, field: str) -> None:
    assert error.field == field, (error.field, str(error))
    assert error.allowed, str(error)
    assert error.value is not None or "None" in str(error)


def test_at_least_forty_bad_inputs():
    assert len(SCENARIO_ROWS) + len(STUDY_ROWS) >= 40


@pytest.mark.parametrize("name", list(SCENARIO_ROWS))
def test_a_bad_scenario_is_refused_before_the_run(name, tmp_path):
    path, overrides, field = SCENARIO_ROWS[name]
    with pytest.raises(SpecError) as error:
        build_scene(load_spec(_file(path, tmp_path), [*VARIANT.get(path, []), *overrides]))
    _refused(error.value, field)


@pytest.mark.parametrize("name", list(STUDY_ROWS))
def test_a_bad_study_is_refused_before_the_run(name, tmp_path):
    path, overrides, field = STUDY_ROWS[name]
    with pytest.raises(SpecError) as error:
        load_study(_file(path, tmp_path), overrides)
    _refused(error.value, field)


def test_overrides_given_as_one_string_are_refused():
    """issue: ``load_spec(path, "load.radial=2000")`` with a string instead of a list."""
    with pytest.raises(SpecError) as error:
        load_spec(SCENARIOS / STEADY, "load.radial=2000")
    _refused(error.value, "overrides")


#: Scenarios whose scene takes seconds to build (the spindle tabulates its films' forces, ~10 s), built by their own
#: tests (tests/test_spindle.py).
BUILT_BY_THEIR_TESTS = ("seed_hybrid_spindle.toml",)


def test_the_seed_scenarios_still_load():
    """Every shipped scenario passes the stricter validation unchanged."""
    static_only = ("seed_slewing", "seed_hybrid_journal")  # their commands read them (their own tests)
    for path in sorted(p for p in SCENARIOS.glob("seed_*.toml") if not p.name.startswith(static_only)) + [
            SCENARIOS / "cage_models.toml", SCENARIOS / "static_check.toml"]:
        for variant in [None, *read_toml(path).get("variants", {})]:
            spec = load_spec(path, [f"scenario.variant={variant}"] if variant else [])
            assert math.isfinite(spec.scenario.end_time)
            if path.name not in BUILT_BY_THEIR_TESTS:
                build_scene(spec)
