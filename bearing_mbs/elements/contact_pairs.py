"""Contact pairs as a force element: normal force, friction and rolling resistance of every pair.

The compiled :func:`add_forces` loops over the pairs calling the pure functions of :mod:`bearing_mbs.contact`
(kinematics, normal and friction laws; compiled inline there, plain Python elsewhere); :func:`add_forces_twin`
does the same on whole arrays with numpy. The tests hold the two to 1e-12.

Per pair it writes the columns of :data:`PAIR_OUTPUTS` into ``pair_out`` (for a lubricated pair with its
hydrodynamic rolling resistance, the friction force and rolling moment include that resistance's tangential force
and couple, :mod:`bearing_mbs.contact.traction`); the power lost to damping, friction and rolling resistance goes
to ``power[1]``. The elastic energy of the pairs is their potential energy.

A pair whose law has a film (:attr:`~bearing_mbs.core.scene.PairLaw.film`) carries the oil film of its circle on
a plane (:mod:`bearing_mbs.fluid_film.cylinder_plane`) whether it touches or not, at its gap or the film's floor,
whichever is larger: the film's load adds to the normal force, its Couette shear to the friction force, and its
Poiseuille shear acts as a rolling resistance does (its tangential force and couple).
"""

from __future__ import annotations

from typing import NamedTuple

import numba
import numpy as np

from bearing_mbs.contact import friction, kinematics, normal, traction
from bearing_mbs.contact.friction import FRICTION_LAWS
from bearing_mbs.contact.kernel import (
    N_PAIR_OUTPUTS,
    PAIR_OUTPUTS,
    body_trigonometry,
    pair_motion,
    pair_position,
    regularised_sign,
    regularised_sign_slope,
    rolling_resistance,
    tangential_force,
)
from bearing_mbs.contact.kinematics import ORIENTATION, PAIR_KINDS
from bearing_mbs.contact.pair_jacobian import pair_motion_jacobian
from bearing_mbs.contact.traction import N_TRACTION_COLUMNS
from bearing_mbs.contact.twin import pair_geometry
from bearing_mbs.contact.twin import regularised_sign as regularised_sign_twin
from bearing_mbs.core.force_element import ForceElement
from bearing_mbs.core.scene import FILM_COLUMNS, ContactPair
from bearing_mbs.fluid_film.cylinder_plane import film_force_slopes, film_forces

_EHL = FRICTION_LAWS.index("ehl")  # read by numba as a compile-time constant


class PairArrays(NamedTuple):
    """Contact pairs as arrays (one entry per pair), read by the kernel and its numpy twin."""

    kind: np.ndarray  # int64, index into PAIR_KINDS
    body_a: np.ndarray  # int64, −1 = ground
    body_b: np.ndarray  # int64
    anchor: np.ndarray  # (P, 2) [m]
    direction: np.ndarray  # (P, 2)
    radius_a: np.ndarray  # [m]
    radius_b: np.ndarray  # [m]
    stiffness: np.ndarray  # [N/m^n]
    exponent: np.ndarray  # [-]
    damping_factor: np.ndarray  # [-]
    approach_speed_floor: np.ndarray  # [m/s]
    friction_law: np.ndarray  # int64, index into FRICTION_LAWS
    friction_coefficient: np.ndarray  # [-]
    regularisation_speed: np.ndarray  # [m/s]
    rolling_resistance_arm: np.ndarray  # [m]
    traction: np.ndarray  # (P, N_TRACTION_COLUMNS): lubricated-traction rows, zeros for the other laws
    film: np.ndarray  # (P, 4): the film's length [m], viscosity [Pa s], half-width [m] and floor [m]; zeros without


def traction_rows(pairs) -> np.ndarray:
    rows = np.zeros((len(pairs), N_TRACTION_COLUMNS))
    for k, p in enumerate(pairs):
        if p.law.traction:
            rows[k] = p.law.traction
    return rows


def pack(pairs) -> PairArrays:
    def column(get, dtype=float):
        return np.array([get(p) for p in pairs], dtype=dtype)

    return PairArrays(
        kind=column(lambda p: PAIR_KINDS.index(p.kind), np.int64),
        body_a=column(lambda p: p.body_a, np.int64),
        body_b=column(lambda p: p.body_b, np.int64),
        anchor=column(lambda p: p.anchor).reshape(-1, 2),
        direction=column(lambda p: p.direction).reshape(-1, 2),
        radius_a=column(lambda p: p.radius_a),
        radius_b=column(lambda p: p.radius_b),
        stiffness=column(lambda p: p.law.stiffness),
        exponent=column(lambda p: p.law.exponent),
        damping_factor=column(lambda p: p.law.damping_factor),
        approach_speed_floor=column(lambda p: p.law.approach_speed_floor),
        friction_law=column(lambda p: FRICTION_LAWS.index(p.law.friction_law), np.int64),
        friction_coefficient=column(lambda p: p.law.friction_coefficient),
        regularisation_speed=column(lambda p: p.law.regularisation_speed),
        rolling_resistance_arm=column(lambda p: p.law.rolling_resistance_arm),
        traction=traction_rows(pairs),
        film=np.array([p.law.film or (0.0,) * len(FILM_COLUMNS) for p in pairs],
                      dtype=float).reshape(-1, len(FILM_COLUMNS)),
    )


