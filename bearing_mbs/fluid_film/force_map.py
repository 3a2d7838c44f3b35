r"""A precomputed map of a journal bearing's film force, plain or recessed, for the time loop.

With Gümbel's condition the full-film pressure of the Reynolds equation (:mod:`.reynolds`) is linear in its sources,
the restrictors being linear (capillaries, or recesses held at the supply pressure). In the frame of the eccentricity
(ε, its direction ψ):

.. math:: p = P_s(\varepsilon, \varphi) + a\,P_a(\varepsilon, \varphi) + b\,P_b(\varepsilon, \varphi),

with the hydrostatic field :math:`P_s` of the supply (none in a plain bearing), the wedge source
:math:`a = \varepsilon(\Omega - 2\dot\psi)` and the squeeze source :math:`b = 2\dot\varepsilon`, both in 1/s (compare
the short bearing's bracket in :mod:`.closed_forms`; the recesses' depth is uniform, so the journal's turning about
the bearing acts as a wedge there too), and φ = ψ − ψ₀ the direction relative to the first recess (ψ₀), periodic over
the recess pitch 2π/N. A plain bearing has no φ and no :math:`P_s`.

The full film's force is therefore :math:`S\mathbf F_s + a\mathbf F_a + b\mathbf F_b` (S = 1 for a fed bearing, 0
for a plain one), with the three forces per unit source tabulated over ε × φ (``linear``, interpolated bilinearly):
exact in the motion, smooth where the film is full. Gümbel's condition then adds the force of the dropped negative
pressure (the *correction*), which is not linear. Writing :math:`(a, b) = M(\cos\beta, \sin\beta)` and, with a
motion scale m [1/s], :math:`(S, M/m) = R(\cos\gamma, \sin\gamma)`, the correction is homogeneous of degree one in
the sources: :math:`R\,\mathbf c(\varepsilon, \varphi, \gamma, \beta)`. γ ∈ [0, π/2] is the hydrodynamic share
of the pressure (0: at rest, hydrostatic only; π/2: hydrodynamic only, a plain bearing's one value); ``c`` is tabulated
in the eccentricity's frame (normal, tangential) over ε × φ × γ × β and interpolated multilinearly (periodic in φ and
β). Both tables come from three Reynolds solves per (ε, φ) and are scaled by :math:`(1-\varepsilon^2)^{5/2}`, which
takes out the growth of the squeeze force towards ε = 1 (the short bearing's pure-squeeze load grows as
:math:`(1-\varepsilon^2)^{-5/2}`; unscaled, the error at ε = 0.94 is 10 % instead of 1 %). m is chosen so that
γ = 45° puts the hydrodynamic pressure peak at ε = 1/2 level with the centred bearing's hydrostatic peak.

:func:`map_force` and :func:`map_force_jacobian` are numba-compilable, so the force element and this library share
them. :func:`interpolation_error` compares the map with direct solves midway between its nodes.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numba
import numpy as np
from numba.extending import register_jitable

from bearing_mbs.fluid_film.closed_forms import journal_motion_slopes
from bearing_mbs.fluid_film.journal import FilmGrid, JournalBearing
from bearing_mbs.fluid_film.restrictors import Capillary, DirectSupply, is_linear
from bearing_mbs.fluid_film.reynolds import JournalState, Supply, solve_film

#: Default table: ε from 0 to 0.95 in steps of 0.025, β in 5° steps.
ECCENTRICITY_RATIOS = np.linspace(0.0, 0.95, 39)
DIRECTIONS = 72
#: A recessed bearing's default steps: φ in steps of at most 7.5° over the recess pitch, γ in 2.5° steps (the recess pressure dropped by Gümbel's condition kinks the force in γ: 5° steps leave 1.5 %).
RECESS_DIRECTION_STEP = 7.5
SHARES = 37
#: The smallest ε at which the fields are solved (the wedge field is P_A/ε).
SMALLEST_ECCENTRICITY = 1e-4
#: The tables hold the force times (1 − ε²) to this power.
SCALING_POWER = 2.5
#: The entries of :attr:`ForceMap.axes`: ε step, φ step [rad], ψ₀ [rad], γ step [rad], m [1/s], S.
AXES = ("eccentricity_step", "recess_direction_step", "first_recess", "share_step", "motion_scale", "supply")
#: Restrictors the map takes: linear in the recess pressure (the superposition above holds) and fed from the supply
#: pressure (a constant flow's source is its flow, which the map does not carry).
MAPPED_RESTRICTORS = (Capillary, DirectSupply)


@dataclass(frozen=True)
class ForceMap:
    """Gümbel's correction c_n, c_t [N] per unit R (module docs), times (1 − ε²)^{5/2}, at ``eccentricity_ratios``
    (uniform, from 0) × φ (uniform over the recess pitch; one column for a plain bearing) × γ = π/2 − k Δγ (one for a
    plain bearing) × β = 2π(l + ½)/n (steady running, β = 0, lies mid-cell); ``linear`` (ε × φ × (S, a, b) × (normal,
    tangential)) the full film's force per unit source [N; N s], times the same; ``axes`` as :data:`AXES`. A plain
    bearing's correction is per unit M [N s]."""

    eccentricity_ratios: np.ndarray
    normal: np.ndarray
    tangential: np.ndarray
    linear: np.ndarray
    axes: np.ndarray

    @property
    def eccentricity_step(self) -> float:
        return float(self.axes[0])

    def forces(self, states: np.ndarray, clearance: float) -> np.ndarray:
        """(F_x, F_y) [N] (K × 2) at each row (e_x, e_y, v_x, v_y, Ω) of ``states`` (:func:`map_forces`)."""
        return map_forces(self.normal, self.tangential, self.linear, self.axes, np.asarray(states, dtype=float),
                          clearance)


