r"""The reference engine's linear systems, solved by eliminating the bodies one block at a time.

The constraint accelerations, the constraint projections and generalized-α's Newton step all solve

.. math::
    \begin{bmatrix} M - \tilde K & -G^T \\ G & 0 \end{bmatrix}
    \begin{bmatrix} x \\ \mu \end{bmatrix} = \begin{bmatrix} b \\ c \end{bmatrix}

where M is the diagonal mass matrix, :math:`\tilde K = \beta'\,\partial F/\partial q + \gamma'\,\partial F/\partial v`
(zero in the constraint systems) and G the constraints' Jacobian; the row of a fixed coordinate (zero inverse
mass) is :math:`x_i = b_i`. Every force element and constraint couples at most two bodies, so the matrix is sparse
in blocks of bodies. Body p's block holds its three coordinates and the multipliers of the constraints it owns (those
whose constrained body b it is). A bearing's rollers couple with the rings and the cage, and a roller with its
neighbours: an arrow with a ring in it. The bodies are eliminated in minimum-degree order, rollers first and hubs
last, which keeps the fill, and so the cost, linear in the number of rollers, where a dense LU is cubic.

:func:`block_system` finds the order and the fill once per scene (Python); the compiled functions fill the blocks
(:func:`assemble_constraints`, :func:`subtract_stiffness`), factor them (:func:`factor`: block LU, Gauss–Jordan with
partial pivoting within each diagonal block, none between blocks) and solve (:func:`solve`), with no allocation.
The diagonal blocks are a body's mass plus β′ times its contact stiffness, bordered by the rows of its
constraints; every constraint kind moves its body b (∂g/∂c_b ≠ 0), so they are invertible. Without pivoting
between blocks the error can grow beyond a pivoted LU's on indefinite systems: on random ones (tests) 99.9 % solve
within 2 × condition number × rounding, the worst within 2e3 ×; the mass-dominated systems of a bearing solve as
accurately as a dense LU. (scipy's sparse LU cannot be called from the compiled driver.)
"""

from __future__ import annotations

from typing import NamedTuple

import numba
import numpy as np

#: Coordinates per body (x, y, θ).
DOF = 3


class BlockSystem(NamedTuple):
    """A system in body blocks, its elimination order and storage. Unknowns: the n coordinates, then the C
    multipliers.

    ``order``: bodies in elimination order; ``member_start``/``members``: each body's unknowns (its coordinates,
    then n + k for each constraint k it owns); ``later_start``/``later``: the bodies coupled to each body (fill
    included) that are eliminated after it; ``offset`` (B × B): where block (i, j) starts in ``values`` (row-major,
    size_i × size_j), −1 where i and j do not couple; ``owner``: each constraint's body, ``slot``: its
    multiplier's place in its owner's block; ``right_hand_side`` (n + C), ``permuted`` (the same, block by
    block), ``pivot`` and ``scratch`` (a block's size and its square): scratch."""

    order: np.ndarray
    member_start: np.ndarray
    members: np.ndarray
    later_start: np.ndarray
    later: np.ndarray
    offset: np.ndarray
    values: np.ndarray
    owner: np.ndarray
    slot: np.ndarray
    right_hand_side: np.ndarray
    permuted: np.ndarray
    pivot: np.ndarray
    scratch: np.ndarray


def owners(constraint_bodies, free_counts) -> list[int]:
    """A body for each constraint, (a, b), b if it can: no body owns more constraints than it has free coordinates
    (``free_counts``), else its diagonal block would be singular. A bipartite matching by augmenting paths (Kuhn);
    a constraint that cannot be placed (the constraints are redundant) goes to its b."""
    owner = [-1] * len(constraint_bodies)
    owned = [[] for _ in free_counts]

    def place(k, visited):
        for body in reversed(constraint_bodies[k]):  # b first
            if body in visited or body < 0:
                continue
            visited.add(body)
            if len(owned[body]) < free_counts[body]:
                owned[body].append(k)
                owner[k] = body
                return True
            for other in owned[body]:  # move one of its constraints to that constraint's other body
                if place(other, visited):
                    owned[body].remove(other)
                    owned[body].append(k)
                    owner[k] = body
                    return True
        return False

    for k, (a, b) in enumerate(constraint_bodies):
        if not place(k, set()):
            owner[k] = b
    return owner