@numba.njit(cache=True, inline="always")  # inlined into the integrators: no per-call reference counting
def add_forces(parameters, t, q, v, latched, forces, pair_out, power, complete):
    """Forces of all pairs. ``complete=False`` (inside integration stages) skips the velocity-level outputs of
    pairs apart, which no force needs (about a third of the evaluation for a bearing, where most pocket and
    upper raceway pairs are apart): their gap rate, slip and rolling speed are left 0."""
    pairs = parameters
    cos_theta, sin_theta = body_trigonometry(q)
    dissipated = 0.0  # a local sum: updating power[1] in the loop would keep it in memory, ~10 ns a pair
    for k in range(pairs.kind.size):
        a, b, kind = pairs.body_a[k], pairs.body_b[k], pairs.kind[k]
        ra, rb = pairs.radius_a[k], pairs.radius_b[k]
        gap, nx, ny, px, py = pair_position(
            kind, a, b, pairs.anchor[k, 0], pairs.anchor[k, 1], pairs.direction[k, 0], pairs.direction[k, 1],
            ra, rb, q, cos_theta[a] if a >= 0 else 1.0, sin_theta[a] if a >= 0 else 0.0)
        film = pairs.film[k, 0] > 0.0
        gap_rate = slip = spin = rolling = cx = cy = 0.0  # all defined on every path, as inlining needs
        if complete or gap < 0.0 or film:
            gap_rate, slip, cx, cy, spin, rolling = pair_motion(kind, a, b, ra, rb, gap, nx, ny, px, py, q, v)
        fn = ft = moment = loss = elastic = 0.0
        if gap < 0.0 or film:
            if gap < 0.0:
                approach = normal.reference_approach_speed(latched[k], gap_rate, pairs.approach_speed_floor[k])
                elastic = normal.elastic_force(gap, pairs.stiffness[k], pairs.exponent[k])
                fn = max(elastic * normal.hysteresis_factor(gap_rate, pairs.damping_factor[k], approach), 0.0)
                law, vreg = pairs.friction_law[k], pairs.regularisation_speed[k]
                ft = tangential_force(law, fn, pairs.friction_coefficient[k], slip, rolling, vreg, pairs.traction[k])
                ft, moment = rolling_resistance(law, ft, fn, pairs.rolling_resistance_arm[k], spin, rolling,
                                                ORIENTATION[kind], ra, rb, gap, vreg, pairs.traction[k])
            if film:
                film_load, couette, poiseuille = film_forces(pairs.film[k, 1], rolling, slip, gap_rate, rb,
                                                             pairs.film[k, 0], pairs.film[k, 2],
                                                             max(gap, pairs.film[k, 3]))
                share = kinematics.contact_point_share(ORIENTATION[kind], ra, rb, gap)
                tangential, couple = traction.inlet_shear_reaction(poiseuille, share, rb)
                fn += film_load
                ft += couette + tangential
                moment += couple
            loss = -(fn - elastic) * gap_rate - ft * slip - moment * spin
            fx, fy = fn * nx - ft * ny, fn * ny + ft * nx
            forces[3 * b] += fx
            forces[3 * b + 1] += fy
            forces[3 * b + 2] += (cx - q[3 * b]) * fy - (cy - q[3 * b + 1]) * fx + moment
            if a >= 0:
                forces[3 * a] -= fx
                forces[3 * a + 1] -= fy
                forces[3 * a + 2] -= (cx - q[3 * a]) * fy - (cy - q[3 * a + 1]) * fx + moment
        pair_out[k, 0] = gap
        pair_out[k, 1] = gap_rate
        pair_out[k, 2] = slip
        pair_out[k, 3] = fn
        pair_out[k, 4] = ft
        pair_out[k, 5] = moment
        pair_out[k, 6] = loss
        pair_out[k, 7] = rolling
        dissipated += loss
    power[1] += dissipated


