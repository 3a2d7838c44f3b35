"""Sliced roller–raceway contacts in three dimensions (issue 31, item 2) against document 003's quasi-static model.

References (independent of the code under test: :mod:`bearing_mbs.contact.sliced_raceway` and the spatial engines):
* document 003's sliced per-roller equilibrium (``sliced_roller_equilibrium``, itself checked against the planar
  model, Stribeck/Harris and its own Jacobians in tests/test_quasistatic_sliced.py): a crowned roller between an
  inner raceway displaced by u_r and tilted by φ = 0.5 mrad and a fixed outer raceway, under a centrifugal force,
  settled by the contacts' damping, must carry the same slice loads within 1 % of the largest (measured 0.05 %; the
  three-dimensional kinematics differ from the document's first-order ones by about φ² R/2 against a 13 µm approach)
  and take the same displacement and tilt within 1 % (measured 0.06 % and 0.001 %);
* a straight roller, aligned, equal laws on both sides: the two approaches are equal, so each contact carries
  Q = K ((u_r − 2 J_b)/2)^n with Palmgren's K and n = 10/9 (closed form, 1e-6 relative);
* a spinning roller set down on a raceway (radius 10 m, nearly a plane) under a constant normal force: it slides
  with Coulomb friction μF until it rolls, v(t) = μF t/m, ω(t) = ω₀ − μF r t/I, then rolls at v = ω₀ r I/(I + m r²)
  (the textbook result for a cylinder set spinning on a plane); within 1e-3 of v_f and ω₀ (measured 1.4e-4: the
  regularisation near the end of sliding, and the raceway's curvature);
* the two engines against each other (1e-6 relative).
"""

from __future__ import annotations

import numpy as np
import pytest
from scipy.spatial.transform import Rotation

from bearing_mbs.contact.line_contact import slice_coefficient
from bearing_mbs.core.spatial import BodyForce, SlicedRaceway, SpatialBody, SpatialScene, TranslationSpring
from bearing_mbs.engines.exudyn.spatial import simulate_spatial_exudyn
from bearing_mbs.engines.reference.spatial import simulate_spatial_reference
from bearing_mbs.models.cylindrical_roller.quasistatic import (
    CircularCrown,
    Flat,
    LogarithmicCrown,
    RollerSet,
    SlicedRollerSet,
    sliced_roller_equilibrium,
)

PITCH, DIAMETER, LENGTH = 0.235, 0.025, 0.055  # m: the sliced model's test bearing
ROLLERS = RollerSet(15, PITCH, DIAMETER, LENGTH)
CROWNED = SlicedRollerSet(ROLLERS, roller_crown=CircularCrown(radius=2.0, straight_length=LENGTH / 2),
                          inner_raceway_crown=Flat(), slices=40)
STRAIGHT = SlicedRollerSet(ROLLERS, slices=20)
LOGARITHMIC = SlicedRollerSet(ROLLERS, roller_crown=LogarithmicCrown.lundberg(15e3, LENGTH, 1.15e11, end_drop=3e-5),
                              inner_raceway_crown=Flat(), slices=40)
DAMPING_TIME = 2e-6  # s: settles the roller's contact modes (about 1e5 rad/s) within 2 ms
STEP, END = 1e-6, 0.006  # s

ENGINES = {"reference": simulate_spatial_reference, "exudyn": simulate_spatial_exudyn}


def one_roller(model: SlicedRollerSet, radial: float, tilt: float, centrifugal: float) -> SpatialScene:
    """Roller 0 of ``model`` at azimuth 0 (on the x axis, its axis along z), the outer raceway fixed and centred, the
    inner raceway's centre moved by ``radial`` [m] towards the roller and its axis tilted by ``tilt`` [rad] about y
    (document 003's u_r and φ); the roller's axial and tangential position held by stiff springs, as the flanges
    and the cage would."""
    rollers = model.rollers
    r, jb, m = rollers.roller_diameter / 2, rollers.contact_clearance, rollers.roller_mass
    pitch_radius = rollers.pitch_diameter / 2
    transverse, axial = m * (3 * r**2 + rollers.roller_length**2) / 12, m * r**2 / 2
    common = {"roller": 0, "ring": -1, "roller_radius": r, "positions": tuple(model.slice_positions),
              "width": model.slice_width, "damping_time": DAMPING_TIME}
    inner = SlicedRaceway("inner", centre=(radial, 0, 0), axis=(np.sin(tilt), 0, np.cos(tilt)),
                          raceway_radius=pitch_radius - r - jb, side="inner", drops=tuple(model.inner_drops),
                          coefficient=float(slice_coefficient(rollers.inner_stiffness, rollers.roller_length)),
                          exponent=rollers.inner_exponent, **common)
    outer = SlicedRaceway("outer", centre=(0, 0, 0), axis=(0, 0, 1), raceway_radius=pitch_radius + r + jb,
                          side="outer", drops=tuple(model.outer_drops),
                          coefficient=float(slice_coefficient(rollers.outer_stiffness, rollers.roller_length)),
                          exponent=rollers.outer_exponent, **common)
    roller = SpatialBody("roller", m, (transverse, transverse, axial), position=(pitch_radius, 0, 0))
    return SpatialScene("one roller", (roller,), forces=(BodyForce(0, (centrifugal, 0, 0)),),
                        springs=(TranslationSpring(0, (0, 1, 0), 1e8, 1e3), TranslationSpring(0, (0, 0, 1), 1e8, 1e3)),
                        raceways=(inner, outer))


