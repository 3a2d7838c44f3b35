"""The energy audit of spatial runs (issue 31): kinetic + gravity's potential + stored + dissipated − supplied stays
what it was at the start.

Reference: the conservation of energy, with the work of the loads and of the dampers and friction integrated by the
engines (the reference engine with RK4's own stages, Exudyn by the trapezoid rule over its steps, as the planar
engine does). Tolerances: the reference engine within 1e-5 of the energy that changes form (measured 1.6e-7 and
4.0e-7), Exudyn's trapezoid within 1e-3 of it (measured 1.4e-5 and 2.7e-4). A wrong sign of any power, a missing
friction or damping term, or stored energy left out breaks the balance by the energy that term moves (tens of per
cent here).
"""

from __future__ import annotations

import numpy as np
import pytest
from scipy.spatial.transform import Rotation

from bearing_mbs.contact.line_contact import slice_coefficient
from bearing_mbs.core.spatial import (
    BodyDrag,
    BodyForce,
    SlicedRaceway,
    SpatialBody,
    SpatialScene,
    TranslationSpring,
    energy_audit,
)
from bearing_mbs.engines.exudyn.spatial import simulate_spatial_exudyn
from bearing_mbs.engines.reference.spatial import simulate_spatial_reference
from bearing_mbs.models.cylindrical_roller.quasistatic import RollerSet, SlicedRollerSet

MODEL = SlicedRollerSet(RollerSet(15, 0.235, 0.025, 0.055), slices=20)
ROLLERS = MODEL.rollers
R, M, L = ROLLERS.roller_diameter / 2, ROLLERS.roller_mass, ROLLERS.roller_length
INERTIA = (M * (3 * R**2 + L**2) / 12,) * 2 + (M * R**2 / 2,)
ENGINES = {"reference": (simulate_spatial_reference, 1e-5), "exudyn": (simulate_spatial_exudyn, 1e-3)}


def raceway(roller: int, ring: int, radius: float, side: str, friction: float, **planar_laws) -> SlicedRaceway:
    return SlicedRaceway(f"{side}", roller=roller, ring=ring, centre=(0, 0, 0), axis=(0, 0, 1), raceway_radius=radius,
                         side=side, roller_radius=R, positions=tuple(MODEL.slice_positions),
                         drops=tuple(MODEL.inner_drops), width=MODEL.slice_width, exponent=10 / 9,
                         coefficient=float(slice_coefficient(ROLLERS.inner_stiffness, L)), damping_time=5e-6,
                         friction_coefficient=friction, regularisation_speed=1e-3, **planar_laws)


def impact() -> SpatialScene:
    """A tilted spinning ring strikes a roller with friction and damping, under gravity: no load supplies work."""
    pitch_radius = ROLLERS.pitch_diameter / 2
    ring = SpatialBody("ring", 2.0, (4e-3, 4e-3, 7e-3),
                       orientation=tuple(np.roll(Rotation.from_rotvec([0.0, 3e-4, 0.0]).as_quat(), 1)),
                       velocity=(0.5, 0.02, 0.0), angular_velocity=(0.3, -0.2, 50.0))
    roller = SpatialBody("roller", M, INERTIA, position=(pitch_radius + 1e-6, 0.0, 0.001),
                         angular_velocity=(0.0, 0.0, -20.0))
    return SpatialScene("impact", (ring, roller), raceways=(raceway(1, 0, pitch_radius - R, "inner", 0.1),),
                        gravity=(0.0, -9.81, 0.0))


def set_down() -> SpatialScene:
    """A spinning roller pushed onto a raceway by a constant force through a damped spring, with the planar laws'
    hysteresis damping (latched per slice), rolling resistance and a lubricant's drag: the force supplies work, all
    of them dissipate it and the spin's energy."""
    roller = SpatialBody("roller", M, INERTIA, position=(10.0 + R + 2e-6, 0, 0), angular_velocity=(0, 0, 30.0))
    laws = {"damping_factor": 0.3, "approach_speed_floor": 1e-3, "rolling_resistance_arm": 2e-4}
    return SpatialScene("set down", (roller,), forces=(BodyForce(0, (-200.0, 0.0, 0.0)),),
                        springs=(TranslationSpring(0, (0, 0, 1), 1e7, 50.0),),
                        raceways=(raceway(0, -1, 10.0, "inner", 0.1, **laws),),
                        drags=(BodyDrag(0, linear=2.0, quadratic=5.0, angular=1e-5, angular_quadratic=1e-6),))


@pytest.mark.parametrize("engine", ENGINES)
@pytest.mark.parametrize("case", [impact, set_down])
def test_the_energy_audit_closes(engine, case):
    run, tolerance = ENGINES[engine]
    scene = case()
    series = run(scene, 2e-7, 2e-3, 1e-4)
    assert series.success, series.message
    audit = energy_audit(scene, series)
    moved = max(np.ptp(audit.kinetic), audit.dissipated[-1], abs(audit.supplied[-1]))
    assert audit.dissipated[-1] > 0.01 * moved  # the dampers and friction did work
    assert np.all(np.diff(audit.dissipated) >= -1e-12 * moved)  # and never gave any back
    assert np.abs(audit.error).max() <= tolerance * moved, (np.abs(audit.error).max() / moved)