def _fields(bearing: JournalBearing, grid: FilmGrid, supply: Supply | None, eps: float, psi: float) -> np.ndarray:
    """(P_s [Pa], P_a [Pa s], P_b [Pa s]) at ε, ψ [rad], each flattened over the grid's cells."""
    clearance = bearing.radial_clearance
    eps = max(eps, SMALLEST_ECCENTRICITY)
    direction = np.array([math.cos(psi), math.sin(psi)])
    centre = tuple(eps * clearance * direction)
    still = None if supply is None else Supply(0.0, supply.restrictor)
    wedge = solve_film(bearing, JournalState(centre, (0.0, 0.0), 1.0), still, grid).pressure / eps
    squeeze = solve_film(bearing, JournalState(centre, tuple(clearance * direction), 0.0), still, grid).pressure / 2
    hydrostatic = (np.zeros_like(wedge) if supply is None
                   else solve_film(bearing, JournalState(centre), supply, grid).pressure)
    return np.stack([hydrostatic.ravel(), wedge.ravel(), squeeze.ravel()])


def _film_forces(grid: FilmGrid, pressure: np.ndarray, psi: float) -> np.ndarray:
    """(normal, tangential) [N] (K × 2) in the frame of the eccentricity at ψ of the pressure fields (K × cells)."""
    relative = np.repeat(grid.theta - psi, grid.n_z)
    return -pressure @ np.column_stack([np.cos(relative), np.sin(relative)]) * grid.cell_area


def _corrections(grid: FilmGrid, fields: np.ndarray, psi: float, sources: np.ndarray):
    """Gümbel's correction (normal, tangential) [N] (K × 2) of the fields' combinations ``sources`` (K × 3) @ fields:
    the force of the truncated pressure less the full film's (the negative pressure's force, reversed), and the
    full film's force per unit source (3 × 2)."""
    pressure = sources @ fields
    return _film_forces(grid, np.minimum(pressure, 0.0), psi) * -1.0, _film_forces(grid, fields, psi)


