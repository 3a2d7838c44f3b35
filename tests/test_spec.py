"""Bad input is rejected before anything runs, with an error naming the field, the value and what is allowed;
good input survives a round trip through its mapping."""

import json
from pathlib import Path

import pytest

from bearing_mbs.models import build_scene
from bearing_mbs.cli import main
from bearing_mbs.spec import SpecError, to_mapping
from bearing_mbs.models import load_spec, spec_from_mapping

SCENARIOS = Path(__file__).resolve().parents[1] / "scenarios"
CASE3 = SCENARIOS / "seed_case3.toml"


def rejected(overrides, path=CASE3):
    with pytest.raises(SpecError) as info:
        build_scene(load_spec(path, overrides))
    return info.value


@pytest.mark.parametrize(
    "override, field, allowed",
    [
        ("balls.0.mass=-0.1", "balls.0.mass", "> 0"),
        ("balls.0.radius=0", "balls.0.radius", "> 0"),
        ("contact.wall.stiffness=-6e6", "contact.wall.stiffness", "> 0"),
        ("contact.wall.restitution=0", "contact.wall.restitution", "(0, 1]"),
        ("contact.wall.restitution=1.2", "contact.wall.restitution", "(0, 1]"),
        ("contact.wall.friction_coefficient=-0.1", "contact.wall.friction_coefficient", "[0, 2]"),
        ("contact.wall.regularisation_speed=0", "contact.wall.regularisation_speed", "> 0"),
        ("contact.wall.normal_law='hertz'", "contact.wall.normal_law", "lankarani_nikravesh"),
        ("solver.reference.step=0", "solver.reference.step", "> 0"),
        ("solver.exudyn.step=-1e-5", "solver.exudyn.step", "> 0"),
        ("solver.output_interval=0", "solver.output_interval", "> 0"),
        ("scenario.end_time=-1", "scenario.end_time", "> 0"),
        ("contact.wall.stifness=1e6", "contact.wall.stifness", "unknown key"),
        ("solver.engine=matlab", "solver.engine", "reference, exudyn"),
        ("balls.3.mass=1", "balls.3", "index"),
        ("contact.wall.stiffness=big", "contact.wall.stiffness", "a number"),
        ("balls.0.position=[0.0, 0.004]", "balls.0.position", "overlap"),
    ],
)
def test_bad_input_names_field_value_and_allowed_range(override, field, allowed):
    error = rejected([override])
    assert error.field == field
    assert allowed in str(error)
    assert field in str(error)


def test_unknown_key_in_the_file_is_an_error(tmp_path):
    text = CASE3.read_text().replace("[box]\n", "[box]\nceiling = 1.0\n")
    path = tmp_path / "bad.toml"
    path.write_text(text)
    error = rejected([], path)
    assert error.field == "box.ceiling" and "allowed keys: floor, left_wall, right_wall" in str(error)


def test_overlapping_balls_are_rejected():
    error = rejected(["balls.1.position=[0.016, 0.021]"], SCENARIOS / "seed_case4.toml")
    assert error.field == "balls.1.position" and "ball1-ball2" in str(error)


def test_fixed_coordinate_must_start_at_rest():
    error = rejected(["balls.0.free=['y']"])
    assert error.field == "balls.0.velocity"


def test_explicit_exudyn_solver_with_a_joint_is_rejected_before_running():
    from bearing_mbs.engines.exudyn.engine import check_supported

    spec = load_spec(SCENARIOS / "seed_case5.toml", ["solver.exudyn.method=rk44"])
    with pytest.raises(SpecError) as info:
        check_supported(build_scene(spec), spec.solver)
    assert info.value.field == "solver.exudyn.method" and "generalized_alpha" in str(info.value)


def test_native_connector_refuses_friction():
    from bearing_mbs.engines.exudyn.engine import check_supported

    spec = load_spec(CASE3, ["solver.exudyn.connector=native"])
    with pytest.raises(SpecError, match="normal forces only"):
        check_supported(build_scene(spec), spec.solver)


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
    assert "contact.wall.restitution = 0" in capsys.readouterr().err
    assert not out.exists()


def test_a_bearing_spec_round_trips_through_its_mapping():
    spec = load_spec(SCENARIOS / "seed_hss_steady.toml")
    assert spec_from_mapping(json.loads(json.dumps(to_mapping(spec)))) == spec
