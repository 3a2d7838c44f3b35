r"""A precomputed, dimensionless-in-speed map of a plain journal bearing's film force, for the time loop.

With Gümbel's condition the full-film pressure of the Reynolds equation is linear in its two sources: in the frame
of the eccentricity (ε, its direction ψ), :math:`p = a\,P_a(\varepsilon) + b\,P_b(\varepsilon)` with
:math:`a = \varepsilon(\Omega - 2\dot\psi)` (wedge) and :math:`b = 2\dot\varepsilon` (squeeze), both in 1/s
(compare the short bearing's bracket in :mod:`.closed_forms`). Writing :math:`(a, b) = M(\cos\beta, \sin\beta)`,
the truncated force is :math:`M\,\mathbf f(\varepsilon, \beta)`: a table over ε and β from two Reynolds solves per ε
(:mod:`.reynolds`), interpolated bilinearly (periodic in β) after scaling by :math:`(1-\varepsilon^2)^{5/2}`, which
takes out the growth of the squeeze force towards ε = 1 (the short bearing's pure-squeeze load grows as
:math:`(1-\varepsilon^2)^{-5/2}`; unscaled, the error at ε = 0.94 is 10 % instead of 1 %). :func:`map_force` is numba-compilable, so the force
element and this library share it. :func:`interpolation_error` compares the map with direct solves midway between
its nodes.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numba.extending import register_jitable

from bearing_mbs.fluid_film.closed_forms import journal_motion_slopes
from bearing_mbs.fluid_film.journal import FilmGrid, JournalBearing
from bearing_mbs.fluid_film.reynolds import JournalState, solve_film

#: Default table: ε from 0 to 0.95 in steps of 0.025, β in 5° steps.
ECCENTRICITY_RATIOS = np.linspace(0.0, 0.95, 39)
DIRECTIONS = 72
#: The smallest ε at which the fields are solved (the wedge field is P_A/ε).
SMALLEST_ECCENTRICITY = 1e-4
#: The tables hold the force times (1 − ε²) to this power.
SCALING_POWER = 2.5


@dataclass(frozen=True)
class ForceMap:
    """f_n, f_t [N s] per unit M, times (1 − ε²)^{5/2}, at ``eccentricity_ratios`` (uniform, from 0) × β = 2πk/n
    (columns)."""

    eccentricity_ratios: np.ndarray
    normal: np.ndarray
    tangential: np.ndarray

    @property
    def eccentricity_step(self) -> float:
        return float(self.eccentricity_ratios[1] - self.eccentricity_ratios[0])


def _fields(bearing: JournalBearing, grid: FilmGrid, eps: float) -> tuple[np.ndarray, np.ndarray]:
    clearance = bearing.radial_clearance
    eps = max(eps, SMALLEST_ECCENTRICITY)
    wedge = solve_film(bearing, JournalState((eps * clearance, 0.0), (0.0, 0.0), 1.0), grid=grid).pressure / eps
    squeeze = solve_film(bearing, JournalState((eps * clearance, 0.0), (clearance, 0.0), 0.0), grid=grid).pressure / 2
    return wedge, squeeze


def _truncated_forces(grid: FilmGrid, wedge, squeeze, directions: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    area = grid.bearing.radius * grid.d_theta * grid.dz
    pressure = np.maximum(np.cos(directions)[:, None, None] * wedge + np.sin(directions)[:, None, None] * squeeze, 0)
    normal = -np.einsum("kij,i->k", pressure, np.cos(grid.theta)) * area
    tangential = -np.einsum("kij,i->k", pressure, np.sin(grid.theta)) * area
    return normal, tangential


def build_force_map(bearing: JournalBearing, grid: tuple[int, int] = (120, 30),
                    eccentricity_ratios: np.ndarray = ECCENTRICITY_RATIOS, directions: int = DIRECTIONS) -> ForceMap:
    """The map of a plain bearing (no recesses), Gümbel cavitation."""
    if bearing.recesses is not None:
        raise ValueError("recesses: a force map is built for a plain journal bearing")
    steps = np.diff(eccentricity_ratios)
    if eccentricity_ratios[0] != 0 or not np.allclose(steps, steps[0]) or eccentricity_ratios[-1] >= 1:
        raise ValueError("eccentricity_ratios: uniform from 0, below 1")
    film_grid = FilmGrid.build(bearing, *grid)
    beta = 2 * math.pi * np.arange(directions) / directions
    normal, tangential = np.zeros((eccentricity_ratios.size, directions)), np.zeros((eccentricity_ratios.size,
                                                                                     directions))
    for i, eps in enumerate(eccentricity_ratios):
        normal[i], tangential[i] = _truncated_forces(film_grid, *_fields(bearing, film_grid, eps), beta)
    scaling = ((1 - eccentricity_ratios**2) ** SCALING_POWER)[:, None]
    normal, tangential = normal * scaling, tangential * scaling
    return ForceMap(np.asarray(eccentricity_ratios, dtype=float), normal, tangential)


@register_jitable
def map_force(normal, tangential, eccentricity_step, e_x, e_y, v_x, v_y, speed, clearance):
    """Film force (F_x, F_y) [N] from the map's tables (numba-compilable); ε beyond the table is held at its end."""
    e = math.sqrt(e_x * e_x + e_y * e_y)
    floor = 1e-12 * clearance
    if e < floor:
        e_x, e_y, e = floor, 0.0, floor
    n_x, n_y = e_x / e, e_y / e
    eps = e / clearance
    a = eps * (speed - 2.0 * (v_y * n_x - v_x * n_y) / e)
    b = 2.0 * (v_x * n_x + v_y * n_y) / clearance
    magnitude = math.sqrt(a * a + b * b)
    rows, columns = normal.shape
    position = min(eps / eccentricity_step, rows - 1.0 - 1e-12)
    i = int(position)
    u = position - i
    angle = math.atan2(b, a) % (2.0 * math.pi) / (2.0 * math.pi) * columns
    k = int(angle) % columns
    w = angle - int(angle)
    k1 = (k + 1) % columns
    f_n = ((1 - u) * ((1 - w) * normal[i, k] + w * normal[i, k1])
           + u * ((1 - w) * normal[i + 1, k] + w * normal[i + 1, k1]))
    f_t = ((1 - u) * ((1 - w) * tangential[i, k] + w * tangential[i, k1])
           + u * ((1 - w) * tangential[i + 1, k] + w * tangential[i + 1, k1]))
    scale = magnitude / (1.0 - min(eps, (rows - 1) * eccentricity_step) ** 2) ** SCALING_POWER
    f_n, f_t = scale * f_n, scale * f_t
    return f_n * n_x - f_t * n_y, f_n * n_y + f_t * n_x


