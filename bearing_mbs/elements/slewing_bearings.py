r"""Four-point-contact slewing bearings as a force element: the balls' diagonals between a body and the ground.

The body's displacement from where it starts, in the bearing's axial plane (x: radial [m], y: axial [m], θ: tilt
[rad]), is the inner ring's (δ_r, δ_a, θ) of the quasi-static model
(:mod:`bearing_mbs.models.slewing_bearing.load_distribution`, where the equations are): ball j at azimuth
ψ_j = 2πj/N, diagonal d = ±1, centre separation s = A₀ e_d + (δ_r cos ψ_j, δ_a + θ R cos ψ_j), force
Q = K (|s| − A₀)^{3/2} along s when the centres have moved apart. The body receives −Σ Bᵀ Q ŝ, the force of the
potential Σ K δ^{5/2}/(5/2) (conservative), plus a stiffness-proportional damping −β K_t v with K_t the bearing's
tangent stiffness (dissipating β vᵀK_t v ≥ 0). The outer ring is the ground.

**Flexible rings**: each ball's ring sectors are relaxed at every evaluation (:mod:`.slewing_balls`). With
flexible rings the analytic Jacobian leaves out the damping's change with the tangent (β ∂(K_t ẋ)/∂x): Newton's
iterations converge a little slower, the solution is the same.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import NamedTuple

import numba
import numpy as np

from bearing_mbs.contact.normal import elastic_energy
from bearing_mbs.core.force_element import ForceElement
from bearing_mbs.elements.slewing_balls import diagonal, flexible_bearing_state


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


@numba.njit(cache=True)
def _flexible_joint(joints, j, displacement):
    """(load (3,), tangent (3, 3), energy [J]) of joint j with flexible rings at ``displacement`` (3,), every ball's
    sectors relaxed from η = 0 (:func:`.slewing_balls.flexible_bearing_state`). Compiled and not inlined: the
    force element calls it as the quasi-static twin does (inlined, it slowed every driver's step)."""
    load, tangent, _, _, energy, _ = flexible_bearing_state(
        joints.balls[j], joints.pitch_radius[j], joints.centre_distance[j], joints.contact_angle[j],
        joints.stiffness[j], joints.modes[j], joints.sector[j], displacement,
        np.zeros((joints.balls[j], joints.sector.shape[1])))
    return load, tangent, energy


@numba.njit(cache=True, inline="always")
def add_forces(parameters, t, q, v, forces, power):
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
            load, tangent, _ = _flexible_joint(joints, j, np.array([radial, axial, tilt]))
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


def _state(joints, j, q):
    """Bearing load (3,) and tangent stiffness (3, 3) of joint j at positions q: with numpy for rigid rings, with
    the compiled :func:`.slewing_balls.ball_state` for flexible ones (no numpy twin of the sectors' relaxation)."""
    i = 3 * joints.body[j]
    if joints.flexible[j]:
        return _flexible_joint(joints, j, q[i:i + 3] - joints.reference[j])[:2]
    load, tangent, _, _ = bearing_state(joints.balls[j], joints.pitch_radius[j], joints.centre_distance[j],
                                        joints.contact_angle[j], joints.stiffness[j], q[i:i + 3] - joints.reference[j])
    return load, tangent


def add_forces_twin(joints, t, q, v, forces, power):
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
            energy += [_flexible_joint(joints, j, x - joints.reference[j])[2] for x in position[:, i:i + 3]]
            continue
        s_r, s_z = centre_separations(joints.balls[j], joints.pitch_radius[j], joints.centre_distance[j],
                                      joints.contact_angle[j], position[:, i:i + 3] - joints.reference[j])
        gap = joints.centre_distance[j] - np.hypot(s_r, s_z)  # negative: the centres moved apart, a ball squeezed
        energy += elastic_energy(gap, joints.stiffness[j], 1.5).sum(axis=(1, 2))
    return energy


@numba.njit(cache=True, inline="always")
def add_jacobian(parameters, t, q, v, force_position, force_velocity):
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
            _, tangent, _ = _flexible_joint(joints, j, displacement)
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
