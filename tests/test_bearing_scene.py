"""The bearing's spec, geometry and scene: validation, only-what-is-needed counts, closed forms.

References:
* item counts follow from the model definition (docs/bearing.md): per roller an inner and an outer raceway
  pair; pocket pairs P and Q for the penalty cage; one point-on-line constraint per roller for the constraint
  cage; Z roller–roller pairs and no cage body for a full complement;
* epicyclic speed ω_c = ω_i(1 − D_w/D_pw)/2 (Harris & Kotzalas, Essential Concepts of Bearing Technology,
  2006, ch. 8) against the kinematics of the built scene (pure rolling: zero slip at both raceways);
* the gear train's α1 (digest eqs. 41–44, sign derived) against a direct solve of eqs. 41–42;
* constraint Jacobians and γ = −Ġq̇ against central finite differences (1e-6 relative).
"""

import dataclasses
import math

import numpy as np
import pytest

from bearing_mbs.contact import twin
from bearing_mbs.core.scene import OrbitConstraint, PointOnLineConstraint
from bearing_mbs.elements import Load, VelocityServo, pack_scene, scene_counts
from bearing_mbs.engines.reference.constraints import constraint_rows
from bearing_mbs.models import build_scene, load_spec, spec_from_mapping
from bearing_mbs.models.cylindrical_roller.drivetrain import GearTrain
from bearing_mbs.models.cylindrical_roller.geometry import BearingGeometry
from bearing_mbs.models.cylindrical_roller.spec import GearTrainSpec
from bearing_mbs.spec import SpecError

from cases import SCENARIOS

STEADY = SCENARIOS / "seed_hss_steady.toml"
Z = 15


def scene_of(*overrides, path=STEADY):
    """The scene of the document's dry model (the scenario's variant "dry") with ``overrides``."""
    return build_scene(load_spec(path, ["scenario.variant=dry", *overrides]))


ROLLER_GUIDED = "bearing.cage_guidance=rollers"


@pytest.mark.parametrize(
    "overrides, counts",
    [
        ([ROLLER_GUIDED], {"bodies": Z + 2, "pairs": 6 * Z, "constraints": 0, "loads": 2, "drives": 1, "drags": Z, "sensors": 3}),
        (["cage.model=constraint", ROLLER_GUIDED], {"bodies": Z + 2, "pairs": 2 * Z, "constraints": Z, "loads": 2, "drives": 1,
                                     "drags": Z, "sensors": 4}),
        (["cage.model=none", ROLLER_GUIDED], {"bodies": Z + 1, "pairs": 3 * Z, "constraints": 0, "loads": 2, "drives": 1,
                               "drags": Z, "sensors": 3}),
        (["bearing.cage_guidance=outer_land", "bearing.land_clearance=4e-4"],
         {"bodies": Z + 2, "pairs": 6 * Z + 1, "constraints": 0, "loads": 2, "drives": 1, "drags": Z, "sensors": 3}),
        (["cage.model=constraint", "bearing.cage_guidance=inner_land", "bearing.land_clearance=4e-4"],
         {"bodies": Z + 2, "pairs": 2 * Z + 1, "constraints": Z, "loads": 2, "drives": 1, "drags": Z, "sensors": 4}),
        (["scenario.gravity=0", ROLLER_GUIDED], {"bodies": Z + 2, "pairs": 6 * Z, "constraints": 0, "loads": 1, "drives": 1,
                                  "drags": Z, "sensors": 3}),
        (["scenario.gravity=0", "load.radial=0", ROLLER_GUIDED], {"bodies": Z + 2, "pairs": 6 * Z, "constraints": 0, "loads": 0,
                                                   "drives": 1, "drags": Z, "sensors": 3}),
    ],
)
def test_each_scene_builds_only_what_it_needs(overrides, counts):
    assert scene_counts(scene_of(*overrides)) == {**counts, "slewing_bearings": 0, "journal_bearings": 0, "unbalances": 0}


