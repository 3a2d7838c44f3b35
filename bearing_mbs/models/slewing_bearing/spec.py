"""A ``slewing_bearing`` scenario: ``[scenario]`` (``model = "slewing_bearing"``), ``[slewing]`` and ``[load]``.

So far the static command reads it (``bearing-mbs slewing``); rigid rings only. Flexible rings (the condensed
matrices of :mod:`.ring_stiffness` assembled around the ring) and the multibody force element are to come, so
the keys for them are not accepted yet.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from bearing_mbs.spec import Spec
from bearing_mbs.spec.fields import finite, in_range, positive, require

#: The ``[scenario] model`` value of a slewing-bearing scenario.
MODEL_NAME = "slewing_bearing"


@dataclass(frozen=True)
class SlewingSection:
    """``[slewing]``: pitch_diameter D_pw [m] > 0; ball_diameter D_w [m] > 0; conformity s = D_w/(2R_c) in
    (0.5, 1); contact_angle α₀ [deg] in (0, 90) (document 002 never states it; 45° is the usual value of
    four-point-contact slewing bearings); balls: optional, at most trunc(π D_pw/D_w) (checked by the bearing);
    youngs_modulus [Pa] and poisson_ratio of the steel rings and balls (document 002: 200 GPa, 0.3)."""

    pitch_diameter: float
    ball_diameter: float
    conformity: float = 0.943
    contact_angle: float = 45.0
    balls: int | None = None
    youngs_modulus: float = 200e9
    poisson_ratio: float = 0.3

    def __post_init__(self):
        positive("pitch_diameter", self.pitch_diameter)
        positive("ball_diameter", self.ball_diameter)
        in_range("conformity", self.conformity, 0.5, 1.0, low_open=True, high_open=True)
        in_range("contact_angle", self.contact_angle, 0.0, 90.0, low_open=True, high_open=True)
        positive("youngs_modulus", self.youngs_modulus)
        in_range("poisson_ratio", self.poisson_ratio, 0.0, 0.5, high_open=True)
        if self.balls is not None:
            require(isinstance(self.balls, int) and self.balls >= 1, "balls", self.balls, "an integer >= 1")


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
class SlewingSpec(Spec):
    """A ``slewing_bearing`` scenario."""

    slewing: SlewingSection | None = None
    load: SlewingLoad | None = None

    def __post_init__(self):
        super().__post_init__()
        require(self.scenario.model == MODEL_NAME, "scenario.model", self.scenario.model, f"{MODEL_NAME!r}")
        require(self.slewing is not None, "slewing", None, "a [slewing] section")
        require(self.load is not None, "load", None, "a [load] section: axial, radial, moment or axial_displacements")

    @property
    def contact_angle_rad(self) -> float:
        return math.radians(self.slewing.contact_angle)
