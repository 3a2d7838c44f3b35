"""The reference engine's implicit method in three dimensions (Lie-group generalized-α,
``engines/reference/spatial_alpha.py``) on the seed HSS bearing, dry, at the setting the cost benchmark finds sound
(1e-5 s, ρ∞ = 0.9, Newton tolerance 1e-6: benchmarks/bench_spatial.py).

References:
* RK4 at 2e-7 s on the same scene (fourth order, 50 steps for each of the implicit method's; its own error is far
  below the tolerances here: the engines agree to 1e-4 at that step, tests/test_spatial_bearing.py);
* conservation of energy (the audit of :func:`bearing_mbs.core.spatial.energy_audit`, the work integrated by the
  trapezoid rule over the steps, as on Exudyn: within 1e-3 of the energy that changes form).

Tolerances (measured in brackets): running aligned at 68 kN from the scenario's rolling start, the rollers' spins
within 1e-3 of the largest (2.7e-4 at 1e-5 s in the misaligned case), the largest slice load at every instant within
1 % of its largest (2.5e-3); misaligned by 0.5 mrad with crowned rollers and damped contacts, the loaded rollers'
(above 5 kN) tilts within 2 % of the largest tilt (0.7 %) and skews within 5 % of the largest skew (2.7 %), the
largest slice load within 1 % (0.6 %). The lightly loaded rollers' skews are free and differ by up to 20 % of the
largest: their skew is the response of a barely held body to the transient, which the implicit method's damping of
the high frequencies changes. A wrong composition of the rotation (p ⊗ exp against exp ⊗ p), a Jacobian of the wrong
sign or a lost gyroscopic term changes these by their whole size.
"""

from __future__ import annotations

import numpy as np
import pytest

from bearing_mbs.core.failures import Failure
from bearing_mbs.core.spatial import SpatialBody, SpatialScene, energy_audit
from bearing_mbs.engines.reference.spatial import simulate_spatial_reference
from bearing_mbs.models import load_spec
from bearing_mbs.models.cylindrical_roller.geometry import BearingGeometry
from bearing_mbs.models.cylindrical_roller.quasistatic import CircularCrown
from bearing_mbs.models.cylindrical_roller.spatial import FIRST_ROLLER, build_spatial_bearing
from bearing_mbs.spec import methods

from cases import SCENARIOS

END, OUTPUT = 3e-3, 1e-4  # s
SOUND = {"method": methods.GENERALIZED_ALPHA, "spectral_radius": 0.9, "tolerance": 1e-6}


def dry_bearing(**options):
    spec = load_spec(SCENARIOS / "seed_hss_steady.toml", ["scenario.variant=dry"])
    return build_spatial_bearing(spec, slices=10, **options)


def scale(values: np.ndarray) -> float:
    return float(np.abs(values).max())


def test_the_implicit_method_runs_the_bearing_as_rk4_does_and_closes_its_energy_audit():
    bearing = dry_bearing(damping_time=0.0)
    reference = simulate_spatial_reference(bearing.scene, 2e-7, END, OUTPUT)
    implicit = simulate_spatial_reference(bearing.scene, 1e-5, END, OUTPUT, **SOUND)
    assert reference.success and implicit.success
    assert implicit.steps >= 300 and implicit.newton_iterations > 0 and implicit.jacobians > 0
    spins = reference.angular_velocity[:, FIRST_ROLLER:, 2]
    np.testing.assert_allclose(implicit.angular_velocity[:, FIRST_ROLLER:, 2], spins, rtol=0, atol=1e-3 * scale(spins))
    largest = reference.slice_loads.max(axis=(1, 2))
    np.testing.assert_allclose(implicit.slice_loads.max(axis=(1, 2)), largest, rtol=0, atol=1e-2 * scale(largest))
    audit = energy_audit(bearing.scene, implicit)
    moved = max(scale(audit.dissipated), scale(audit.supplied), scale(audit.kinetic - audit.kinetic[0]))
    assert scale(audit.error) < 1e-3 * moved


@pytest.mark.slow
def test_the_implicit_method_follows_the_loaded_rollers_attitudes_under_misalignment():
    geometry = BearingGeometry.from_spec(load_spec(SCENARIOS / "seed_hss_steady.toml").bearing)
    bearing = dry_bearing(crown=CircularCrown(radius=2.0, straight_length=geometry.roller_length / 2),
                          misalignment=5e-4, damping_time=1e-4)
    reference = simulate_spatial_reference(bearing.scene, 2e-7, END, OUTPUT)
    implicit = simulate_spatial_reference(bearing.scene, 5e-6, END, OUTPUT, **{**SOUND, "tolerance": 1e-8})
    assert reference.success and implicit.success
    loaded = bearing.roller_loads(reference).max(axis=0) > 5e3
    assert 4 <= loaded.sum() < geometry.rollers
    for expected, actual, tolerance in zip(bearing.attitudes(reference), bearing.attitudes(implicit), (5e-2, 2e-2),
                                           strict=True):
        np.testing.assert_allclose(actual[:, loaded], expected[:, loaded], rtol=0,
                                   atol=tolerance * scale(expected[:, loaded]))
    largest = reference.slice_loads.max(axis=(1, 2))
    np.testing.assert_allclose(implicit.slice_loads.max(axis=(1, 2)), largest, rtol=0, atol=1e-2 * scale(largest))


@pytest.mark.parametrize("settings", [{"spectral_radius": 1.5}, {"spectral_radius": -0.1}, {"tolerance": 0.0},
                                      {"tolerance": 2.0}, {"method": methods.DOPRI5}])
def test_bad_implicit_settings_are_refused_before_running(settings):
    scene = SpatialScene("s", (SpatialBody("b", 1.0, (1.0, 1.0, 1.0)),))
    with pytest.raises(ValueError):
        simulate_spatial_reference(scene, 1e-3, 1.0, 0.1, **{**SOUND, **settings})


def test_a_free_body_needs_no_newton_iteration_beyond_the_first():
    """Without force elements f does not depend on x for a body spinning about a principal axis: the first Newton
    increment is exact, and the run's status says success."""
    scene = SpatialScene("spinner", (SpatialBody("b", 1.0, (1.0, 2.0, 3.0), angular_velocity=(0.0, 0.0, 5.0)),))
    series = simulate_spatial_reference(scene, 1e-3, 0.1, 0.01, **SOUND)
    assert series.success and series.failure == Failure.NONE
    np.testing.assert_allclose(series.angular_velocity[:, 0], [[0.0, 0.0, 5.0]] * series.time.size, atol=1e-12)
    assert series.newton_iterations <= 2 * series.steps
