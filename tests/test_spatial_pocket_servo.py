"""A roller against a plane (a cage pocket's wall), the spin servo and the axis spring, in three dimensions (issue 31).

References (independent of the kernel):
* a straight roller tilted against a plane carries document 003's slice loads Q_k = C_f w (δ + α z_k)^n
  (``sliced_contact`` of the quasi-static model, eq. 12 and 14 there), to the three-dimensional kinematics'
  second-order difference: within 1e-6 of the largest slice load for α = 2e-4;
* a free body spun up by the servo M = g (Ω − ω): ω(t) = Ω (1 − exp(−g t/I)), within 1e-6 of Ω (RK4 at 1e-4 s
  against a time constant of 0.05 s); the servo's work closes the energy audit within 1e-6 of it;
* a body whose axis a spring holds, turned by a constant moment: k sin θ = M (1e-6 relative).
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.spatial.transform import Rotation

from bearing_mbs.contact.line_contact import slice_coefficient, sliced_contact
from bearing_mbs.core.spatial import (
    AxisSpring,
    BodyMoment,
    SlicedRaceway,
    SpatialBody,
    SpatialScene,
    SpinServo,
    energy_audit,
)
from bearing_mbs.engines.exudyn.spatial import simulate_spatial_exudyn
from bearing_mbs.engines.reference.spatial import simulate_spatial_reference
from bearing_mbs.models.cylindrical_roller.quasistatic import RollerSet, SlicedRollerSet

ENGINES = {"reference": simulate_spatial_reference, "exudyn": simulate_spatial_exudyn}
MODEL = SlicedRollerSet(RollerSet(15, 0.235, 0.025, 0.055), slices=30)
ROLLERS = MODEL.rollers
R, M, L = ROLLERS.roller_diameter / 2, ROLLERS.roller_mass, ROLLERS.roller_length


@pytest.mark.parametrize("engine", ENGINES)
def test_a_tilted_roller_against_a_wall_carries_the_sliced_loads(engine):
    approach, tilt = 4e-6, 2e-4  # m at the centre; rad, its axis turned towards the wall for z > 0
    normal = np.array([0.0, 1.0, 0.0])  # the wall y = 0 faces +y; the roller lies on +y
    orientation = Rotation.from_rotvec([tilt, 0.0, 0.0])  # turns the axis (0, 0, 1) towards −y for z > 0
    roller = SpatialBody("roller", M, (M * (3 * R**2 + L**2) / 12,) * 2 + (M * R**2 / 2,),
                         position=(0.0, R - approach, 0.0), orientation=tuple(np.roll(orientation.as_quat(), 1)))
    coefficient = float(slice_coefficient(ROLLERS.inner_stiffness, L))
    wall = SlicedRaceway("wall", roller=0, ring=-1, centre=(0, 0, 0), axis=tuple(normal), raceway_radius=0.0,
                         side="plane", roller_radius=R, positions=tuple(MODEL.slice_positions),
                         drops=tuple(MODEL.inner_drops), width=MODEL.slice_width, coefficient=coefficient,
                         exponent=10 / 9)
    series = ENGINES[engine](SpatialScene("against a wall", (roller,), raceways=(wall,)), 1e-7, 1e-7, 1e-7)
    expected = sliced_contact(approach, tilt, MODEL.slice_positions, MODEL.inner_drops, MODEL.slice_width,
                              coefficient, 10 / 9).slice_forces
    np.testing.assert_allclose(series.slice_loads[0, 0], expected, rtol=0, atol=1e-6 * expected.max())
    assert expected.min() < 0.5 * expected.max()  # the tilt shows


@pytest.mark.parametrize("engine", ENGINES)
def test_a_servo_spins_a_body_up_at_its_time_constant(engine):
    axial, speed, gain = 0.02, 150.0, 0.4  # kg m², rad/s, N m s: time constant 0.05 s
    axis = Rotation.from_rotvec([0.2, -0.1, 0.0]).apply([0.0, 0.0, 1.0])  # a tilted axis, a principal one
    body = SpatialBody("disc", 3.0, (0.011, 0.011, axial), orientation=tuple(
        np.roll(Rotation.from_rotvec([0.2, -0.1, 0.0]).as_quat(), 1)))
    scene = SpatialScene("spin-up", (body,), servos=(SpinServo(0, tuple(axis), speed, gain),))
    series = ENGINES[engine](scene, 1e-4, 0.2, 0.01)
    expected = speed * (1 - np.exp(-gain * series.time / axial))
    np.testing.assert_allclose(series.angular_velocity[:, 0, 2], expected, rtol=0, atol=1e-6 * speed)
    np.testing.assert_allclose(series.angular_velocity[:, 0, :2], 0.0, atol=1e-9 * speed)
    audit = energy_audit(scene, series)
    assert np.abs(audit.error).max() <= (1e-6 if engine == "reference" else 1e-3) * audit.supplied[-1]


def test_bad_servos_and_planes_are_refused():
    with pytest.raises(ValueError):
        SpinServo(0, (0, 0, 2), 10.0, 1.0)
    with pytest.raises(ValueError):
        SpinServo(0, (0, 0, 1), 10.0, 0.0)
    with pytest.raises(ValueError):
        SlicedRaceway("c", 0, -1, (0, 0, 0), (0, 0, 1), 0.0, "outer", 0.01, (0.0,), (0.0,), 0.01, 1e10, 10 / 9)
    body = SpatialBody("b", 1.0, (1.0, 1.0, 1.0))
    with pytest.raises(ValueError):
        SpatialScene("s", (body,), servos=(SpinServo(1, (0, 0, 1), 10.0, 1.0),))


@pytest.mark.parametrize("engine", ENGINES)
def test_an_axis_spring_holds_an_axis_against_a_moment(engine):
    """A body whose axis a shaft holds along z (stiffness k, damped), turned by a constant moment M about its x axis:
    it settles where k sin θ = M, θ = arcsin(M/k) (within 1e-6 relative)."""
    stiffness, moment, transverse = 2e3, 30.0, 0.01  # N m/rad, N m, kg m²
    body = SpatialBody("shaft", 1.0, (transverse, transverse, 0.02))
    scene = SpatialScene("held", (body,), moments=(BodyMoment(0, (moment, 0.0, 0.0)),), axis_springs=(
        AxisSpring(0, (0.0, 0.0, 1.0), stiffness, 2 * math.sqrt(stiffness * transverse)),))
    series = ENGINES[engine](scene, 1e-4, 0.5, 0.05)
    w = series.orientation[-1, 0]
    axis = Rotation.from_quat([*w[1:], w[0]]).apply([0.0, 0.0, 1.0])
    np.testing.assert_allclose(np.arccos(axis[2]), np.arcsin(moment / stiffness), rtol=1e-6)
