"""One dispatch path for every force-element kind, built-in or registered: forces, Jacobians and numpy twins.

A packed scene's kinds (:attr:`~bearing_mbs.elements.assembly.PackedScene.elements`) are every registered kind
in registry order. :func:`follow_registry` writes, for the kinds registered now, three flat call sequences, one
call per kind in registry order, each passing the arguments that kind's form of the protocol takes
(:attr:`~bearing_mbs.core.force_element.ForceElement.force_arguments`: the contact pairs their per-pair state,
every other kind the short form):

* :data:`add_element_forces` — every kind's compiled ``add_forces`` (compiled, inlined into its callers);
* :data:`add_element_jacobians` — every kind's compiled ``add_jacobian``, for the kinds that have one;
* :data:`add_element_forces_twin` — every kind's numpy ``add_forces_twin`` (Python).

Numba cannot loop over a tuple of different types; a flat sequence of direct calls to inlined functions is
what it compiles fastest (a recursion over the tuple, an overload per kind or ``numba.literal_unroll`` each
compile every kind's function once more on its own). The compiled callers
(:func:`~bearing_mbs.elements.assembly.element_forces`, :func:`~bearing_mbs.elements.assembly.element_jacobian`)
read the sequences from this module when numba compiles them for a tuple of kinds, and a tuple's type names its
kinds, so each compiled copy holds the calls of the kinds it was compiled for. :func:`pack_scene
<bearing_mbs.elements.assembly.pack_scene>` calls :func:`follow_registry` first, so a kind registered from
outside is in the sequences before any scene with it is evaluated. A compiled copy keeps the functions it was
compiled with: a kind registered again with other functions but the same parameter type needs a new process.
With ``NUMBA_DISABLE_JIT=1`` the sequences are plain Python.
"""

from __future__ import annotations

from collections.abc import Callable

import numba

from bearing_mbs.elements.registry import FORCE_ELEMENTS

FORCES_SIGNATURE = ("elements", "t", "q", "v", "latched", "forces", "pair_out", "power", "complete")
JACOBIAN_SIGNATURE = ("elements", "t", "q", "v", "latched", "pair_out", "force_position", "force_velocity")


def flat_calls(name: str, signature: tuple[str, ...], calls: list[tuple]) -> Callable:
    """A Python function ``name(*signature)`` whose body is ``function(elements[i], *arguments)`` for each
    ``(function, i, arguments)`` of ``calls``, in order (``pass`` when there are none)."""
    namespace = {"__name__": __name__, **{f"kind_{j}": function for j, (function, _, _) in enumerate(calls)}}
    lines = [f"    kind_{j}(elements[{i}], {', '.join(arguments)})" for j, (_, i, arguments) in enumerate(calls)]
    source = f"def {name}({', '.join(signature)}):\n" + "\n".join(lines or ["    pass"]) + "\n"
    # the text is made here from the kinds' argument names alone; nothing in it comes from input
    exec(compile(source, f"<{__name__}.{name}: {len(calls)} kinds>", "exec"), namespace)  # noqa: S102
    return namespace[name]


def _sequences(kinds: tuple) -> tuple[Callable, Callable, Callable]:
    """The three call sequences (module docstring) for ``kinds`` in order."""
    forces = [(kind.add_forces, i, kind.force_arguments) for i, kind in enumerate(kinds)]
    jacobians = [(kind.add_jacobian, i, kind.jacobian_arguments) for i, kind in enumerate(kinds)
                 if kind.add_jacobian is not None]
    twins = [(kind.add_forces_twin, i, kind.force_arguments) for i, kind in enumerate(kinds)]
    inlined = numba.njit(inline="always")
    return (inlined(flat_calls("add_element_forces", FORCES_SIGNATURE, forces)),
            inlined(flat_calls("add_element_jacobians", JACOBIAN_SIGNATURE, jacobians)),
            flat_calls("add_element_forces_twin", FORCES_SIGNATURE, twins))


_followed: tuple = ()


def follow_registry() -> None:
    """Rewrite the call sequences if the registered kinds changed since they were last written."""
    global _followed, add_element_forces, add_element_jacobians, add_element_forces_twin
    kinds = tuple(FORCE_ELEMENTS.values())
    if len(kinds) == len(_followed) and all(a is b for a, b in zip(kinds, _followed)):
        return
    add_element_forces, add_element_jacobians, add_element_forces_twin = _sequences(kinds)
    _followed = kinds


add_element_forces: Callable
add_element_jacobians: Callable
add_element_forces_twin: Callable
follow_registry()
