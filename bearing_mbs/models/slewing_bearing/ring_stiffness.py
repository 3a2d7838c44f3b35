r"""Condensed ring-stiffness matrices of four-point-contact slewing bearings, parametrised by the pitch diameter.

Source: I. Fernández Apezteguia, *Parametrización de matrices de rigidez de anillos de rodamientos de vuelco*,
bachelor's thesis, UPV/EHU (Bilbao), 2019, eq. (20) and Tables 8–9. A finite-element sector of one ball pitch of
each ring (inner or outer; free, or with its bolted face clamped: "fixed") was condensed (Guyan) onto the two
raceway curvature centres; the two tangential degrees of freedom were dropped, leaving 4×4 matrices in the
order (r₁, a₁, r₂, a₂): radial and axial displacement of the first and the second curvature centre (an order
inferred from the matrices' eigenvectors: the softest mode of the free inner ring is (1, 0, 1, 0), a uniform
radial expansion, whose hoop stiffness falls as 1/D_pw²); node 1 is the centre of the ring's upper raceway arc,
node 2 of its lower arc (:mod:`.flexible` gives the evidence). Each entry was fitted over D_pw = 0.5…2.5 m as

.. math:: K(D_{pw}) = \left(\frac{A}{D_{pw}^2} + B\right)\cdot 10^8\ \mathrm{N/m},\qquad D_{pw}\ \text{in m}.

**Two printed coefficients are wrong** (:data:`ERRATA`): A_inner,free[4,2] = 0.257 must be −0.187 (symmetry,
and the thesis's own Annex III lists −0.187); B_outer,free[2,3] = [3,2] = +3.72 must be −3.72 (with +3.72 the
matrix has an eigenvalue of about −3.3e8 N/m at every diameter; the outer-free matrices follow the inner-free
ones up to the signs diag(1, −1, 1, −1), which requires −3.72). ``coefficients="as_printed"`` reproduces the
thesis, with a warning that names them.

Validity (:data:`VALIDITY`): ball diameter 35 mm, conformity 0.943, the geometry ratios of the thesis's Table 1
(from Heras' design DP7), no spacers, bolts rigid, 0.5 ≤ D_pw ≤ 2.5 m. Outside that range the matrices are an
extrapolation: a warning, or a :class:`~bearing_mbs.spec.SpecError` with ``strict=True``.
"""

from __future__ import annotations

import warnings

import numpy as np

from bearing_mbs.spec import SpecError

RINGS = ("inner", "outer")
MOUNTS = ("free", "fixed")
COEFFICIENTS = ("corrected", "as_printed")

#: What the fits were made for (the thesis's sections 7–8 and Table 1).
VALIDITY = {
    "ball_diameter_m": 0.035,
    "conformity": 0.943,
    "pitch_diameter_m": (0.5, 2.5),
    "geometry_ratios": {"R_h": 2.15, "H_g_mm": 10.0, "R_L": 1.9, "R_Lg": 0.1, "R_Lt": 1.15, "R_Dt": 0.75,
                        "R_Nh": 1.0},
    "dof_order": ("r1", "a1", "r2", "a2"),
    "notes": "single-row four-point-contact ball bearing, no spacers, bolt holes ignored, bolts rigid",
}

#: The thesis's Tables 8 and 9 as printed: (ring, mount) -> (A, B), dimensionless factors of 1e8 N/m.
AS_PRINTED = {
    ("inner", "free"): (
        [[0.285, -0.209, 0.318, 0.251], [-0.209, 0.148, -0.239, -0.187], [0.318, -0.239, 0.342, 0.269],
         [0.251, 0.257, 0.269, 0.209]],
        [[5.27, -3.63, -5.26, -3.68], [-3.63, 5.54, 3.63, 2.57], [-5.26, 3.63, 5.27, 3.68],
         [-3.68, 2.57, 3.68, 5.84]]),
    ("inner", "fixed"): (
        [[0.051, -0.038, 0.036, 0.025], [-0.038, 0.023, -0.032, -0.027], [0.036, -0.032, 0.025, 0.016],
         [0.025, -0.027, 0.016, 0.016]],
        [[7.91, -5.47, -1.85, -1.12], [-5.47, 6.82, 1.25, 0.77], [-1.85, 1.25, 12.23, 10.37],
         [-1.12, 0.77, 10.37, 12.92]]),
    ("outer", "free"): (
        [[0.281, 0.243, 0.193, -0.138], [0.243, 0.221, 0.145, -0.104], [0.193, 0.145, 0.242, -0.201],
         [-0.138, -0.104, -0.201, 0.178]],
        [[5.34, 3.77, -5.29, 3.67], [3.77, 5.95, 3.72, 2.60], [-5.29, 3.72, 5.34, -3.71],
         [3.67, 2.60, -3.71, 5.64]]),
    ("outer", "fixed"): (
        [[0.036, 0.022, 0.050, -0.036], [0.022, 0.0089, 0.030, -0.022], [0.050, 0.030, 0.133, -0.124],
         [-0.036, -0.022, -0.124, 0.124]],
        [[12.28, 10.4, -1.81, 1.23], [10.4, 12.94, -1.1, 0.76], [-1.81, -1.1, 8.06, -5.61],
         [1.23, 0.76, -5.61, 6.97]]),
}