def tilt_about_y(orientation) -> float:
    """The roller's tilt β [rad]: its axis (R e₃) turned towards +x."""
    w, x, y, z = orientation
    axis = Rotation.from_quat([x, y, z, w]).as_matrix()[:, 2]
    return float(np.arctan2(axis[0], axis[2]))


@pytest.mark.parametrize("engine, model", [("reference", CROWNED), ("exudyn", CROWNED), ("reference", LOGARITHMIC)])
def test_a_settled_misaligned_crowned_roller_carries_document_003s_slice_loads(engine, model):
    """Circular and logarithmic (Lundberg's, with an end drop) crowns: the profile enters the slices as their
    drops, as in document 003."""
    radial, tilt, centrifugal = 2.5e-5, 5e-4, 100.0
    expected = sliced_roller_equilibrium(model, [radial], [tilt], centrifugal)
    series = ENGINES[engine](one_roller(model, radial, tilt, centrifugal), STEP, END, 1e-3)
    assert series.success, series.message
    for contact, reference in enumerate((expected.inner, expected.outer)):
        loads = reference.slice_forces[0]
        np.testing.assert_allclose(series.slice_loads[-1, contact], loads, rtol=0, atol=0.01 * loads.max())
    displacement = series.position[-1, 0, 0] - PITCH / 2
    np.testing.assert_allclose(displacement, expected.roller_displacement[0], rtol=0.01)
    np.testing.assert_allclose(tilt_about_y(series.orientation[-1, 0]), expected.roller_tilt[0], rtol=0.01)
    # settled: the last two output instants agree (the damping has done its work)
    np.testing.assert_allclose(series.slice_loads[-1], series.slice_loads[-2], rtol=0, atol=1e-6 * loads.max())


def test_an_aligned_straight_roller_carries_palmgrens_line_load():
    radial = 3e-5
    series = simulate_spatial_reference(one_roller(STRAIGHT, radial, 0.0, 0.0), STEP, END, 1e-3)
    rollers = STRAIGHT.rollers
    expected = rollers.inner_stiffness * ((radial - 2 * rollers.contact_clearance) / 2) ** rollers.inner_exponent
    for contact in range(2):
        np.testing.assert_allclose(series.slice_loads[-1, contact].sum(), expected, rtol=1e-6)
        # uniform along the straight roller
        np.testing.assert_allclose(series.slice_loads[-1, contact], expected / STRAIGHT.slices, rtol=1e-6)


def test_the_engines_agree_on_the_misaligned_roller():
    scene = one_roller(CROWNED, 2.5e-5, 5e-4, 100.0)
    reference, exudyn = (run(scene, STEP, 0.002, 5e-4) for run in ENGINES.values())
    scale = reference.slice_loads.max()
    np.testing.assert_allclose(exudyn.slice_loads, reference.slice_loads, rtol=0, atol=1e-6 * scale)
    np.testing.assert_allclose(exudyn.position, reference.position, rtol=0, atol=1e-12)
    np.testing.assert_allclose(exudyn.orientation, reference.orientation, rtol=0, atol=1e-10)


@pytest.mark.parametrize("change", [
    {"axis": (0.0, 0.0, 2.0)},  # not a unit vector
    {"side": "left"},
    {"drops": (-1e-6,) * 3},
    {"positions": (0.0, 0.01), "drops": (0.0,) * 3},  # a drop per slice
    {"coefficient": 0.0},
    {"exponent": 0.5},
    {"damping_time": -1.0},
])
def test_bad_raceway_contacts_are_refused_on_construction(change):
    fields = {"name": "c", "roller": 0, "ring": -1, "centre": (0, 0, 0), "axis": (0, 0, 1), "raceway_radius": 0.1,
              "side": "inner", "roller_radius": 0.01, "positions": (-0.01, 0.0, 0.01), "drops": (0.0,) * 3,
              "width": 0.01, "coefficient": 1e10, "exponent": 10 / 9}
    with pytest.raises(ValueError):
        SlicedRaceway(**{**fields, **change})