def test_the_lubricated_default_builds_its_film_and_churning():
    """The scenario's default variant, lubricated: constraint cage (2Z raceway pairs, Z joints, 2Z oiled pocket
    walls) on its land (one contact pair for the land's rim and the oil film on it, one journal bearing), the
    churning of each roller and of the cage (Z + 1 drags)."""
    scene = build_scene(load_spec(STEADY))
    assert scene_counts(scene) == {"bodies": Z + 2, "pairs": 4 * Z + 1, "constraints": Z, "loads": 2, "drives": 1,
                                   "drags": Z + 1, "sensors": 4, "slewing_bearings": 0, "journal_bearings": 1,
                                   "unbalances": 0}


def test_full_complement_has_no_cage_and_neighbour_pairs_only():
    scene = scene_of("cage.model=none")
    assert "cage" not in [b.name for b in scene.bodies]
    roller_pairs = [p for p in scene.pairs if p.name.count("roller") == 2]
    assert len(roller_pairs) == Z
    assert {(p.body_a, p.body_b) for p in roller_pairs} == {(1 + k, 1 + (k + 1) % Z) for k in range(Z)}


def test_gear_train_scene_has_train_loads_and_no_servo():
    scene = scene_of(path=SCENARIOS / "seed_hss_gear_driven.toml")
    assert [l.name for l in scene.items_of(Load)] == ["drive_torque", "mesh_load_x", "mesh_load_y"]
    assert scene.items_of(VelocityServo) == ()


def test_initial_rolling_state_is_epicyclic_with_zero_slip():
    """Rollers start at the epicyclic speeds: pure rolling at both raceways (slip ~ 0), cage at ω_c."""
    spec = load_spec(STEADY, ["scenario.variant=dry", "scenario.gravity=0", "load.radial=0"])
    scene = build_scene(spec)
    geometry = BearingGeometry.from_spec(spec.bearing)
    q, v = scene.initial_state()
    omega_i = 1500 * 2 * math.pi / 60
    assert v[5] == pytest.approx(omega_i * (1 - geometry.roller_diameter / geometry.pitch_diameter) / 2)
    _, _, slip, *_ = twin.pair_geometry(pack_scene(scene).pairs, q, v)
    races = [k for k, p in enumerate(scene.pairs) if p.name.endswith("_race")]
    assert np.max(np.abs(slip[races])) < 1e-12 * omega_i * geometry.pitch_diameter


def test_seed_preset_is_the_coherent_document_bearing():
    geometry = BearingGeometry.from_spec(load_spec(STEADY, ["scenario.variant=dry"]).bearing)
    assert geometry.roller_diameter == pytest.approx((0.260 - 0.210) / 2, rel=1e-12)
    assert geometry.pitch_diameter == pytest.approx(0.235)
    assert abs(geometry.clearance) < 1e-15
    # roller mass and inertia as the document defines them: ρ π L D²/4 and m D²/8
    assert geometry.roller_mass == pytest.approx(7850 * math.pi * 0.055 * 0.025**2 / 4)
    assert geometry.roller_inertia == pytest.approx(geometry.roller_mass * 0.025**2 / 8)
    # a centred roller is exactly H from each pocket edge (eq. 45, and its mirror inside the pitch circle)
    for k in (0, 7):
        for point in geometry.pocket_points(k).values():
            centre = 0.5 * geometry.pitch_diameter * np.array([np.cos(geometry.roller_angles[k]),
                                                               np.sin(geometry.roller_angles[k])])
            assert np.hypot(*(centre - point)) == pytest.approx(0.0125 + 0.001, rel=1e-12)


VALID = object()  # marks an override that is accepted