def add_forces_twin(pairs, t, q, v, latched, forces, pair_out, power, complete):
    """Numpy twin of :func:`add_forces`; always complete."""
    gap, gap_rate, slip, nx, ny, cx, cy, spin, rolling = pair_geometry(pairs, q, v)
    approach = normal.reference_approach_speed(latched, gap_rate, pairs.approach_speed_floor)
    fn = normal.hysteresis_force(gap, gap_rate, pairs.stiffness, pairs.exponent, pairs.damping_factor, approach)
    ft = friction.friction_force(
        fn, pairs.friction_coefficient, regularised_sign_twin(pairs.friction_law, slip, pairs.regularisation_speed)
    )
    rolling_force = np.zeros_like(fn)
    for k in np.flatnonzero((pairs.friction_law == _EHL) & (fn > 0)):
        ft[k] = -fn[k] * traction.ehl_traction(pairs.traction[k], slip[k], rolling[k], fn[k],
                                               pairs.friction_coefficient[k], pairs.regularisation_speed[k])[0]
        rolling_force[k] = traction.rolling_force(pairs.traction[k], rolling[k], fn[k])
    spin_sign = regularised_sign_twin(pairs.friction_law, spin * pairs.radius_b, pairs.regularisation_speed)
    moment = friction.rolling_resistance_moment(fn, pairs.rolling_resistance_arm, spin_sign)
    share = kinematics.contact_point_share(np.asarray(ORIENTATION)[pairs.kind], pairs.radius_a, pairs.radius_b, gap)
    tangential, couple = traction.rolling_resistance(rolling_force, rolling, pairs.regularisation_speed, share,
                                                     pairs.radius_b)
    ft, moment = ft + tangential, moment + couple
    film = pairs.film[:, 0] > 0
    if film.any():
        length, viscosity, half_width, floor = pairs.film[film].T
        film_load, couette, poiseuille = film_forces(viscosity, rolling[film], slip[film], gap_rate[film],
                                                     pairs.radius_b[film], length, half_width,
                                                     np.maximum(gap[film], floor))
        tangential, couple = traction.inlet_shear_reaction(poiseuille, share[film], pairs.radius_b[film])
        fn[film] += film_load
        ft[film] += couette + tangential
        moment[film] += couple
    damping = fn - normal.elastic_force(gap, pairs.stiffness, pairs.exponent)
    loss = -damping * gap_rate - ft * slip - moment * spin

    fx, fy = fn * nx - ft * ny, fn * ny + ft * nx
    qb = q.reshape(-1, 3)
    a, b = pairs.body_a, pairs.body_b
    torque_b = (cx - qb[b, 0]) * fy - (cy - qb[b, 1]) * fx + moment
    body_forces = forces.reshape(-1, 3)
    np.add.at(body_forces, b, np.column_stack([fx, fy, torque_b]))
    on_a = a >= 0
    ai = a[on_a]
    torque_a = (cx[on_a] - qb[ai, 0]) * fy[on_a] - (cy[on_a] - qb[ai, 1]) * fx[on_a] + moment[on_a]
    np.add.at(body_forces, ai, -np.column_stack([fx[on_a], fy[on_a], torque_a]))
    pair_out[:, :N_PAIR_OUTPUTS] = np.column_stack([gap, gap_rate, slip, fn, ft, moment, loss, rolling])
    power[1] += loss.sum()


def potential_energy(pairs, position, pair_output):
    """Elastic energy of the pairs [J] at each output instant, from the recorded gaps."""
    gap = pair_output[:, :, PAIR_OUTPUTS.index("gap")]
    if gap.shape[1] == 0:
        return np.zeros(gap.shape[0])
    return np.sum(normal.elastic_energy(gap, pairs.stiffness, pairs.exponent), axis=1)