def _sources(shares: np.ndarray, directions: np.ndarray, motion_scale: float) -> np.ndarray:
    """(K × 3) weights of (P_s, P_a, P_b) for every (γ, β), β fastest: (cos γ, m sin γ cos β, m sin γ sin β)."""
    gamma, beta = np.meshgrid(shares, directions, indexing="ij")
    return np.stack([np.cos(gamma), motion_scale * np.sin(gamma) * np.cos(beta),
                     motion_scale * np.sin(gamma) * np.sin(beta)], axis=-1).reshape(-1, 3)


def build_force_map(bearing: JournalBearing, grid: tuple[int, int] = (120, 30), supply: Supply | None = None,
                    eccentricity_ratios: np.ndarray = ECCENTRICITY_RATIOS, directions: int = DIRECTIONS,
                    recess_direction_step: float = RECESS_DIRECTION_STEP, shares: int = SHARES) -> ForceMap:
    """The map of ``bearing`` (Gümbel cavitation); a recessed bearing needs its ``supply`` through a linear restrictor
    of :data:`MAPPED_RESTRICTORS`; ``recess_direction_step`` [deg] bounds the φ step."""
    steps = np.diff(eccentricity_ratios)
    if eccentricity_ratios[0] != 0 or not np.allclose(steps, steps[0]) or eccentricity_ratios[-1] >= 1:
        raise ValueError("eccentricity_ratios: uniform from 0, below 1")
    recesses = bearing.recesses
    if recesses is not None:
        if supply is None:
            raise ValueError("supply = None: a recessed bearing's map needs its supply pressure and restrictor")
        if not (isinstance(supply.restrictor, MAPPED_RESTRICTORS) and is_linear(supply.restrictor)):
            raise ValueError(f"restrictor = {supply.restrictor!r}: the force map superposes the film's sources, which "
                             "holds for a capillary without entrance loss or a directly supplied recess only; use the "
                             "Reynolds solve per evaluation")
    film_grid = FilmGrid.build(bearing, *grid)
    beta = 2 * math.pi * (np.arange(directions) + 0.5) / directions
    if recesses is None:
        pitch, columns, first, gamma, share_step, scale, weight = 2 * math.pi, 1, 0.0, np.array([math.pi / 2]), 1.0, \
            1.0, 0.0
    else:
        pitch, first = 2 * math.pi / recesses.count, math.radians(recesses.first_angle)
        columns = math.ceil(math.degrees(pitch) / recess_direction_step - 1e-9)
        share_step = math.pi / 2 / (shares - 1)
        gamma = math.pi / 2 - share_step * np.arange(shares)
        centred = _fields(bearing, film_grid, supply, 0.0, first)
        middle = _fields(bearing, film_grid, supply, 0.5, first)
        scale, weight = float(np.abs(centred[0]).max() / np.abs(middle[1]).max()), 1.0
    sources = _sources(gamma, beta, scale)
    shape = (eccentricity_ratios.size, columns, gamma.size, directions)
    normal, tangential = np.zeros(shape), np.zeros(shape)
    linear = np.zeros((eccentricity_ratios.size, columns, 3, 2))
    for i, eps in enumerate(eccentricity_ratios):
        for j in range(columns):
            psi = first + pitch * j / columns
            correction, linear[i, j] = _corrections(film_grid, _fields(bearing, film_grid, supply, eps, psi), psi,
                                                    sources)
            normal[i, j], tangential[i, j] = (force.reshape(gamma.size, directions) for force in correction.T)
    scaling = (1 - eccentricity_ratios**2) ** SCALING_POWER
    axes = np.array([steps[0], pitch / columns, first, share_step, scale, weight])
    return ForceMap(np.asarray(eccentricity_ratios, dtype=float), normal * scaling[:, None, None, None],
                    tangential * scaling[:, None, None, None], linear * scaling[:, None, None, None], axes)


