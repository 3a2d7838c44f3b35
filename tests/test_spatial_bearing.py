"""The seed HSS bearing in three dimensions (issue 31: ``models/cylindrical_roller/spatial.py``), dry, aligned.

References:
* the planar model on the same bearing (issue 31's first acceptance line): the scenario's dry variant as it is
  (Lankarani–Nikravesh contacts, erf friction, rolling resistance, Palmgren's drag, the cage on its outer land), so
  the two are the same physics: an aligned three-dimensional run from rest at 5 kN (rollers and cage accelerated by
  friction, the cage pushed by its rollers) must reproduce the planar run's cage speed and roller loads within 0.5 %
  of their scales (measured 5.6e-12 and 7.7e-10 over 2 ms, the cage at slip 0.86: RK4 on the quaternion against RK4
  on the angle), and every slice's frictional power intensity (the smearing measure, docs/smearing.md) the planar
  contact's;
* document 003's quasi-static load distribution (``solve_radial``, checked against Stribeck/Harris in
  tests/test_quasistatic_planar.py) at the same geometry, load and speed (centrifugal forces included): the inner
  ring's mean displacement over the last 2 ms of a 5 ms run from rolling start must match it within 2 % (measured
  1.0 %; what remains is the ring's settling bounce under the contacts' damping and the rollers' passing);
* document 003's sliced per-roller equilibrium (``sliced_roller_equilibrium``) under misalignment (issue 31's second
  acceptance line): crowned rollers, the inner ring's axis held 0.5 mrad off by the shaft, a slow run (100 rpm,
  5 ms, the contacts damped for a quasi-static response); at the run's last instant, each roller's slice loads on
  both raceways against the document's equilibrium at that roller's azimuth and the ring's displacement and tilt
  there, within 1 % of the largest slice load (measured 0.44 %);
* epicyclic kinematics: at 68 kN the rollers roll, so their spins stay within 1 % of the epicyclic spin (measured
  0.39 %: the raceways' deflections change the rolling radii) and the cage, which no roller pushes while all roll,
  keeps the epicyclic speed;
* the two engines on the same scene (0.3 ms, 1500 RK4 steps): within 1e-12 m and 1e-6 of the largest slice load
  (measured 6e-17 m, 5e-9 N); and (issue 31's fourth acceptance line) on the misaligned bearing started from rest,
  its rollers and cage dragged up to speed (cage slip 0.82 at 1.5 ms): skew, cage slip and the largest slice load
  within 0.5 % of their scales (measured 1.1e-4, 3.6e-6, 1.2e-4: the engines turn the bodies differently).
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.spatial.transform import Rotation

from bearing_mbs.engines import simulate
from bearing_mbs.engines.exudyn.spatial import simulate_spatial_exudyn
from bearing_mbs.engines.reference.spatial import simulate_spatial_reference
from bearing_mbs.models import build_scene, load_spec
from bearing_mbs.models.cylindrical_roller.geometry import BearingGeometry
from bearing_mbs.models.cylindrical_roller.metrics import raceway_power_intensity
from bearing_mbs.models.cylindrical_roller.quasistatic import (
    CircularCrown,
    RollerSet,
    SlicedRollerSet,
    sliced_roller_equilibrium,
    solve_radial,
)
from bearing_mbs.models.cylindrical_roller.spatial import (
    CAGE,
    CONTACTS_PER_ROLLER,
    FIRST_ROLLER,
    INNER,
    INNER_RING,
    OUTER,
    RIM_ANGLES,
    build_spatial_bearing,
)
from bearing_mbs.models.cylindrical_roller.spatial_figures import plot_attitudes, plot_slice_loads
from bearing_mbs.spec import SpecError, methods

from cases import SCENARIOS

DRY = ["scenario.variant=dry", "bearing.cage_guidance=rollers", "lubricant.model=none",
       "contact.inner_race.rolling_resistance_arm=0", "contact.outer_race.rolling_resistance_arm=0"]


def spec(*overrides):
    return load_spec(SCENARIOS / "seed_hss_steady.toml", [*DRY, *overrides])


def test_the_scene_holds_what_the_bearing_needs():
    bearing = build_spatial_bearing(spec(), slices=8)
    scene, rollers = bearing.scene, bearing.geometry.rollers
    assert len(scene.bodies) == 2 + rollers  # inner ring, cage, rollers; the outer ring is the ground
    assert len(scene.raceways) == CONTACTS_PER_ROLLER * rollers  # inner and outer raceway, four pocket edges
    assert all(len(contact.positions) == 8 for contact in scene.raceways)
    assert len(scene.flanges) == 3 * len(RIM_ANGLES) * rollers  # the outer ring's two ribs, the inner ring's one (NJ)
    assert len(scene.servos) == 1 and len(scene.forces) == 1 and len(scene.springs) == 2
    assert len(scene.axis_springs) == 1  # the shaft holding the inner ring's axis
    assert scene.gravity[1] < 0


@pytest.mark.parametrize("override, field", [
    ("cage.model=constraint", "cage.model"),
    ("contact.pocket.friction_law=tanh", "contact.pocket.friction_law"),
    ("contact.inner_race.friction_law=tanh", "contact.inner_race.friction_law"),
])
def test_what_three_dimensions_do_not_model_yet_is_refused_by_field(override, field):
    with pytest.raises(SpecError) as refused:
        build_spatial_bearing(spec(override))
    assert refused.value.field == field


def test_the_engines_agree_on_the_bearing():
    scene = build_spatial_bearing(spec(), damping_time=2e-5).scene
    reference, exudyn = (run(scene, 2e-7, 3e-4, 5e-5) for run in (simulate_spatial_reference, simulate_spatial_exudyn))
    assert reference.success and exudyn.success
    np.testing.assert_allclose(exudyn.position, reference.position, rtol=0, atol=1e-12)
    np.testing.assert_allclose(exudyn.slice_loads, reference.slice_loads, rtol=0,
                               atol=1e-6 * reference.slice_loads.max())


def test_under_its_nominal_load_the_bearing_settles_to_the_quasi_static_displacement():
    bearing_spec = spec()
    bearing = build_spatial_bearing(bearing_spec, damping_time=2e-5)
    series = simulate_spatial_reference(bearing.scene, 2e-7, 5e-3, 5e-5)
    assert series.success, series.message
    geometry = BearingGeometry.from_spec(bearing_spec.bearing)
    speed = bearing_spec.drive.speed_rpm * 2 * math.pi / 60
    angle = math.radians(bearing_spec.load.angle)
    load = bearing_spec.load.radial * np.array([math.cos(angle), math.sin(angle)])
    expected = solve_radial(RollerSet.from_geometry(geometry), tuple(load), shaft_speed=speed).displacement
    last = series.time >= 3e-3
    mean = series.position[last, INNER_RING, :2].mean(axis=0)
    np.testing.assert_allclose(mean[1], expected[1], rtol=0.02)
    assert abs(mean[0]) < 0.02 * abs(expected[1])
    np.testing.assert_allclose(series.angular_velocity[last, CAGE, 2], bearing.epicyclic_cage_speed, rtol=0.01)
    spin = bearing.geometry.epicyclic_roller_spin(speed)
    np.testing.assert_allclose(series.angular_velocity[-1, FIRST_ROLLER:, 2], spin, rtol=0.01)


def test_aligned_the_bearing_is_the_planar_model():
    solver = ["solver.engine=reference", "solver.reference.method=rk4", "solver.reference.step=2e-7",
              "solver.output_interval=1e-4"]
    bearing_spec = load_spec(SCENARIOS / "seed_hss_steady.toml", ["scenario.variant=dry", "drive.initial_state=rest",
                                                                  "load.radial=5000", *solver])
    end = 2e-3
    scene = build_scene(bearing_spec)
    planar = simulate(scene, bearing_spec.solver, end)
    bearing = build_spatial_bearing(bearing_spec, damping_time=0.0)  # the planar laws alone
    spatial = simulate_spatial_reference(bearing.scene, 2e-7, end, 1e-4)
    assert planar.success and spatial.success
    cage = planar.velocity[:, 3 * planar.body("cage") + 2]
    assert cage[-1] > 5.0  # the rollers have pushed the cage up to speed: the comparison sees the cage's dynamics
    np.testing.assert_allclose(spatial.angular_velocity[:, CAGE, 2], cage, rtol=0, atol=5e-3 * np.abs(cage).max())
    inner = [i for i, name in enumerate(planar.pair_names) if name.endswith("inner_race")]
    loads = planar.pair_output[:, inner, 3]  # normal force
    np.testing.assert_allclose(bearing.roller_loads(spatial), loads, rtol=0, atol=5e-3 * loads.max())
    # and the smearing measure: the planar contacts' frictional power intensity is every slice's of the aligned roller
    intensity = raceway_power_intensity(bearing_spec, scene, planar, np.ones(planar.time.size, bool), "inner_race")
    assert intensity.max() > 1e5  # W/m²: the rollers slide while they are dragged up to speed
    slices = bearing.power_intensity(spatial, INNER)
    for reduce in (np.max, np.min):
        np.testing.assert_allclose(reduce(slices, axis=2), intensity, rtol=0, atol=5e-3 * intensity.max())


#: The scenario's lubricated variant as far as three dimensions model it (docs/spatial.md): EHL traction on the
#: raceways (the planar ``ehl`` law per slice: Eyring film shear, shear heating, starved inlets, mixed friction,
#: hydrodynamic rolling resistance), churning drags, the cage on its land film, the pockets' films; the penalty cage.
LUBRICATED = ["cage.model=penalty"]


def test_aligned_and_lubricated_the_bearing_is_the_planar_model():
    """At 5 kN from rolling start the churning, the land film and the pocket films slow the cage, the churning and
    the pocket films the rollers, and each roller's traction, the planar ``ehl`` law on each slice at its load, slip
    and entrainment speed, drives it against the hydrodynamic rolling resistance: the three-dimensional run
    reproduces the planar run's cage speed, roller spins and roller loads within 0.5 % of their scales (measured
    4.9e-15, 6.9e-13 and 6.1e-11 over 2 ms: the same physics, RK4 on the quaternion against RK4 on the angle); the
    spins are also held to 1e-8, which 1.5 times the entrainment speed, the rolling resistance's or the pocket
    film's couple of the other sign fails."""
    solver = ["solver.engine=reference", "solver.reference.method=rk4", "solver.reference.step=2e-7",
              "solver.output_interval=1e-4"]
    bearing_spec = load_spec(SCENARIOS / "seed_hss_steady.toml", [*LUBRICATED, "load.radial=5000", *solver])
    end = 2e-3
    scene = build_scene(bearing_spec)
    planar = simulate(scene, bearing_spec.solver, end)
    bearing = build_spatial_bearing(bearing_spec, damping_time=0.0)
    assert bearing.scene.raceways[0].traction  # the inner raceway's slices carry the lubricated traction
    assert len(bearing.scene.films) == 1  # the cage's land film
    assert len(bearing.scene.pocket_films) == 2 * bearing.geometry.rollers  # each pocket's two walls
    spatial = simulate_spatial_reference(bearing.scene, 2e-7, end, 1e-4)
    assert planar.success and spatial.success
    cage = planar.velocity[:, 3 * planar.body("cage") + 2]
    assert cage[0] - cage[-1] > 0.1  # rad/s: the churning slows the cage
    np.testing.assert_allclose(spatial.angular_velocity[:, CAGE, 2], cage, rtol=0, atol=5e-3 * np.abs(cage).max())
    spins = np.column_stack([planar.velocity[:, 3 * planar.body(f"roller{k}") + 2]
                             for k in range(bearing.geometry.rollers)])
    assert np.ptp(spins, axis=0).max() > 1.0  # rad/s: traction and drag change the rollers' spins
    # the acceptance's 0.5 %, and (the same physics) far closer: a traction at another entrainment speed or slip
    # (1.5 times the entrainment speed, say) moves the spins by more than 1e-8 of their scale within 2 ms
    for tolerance in (5e-3, 1e-8):
        np.testing.assert_allclose(spatial.angular_velocity[:, FIRST_ROLLER:, 2], spins, rtol=0,
                                   atol=tolerance * np.abs(spins).max())
    inner = [i for i, name in enumerate(planar.pair_names) if name.endswith("inner_race")]
    loads = planar.pair_output[:, inner, 3]
    np.testing.assert_allclose(bearing.roller_loads(spatial), loads, rtol=0, atol=5e-3 * loads.max())