@numba.njit(cache=True)
def _law_partials(pairs, k, fn, normal_gap, normal_rate, gap, gap_rate, slip, rolling, spin):
    """(∂F_N, ∂F_T, ∂M) over the pair's (gap, gap rate, slip, rolling speed, spin) of its contact law: the
    Coulomb family's F_T = −μ F_N φ(slip), or ``ehl``'s −μ(Δu, u, F_N) F_N with its hydrodynamic rolling
    resistance's force and couple; and the dry rolling arm's M = −μ_R F_N φ(r_b ω_rel)."""
    law, vreg, rb = pairs.friction_law[k], pairs.regularisation_speed[k], pairs.radius_b[k]
    d_fn = np.array([normal_gap, normal_rate, 0.0, 0.0, 0.0])
    d_ft = np.zeros(5)
    d_moment = np.zeros(5)
    if law == _EHL:
        if fn > 0.0:
            row, boundary = pairs.traction[k], pairs.friction_coefficient[k]
            mu = traction.ehl_traction(row, slip, rolling, fn, boundary, vreg)[0]
            mu_slip, mu_rolling, mu_load = traction.ehl_traction_slopes(row, slip, rolling, fn, boundary, vreg)
            d_ft = -(mu + fn * mu_load) * d_fn
            d_ft[2] -= fn * mu_slip
            d_ft[3] -= fn * mu_rolling
            force, force_rolling, force_load = traction.signed_rolling_force_slopes(row, rolling, fn, vreg)
            if force != 0.0 or force_rolling != 0.0:
                orientation = ORIENTATION[pairs.kind[k]]
                share = kinematics.contact_point_share(orientation, pairs.radius_a[k], rb, gap)
                distance = pairs.radius_a[k] + orientation * (rb + gap)
                share_gap = -rb / distance**2 if orientation != 0 else 0.0
                d_force = force_load * d_fn
                d_force[3] += force_rolling
                d_ft += (0.5 - share) * d_force
                d_ft[0] -= force * share_gap
                d_moment += (1.0 - share) * rb * d_force
                d_moment[0] -= rb * force * share_gap
    else:
        sign, slope = regularised_sign(law, slip, vreg), regularised_sign_slope(law, slip, vreg)
        d_ft = -pairs.friction_coefficient[k] * (sign * d_fn)
        d_ft[2] -= pairs.friction_coefficient[k] * fn * slope
    arm = pairs.rolling_resistance_arm[k]
    if arm > 0.0:
        spin_sign = regularised_sign(law, spin * rb, vreg)
        d_moment -= arm * spin_sign * d_fn
        d_moment[4] -= arm * fn * regularised_sign_slope(law, spin * rb, vreg) * rb
    if pairs.film[k, 0] > 0.0:
        _add_film_partials(pairs, k, gap, gap_rate, slip, rolling, d_fn, d_ft, d_moment)
    return d_fn, d_ft, d_moment


@numba.njit(cache=True)
def _add_film_partials(pairs, k, gap, gap_rate, slip, rolling, d_fn, d_ft, d_moment):
    """Add the film's load, Couette shear and Poiseuille shear (split as the rolling resistance's) to the
    partials over (gap, gap rate, slip, rolling speed, spin); below the floor the film does not see the gap."""
    length, viscosity, half_width, floor = pairs.film[k, 0], pairs.film[k, 1], pairs.film[k, 2], pairs.film[k, 3]
    rb, ra, orientation = pairs.radius_b[k], pairs.radius_a[k], ORIENTATION[pairs.kind[k]]
    film_gap = max(gap, floor)
    load, couette, shear = film_force_slopes(viscosity, rolling, slip, gap_rate, rb, length, half_width, film_gap)
    if gap < floor:
        load[0] = couette[0] = shear[0] = 0.0
    poiseuille = film_forces(viscosity, rolling, slip, gap_rate, rb, length, half_width, film_gap)[2]
    share = kinematics.contact_point_share(orientation, ra, rb, gap)
    share_gap = -rb / (ra + orientation * (rb + gap)) ** 2 if orientation != 0 else 0.0
    # (h, ḣ, u, Δu) → (gap, gap rate, slip, rolling, spin)
    d_load = np.array([load[0], load[1], load[3], load[2], 0.0])
    d_shear = np.array([shear[0], shear[1], shear[3], shear[2], 0.0])
    d_fn += d_load
    d_ft += np.array([couette[0], couette[1], couette[3], couette[2], 0.0]) + (0.5 - share) * d_shear
    d_ft[0] -= poiseuille * share_gap
    d_moment += (1.0 - share) * rb * d_shear
    d_moment[0] -= rb * poiseuille * share_gap


