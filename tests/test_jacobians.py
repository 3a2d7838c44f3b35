"""Force elements' analytic Jacobians (``ForceElement.add_jacobian``) against finite differences of their forces.

Reference: central differences of each kind's compiled ``add_forces`` in every coordinate and velocity,
Richardson-extrapolated (steps 1e-6 and 5e-7 of the coordinate's scale); tolerance 1e-6 relative to the largest
entry of the Jacobian, as the implicit-integrator issue asks. Random states, every item of a kind on bodies among
others, so that a derivative put in the wrong row or column fails. The laws' own slopes (smooth scalar functions)
are held entry by entry to 1e-6 relative, where the assembled matrices' largest entries (the contact stiffness)
would hide a small term.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from bearing_mbs.contact import kernel
from bearing_mbs.contact.kernel import N_PAIR_OUTPUTS
from bearing_mbs.contact.kinematics import PAIR_KINDS
from bearing_mbs.contact.pair_jacobian import pair_motion_jacobian
from bearing_mbs.core.scene import Profile
from bearing_mbs.elements import Drag, Load, VelocityServo, contact_pairs, drags, loads, servos, unbalances
from bearing_mbs.elements.unbalances import Unbalance

BODIES = 4
N = 3 * BODIES


def random_items(kind, rng):
    """Items of one kind on random bodies (two on the same body, to check that they add up)."""
    bodies = [int(b) for b in rng.integers(BODIES, size=3)] + [1]
    if kind is drags:
        return [Drag(f"d{k}", b, *rng.uniform(0.0, 2.0, size=4)) for k, b in enumerate(bodies)]
    if kind is servos:
        return [VelocityServo(f"s{k}", b, rng.uniform(1, 10), Profile((0.0, 1.0), (0.0, rng.uniform(10, 100))))
                for k, b in enumerate(bodies)]
    if kind is loads:
        return [Load(f"l{k}", b, tuple(rng.normal(size=3)), Profile((0.0, 1.0), (1.0, 2.0)))
                for k, b in enumerate(bodies)]
    return [Unbalance(f"u{k}", b, rng.uniform(1e-4, 1e-2), rng.uniform(0, 6.3)) for k, b in enumerate(bodies)]


def forces(element, parameters, t, q, v, latched):
    total = np.zeros(N)
    if element.pair_state:
        element.add_forces(parameters, t, q, v, latched, total, np.zeros((latched.size, N_PAIR_OUTPUTS)),
                           np.zeros(2), True)
    else:
        element.add_forces(parameters, t, q, v, total, np.zeros(2))
    return total


def finite_differences(element, parameters, t, q, v, latched, relative=1e-6):
    """(∂F/∂q, ∂F/∂v) by central differences, Richardson-extrapolated from the steps h and h/2 (error O(h⁴)),
    h = ``relative`` times the coordinate's scale."""
    def central(state, j, step, position):
        ahead, behind = state.copy(), state.copy()
        ahead[j] += step
        behind[j] -= step
        if position:
            return (forces(element, parameters, t, ahead, v, latched)
                    - forces(element, parameters, t, behind, v, latched)) / (2 * step)
        return (forces(element, parameters, t, q, ahead, latched)
                - forces(element, parameters, t, q, behind, latched)) / (2 * step)

    columns = []
    for state, position in ((q, True), (v, False)):
        jacobian = np.empty((N, N))
        for j in range(N):
            step = relative * max(abs(state[j]), 1.0)
            jacobian[:, j] = (4 * central(state, j, step / 2, position) - central(state, j, step, position)) / 3
        columns.append(jacobian)
    return columns


@pytest.mark.parametrize("kind", [loads, servos, drags, unbalances], ids=lambda kind: kind.ELEMENT.name)
def test_the_jacobian_matches_finite_differences(kind):
    rng = np.random.default_rng(11)
    element = kind.ELEMENT
    for _ in range(20):
        parameters = element.pack(random_items(kind, rng))
        q, v = rng.normal(scale=0.5, size=N), rng.normal(scale=3.0, size=N)
        t, latched = rng.uniform(0, 1), np.zeros(0)
        position, velocity = np.zeros((N, N)), np.zeros((N, N))
        element.add_jacobian(parameters, t, q, v, position, velocity)
        expected_position, expected_velocity = finite_differences(element, parameters, t, q, v, latched)
        for analytic, expected in ((position, expected_position), (velocity, expected_velocity)):
            scale = max(np.abs(expected).max(), 1e-300)
            np.testing.assert_allclose(analytic, expected, rtol=0, atol=1e-6 * scale)