def block_system(body_count: int, couplings, constraint_bodies, free_counts) -> BlockSystem:
    """The elimination of a system whose bodies couple as ``couplings`` (pairs of body indices; ground, −1, and a
    body with itself are ignored) and ``constraint_bodies`` ((a, b) per constraint), with ``free_counts`` free
    coordinates per body; each constraint's multiplier joins the block of its body by :func:`owners`."""
    constraint_bodies = [(int(a), int(b)) for a, b in constraint_bodies]
    owner = np.array(owners(constraint_bodies, free_counts), dtype=np.int64)
    neighbours = [set() for _ in range(body_count)]
    for a, b in [*couplings, *constraint_bodies]:
        if a >= 0 and b >= 0 and a != b:
            neighbours[a].add(b)
            neighbours[b].add(a)
    order, later, remaining = [], [], set(range(body_count))
    while remaining:  # minimum degree, ties to the lowest index; the eliminated body's neighbours become a clique
        body = min(remaining, key=lambda p: (len(neighbours[p]), p))
        remaining.discard(body)
        coupled = sorted(neighbours[body])
        order.append(body)
        later.append(coupled)
        for i in coupled:
            neighbours[i].discard(body)
            neighbours[i].update(j for j in coupled if j != i)
    later_of = dict(zip(order, later))
    n = DOF * body_count
    members = [[DOF * p + d for d in range(DOF)] for p in range(body_count)]
    for k, p in enumerate(owner):
        members[p].append(n + k)
    size = [len(m) for m in members]
    offset = np.full((body_count, body_count), -1, dtype=np.int64)
    total = 0
    for p in order:
        for i, j in [(p, p), *((p, i) for i in later_of[p]), *((i, p) for i in later_of[p])]:
            offset[i, j] = total
            total += size[i] * size[j]
    return BlockSystem(
        order=np.array(order, dtype=np.int64),
        member_start=np.cumsum([0, *size]).astype(np.int64),
        members=np.array([u for m in members for u in m], dtype=np.int64),
        later_start=np.cumsum([0, *(len(later_of[p]) for p in range(body_count))]).astype(np.int64),
        later=np.array([i for p in range(body_count) for i in later_of[p]], dtype=np.int64),
        offset=offset,
        values=np.zeros(total),
        owner=owner,
        slot=np.array([members[p].index(n + k) for k, p in enumerate(owner)], dtype=np.int64),
        right_hand_side=np.zeros(n + len(constraint_bodies)),
        permuted=np.zeros(n + len(constraint_bodies)),
        pivot=np.zeros(max(size, default=DOF), dtype=np.int64),
        scratch=np.zeros(max(size, default=DOF) ** 2),
    )


@numba.njit(cache=True, inline="always")
def _size(system, p):
    return system.member_start[p + 1] - system.member_start[p]


@numba.njit(cache=True, inline="always")
def assemble_constraints(system, inverse_mass, rows, body_a, body_b):
    """Fill the blocks with the mass (identity on fixed coordinates) and the constraints' G, compact in ``rows``
    (C × 6: the columns of a's coordinates, then b's; see :func:`~bearing_mbs.engines.reference.constraints.
    constraint_rows`), erasing what was there. Block (i, j) is row-major at ``offset[i, j]``."""
    values = system.values
    values[:] = 0.0
    for p in range(system.offset.shape[0]):
        start, size = system.offset[p, p], _size(system, p)
        for d in range(DOF):
            w = inverse_mass[DOF * p + d]
            values[start + d * size + d] = 1.0 / w if w > 0.0 else 1.0
    for k in range(system.owner.size):
        owner, local = system.owner[k], system.slot[k]
        owner_size = _size(system, owner)
        for side in range(2):
            body = body_a[k] if side == 0 else body_b[k]
            row_block, column_block = system.offset[body, owner], system.offset[owner, body]
            body_size = _size(system, body)
            for d in range(DOF):
                g = rows[k, DOF * side + d]
                if inverse_mass[DOF * body + d] > 0.0:  # a fixed coordinate's row is x = b
                    values[row_block + d * owner_size + local] = -g
                values[column_block + local * body_size + d] = g


@numba.njit(cache=True, inline="always")
def _subtract_block(system, i, j, inverse_mass, force_position, force_velocity, slope_q, slope_v):
    start, columns = system.offset[i, j], _size(system, j)
    for r in range(DOF):
        row = DOF * i + r
        if inverse_mass[row] > 0.0:  # a fixed coordinate's row is x = b
            for c in range(DOF):
                column = DOF * j + c
                system.values[start + r * columns + c] -= (slope_q * force_position[row, column]
                                                           + slope_v * force_velocity[row, column])


@numba.njit(cache=True)
def subtract_stiffness(system, inverse_mass, force_position, force_velocity, slope_q, slope_v):
    """Subtract K̃ = slope_q ∂F/∂q + slope_v ∂F/∂v (dense n × n) from the free coordinates' rows of the blocks
    that couple (K̃ is zero elsewhere: no element couples those bodies)."""
    for p in system.order:
        _subtract_block(system, p, p, inverse_mass, force_position, force_velocity, slope_q, slope_v)
        for a in range(system.later_start[p], system.later_start[p + 1]):
            i = system.later[a]
            _subtract_block(system, p, i, inverse_mass, force_position, force_velocity, slope_q, slope_v)
            _subtract_block(system, i, p, inverse_mass, force_position, force_velocity, slope_q, slope_v)