@numba.njit(cache=True)
def add_jacobian(parameters, t, q, v, latched, pair_out, force_position, force_velocity):
    r"""∂F/∂q and ∂F/∂v of the pairs in contact (and of those with a film), by the chain rule: the laws' partial
    derivatives in the pair's gap, gap rate, slip, rolling speed and spin (:func:`_law_partials`) times those
    quantities' derivatives (:func:`bearing_mbs.contact.pair_jacobian.pair_motion_jacobian`), and the turning of
    the normal and the moving contact point for the force's direction and arm. The force on b is
    :math:`F = F_N n + F_T t` at c, its torque :math:`-r_b F_T + M`; a receives −F at c and :math:`-(c - c_a)\times F
    - M`."""
    pairs = parameters
    for k in range(pairs.kind.size):
        gap, gap_rate, slip, fn, ft, moment, _, rolling = pair_out[k]
        if not (gap < 0.0 or pairs.film[k, 0] > 0.0):
            continue
        a, b, kind, rb = pairs.body_a[k], pairs.body_b[k], pairs.kind[k], pairs.radius_b[k]
        gap_q, kappa, c_x, c_y, rate_z, slip_z, rolling_z, spin_z = pair_motion_jacobian(
            kind, a, b, pairs.anchor[k, 0], pairs.anchor[k, 1], pairs.direction[k, 0], pairs.direction[k, 1], rb, q, v)
        spin = v[3 * b + 2] - (v[3 * a + 2] if a >= 0 else 0.0)
        normal_gap = normal_rate = 0.0
        if gap < 0.0:
            normal_gap, normal_rate = normal.hysteresis_force_slopes(
                gap, gap_rate, pairs.stiffness[k], pairs.exponent[k], pairs.damping_factor[k], latched[k],
                pairs.approach_speed_floor[k])
        dry = fn  # the contact's own normal force, which its friction law reads: less any film's load
        if pairs.film[k, 0] > 0.0:
            dry -= film_forces(pairs.film[k, 1], rolling, slip, gap_rate, rb, pairs.film[k, 0], pairs.film[k, 2],
                               max(gap, pairs.film[k, 3]))[0]
        d_fn, d_ft, d_moment = _law_partials(pairs, k, dry, normal_gap, normal_rate, gap, gap_rate, slip, rolling,
                                             spin)
        # over (z, ż): the five quantities' derivatives
        gap_z = np.zeros(12)
        gap_z[:6] = gap_q
        fn_z = d_fn[0] * gap_z + d_fn[1] * rate_z + d_fn[2] * slip_z + d_fn[3] * rolling_z + d_fn[4] * spin_z
        ft_z = d_ft[0] * gap_z + d_ft[1] * rate_z + d_ft[2] * slip_z + d_ft[3] * rolling_z + d_ft[4] * spin_z
        moment_z = (d_moment[0] * gap_z + d_moment[1] * rate_z + d_moment[2] * slip_z + d_moment[3] * rolling_z
                    + d_moment[4] * spin_z)
        cos_a, sin_a = (np.cos(q[3 * a + 2]), np.sin(q[3 * a + 2])) if a >= 0 else (1.0, 0.0)
        _, nx, ny, _, _ = pair_position(kind, a, b, pairs.anchor[k, 0], pairs.anchor[k, 1], pairs.direction[k, 0],
                                        pairs.direction[k, 1], pairs.radius_a[k], rb, q, cos_a, sin_a)
        tx, ty = -ny, nx
        kappa_z = np.zeros(12)
        kappa_z[:6] = kappa
        fx_z = nx * fn_z - ny * ft_z + (fn * tx - ft * nx) * kappa_z
        fy_z = ny * fn_z + nx * ft_z + (fn * ty - ft * ny) * kappa_z
        torque_b_z = -rb * ft_z + moment_z
        columns = np.array([3 * a, 3 * a + 1, 3 * a + 2, 3 * b, 3 * b + 1, 3 * b + 2])
        for j in range(12):
            column = columns[j % 6]
            if j % 6 < 3 and a < 0:
                continue
            target = force_position if j < 6 else force_velocity
            target[3 * b, column] += fx_z[j]
            target[3 * b + 1, column] += fy_z[j]
            target[3 * b + 2, column] += torque_b_z[j]
        if a >= 0:
            fx, fy = fn * nx - ft * ny, fn * ny + ft * nx
            cx, cy = q[3 * b] - rb * nx, q[3 * b + 1] - rb * ny
            arm_x, arm_y = cx - q[3 * a], cy - q[3 * a + 1]
            arm_x_z, arm_y_z = np.zeros(12), np.zeros(12)
            arm_x_z[:6], arm_y_z[:6] = c_x, c_y
            arm_x_z[0] -= 1.0
            arm_y_z[1] -= 1.0
            torque_a_z = -(arm_x_z * fy + arm_x * fy_z - arm_y_z * fx - arm_y * fx_z + moment_z)
            for j in range(12):
                target = force_position if j < 6 else force_velocity
                column = columns[j % 6]
                target[3 * a, column] -= fx_z[j]
                target[3 * a + 1, column] -= fy_z[j]
                target[3 * a + 2, column] += torque_a_z[j]


ELEMENT = ForceElement(name="pairs", item_type=ContactPair, parameters=PairArrays, pack=pack,
                       add_forces=add_forces, add_forces_twin=add_forces_twin, potential_energy=potential_energy,
                       add_jacobian=add_jacobian)
