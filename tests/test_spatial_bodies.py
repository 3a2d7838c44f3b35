"""Rigid bodies in three dimensions (issue 31, item 1) on both engines, against closed forms.

References (independent of the code under test):
* the torque-free asymmetric top: Euler's equations solved with Jacobi's elliptic functions (L. D. Landau,
  E. M. Lifshitz, Mechanics, 3rd ed., §37): for I₁ < I₂ < I₃, ω(0) = (ω₁, 0, ω₃) with ω₁, ω₃ > 0 and
  M² > 2 E I₂, ω = (A₁ cn τ, A₂ sn τ, A₃ dn τ); the angular momentum in the world frame, R(p) I ω, is constant;
* a symmetric body (I₁ = I₂ = I_t, axis 3) spinning at Ω under a constant body-fixed moment M about axis 1, from
  rest in the transverse directions: Euler's equations give ω₃ = Ω and, with λ = (I₃ − I_t) Ω / I_t,
  ω₁ = M/(I_t λ) sin λt, ω₂ = M/(I_t λ)(1 − cos λt) (substitute to check);
* free fall: r = r₀ + ṙ₀ t + g t²/2.
Orders: the methods' declared orders (RK4's fourth, generalized-α's second; :mod:`bearing_mbs.spec.methods`).
"""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.spatial.transform import Rotation
from scipy.special import ellipj

from bearing_mbs.core.failures import Failure
from bearing_mbs.core.interrupt import StopRequest
from bearing_mbs.core.progress import ProgressMeter
from bearing_mbs.core.spatial import BodyMoment, SpatialBody, SpatialScene
from bearing_mbs.engines.exudyn.spatial import simulate_spatial_exudyn
from bearing_mbs.engines.reference.spatial import simulate_spatial_reference
from bearing_mbs.engines.reference.tableaus import RK4
from bearing_mbs.spec import methods

INERTIA = np.array([0.01, 0.02, 0.03])  # kg m²
OMEGA = np.array([2.0, 0.0, 5.0])  # rad/s, body frame; M² > 2 E I₂ for these
ORIENTATION = Rotation.from_euler("xyz", [0.3, -0.5, 1.1])  # any start: the closed forms are in the body frame
GRAVITY = np.array([0.0, 0.0, -9.81])
END = 2.0  # s: about 1.5 turns of the body's wobble


def quaternion(rotation: Rotation) -> tuple:
    x, y, z, w = rotation.as_quat()
    return (w, x, y, z)


def top_closed_form(t: np.ndarray, inertia=INERTIA, omega=OMEGA) -> np.ndarray:
    """ω(t) (T, 3) of the torque-free asymmetric top (Landau & Lifshitz §37)."""
    i1, i2, i3 = inertia
    energy2 = np.sum(inertia * omega**2)  # 2E
    momentum2 = np.sum((inertia * omega) ** 2)  # M²
    tau = t * np.sqrt((i3 - i2) * (momentum2 - energy2 * i1) / (i1 * i2 * i3))
    modulus = (i2 - i1) * (energy2 * i3 - momentum2) / ((i3 - i2) * (momentum2 - energy2 * i1))
    sn, cn, dn, _ = ellipj(tau, modulus)
    return np.column_stack([np.sqrt((energy2 * i3 - momentum2) / (i1 * (i3 - i1))) * cn,
                            np.sqrt((energy2 * i3 - momentum2) / (i2 * (i3 - i2))) * sn,
                            np.sqrt((momentum2 - energy2 * i1) / (i3 * (i3 - i1))) * dn])


def top_scene() -> SpatialScene:
    body = SpatialBody("top", 1.0, tuple(INERTIA), position=(1.0, 2.0, 3.0), orientation=quaternion(ORIENTATION),
                       velocity=(0.1, 0.0, 0.0), angular_velocity=tuple(OMEGA))
    return SpatialScene("asymmetric top", (body,), gravity=tuple(GRAVITY))


