r"""One slewing bearing ball's two diagonals, with rigid rings or with its ring sectors relaxed (compiled).

Diagonal d = ±1 of a ball joins two raceway curvature centres across it: unloaded they are A₀ apart along
e_d = (cos α₀, d sin α₀) in the ball's (radial, axial) section; the inner ring's rigid offset w at the ball moves them
apart to s = A₀ e_d + w, and the diagonal carries Q = K (|s| − A₀)^{3/2} along s when |s| > A₀ (:func:`diagonal`).
With flexible rings (:mod:`bearing_mbs.models.slewing_bearing.flexible` builds them) each ball's ring sectors have
coordinates η (m per ball) that move the diagonals' ends, s_d = A₀ e_d + B x + M_d η (``modes`` M, (2, 2, m)),
with the sectors' energy ½ ηᵀ K_η η (``sector`` K_η, m×m). The sectors are massless: at every evaluation each
ball's η minimises ½ ηᵀ K_η η + Σ_d K δ_d^{5/2}/(5/2) (convex; :func:`ball_state`, Newton's method), and the ball
acts on the inner ring with f = Σ_d Q_d ŝ_d and the tangent ∂f/∂w = Σ D_d − (Σ D_d M_d) H⁻¹ (Σ M_dᵀ D_d) at the
ball's rigid offset w = B x (H the Hessian in η, D_d = ∂(Qŝ)/∂s). The same functions serve the quasi-static model
(:func:`flexible_bearing_state`) and the force element (:mod:`.slewing_bearings`).
"""

from __future__ import annotations

import math

import numba
import numpy as np


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