def test_a_slow_misaligned_run_carries_document_003s_slice_loads(tmp_path):
    bearing_spec = spec("drive.speed_rpm=100")
    geometry = BearingGeometry.from_spec(bearing_spec.bearing)
    rollers = RollerSet.from_geometry(geometry)
    crown = CircularCrown(radius=2.0, straight_length=geometry.roller_length / 2)
    model = SlicedRollerSet(rollers, roller_crown=crown, slices=20)
    misalignment = 5e-4
    bearing = build_spatial_bearing(bearing_spec, slices=20, crown=crown, damping_time=1e-4, misalignment=misalignment)
    series = simulate_spatial_reference(bearing.scene, 2e-7, 5e-3, 1e-3)
    assert series.success, series.message
    x, y = series.position[-1, INNER_RING, :2]
    w = series.orientation[-1, INNER_RING]
    axis = Rotation.from_quat([*w[1:], w[0]]).apply([0.0, 0.0, 1.0])
    theta_x, theta_y = -axis[1], axis[0]  # document 003's ring tilts (small angles)
    np.testing.assert_allclose(theta_x, misalignment, rtol=0.01)
    centres = series.position[-1, FIRST_ROLLER:, :2]
    psi = np.arctan2(centres[:, 1], centres[:, 0])
    speed = bearing_spec.drive.speed_rpm * 2 * math.pi / 60
    expected = sliced_roller_equilibrium(model, x * np.cos(psi) + y * np.sin(psi),
                                         -theta_x * np.sin(psi) + theta_y * np.cos(psi),
                                         rollers.centrifugal_force(speed))
    largest = expected.inner.slice_forces.max()
    for contact, reference in ((INNER, expected.inner), (OUTER, expected.outer)):
        np.testing.assert_allclose(bearing.slice_loads(series, contact)[-1], reference.slice_forces, rtol=0,
                                   atol=0.01 * largest)
    # the outputs: the loaded rollers' tilts are the document's β within 3 % of the largest (measured 1.6 %; 0.11 %
    # without the raceways' friction, whose axial part on a tilted rolling roller turns it and which document 003
    # leaves out); their skews (up to 0.04 mrad, of opposite signs on the two sides of the load) are the part of the
    # ring's tilt across their orbit, which the document's rollers cannot follow
    _skew, tilt = bearing.attitudes(series)
    loaded = expected.inner.force > 0.01 * expected.inner.force.max()
    np.testing.assert_allclose(tilt[-1, loaded], expected.roller_tilt[loaded], rtol=0,
                               atol=0.03 * np.abs(expected.roller_tilt).max())
    for draw, name in ((plot_slice_loads, "slices.png"), (plot_attitudes, "attitudes.png")):
        assert draw(bearing, series, tmp_path / name).stat().st_size > 10_000