def test_a_drag_at_rest_has_its_linear_coefficient():
    """At v = 0 the quadratic drag's derivative vanishes; the linear one remains (a kink of |v| the finite
    differences straddle)."""
    parameters = drags.pack([Drag("d", 0, 0.3, 0.2, 5.0, 7.0)])
    position, velocity = np.zeros((N, N)), np.zeros((N, N))
    drags.add_jacobian(parameters, 0.0, np.zeros(N), np.zeros(N), position, velocity)
    assert np.diag(velocity)[:3].tolist() == [-0.3, -0.3, -0.2]
    assert not position.any()


def pair_values(kind, a, b, anchor, direction, ra, rb, q, v):
    """(gap, normal angle, c_x, c_y, gap rate, slip, rolling speed, spin) from the kernel's own kinematics."""
    cos_a, sin_a = (np.cos(q[3 * a + 2]), np.sin(q[3 * a + 2])) if a >= 0 else (1.0, 0.0)
    gap, nx, ny, px, py = kernel.pair_position(kind, a, b, *anchor, *direction, ra, rb, q, cos_a, sin_a)
    gap_rate, slip, cx, cy, spin, rolling = kernel.pair_motion(kind, a, b, ra, rb, gap, nx, ny, px, py, q, v)
    return np.array([gap, np.arctan2(ny, nx), cx, cy, gap_rate, slip, rolling, spin])


@pytest.mark.parametrize("kind", range(len(PAIR_KINDS)), ids=PAIR_KINDS)
@pytest.mark.parametrize("ground", [False, True], ids=["on a body", "on the ground"])
def test_the_pair_kinematics_derivatives_match_finite_differences(kind, ground):
    """bearing_mbs.contact.pair_jacobian against central differences of the kernel's gap, normal angle, contact
    point, gap rate, slip, rolling speed and spin, over both bodies' coordinates and velocities."""
    rng = np.random.default_rng(12 + kind)
    for _ in range(20):
        a, b = (-1 if ground else 2), 1
        q, v = rng.normal(scale=0.05, size=N), rng.normal(scale=2.0, size=N)
        anchor, direction = rng.normal(scale=0.02, size=2), rng.normal(size=2)
        direction /= np.linalg.norm(direction)
        ra = 0.0 if PAIR_KINDS[kind] == "circle_point" else rng.uniform(0.3, 0.5) if PAIR_KINDS[kind] == \
            "circle_in_circle" else rng.uniform(0.01, 0.1)
        rb = rng.uniform(0.01, 0.05)
        gap_q, kappa, c_x, c_y, gap_rate, slip, rolling, spin = pair_motion_jacobian(
            PAIR_KINDS.index(PAIR_KINDS[kind]), a, b, *anchor, *direction, rb, q, v)
        analytic = np.column_stack([np.concatenate([gap_q, np.zeros(6)]), np.concatenate([kappa, np.zeros(6)]),
                                    np.concatenate([c_x, np.zeros(6)]), np.concatenate([c_y, np.zeros(6)]),
                                    gap_rate, slip, rolling, spin])
        local = [3 * a, 3 * a + 1, 3 * a + 2, 3 * b, 3 * b + 1, 3 * b + 2]
        expected = np.zeros((12, 8))
        for column in range(12):
            if ground and column % 6 < 3:
                continue  # the ground has no coordinates
            state = q if column < 6 else v
            index = local[column % 6]
            step = 1e-6 * max(abs(state[index]), 1.0)
            ahead, behind = state.copy(), state.copy()
            ahead[index] += step
            behind[index] -= step
            pairs = ((ahead, v), (behind, v)) if column < 6 else ((q, ahead), (q, behind))
            expected[column] = (pair_values(kind, a, b, anchor, direction, ra, rb, *pairs[0])
                                - pair_values(kind, a, b, anchor, direction, ra, rb, *pairs[1])) / (2 * step)
        if ground:
            analytic[[0, 1, 2, 6, 7, 8]] = 0.0
        for quantity in range(8):  # each against its own scale: they have different units
            scale = np.abs(expected[:, quantity]).max()
            np.testing.assert_allclose(analytic[:, quantity], expected[:, quantity], rtol=0, atol=1e-6 * scale,
                                       err_msg=f"{PAIR_KINDS[kind]}, quantity {quantity}")


