"""``[contact.<group>]``: contact-law settings of one group of pairs (e.g. ball–wall, ball–ball)."""

from __future__ import annotations

from dataclasses import dataclass

from bearing_mbs.contact.friction import FRICTION_LAWS
from bearing_mbs.contact.normal import NORMAL_LAWS
from bearing_mbs.spec.fields import SpecError, in_range, non_negative, one_of, positive

STIFFNESS_MODELS = ("given", "palmgren", "document")
#: stiffness [N/m^n] and exponent [-] of ``stiffness_model = "given"`` when the file gives none.
GIVEN_DEFAULTS = {"stiffness": 6e6, "exponent": 1.5}


@dataclass(frozen=True)
class ContactSpec:
    """Normal law, friction law and rolling resistance of a group of contact pairs.

    normal_law: one of ``power``, ``lankarani_nikravesh``, ``hunt_crossley``, ``flores``, ``gonthier``.
    stiffness_model: ``given`` (use stiffness and exponent), ``palmgren`` (line contact of the bearing's
    contact length, n = 10/9, scaled by the pair's effective modulus) or ``document`` (the primary document's
    K δ^1.3 with K = 3e10 inner, 4e10 outer; raceways only). Only ``given`` applies to the balls model.
    stiffness: K [N/m^n] > 0 (default 6e6). exponent: n [-] in [1, 3] (default 1.5, Hertz point contact; 10/9
    Palmgren line contact). Both only with ``given``: the other models set them, and a value given with them is
    refused rather than ignored. restitution: e in (0, 1], mapped to damping by the law (ignored by ``power``).
    approach_speed_floor [m/s] > 0: lower bound of the latched approach speed (see
    :mod:`bearing_mbs.contact.normal`). friction_law: ``none``, ``erf``, ``tanh``, ``linear`` or
    ``dead_zone``. friction_coefficient: μ in [0, 2]. regularisation_speed: v_reg [m/s] > 0.
    rolling_resistance_arm: μ_R [m] >= 0, needs a friction law for its regularisation.
    """

    normal_law: str = "lankarani_nikravesh"
    stiffness_model: str = "given"
    stiffness: float | None = None
    exponent: float | None = None
    restitution: float = 0.9
    approach_speed_floor: float = 1e-3
    friction_law: str = "none"
    friction_coefficient: float = 0.0
    regularisation_speed: float = 1e-2
    rolling_resistance_arm: float = 0.0

    def __post_init__(self):
        one_of("normal_law", self.normal_law, NORMAL_LAWS)
        one_of("stiffness_model", self.stiffness_model, STIFFNESS_MODELS)
        if self.stiffness_model == "given":
            for name, default in GIVEN_DEFAULTS.items():
                if getattr(self, name) is None:
                    object.__setattr__(self, name, default)
            positive("stiffness", self.stiffness)
            in_range("exponent", self.exponent, 1.0, 3.0)
        else:
            for name in GIVEN_DEFAULTS:
                if getattr(self, name) is not None:
                    raise SpecError(name, getattr(self, name), f"is set by stiffness_model = "
                                    f"{self.stiffness_model!r}: remove it, or use stiffness_model = 'given'")
        in_range("restitution", self.restitution, 0.0, 1.0, low_open=True)
        positive("approach_speed_floor", self.approach_speed_floor)
        one_of("friction_law", self.friction_law, FRICTION_LAWS)
        in_range("friction_coefficient", self.friction_coefficient, 0.0, 2.0)
        positive("regularisation_speed", self.regularisation_speed)
        non_negative("rolling_resistance_arm", self.rolling_resistance_arm)
        if self.rolling_resistance_arm > 0 and self.friction_law == "none":
            raise SpecError(
                "rolling_resistance_arm", self.rolling_resistance_arm, "needs a friction_law other than none"
            )
