r"""Four-point-contact slewing bearings as a force element: the balls' diagonals between a body and the ground.

The body's displacement from where it starts, in the bearing's axial plane (x: radial [m], y: axial [m], θ: tilt
[rad]), is the inner ring's (δ_r, δ_a, θ) of the quasi-static model
(:mod:`bearing_mbs.models.slewing_bearing.load_distribution`, where the equations are): ball j at azimuth
ψ_j = 2πj/N, diagonal d = ±1, centre separation s = A₀ e_d + (δ_r cos ψ_j, δ_a + θ R cos ψ_j), force
Q = K (|s| − A₀)^{3/2} along s when the centres have moved apart. The body receives −Σ Bᵀ Q ŝ, the force of the
potential Σ K δ^{5/2}/(5/2) (conservative), plus a stiffness-proportional damping −β K_t v with K_t the bearing's
tangent stiffness (dissipating β vᵀK_t v ≥ 0). The outer ring is the ground.

**Flexible rings** (:mod:`bearing_mbs.models.slewing_bearing.flexible` builds them): each ball's ring sectors have
coordinates η (m per ball) that move the diagonals' ends, s_d = A₀ e_d + B x + M_d η (``modes`` M, (2, 2, m)),
with the sectors' energy ½ ηᵀ K_η η (``sector`` K_η, m×m). The sectors are massless: at every evaluation each
ball's η minimises ½ ηᵀ K_η η + Σ_d K δ_d^{5/2}/(5/2) (convex; :func:`ball_state`, Newton's method), and the ball
acts on the inner ring with f = Σ_d Q_d ŝ_d and the tangent ∂f/∂w = Σ D_d − (Σ D_d M_d) H⁻¹ (Σ M_dᵀ D_d) at the
ball's rigid offset w = B x (H the Hessian in η, D_d = ∂(Qŝ)/∂s). The same function serves the quasi-static model
(:func:`flexible_bearing_state`) and the force element. With flexible rings the analytic Jacobian leaves out the
damping's change with the tangent (β ∂(K_t ẋ)/∂x): Newton's iterations converge a little slower, the solution
is the same.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import NamedTuple

import numba
import numpy as np

from bearing_mbs.contact.normal import elastic_energy
from bearing_mbs.core.force_element import ForceElement


@dataclass(frozen=True)
class SlewingBearingJoint:
    """A slewing bearing between the ground (its outer ring) and ``body`` (what its inner ring carries).

    balls N >= 1; pitch_radius R [m] > 0; centre_distance A₀ [m] > 0; contact_angle α₀ [rad]; stiffness K
    [N/m^1.5] of a diagonal; damping β [s] >= 0 (stiffness-proportional); reference (x, y, θ) [m, m, rad]: the
    body's position where the balls just touch.
    """

    name: str
    body: int
    balls: int
    pitch_radius: float
    centre_distance: float
    contact_angle: float
    stiffness: float
    damping: float
    reference: tuple[float, float, float]
    modes: np.ndarray | None = None
    sector: np.ndarray | None = None


class SlewingBearingArrays(NamedTuple):
    body: np.ndarray  # (J,) int64
    balls: np.ndarray  # (J,) int64
    pitch_radius: np.ndarray  # (J,) [m]
    centre_distance: np.ndarray  # (J,) [m]
    contact_angle: np.ndarray  # (J,) [rad]
    stiffness: np.ndarray  # (J,) [N/m^1.5]
    damping: np.ndarray  # (J,) [s]
    reference: np.ndarray  # (J, 3)
    flexible: np.ndarray  # (J,) bool: flexible rings
    modes: np.ndarray  # (J, 2, 2, m): M_d of each joint, zero-padded to the largest m (0 without flexible rings)
    sector: np.ndarray  # (J, m, m): K_η, identity on the padding (its coordinates feel no force and stay 0)


def pack(joints) -> SlewingBearingArrays:
    def column(get, dtype=float):
        return np.array([get(j) for j in joints], dtype=dtype)

    m = max((j.sector.shape[0] for j in joints if j.sector is not None), default=0)
    modes, sector = np.zeros((len(joints), 2, 2, m)), np.tile(np.eye(m), (len(joints), 1, 1))
    for n, joint in enumerate(joints):
        if joint.sector is not None:
            size = joint.sector.shape[0]
            modes[n, :, :, :size], sector[n, :size, :size] = joint.modes, joint.sector
    return SlewingBearingArrays(
        body=column(lambda j: j.body, np.int64), balls=column(lambda j: j.balls, np.int64),
        pitch_radius=column(lambda j: j.pitch_radius), centre_distance=column(lambda j: j.centre_distance),
        contact_angle=column(lambda j: j.contact_angle), stiffness=column(lambda j: j.stiffness),
        damping=column(lambda j: j.damping), reference=column(lambda j: j.reference).reshape(-1, 3),
        flexible=column(lambda j: j.sector is not None, np.bool_), modes=modes, sector=sector)


@numba.njit(cache=True, inline="always")
def diagonal(a0, alpha, r, c, d, radial, axial, tilt, k):
    """(s_r, s_z, |s|, load Q, slope Q′) of the diagonal d = ±1 of the ball at cos ψ = c, at the inner ring's
    displacement (radial, axial, tilt); Q = Q′ = 0 where the centres have not moved apart."""
    s_r = a0 * math.cos(alpha) + radial * c
    s_z = d * a0 * math.sin(alpha) + axial + tilt * r * c
    length = math.sqrt(s_r * s_r + s_z * s_z)
    approach = length - a0
    if approach <= 0.0:
        return s_r, s_z, length, 0.0, 0.0
    return s_r, s_z, length, k * approach**1.5, 1.5 * k * math.sqrt(approach)


#: Newton's method of :func:`ball_state`: converged when the gradient in η is below RELAX_TOLERANCE × the ball's
#: largest diagonal force (or 1 N), at most RELAX_ITERATIONS steps. A step is halved only where it raises the energy
#: by more than ENERGY_ROUND_OFF of it: the approach |s| − A₀ loses digits to cancellation (about 1e-12 of the energy
#: of a lightly loaded ball), and near the minimum a strict test would reject Newton's good steps.
RELAX_TOLERANCE = 1e-10
RELAX_ITERATIONS = 60
ENERGY_ROUND_OFF = 1e-9


@numba.njit(cache=True)
def _separations(a0, alpha, k, w_r, w_z, modes, eta, s, load, slope):
    """Fill s (2, 2), Q and Q′ (2,) of the ball's diagonals d = +1, −1 at rigid offset w and sector coordinates η;
    return their energy Σ K δ^{5/2}/(5/2) [J]."""
    energy = 0.0
    for n in range(2):
        offset_r, offset_z = w_r, w_z
        for i in range(eta.size):
            offset_r += modes[n, 0, i] * eta[i]
            offset_z += modes[n, 1, i] * eta[i]
        s[n, 0], s[n, 1], _, load[n], slope[n] = diagonal(a0, alpha, 0.0, 1.0, 1.0 - 2.0 * n, offset_r, offset_z,
                                                           0.0, k)
        if load[n] > 0.0:
            energy += load[n] * (load[n] / k) ** (2.0 / 3.0) / 2.5  # K δ^{5/2}/(5/2) with δ = (Q/K)^{2/3}
    return energy


@numba.njit(cache=True)
def _derivatives(s, load, slope, derivative):
    """D_d = ∂(Q ŝ)/∂s = Q′ ŝŝᵀ + (Q/|s|)(I − ŝŝᵀ) (2, 2, 2) of the two diagonals."""
    for n in range(2):
        length = math.sqrt(s[n, 0] ** 2 + s[n, 1] ** 2)
        for a in range(2):
            for b in range(2):
                derivative[n, a, b] = ((slope[n] - load[n] / length) * s[n, a] * s[n, b] / length**2
                                       + (load[n] / length if a == b else 0.0))


@numba.njit(cache=True)
def _quadratic(matrix, x):
    """½ xᵀ A x."""
    total = 0.0
    for i in range(x.size):
        for j in range(x.size):
            total += x[i] * matrix[i, j] * x[j]
    return 0.5 * total


@numba.njit(cache=True)
def _cholesky_solve(matrix, right):
    """Solve A X = B in place of B (m, r) for a small symmetric positive definite A (m, m), by Cholesky: loops, not
    LAPACK (the kernel is part of every compiled driver, and numba compiles LAPACK's bindings slowly)."""
    m = matrix.shape[0]
    lower = np.zeros((m, m))
    for i in range(m):
        for j in range(i + 1):
            total = matrix[i, j]
            for p in range(j):
                total -= lower[i, p] * lower[j, p]
            lower[i, j] = math.sqrt(total) if i == j else total / lower[j, j]
    for c in range(right.shape[1]):
        for i in range(m):
            total = right[i, c]
            for p in range(i):
                total -= lower[i, p] * right[p, c]
            right[i, c] = total / lower[i, i]
        for i in range(m - 1, -1, -1):
            total = right[i, c]
            for p in range(i + 1, m):
                total -= lower[p, i] * right[p, c]
            right[i, c] = total / lower[i, i]


@numba.njit(cache=True)
def _gradient_and_hessian(modes, sector, eta, load, s, derivative, gradient, hessian):
    """g = K_η η + Σ_d M_dᵀ Q_d ŝ_d and H = K_η + Σ_d M_dᵀ D_d M_d of the loaded diagonals."""
    m = eta.size
    for i in range(m):
        gradient[i] = 0.0
        for j in range(m):
            gradient[i] += sector[i, j] * eta[j]
            hessian[i, j] = sector[i, j]
    for n in range(2):
        if load[n] <= 0.0:
            continue
        length = math.sqrt(s[n, 0] ** 2 + s[n, 1] ** 2)
        for i in range(m):
            gradient[i] += load[n] * (modes[n, 0, i] * s[n, 0] + modes[n, 1, i] * s[n, 1]) / length
            for j in range(m):
                for a in range(2):
                    for b in range(2):
                        hessian[i, j] += modes[n, a, i] * derivative[n, a, b] * modes[n, b, j]


@numba.njit(cache=True)
def ball_state(a0, alpha, k, w_r, w_z, modes, sector, eta, force, tangent, load, s):
    """One ball at rigid offset w = (w_r, w_z) [m] (module docstring): relax its sector coordinates ``eta`` (m,) in
    place from their value (Newton's method on the convex energy, halving a step that raises it), and fill
    ``force`` f (2,) [N], ``tangent`` ∂f/∂w (2, 2) [N/m], the diagonals' ``load`` Q (2,) [N] and separations ``s``
    (2, 2) [m]. Returns (energy [J], converged). With m = 0 (rigid rings) no iteration."""
    m = eta.size
    slope = np.zeros(2)
    derivative = np.zeros((2, 2, 2))
    gradient, hessian, step, previous = np.zeros(m), np.zeros((m, m)), np.zeros((m, 1)), np.zeros(m)
    energy = _separations(a0, alpha, k, w_r, w_z, modes, eta, s, load, slope) + _quadratic(sector, eta)
    _derivatives(s, load, slope, derivative)
    converged = True
    for iteration in range(RELAX_ITERATIONS + 1 if m > 0 else 0):
        _gradient_and_hessian(modes, sector, eta, load, s, derivative, gradient, hessian)
        if np.abs(gradient).max() <= RELAX_TOLERANCE * max(load[0], load[1], 1.0):
            break
        if iteration == RELAX_ITERATIONS:
            converged = False
            break
        step[:, 0] = -gradient
        _cholesky_solve(hessian, step)
        previous[:] = eta
        factor = 1.0
        while True:
            eta[:] = previous + factor * step[:, 0]
            trial = _separations(a0, alpha, k, w_r, w_z, modes, eta, s, load, slope) + _quadratic(sector, eta)
            if trial <= energy + ENERGY_ROUND_OFF * abs(energy) or factor < 1e-6:
                energy = trial
                break
            factor *= 0.5
        _derivatives(s, load, slope, derivative)
    force[:] = 0.0
    tangent[:] = 0.0
    coupling = np.zeros((m, 2))  # (Σ D_d M_d)ᵀ
    for n in range(2):
        if load[n] <= 0.0:
            continue
        length = math.sqrt(s[n, 0] ** 2 + s[n, 1] ** 2)
        for a in range(2):
            force[a] += load[n] * s[n, a] / length
            for b in range(2):
                tangent[a, b] += derivative[n, a, b]
                for i in range(m):
                    coupling[i, a] += derivative[n, a, b] * modes[n, b, i]
    if m > 0:  # the Hessian is the last iterate's
        relief = coupling.copy()
        _cholesky_solve(hessian, relief)
        for a in range(2):
            for b in range(2):
                for i in range(m):
                    tangent[a, b] -= coupling[i, a] * relief[i, b]
    return energy, converged


@numba.njit(cache=True)
def flexible_bearing_state(balls, pitch_radius, a0, alpha, k, modes, sector, displacement, eta):
    """All balls at the inner ring's ``displacement`` (3,), their sector coordinates ``eta`` (N, m) relaxed in place:
    (load (3,) [N, N, N m], tangent (3, 3), loads Q (N, 2) [N], separations s (N, 2, 2) [m], energy [J], every ball
    converged). Ball j's offset is w = B x with B = [[c, 0, 0], [0, 1, R c]], c = cos ψ_j."""
    load = np.zeros(3)
    tangent = np.zeros((3, 3))
    loads = np.zeros((balls, 2))
    separations = np.zeros((balls, 2, 2))
    force, ball_tangent = np.zeros(2), np.zeros((2, 2))
    energy, converged = 0.0, True
    for n in range(balls):
        c = math.cos(2.0 * math.pi * n / balls)
        ball_energy, ok = ball_state(a0, alpha, k, displacement[0] * c,
                                     displacement[1] + displacement[2] * pitch_radius * c, modes, sector, eta[n],
                                     force, ball_tangent, loads[n], separations[n])
        energy += ball_energy
        converged = converged and ok
        rows = ((0, c), (1, 1.0), (1, pitch_radius * c))  # B's non-zero entry of each column: (row, value)
        for i in range(3):
            load[i] += rows[i][1] * force[rows[i][0]]
            for j in range(3):
                tangent[i, j] += rows[i][1] * ball_tangent[rows[i][0], rows[j][0]] * rows[j][1]
    return load, tangent, loads, separations, energy, converged


@numba.njit(cache=True, inline="always")
def add_forces(parameters, t, q, v, latched, forces, pair_out, power, complete):
    joints = parameters
    for j in range(joints.body.size):
        i = 3 * joints.body[j]
        radial = q[i] - joints.reference[j, 0]
        axial = q[i + 1] - joints.reference[j, 1]
        tilt = q[i + 2] - joints.reference[j, 2]
        a0, k, r = joints.centre_distance[j], joints.stiffness[j], joints.pitch_radius[j]
        alpha, beta, balls = joints.contact_angle[j], joints.damping[j], joints.balls[j]
        f0 = f1 = f2 = 0.0
        k00 = k01 = k02 = k11 = k12 = k22 = 0.0
        if joints.flexible[j]:
            load, tangent, _, _, _, _ = flexible_bearing_state(
                balls, r, a0, alpha, k, joints.modes[j], joints.sector[j], np.array([radial, axial, tilt]),
                np.zeros((balls, joints.sector.shape[1])))
            f0, f1, f2 = load[0], load[1], load[2]
            k00, k01, k02, k11, k12, k22 = (tangent[0, 0], tangent[0, 1], tangent[0, 2], tangent[1, 1],
                                            tangent[1, 2], tangent[2, 2])
            balls = 0  # the loop below is the rigid rings'
        for n in range(balls):
            c = math.cos(2.0 * math.pi * n / balls)
            for d in (1.0, -1.0):
                s_r, s_z, length, load, slope = diagonal(a0, alpha, r, c, d, radial, axial, tilt, k)
                if load <= 0.0:
                    continue
                u_r, u_z = s_r / length, s_z / length
                f0 += load * u_r * c
                f1 += load * u_z
                f2 += load * u_z * r * c
                if beta > 0.0:
                    tangent = load / length
                    d_rr = slope * u_r * u_r + tangent * (1.0 - u_r * u_r)
                    d_rz = (slope - tangent) * u_r * u_z
                    d_zz = slope * u_z * u_z + tangent * (1.0 - u_z * u_z)
                    k00 += d_rr * c * c
                    k01 += d_rz * c
                    k02 += d_rz * r * c * c
                    k11 += d_zz
                    k12 += d_zz * r * c
                    k22 += d_zz * r * r * c * c
        v0, v1, v2 = v[i], v[i + 1], v[i + 2]
        g0 = beta * (k00 * v0 + k01 * v1 + k02 * v2)
        g1 = beta * (k01 * v0 + k11 * v1 + k12 * v2)
        g2 = beta * (k02 * v0 + k12 * v1 + k22 * v2)
        forces[i] -= f0 + g0
        forces[i + 1] -= f1 + g1
        forces[i + 2] -= f2 + g2
        power[1] += g0 * v0 + g1 * v1 + g2 * v2


def centre_separations(balls: int, pitch_radius: float, centre_distance: float, contact_angle: float,
                       displacement) -> tuple[np.ndarray, np.ndarray]:
    """(s_r, s_z) [m], each (..., N, 2), of the diagonals d = +1, −1 (last axis) of every ball at the inner ring's
    ``displacement`` (..., 3) = (δ_r [m], δ_a [m], θ [rad]) (module docstring)."""
    x = np.asarray(displacement, dtype=float)[..., None, None, :]
    c = np.cos(2 * np.pi * np.arange(balls) / balls)[:, None]
    d = np.array([1.0, -1.0])
    s_r = centre_distance * np.cos(contact_angle) + x[..., 0] * c + 0 * d
    s_z = d * centre_distance * np.sin(contact_angle) + x[..., 1] + x[..., 2] * pitch_radius * c
    return s_r, s_z


def bearing_state(balls: int, pitch_radius: float, centre_distance: float, contact_angle: float, stiffness: float,
                  displacement) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """With numpy, at one ``displacement`` (3,): the bearing's load Σ Bᵀ Q ŝ (F_r [N], F_a [N], M [N m]), its
    tangent stiffness Σ Bᵀ (∂(Qŝ)/∂s) B (3×3, with ∂(Qŝ)/∂s = Q′ ŝŝᵀ + (Q/|s|)(I − ŝŝᵀ)), and per ball and diagonal
    (N, 2) the loads Q [N] and contact angles atan2(|s_z|, s_r) [rad]."""
    s_r, s_z = centre_separations(balls, pitch_radius, centre_distance, contact_angle, displacement)
    length = np.hypot(s_r, s_z)
    approach = np.maximum(length - centre_distance, 0.0)
    q = stiffness * approach**1.5
    slope = 1.5 * stiffness * np.sqrt(approach)
    unit = np.stack([s_r, s_z], axis=-1) / length[..., None]  # (N, 2 diagonals, 2 components)
    c = np.cos(2 * np.pi * np.arange(balls) / balls)
    b = np.zeros((balls, 2, 3))  # ∂s/∂x per ball: rows s_r, s_z
    b[:, 0, 0], b[:, 1, 1], b[:, 1, 2] = c, 1.0, pitch_radius * c
    load = np.einsum("nki,ndk->i", b, q[..., None] * unit)
    outer = np.einsum("ndk,ndl->ndkl", unit, unit)
    derivative = slope[..., None, None] * outer + (q / length)[..., None, None] * (np.eye(2) - outer)
    tangent = np.einsum("nki,ndkl,nlj->ij", b, derivative, b)
    return load, tangent, q, np.arctan2(np.abs(s_z), s_r)


def _flexible_state(joints, j, displacement):
    """(load, tangent, energy) of joint j with flexible rings at one displacement (3,) (:func:`ball_state`)."""
    load, tangent, _, _, energy, _ = flexible_bearing_state(
        joints.balls[j], joints.pitch_radius[j], joints.centre_distance[j], joints.contact_angle[j],
        joints.stiffness[j], joints.modes[j], joints.sector[j], np.asarray(displacement, dtype=float),
        np.zeros((joints.balls[j], joints.sector.shape[1])))
    return load, tangent, energy


def _state(joints, j, q):
    """Bearing load (3,) and tangent stiffness (3, 3) of joint j at positions q: with numpy for rigid rings, with
    the compiled :func:`ball_state` for flexible ones (no numpy twin of the sectors' relaxation)."""
    i = 3 * joints.body[j]
    if joints.flexible[j]:
        return _flexible_state(joints, j, q[i:i + 3] - joints.reference[j])[:2]
    load, tangent, _, _ = bearing_state(joints.balls[j], joints.pitch_radius[j], joints.centre_distance[j],
                                        joints.contact_angle[j], joints.stiffness[j], q[i:i + 3] - joints.reference[j])
    return load, tangent


def add_forces_twin(joints, t, q, v, latched, forces, pair_out, power, complete):
    for j in range(joints.body.size):
        i = 3 * joints.body[j]
        load, stiffness = _state(joints, j, q)
        damping = joints.damping[j] * stiffness @ v[i:i + 3]
        forces[i:i + 3] -= load + damping
        power[1] += damping @ v[i:i + 3]


def potential_energy(joints, position, pair_output):
    """Σ K δ^{5/2}/(5/2) over the balls' diagonals [J] at each output instant, plus the ring sectors' ½ ηᵀ K_η η
    with flexible rings."""
    energy = np.zeros(position.shape[0])
    for j in range(joints.body.size):
        i = 3 * joints.body[j]
        if joints.flexible[j]:  # the balls' and the ring sectors' energy
            energy += [_flexible_state(joints, j, x - joints.reference[j])[2] for x in position[:, i:i + 3]]
            continue
        s_r, s_z = centre_separations(joints.balls[j], joints.pitch_radius[j], joints.centre_distance[j],
                                      joints.contact_angle[j], position[:, i:i + 3] - joints.reference[j])
        gap = joints.centre_distance[j] - np.hypot(s_r, s_z)  # negative: the centres moved apart, a ball squeezed
        energy += elastic_energy(gap, joints.stiffness[j], 1.5).sum(axis=(1, 2))
    return energy


@numba.njit(cache=True, inline="always")
def add_jacobian(parameters, t, q, v, latched, pair_out, force_position, force_velocity):
    r"""With the body's force :math:`-(f + \beta K_t \dot x)`, f = Σ Bᵀ Q ŝ and :math:`K_t = \partial f/\partial x`:
    ∂F/∂v = −β K_t and ∂F/∂q = −K_t − β ∂(K_t ẋ)/∂x. Per diagonal the Hessian of its potential is
    :math:`H = a\,ŝŝ^T + b\,I` with a = Q′ − Q/|s|, b = Q/|s| (Q = Kδ^{3/2}, Q′ = 1.5Kδ^{1/2}), whose derivative
    along the separation's rate w = B ẋ is
    :math:`a'(ŝ\cdot w)ŝ\,ŝ^T + a[(ŝ\cdot w)(I - ŝŝ^T) + ŝ(w - (ŝ\cdot w)ŝ)^T]/|s| + b'\,w\,ŝ^T`
    (a′ = Q″ − Q′/|s| + Q/|s|², b′ = Q′/|s| − Q/|s|², Q″ = 0.75Kδ^{−1/2})."""
    joints = parameters
    for j in range(joints.body.size):
        i = 3 * joints.body[j]
        displacement = q[i:i + 3] - joints.reference[j]
        a0, k, r = joints.centre_distance[j], joints.stiffness[j], joints.pitch_radius[j]
        alpha, beta, balls = joints.contact_angle[j], joints.damping[j], joints.balls[j]
        rate = v[i:i + 3]
        tangent = np.zeros((3, 3))
        rate_term = np.zeros((3, 3))
        if joints.flexible[j]:  # the tangent of the relaxed sectors; the damping's rate term is left out
            _, tangent, _, _, _, _ = flexible_bearing_state(balls, r, a0, alpha, k, joints.modes[j], joints.sector[j],
                                                            displacement, np.zeros((balls, joints.sector.shape[1])))
            balls = 0
        for n in range(balls):
            c = math.cos(2.0 * math.pi * n / balls)
            b_matrix = np.array([[c, 0.0, 0.0], [0.0, 1.0, r * c]])
            for d in (1.0, -1.0):
                s_r, s_z, length, load, slope = diagonal(a0, alpha, r, c, d, displacement[0], displacement[1],
                                                         displacement[2], k)
                if load <= 0.0:
                    continue
                curvature = 1.125 * k * k / slope  # 0.75 K δ^(−1/2), with δ^(1/2) = Q′/1.5K
                unit = np.array([s_r / length, s_z / length])
                outer = np.outer(unit, unit)
                a_coef, b_coef = slope - load / length, load / length
                hessian = a_coef * outer + b_coef * np.eye(2)
                tangent += b_matrix.T @ hessian @ b_matrix
                if beta > 0.0:
                    w = b_matrix @ rate
                    along = unit @ w
                    a_slope = curvature - slope / length + load / length**2
                    b_slope = slope / length - load / length**2
                    change = (a_slope * along * outer
                              + a_coef * (along * (np.eye(2) - outer) + np.outer(unit, w - along * unit)) / length
                              + b_slope * np.outer(w, unit))
                    rate_term += b_matrix.T @ change @ b_matrix
        for row in range(3):
            for column in range(3):
                force_position[i + row, i + column] -= tangent[row, column] + beta * rate_term[row, column]
                force_velocity[i + row, i + column] -= beta * tangent[row, column]


ELEMENT = ForceElement(name="slewing_bearings", item_type=SlewingBearingJoint, parameters=SlewingBearingArrays,
                       pack=pack, add_forces=add_forces, add_forces_twin=add_forces_twin,
                       potential_energy=potential_energy, add_jacobian=add_jacobian)
