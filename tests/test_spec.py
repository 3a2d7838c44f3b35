"""Bad input is rejected before anything runs, with an error naming the field, the value and what is allowed;
good input survives a round trip through its mapping."""

import json
import math
import tomllib
from pathlib import Path

import pytest

from bearing_mbs.cli import main
from bearing_mbs.contact.normal import NORMAL_LAWS
from bearing_mbs.models import build_scene, load_spec, spec_from_mapping
from bearing_mbs.spec import SpecError, read_scenario, to_mapping

SCENARIOS = Path(__file__).resolve().parents[1] / "scenarios"
CASE3 = SCENARIOS / "seed_case3.toml"


def rejected(overrides, path=CASE3):
    with pytest.raises(SpecError) as info:
        build_scene(load_spec(path, overrides))
    return info.value


@pytest.mark.parametrize(
    "override, field, value",
    [
        ("balls.0.mass=-0.1", "balls.0.mass", -0.1),
        ("balls.0.radius=0", "balls.0.radius", 0.0),
        ("contact.wall.stiffness=-6e6", "contact.wall.stiffness", -6e6),
        ("contact.wall.restitution=0", "contact.wall.restitution", 0.0),
        ("contact.wall.restitution=1.2", "contact.wall.restitution", 1.2),
        ("contact.wall.friction_coefficient=-0.1", "contact.wall.friction_coefficient", -0.1),
        ("contact.wall.regularisation_speed=0", "contact.wall.regularisation_speed", 0.0),
        ("contact.wall.normal_law='hertz'", "contact.wall.normal_law", "hertz"),
        ("solver.reference.step=0", "solver.reference.step", 0.0),
        ("solver.exudyn.step=-1e-5", "solver.exudyn.step", -1e-5),
        ("solver.output_interval=0", "solver.output_interval", 0.0),
        ("scenario.end_time=-1", "scenario.end_time", -1.0),
        ("contact.wall.stifness=1e6", "contact.wall.stifness", 1e6),
        ("solver.engine=matlab", "solver.engine", "matlab"),
        ("balls.3.mass=1", "balls.3", "3"),
        ("contact.wall.stiffness=big", "contact.wall.stiffness", "big"),
        # the value reported is the starting gap: centre height 4 mm minus radius 5 mm
        ("balls.0.position=[0.0, 0.004]", "balls.0.position", -0.001),
    ],
)
def test_bad_input_names_field_value_and_allowed_range(override, field, value):
    error = rejected([override])
    assert error.field == field
    assert error.value == (pytest.approx(value, rel=1e-12) if isinstance(value, float) else value)
    assert error.allowed
    # the message shows the field, the value and what is allowed, whatever its wording
    assert all(str(part) in str(error) for part in (error.field, error.value, error.allowed))


@pytest.mark.parametrize(
    "override, field, choices",
    [
        ("contact.wall.normal_law='hertz'", "contact.wall.normal_law", NORMAL_LAWS),
        ("solver.engine=matlab", "solver.engine", ("reference", "exudyn")),
        ("contact.wall.stifness=1e6", "contact.wall.stifness", ("stiffness", "restitution", "friction_law")),
    ],
)
def test_a_bad_choice_lists_the_allowed_ones(override, field, choices):
    error = rejected([override])
    assert error.field == field
    assert all(choice in error.allowed for choice in choices), error.allowed


def test_unknown_key_in_the_file_is_an_error(tmp_path):
    text = CASE3.read_text().replace("[box]\n", "[box]\nceiling = 1.0\n")
    path = tmp_path / "bad.toml"
    path.write_text(text)
    error = rejected([], path)
    assert error.field == "box.ceiling" and error.value == 1.0
    assert all(key in error.allowed for key in ("floor", "left_wall", "right_wall")), error.allowed


