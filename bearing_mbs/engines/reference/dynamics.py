r"""The right-hand side of the equations of motion, the one place the compiled engine evaluates forces.

:math:`a = M^{-1} f(t, q, v) + g`, made consistent with the constraints (index-1 form, see
:mod:`bearing_mbs.engines.reference.constraints`).
"""

from __future__ import annotations

import numba
import numpy as np

from bearing_mbs.elements import element_forces
from bearing_mbs.engines.reference.constraints import add_constraint_accelerations
from bearing_mbs.engines.reference.copies import copy_into

#: The values of :func:`accelerations`' flags for compiled callers: numpy booleans, which numba types as plain
#: booleans, where it would compile a separate copy of the function for each literal ``True`` or ``False``.
PARTIAL, COMPLETE = np.False_, np.True_
UNCONSTRAINED, CONSTRAINED = np.False_, np.True_


@numba.njit(cache=True)
def accelerations(packed, t, q, v, latched, a, workspace, complete, constrained):
    """a = M⁻¹ f(t, q, v) + gravity [m/s², rad/s²], made consistent with the constraints; the generalized forces
    [N, N, N m], the pair outputs and the constraint forces [N] into ``workspace`` (its ``forces``, ``pair_out``,
    ``constraint_forces``; its ``constraint_system`` solves for the latter). Returns (supplied, dissipated) power
    [W]. ``complete`` (:data:`COMPLETE`): also the velocity-level outputs of pairs apart (output instants only;
    see :func:`bearing_mbs.elements.element_forces`). ``constrained`` (:data:`CONSTRAINED`), else leave the
    constraints out (generalized-α solves for their multipliers itself).

    The reference engine's one compiled copy of the forces (every force element's function is inlined here), not
    inlined into its callers: it compiles once per scene type and serves every method and the Python side. Its
    callers pass it bundles they received as arguments themselves, so that the call counts no references (see
    :mod:`bearing_mbs.engines.reference.integrators`).
    """
    forces = workspace.forces
    supplied, dissipated = element_forces(packed.elements, t, q, v, latched, forces, workspace.pair_out, complete)
    for i in range(q.size):
        a[i] = packed.inverse_mass[i] * forces[i] + packed.gravity[i]
    if constrained and packed.constraints.kind.size > 0:
        copy_into(workspace.constraint_forces, add_constraint_accelerations(packed.constraints, packed.inverse_mass, q,
                                                                            v, a, workspace.constraint_system))
    return supplied, dissipated