@register_jitable
def map_force_jacobian(normal, tangential, eccentricity_step, e_x, e_y, v_x, v_y, speed, clearance):
    """∂(F_x, F_y)/∂(e_x, e_y, v_x, v_y, Ω) of :func:`map_force` (2 × 5): the bilinear interpolant's slopes on its
    cell in ε and in the motion's angle atan2(2ε̇, ε(Ω − 2ψ̇)), the scale's magnitude and ε, and the turning of the
    line of centres (:func:`~bearing_mbs.fluid_film.closed_forms.journal_motion_slopes`)."""
    jacobian = np.zeros((2, 5))
    if math.sqrt(e_x * e_x + e_y * e_y) < 1e-12 * clearance:
        return jacobian
    n_x, n_y, eps, eps_rate, a, nx_d, ny_d, eps_d, eps_rate_d, a_d = journal_motion_slopes(
        e_x, e_y, v_x, v_y, speed, clearance)
    b, b_d = 2.0 * eps_rate, 2.0 * eps_rate_d
    magnitude = math.sqrt(a * a + b * b)
    if magnitude <= 0.0:
        return jacobian
    magnitude_d = (a * a_d + b * b_d) / magnitude
    rows, columns = normal.shape
    raw = eps / eccentricity_step
    position = min(raw, rows - 1.0 - 1e-12)
    position_d = eps_d / eccentricity_step if raw < rows - 1.0 - 1e-12 else np.zeros(5)
    i = int(position)
    u = position - i
    angle = math.atan2(b, a) % (2.0 * math.pi) / (2.0 * math.pi) * columns
    angle_d = columns / (2.0 * math.pi) * (a * b_d - b * a_d) / (magnitude * magnitude)
    k = int(angle) % columns
    w = angle - int(angle)
    k1 = (k + 1) % columns
    values = np.zeros(2)
    values_d = np.zeros((2, 5))
    for m in range(2):
        table = normal if m == 0 else tangential
        low = (1 - w) * table[i, k] + w * table[i, k1]
        high = (1 - w) * table[i + 1, k] + w * table[i + 1, k1]
        values[m] = (1 - u) * low + u * high
        by_w = (1 - u) * (table[i, k1] - table[i, k]) + u * (table[i + 1, k1] - table[i + 1, k])
        values_d[m] = (high - low) * position_d + by_w * angle_d
    largest = (rows - 1) * eccentricity_step
    bounded = min(eps, largest)
    divisor = (1.0 - bounded**2) ** SCALING_POWER
    scale = magnitude / divisor
    scale_d = magnitude_d / divisor
    if eps < largest:
        scale_d += scale * SCALING_POWER * 2.0 * eps / (1.0 - eps**2) * eps_d
    f_n, f_t = scale * values[0], scale * values[1]
    f_n_d, f_t_d = scale_d * values[0] + scale * values_d[0], scale_d * values[1] + scale * values_d[1]
    jacobian[0] = f_n_d * n_x + f_n * nx_d - f_t_d * n_y - f_t * ny_d
    jacobian[1] = f_n_d * n_y + f_n * ny_d + f_t_d * n_x + f_t * nx_d
    return jacobian


def interpolation_error(bearing: JournalBearing, force_map: ForceMap, grid: tuple[int, int] = (120, 30)) -> float:
    """The largest |F_map − F_solve| / max |F_solve| over points midway between the map's nodes (in ε and β),
    at ε up to the table's last interval."""
    film_grid = FilmGrid.build(bearing, *grid)
    columns = force_map.normal.shape[1]
    beta = 2 * math.pi * (np.arange(columns) + 0.5) / columns
    worst = 0.0
    for eps in (force_map.eccentricity_ratios[:-1] + force_map.eccentricity_step / 2):
        normal, tangential = _truncated_forces(film_grid, *_fields(bearing, film_grid, eps), beta)
        clearance = bearing.radial_clearance
        mapped = np.array([map_force(force_map.normal, force_map.tangential, force_map.eccentricity_step,
                                     eps * clearance, 0.0, clearance * math.sin(b) / 2, 0.0,
                                     math.cos(b) / eps, clearance) for b in beta])
        exact = np.stack([normal, tangential], axis=1)
        worst = max(worst, float(np.abs(mapped - exact).max() / np.abs(exact).max()))
    return worst
