r"""Slewing-bearing geometry from the ball diameter and the design ratios of document 002 (eqs. 4–12).

The ratios are those of Heras' design "DP7" (the thesis's Table 1): :data:`DP7`. With D_w the ball diameter:

* groove radius R_c = D_w/(2s), s the conformity (eq. 4);
* G = R_Lg D_w/2 (6), T = R_L D_w − G (7), H = R_h D_w + H_g (8), H₁ = H/2 (9), H₂ = H/2 − H_g (10): the ring
  section's gap, width and heights [m];
* number of balls N = trunc(π D_pw / D_w) (eqs. 11–12): balls side by side on the pitch circle, no spacers.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

#: Heras' design ratios (the thesis's Table 1); H_g in m.
DP7 = {"R_h": 2.15, "H_g": 0.010, "R_L": 1.9, "R_Lg": 0.1, "R_Lt": 1.15, "R_Dt": 0.75, "R_Nh": 1.0}


def ball_count(pitch_diameter: float, ball_diameter: float) -> int:
    """N = trunc(π D_pw / D_w): the balls that fit side by side on the pitch circle (eqs. 11–12)."""
    return math.floor(math.pi * pitch_diameter / ball_diameter * (1 + 1e-12))


def groove_radius(ball_diameter: float, conformity: float) -> float:
    """R_c = D_w/(2s) [m] (eq. 4)."""
    return ball_diameter / (2 * conformity)


@dataclass(frozen=True)
class RingSection:
    """The ring section of eqs. 6–10 [m]: gap G, width T, height H and its parts H₁, H₂."""

    gap: float
    width: float
    height: float
    height_1: float
    height_2: float

    @classmethod
    def from_ratios(cls, ball_diameter: float, ratios: dict = DP7) -> RingSection:
        gap = ratios["R_Lg"] * ball_diameter / 2
        height = ratios["R_h"] * ball_diameter + ratios["H_g"]
        return cls(gap=gap, width=ratios["R_L"] * ball_diameter - gap, height=height, height_1=height / 2,
                   height_2=height / 2 - ratios["H_g"])