def world_momentum(series, inertia) -> np.ndarray:
    """R(p) I ω of body 0 at each output instant (T, 3) [kg m²/s]."""
    w = series.orientation[:, 0]
    matrices = Rotation.from_quat(np.column_stack([w[:, 1:], w[:, 0]])).as_matrix()
    return np.einsum("tij,tj->ti", matrices, inertia * series.angular_velocity[:, 0])


ENGINES = {
    "reference rk4": (lambda scene, h, end, dt: simulate_spatial_reference(scene, h, end, dt), RK4.order),
    "exudyn rk4": (lambda scene, h, end, dt: simulate_spatial_exudyn(scene, h, end, dt), methods.RK4.order),
    "exudyn generalized_alpha": (lambda scene, h, end, dt: simulate_spatial_exudyn(
        scene, h, end, dt, method=methods.GENERALIZED_ALPHA), methods.GENERALIZED_ALPHA.order),
    "reference generalized_alpha": (lambda scene, h, end, dt: simulate_spatial_reference(
        scene, h, end, dt, method=methods.GENERALIZED_ALPHA), methods.GENERALIZED_ALPHA.order),
}
#: The coarser of each engine's two steps [s] (the order's asymptotic range).
COARSE = {"reference rk4": 1e-2, "exudyn rk4": 1e-2, "exudyn generalized_alpha": 1e-3,
          "reference generalized_alpha": 1e-3}


@pytest.mark.parametrize("engine", ENGINES)
def test_torque_free_top_matches_its_closed_form_to_the_observed_order(engine):
    run, order = ENGINES[engine]
    errors, drifts = [], []
    for h in (COARSE[engine], COARSE[engine] / 2):
        series = run(top_scene(), h, END, 0.1)
        np.testing.assert_allclose(series.time[-1], END, rtol=1e-12)
        errors.append(np.abs(series.angular_velocity[:, 0] - top_closed_form(series.time)).max())
        momentum = world_momentum(series, INERTIA)
        drifts.append(np.abs(momentum - momentum[0]).max() / np.linalg.norm(momentum[0]))
        # the centre of mass falls freely: closed form to rounding
        expected = np.array([1.0, 2.0, 3.0]) + np.array([0.1, 0.0, 0.0]) * END + 0.5 * GRAVITY * END**2
        np.testing.assert_allclose(series.position[-1, 0], expected, rtol=0, atol=1e-9)
    observed = np.log2(errors[0] / errors[1])
    assert abs(observed - order) < 0.3, (errors, observed)
    # the orientation: the world-frame angular momentum is conserved to the integrator's accuracy, and its error
    # falls at the same order (a wrong quaternion rate or frame turns it by O(1))
    assert drifts[1] < 1e-5 and abs(np.log2(drifts[0] / drifts[1]) - order) < 0.5, drifts
    assert errors[1] < (1e-7 if order == 4 else 1e-4)


@pytest.mark.parametrize("engine", ["reference rk4", "exudyn rk4", "reference generalized_alpha"])
def test_constant_body_moment_on_a_spinning_roller_matches_its_closed_form(engine):
    run, order = ENGINES[engine]
    radius, length, mass = 0.012, 0.024, 0.085  # a roller of the seed bearing's size [m, m, kg]
    transverse, axial = mass * (3 * radius**2 + length**2) / 12, mass * radius**2 / 2
    spin, moment = 500.0, 2e-3  # rad/s about the roller's axis (3), N m about axis 1
    scene = SpatialScene("roller", (SpatialBody("roller", mass, (transverse, transverse, axial),
                                                angular_velocity=(0.0, 0.0, spin)),),
                         moments=(BodyMoment(0, (moment, 0.0, 0.0)),))
    rate = (axial - transverse) * spin / transverse  # λ
    errors = []
    for h in (1e-4, 5e-5):
        series = run(scene, h, 0.05, 1e-3)
        t = series.time
        expected = np.column_stack([moment / (transverse * rate) * np.sin(rate * t),
                                    moment / (transverse * rate) * (1 - np.cos(rate * t)), np.full(t.size, spin)])
        errors.append(np.abs(series.angular_velocity[:, 0] - expected).max())
    amplitude = abs(moment / (transverse * rate))
    assert errors[1] < (1e-6 if order == 4 else 1e-2) * amplitude
    assert abs(np.log2(errors[0] / errors[1]) - order) < 0.3, errors