def test_the_attitudes_are_measured_in_each_rollers_own_frame():
    """A roller at azimuth 90° (on +y), its axis turned by 2 mrad towards +y (its radius: tilt) and by 1 mrad
    towards −x (its orbit's tangent: skew)."""
    bearing = build_spatial_bearing(spec(), slices=4)
    rollers = bearing.geometry.rollers
    turn = Rotation.from_rotvec([-2e-3, 0.0, 0.0]) * Rotation.from_rotvec([0.0, -1e-3, 0.0])
    orientation = np.tile([1.0, 0.0, 0.0, 0.0], (1, 2 + rollers, 1))
    orientation[0, FIRST_ROLLER] = np.roll(turn.as_quat(), 1)
    position = np.zeros((1, 2 + rollers, 3))
    position[0, FIRST_ROLLER] = (0.0, 0.1, 0.0)
    series = type("Series", (), {"orientation": orientation, "position": position})
    skew, tilt = bearing.attitudes(series)
    np.testing.assert_allclose([skew[0, 0], tilt[0, 0]], [1e-3, 2e-3], rtol=1e-5)


def test_the_engines_agree_on_skew_cage_slip_and_the_largest_slice_load():
    bearing_spec = spec("drive.initial_state=rest", "load.radial=20000")
    geometry = BearingGeometry.from_spec(bearing_spec.bearing)
    crown = CircularCrown(radius=2.0, straight_length=geometry.roller_length / 2)
    bearing = build_spatial_bearing(bearing_spec, slices=10, crown=crown, damping_time=1e-4, misalignment=5e-4)
    reference, exudyn = (run(bearing.scene, 2e-7, 1.5e-3, 1e-4)
                         for run in (simulate_spatial_reference, simulate_spatial_exudyn))
    assert reference.success and exudyn.success
    assert bearing.cage_slip(reference)[-1] < 0.99  # the rollers have started to push the cage
    outputs = (lambda series: bearing.attitudes(series)[0], bearing.cage_slip,
               lambda series: series.slice_loads.max(axis=(1, 2)))
    for output in outputs:
        expected = output(reference)
        np.testing.assert_allclose(output(exudyn), expected, rtol=0, atol=5e-3 * np.abs(expected).max())


