"""Rotation matrices of the two parametrisations the engines use for bodies in three dimensions (compiled).

R turns body-frame vectors into world-frame ones. A unit quaternion p = (w, x, y, z), scalar first (the reference
engine's), and a rotation vector φ = θ e (Exudyn's Lie-group nodes) give, by the Euler–Rodrigues formula,
R = I + sin θ [e]× + (1 − cos θ) [e]×².
"""

from __future__ import annotations

import math

import numba

#: Below this angle [rad] the rotation vector's R uses the Taylor series of sin θ/θ and (1 − cos θ)/θ².
SMALL_ANGLE = 1e-4


@numba.njit(cache=True)
def rotation_from_quaternion(w, x, y, z, out):
    """R of the unit quaternion (w, x, y, z), into ``out`` (3, 3)."""
    out[0, 0] = 1.0 - 2.0 * (y * y + z * z)
    out[0, 1] = 2.0 * (x * y - w * z)
    out[0, 2] = 2.0 * (x * z + w * y)
    out[1, 0] = 2.0 * (x * y + w * z)
    out[1, 1] = 1.0 - 2.0 * (x * x + z * z)
    out[1, 2] = 2.0 * (y * z - w * x)
    out[2, 0] = 2.0 * (x * z - w * y)
    out[2, 1] = 2.0 * (y * z + w * x)
    out[2, 2] = 1.0 - 2.0 * (x * x + y * y)


@numba.njit(cache=True)
def rotation_from_vector(a, b, c, out):
    """R of the rotation vector (a, b, c) [rad], into ``out`` (3, 3)."""
    angle2 = a * a + b * b + c * c
    if angle2 < SMALL_ANGLE**2:
        s, k = 1.0 - angle2 / 6.0, 0.5 - angle2 / 24.0  # sin θ/θ, (1 − cos θ)/θ²
    else:
        angle = math.sqrt(angle2)
        s, k = math.sin(angle) / angle, (1.0 - math.cos(angle)) / angle2
    out[0, 0] = 1.0 - k * (b * b + c * c)
    out[0, 1] = -s * c + k * a * b
    out[0, 2] = s * b + k * a * c
    out[1, 0] = s * c + k * a * b
    out[1, 1] = 1.0 - k * (a * a + c * c)
    out[1, 2] = -s * a + k * b * c
    out[2, 0] = -s * b + k * a * c
    out[2, 1] = s * a + k * b * c
    out[2, 2] = 1.0 - k * (a * a + b * b)


@numba.njit(cache=True)
def turned_quaternion(w, x, y, z, a, b, c):
    """The unit quaternion (w, x, y, z) turned by the rotation vector (a, b, c) [rad] given in its body frame:
    p ⊗ exp(φ/2) with exp(φ/2) = (cos(θ/2), sin(θ/2) φ/θ), θ = |φ|; returns its four components, normalised."""
    angle2 = a * a + b * b + c * c
    if angle2 < SMALL_ANGLE**2:
        s, cw = 0.5 - angle2 / 48.0, 1.0 - angle2 / 8.0  # sin(θ/2)/θ, cos(θ/2)
    else:
        angle = math.sqrt(angle2)
        s, cw = math.sin(0.5 * angle) / angle, math.cos(0.5 * angle)
    qa, qb, qc = s * a, s * b, s * c
    pw = w * cw - x * qa - y * qb - z * qc
    px = w * qa + x * cw + y * qc - z * qb
    py = w * qb - x * qc + y * cw + z * qa
    pz = w * qc + x * qb - y * qa + z * cw
    norm = math.sqrt(pw * pw + px * px + py * py + pz * pz)
    return pw / norm, px / norm, py / norm, pz / norm