@pytest.mark.parametrize(
    "override, field, value",
    [
        ("bearing.rollers=40", "bearing.rollers", 40),
        # the seed preset's raceways (D_i = 0.210, D_o = 0.260 m) around rollers of 0.03 m: interference 0.01 m
        ("bearing.roller_diameter=0.03", "bearing.outer_race_diameter", 0.26),
        ("bearing.outer_race_diameter=0.275", "bearing.outer_race_diameter", 0.275),
        ("bearing.inner_race_diameter=0.2101", "bearing.outer_race_diameter", 0.26),
        ("bearing.cage_diameter=0.27", "bearing.cage_diameter", 0.27),
        ("bearing.pocket_clearance=0.02", "bearing.rollers", Z),
        ("bearing.pitch_diameter=0.235", "bearing.pitch_diameter", 0.235),
        ("bearing.roller_length=-0.055", "bearing.roller_length", -0.055),
        ("bearing.supported_mass=-1", "bearing.supported_mass", -1.0),
        ("bearing.preset=nu999", "bearing.preset", "nu999"),
        ("bearing.cage_material.density=0", "bearing.cage_material.density", 0.0),
        ("bearing.ring_material.poisson_ratio=0.6", "bearing.ring_material.poisson_ratio", 0.6),
        ("cage.model=floating", "cage.model", "floating"),
        ("drive.kind=belt", "drive.kind", "belt"),
        ("drive.servo_time_constant=0", "drive.servo_time_constant", 0.0),
        ("drive.kind=gear_train", "drive.gear_train", None),  # the section a gear train needs is missing
        ("load.radial=-5", "load.radial", -5.0),
        ("load.profile=step", None, VALID),  # valid: a step to final = 0
        ("contact.pocket.stiffness_model=document", "contact.pocket.stiffness_model", "document"),
        ("contact.wall.stiffness=1e6", "contact.wall", {"stiffness": 1e6}),
        ("balls.0.mass=1", "balls", {"0": {"mass": 1}}),
        ("analysis.start_fraction=1.0", "analysis.start_fraction", 1.0),
    ],
)
def test_bearing_bad_input_names_the_field(override, field, value):
    if value is VALID:
        scene_of(override)
        return
    with pytest.raises(SpecError) as info:
        scene_of(override)
    error = info.value
    assert error.field == field, str(error)
    assert error.value == (pytest.approx(value, rel=1e-12) if isinstance(value, float) else value), str(error)
    assert error.allowed  # says what is allowed


@pytest.mark.parametrize(
    "override, choices",
    [
        ("bearing.preset=nu999", ("seed-hss",)),
        ("cage.model=floating", ("penalty", "constraint", "none")),
        ("drive.kind=belt", ("speed", "gear_train")),
        ("contact.wall.stiffness=1e6", ("inner_race", "outer_race", "pocket")),
    ],
)
def test_a_bad_bearing_choice_lists_the_allowed_ones(override, choices):
    with pytest.raises(SpecError) as info:
        scene_of(override)
    assert all(choice in info.value.allowed for choice in choices), info.value.allowed


def test_land_guidance_needs_a_land_clearance():
    mapping = {"scenario": {"name": "b", "model": "cylindrical_roller", "end_time": 0.01},
               "bearing": {"preset": "seed-hss", "cage_guidance": "inner_land"}}
    with pytest.raises(SpecError) as info:
        spec_from_mapping(mapping)
    assert info.value.field == "bearing.land_clearance" and info.value.value is None  # missing


def test_preload_within_bound_overlaps_only_the_raceways():
    scene = scene_of("bearing.inner_race_diameter=0.21004")  # 40 µm diametral interference
    q, v = scene.initial_state()
    gaps = twin.pair_geometry(pack_scene(scene).pairs, q, v)[0]
    raceways = np.array([p.name.endswith("_race") for p in scene.pairs])
    assert np.all(gaps[raceways] < 0) and np.all(gaps[~raceways] > 0)


