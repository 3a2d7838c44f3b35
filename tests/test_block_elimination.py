"""The reference engine's block elimination (engines/reference/block_elimination.py) against a dense solve.

Reference: numpy's LU (``np.linalg.solve``) of the same system written out densely here from its definition
(mass, stiffness on the coupled bodies' blocks, constraint rows; identity rows on fixed coordinates), to 1e-10 of
the solution, or 1e4 × the condition number × the rounding where that is larger (see the test). The structural
check: on a bearing's coupling graph the stored blocks grow linearly with the number of rollers (a dense
elimination grows with its square).
"""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from bearing_mbs.engines.reference.block_elimination import (
    assemble_constraints,
    block_system,
    factor,
    solve,
    subtract_stiffness,
)


def coupled_only(matrix, bodies, couplings):
    """``matrix`` (3N × 3N) with the blocks of bodies that no coupling joins set to zero, as a scene's ∂F/∂q."""
    mask = np.eye(bodies, dtype=bool)
    for a, b in couplings:
        mask[a, b] = mask[b, a] = True
    return matrix * np.kron(mask, np.ones((3, 3)))


def dense_matrix(bodies, constraints, inverse_mass, rows, stiffness):
    """The system of block_elimination's docstring, written out."""
    n, c = 3 * bodies, len(constraints)
    matrix = np.zeros((n + c, n + c))
    matrix[:n, :n] = -stiffness
    for k, (a, b) in enumerate(constraints):
        for side, body in enumerate((a, b)):
            matrix[n + k, 3 * body:3 * body + 3] = rows[k, 3 * side:3 * side + 3]
            matrix[3 * body:3 * body + 3, n + k] = -rows[k, 3 * side:3 * side + 3]
    for r in range(n):
        if inverse_mass[r] > 0:
            matrix[r, r] += 1 / inverse_mass[r]
        else:
            matrix[r, :] = 0.0
            matrix[r, r] = 1.0
    return matrix


@st.composite
def systems(draw):
    bodies = draw(st.integers(2, 9))
    pair = st.tuples(st.integers(0, bodies - 1), st.integers(0, bodies - 1)).filter(lambda p: p[0] != p[1])
    couplings = draw(st.lists(pair, max_size=2 * bodies))
    fixed = draw(st.lists(st.booleans(), min_size=bodies, max_size=bodies))
    # a constraint must move one of its bodies; a body is the constrained body b of one constraint at most (as in
    # every model: a roller in its pocket, case 5's distance)
    constraints = draw(st.lists(pair.filter(lambda p: not (fixed[p[0]] and fixed[p[1]])), max_size=bodies,
                                unique_by=lambda p: p[1]))
    seed = draw(st.integers(0, 2**32 - 1))
    return bodies, couplings, constraints, fixed, seed


@settings(max_examples=60, deadline=None)
@given(systems())
def test_block_elimination_solves_the_dense_system(system_case):
    bodies, couplings, constraints, fixed, seed = system_case
    rng = np.random.default_rng(seed)
    n = 3 * bodies
    inverse_mass = np.repeat(1 / rng.uniform(0.5, 5.0, bodies), 3) * np.repeat(~np.array(fixed), 3)
    stiffness = coupled_only(0.2 * rng.standard_normal((n, n)), bodies, couplings)
    damping = coupled_only(0.2 * rng.standard_normal((n, n)), bodies, couplings)
    rows = rng.uniform(0.5, 1.5, (len(constraints), 6)) * rng.choice([-1, 1], (len(constraints), 6))
    system = system_of(bodies, couplings, constraints, fixed)
    body_a = np.array([a for a, _ in constraints], dtype=np.int64)
    body_b = np.array([b for _, b in constraints], dtype=np.int64)
    assemble_constraints(system, inverse_mass, rows.reshape(-1, 6), body_a, body_b)
    subtract_stiffness(system, inverse_mass, stiffness, damping, 0.7, 0.3)
    factor(system)
    right_hand_side = rng.standard_normal(n + len(constraints))
    system.right_hand_side[:] = right_hand_side
    solve(system)

    matrix = dense_matrix(bodies, constraints, inverse_mass, rows.reshape(-1, 6), 0.7 * stiffness + 0.3 * damping)
    condition = np.linalg.cond(matrix)
    if condition > 1e6:  # a nearly singular draw says nothing about the elimination
        return
    expected = np.linalg.solve(matrix, right_hand_side)
    # a stable solve errs by about the condition number times the rounding, a wrong one by the solution's size;
    # without pivoting between blocks the error of a rare draw grows further (measured over 3000 draws: 99.9 %
    # within 2 × condition × rounding, the worst 1.9e3 ×)
    tolerance = max(1e-10, 1e4 * condition * np.finfo(float).eps)
    np.testing.assert_allclose(system.right_hand_side, expected, rtol=0, atol=tolerance * np.abs(expected).max())


def bearing_graph(rollers: int):
    """Inner ring 0, cage 1, fixed outer ring 2, rollers 3…: each roller touches both rings and its neighbours and
    is held by the cage."""
    roller = [3 + k for k in range(rollers)]
    couplings = [(r, ring) for r in roller for ring in (0, 2)]
    couplings += [(roller[k], roller[(k + 1) % rollers]) for k in range(rollers)] + [(1, 0)]
    constraints = [(1, r) for r in roller]
    return 3 + rollers, couplings, constraints, [False, False, True] + [False] * rollers


def system_of(bodies, couplings, constraints, fixed):
    return block_system(bodies, couplings, constraints, [0 if f else 3 for f in fixed])


def test_fill_grows_linearly_with_the_rollers():
    """Reference: a dense elimination stores (3Z + 9 + Z)² values; the arrow elimination ~Z (the hubs' block
    and each roller's few blocks). Doubling Z must double the storage to within 10 %."""
    sizes = {z: system_of(*bearing_graph(z)).values.size for z in (15, 30, 60)}
    assert sizes[60] / sizes[30] == pytest.approx(2.0, rel=0.1)
    assert sizes[30] / sizes[15] == pytest.approx(2.0, rel=0.1)
    assert sizes[60] < 0.2 * (4 * 60 + 9) ** 2


def test_a_bearing_system_solves_like_the_dense_one():
    """The bearing graph at Z = 30 with random values: the same check as the property test, on the structure it
    is for (ring of rollers, hubs, fixed ring, constraint cage)."""
    bodies, couplings, constraints, fixed = bearing_graph(30)
    rng = np.random.default_rng(3)
    n = 3 * bodies
    inverse_mass = np.repeat(1 / rng.uniform(0.5, 5.0, bodies), 3) * np.repeat(~np.array(fixed), 3)
    stiffness = coupled_only(rng.standard_normal((n, n)), bodies, couplings)
    rows = rng.uniform(0.5, 1.5, (len(constraints), 6))
    system = system_of(bodies, couplings, constraints, fixed)
    body_a = np.array([a for a, _ in constraints], dtype=np.int64)
    body_b = np.array([b for _, b in constraints], dtype=np.int64)
    assemble_constraints(system, inverse_mass, rows, body_a, body_b)
    subtract_stiffness(system, inverse_mass, stiffness, np.zeros((n, n)), 0.1, 0.0)
    factor(system)
    right_hand_side = rng.standard_normal(n + len(constraints))
    system.right_hand_side[:] = right_hand_side
    solve(system)
    expected = np.linalg.solve(dense_matrix(bodies, constraints, inverse_mass, rows, 0.1 * stiffness),
                               right_hand_side)
    np.testing.assert_allclose(system.right_hand_side, expected, rtol=0, atol=1e-10 * np.abs(expected).max())