def test_the_engines_agree_on_the_orientation():
    reference = simulate_spatial_reference(top_scene(), 5e-3, END, 0.1)
    exudyn = simulate_spatial_exudyn(top_scene(), 5e-3, END, 0.1)
    # both fourth order at 5e-3 s: the closed form's error is 6e-8 rad/s; the orientations agree to that scale
    np.testing.assert_allclose(exudyn.orientation, reference.orientation, rtol=0, atol=1e-7)
    np.testing.assert_allclose(exudyn.angular_velocity, reference.angular_velocity, rtol=0, atol=1e-7)
    np.testing.assert_allclose(np.linalg.norm(reference.orientation, axis=2), 1.0, rtol=0, atol=1e-14)


def test_the_engines_generalized_alpha_is_the_same_scheme():
    """The reference engine's Lie-group generalized-α (body-frame increments, quaternions) against Exudyn's (its
    rotation-vector Lie-group nodes) on the top, both at ρ∞ = 0.9: the same scheme, so they agree far below their
    common error against the closed form (3.8e-5 rad/s at 1e-3 s), to Newton's tolerance."""
    reference = simulate_spatial_reference(top_scene(), 1e-3, END, 0.1, method=methods.GENERALIZED_ALPHA,
                                           tolerance=1e-12)
    exudyn = simulate_spatial_exudyn(top_scene(), 1e-3, END, 0.1, method=methods.GENERALIZED_ALPHA)
    error = np.abs(reference.angular_velocity[:, 0] - top_closed_form(reference.time)).max()
    assert 1e-5 < error < 1e-4
    np.testing.assert_allclose(exudyn.angular_velocity, reference.angular_velocity, rtol=0, atol=1e-3 * error)
    np.testing.assert_allclose(np.linalg.norm(reference.orientation, axis=2), 1.0, rtol=0, atol=1e-14)


positive = st.floats(0.5, 2.0)


@settings(max_examples=15, deadline=None, derandomize=True)
@given(a=positive, b=positive, c=positive, w=st.tuples(st.floats(-5, 5), st.floats(-5, 5), st.floats(-5, 5)))
def test_free_bodies_keep_energy_and_momentum(a, b, c, w):
    """Any realisable inertia and spin: the kinetic energy and the world-frame angular momentum of a torque-free
    body are conserved (RK4 at 2e-3 s over 1 s: within 1e-6 of their scales)."""
    inertia = np.array([a, b, c]) * 1e-2
    if 2 * inertia.max() > inertia.sum():
        inertia[np.argmax(inertia)] = 0.99 * (inertia.sum() - inertia.max())
    scene = SpatialScene("free", (SpatialBody("b", 1.0, tuple(inertia), orientation=quaternion(ORIENTATION),
                                              angular_velocity=w),))
    series = simulate_spatial_reference(scene, 2e-3, 1.0, 0.25)
    energy = 0.5 * np.sum(inertia * series.angular_velocity[:, 0] ** 2, axis=1)
    momentum = world_momentum(series, inertia)
    scale = 1e-6 * (1 + np.linalg.norm(momentum[0]) * max(1.0, float(np.max(np.abs(w)))))
    assert np.abs(energy - energy[0]).max() <= scale
    assert np.abs(momentum - momentum[0]).max() <= scale


@pytest.mark.parametrize("body", [
    {"mass": 0.0, "inertia": (1, 1, 1)},
    {"mass": 1.0, "inertia": (1, 1, 3)},  # no mass distribution has I₃ > I₁ + I₂
    {"mass": 1.0, "inertia": (1, 1, 1), "orientation": (1, 0.1, 0, 0)},  # not a unit quaternion
    {"mass": 1.0, "inertia": (1, 1), "orientation": (1, 0, 0, 0)},
    {"mass": 1.0, "inertia": (1, 1, 1), "angular_velocity": (0, float("nan"), 0)},
])
def test_bad_bodies_are_refused_on_construction(body):
    with pytest.raises(ValueError):
        SpatialBody("b", **body)