def pairs_scene(rng, laws):
    """Random pairs of every kind with friction laws in ``laws`` (ehl rows random: both film-shear models,
    thermal reduction and rolling resistance on and off), most of them in contact, without oil films."""
    from test_kernel import random_scene

    from bearing_mbs.core.scene import Scene

    scene = random_scene(rng, n_bodies=BODIES, n_pairs=144)
    pairs = tuple(p for p in scene.pairs if p.law.friction_law in laws and not p.law.film)
    return Scene("pairs", scene.bodies, pairs)


@pytest.mark.parametrize("laws", [("none", "erf", "tanh", "linear", "dead_zone"), ("ehl",)],
                         ids=["coulomb family", "ehl"])
def test_the_contact_pairs_jacobian_matches_finite_differences(laws):
    """Every pair kind and normal law of the hysteresis family (random damping factors), the friction laws and
    the dry rolling arm; for ehl the traction's dependence on slip, rolling speed and load (film, Λ, Eyring or
    curve) and the hydrodynamic rolling resistance; with the pairs' latched approach speeds held."""
    from test_kernel import random_state

    rng = np.random.default_rng(13)
    scene = pairs_scene(rng, laws)
    parameters = contact_pairs.pack(scene.pairs)
    element = contact_pairs.ELEMENT
    touching = 0
    for _ in range(10):
        q, v, latched = random_state(rng, scene)
        pair_out = np.zeros((len(scene.pairs), N_PAIR_OUTPUTS))
        element.add_forces(parameters, 0.0, q, v, latched, np.zeros(N), pair_out, np.zeros(2), True)
        touching += int(np.sum(pair_out[:, 0] < 0))
        position, velocity = np.zeros((N, N)), np.zeros((N, N))
        contact_pairs.add_jacobian(parameters, 0.0, q, v, latched, pair_out, position, velocity)
        expected_position, expected_velocity = finite_differences(element, parameters, 0.0, q, v, latched)
        for analytic, expected in ((position, expected_position), (velocity, expected_velocity)):
            np.testing.assert_allclose(analytic, expected, rtol=0, atol=1e-6 * np.abs(expected).max())
    assert touching > 30


def scalar_slope(function, x, step):
    """d function/dx by Richardson-extrapolated central differences."""
    def central(h):
        return (function(x + h) - function(x - h)) / (2 * h)

    return (4 * central(step / 2) - central(step)) / 3


@pytest.mark.parametrize("k", range(8))
def test_the_lubricated_laws_slopes_match_finite_differences(k):
    """∂μ/∂Δu, ∂μ/∂u, ∂μ/∂Q of the ehl traction (both film-shear models, inlet heating on and off, slips from
    micro-slip to gross sliding, rolling speeds below and above v_reg) and the signed rolling force's ∂f/∂u and
    ∂f/∂Q, entry by entry to 1e-6 relative (or 1e-9 of the value's scale where a slope vanishes)."""
    from test_kernel import lubricated_row

    from bearing_mbs.contact import traction

    rng = np.random.default_rng(20 + k)
    row = np.array(lubricated_row(rng, k))
    row[list(traction.TRACTION_COLUMNS).index("rolling_resistance")] = 1.0
    boundary, vreg = 0.1, 0.01
    for slip, rolling, load in ((1e-4, 5.0, 3e3), (0.3, 2.0, 2e4), (-0.02, -8.0, 500.0), (0.5, 0.004, 1e3)):
        mu_value, *slopes = traction.ehl_traction_slopes(row, slip, rolling, load, boundary, vreg)
        assert mu_value == traction.ehl_traction(row, slip, rolling, load, boundary, vreg)[0]
        expected = (scalar_slope(lambda x: traction.ehl_traction(row, x, rolling, load, boundary, vreg)[0], slip,
                                 1e-4 * max(abs(slip), vreg)),
                    scalar_slope(lambda x: traction.ehl_traction(row, slip, x, load, boundary, vreg)[0], rolling,
                                 1e-4 * abs(rolling) if abs(rolling) > vreg else 1e-6),
                    scalar_slope(lambda x: traction.ehl_traction(row, slip, rolling, x, boundary, vreg)[0], load,
                                 1e-4 * load))
        mu = abs(traction.ehl_traction(row, slip, rolling, load, boundary, vreg)[0])
        for name, got, want, scale in zip(("slip", "rolling", "load"), slopes, expected,
                                          (mu / max(abs(slip), vreg), mu / abs(rolling), mu / load)):
            assert got == pytest.approx(want, rel=1e-6, abs=1e-9 * scale), (name, slip, rolling, load)
        force, by_rolling, by_load = traction.signed_rolling_force_slopes(row, rolling, load, vreg)
        signed = (lambda u, q: traction.rolling_force(row, u, q) * math.erf(2 * u / vreg))
        assert by_rolling == pytest.approx(scalar_slope(lambda x: signed(x, load), rolling, 1e-5 * abs(rolling)),
                                           rel=1e-6, abs=1e-9 * abs(force) / abs(rolling))
        assert by_load == pytest.approx(scalar_slope(lambda x: signed(rolling, x), load, 1e-5 * load), rel=1e-6,
                                        abs=1e-9 * abs(force) / load)


