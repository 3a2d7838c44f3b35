"""Flexible rings of the slewing bearing (docs/slewing.md): the condensed sector matrices at every ball.

References (none from the code under test): rigid rings as the stiff limit; the series spring of one ball with
diagonal ring matrices, solved by hand (a scalar equation); central differences of the load for the analytic
stiffness; each sector's equilibrium; a thin ring's hoop stiffness 2πEA/(R N) per ball pitch for the units of the
matrices; and the requirement of the slewing-bearing issue that flexible rings are softer than rigid ones.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.optimize import brentq

from bearing_mbs.models.slewing_bearing.flexible import FlexibleRings, flexible_state, relax
from bearing_mbs.models.slewing_bearing.geometry import RingSection, ball_count
from bearing_mbs.models.slewing_bearing.load_distribution import SlewingBearing, evaluate, solve
from bearing_mbs.models.slewing_bearing.ring_stiffness import ring_stiffness

ALPHA = math.radians(45.0)
AXIAL = {"radial": 0.0, "axial": 0.42e-3, "tilt": 0.0}


def bearing(diameter=1.5, balls=None):
    return SlewingBearing(diameter, 0.035, 0.943, ALPHA, balls)


@pytest.mark.parametrize("diameter", [0.5, 1.0, 1.5, 2.0, 2.5])
@pytest.mark.parametrize("mount", ["free", "fixed"])
def test_flexible_rings_are_softer_than_rigid_rings(diameter, mount):
    rings = FlexibleRings.of(diameter, mount)
    for imposed in (AXIAL, {"radial": 0.0, "axial": -0.42e-3, "tilt": 0.0},
                    {"radial": 0.0, "axial": 0.0, "tilt": 2e-4}):
        rigid = solve(bearing(diameter), imposed=imposed).load
        flexible = solve(bearing(diameter), imposed=imposed, rings=rings).load
        k = 1 if imposed["axial"] else 2
        assert 0 < flexible[k] / rigid[k] < 1


def test_rigid_rings_are_the_stiff_limit():
    stiff = FlexibleRings(1e16 * np.eye(4), 1e16 * np.eye(4))
    rigid = solve(bearing(), (1e5, 3e6, 2e6))
    flexible = solve(bearing(), (1e5, 3e6, 2e6), rings=stiff)
    np.testing.assert_allclose(flexible.displacement, rigid.displacement, rtol=1e-6)


def test_one_ball_with_diagonal_ring_matrices_by_hand():
    """One ball, rings k·I, an axial displacement δ: the loaded diagonal's centres approach each other by Q/k at each
    ring along the diagonal, so |s| = |s_rigid| − 2Q/k with Q = K(|s| − A₀)^{3/2}: a scalar equation."""
    single, k, delta = bearing(balls=1), 5e8, 0.2e-3
    rings = FlexibleRings(k * np.eye(4), k * np.eye(4))
    state = solve(single, imposed={"radial": 0.0, "axial": delta, "tilt": 0.0}, rings=rings)
    a0 = single.centre_distance
    rigid_length = math.hypot(a0 * math.cos(ALPHA), a0 * math.sin(ALPHA) + delta)
    q = brentq(lambda q: q - single.stiffness * max(rigid_length - 2 * q / k - a0, 0) ** 1.5, 0, 1e7, xtol=1e-9)
    assert state.ball_loads[0, 0] == pytest.approx(q, rel=1e-9)
    assert state.ball_loads[0, 1] == 0


@pytest.mark.parametrize("mount", ["free", "fixed"])
def test_analytic_stiffness_against_central_differences(mount):
    rings, x = FlexibleRings.of(1.5, mount), np.array([2e-5, 3e-4, 4e-4])
    _, stiffness, _, _, local = flexible_state(bearing(), rings, x)
    step, numeric = 1e-9, np.zeros((3, 3))
    for j in range(3):
        shift = step * np.eye(3)[j]
        numeric[:, j] = (flexible_state(bearing(), rings, x + shift, local)[0]
                         - flexible_state(bearing(), rings, x - shift, local)[0]) / (2 * step)
    assert np.abs(numeric - stiffness).max() <= 1e-6 * np.abs(stiffness).max()


def test_every_sector_and_the_ring_are_in_equilibrium():
    """Each sector: K z_j = −Σ_d P_dᵀ Q ŝ (the ring's elastic force balances the balls'), to 1e-9 of the largest
    ball load; the ring: the load equals the applied one to 1e-9."""
    rings, load = FlexibleRings.of(1.5, "fixed"), np.array([2e5, 3e6, 4e6])
    state = solve(bearing(), load, rings=rings)
    np.testing.assert_allclose(state.load, load, rtol=1e-9)
    z = state.ring_displacements
    np.testing.assert_allclose(relax(bearing(), rings, state.displacement, z), z, atol=1e-12 * np.abs(z).max())


@pytest.mark.parametrize("diameter", [0.5, 1.0, 1.5, 2.0, 2.5])
def test_hoop_stiffness_gives_the_matrices_in_newton_per_metre(diameter):
    """The free inner ring's uniform radial expansion, u = (1, 0, 1, 0), against a thin ring's hoop stiffness per
    ball pitch 2πEA/(R N), with A the full rectangular section T × H of eqs. 7–8 (an upper bound: the groove is
    left in): the ratio is 0.80–0.90 at every diameter, where reading the matrices in N/mm would make it ~1000."""
    u = np.array([1.0, 0.0, 1.0, 0.0])
    section = RingSection.from_ratios(0.035)
    hoop = 2 * math.pi * 200e9 * section.width * section.height / (diameter / 2 * ball_count(diameter, 0.035))
    assert 0.7 < u @ ring_stiffness(diameter, "inner", "free") @ u / hoop < 1.0


def test_rigid_evaluate_is_unchanged_by_the_rings_argument():
    x = np.array([1e-5, 2e-4, 1e-4])
    np.testing.assert_array_equal(evaluate(bearing(), x).load, evaluate(bearing(), x, None).load)


def test_the_pitch_run_refuses_flexible_rings():
    from bearing_mbs.models import load_spec
    from bearing_mbs.spec import SpecError

    from cases import SCENARIOS

    with pytest.raises(SpecError) as error:
        load_spec(SCENARIOS / "seed_slewing_pitch.toml", ["slewing.rings='flexible'"])
    assert error.value.field == "slewing.rings"