#: The two printed errors: (ring, mount, matrix, entries (1-based, as printed), printed value, corrected value).
ERRATA = (
    ("inner", "free", "A", ((4, 2),), 0.257, -0.187),
    ("outer", "free", "B", ((2, 3), (3, 2)), 3.72, -3.72),
)

#: The factor of eq. (20) [N/m].
SCALE = 1e8


def _corrected() -> dict:
    table = {key: (np.array(a, dtype=float), np.array(b, dtype=float)) for key, (a, b) in AS_PRINTED.items()}
    for ring, mount, which, entries, printed, corrected in ERRATA:
        matrix = table[ring, mount][0 if which == "A" else 1]
        for i, j in entries:
            matrix[i - 1, j - 1] = corrected
    return table


def ring_stiffness(pitch_diameter: float, ring: str, mount: str, coefficients: str = "corrected",
                   strict: bool = False) -> np.ndarray:
    """The condensed 4×4 stiffness [N/m] of one ball pitch of a ring, in the order (r₁, a₁, r₂, a₂), at the pitch
    diameter D_pw [m]: (A/D_pw² + B)·1e8 (module docstring).

    ``ring``: ``inner`` or ``outer``; ``mount``: ``free`` or ``fixed`` (bolted face clamped); ``coefficients``:
    ``corrected`` (default) or ``as_printed`` (warns, naming the errata). Outside 0.5 ≤ D_pw ≤ 2.5 m: a warning,
    or a SpecError with ``strict``.
    """
    if ring not in RINGS:
        raise SpecError("ring", ring, f"one of {', '.join(RINGS)}")
    if mount not in MOUNTS:
        raise SpecError("mount", mount, f"one of {', '.join(MOUNTS)}")
    if coefficients not in COEFFICIENTS:
        raise SpecError("coefficients", coefficients, f"one of {', '.join(COEFFICIENTS)}")
    if not (isinstance(pitch_diameter, (int, float)) and np.isfinite(pitch_diameter) and pitch_diameter > 0):
        raise SpecError("pitch_diameter", pitch_diameter, "a finite length > 0 [m]")
    low, high = VALIDITY["pitch_diameter_m"]
    if not low <= pitch_diameter <= high:
        message = (f"pitch_diameter = {pitch_diameter:g} m is outside the range the matrices were fitted over, "
                   f"[{low:g}, {high:g}] m: an extrapolation")
        if strict:
            raise SpecError("pitch_diameter", pitch_diameter, f"in [{low:g}, {high:g}] m (the fit's range)")
        warnings.warn(message, UserWarning, stacklevel=2)
    if coefficients == "as_printed":
        a, b = (np.array(m, dtype=float) for m in AS_PRINTED[ring, mount])
        erratum = [e for e in ERRATA if (e[0], e[1]) == (ring, mount)]
        if erratum:
            _, _, which, entries, printed, corrected = erratum[0]
            warnings.warn(f"the as-printed {ring}-{mount} matrix has the thesis's erratum {which}"
                          f"{list(entries)} = {printed} (should be {corrected}): not symmetric positive definite",
                          UserWarning, stacklevel=2)
    else:
        a, b = _corrected()[ring, mount]
    return (a / pitch_diameter**2 + b) * SCALE