def test_overlapping_balls_are_rejected():
    error = rejected(["balls.1.position=[0.016, 0.021]"], SCENARIOS / "seed_case4.toml")
    assert error.field == "balls.1.position"
    # the value is the pair's starting gap: centre distance minus the sum of the radii, from the scenario file
    case4 = tomllib.loads((SCENARIOS / "seed_case4.toml").read_text())["balls"]
    centre = case4[0]["position"]
    expected_gap = math.hypot(0.016 - centre[0], 0.021 - centre[1]) - case4[0]["radius"] - case4[1]["radius"]
    assert expected_gap < 0 and error.value == pytest.approx(expected_gap, rel=1e-9)
    assert "ball1-ball2" in str(error)  # names the pair


def test_fixed_coordinate_must_start_at_rest():
    error = rejected(["balls.0.free=['y']"])
    assert error.field == "balls.0.velocity"
    assert error.value == tomllib.loads(CASE3.read_text())["balls"][0]["velocity"][0]  # the fixed x's speed


def test_explicit_exudyn_solver_with_a_joint_is_rejected_before_running():
    from bearing_mbs.engines.exudyn.engine import check_supported

    spec = load_spec(SCENARIOS / "seed_case5.toml", ["solver.exudyn.method=rk4"])
    with pytest.raises(SpecError) as info:
        check_supported(build_scene(spec), spec.solver)
    assert info.value.field == "solver.exudyn.method" and info.value.value == "rk4"
    assert "generalized_alpha" in info.value.allowed  # an implicit method that accepts joints


def test_native_connector_refuses_friction():
    from bearing_mbs.engines.exudyn.engine import check_supported

    spec = load_spec(CASE3, ["solver.exudyn.connector=native"])
    with pytest.raises(SpecError) as info:
        check_supported(build_scene(spec), spec.solver)
    assert info.value.field == "solver.exudyn.connector" and info.value.value == "native"
    assert "ball-floor" in info.value.allowed  # names the pair with friction


@pytest.mark.parametrize("name", [f"seed_case{i}" for i in range(1, 6)])
def test_shipped_scenarios_round_trip_through_their_mapping(name):
    spec = load_spec(SCENARIOS / f"{name}.toml")
    assert spec_from_mapping(json.loads(json.dumps(to_mapping(spec)))) == spec


def test_set_overrides_any_field_with_the_same_validation():
    spec = load_spec(CASE3, ["contact.wall.friction_law=erf", "balls.0.velocity=[0.5, 0]", "solver.engine=exudyn"])
    assert spec.contact.wall.friction_law == "erf"
    assert spec.balls[0].velocity == (0.5, 0.0)
    assert spec.solver.engine == "exudyn"


def test_cli_rejects_bad_input_with_exit_status_2_and_writes_nothing(tmp_path, capsys):
    out = tmp_path / "out"
    status = main(["run", str(CASE3), "--out", str(out), "--set", "contact.wall.restitution=0", "--quiet"])
    assert status == 2
    assert "contact.wall.restitution" in capsys.readouterr().err  # the field is named
    assert not out.exists()


def test_a_bearing_spec_round_trips_through_its_mapping():
    spec = load_spec(SCENARIOS / "seed_hss_steady.toml")
    assert spec_from_mapping(json.loads(json.dumps(to_mapping(spec)))) == spec


def test_a_variant_changes_only_what_it_names_and_an_override_beats_it(tmp_path):
    """[scenario] variant applies its [variants.<name>] table's values over the file's, an override may choose
    the variant and overrides win over it; the spec holds the result, not the variant's name."""
    path = tmp_path / "variants.toml"
    text = (SCENARIOS / "seed_case2.toml").read_text().replace("[scenario]\n", "[scenario]\nvariant = 'soft'\n", 1)
    path.write_text(text + "\n[variants.soft]\ncontact.wall = { restitution = 0.5 }\nscenario.end_time = 0.05\n"
                    "\n[variants.base]\n")
    base = load_spec(SCENARIOS / "seed_case2.toml")
    soft = load_spec(path)
    assert soft.contact.wall.restitution == 0.5 and soft.scenario.end_time == 0.05
    assert to_mapping(soft) == to_mapping(load_spec(SCENARIOS / "seed_case2.toml", [
        "contact.wall.restitution=0.5", "scenario.end_time=0.05"]))
    assert load_spec(path, ["scenario.variant=base"]) == base
    assert load_spec(path, ["scenario.end_time=0.2"]).scenario.end_time == 0.2  # the override wins
    assert "variant" not in to_mapping(soft)["scenario"]