@pytest.mark.parametrize("half_width", [5e-3, np.inf])
@pytest.mark.parametrize("entrainment, gap_rate", [(1.0, 0.0), (2.0, -1e-3), (-1.5, 2e-3), (0.3, -2e-2),
                                                   (1.0, 1e-2), (0.0, -1e-3)])
def test_the_films_slopes_match_finite_differences(entrainment, gap_rate, half_width):
    """∂(W, F_c, f_P)/∂(h₀, ḣ₀, u, Δu) of the cylinder–plane film, on a pocket wall of half width 5 mm and on an
    unbounded plane, entry by entry to 1e-5 relative (the outlet's table is piecewise linear, so the differences stay
    on one segment: steps of 1e-7 relative)."""
    from bearing_mbs.fluid_film.cylinder_plane import film_force_slopes, film_forces

    values = np.array([2e-5, gap_rate, entrainment, 0.7])  # h₀, ḣ₀, u, Δu
    slopes = np.array(film_force_slopes(0.1, values[2], values[3], values[1], 0.0125, 0.055, half_width, values[0]))
    assert np.isfinite(slopes).all()
    for i in range(4):
        def film(x, i=i):
            point = values.copy()
            point[i] = x
            return np.array(film_forces(0.1, point[2], point[3], point[1], 0.0125, 0.055, half_width, point[0]))

        step = 1e-7 * max(abs(values[i]), 1e-3 if i == 1 else 1e-2 if i == 2 else 1e-9)
        expected = (film(values[i] + step) - film(values[i] - step)) / (2 * step)
        for output in range(3):
            scale = np.abs(np.array(film(values[i]))).max() / max(abs(values[i]), 1e-3)
            assert slopes[output, i] == pytest.approx(expected[output], rel=1e-5, abs=1e-9 * scale), (output, i)