def test_the_rib_loads_are_each_rollers_own():
    """The scene lists the outer ring's two ribs per roller, then the inner ring's one per roller, each with its
    points on the roller's edge: each roller's three rib loads must sum its own points and come out in its own row."""
    bearing = build_spatial_bearing(spec(), slices=2)
    rollers = bearing.geometry.rollers
    names = [flange.name for flange in bearing.scene.flanges]
    for k in range(rollers):
        for rib in ("rib+", "rib-", "inner_rib"):
            marked = np.array([[name.startswith(f"roller{k}-{rib}") and name[len(f"roller{k}-{rib}"):].isdigit()
                                for name in names]], dtype=float)  # 1 on this rib's points
            ribs = bearing.rib_loads(type("Series", (), {"flange_loads": marked, "time": np.zeros(1)}))
            expected = np.zeros((rollers, 3))
            expected[k, ("rib+", "rib-", "inner_rib").index(rib)] = len(RIM_ANGLES)
            np.testing.assert_array_equal(ribs[0], expected)


def test_an_axial_load_goes_through_the_ribs():
    """NJ arrangement (the inner ring's rib at −z, the outer ring's two): an axial load on the inner ring along +z,
    every contact frictionless, the contacts damped (τ = 1e-4 s) so that the bearing settles: statics asks the
    inner ring's rib to push the rollers with the whole axial load and the outer ring's rib at +z to take it
    (Newton's third law along the chain ring–rollers–ring), the rib at −z nothing; over the last 2 ms of 8 ms each
    mean within 1 % of the load (measured 0.33 %; the implicit method at its sound setting). The rollers' ends meet
    the ribs on their rounded edges: their tilts and skews stay below 1 mrad (measured 0.13 and 0.015 mrad)."""
    frictionless = [f"contact.{group}.friction_law=none" for group in ("inner_race", "outer_race", "pocket", "land")]
    frictionless += [f"contact.{group}.rolling_resistance_arm=0" for group in ("inner_race", "outer_race")]
    bearing_spec = load_spec(SCENARIOS / "seed_hss_steady.toml", ["scenario.variant=dry", *frictionless])
    axial = 0.05 * bearing_spec.load.radial
    bearing = build_spatial_bearing(bearing_spec, damping_time=1e-4, axial_load=axial)
    series = simulate_spatial_reference(bearing.scene, 1e-5, 8e-3, 1e-4, method=methods.GENERALIZED_ALPHA,
                                        tolerance=1e-6)
    assert series.success, series.message
    late = series.time >= 6e-3 - 1e-12
    ribs = bearing.rib_loads(series)[late].sum(axis=1).mean(axis=0)  # +z outer, −z outer, inner [N]
    np.testing.assert_allclose(ribs, [axial, 0.0, axial], rtol=0, atol=1e-2 * axial)
    skew, tilt = bearing.attitudes(series)
    assert np.abs(skew[late]).max() < 1e-3 and np.abs(tilt[late]).max() < 1e-3