@register_jitable
def _cell(position, size, periodic):
    """(node, next node, fraction, slope factor) of ``position`` (in node steps) on an axis of ``size`` nodes:
    wrapped if ``periodic``, else held within [0, size − 1] (slope factor 0 where held, else 1)."""
    if periodic:
        node = math.floor(position)
        first = int(node) % size
        return first, (first + 1) % size, position - node, 1.0
    if size == 1:
        return 0, 0, 0.0, 0.0
    top = size - 1.0 - 1e-12
    held = min(max(position, 0.0), top)
    first = int(held)
    return first, first + 1, held - first, 1.0 if held == position else 0.0


@register_jitable
def _interpolate(table, cells):
    """The multilinear interpolant of the 4-D ``table`` in the ``cells`` of :func:`_cell` (one per axis), and its
    slopes in the four positions."""
    (i0, i1, f0, s0), (j0, j1, f1, s1), (k0, k1, f2, s2), (l0, l1, f3, s3) = cells
    value = d0 = d1 = d2 = d3 = 0.0
    for corner in range(16):
        b0, b1, b2, b3 = corner & 1, (corner >> 1) & 1, (corner >> 2) & 1, (corner >> 3) & 1
        w0, w1, w2, w3 = (f0 if b0 else 1.0 - f0), (f1 if b1 else 1.0 - f1), (f2 if b2 else 1.0 - f2), \
            (f3 if b3 else 1.0 - f3)
        entry = table[i1 if b0 else i0, j1 if b1 else j0, k1 if b2 else k0, l1 if b3 else l0]
        value += w0 * w1 * w2 * w3 * entry
        d0 += (1.0 if b0 else -1.0) * w1 * w2 * w3 * entry
        d1 += (1.0 if b1 else -1.0) * w0 * w2 * w3 * entry
        d2 += (1.0 if b2 else -1.0) * w0 * w1 * w3 * entry
        d3 += (1.0 if b3 else -1.0) * w0 * w1 * w2 * entry
    return value, (d0 * s0, d1 * s1, d2 * s2, d3 * s3)


@register_jitable
def _bilinear(linear, at_eps, at_phi, source, component):
    """The full film's force per unit source (:attr:`ForceMap.linear`) interpolated in ε and φ, and its slopes in
    the two positions."""
    i0, i1, f0, s0 = at_eps
    j0, j1, f1, s1 = at_phi
    low = (1.0 - f1) * linear[i0, j0, source, component] + f1 * linear[i0, j1, source, component]
    high = (1.0 - f1) * linear[i1, j0, source, component] + f1 * linear[i1, j1, source, component]
    across = (1.0 - f0) * (linear[i0, j1, source, component] - linear[i0, j0, source, component]) \
        + f0 * (linear[i1, j1, source, component] - linear[i1, j0, source, component])
    return (1.0 - f0) * low + f0 * high, (high - low) * s0, across * s1


