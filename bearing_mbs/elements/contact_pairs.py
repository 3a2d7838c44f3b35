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

Their analytic Jacobian, :func:`~bearing_mbs.elements.contact_pair_jacobian.add_jacobian`, is in its own module.
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
    rolling_resistance,
    tangential_force,
)
from bearing_mbs.contact.kinematics import ORIENTATION, PAIR_KINDS
from bearing_mbs.contact.traction import N_TRACTION_COLUMNS
from bearing_mbs.contact.twin import pair_geometry
from bearing_mbs.contact.twin import regularised_sign as regularised_sign_twin
from bearing_mbs.core.force_element import ForceElement
from bearing_mbs.core.scene import FILM_COLUMNS, ContactPair
from bearing_mbs.elements.contact_pair_jacobian import add_jacobian
from bearing_mbs.fluid_film.cylinder_plane import film_forces

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


ELEMENT = ForceElement(name="pairs", item_type=ContactPair, parameters=PairArrays, pack=pack,
                       add_forces=add_forces, add_forces_twin=add_forces_twin, potential_energy=potential_energy,
                       add_jacobian=add_jacobian, pair_state=True)
