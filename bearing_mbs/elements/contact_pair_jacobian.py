"""The analytic Jacobian of the contact pairs (:mod:`bearing_mbs.elements.contact_pairs`), for implicit integrators.

:func:`add_jacobian` adds ∂F/∂q and ∂F/∂v of every pair in contact or with an oil film, by the chain rule: the
laws' partial derivatives in the pair's gap, gap rate, slip, rolling speed and spin (:func:`_law_partials`,
:func:`_add_film_partials`) times those quantities' derivatives
(:func:`bearing_mbs.contact.pair_jacobian.pair_motion_jacobian`), and the turning normal and moving contact point
for the force's direction and arm. ``tests/test_jacobians.py`` holds it to finite differences.
"""

from __future__ import annotations

import numba
import numpy as np

from bearing_mbs.contact import kinematics, normal, traction
from bearing_mbs.contact.friction import FRICTION_LAWS
from bearing_mbs.contact.kernel import pair_position, regularised_sign, regularised_sign_slope
from bearing_mbs.contact.kinematics import ORIENTATION
from bearing_mbs.contact.pair_jacobian import pair_motion_jacobian
from bearing_mbs.fluid_film.cylinder_plane import film_force_slopes, film_forces

_EHL = FRICTION_LAWS.index("ehl")  # read by numba as a compile-time constant


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
            mu, mu_slip, mu_rolling, mu_load = traction.ehl_traction_slopes(row, slip, rolling, fn, boundary, vreg)
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
    return d_fn, d_ft, d_moment


@numba.njit(cache=True)
def _add_film_partials(pairs, k, gap, gap_rate, slip, rolling, poiseuille, d_fn, d_ft, d_moment):
    """Add the film's load, Couette shear and Poiseuille shear f_P (``poiseuille``, split as the rolling
    resistance's) to the partials over (gap, gap rate, slip, rolling speed, spin); below the floor the film does
    not see the gap."""
    length, viscosity, half_width, floor = pairs.film[k, 0], pairs.film[k, 1], pairs.film[k, 2], pairs.film[k, 3]
    rb, ra, orientation = pairs.radius_b[k], pairs.radius_a[k], ORIENTATION[pairs.kind[k]]
    film_gap = max(gap, floor)
    load, couette, shear = film_force_slopes(viscosity, rolling, slip, gap_rate, rb, length, half_width, film_gap)
    if gap < floor:
        load[0] = couette[0] = shear[0] = 0.0
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


@numba.njit(cache=True, inline="always")
def add_jacobian(parameters, t, q, v, latched, pair_out, force_position, force_velocity):
    r"""∂F/∂q and ∂F/∂v of the pairs in contact (and of those with a film), by the chain rule: the laws' partial
    derivatives in the pair's gap, gap rate, slip, rolling speed and spin (:func:`_law_partials`,
    :func:`_add_film_partials`) times those
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
        film = pairs.film[k, 0] > 0.0
        film_load = poiseuille = 0.0
        if film:
            film_load, _, poiseuille = film_forces(pairs.film[k, 1], rolling, slip, gap_rate, rb, pairs.film[k, 0],
                                                   pairs.film[k, 2], max(gap, pairs.film[k, 3]))
        # the contact's own normal force, which its friction law reads: less any film's load
        d_fn, d_ft, d_moment = _law_partials(pairs, k, fn - film_load, normal_gap, normal_rate, gap, gap_rate, slip,
                                             rolling, spin)
        if film:
            _add_film_partials(pairs, k, gap, gap_rate, slip, rolling, poiseuille, d_fn, d_ft, d_moment)
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
