"""Roller end–flange contacts in three dimensions (issue 31, item 2) against closed forms.

References (independent of :mod:`bearing_mbs.contact.flange` and the engines):
* Hertz, a sphere of radius R_e on a plane under a load F: the approach δ = (9F²/(16 R_e E*²))^(1/3), E* Johnson's
  contact modulus (K. L. Johnson, *Contact Mechanics*, 1985, eq. 4.23); 1e-6 relative once settled;
* Newton's law for the centre of a roller sliding on a flange with Coulomb friction under a constant axial load F:
  its speed falls at μF/m while its contact point slides (1e-3 of the start speed: the load varies a little as the
  friction tips the roller);
* the flange's band: a contact point outside the flange's radial extent carries nothing.
"""

from __future__ import annotations

import numpy as np
import pytest
from scipy.spatial.transform import Rotation

from bearing_mbs.contact.line_contact import STEEL_POISSON_RATIO, STEEL_YOUNGS_MODULUS, contact_modulus, reduced_modulus
from bearing_mbs.contact.point_contact import hertz_stiffness
from bearing_mbs.core.spatial import BodyForce, FlangeContact, SpatialBody, SpatialScene, TranslationSpring
from bearing_mbs.elements.spatial import new_work, spatial_forces
from bearing_mbs.engines.exudyn.spatial import simulate_spatial_exudyn
from bearing_mbs.engines.reference.spatial import simulate_spatial_reference

ENGINES = {"reference": simulate_spatial_reference, "exudyn": simulate_spatial_exudyn}
RADIUS, HALF_LENGTH, MASS = 0.0125, 0.0275, 0.21  # m, m, kg: a roller of the sliced model's test bearing
INERTIA = (MASS * (3 * RADIUS**2 + 4 * HALF_LENGTH**2) / 12,) * 2 + (MASS * RADIUS**2 / 2,)
END_RADIUS = 0.5  # m: the roller's spherical end
MODULUS = reduced_modulus(STEEL_YOUNGS_MODULUS, STEEL_POISSON_RATIO, STEEL_YOUNGS_MODULUS, STEEL_POISSON_RATIO)
STIFFNESS = hertz_stiffness((1 / END_RADIUS, 1 / END_RADIUS, 0.0, 0.0), MODULUS)


def pressed(load: float, band=(0.0, 1.0), velocity=(0.0, 0.0, 0.0), friction: float = 0.0,
            damping_time: float = 2e-5, approach: float = 0.0) -> SpatialScene:
    """A roller standing on its lower end on a flange in the plane z = 0 (normal +z), ``approach`` [m] into it,
    pushed down by ``load`` [N], its centre's x held by a spring (y free)."""
    roller = SpatialBody("roller", MASS, INERTIA, position=(0.1, 0.0, HALF_LENGTH - approach), velocity=velocity)
    flange = FlangeContact("flange", roller=0, ring=-1, end=-1, half_length=HALF_LENGTH, end_radius=END_RADIUS,
                           point=(0, 0, 0), normal=(0, 0, 1), band=band, stiffness=STIFFNESS,
                           damping_time=damping_time, friction_coefficient=friction, regularisation_speed=1e-4)
    return SpatialScene("on a flange", (roller,), forces=(BodyForce(0, (0.0, 0.0, -load)),),
                        springs=(TranslationSpring(0, (1, 0, 0), 1e8, 1e3),), flanges=(flange,))


@pytest.mark.parametrize("engine", ENGINES)
def test_an_axial_load_on_a_flange_gives_hertzs_approach(engine):
    load = 500.0
    series = ENGINES[engine](pressed(load), 1e-6, 0.004, 1e-3)
    assert series.success, series.message
    star = contact_modulus(STEEL_YOUNGS_MODULUS, STEEL_POISSON_RATIO, STEEL_YOUNGS_MODULUS, STEEL_POISSON_RATIO)
    approach = (9 * load**2 / (16 * END_RADIUS * star**2)) ** (1 / 3)
    np.testing.assert_allclose(HALF_LENGTH - series.position[-1, 0, 2], approach, rtol=1e-6)
    np.testing.assert_allclose(series.flange_loads[-1, 0], load, rtol=1e-6)


def test_a_flange_carries_nothing_outside_its_band():
    # the contact point lies 0.1 m from the flange's axis: a band of 0.11-0.2 m misses it, and the roller falls through
    series = simulate_spatial_reference(pressed(500.0, band=(0.11, 0.2)), 1e-6, 0.002, 1e-3)
    assert not series.flange_loads.any()
    np.testing.assert_allclose(series.position[-1, 0, 2], HALF_LENGTH - 0.5 * 500.0 / MASS * 0.002**2, rtol=1e-9)


