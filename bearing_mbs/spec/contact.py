"""``[contact.<group>]``: contact-law settings of one group of pairs (e.g. ball–wall, ball–ball)."""

from __future__ import annotations

from dataclasses import dataclass

from bearing_mbs.contact.ehl import FILM_FORMULAS
from bearing_mbs.contact.friction import FRICTION_LAWS
from bearing_mbs.contact.normal import NORMAL_LAWS
from bearing_mbs.contact.traction import TRACTION_MODELS
from bearing_mbs.spec.fields import SpecError, in_range, non_negative, one_of, positive, require

STIFFNESS_MODELS = ("given", "palmgren", "document")
#: stiffness [N/m^n] and exponent [-] of ``stiffness_model = "given"`` when the file gives none.
GIVEN_DEFAULTS = {"stiffness": 6e6, "exponent": 1.5}


@dataclass(frozen=True)
class ContactSpec:
    """Normal law, friction law and rolling resistance of a group of contact pairs.

    normal_law: one of ``power``, ``lankarani_nikravesh``, ``hunt_crossley``, ``flores``, ``gonthier``.
    stiffness_model: ``given`` (use stiffness and exponent), ``palmgren`` (line contact of the bearing's
    contact length, n = 10/9, scaled by the pair's contact modulus E*) or ``document`` (the primary document's
    K δ^1.3 with K = 3e10 inner, 4e10 outer; raceways only). Only ``given`` applies to the balls model.
    stiffness: K [N/m^n] > 0 (default 6e6). exponent: n [-] in [1, 3] (default 1.5, Hertz point contact; 10/9
    Palmgren line contact). Both only with ``given``: the other models set them, and a value given with them is
    refused rather than ignored. restitution: e in (0, 1], mapped to damping by the law (ignored by ``power``).
    approach_speed_floor [m/s] > 0: lower bound of the latched approach speed (see
    :mod:`bearing_mbs.contact.normal`). friction_law: ``none``, ``erf``, ``tanh``, ``linear`` or
    ``dead_zone``. friction_coefficient: μ in [0, 2]. regularisation_speed: v_reg [m/s] > 0.
    rolling_resistance_arm: μ_R [m] >= 0, needs a friction law for its regularisation.

    Lubricated traction (``friction_law = "ehl"``, :mod:`bearing_mbs.contact.traction`; the oil comes from the
    model's ``[lubricant]``): friction_coefficient is then the boundary coefficient μ_b and regularisation_speed
    its v_reg (also the floor of the entrainment speed). traction_model: ``eyring`` (default) or ``curve``.
    film_formula: ``pan_hamrock`` (default) or ``dowson_higginson``. thermal_reduction: Murch–Wilson's inlet
    heating (default true). roughness: composite rms roughness σ [m] in [1e-9, 1e-5] (default 0.2e-6, ground
    raceways and rollers). eyring_stress τ0 [Pa] in [1e5, 1e8] (default 5e6), shear_modulus G [Pa] in [1e6, 1e10]
    (default 1e8), limiting_shear_coefficient Λ_L in [0.01, 0.2] (default 0.07): the ``eyring`` model.
    traction_curve: (A, B, C, D) of the ``curve`` model, with B > 0, C > 0 and |A + D| <= 1e-3 (no jump at zero
    slip); required by it. ehl_rolling_resistance: the contact's hydrodynamic rolling resistance (Zhou–Hoeprich's,
    Martin's rigid one at light load: :func:`bearing_mbs.contact.ehl.rolling_force`), added to the dry arm's
    (default false; ``ehl`` only). shear_heating: the film's shear heating reduces the ``eyring`` model's viscous
    stress (the Couette film's Nahme reduction, :mod:`bearing_mbs.contact.shear_heating`; default false, ``ehl``
    with ``eyring`` only).
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
    traction_model: str = "eyring"
    film_formula: str = "pan_hamrock"
    thermal_reduction: bool = True
    roughness: float = 0.2e-6
    eyring_stress: float = 5e6
    shear_modulus: float = 1e8
    limiting_shear_coefficient: float = 0.07
    traction_curve: tuple[float, ...] | None = None
    ehl_rolling_resistance: bool = False
    shear_heating: bool = False

    def __post_init__(self):
        one_of("normal_law", self.normal_law, NORMAL_LAWS)
        one_of("stiffness_model", self.stiffness_model, STIFFNESS_MODELS)
        if self.stiffness_model == "given":
            for name, default in GIVEN_DEFAULTS.items():
                if getattr(self, name) is None:
                    object.__setattr__(self, name, default)
            positive("stiffness", self.stiffness)
            in_range("exponent", self.exponent, 1.0, 3.0, "-")
        else:
            for name in GIVEN_DEFAULTS:
                if getattr(self, name) is not None:
                    raise SpecError(name, getattr(self, name), f"is set by stiffness_model = "
                                    f"{self.stiffness_model!r}: remove it, or use stiffness_model = 'given'")
        in_range("restitution", self.restitution, 0.0, 1.0, "-", low_open=True)
        positive("approach_speed_floor", self.approach_speed_floor)
        one_of("friction_law", self.friction_law, FRICTION_LAWS)
        in_range("friction_coefficient", self.friction_coefficient, 0.0, 2.0, "-")
        positive("regularisation_speed", self.regularisation_speed)
        non_negative("rolling_resistance_arm", self.rolling_resistance_arm)
        if self.rolling_resistance_arm > 0 and self.friction_law == "none":
            raise SpecError(
                "rolling_resistance_arm", self.rolling_resistance_arm, "needs a friction_law other than none"
            )
        one_of("traction_model", self.traction_model, TRACTION_MODELS)
        one_of("film_formula", self.film_formula, FILM_FORMULAS)
        require(isinstance(self.thermal_reduction, bool), "thermal_reduction", self.thermal_reduction,
                "must be true or false")
        in_range("roughness", self.roughness, 1e-9, 1e-5, "m")
        in_range("eyring_stress", self.eyring_stress, 1e5, 1e8, "Pa")
        in_range("shear_modulus", self.shear_modulus, 1e6, 1e10, "Pa")
        in_range("limiting_shear_coefficient", self.limiting_shear_coefficient, 0.01, 0.2, "-")
        if self.traction_curve is not None:
            curve = tuple(self.traction_curve)
            require(len(curve) == 4 and all(isinstance(c, (int, float)) for c in curve), "traction_curve", curve,
                    "must be four numbers (A, B, C, D)")
            a, b, c, d = curve
            require(b > 0 and c > 0, "traction_curve", curve, "needs B > 0 and C > 0")
            require(abs(a + d) <= 1e-3, "traction_curve", curve, "needs |A + D| <= 1e-3 (no jump at zero slip)")
            object.__setattr__(self, "traction_curve", tuple(float(x) for x in curve))
        require(isinstance(self.ehl_rolling_resistance, bool), "ehl_rolling_resistance", self.ehl_rolling_resistance,
                "must be true or false")
        if self.ehl_rolling_resistance:
            require(self.friction_law == "ehl", "ehl_rolling_resistance", True,
                    f"needs friction_law = 'ehl' (the film it comes from), not {self.friction_law!r}")
        require(isinstance(self.shear_heating, bool), "shear_heating", self.shear_heating, "must be true or false")
        if self.shear_heating:
            require(self.friction_law == "ehl" and self.traction_model == "eyring", "shear_heating", True,
                    "needs friction_law = 'ehl' with traction_model = 'eyring' (the film's viscous stress it "
                    f"reduces), not {self.friction_law!r} with {self.traction_model!r}")
        if self.friction_law == "ehl" and self.traction_model == "curve":
            require(self.traction_curve is not None, "traction_curve", None,
                    "the curve traction model needs (A, B, C, D)")