def test_the_seed_hss_scenarios_are_lubricated_and_their_dry_variant_is_the_documents_model():
    """The lubricated default: EHL raceways with rolling resistance, churning, the land and pocket films and the
    side rings, the constraint cage. The dry variant: the document's regularised Coulomb (erf) raceways, no
    lubricant section, the cage without side rings (the preset's width, the 55 mm pocket length) and the penalty
    cage."""
    for name in ("steady", "startup", "load_drop", "emergency_stop", "gear_driven"):
        path = SCENARIOS / f"seed_hss_{name}.toml"
        lubricated, dry = load_spec(path), load_spec(path, ["scenario.variant=dry"])
        for race in (lubricated.contact.inner_race, lubricated.contact.outer_race):
            assert (race.friction_law, race.ehl_rolling_resistance) == ("ehl", True)
        assert (lubricated.lubricant.model, lubricated.lubricant.land_film, lubricated.lubricant.pocket_film) == (
            "churning", True, True)
        assert (lubricated.cage.model, lubricated.bearing.cage_width) == ("constraint", 0.071)
        for race in (dry.contact.inner_race, dry.contact.outer_race):
            assert (race.friction_law, race.ehl_rolling_resistance) == ("erf", False)
        assert dry.lubricant.temperature is None and not dry.lubricant.pocket_film and dry.cage.model == "penalty"
        assert dry.drive == lubricated.drive and dry.load == lubricated.load


def test_an_old_method_name_is_accepted_with_a_warning():
    """Exudyn's classic Runge–Kutta is ``rk4``, as on the reference engine; ``rk44`` still loads, and warns."""
    with pytest.warns(FutureWarning, match="rk4"):
        spec = load_spec(SCENARIOS / "seed_hss_steady.toml", ["solver.exudyn.method=rk44"])
    assert spec.solver.exudyn.method == "rk4"


def test_the_old_model_name_is_accepted_with_a_warning_that_names_the_new_one():
    """The bearing model is ``cylindrical_roller``, its package's name; ``bearing`` still loads, warns, and gives the
    same spec as the new name."""
    with pytest.warns(FutureWarning, match="cylindrical_roller"):
        old = load_spec(SCENARIOS / "seed_hss_steady.toml", ["scenario.model=bearing"])
    assert old.scenario.model == "cylindrical_roller"
    assert old == load_spec(SCENARIOS / "seed_hss_steady.toml")


def test_an_analysis_start_past_a_shortened_run_moves_to_half_of_it(caplog):
    """One override shortens a run: the scenario's 0.05 s window start is past a 0.01 s end, so the window starts
    at 0.005 s, and the log says so."""
    with caplog.at_level("WARNING"):
        spec = load_spec(SCENARIOS / "seed_hss_steady.toml", ["scenario.end_time=0.01"])
    assert spec.analysis.window_start(spec.scenario.end_time) == pytest.approx(0.005)
    assert any("analysis.start" in record.getMessage() for record in caplog.records)


def test_the_analysis_window_as_a_fraction_of_the_run():
    spec = spec_from_mapping(_steady_with_fraction(0.25))
    assert spec.analysis.window_start(spec.scenario.end_time) == pytest.approx(0.25 * spec.scenario.end_time)
    with pytest.raises(SpecError) as error:
        spec_from_mapping(_steady_with_fraction(0.25, start=0.05))
    assert error.value.field == "analysis.start_fraction"


def _steady_with_fraction(fraction, start=None):
    data = read_scenario(SCENARIOS / "seed_hss_steady.toml")
    data["analysis"] = {"start_fraction": fraction, **({"start": start} if start is not None else {})}
    return data