def test_gear_train_acceleration_solves_equations_41_and_42():
    """α1 from the reduced inertia and drive torque equals a direct solve of eqs. 41–42, and has the sign
    of the derivation (a rotor torque above the reduced generator torque accelerates shaft 1)."""
    spec = GearTrainSpec(pinion_radius=0.1, gear_radius=0.4, shaft1_inertia=80, shaft2_inertia=8000,
                         generator_torque=5000, generator_torque_rate=0, rotor_torque=50000, rotor_torque_rate=0)
    train = GearTrain(spec)
    r1, r2, i1, i2 = 0.1, 0.4, 80.0, 8000.0
    # unknowns (α1, F_T): I1 α1 − r1 F_T = −T_R1 ; I2 (r1/r2) α1 + r2 F_T = T_M2
    alpha1, tangential = np.linalg.solve([[i1, -r1], [i2 * r1 / r2, r2]], [-5000.0, 50000.0])
    assert train.pinion_acceleration(0.0) == pytest.approx(alpha1, rel=1e-12)
    assert train.tangential_force(0.0) == pytest.approx(tangential, rel=1e-12)
    assert train.drive_torque(0.0) / train.reduced_inertia == pytest.approx(alpha1, rel=1e-12)
    assert alpha1 > 0


def _as_point_on_line(scene):
    """The constraint cage with each roller on its pocket's line through the cage centre instead (the other
    kind the builder does not use, checked the same way)."""
    lines = tuple(PointOnLineConstraint(c.name, c.body_a, c.body_b, (0.0, 0.0), c.direction)
                  for c in scene.constraints)
    return dataclasses.replace(scene, constraints=lines)


@pytest.mark.parametrize("kind", ["orbit", "point_on_line"])
def test_constraint_jacobian_and_gamma_match_finite_differences(kind):
    rng = np.random.default_rng(7)
    scene = scene_of("cage.model=constraint")
    assert all(isinstance(c, OrbitConstraint) for c in scene.constraints)
    if kind == "point_on_line":
        scene = _as_point_on_line(scene)
    constraints = pack_scene(scene).constraints
    q, v = scene.initial_state()
    q = q + rng.normal(scale=1e-3, size=q.size)
    v = v + rng.normal(scale=0.5, size=v.size)
    c, n = constraints.kind.size, q.size
    residual, jacobian, gamma = dense_constraint_rows(constraints, q, v)
    eps = 1e-7
    numeric = np.empty((c, n))
    for i in range(n):
        dq = np.zeros(n)
        dq[i] = eps
        numeric[:, i] = (dense_constraint_rows(constraints, q + dq, v)[0]
                         - dense_constraint_rows(constraints, q - dq, v)[0]) / (2 * eps)
    np.testing.assert_allclose(jacobian, numeric, rtol=1e-6, atol=1e-9)
    # γ = −Ġq̇: d/dt (G v) along the motion with v fixed, i.e. −(G(q + εv) − G(q − εv)) v / 2ε
    jp = dense_constraint_rows(constraints, q + eps * v, v)[1]
    jm = dense_constraint_rows(constraints, q - eps * v, v)[1]
    np.testing.assert_allclose(gamma, -((jp - jm) / (2 * eps)) @ v, rtol=1e-5, atol=1e-6)


def dense_constraint_rows(constraints, q, v):
    """(g, G as a dense C × n matrix, γ) from constraint_rows' compact rows (a's three columns, then b's)."""
    c = constraints.kind.size
    residual, gamma, rows = np.empty(c), np.empty(c), np.empty((c, 6))
    constraint_rows(constraints, q, v, residual, rows, gamma)
    jacobian = np.zeros((c, q.size))
    for k in range(c):
        a, b = constraints.body_a[k], constraints.body_b[k]
        jacobian[k, 3 * a:3 * a + 3] += rows[k, :3]
        jacobian[k, 3 * b:3 * b + 3] += rows[k, 3:]
    return residual, jacobian, gamma


def test_palmgren_stiffness_is_used_for_the_raceways_by_default():
    from bearing_mbs.contact.line_contact import palmgren_stiffness

    scene = scene_of()
    inner = next(p for p in scene.pairs if p.name == "roller0-inner_race")
    assert inner.law.stiffness == pytest.approx(palmgren_stiffness(0.055), rel=1e-12)
    assert inner.law.exponent == pytest.approx(10 / 9)
    document = scene_of("contact.inner_race.stiffness_model=document")
    inner = next(p for p in document.pairs if p.name == "roller0-inner_race")
    assert (inner.law.stiffness, inner.law.exponent) == (3e10, 1.3)