@pytest.mark.parametrize("engine", ENGINES)
def test_a_roller_sliding_on_a_flange_slows_at_coulombs_rate(engine):
    """The friction at the end also tips the roller, which stops the contact point sliding within about 0.2 ms: the
    centre's speed follows Coulomb's rate while the contact point slides."""
    load, mu, speed = 500.0, 0.1, 0.2
    settled = (load / STIFFNESS) ** (2 / 3)  # start at the static approach: the normal load is the axial one
    series = ENGINES[engine](pressed(load, velocity=(0.0, speed, 0.0), friction=mu, approach=settled), 1e-6, 3e-4,
                             1e-5)
    assert series.success, series.message
    w = series.orientation[:, 0]
    rotations = Rotation.from_quat(np.column_stack([w[:, 1:], w[:, 0]])).as_matrix()
    arm = (HALF_LENGTH - END_RADIUS) * -rotations[:, :, 2] - END_RADIUS * np.array([0.0, 0.0, 1.0])
    spin = np.einsum("tij,tj->ti", rotations, series.angular_velocity[:, 0])
    point_speed = np.linalg.norm((series.velocity[:, 0] + np.cross(spin, arm))[:, :2], axis=1)
    sliding = point_speed > 100 * 1e-4  # well beyond the friction law's regularisation speed
    assert 5 <= sliding.sum() < series.time.size  # it slides, then sticks
    expected = speed - mu * load / MASS * series.time
    np.testing.assert_allclose(series.velocity[sliding, 0, 1], expected[sliding], rtol=0, atol=1e-3 * speed)


def test_the_engines_agree_on_a_sliding_roller():
    """The engines turn the bodies differently (RK4 on the quaternion, projected; Exudyn's RK44 on the Lie group), so
    they agree to their truncation errors, which the stick at the end of sliding amplifies: at 5e-7 s within 1e-8 m,
    1e-4 rad/s of 5 rad/s and 1e-3 N of 500 N (measured 1.4e-9 m, 3.6e-5 rad/s, 4e-5 N; at 1e-6 s the spins differ
    by 1.1e-2 rad/s)."""
    scene = pressed(500.0, velocity=(0.0, 0.2, 0.0), friction=0.1, approach=(500.0 / STIFFNESS) ** (2 / 3))
    reference, exudyn = (run(scene, 5e-7, 0.002, 2e-4) for run in ENGINES.values())
    np.testing.assert_allclose(exudyn.position, reference.position, rtol=0, atol=1e-8)
    np.testing.assert_allclose(exudyn.angular_velocity, reference.angular_velocity, rtol=0, atol=1e-4)
    np.testing.assert_allclose(exudyn.flange_loads, reference.flange_loads, rtol=0, atol=1e-3)


@pytest.mark.parametrize("change", [
    {"end": 0}, {"normal": (0, 0, 2)}, {"band": (0.2, 0.1)}, {"end_radius": 0.0}, {"stiffness": -1.0},
    {"exponent": 0.5}, {"friction_coefficient": -0.1},
])
def test_bad_flange_contacts_are_refused_on_construction(change):
    fields = {"name": "f", "roller": 0, "ring": -1, "end": 1, "half_length": 0.02, "end_radius": 0.5,
              "point": (0, 0, 0), "normal": (0, 0, 1), "band": (0.0, 0.1), "stiffness": 1e10}
    with pytest.raises(ValueError):
        FlangeContact(**{**fields, **change})


