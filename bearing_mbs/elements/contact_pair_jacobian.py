"""The analytic Jacobian of the contact pairs (:mod:`bearing_mbs.elements.contact_pairs`), for implicit integrators.

:func:`add_jacobian` adds ∂F/∂q and ∂F/∂v of every pair in contact or with an oil film, by the chain rule: the
laws' partial derivatives in the pair's gap, gap rate, slip, rolling speed and spin (:func:`_law_partials`,
:func:`_add_film_partials`) times those quantities' derivatives
(:func:`bearing_mbs.contact.pair_jacobian.pair_motion_derivatives`), and the turning normal and moving contact point
for the force's direction and arm. ``tests/test_jacobians.py`` holds it to finite differences.

It allocates its scratch once per evaluation, not per pair: the derivatives of a pair's kinematics (rows of
:data:`~bearing_mbs.contact.pair_jacobian.DERIVATIVE_ROWS`), the laws' partials (:data:`PARTIAL_ROWS`) and the
force's derivatives over (z, ż) (:data:`FORCE_ROWS`); a few small arrays per pair would cost more than the arithmetic
(the lubricated seed bearing's Jacobian took eight times its force evaluation when they did).
"""

from __future__ import annotations

import numba
import numpy as np

from bearing_mbs.contact import kinematics, normal, traction
from bearing_mbs.contact.friction import FRICTION_LAWS
from bearing_mbs.contact.kernel import pair_position, regularised_sign, regularised_sign_slope
from bearing_mbs.contact.kinematics import ORIENTATION
from bearing_mbs.contact.pair_jacobian import (
    DERIVATIVE_ROWS,
    GAP,
    GAP_RATE,
    KAPPA,
    LOCAL_COLUMNS,
    POINT_X,
    POINT_Y,
    ROLLING,
    SLIP,
    SPIN,
    pair_motion_derivatives,
)
from bearing_mbs.fluid_film.cylinder_plane import film_force_slopes, film_forces

_EHL = FRICTION_LAWS.index("ehl")  # read by numba as a compile-time constant
#: Rows of the laws' partials (5 columns: gap, gap rate, slip, rolling speed, spin): F_N, F_T, M.
NORMAL, TANGENTIAL, MOMENT = range(3)
PARTIAL_ROWS, PARTIAL_COLUMNS = 3, 5
#: Rows of the force's derivatives over (z, ż): F_N, F_T, M, then F_x, F_y and the torque on b.
FORCE_X, FORCE_Y, TORQUE_B = range(3, 6)
FORCE_ROWS = 6


@numba.njit(cache=True)
def _law_partials(law, coefficient, vreg, arm, row, orientation, ra, rb, fn, normal_gap, normal_rate, gap, slip,
                  rolling, spin, partials):
    """(∂F_N, ∂F_T, ∂M) over the pair's (gap, gap rate, slip, rolling speed, spin) of its contact law, into the rows
    :data:`NORMAL`, :data:`TANGENTIAL`, :data:`MOMENT` of ``partials`` (overwritten): the Coulomb family's
    F_T = −μ F_N φ(slip), or ``ehl``'s −μ(Δu, u, F_N) F_N with its hydrodynamic rolling resistance's force and
    couple; and the dry rolling arm's M = −μ_R F_N φ(r_b ω_rel). The pair's columns come one by one (law, μ,
    v_reg, the rolling arm, its traction row, orientation and radii): a call that passed the pairs' tuple would
    count references to each of its arrays."""
    d_fn = (normal_gap, normal_rate, 0.0, 0.0, 0.0)
    for i in range(PARTIAL_COLUMNS):
        partials[NORMAL, i] = d_fn[i]
        partials[TANGENTIAL, i] = 0.0
        partials[MOMENT, i] = 0.0
    if law == _EHL:
        if fn > 0.0:
            mu, mu_slip, mu_rolling, mu_load = traction.ehl_traction_slopes(row, slip, rolling, fn, coefficient, vreg)
            for i in range(PARTIAL_COLUMNS):
                partials[TANGENTIAL, i] = -(mu + fn * mu_load) * d_fn[i]
            partials[TANGENTIAL, 2] -= fn * mu_slip
            partials[TANGENTIAL, 3] -= fn * mu_rolling
            force, force_rolling, force_load = traction.signed_rolling_force_slopes(row, rolling, fn, vreg)
            if force != 0.0 or force_rolling != 0.0:
                share = kinematics.contact_point_share(orientation, ra, rb, gap)
                distance = ra + orientation * (rb + gap)
                share_gap = -rb / distance**2 if orientation != 0 else 0.0
                for i in range(PARTIAL_COLUMNS):
                    d_force = force_load * d_fn[i]
                    if i == 3:
                        d_force += force_rolling
                    partials[TANGENTIAL, i] += (0.5 - share) * d_force
                    partials[MOMENT, i] += (1.0 - share) * rb * d_force
                partials[TANGENTIAL, 0] -= force * share_gap
                partials[MOMENT, 0] -= rb * force * share_gap
    else:
        sign, slope = regularised_sign(law, slip, vreg), regularised_sign_slope(law, slip, vreg)
        for i in range(PARTIAL_COLUMNS):
            partials[TANGENTIAL, i] = -coefficient * (sign * d_fn[i])
        partials[TANGENTIAL, 2] -= coefficient * fn * slope
    if arm > 0.0:
        spin_sign = regularised_sign(law, spin * rb, vreg)
        for i in range(PARTIAL_COLUMNS):
            partials[MOMENT, i] -= arm * spin_sign * d_fn[i]
        partials[MOMENT, 4] -= arm * fn * regularised_sign_slope(law, spin * rb, vreg) * rb