@register_jitable
def _map_evaluation(normal, tangential, linear, axes, e_x, e_y, v_x, v_y, speed, clearance, with_slopes):
    """(F_x, F_y) [N] and, if ``with_slopes``, ∂(F_x, F_y)/∂(e_x, e_y, v_x, v_y, Ω) (2 × 5; zeros otherwise)."""
    jacobian = np.zeros((2, 5))
    e = math.sqrt(e_x * e_x + e_y * e_y)
    floor = 1e-12 * clearance
    centred = e < floor
    if centred:
        e_x, e_y, e = floor, 0.0, floor
    eps_step, phi_step, first_recess, share_step, motion_scale, supply = axes[0], axes[1], axes[2], axes[3], \
        axes[4], axes[5]
    rows, columns, shares, directions = normal.shape
    n_x, n_y = e_x / e, e_y / e
    eps = e / clearance
    a = eps * (speed - 2.0 * (v_y * n_x - v_x * n_y) / e)
    b = 2.0 * (v_x * n_x + v_y * n_y) / clearance
    magnitude = math.sqrt(a * a + b * b)
    u = magnitude / motion_scale
    radius = math.sqrt(supply * supply + u * u)
    gamma = math.atan2(u, supply)
    beta = math.atan2(b, a) % (2.0 * math.pi)
    phi = (math.atan2(n_y, n_x) - first_recess) % (2.0 * math.pi)
    at_eps, at_phi = _cell(eps / eps_step, rows, False), _cell(phi / phi_step, columns, True)
    cells = (at_eps, at_phi, _cell((0.5 * math.pi - gamma) / share_step, shares, False),
             _cell(beta / (2.0 * math.pi) * directions - 0.5, directions, True))
    slopes = with_slopes and not centred
    # the slopes' arrays are made only when asked for: the force alone (every step of a run) allocates no more
    zero = np.zeros(5)
    radius_d = a_d = b_d = nx_d = ny_d = eps_d = zero
    positions_d = (zero, zero, zero, zero)
    film_d = jacobian  # a placeholder the force alone never writes
    if slopes:
        n_x, n_y, eps, _, a, nx_d, ny_d, eps_d, eps_rate_d, a_d = journal_motion_slopes(
            e_x, e_y, v_x, v_y, speed, clearance)
        b_d = 2.0 * eps_rate_d
        psi_d = np.array([-n_y / e, n_x / e, 0.0, 0.0, 0.0])
        gamma_d = beta_d = zero
        if magnitude > 0.0:
            u_d = (a * a_d + b * b_d) / (magnitude * motion_scale)
            beta_d = (a * b_d - b * a_d) / (magnitude * magnitude)
            radius_d = u * u_d / radius
            gamma_d = supply * u_d / (radius * radius)
        positions_d = (eps_d / eps_step, psi_d / phi_step, -gamma_d / share_step,
                       beta_d / (2.0 * math.pi) * directions)
        film_d = np.zeros((2, 5))
    # the film in the eccentricity's frame: the full film S F_s + a F_a + b F_b, plus R times Gümbel's correction
    film_n = film_t = 0.0
    for m in range(2):
        correction, correction_slopes = _interpolate(normal if m == 0 else tangential, cells)
        value = radius * correction
        if slopes:
            film_d[m] = radius_d * correction
            for axis in range(4):
                film_d[m] += radius * correction_slopes[axis] * positions_d[axis]
        for k, (weight, weight_d) in enumerate(((supply, zero), (a, a_d), (b, b_d))):
            part, by_eps, by_phi = _bilinear(linear, at_eps, at_phi, k, m)
            value += weight * part
            if slopes:
                film_d[m] += weight_d * part + weight * (by_eps * positions_d[0] + by_phi * positions_d[1])
        if m == 0:
            film_n = value
        else:
            film_t = value
    bounded = min(eps, (rows - 1) * eps_step)
    scale = 1.0 / (1.0 - bounded * bounded) ** SCALING_POWER
    force_x = scale * (film_n * n_x - film_t * n_y)
    force_y = scale * (film_n * n_y + film_t * n_x)
    if not slopes:
        return force_x, force_y, jacobian
    scale_d = zero
    if eps < (rows - 1) * eps_step:
        scale_d = scale * SCALING_POWER * 2.0 * eps / (1.0 - eps * eps) * eps_d
    f_n, f_t = scale * film_n, scale * film_t
    f_n_d, f_t_d = scale_d * film_n + scale * film_d[0], scale_d * film_t + scale * film_d[1]
    jacobian[0] = f_n_d * n_x + f_n * nx_d - f_t_d * n_y - f_t * ny_d
    jacobian[1] = f_n_d * n_y + f_n * ny_d + f_t_d * n_x + f_t * nx_d
    return force_x, force_y, jacobian


@register_jitable
def map_force(normal, tangential, linear, axes, e_x, e_y, v_x, v_y, speed, clearance):
    """Film force (F_x, F_y) [N] from the map's tables (numba-compilable); ε beyond the table is held at its end."""
    force_x, force_y, _ = _map_evaluation(normal, tangential, linear, axes, e_x, e_y, v_x, v_y, speed, clearance,
                                          False)
    return force_x, force_y