def test_bad_spatial_force_elements_are_refused():
    body = SpatialBody("b", 1.0, (1.0, 1.0, 1.0))
    with pytest.raises(ValueError):
        TranslationSpring(0, (0, 0, 2), 1e6)
    with pytest.raises(ValueError):
        TranslationSpring(0, (1, 0, 0), 0.0)
    with pytest.raises(ValueError):
        SpatialScene("s", (body,), forces=(BodyForce(2, (0, 0, 1)),))
    contact = SlicedRaceway("c", 0, 0, (0, 0, 0), (0, 0, 1), 0.1, "inner", 0.01, (0.0,), (0.0,), 0.01, 1e10, 10 / 9)
    with pytest.raises(ValueError):  # a roller against itself
        SpatialScene("s", (body,), raceways=(contact,))


def test_a_free_ring_and_roller_keep_their_momentum():
    """No external load: a tilted, spinning ring (the raceway on a body) strikes a roller and they part, with
    friction. The contact forces act in pairs with their moments, so the total linear momentum and the angular momentum about the origin,
    Σ (r × m ṙ + R I ω), stay what they were (to the integrator's accuracy, 1e-9 of their scale), while the roller
    picks up a large part of both (the contact did act)."""
    rollers = CROWNED.rollers
    r, m = rollers.roller_diameter / 2, rollers.roller_mass
    pitch_radius = rollers.pitch_diameter / 2
    ring = SpatialBody("ring", 2.0, (4e-3, 4e-3, 7e-3), orientation=tuple(
        np.roll(Rotation.from_rotvec([0.0, 3e-4, 0.0]).as_quat(), 1)), velocity=(0.5, 0.02, 0.0),
        angular_velocity=(0.3, -0.2, 50.0))
    roller = SpatialBody("roller", m, (m * (3 * r**2 + LENGTH**2) / 12,) * 2 + (m * r**2 / 2,),
                         position=(pitch_radius + 1e-6, 0.0, 0.001), angular_velocity=(0.0, 0.0, -20.0))
    contact = SlicedRaceway("inner", roller=1, ring=0, centre=(0, 0, 0), axis=(0, 0, 1),
                            raceway_radius=pitch_radius - r, side="inner", roller_radius=r,
                            positions=tuple(CROWNED.slice_positions), drops=tuple(CROWNED.inner_drops),
                            width=CROWNED.slice_width, exponent=10 / 9, damping_time=DAMPING_TIME,
                            coefficient=float(slice_coefficient(rollers.inner_stiffness, LENGTH)),
                            friction_coefficient=0.1, regularisation_speed=1e-3)
    scene = SpatialScene("ring and roller", (ring, roller), raceways=(contact,))
    for run in ENGINES.values():
        series = run(scene, 2e-7, 2e-4, 1e-5)
        assert series.success, series.message
        assert series.slice_loads[:, 0].sum(axis=1).max() > 100.0  # they met
        masses = np.array([ring.mass, roller.mass])
        linear = np.einsum("b,tbj->tj", masses, series.velocity)
        w = series.orientation
        rotations = Rotation.from_quat(np.concatenate([w[..., 1:], w[..., :1]], axis=-1).reshape(-1, 4)).as_matrix()
        inertia = np.array([ring.inertia, roller.inertia])
        spin = np.einsum("tbij,tbj->tbi", rotations.reshape(*w.shape[:2], 3, 3), inertia * series.angular_velocity)
        angular = (np.cross(series.position, masses[None, :, None] * series.velocity) + spin).sum(axis=1)
        scale_linear, scale_angular = np.abs(linear[0]).max(), np.abs(angular[0]).max()
        np.testing.assert_allclose(linear, np.broadcast_to(linear[0], linear.shape), rtol=0, atol=1e-9 * scale_linear)
        np.testing.assert_allclose(angular, np.broadcast_to(angular[0], angular.shape), rtol=0,
                                   atol=1e-9 * scale_angular)
        assert np.abs(roller.mass * series.velocity[-1, 1]).max() > 0.05 * scale_linear  # the roller was pushed


