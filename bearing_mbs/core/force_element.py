"""The force-element protocol and its registry (in the spirit of Drake's ``ForceElement``).

A force element is one kind of scene item that applies forces to bodies: contact pairs, time-profile loads,
velocity servos, viscous drags, or a kind a user registers. Each kind is one module that provides the
:class:`ForceElement` record below, and both engines evaluate every kind through one dispatch
(:mod:`bearing_mbs.elements.dispatch`): adding a kind touches no engine.

The contract of the evaluation functions (compiled and numpy twin alike)::

    add_forces(parameters, t, q, v, forces, power) -> None

* ``parameters`` — the kind's items packed into arrays (a ``NamedTuple`` of numpy arrays, from ``pack``);
* ``t`` [s], ``q`` (3N,) positions (x, y, θ per body), ``v`` (3N,) velocities;
* ``forces`` (3N,) — generalized forces [N, N, N m], to be **added to**;
* ``power`` (2,) — running totals [W] to be **added to**: ``power[0]`` the power the kind supplies (loads,
  drives), ``power[1]`` the power it dissipates (friction, damping, drag). A conservative force supplies and
  dissipates nothing here: its work is the change of the kind's ``potential_energy``, which closes the audit.

Each kind takes the state it needs and no more. The contact pairs (``pair_state=True``) also carry per-pair
state and outputs, and take the long form::

    add_forces(parameters, t, q, v, latched, forces, pair_out, power, complete) -> None

* ``latched`` (P,), ``pair_out`` (P, k) — the pairs' latched approach speeds and their outputs (written);
* ``complete`` — False inside integration stages: the pairs may skip outputs that no force needs.

The compiled function is called from the integrators' one compiled function of the forces: decorate it
``numba.njit(inline="always")`` (with ``cache=True`` inside the package) so that it is inlined there, and then
assign every local variable on every path before it is read (numba's inliner refuses a variable that may be
undefined).

A kind may also give its forces' derivatives, for implicit integrators (compiled, same conventions)::

    add_jacobian(parameters, t, q, v, force_position, force_velocity) -> None
    add_jacobian(parameters, t, q, v, latched, pair_out, force_position, force_velocity) -> None  # pair_state

* ``force_position`` (3N, 3N) ∂F/∂q and ``force_velocity`` (3N, 3N) ∂F/∂v, to be **added to**, at (t, q, v);
* for the pairs, with ``latched`` held fixed (as a Newton iteration of an implicit step holds it) and
  ``pair_out`` the outputs that ``add_forces`` wrote at the same (t, q, v), complete (read only).

The implicit methods of both engines use it wherever every kind of a scene has one; a scene with a kind without
one is differentiated numerically by the engines.

Body index −1 is the ground. All quantities are SI.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np

from bearing_mbs.core.registry import Registry

#: The arguments of the two forms of ``add_forces`` and ``add_jacobian`` after ``parameters`` (module docstring).
FORCE_ARGUMENTS = ("t", "q", "v", "forces", "power")
FORCE_ARGUMENTS_WITH_PAIR_STATE = ("t", "q", "v", "latched", "forces", "pair_out", "power", "complete")
JACOBIAN_ARGUMENTS = ("t", "q", "v", "force_position", "force_velocity")
JACOBIAN_ARGUMENTS_WITH_PAIR_STATE = ("t", "q", "v", "latched", "pair_out", "force_position", "force_velocity")


def no_potential_energy(parameters, position: np.ndarray, pair_output: np.ndarray) -> None:
    """For kinds whose work is counted as supplied or dissipated power: they store no energy."""
    return


@dataclass(frozen=True)
class ForceElement:
    """One kind of force element.

    * ``name`` — plural noun used in scene counts and reports (``"drags"``);
    * ``item_type`` — the frozen dataclass of one item in :attr:`bearing_mbs.core.scene.Scene.forces`, with a
      ``body`` or ``body_a``/``body_b`` index and a ``name``;
    * ``parameters`` — the ``NamedTuple`` class that ``pack`` returns (it identifies the kind in compiled code);
    * ``pack(items) -> parameters`` — the items as arrays;
    * ``add_forces`` — the compiled (numba ``njit``) evaluation, contract in the module docstring;
    * ``add_forces_twin`` — its readable numpy twin, same contract, held to the compiled one by the tests;
    * ``potential_energy(parameters, position, pair_output) -> (T,) array | None`` — the energy the kind
      stores [J] at each output instant, from the result's positions (T, 3N) and pair outputs (T, P, k);
    * ``add_jacobian`` — the compiled derivatives of its forces (module docstring), or None;
    * ``pair_state`` — True for the contact pairs alone: their functions take the per-pair state (``latched``,
      ``pair_out``) and ``complete`` (the long form in the module docstring).
    """

    name: str
    item_type: type
    parameters: type
    pack: Callable[[Sequence[Any]], Any]
    add_forces: Callable
    add_forces_twin: Callable
    potential_energy: Callable = no_potential_energy
    add_jacobian: Callable | None = None
    pair_state: bool = False

    @property
    def force_arguments(self) -> tuple[str, ...]:
        """The names of the arguments ``add_forces`` and ``add_forces_twin`` take after ``parameters``."""
        return FORCE_ARGUMENTS_WITH_PAIR_STATE if self.pair_state else FORCE_ARGUMENTS

    @property
    def jacobian_arguments(self) -> tuple[str, ...]:
        """The names of the arguments ``add_jacobian`` takes after ``parameters``."""
        return JACOBIAN_ARGUMENTS_WITH_PAIR_STATE if self.pair_state else JACOBIAN_ARGUMENTS


class ForceElementRegistry(Registry[ForceElement]):
    """Force-element kinds in evaluation order, by name. :meth:`register` adds a kind from outside the package;
    the order of registration is the order of evaluation (and so of floating-point accumulation). A kind's name,
    item type and parameter type are each its own."""

    def clashes(self, element: ForceElement, other: ForceElement) -> bool:
        return (other.name == element.name or other.item_type is element.item_type
                or other.parameters is element.parameters)

    def of_item(self, item) -> ForceElement:
        for element in self.values():
            if isinstance(item, element.item_type):
                return element
        raise TypeError(f"{type(item).__name__} is not a registered force element; registered: "
                        f"{', '.join(e.item_type.__name__ for e in self.values())}")

    def of_parameters(self, parameters_type: type) -> ForceElement:
        for element in self.values():
            if element.parameters is parameters_type:
                return element
        raise TypeError(f"no registered force element packs {parameters_type.__name__}")