@numba.njit(cache=True, error_model="numpy")  # a zero pivot gives inf, not an exception
def _invert(values, start, size, pivot):
    """Invert the square block of ``size`` at ``start`` of ``values`` in place: Gauss–Jordan with partial
    pivoting. A singular block gives inf/NaN, which the callers' Newton test or run guards catch."""
    for k in range(size):
        best = k
        for i in range(k + 1, size):
            if abs(values[start + i * size + k]) > abs(values[start + best * size + k]):
                best = i
        pivot[k] = best
        if best != k:
            for j in range(size):
                a, b = start + k * size + j, start + best * size + j
                values[a], values[b] = values[b], values[a]
        row = start + k * size
        inverse_pivot = 1.0 / values[row + k]
        values[row + k] = 1.0
        for j in range(size):
            values[row + j] *= inverse_pivot
        for i in range(size):
            if i != k:
                other = start + i * size
                factor = values[other + k]
                values[other + k] = 0.0
                for j in range(size):
                    values[other + j] -= factor * values[row + j]
    for k in range(size - 1, -1, -1):  # undo the row swaps as column swaps
        if pivot[k] != k:
            for i in range(size):
                a, b = start + i * size + k, start + i * size + pivot[k]
                values[a], values[b] = values[b], values[a]


@numba.njit(cache=True)
def factor(system):
    """Block LU in place: each diagonal block becomes its (Schur-updated) inverse D⁻¹, each block (i, p) below it
    L_ip = A_ip D⁻¹; the blocks (p, j) above stay."""
    values, scratch = system.values, system.scratch
    for p in system.order:
        diagonal, size = system.offset[p, p], _size(system, p)
        _invert(values, diagonal, size, system.pivot)
        for a in range(system.later_start[p], system.later_start[p + 1]):
            i = system.later[a]
            below, rows = system.offset[i, p], _size(system, i)
            for m in range(rows * size):
                scratch[m] = 0.0
            for r in range(rows):  # L_ip = A_ip D⁻¹ through the scratch, by rows: the blocks are mostly zeros
                for m in range(size):
                    entry = values[below + r * size + m]
                    if entry != 0.0:
                        for c in range(size):
                            scratch[r * size + c] += entry * values[diagonal + m * size + c]
            for m in range(rows * size):
                values[below + m] = scratch[m]
            for b in range(system.later_start[p], system.later_start[p + 1]):  # A_ij −= L_ip A_pj
                j = system.later[b]
                above, target, columns = system.offset[p, j], system.offset[i, j], _size(system, j)
                for m in range(size):
                    for c in range(columns):
                        entry = values[above + m * columns + c]
                        if entry != 0.0:
                            for r in range(rows):
                                values[target + r * columns + c] -= values[below + r * size + m] * entry


@numba.njit(cache=True)
def solve(system):
    """Solve the factored system for ``system.right_hand_side``, in place (the unknowns replace it)."""
    start, values, y = system.member_start, system.values, system.permuted
    for k in range(y.size):  # block by block: body p's unknowns at start[p] … start[p + 1]
        y[k] = system.right_hand_side[system.members[k]]
    for p in system.order:  # forward: b_i −= L_ip b_p
        size = start[p + 1] - start[p]
        for a in range(system.later_start[p], system.later_start[p + 1]):
            i = system.later[a]
            below = system.offset[i, p]
            for r in range(start[i + 1] - start[i]):
                total = 0.0
                for m in range(size):
                    total += values[below + r * size + m] * y[start[p] + m]
                y[start[i] + r] -= total
    residual = system.scratch
    for back in range(system.order.size - 1, -1, -1):  # backward: x_p = D⁻¹ (b_p − Σ A_pj x_j)
        p = system.order[back]
        size = start[p + 1] - start[p]
        for r in range(size):
            residual[r] = y[start[p] + r]
        for a in range(system.later_start[p], system.later_start[p + 1]):
            j = system.later[a]
            above, columns = system.offset[p, j], start[j + 1] - start[j]
            for r in range(size):
                total = 0.0
                for m in range(columns):
                    total += values[above + r * columns + m] * y[start[j] + m]
                residual[r] -= total
        diagonal = system.offset[p, p]
        for r in range(size):
            total = 0.0
            for m in range(size):
                total += values[diagonal + r * size + m] * residual[m]
            y[start[p] + r] = total
    for k in range(y.size):
        system.right_hand_side[system.members[k]] = y[k]