@pytest.mark.parametrize("engine", ENGINES)
def test_a_common_rigid_motion_does_not_damp(engine):
    """Ring and roller pressed together, at rest or turning and moving together as one rigid body: the interference
    does not change, so the damped slice loads at the start are the static ones (1e-9 of the largest); a wrong
    relative velocity of the ring's material point would damp the common motion."""
    rollers = CROWNED.rollers
    r, m = rollers.roller_diameter / 2, rollers.roller_mass
    pitch_radius = rollers.pitch_diameter / 2
    spin, drift = np.array([0.4, -0.3, 80.0]), np.array([0.2, -0.1, 0.05])  # rad/s, m/s
    tilt = Rotation.from_rotvec([0.0, 4e-4, 0.0])
    centre = tilt.apply([pitch_radius - 1e-5, 0.0, 0.0])  # the roller 10 µm into the raceway, on the tilted ring

    def scene(moving: bool) -> SpatialScene:
        w = spin if moving else np.zeros(3)
        ring = SpatialBody("ring", 2.0, (4e-3, 4e-3, 7e-3), orientation=tuple(np.roll(tilt.as_quat(), 1)),
                           velocity=tuple(drift if moving else np.zeros(3)), angular_velocity=tuple(w))
        world_spin = tilt.apply(w)  # the ring's ω in the world frame; the roller turns with it
        roller = SpatialBody("roller", m, (m * (3 * r**2 + LENGTH**2) / 12,) * 2 + (m * r**2 / 2,), position=tuple(centre),
                             orientation=tuple(np.roll(tilt.as_quat(), 1)),
                             velocity=tuple((drift + np.cross(world_spin, centre)) if moving else np.zeros(3)),
                             angular_velocity=tuple(w))
        contact = SlicedRaceway("inner", roller=1, ring=0, centre=(0, 0, 0), axis=(0, 0, 1),
                                raceway_radius=pitch_radius - r, side="inner", roller_radius=r,
                                positions=tuple(CROWNED.slice_positions), drops=tuple(CROWNED.inner_drops),
                                width=CROWNED.slice_width, exponent=10 / 9, damping_time=1e-4,
                                coefficient=float(slice_coefficient(rollers.inner_stiffness, LENGTH)))
        return SpatialScene("pressed", (ring, roller), raceways=(contact,))

    at_rest, moving = (ENGINES[engine](scene(flag), 1e-7, 1e-7, 1e-7).slice_loads[0, 0] for flag in (False, True))
    assert at_rest.max() > 100.0  # N: pressed
    np.testing.assert_allclose(moving, at_rest, rtol=0, atol=1e-9 * at_rest.max())


@pytest.mark.parametrize("engine", ENGINES)
def test_a_spinning_roller_set_on_a_raceway_slides_then_rolls(engine):
    rollers = STRAIGHT.rollers
    r, m = rollers.roller_diameter / 2, rollers.roller_mass
    axial, transverse = m * r**2 / 2, m * (3 * r**2 + LENGTH**2) / 12
    radius, normal, mu, spin = 10.0, 20.0, 0.1, 10.0  # m, N, -, rad/s
    stiffness, exponent = rollers.inner_stiffness, rollers.inner_exponent
    approach = (normal / stiffness) ** (1 / exponent)  # set down at the static approach
    contact = SlicedRaceway("plane", roller=0, ring=-1, centre=(0, 0, 0), axis=(0, 0, 1), raceway_radius=radius,
                            side="inner", roller_radius=r, positions=tuple(STRAIGHT.slice_positions),
                            drops=tuple(STRAIGHT.inner_drops), width=STRAIGHT.slice_width, exponent=exponent,
                            damping_time=DAMPING_TIME, coefficient=float(slice_coefficient(stiffness, LENGTH)),
                            friction_coefficient=mu, regularisation_speed=1e-4)
    roller = SpatialBody("roller", m, (transverse, transverse, axial), position=(radius + r - approach, 0, 0),
                         angular_velocity=(0, 0, spin))
    scene = SpatialScene("set down spinning", (roller,), forces=(BodyForce(0, (-normal, 0, 0)),),
                         springs=(TranslationSpring(0, (0, 0, 1), 1e8, 1e3),), raceways=(contact,))
    acceleration, deceleration = mu * normal / m, mu * normal * r / axial
    rolls_at = spin * r / (acceleration + deceleration * r)
    series = ENGINES[engine](scene, 2e-6, 2 * rolls_at, rolls_at / 10)
    assert series.success, series.message
    t = np.minimum(series.time, rolls_at)
    final_speed = spin * r * axial / (axial + m * r**2)
    np.testing.assert_allclose(series.velocity[:, 0, 1], acceleration * t, rtol=0, atol=1e-3 * final_speed)
    np.testing.assert_allclose(series.angular_velocity[:, 0, 2], spin - deceleration * t, rtol=0, atol=1e-3 * spin)
    np.testing.assert_allclose(series.velocity[-1, 0, 1], final_speed, rtol=1e-3)