@pytest.mark.parametrize("kind", PAIR_KINDS)
@pytest.mark.parametrize("ground", [False, True], ids=["on a body", "on the ground"])
def test_the_oil_films_jacobian_matches_finite_differences(kind, ground):
    """A pair with an oil film alone (bearing_mbs.fluid_film.cylinder_plane) at gaps from 3 µm to 0.3 mm and
    below its floor, a spinning roller (entrainment of metres per second) moving slowly against the feature,
    so that wedge and squeeze both act. (Near pure separation, squeeze a thousand times the entrainment, the
    film's load is a vanishing difference and its finite differences are rounding: those states are not
    compared.)"""
    from bearing_mbs.core.scene import Body, ContactPair, PairLaw, Scene

    rng = np.random.default_rng(30 + PAIR_KINDS.index(kind) + 10 * ground)
    radius_a = {"circle_line": 0.0, "circle_point": 0.0, "circle_in_circle": 0.3}.get(kind, 0.05)
    law = PairLaw("power", 0.0, 1.0, 1.0, 0.0, 1e-3, film=(0.055, 0.1, 5e-3, 1e-6))
    pair = ContactPair("film", kind, -1 if ground else 2, 1, law, radius_b=0.0125, radius_a=radius_a,
                       direction=(0.0, 1.0))
    scene = Scene("film", tuple(Body(f"b{i}", 1.0, 1e-3, (0.0, 0.0, 0.0)) for i in range(BODIES)), (pair,))
    parameters = contact_pairs.pack(scene.pairs)
    element = contact_pairs.ELEMENT
    for gap in (3e-6, 3e-5, 3e-4, -1e-6):
        q, v = np.zeros(N), rng.normal(scale=1e-3, size=N)
        q[4] = {"circle_line": 0.0125, "circle_point": 0.0125, "circle_in_circle": 0.3 - 0.0125}.get(kind, 0.0625)
        q[4] += -gap if kind == "circle_in_circle" else gap
        v[5] = rng.choice([-1.0, 1.0]) * rng.uniform(100, 300)  # the roller's spin
        pair_out = np.zeros((1, N_PAIR_OUTPUTS))
        element.add_forces(parameters, 0.0, q, v, np.zeros(1), np.zeros(N), pair_out, np.zeros(2), True)
        assert pair_out[0, 0] == pytest.approx(gap, abs=1e-12)
        position, velocity = np.zeros((N, N)), np.zeros((N, N))
        contact_pairs.add_jacobian(parameters, 0.0, q, v, np.zeros(1), pair_out, position, velocity)
        expected_position, expected_velocity = finite_differences(element, parameters, 0.0, q, v, np.zeros(1), 1e-8)
        for analytic, expected in ((position, expected_position), (velocity, expected_velocity)):
            np.testing.assert_allclose(analytic, expected, rtol=0, atol=1e-6 * np.abs(expected).max(),
                                       err_msg=f"gap {gap}")


@pytest.mark.parametrize("source, recessed", [("short", False), ("map", False), ("map", True)])
def test_the_journal_films_jacobian_matches_finite_differences(source, recessed):
    """Journal films (short bearing, and force maps of random tables: a plain bearing's over ε and β, a recessed
    one's over ε, the direction to the recesses, the hydrodynamic share and β) at eccentricities inside the clearance
    and beyond the largest one evaluated (held there, so only the direction acts), both directions of whirl."""
    from bearing_mbs.elements import journal_bearings
    from bearing_mbs.elements.journal_bearings import JournalFilm

    rng = np.random.default_rng(40)
    clearance = 2.5e-4
    shape, axes = ((12, 5, 7, 16), [0.09, np.pi / 10, 0.3, np.pi / 12, 40.0, 1.0]) if recessed else \
        ((12, 1, 1, 16), [0.09, 2 * np.pi, 0.0, 1.0, 1.0, 0.0])
    tables = {"map_normal": rng.normal(size=shape), "map_tangential": rng.normal(size=shape),
              "map_linear": rng.normal(size=(*shape[:2], 3, 2)), "map_axes": np.array(axes)} if source == "map" else {}
    films = [JournalFilm(f"j{b}", b, 1 + b % 2, 0.12, 0.03 + 0.01 * b, clearance, 0.05, tuple(rng.normal(size=2)),
                         source=source, **tables) for b in range(BODIES - 1)]
    parameters = journal_bearings.pack(films)
    element = journal_bearings.ELEMENT
    for ratio in (0.3, 0.7, 0.95, 1.3):
        q, v = np.zeros(N), rng.normal(scale=0.05, size=N)
        for film in films:
            angle = rng.uniform(0, 2 * np.pi)
            q[3 * film.body: 3 * film.body + 2] = np.array(film.centre) + ratio * clearance * np.array(
                [np.cos(angle), np.sin(angle)])
            v[3 * film.body + 2] = rng.choice([-1.0, 1.0]) * rng.uniform(50, 200)
        position, velocity = np.zeros((N, N)), np.zeros((N, N))
        element.add_jacobian(parameters, 0.0, q, v, position, velocity)
        expected_position, expected_velocity = finite_differences(element, parameters, 0.0, q, v, np.zeros(0), 1e-9)
        for analytic, expected in ((position, expected_position), (velocity, expected_velocity)):
            np.testing.assert_allclose(analytic, expected, rtol=0, atol=1e-6 * np.abs(expected).max(),
                                       err_msg=f"eccentricity ratio {ratio}")


