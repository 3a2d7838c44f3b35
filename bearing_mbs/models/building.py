"""Pieces shared by the builders."""

from __future__ import annotations

import numpy as np

from bearing_mbs.contact import twin
from bearing_mbs.contact.normal import DAMPING_FACTOR
from bearing_mbs.core.scene import PairLaw, Scene
from bearing_mbs.elements import contact_pairs
from bearing_mbs.spec import ContactSpec, SpecError


def pair_law(contact: ContactSpec, stiffness: float | None = None, exponent: float | None = None,
             traction: tuple[float, ...] = ()) -> PairLaw:
    """Resolve a group's contact settings into the numbers the kernels read; ``stiffness`` and ``exponent``
    replace the given ones when a stiffness model derives them; ``traction`` is the lubricated-traction row of a
    group with ``friction_law = "ehl"``, which only a model that knows the contact geometry and the oil builds."""
    if contact.friction_law == "ehl" and not traction:
        raise SpecError("friction_law", "ehl", "lubricated traction is built for the raceways of the bearing model "
                        "only (it needs their line-contact geometry and the [lubricant] oil)")
    return PairLaw(
        normal_law=contact.normal_law,
        stiffness=contact.stiffness if stiffness is None else float(stiffness),
        exponent=contact.exponent if exponent is None else float(exponent),
        restitution=contact.restitution,
        damping_factor=float(DAMPING_FACTOR[contact.normal_law](contact.restitution)),
        approach_speed_floor=contact.approach_speed_floor,
        friction_law=contact.friction_law,
        friction_coefficient=contact.friction_coefficient,
        regularisation_speed=contact.regularisation_speed,
        rolling_resistance_arm=contact.rolling_resistance_arm,
        traction=tuple(traction),
    )


def initial_gaps(scene: Scene) -> np.ndarray:
    """Gap [m] of every pair at t = 0."""
    q, v = scene.initial_state()
    return twin.pair_geometry(contact_pairs.pack(scene.pairs), q, v)[0]


def reject_initial_overlap(scene: Scene, field_of_pair) -> None:
    """Raise a :class:`SpecError` for the first pair that penetrates at t = 0.

    ``field_of_pair(k)`` names the spec field to blame for pair k.
    """
    for k, gap in enumerate(initial_gaps(scene)):
        if gap < 0:
            pair = scene.pairs[k]
            raise SpecError(
                field_of_pair(k),
                gap,
                f"bodies overlap at the start: pair {pair.name!r} penetrates {-gap:.3g} m; start with a gap >= 0",
            )