def test_bad_scenes_and_run_settings_are_refused_before_running():
    body = SpatialBody("b", 1.0, (1.0, 1.0, 1.0))
    with pytest.raises(ValueError):
        SpatialScene("s", (body,), moments=(BodyMoment(1, (0, 0, 1)),))  # no body 1
    with pytest.raises(ValueError):
        SpatialScene("s", ())
    scene = SpatialScene("s", (body,))
    for step, end in ((0.0, 1.0), (1e-3, -1.0), (float("inf"), 1.0)):
        with pytest.raises(ValueError):
            simulate_spatial_reference(scene, step, end, 0.1)
        with pytest.raises(ValueError):
            simulate_spatial_exudyn(scene, step, end, 0.1)
    with pytest.raises(ValueError):
        simulate_spatial_exudyn(scene, 1e-3, 1.0, 0.1, method=methods.DOPRI5)


@pytest.mark.parametrize("engine", ["reference rk4", "exudyn rk4"])
def test_a_diverging_run_stops_with_the_body_and_keeps_what_it_computed(engine):
    """A spin far beyond RK4's stability at this step (ω h ≈ 1e5): the run stops, names the body, keeps the
    output instants before the blow-up, and says so."""
    run, _ = ENGINES[engine]
    scene = SpatialScene("spinning", (
        SpatialBody("calm", 1.0, (1.0, 1.0, 1.0)),
        SpatialBody("wild", 1.0, (1.0, 2.0, 2.5), angular_velocity=(3e3, 1e4, 3e3)),))
    series = run(scene, 1e-1, 100.0, 1.0)
    assert not series.success and series.failure == Failure.NONFINITE
    assert "'wild'" in series.message
    assert 1 <= series.time.size < 101
    assert np.isfinite(series.angular_velocity).all()


class _StopHalfway(ProgressMeter):
    """A meter that asks the run to stop once it has passed half its span (as Ctrl-C would), counting updates."""

    def __init__(self, stop: StopRequest):
        super().__init__()
        self.stop, self.updates, self.total = stop, 0, 0.0

    def start(self, total: float, description: str = "") -> None:
        self.total = total

    def update(self, value: float) -> None:
        self.updates += 1
        if value >= 0.5 * self.total:
            self.stop.set()


@pytest.mark.parametrize("engine", [simulate_spatial_reference, simulate_spatial_exudyn])
def test_a_stop_request_ends_the_run_and_keeps_its_output(engine):
    stop = StopRequest()
    meter = _StopHalfway(stop)
    series = engine(top_scene(), 1e-3, END, 0.1, progress=meter, stop=stop)
    assert not series.success and series.failure == Failure.INTERRUPTED
    assert meter.updates >= 10  # the run reported its progress at its output instants
    np.testing.assert_allclose(series.time[-1], 0.5 * END, rtol=1e-9)  # stopped where asked, the instants kept
    assert series.time.size == 11 and np.isfinite(series.angular_velocity).all()
    assert series.wall_time_s > 0


@pytest.mark.parametrize("rotvec", [(0.3, -0.5, 1.1), (1e-6, 2e-6, -1e-6), (3.0, 0.1, 0.2), (0.0, 0.0, 0.0)])
def test_the_rotation_matrices_are_scipys(rotvec):
    """The compiled rotation matrices of a quaternion and of a rotation vector (core/rotations.py) against scipy's
    (1e-15), across small, ordinary and near-π angles."""
    from bearing_mbs.core.rotations import rotation_from_quaternion, rotation_from_vector

    rotation = Rotation.from_rotvec(rotvec)
    out = np.empty((3, 3))
    rotation_from_quaternion(*quaternion(rotation), out)
    np.testing.assert_allclose(out, rotation.as_matrix(), rtol=0, atol=1e-15)
    rotation_from_vector(*rotvec, out)
    np.testing.assert_allclose(out, rotation.as_matrix(), rtol=0, atol=1e-15)
