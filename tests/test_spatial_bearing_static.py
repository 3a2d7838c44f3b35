"""A statically loaded, misaligned roller set in three dimensions (issue 31) against document 003's sliced solver.

Reference: ``sliced_state`` (document 003's reverse problem, checked in tests/test_quasistatic_sliced.py): the
rollers' loads, slice loads and tilts at an inner-ring displacement (x, y, θx, θy). Here the fifteen rollers of the
sliced model's test bearing, each a body with six degrees of freedom between the fixed outer raceway and an inner
raceway moved and tilted by that displacement (0.4 mrad of misalignment), held tangentially and axially by stiff
springs (the cage's and the flanges' part), settle under their sliced contacts' damping. Every slice load must match
within 1 % of the largest (measured 0.05 % on both engines: the exact three-dimensional kinematics against the
document's first-order ones), every loaded roller's tilt within 1 % of the largest tilt (measured 0.11 %).
"""

from __future__ import annotations

import numpy as np
import pytest
from scipy.spatial.transform import Rotation

from bearing_mbs.contact.line_contact import slice_coefficient
from bearing_mbs.core.spatial import SlicedRaceway, SpatialBody, SpatialScene, TranslationSpring
from bearing_mbs.engines.exudyn.spatial import simulate_spatial_exudyn
from bearing_mbs.engines.reference.spatial import simulate_spatial_reference
from bearing_mbs.models.cylindrical_roller.quasistatic import (
    CircularCrown,
    Flat,
    RollerSet,
    SlicedRollerSet,
    sliced_state,
)

PITCH, DIAMETER, LENGTH = 0.235, 0.025, 0.055
MODEL = SlicedRollerSet(RollerSet(15, PITCH, DIAMETER, LENGTH),
                        roller_crown=CircularCrown(radius=2.0, straight_length=LENGTH / 2), inner_raceway_crown=Flat(),
                        slices=20)
DISPLACEMENT = np.array([2.5e-5, 1.0e-5, -1.5e-4, 3.7e-4])  # x, y [m], θx, θy [rad]: 0.4 mrad of misalignment
ENGINES = {"reference": simulate_spatial_reference, "exudyn": simulate_spatial_exudyn}


def roller_set(model: SlicedRollerSet, displacement: np.ndarray) -> SpatialScene:
    """The rollers of ``model`` between the fixed outer raceway and the inner raceway moved by ``displacement``."""
    rollers = model.rollers
    r, jb, m = rollers.roller_diameter / 2, rollers.contact_clearance, rollers.roller_mass
    pitch_radius, length = rollers.pitch_diameter / 2, rollers.roller_length
    x, y, theta_x, theta_y = displacement
    axis = Rotation.from_rotvec([theta_x, theta_y, 0.0]).apply([0.0, 0.0, 1.0])
    bodies, raceways, springs = [], [], []
    for j, psi in enumerate(rollers.roller_angles):
        bodies.append(SpatialBody(f"roller{j}", m, (m * (3 * r**2 + length**2) / 12,) * 2 + (m * r**2 / 2,),
                                  position=(pitch_radius * np.cos(psi), pitch_radius * np.sin(psi), 0.0)))
        common = {"roller": j, "ring": -1, "roller_radius": r, "positions": tuple(model.slice_positions),
                  "width": model.slice_width, "damping_time": 2e-6}
        raceways += [
            SlicedRaceway(f"roller{j}-inner", centre=(x, y, 0.0), axis=tuple(axis), raceway_radius=pitch_radius - r - jb,
                          side="inner", drops=tuple(model.inner_drops), exponent=rollers.inner_exponent,
                          coefficient=float(slice_coefficient(rollers.inner_stiffness, length)), **common),
            SlicedRaceway(f"roller{j}-outer", centre=(0, 0, 0), axis=(0, 0, 1), raceway_radius=pitch_radius + r + jb,
                          side="outer", drops=tuple(model.outer_drops), exponent=rollers.outer_exponent,
                          coefficient=float(slice_coefficient(rollers.outer_stiffness, length)), **common)]
        springs += [TranslationSpring(j, (-np.sin(psi), np.cos(psi), 0.0), 1e8, 1e3),
                    TranslationSpring(j, (0.0, 0.0, 1.0), 1e8, 1e3)]
    return SpatialScene("misaligned roller set", tuple(bodies), springs=tuple(springs), raceways=tuple(raceways))


def radial_tilts(series, angles) -> np.ndarray:
    """Each roller's tilt β [rad] in its radial plane: its axis turned outwards."""
    w = series.orientation[-1]
    axes = Rotation.from_quat(np.column_stack([w[:, 1:], w[:, 0]])).apply([0.0, 0.0, 1.0])
    return np.arctan2(axes[:, 0] * np.cos(angles) + axes[:, 1] * np.sin(angles), axes[:, 2])


@pytest.mark.parametrize("engine", ENGINES)
def test_a_misaligned_roller_set_carries_document_003s_slice_loads(engine):
    expected = sliced_state(MODEL, DISPLACEMENT)
    assert 4 <= np.count_nonzero(expected.inner_loads) < 15  # a load zone, and rollers outside it
    series = ENGINES[engine](roller_set(MODEL, DISPLACEMENT), 1e-6, 0.006, 1e-3)
    assert series.success, series.message
    inner, outer = series.slice_loads[-1, 0::2], series.slice_loads[-1, 1::2]  # (rollers, slices)
    largest = expected.inner_slice_loads.max()
    np.testing.assert_allclose(inner, expected.inner_slice_loads, rtol=0, atol=0.01 * largest)
    np.testing.assert_allclose(outer, expected.outer_slice_loads, rtol=0, atol=0.01 * largest)
    np.testing.assert_allclose(inner.sum(axis=1), expected.inner_loads, rtol=0, atol=0.01 * expected.inner_loads.max())
    loaded = expected.inner_loads > 0
    tilts = radial_tilts(series, MODEL.rollers.roller_angles)
    np.testing.assert_allclose(tilts[loaded], expected.roller_tilts[loaded], rtol=0,
                               atol=0.01 * np.abs(expected.roller_tilts[loaded]).max())