@register_jitable
def map_force_jacobian(normal, tangential, linear, axes, e_x, e_y, v_x, v_y, speed, clearance):
    """∂(F_x, F_y)/∂(e_x, e_y, v_x, v_y, Ω) of :func:`map_force` (2 × 5): the interpolants' slopes on their cells
    in ε, φ, γ and β, the sources' and R's, the scale's in ε, and the turning of the line of centres
    (:func:`~bearing_mbs.fluid_film.closed_forms.journal_motion_slopes`)."""
    return _map_evaluation(normal, tangential, linear, axes, e_x, e_y, v_x, v_y, speed, clearance, True)[2]


@numba.njit(cache=True)
def map_forces(normal, tangential, linear, axes, states, clearance):
    """(F_x, F_y) [N] (K × 2) of :func:`map_force` at each row (e_x, e_y, v_x, v_y, Ω) of ``states`` (K × 5),
    compiled: the library's calls from Python."""
    forces = np.empty((states.shape[0], 2))
    for k in range(states.shape[0]):
        forces[k] = map_force(normal, tangential, linear, axes, states[k, 0], states[k, 1], states[k, 2],
                              states[k, 3], states[k, 4], clearance)
    return forces


def interpolation_error(bearing: JournalBearing, force_map: ForceMap, grid: tuple[int, int] = (120, 30),
                        supply: Supply | None = None) -> float:
    """The largest |F_map − F_solve| / max |F_solve| over points midway between the map's nodes in ε, φ, γ and β
    (each ε row's largest direct force the scale), at ε up to the table's last interval."""
    film_grid = FilmGrid.build(bearing, *grid)
    _, columns, shares, directions = force_map.normal.shape
    step, phi_step, first, share_step, scale, weight = force_map.axes
    clearance = bearing.radial_clearance
    beta = 2 * math.pi * (np.arange(directions) + 1.0) / directions
    gamma = (math.pi / 2 - share_step * (np.arange(shares - 1) + 0.5)) if shares > 1 else np.array([math.pi / 2])
    sources = _sources(gamma, beta, scale)
    worst = 0.0
    for eps in force_map.eccentricity_ratios[:-1] + step / 2:
        for j in range(columns):
            psi = first + phi_step * (j + 0.5 if columns > 1 else 0.0)
            fields = _fields(bearing, film_grid, supply, eps, psi)
            exact = _film_forces(film_grid, np.maximum(sources @ fields, 0.0), psi)
            mapped = _mapped(force_map, eps, psi, sources, weight, clearance)
            worst = max(worst, float(np.abs(mapped - exact).max() / np.abs(exact).max()))
    return worst


def _mapped(force_map: ForceMap, eps: float, psi: float, sources: np.ndarray, weight: float, clearance: float):
    """f (normal, tangential) (K × 2) of the map at ε along ψ for each row of source weights (cos γ, m sin γ cos β,
    m sin γ sin β): the motion with the wedge and squeeze sources (a, b) = (m sin γ cos β, m sin γ sin β) / cos γ
    at Ω = 1 (per unit supply; a plain bearing's per unit M), i.e. ε̇ = b/2, ψ̇ = (1 − a/ε)/2, evaluated and
    divided by R = 1/cos γ."""
    divisor = sources[:, 0] if weight else np.ones(len(sources))
    a, b = sources[:, 1] / divisor, sources[:, 2] / divisor
    n, tangent = np.array([math.cos(psi), math.sin(psi)]), np.array([-math.sin(psi), math.cos(psi)])
    velocity = np.outer(clearance * b / 2, n) + np.outer(eps * clearance * (1 - a / eps) / 2, tangent)
    states = np.column_stack([np.tile(eps * clearance * n, (len(sources), 1)), velocity, np.ones(len(sources))])
    force = force_map.forces(states, clearance)
    return np.column_stack([force @ n, force @ tangent]) * divisor[:, None]