def test_the_slewing_bearings_jacobian_matches_finite_differences():
    """Four-point-contact slewing bearings loaded radially, axially and in tilt (some balls' diagonals apart),
    with stiffness-proportional damping: ∂F/∂q includes the damping's change with the tangent stiffness."""
    from bearing_mbs.elements import slewing_bearings
    from bearing_mbs.elements.slewing_bearings import SlewingBearingJoint

    rng = np.random.default_rng(50)
    joints = [SlewingBearingJoint(f"s{b}", b, 12 + 5 * b, 0.5 + 0.1 * b, 2e-4, rng.uniform(0.6, 0.9),
                                  rng.uniform(1e9, 1e10), rng.uniform(0.0, 1e-4), tuple(rng.normal(size=3) * 0.01))
              for b in range(BODIES - 1)]
    parameters = slewing_bearings.pack(joints)
    element = slewing_bearings.ELEMENT
    for _ in range(5):
        q, v = np.zeros(N), rng.normal(scale=0.01, size=N)
        for joint in joints:
            q[3 * joint.body: 3 * joint.body + 3] = np.array(joint.reference) + rng.normal(size=3) * [2e-5, 3e-5, 4e-5]
        position, velocity = np.zeros((N, N)), np.zeros((N, N))
        element.add_jacobian(parameters, 0.0, q, v, position, velocity)
        expected_position, expected_velocity = finite_differences(element, parameters, 0.0, q, v, np.zeros(0), 1e-9)
        for analytic, expected in ((position, expected_position), (velocity, expected_velocity)):
            np.testing.assert_allclose(analytic, expected, rtol=0, atol=1e-6 * np.abs(expected).max())
        assert np.abs(position).max() > 0


def test_every_built_in_kind_has_an_analytic_jacobian():
    from bearing_mbs.elements.registry import BUILT_IN

    assert all(element.add_jacobian is not None for element in BUILT_IN)


@pytest.mark.parametrize("overrides", [["cage.model=penalty", "load.radial=6800"], ["scenario.variant=dry"],
                                       ["load.radial=2000"]],
                         ids=["lubricated, oiled pockets", "dry", "lubricated, constraint cage"])
def test_the_seed_bearings_jacobian_matches_finite_differences(overrides):
    """The whole scene's Jacobian (elements.assembly.element_jacobian: pairs, servo, drags, land film, loads) of the
    seed bearing at a state of its run, against central differences of its forces: 1e-6 of the largest entry."""
    from bearing_mbs.elements import pack_scene, scene_forces
    from bearing_mbs.elements.assembly import element_jacobian, has_analytic_jacobian
    from bearing_mbs.engines import simulate
    from bearing_mbs.models import build_scene, load_spec

    from cases import SCENARIOS

    spec = load_spec(SCENARIOS / "seed_hss_steady.toml", [*overrides, "scenario.end_time=0.003",
                                                          "solver.output_interval=1e-3"])
    scene = build_scene(spec)
    assert has_analytic_jacobian(scene)
    result = simulate(scene, spec.solver, spec.scenario.end_time)
    packed = pack_scene(scene)
    q, v, n = result.position[-1], result.velocity[-1], scene.coordinate_count
    latched = np.zeros(len(scene.pairs))  # no contact latched: the approach speeds follow the gap rates

    def forces_at(q, v):
        total, pair_out = np.zeros(n), np.zeros((len(scene.pairs), N_PAIR_OUTPUTS))
        scene_forces(packed, 0.003, q, v, latched, total, pair_out)
        return total, pair_out

    _, pair_out = forces_at(q, v)
    position, velocity = np.zeros((n, n)), np.zeros((n, n))
    element_jacobian(packed.elements, 0.003, q, v, latched, pair_out, position, velocity)
    for analytic, state, other, is_position in ((position, q, v, True), (velocity, v, q, False)):
        expected = np.empty((n, n))
        for j in range(n):
            step = 1e-9 * max(abs(state[j]), 1.0) if is_position else 1e-7 * max(abs(state[j]), 1.0)
            ahead, behind = state.copy(), state.copy()
            ahead[j] += step
            behind[j] -= step
            args = ((ahead, other), (behind, other)) if is_position else ((other, ahead), (other, behind))
            expected[:, j] = (forces_at(*args[0])[0] - forces_at(*args[1])[0]) / (2 * step)
        np.testing.assert_allclose(analytic, expected, rtol=0, atol=1e-6 * np.abs(expected).max())
