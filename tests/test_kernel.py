"""The compiled kernel against its numpy twin, and the pair kinematics against finite differences.

References: the twin (independent vectorised assembly of the same laws), tolerance 1e-12 relative as the
verified-core issue asks; central finite differences of the gap for the gap rate (truncation O(ε²),
tolerance 1e-7 relative); Newton's third law and the angular-momentum balance for the assembly.
"""

import math
from dataclasses import replace

import numpy as np
import pytest

from bearing_mbs.contact import FRICTION_LAWS, PAIR_KINDS, kernel, traction, twin
from bearing_mbs.contact.traction import TRACTION_COLUMNS
from bearing_mbs.core.scene import (
    GROUND,
    Body,
    ContactPair,
    PairLaw,
    Profile,
    Scene,
)
from bearing_mbs.elements import Drag, Load, VelocityServo, pack_scene, scene_forces, scene_forces_twin


def lubricated_row(rng, k):
    """A random traction row of either model (bearing_mbs.contact.traction), inlet heating, rolling resistance and
    shear heating on or off, a random starvation factor."""
    values = {"model": k % 2, "film_formula": (k // 2) % 2, "thermal": (k + 1) // 2 % 2,
              "viscosity": rng.uniform(0.01, 0.5),
              "pressure_viscosity": rng.uniform(1e-8, 3e-8), "temperature_viscosity": rng.uniform(0.02, 0.07),
              "conductivity": 0.13, "modulus": rng.uniform(1e11, 4e11), "radius": rng.uniform(0.005, 0.05),
              "length": rng.uniform(0.01, 0.06), "roughness": rng.uniform(5e-8, 5e-7), "eyring_stress": 5e6,
              "shear_modulus": rng.uniform(1e7, 1e9), "limiting_shear": 0.07, "curve_a": -0.01, "curve_b": 4.0,
              "curve_c": 40.0, "curve_d": 0.01, "rolling_resistance": k % 3 % 2, "shear_heating": k // 4 % 2,
              "replenishment": rng.uniform(0.4, 1.0)}
    return tuple(values[c] for c in TRACTION_COLUMNS)


def random_scene(rng, n_bodies=4, n_pairs=40):
    """Bodies with random states and pairs of every kind and friction law, most of them penetrating; every
    seventh pair carries an oil film (bearing_mbs.fluid_film.cylinder_plane)."""
    bodies = tuple(
        Body(f"b{i}", mass=rng.uniform(0.1, 2), inertia=rng.uniform(1e-4, 1e-2), position=(0.0, 0.0, 0.0))
        for i in range(n_bodies)
    )
    pairs = []
    for k in range(n_pairs):
        kind = PAIR_KINDS[k % len(PAIR_KINDS)]
        b = int(rng.integers(n_bodies))
        a = int(rng.integers(-1, n_bodies - 1))
        a = a if a < b else a + 1
        law = PairLaw(
            normal_law="lankarani_nikravesh",
            stiffness=rng.uniform(1e5, 1e9),
            exponent=rng.choice([1.0, 10 / 9, 1.3, 1.5]),
            restitution=0.8,
            damping_factor=rng.uniform(0, 2),
            approach_speed_floor=1e-3,
            friction_law=FRICTION_LAWS[k % len(FRICTION_LAWS)],
            friction_coefficient=rng.uniform(0, 0.3),
            regularisation_speed=rng.uniform(1e-3, 1e-1),
            rolling_resistance_arm=rng.uniform(0, 1e-3),
            traction=lubricated_row(rng, k // len(FRICTION_LAWS)) if FRICTION_LAWS[k % len(FRICTION_LAWS)] == "ehl" else (),
            film=(rng.uniform(0.01, 0.06), rng.uniform(0.01, 0.5), rng.uniform(1e-3, 1e-2), rng.uniform(1e-7, 1e-6))
            if k % 7 == 3 else (),
        )
        direction = rng.normal(size=2)
        pairs.append(
            ContactPair(
                name=f"p{k}",
                kind=kind,
                body_a=a,
                body_b=b,
                law=law,
                radius_b=rng.uniform(0.01, 0.05),
                radius_a=0.0 if kind == "circle_point" else rng.uniform(0.05, 0.2),
                anchor=tuple(rng.normal(scale=0.01, size=2)),
                direction=tuple(direction / np.linalg.norm(direction)),
            )
        )
    loads = (Load("f", 0, (1.0, -2.0, 0.3), Profile((0.0, 1.0), (0.0, 2.0))),)
    drives = (VelocityServo("servo", 1, 5.0, Profile((0.0, 0.5), (0.0, 100.0))),)
    drags = (Drag("drag", 2, 0.3, 1e-3, 0.05, 1e-5),)
    return Scene("random", bodies, tuple(pairs), forces=(*loads, *drives, *drags))


def random_state(rng, scene, spread=0.1):
    n = scene.coordinate_count
    q = rng.normal(scale=spread, size=n)
    v = rng.normal(scale=1.0, size=n)
    latched = np.where(rng.random(len(scene.pairs)) < 0.5, rng.uniform(1e-4, 1.0, len(scene.pairs)), 0.0)
    return q, v, latched


def evaluate(scene_forces_of, packed, t, q, v, latched):
    forces = np.empty(q.size)
    pair_out = np.empty((packed.pairs.kind.size, kernel.N_PAIR_OUTPUTS))
    scene_forces_of(packed, t, q, v, latched, forces, pair_out)
    return forces, pair_out


def test_kernel_matches_numpy_twin_on_random_states():
    rng = np.random.default_rng(1)
    scene = random_scene(rng)
    packed = pack_scene(scene)
    in_contact = 0
    for trial in range(50):
        q, v, latched = random_state(rng, scene)
        t = rng.uniform(0, 1)
        f_kernel, p_kernel = evaluate(scene_forces, packed, t, q, v, latched)
        f_twin, p_twin = evaluate(scene_forces_twin, packed, t, q, v, latched)
        np.testing.assert_allclose(f_kernel, f_twin, rtol=1e-12, atol=1e-12 * np.abs(f_twin).max())
        scale = np.abs(p_twin).max(axis=0) + 1e-300
        np.testing.assert_allclose(p_kernel / scale, p_twin / scale, rtol=0, atol=1e-12)
        in_contact += int(np.sum(p_twin[:, 3] > 0))
    assert in_contact > 200, "random states must exercise many active contacts"


def test_incomplete_evaluation_gives_the_same_forces_and_power():
    """Inside integration stages the kernel skips the velocity-level outputs of pairs apart; forces, powers and
    the outputs of pairs in contact must not change (exactly)."""
    rng = np.random.default_rng(6)
    scene = random_scene(rng)
    packed = pack_scene(scene)
    for _ in range(20):
        q, v, latched = random_state(rng, scene)
        full, partial = np.empty(q.size), np.empty(q.size)
        pairs_full, pairs_partial = (np.empty((len(scene.pairs), kernel.N_PAIR_OUTPUTS)) for _ in range(2))
        power_full = scene_forces(packed, 0.3, q, v, latched, full, pairs_full, True)
        power_partial = scene_forces(packed, 0.3, q, v, latched, partial, pairs_partial, False)
        assert power_full == power_partial
        np.testing.assert_array_equal(full, partial)
        touching = pairs_full[:, 0] < 0
        np.testing.assert_array_equal(pairs_full[touching], pairs_partial[touching])


def test_gap_rate_is_the_time_derivative_of_the_gap():
    rng = np.random.default_rng(2)
    scene = random_scene(rng)
    pairs = pack_scene(scene).pairs
    q, v, _ = random_state(rng, scene)
    eps = 1e-6
    gap_plus = twin.pair_geometry(pairs, q + eps * v, v)[0]
    gap_minus = twin.pair_geometry(pairs, q - eps * v, v)[0]
    gap_rate = twin.pair_geometry(pairs, q, v)[1]
    np.testing.assert_allclose(gap_rate, (gap_plus - gap_minus) / (2 * eps), rtol=1e-7, atol=1e-9)


def test_contact_forces_balance_between_bodies():
    """Internal pairs only: total force and total angular momentum rate about the origin vanish."""
    rng = np.random.default_rng(3)
    scene = random_scene(rng)
    internal = tuple(p for p in scene.pairs if p.body_a != GROUND)
    scene = Scene("internal", scene.bodies, internal)
    q, v, latched = random_state(rng, scene)
    forces, pair_out = evaluate(scene_forces, pack_scene(scene), 0.0, q, v, latched)
    f = forces.reshape(-1, 3)
    qb = q.reshape(-1, 3)
    assert np.sum(pair_out[:, 3] > 0) > 5
    scale = np.abs(f).max()
    assert abs(f[:, 0].sum()) < 1e-12 * scale and abs(f[:, 1].sum()) < 1e-12 * scale
    moment_about_origin = np.sum(f[:, 2] + qb[:, 0] * f[:, 1] - qb[:, 1] * f[:, 0])
    assert abs(moment_about_origin) < 1e-12 * scale


def test_contact_power_loss_is_never_negative():
    """Dissipation of damping, friction and rolling resistance is ≥ 0 for every pair and state."""
    rng = np.random.default_rng(4)
    scene = random_scene(rng)
    packed = pack_scene(scene)
    for _ in range(20):
        q, v, latched = random_state(rng, scene)
        _, pair_out = evaluate(scene_forces, packed, 0.0, q, v, latched)
        assert np.all(pair_out[:, 6] >= -1e-12 * np.abs(pair_out[:, 6]).max())


@pytest.mark.parametrize("kind", PAIR_KINDS)
def test_separated_pairs_exert_no_force(kind):
    law = PairLaw("lankarani_nikravesh", 1e8, 1.5, 0.9, 0.1425, 1e-3, "erf", 0.1, 1e-2, 1e-4)
    bodies = (Body("a", 1.0, 1.0, (0.0, 0.0, 0.0)), Body("b", 1.0, 1.0, (0.0, 0.5, 0.0)))
    radius_a = {"circle_in_circle": 1.0, "circle_point": 0.0}.get(kind, 0.1)
    pair = ContactPair("p", kind, 0, 1, law, radius_b=0.1, radius_a=radius_a)
    forces, pair_out = evaluate(scene_forces, pack_scene(Scene("s", bodies, (pair,))), 0.0, *Scene("s", bodies).initial_state(), np.zeros(1))
    assert pair_out[0, 0] > 0
    assert np.all(forces == 0.0)


def test_rolling_speed_is_relative_to_the_moving_contact_point():
    """u = t·(v_a(p) + v_b(p))/2 − t·ṗ, with ṗ from central differences of p = c_b − r_b n (1e-6 relative)."""
    rng = np.random.default_rng(5)
    scene = random_scene(rng)
    pairs = pack_scene(scene).pairs
    q, v, _ = random_state(rng, scene)
    eps = 1e-7
    _, _, _, nx, ny, cx, cy, _, rolling = twin.pair_geometry(pairs, q, v)
    plus = twin.pair_geometry(pairs, q + eps * v, v)
    minus = twin.pair_geometry(pairs, q - eps * v, v)
    pvx, pvy = (plus[5] - minus[5]) / (2 * eps), (plus[6] - minus[6]) / (2 * eps)
    qb, vb = q.reshape(-1, 3), v.reshape(-1, 3)

    def surface_velocity(body, x, y):
        vx = np.where(body < 0, 0.0, vb[body, 0] - vb[body, 2] * (y - qb[body, 1]))
        vy = np.where(body < 0, 0.0, vb[body, 1] + vb[body, 2] * (x - qb[body, 0]))
        return vx, vy

    vax, vay = surface_velocity(pairs.body_a, cx, cy)
    vbx, vby = surface_velocity(pairs.body_b, cx, cy)
    expected = 0.5 * (-ny * (vax + vbx) + nx * (vay + vby)) - (-ny * pvx + nx * pvy)
    np.testing.assert_allclose(rolling, expected, rtol=1e-6, atol=1e-8)


def test_pure_rolling_inside_a_fixed_ring_has_zero_slip_and_the_orbital_rolling_speed():
    """A roller of radius r rolling without slip inside a fixed ring of radius R: slip 0, |u| = Ω R."""
    ring, roller, orbit = 0.13, 0.0125, 70.0
    centre = ring - roller
    spin = -orbit * centre / roller  # the contact point on the roller is at rest
    law = PairLaw("power", 1e9, 10 / 9, 1.0, 0.0, 1e-3)
    body = Body("roller", 0.2, 1e-5, (centre, 0.0, 0.0), (0.0, orbit * centre, spin))
    pair = ContactPair("p", "circle_in_circle", GROUND, 0, law, radius_b=roller, radius_a=ring)
    scene = Scene("s", (body,), (pair,))
    _, pair_out = evaluate(scene_forces, pack_scene(scene), 0.0, *scene.initial_state(), np.zeros(1))
    assert abs(pair_out[0, 2]) < 1e-12
    assert abs(pair_out[0, 7]) == pytest.approx(orbit * ring, rel=1e-12)


def lubricated(scene, rng, rolling_resistance):
    """The scene with every pair lubricated (``ehl``, random traction rows) and its hydrodynamic rolling
    resistance on or off, without oil films; the same rows for the same generator state."""
    column = TRACTION_COLUMNS.index("rolling_resistance")

    def law(k, pair):
        row = list(lubricated_row(rng, k))
        row[column] = float(rolling_resistance)
        return replace(pair, law=replace(pair.law, friction_law="ehl", traction=tuple(row), film=()))

    return replace(scene, pairs=tuple(law(k, p) for k, p in enumerate(scene.pairs)))


def test_the_hydrodynamic_rolling_resistance_dissipates_its_force_times_the_rolling_speed():
    """Its forces (a tangential pair force and a couple, bearing_mbs.contact.traction) must do the power
    −F_R erf(2u/v_reg) u on the bodies, u the rolling speed of the pair kinematics, in any motion (rolling or
    sliding) and on every pair kind. The power is summed from the body forces and velocities (sum F·v), not from
    the kernel's loss column, which must agree too. 1e-9 relative, or 1e-12 of the sums they are differences of."""
    rng = np.random.default_rng(8)
    base = random_scene(rng)
    scenes = [lubricated(base, np.random.default_rng(9), flag) for flag in (True, False)]
    on, off = (pack_scene(scene) for scene in scenes)
    kinds = np.array([p.kind for p in base.pairs])
    touched = set()
    for _ in range(30):
        q, v, latched = random_state(rng, base)
        forces_on, pairs_on = evaluate(scene_forces, on, 0.0, q, v, latched)
        forces_off, pairs_off = evaluate(scene_forces, off, 0.0, q, v, latched)
        touching = pairs_on[:, 3] > 0
        rolling = pairs_on[:, 7]
        expected = sum(traction.rolling_force(np.asarray(scenes[0].pairs[k].law.traction), rolling[k], pairs_on[k, 3])
                       * math.erf(2 * rolling[k] / base.pairs[k].law.regularisation_speed) * rolling[k]
                       for k in np.flatnonzero(touching))
        assert expected > 0
        power = np.dot(forces_on - forces_off, v)  # the difference of two sums of normal forces up to ~1e6 N
        assert power == pytest.approx(-expected, rel=1e-9, abs=1e-12 * np.abs(forces_on * v).sum())
        rounding = 1e-12 * np.abs(pairs_on[:, 6]).sum()  # the loss column sums traction losses up to ~1e4 W
        assert np.sum(pairs_on[:, 6] - pairs_off[:, 6]) == pytest.approx(expected, rel=1e-9, abs=rounding)
        touched.update(kinds[touching])
    assert touched == set(PAIR_KINDS)


def test_the_oil_film_does_the_power_of_its_load_and_shears():
    """A pair's film (bearing_mbs.fluid_film.cylinder_plane: load W, Couette shear F_c, Poiseuille shear f_P)
    must do the power W dh/dt + F_c slip − f_P u on the bodies (the Poiseuille shear acting as a rolling
    resistance does), at the pair kinematics' gap (or the film's floor), gap rate, slip and rolling speed; and the
    film's loss, −W dh/dt + f_P u − F_c slip, is never negative: by parts its first two terms are the Poiseuille
    dissipation ∫ h³p'²/12η dx. The power is summed from the body forces and velocities (Σ F·v) of the scene with
    and without the films, 1e-9 relative or 1e-12 of the sums it is a difference of."""
    from bearing_mbs.fluid_film.cylinder_plane import film_forces

    rng = np.random.default_rng(10)
    with_films = random_scene(rng)
    without = Scene("dry", with_films.bodies, tuple(replace(p, law=replace(p.law, film=())) for p in with_films.pairs),
                    forces=with_films.forces)
    on, off = pack_scene(with_films), pack_scene(without)
    films = [k for k, p in enumerate(with_films.pairs) if p.law.film]
    for _ in range(30):
        q, v, latched = random_state(rng, with_films)
        forces_on, pairs_on = evaluate(scene_forces, on, 0.0, q, v, latched)
        forces_off, pairs_off = evaluate(scene_forces, off, 0.0, q, v, latched)
        expected, losses = 0.0, []
        for k in films:
            length, viscosity, half_width, floor = with_films.pairs[k].law.film
            gap, rate, slip, rolling = pairs_on[k, [0, 1, 2, 7]]
            load, couette, poiseuille = film_forces(viscosity, rolling, slip, rate, with_films.pairs[k].radius_b,
                                                    length, half_width, max(gap, floor))
            expected += load * rate + couette * slip - poiseuille * rolling
            losses.append(pairs_on[k, 6] - pairs_off[k, 6])
            assert losses[-1] == pytest.approx(-(load * rate + couette * slip - poiseuille * rolling), rel=1e-9,
                                               abs=1e-12 * abs(pairs_on[k, 6]))
        power = np.dot(forces_on - forces_off, v)
        assert power == pytest.approx(expected, rel=1e-9, abs=1e-12 * np.abs(forces_on * v).sum())
        assert min(losses) >= -1e-9 * max(abs(loss) for loss in losses)