@pytest.mark.parametrize("skew", [0.0, 2e-4, -3e-4])
def test_a_roller_edge_on_a_rib_carries_hertzs_loads_and_resists_skew(skew):
    """A flat roller end with a rounded edge (corner radius ρ_c, the edge's centre circle at ρ from the axis) skewed
    by ψ about the radial direction x and pressed δ₀ into a rib (the plane z = 0) at five points of its edge, at
    angles φ_i about x: each point is a sphere of radius ρ_c centred at c_i = r + R(ψ)(ρ cos φ_i, ρ sin φ_i,
    −(L/2 − ρ_c)), so its load is Hertz's Q_i = K (ρ_c − c_i,z)^(3/2) ≈ K (δ₀ − ρ sin φ_i sin ψ)^(3/2), acting
    along z at c_i − ρ_c z. The moment of the loads about the radial axis, Σ (P_i − r)_y Q_i, opposes ψ: the rib
    resists skew to first order in ψ. One kernel evaluation against that closed form, within 1e-9."""
    corner, rim, approach = 1.25e-3, RADIUS - 1.25e-3, 2e-6  # m
    angles = np.radians([-60.0, -30.0, 0.0, 30.0, 60.0])
    stiffness = hertz_stiffness((1 / corner, 1 / corner, 0.0, 0.0), MODULUS)
    turn = Rotation.from_rotvec([skew, 0.0, 0.0])
    position = np.array([0.1, 0.0, HALF_LENGTH - approach])
    flanges = tuple(FlangeContact(f"edge{i}", roller=0, ring=-1, end=-1, half_length=HALF_LENGTH, end_radius=corner,
                                  point=(0, 0, 0), normal=(0, 0, 1), band=(0.0, 1.0), stiffness=stiffness,
                                  rim_radius=rim, rim_angle=angle) for i, angle in enumerate(angles))
    roller = SpatialBody("roller", MASS, INERTIA, position=tuple(position),
                         orientation=tuple(np.roll(turn.as_quat(), 1)))
    packed = SpatialScene("edge", (roller,), flanges=flanges).packed()
    work = new_work(1, packed)
    work.rotation[0] = turn.as_matrix()
    spatial_forces(packed, position[None, :], np.zeros((1, 3)), np.zeros((1, 3)), work)
    centres = position + turn.apply(np.column_stack([rim * np.cos(angles), rim * np.sin(angles),
                                                     np.full(5, -(HALF_LENGTH - corner))]))
    loads = stiffness * np.clip(corner - centres[:, 2], 0.0, None) ** 1.5
    np.testing.assert_allclose(work.flange_loads, loads, rtol=1e-9)
    first_order = stiffness * np.clip(approach - rim * np.sin(angles) * np.sin(skew), 0.0, None) ** 1.5
    np.testing.assert_allclose(loads, first_order, rtol=0, atol=1e-3 * loads.max())
    arms = centres - position - [0.0, 0.0, corner]
    moment = np.cross(arms, np.column_stack([np.zeros(5), np.zeros(5), loads])).sum(axis=0)
    np.testing.assert_allclose(turn.apply(work.moment[0]), moment, rtol=0, atol=1e-9 * loads.sum())
    if skew != 0.0:
        assert moment[0] * skew < 0  # against the skew


@pytest.mark.parametrize("edge", [1e-3, 0.0])
def test_a_point_crossing_a_rounded_flange_edge_keeps_the_energy_audit_closed(edge):
    """A roller standing on a small end sphere (1.25 mm, a rounded edge's corner) pressed onto a flange by 500 N
    slides radially at 0.5 m/s, its contact point leaving the flange over the band's outer edge, without friction:
    kinetic + stored − the load's work must stay what it was. With the edge rounded over 1 mm the point unloads
    continuously and the radial force −(∂w/∂d) E of the fading stored energy keeps the balance (within 1e-3 of the
    stored energy the edge hands back, RK4 at 1e-7 s); a sharp edge (0) drops that energy without work, and the
    audit fails by all of it."""
    from bearing_mbs.core.spatial import energy_audit

    load, speed, edge_at, corner = 500.0, 0.5, 0.1005, 1.25e-3
    stiffness = hertz_stiffness((1 / corner, 1 / corner, 0.0, 0.0), MODULUS)
    settled = (load / stiffness) ** (2 / 3)
    roller = SpatialBody("roller", MASS, INERTIA, position=(0.1, 0.0, HALF_LENGTH - settled),
                         velocity=(speed, 0.0, 0.0))
    flange = FlangeContact("flange", roller=0, ring=-1, end=-1, half_length=HALF_LENGTH, end_radius=corner,
                           point=(0, 0, 0), normal=(0, 0, 1), band=(0.0, edge_at), stiffness=stiffness, edge=edge)
    scene = SpatialScene("over the edge", (roller,), forces=(BodyForce(0, (0.0, 0.0, -load)),), flanges=(flange,))
    series = simulate_spatial_reference(scene, 1e-7, 0.004, 1e-4)
    assert series.success, series.message
    assert series.flange_loads[0, 0] > 0.99 * load and series.flange_loads[-1, 0] == 0.0  # on, then off the flange
    audit = energy_audit(scene, series)
    handed_back = audit.stored[0]  # the energy stored at the start, all of it released over the edge
    error = np.abs(audit.error).max() / handed_back
    if edge > 0:
        assert error < 1e-3, error
    else:
        assert error > 0.5, error
