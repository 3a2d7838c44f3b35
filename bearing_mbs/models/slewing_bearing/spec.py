"""A ``slewing_bearing`` scenario: ``[scenario]`` (``model = "slewing_bearing"``), ``[slewing]`` and ``[load]``.

``bearing-mbs slewing`` solves it statically; ``bearing-mbs run`` simulates it when it has a ``[pitch]`` section (a
blade root carried by the bearing under a gusting tilting moment). ``rings = "flexible"`` puts the condensed
matrices of :mod:`.ring_stiffness` at every ball (:mod:`.flexible`), in the static solution and in the run.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from bearing_mbs.models.slewing_bearing.flexible import COUPLINGS
from bearing_mbs.models.slewing_bearing.ring_stiffness import COEFFICIENTS, MOUNTS
from bearing_mbs.spec import Spec
from bearing_mbs.spec.fields import finite, in_range, one_of, positive, require

#: The ``[scenario] model`` value of a slewing-bearing scenario.
MODEL_NAME = "slewing_bearing"


@dataclass(frozen=True)
class SlewingSection:
    """``[slewing]``: pitch_diameter D_pw [m] > 0; ball_diameter D_w [m] in (0, D_pw); conformity s = D_w/(2R_c) in
    (0.5, 1); contact_angle α₀ [deg] in (0, 90) (document 002 never states it; 45° is the usual value of
    four-point-contact slewing bearings); balls: optional, at most trunc(π D_pw/D_w) (checked by the bearing);
    youngs_modulus [Pa] and poisson_ratio of the steel rings and balls (document 002: 200 GPa, 0.3); rings
    ``rigid`` or ``flexible`` (the condensed sector matrices); of the flexible rings: mount ``fixed`` (both rings'
    bolted faces clamped, the inner ring's at the bottom and the outer ring's at the top: the document's
    validation) or ``free`` (nothing clamped), coupling ``structural`` (the rings' shared deformation only: the
    Hertz springs carry the contacts' local one) or ``full_matrix`` (the whole matrices in series with the Hertz
    springs: counts the local deformation twice), coefficients ``corrected`` or ``as_printed`` (as printed, the
    free rings carry the thesis's two errata and are not symmetric positive definite: refused with
    ``mount = "free"``)."""

    pitch_diameter: float
    ball_diameter: float
    conformity: float = 0.943
    contact_angle: float = 45.0
    balls: int | None = None
    youngs_modulus: float = 200e9
    poisson_ratio: float = 0.3
    rings: str = "rigid"
    mount: str = "fixed"
    coupling: str = "structural"
    coefficients: str = "corrected"

    def __post_init__(self):
        positive("pitch_diameter", self.pitch_diameter)
        positive("ball_diameter", self.ball_diameter)
        require(self.ball_diameter < self.pitch_diameter, "ball_diameter", self.ball_diameter,
                f"< pitch_diameter = {self.pitch_diameter:g} m: the inner raceway, D_pw − D_w cos α across, must "
                "keep a positive diameter at every contact angle")
        in_range("conformity", self.conformity, 0.5, 1.0, "-", low_open=True, high_open=True)
        in_range("contact_angle", self.contact_angle, 0.0, 90.0, "deg", low_open=True, high_open=True)
        positive("youngs_modulus", self.youngs_modulus)
        in_range("poisson_ratio", self.poisson_ratio, 0.0, 0.5, "-", high_open=True)
        if self.balls is not None:
            require(isinstance(self.balls, int) and self.balls >= 1, "balls", self.balls, "an integer >= 1")
        one_of("rings", self.rings, ("rigid", "flexible"))
        one_of("mount", self.mount, MOUNTS)
        one_of("coupling", self.coupling, COUPLINGS)
        one_of("coefficients", self.coefficients, COEFFICIENTS)
        require(not (self.coefficients == "as_printed" and self.mount == "free"), "coefficients", self.coefficients,
                "'corrected' with mount = 'free': the printed free-ring matrices have two errata and are not symmetric "
                "positive definite")


@dataclass(frozen=True)
class SlewingLoad:
    """``[load]`` on the inner ring (the outer ring held): axial [N], radial [N] (along x) and moment [N m]
    (about y), in any combination; or ``axial_displacements`` [m], a list of imposed axial displacements (radial
    shift and tilt held at zero) for a load–deflection curve, alone."""

    axial: float = 0.0
    radial: float = 0.0
    moment: float = 0.0
    axial_displacements: tuple[float, ...] = ()

    def __post_init__(self):
        for name in ("axial", "radial", "moment"):
            finite(name, getattr(self, name))
        for i, value in enumerate(self.axial_displacements):
            finite(f"axial_displacements.{i}", value)
        if self.axial_displacements:
            require(not (self.axial or self.radial or self.moment), "axial_displacements",
                    list(self.axial_displacements), "alone: an imposed displacement curve has no applied load")
        else:
            require(any((self.axial, self.radial, self.moment)), "load", None,
                    "an axial, radial or moment load, or axial_displacements")


@dataclass(frozen=True)
class PitchSection:
    """``[pitch]``: the blade root a pitch bearing carries, for ``bearing-mbs run``. blade_mass [kg] > 0 and
    blade_inertia [kg m²] > 0 (about the tilt axis) of the body on the inner ring; damping β [s] >= 0 of the
    bearing (stiffness-proportional); gust_amplitude [N m] and gust_period [s] > 0: the tilting moment is
    [load] moment + gust_amplitude · sin(2π t/gust_period); ramp_time [s] >= 0: every load rises from 0 along a
    half cosine over it."""

    blade_mass: float
    blade_inertia: float
    damping: float = 0.0
    gust_amplitude: float = 0.0
    gust_period: float = 1.0
    ramp_time: float = 0.0

    def __post_init__(self):
        positive("blade_mass", self.blade_mass)
        positive("blade_inertia", self.blade_inertia)
        for name in ("damping", "ramp_time"):
            in_range(name, getattr(self, name), 0.0, math.inf, "s")
        finite("gust_amplitude", self.gust_amplitude)
        positive("gust_period", self.gust_period)


@dataclass(frozen=True)
class SlewingSpec(Spec):
    """A ``slewing_bearing`` scenario."""

    slewing: SlewingSection | None = None
    load: SlewingLoad | None = None
    pitch: PitchSection | None = None

    def __post_init__(self):
        super().__post_init__()
        require(self.scenario.model == MODEL_NAME, "scenario.model", self.scenario.model, f"{MODEL_NAME!r}")
        require(self.slewing is not None, "slewing", None, "a [slewing] section")
        require(self.load is not None, "load", None, "a [load] section: axial, radial, moment or axial_displacements")
        if self.pitch is not None:
            require(not self.load.axial_displacements, "load.axial_displacements", list(self.load.axial_displacements),
                    "not with [pitch]: a run applies loads")

    @property
    def contact_angle_rad(self) -> float:
        return math.radians(self.slewing.contact_angle)