@numba.njit(cache=True)
def _add_film_partials(film, orientation, ra, rb, gap, gap_rate, slip, rolling, poiseuille, partials):
    """Add the film's load, Couette shear and Poiseuille shear f_P (``poiseuille``, split as the rolling
    resistance's) to the partials over (gap, gap rate, slip, rolling speed, spin) in ``partials``; below the floor
    the film does not see the gap. ``film``: the pair's film row (length, viscosity, half-width, floor)."""
    length, viscosity, half_width, floor = film[0], film[1], film[2], film[3]
    film_gap = max(gap, floor)
    load, couette, shear = film_force_slopes(viscosity, rolling, slip, gap_rate, rb, length, half_width, film_gap)
    below = gap < floor  # the gap's column is 0 there
    share = kinematics.contact_point_share(orientation, ra, rb, gap)
    share_gap = -rb / (ra + orientation * (rb + gap)) ** 2 if orientation != 0 else 0.0
    # (h, ḣ, u, Δu) → (gap, gap rate, slip, rolling, spin)
    d_load = (0.0 if below else load[0], load[1], load[3], load[2], 0.0)
    d_shear = (0.0 if below else shear[0], shear[1], shear[3], shear[2], 0.0)
    d_couette = (0.0 if below else couette[0], couette[1], couette[3], couette[2], 0.0)
    for i in range(PARTIAL_COLUMNS):
        partials[NORMAL, i] += d_load[i]
        partials[TANGENTIAL, i] += d_couette[i] + (0.5 - share) * d_shear[i]
        partials[MOMENT, i] += (1.0 - share) * rb * d_shear[i]
    if orientation != 0.0:  # on a line the reaction does not move with the gap (and f_P is not given)
        partials[TANGENTIAL, 0] -= poiseuille * share_gap
        partials[MOMENT, 0] -= rb * poiseuille * share_gap


