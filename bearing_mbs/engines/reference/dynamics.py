r"""The right-hand side of the equations of motion, the one place the compiled engine evaluates forces.

:math:`a = M^{-1} f(t, q, v) + g`, made consistent with the constraints (index-1 form, see
:mod:`bearing_mbs.engines.reference.constraints`).
"""

from __future__ import annotations

import numba

from bearing_mbs.elements import scene_forces
from bearing_mbs.engines.reference.constraints import add_constraint_accelerations


@numba.njit(cache=True, inline="always")
def accelerations(packed, t, q, v, latched, a, workspace, complete=False, constrained=True):
    """a = M⁻¹ f(t, q, v) + gravity [m/s², rad/s²], made consistent with the constraints; the generalized forces
    [N, N, N m], the pair outputs and the constraint forces [N] into ``workspace`` (its ``forces``, ``pair_out``,
    ``constraint_forces``; its ``constraint_system`` solves for the latter). Returns (supplied, dissipated) power
    [W]. ``complete``: also the velocity-level outputs of pairs apart (output instants only; see
    :func:`bearing_mbs.elements.scene_forces`). ``constrained=False``: leave the constraints out (generalized-α
    solves for their multipliers itself)."""
    forces = workspace.forces
    supplied, dissipated = scene_forces(packed, t, q, v, latched, forces, workspace.pair_out, complete)
    for i in range(q.size):
        a[i] = packed.inverse_mass[i] * forces[i] + packed.gravity[i]
    if constrained and packed.constraints.kind.size > 0:
        workspace.constraint_forces[:] = add_constraint_accelerations(packed.constraints, packed.inverse_mass, q, v,
                                                                      a, workspace.constraint_system)
    return supplied, dissipated
