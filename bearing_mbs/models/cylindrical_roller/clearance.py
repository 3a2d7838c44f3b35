r"""The operating diametral clearance of a mounted, running cylindrical roller bearing: its internal clearance
group less what the inner ring's interference fit and the rings' temperature difference take up.

* **Internal clearance before mounting**: the groups of ISO 5753-1:2009 for cylindrical roller bearings with a
  cylindrical bore (:data:`ISO_5753_1_CYLINDRICAL`, µm by bore; the values as catalogues reproduce them, e.g. SKF's
  rolling bearings catalogue). Group 3 (C3) is the usual choice where the inner ring is warmer than the outer, as in
  a gearbox's high-speed shaft.
* **Fit**: an inner ring of bore d and raceway diameter F pressed with diametral interference I on a solid shaft of
  the same steel (Lamé's thick cylinders: the contact pressure :math:`p = E I (F^2 - d^2)/(2 d F^2)`, the ring's outer
  radial displacement :math:`2 p d^2 F/(2 E (F^2 - d^2))`) grows at its raceway by :math:`I\,d/F`
  (:func:`fit_reduction`; the outer ring, stationary in a housing with a loose or transition fit, is taken
  unchanged).
* **Temperature**: an inner ring ΔT warmer than the outer (5–10 K in running machines, as SKF's catalogue says in
  choosing an internal clearance) grows against it by
  :math:`\alpha\,\Delta T\,D_{pw}` (:func:`thermal_reduction`: the raceways and rollers taken at the pitch
  diameter, the rollers at the mean of the rings' temperatures; α = 12e-6 1/K, the through-hardened bearing steel's
  value bearing catalogues give).

The seed bearing (bore 160 mm, raceway 210 mm, pitch 235 mm), group 3 at its mid-range 140 µm, on a p6 shaft seat
(+43/+68 µm on 160 mm, ISO 286-2; p6 is SKF's recommendation for cylindrical roller bearings of 140–280 mm bore under
normal to heavy loads on a rotating inner ring) at the mean interference 55.5 µm, and 10 K between the rings:
140 − 42.3 − 28.2 = 69.5 µm (:data:`SEED_OPERATING_CLEARANCE`); over the tolerance bands, 35–118 µm.
"""

from __future__ import annotations

#: Linear thermal expansion of bearing steel [1/K].
STEEL_THERMAL_EXPANSION = 12e-6

#: ISO 5753-1 radial internal clearance of cylindrical roller bearings with a cylindrical bore: (bore over, bore
#: up to [mm]) → {group: (min, max) [µm]}.
ISO_5753_1_CYLINDRICAL = {
    (120, 140): {"2": (15, 60), "N": (60, 105), "3": (100, 145), "4": (145, 190), "5": (200, 245)},
    (140, 160): {"2": (20, 70), "N": (70, 120), "3": (115, 165), "4": (165, 215), "5": (225, 275)},
    (160, 180): {"2": (25, 75), "N": (75, 125), "3": (120, 170), "4": (170, 220), "5": (250, 300)},
    (180, 200): {"2": (35, 90), "N": (90, 145), "3": (140, 195), "4": (195, 250), "5": (275, 330)},
}


def internal_clearance(bore: float, group: str) -> tuple[float, float]:
    """(min, max) [m] of the ISO 5753-1 group ``group`` ("2", "N", "3", "4", "5") for a bore [m] in the table's
    range (120–200 mm); ValueError outside it."""
    millimetres = bore * 1e3
    for (low, high), groups in ISO_5753_1_CYLINDRICAL.items():
        if low < millimetres <= high:
            if group not in groups:
                raise ValueError(f"group = {group!r}: must be one of {', '.join(groups)}")
            return groups[group][0] * 1e-6, groups[group][1] * 1e-6
    raise ValueError(f"bore = {bore!r} m: the table here covers bores over 120 up to 200 mm")


def fit_reduction(interference: float, bore: float, inner_raceway: float) -> float:
    """The clearance [m] an inner ring's diametral interference [m] on a solid shaft of the same steel takes up:
    I d/F (bore d and raceway diameter F [m])."""
    return interference * bore / inner_raceway


def thermal_reduction(temperature_difference: float, pitch_diameter: float,
                      expansion: float = STEEL_THERMAL_EXPANSION) -> float:
    """The clearance [m] an inner ring ΔT [K] warmer than the outer takes up: α ΔT D_pw."""
    return expansion * temperature_difference * pitch_diameter


#: The seed bearing's operating diametral clearance [m] (module docstring).
SEED_OPERATING_CLEARANCE = (140e-6 - fit_reduction(55.5e-6, 0.160, 0.210) - thermal_reduction(10.0, 0.235))