@numba.njit(cache=True, inline="always")
def add_jacobian(parameters, t, q, v, latched, pair_out, force_position, force_velocity):
    r"""∂F/∂q and ∂F/∂v of the pairs in contact (and of those with a film), by the chain rule: the laws' partial
    derivatives in the pair's gap, gap rate, slip, rolling speed and spin (:func:`_law_partials`,
    :func:`_add_film_partials`) times those
    quantities' derivatives (:func:`bearing_mbs.contact.pair_jacobian.pair_motion_derivatives`), and the turning of
    the normal and the moving contact point for the force's direction and arm. The force on b is
    :math:`F = F_N n + F_T t` at c, its torque :math:`-r_b F_T + M`; a receives −F at c and :math:`-(c - c_a)\times F
    - M`."""
    pairs = parameters
    motion = np.empty((DERIVATIVE_ROWS, LOCAL_COLUMNS))
    partials = np.empty((PARTIAL_ROWS, PARTIAL_COLUMNS))
    force_z = np.empty((FORCE_ROWS, LOCAL_COLUMNS))
    for k in range(pairs.kind.size):
        gap, gap_rate, slip, fn, ft, moment, _, rolling = pair_out[k]
        if not (gap < 0.0 or pairs.film[k, 0] > 0.0):
            continue
        a, b, kind, rb = pairs.body_a[k], pairs.body_b[k], pairs.kind[k], pairs.radius_b[k]
        pair_motion_derivatives(kind, a, b, pairs.anchor[k, 0], pairs.anchor[k, 1], pairs.direction[k, 0],
                                pairs.direction[k, 1], rb, q, v, motion)
        spin = v[3 * b + 2] - (v[3 * a + 2] if a >= 0 else 0.0)
        normal_gap = normal_rate = 0.0
        if gap < 0.0:
            normal_gap, normal_rate = normal.hysteresis_force_slopes(
                gap, gap_rate, pairs.stiffness[k], pairs.exponent[k], pairs.damping_factor[k], latched[k],
                pairs.approach_speed_floor[k])
        film = pairs.film[k, 0] > 0.0
        orientation, ra = ORIENTATION[kind], pairs.radius_a[k]
        # the contact's own normal force, which its friction law reads: the film's load taken off, 0 apart (where
        # the force is the film's alone); the film's Poiseuille shear, which moves its reaction on a curved surface
        contact, poiseuille = (fn if gap < 0.0 else 0.0), 0.0
        if film and (gap < 0.0 or orientation != 0.0):  # the force pass's values, not kept: evaluated again
            film_load, _, poiseuille = film_forces(pairs.film[k, 1], rolling, slip, gap_rate, rb, pairs.film[k, 0],
                                                   pairs.film[k, 2], max(gap, pairs.film[k, 3]))
            if gap < 0.0:
                contact = fn - film_load
        _law_partials(pairs.friction_law[k], pairs.friction_coefficient[k], pairs.regularisation_speed[k],
                      pairs.rolling_resistance_arm[k], pairs.traction[k], orientation, ra, rb, contact,
                      normal_gap, normal_rate, gap, slip, rolling, spin, partials)
        if film:
            _add_film_partials(pairs.film[k], orientation, ra, rb, gap, gap_rate, slip, rolling, poiseuille, partials)
        cos_a, sin_a = (np.cos(q[3 * a + 2]), np.sin(q[3 * a + 2])) if a >= 0 else (1.0, 0.0)
        _, nx, ny, _, _ = pair_position(kind, a, b, pairs.anchor[k, 0], pairs.anchor[k, 1], pairs.direction[k, 0],
                                        pairs.direction[k, 1], ra, rb, q, cos_a, sin_a)
        tx, ty = -ny, nx
        turn_x, turn_y = fn * tx - ft * nx, fn * ty - ft * ny
        # over (z, ż): F_N, F_T, M from the five quantities' derivatives, then F_x, F_y and the torque on b
        for j in range(LOCAL_COLUMNS):
            kappa = motion[KAPPA, j]  # 0 over ż
            for row in range(PARTIAL_ROWS):
                force_z[row, j] = (partials[row, 0] * motion[GAP, j] + partials[row, 1] * motion[GAP_RATE, j]
                                   + partials[row, 2] * motion[SLIP, j] + partials[row, 3] * motion[ROLLING, j]
                                   + partials[row, 4] * motion[SPIN, j])
            force_z[FORCE_X, j] = nx * force_z[NORMAL, j] - ny * force_z[TANGENTIAL, j] + turn_x * kappa
            force_z[FORCE_Y, j] = ny * force_z[NORMAL, j] + nx * force_z[TANGENTIAL, j] + turn_y * kappa
            force_z[TORQUE_B, j] = -rb * force_z[TANGENTIAL, j] + force_z[MOMENT, j]
        for j in range(LOCAL_COLUMNS):
            local = j % 6
            if local < 3 and a < 0:
                continue
            column = 3 * (a if local < 3 else b) + local % 3
            target = force_position if j < 6 else force_velocity
            target[3 * b, column] += force_z[FORCE_X, j]
            target[3 * b + 1, column] += force_z[FORCE_Y, j]
            target[3 * b + 2, column] += force_z[TORQUE_B, j]
        if a >= 0:
            fx, fy = fn * nx - ft * ny, fn * ny + ft * nx
            cx, cy = q[3 * b] - rb * nx, q[3 * b + 1] - rb * ny
            arm_x, arm_y = cx - q[3 * a], cy - q[3 * a + 1]
            for j in range(LOCAL_COLUMNS):
                arm_x_z = arm_y_z = 0.0
                if j < 6:
                    arm_x_z, arm_y_z = motion[POINT_X, j], motion[POINT_Y, j]
                    if j == 0:
                        arm_x_z -= 1.0
                    elif j == 1:
                        arm_y_z -= 1.0
                fx_z, fy_z = force_z[FORCE_X, j], force_z[FORCE_Y, j]
                torque_a_z = -(arm_x_z * fy + arm_x * fy_z - arm_y_z * fx - arm_y * fx_z + force_z[MOMENT, j])
                target = force_position if j < 6 else force_velocity
                column = 3 * (a if j % 6 < 3 else b) + j % 3
                target[3 * a, column] -= fx_z
                target[3 * a + 1, column] -= fy_z
                target[3 * a + 2, column] += torque_a_z
