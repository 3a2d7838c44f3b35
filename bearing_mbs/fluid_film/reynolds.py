r"""The Reynolds equation of a journal bearing, by a conservative finite-volume method on the unwrapped film.

Incompressible, isoviscous, laminar thin film (document 001, eqs. 5.6–5.11, 5.17); with :math:`x = R\theta` and
the journal's surface speed :math:`U = \Omega R` (the bearing is fixed), the mass flux per unit width is

.. math:: \mathbf q = -\frac{h^3}{12\mu}\nabla p + \frac{U h}{2}\,\vartheta\,\mathbf e_x,
          \qquad \nabla\cdot\mathbf q + \frac{\partial (h\vartheta)}{\partial t} = 0,

where ϑ ∈ [0, 1] is the fraction of the gap filled with oil (1 in a full film). Each cell balances the fluxes
through its four faces: pressure flux with the land film at the face, Couette flux upwinded in ϑ, and the
squeeze term :math:`\vartheta\,\dot h` (the quasi-static film: :math:`\partial\vartheta/\partial t` neglected).
A recess is one pressure unknown acting at its edges; its balance adds the restrictor's inflow
(:mod:`.restrictors`). Ends z = ±L/2 are at ambient pressure 0.

Cavitation (``cavitation``):

* ``"gumbel"`` — the full-film (Sommerfeld) solution, ϑ = 1 everywhere; negative pressures are dropped from the
  load (Gümbel's half-Sommerfeld condition). Mass is conserved by the full-film field, not by the truncated one.
* ``"jfo"`` — mass-conserving Jakobsson–Floberg–Olsson cavitation in the complementarity form of M. Giacopini,
  M. T. Fowell, D. Dini, A. Strozzi, "A mass-conserving complementarity formulation to study lubricant films in
  the presence of cavitation", J. Tribol. 132 (2010) 041702: :math:`p \ge 0,\ 1-\vartheta \ge 0,\
  p\,(1-\vartheta) = 0`, solved by a primal–dual active set (semismooth Newton on min(p, 1−ϑ)): each cell carries
  p where the film is full and 1−ϑ where it is cavitated; cells switch until no sign is violated.

Outputs (:class:`FilmSolution`) are the force on the journal, recess pressures and inflows, the flow out of both
ends, and the viscous friction torque :math:`T = \sum (\mu U\vartheta/h + \tfrac h2\,\partial p/\partial x)\,R\,dA`
(Gümbel: ϑ = 1, the Petroff shear over the whole bore).
"""

from __future__ import annotations

import math
import warnings
from dataclasses import dataclass, field

import numpy as np
import scipy.sparse as sp
from scipy.sparse.linalg import MatrixRankWarning, spsolve

from bearing_mbs.fluid_film.journal import FilmGrid, JournalBearing
from bearing_mbs.fluid_film.newton import solve_balance
from bearing_mbs.fluid_film.restrictors import DirectSupply, feeds_oil, is_linear

#: Cavitation models by name.
CAVITATION = ("gumbel", "jfo")

#: Iteration limit of the active set and of the restrictors' Newton loop.
MAX_ITERATIONS = 200


class FilmNotConverged(RuntimeError):
    """The active set or a restrictor's Newton loop did not settle within :data:`MAX_ITERATIONS`."""


@dataclass(frozen=True)
class JournalState:
    """The journal's centre (e_x, e_y) [m] and velocity (ė_x, ė_y) [m/s] relative to the bearing; its speed Ω
    [rad/s], counter-clockwise positive."""

    eccentricity: tuple[float, float] = (0.0, 0.0)
    eccentricity_rate: tuple[float, float] = (0.0, 0.0)
    speed: float = 0.0


@dataclass(frozen=True)
class Supply:
    """Oil supply of every recess: ``pressure`` p_s [Pa] through one ``restrictor`` each (:mod:`.restrictors`)."""

    pressure: float
    restrictor: object = field(default_factory=DirectSupply)


@dataclass(frozen=True)
class FilmSolution:
    """A solved film. Fields are cell values on ``grid`` (shape n_theta × n_z) unless stated.

    pressure [Pa] (Gümbel: the full-film field, negative where it would cavitate), fill ϑ [-], recess_pressures
    [Pa], supply_flows into each recess [m³/s], force on the journal (F_x, F_y) [N], edge_outflow out of both ends
    [m³/s], volume_rate [m³/s] (the rate at which the oil in the gap grows: Σ ϑ ḣ dA; mass balance: supply =
    edge outflow + volume rate), friction_torque [N m] (resisting a positive
    speed), iterations of the active set / restrictor loop.
    """

    grid: FilmGrid
    state: JournalState
    cavitation: str
    pressure: np.ndarray
    fill: np.ndarray
    recess_pressures: np.ndarray
    supply_flows: np.ndarray
    force: np.ndarray
    edge_outflow: float
    volume_rate: float
    friction_torque: float
    iterations: int

    @property
    def load_capacity(self) -> float:
        """|F| [N]."""
        return float(np.hypot(*self.force))

    @property
    def attitude_angle(self) -> float:
        """Angle [deg] from the load the film carries (−F) to the eccentricity vector, positive in the sense of
        rotation (NaN at zero eccentricity or zero load)."""
        load = -self.force
        e_x, e_y = self.state.eccentricity
        if math.hypot(e_x, e_y) == 0 or not np.any(load):
            return math.nan
        angle = math.degrees(math.atan2(load[0] * e_y - load[1] * e_x, load[0] * e_x + load[1] * e_y))
        return angle if self.state.speed >= 0 else -angle

    @property
    def supply_flow(self) -> float:
        """Total inflow of all recesses [m³/s]."""
        return float(self.supply_flows.sum())

    @property
    def friction_power(self) -> float:
        """T Ω [W]."""
        return self.friction_torque * self.state.speed

    @property
    def load_pressure(self) -> np.ndarray:
        """The pressure that carries load [Pa]: the field with Gümbel's negative part dropped."""
        return np.maximum(self.pressure, 0.0)


@dataclass(frozen=True)
class _Balance:
    """Each unknown's net outflow to the film, A p + B (1−ϑ) + s, and the pieces to report flows."""

    unknown: np.ndarray
    n_land: int
    pressure_flux: sp.csr_matrix
    fill_flux: sp.csr_matrix
    constant: np.ndarray
    edge_conductance: np.ndarray
    squeeze: np.ndarray


def _assemble(grid: FilmGrid, state: JournalState) -> _Balance:
    bearing = grid.bearing
    mu, radius = bearing.viscosity, bearing.radius
    nt, nz = grid.n_theta, grid.n_z
    dx, dz = radius * grid.d_theta, grid.dz
    land = grid.recess_of < 0
    n_land = int(np.count_nonzero(land))
    unknown = np.empty((nt, nz), dtype=np.int64)
    unknown[land] = np.arange(n_land)
    unknown[~land] = n_land + grid.recess_of[~land]
    n = n_land + grid.recess_count
    rows, cols, values = [], [], []
    fill_rows, fill_cols, fill_values = [], [], []
    constant = np.zeros(n)

    def couple(a, b, conductance):
        rows.extend((a, a, b, b))
        cols.extend((a, b, b, a))
        values.extend((conductance, -conductance, conductance, -conductance))

    # θ-faces: face i lies between cell i-1 (west) and cell i (east), periodic.
    west, east = unknown[np.arange(nt) - 1], unknown
    at_recess = ~land[np.arange(nt) - 1] | ~land
    h_face = np.broadcast_to(grid.land_film(grid.theta_faces, state.eccentricity)[:, None], (nt, nz))
    conductance = h_face**3 / (12 * mu) * dz / np.where(at_recess, dx / 2, dx)
    apart = west != east
    couple(west[apart], east[apart], conductance[apart])
    couette = 0.5 * state.speed * radius * h_face[apart] * dz
    upwind = np.where(state.speed >= 0, west[apart], east[apart])
    np.add.at(constant, west[apart], couette)
    np.add.at(constant, east[apart], -couette)
    fill_rows.extend((west[apart], east[apart]))
    fill_cols.extend((upwind, upwind))
    fill_values.extend((-couette, couette))

    # interior z-faces between (i, j) and (i, j+1)
    h_cell = np.broadcast_to(grid.land_film(grid.theta, state.eccentricity)[:, None], (nt, nz))
    low, high = unknown[:, :-1], unknown[:, 1:]
    at_recess = ~land[:, :-1] | ~land[:, 1:]
    conductance = h_cell[:, :-1] ** 3 / (12 * mu) * dx / np.where(at_recess, dz / 2, dz)
    apart = low != high
    couple(low[apart], high[apart], conductance[apart])

    # ends at ambient pressure, half a cell from the outermost centres
    edge_cells = np.concatenate([unknown[:, 0], unknown[:, -1]])
    edge_conductance = np.zeros(n)
    np.add.at(edge_conductance, edge_cells, np.concatenate([h_cell[:, 0], h_cell[:, -1]]) ** 3 / (12 * mu) * dx
              / (dz / 2))

    # squeeze: the cell's volume shrinks at area · ḣ
    squeeze = np.zeros(n)
    np.add.at(squeeze, unknown.ravel(),
              np.broadcast_to(grid.film_rate(grid.theta, state.eccentricity_rate)[:, None] * dx * dz, (nt, nz)).ravel())
    constant += squeeze
    flat = lambda parts: np.concatenate([np.ravel(p) for p in parts])  # noqa: E731
    pressure_flux = sp.csr_matrix((flat(values), (flat(rows), flat(cols))), shape=(n, n))
    pressure_flux = pressure_flux + sp.diags(edge_conductance)
    fill_flux = sp.csr_matrix((np.concatenate([flat(fill_values), -squeeze]),
                               (np.concatenate([flat(fill_rows), np.arange(n)]),
                                np.concatenate([flat(fill_cols), np.arange(n)]))), shape=(n, n))
    return _Balance(unknown, n_land, pressure_flux.tocsr(), fill_flux.tocsr(), constant, edge_conductance, squeeze)


def solve_film(bearing: JournalBearing, state: JournalState, supply: Supply | None = None,
               grid: FilmGrid | tuple[int, int] = (120, 30), cavitation: str = "gumbel") -> FilmSolution:
    """Solve the film of ``bearing`` in ``state``; ``supply`` feeds the recesses (required when it has some).

    Raises ValueError on inconsistent input, :class:`FilmNotConverged` if the iterations do not settle.
    """
    if cavitation not in CAVITATION:
        raise ValueError(f"cavitation = {cavitation!r}: must be one of {', '.join(CAVITATION)}")
    if not isinstance(grid, FilmGrid):
        grid = FilmGrid.build(bearing, *grid)
    eccentricity = math.hypot(*state.eccentricity)
    if not eccentricity < bearing.radial_clearance:
        raise ValueError(f"eccentricity = {eccentricity!r} m: must be < the radial clearance "
                         f"{bearing.radial_clearance:g} m (eccentricity ratio < 1)")
    if grid.recess_count and supply is None:
        raise ValueError("supply = None: a bearing with recesses needs a supply pressure and restrictor")
    if cavitation == "jfo" and not _has_oil_source(grid, supply):
        raise ValueError("cavitation = 'jfo': the mass-conserving film needs an oil source (recesses fed from a supply "
                         "pressure > 0, a constant flow, or a supply groove held at its pressure); without one every "
                         "cavitated film with ϑh constant along the bore solves it (a starved bearing carries nothing)")
    balance = _assemble(grid, state)
    n = balance.pressure_flux.shape[0]
    recess = balance.n_land + np.arange(grid.recess_count)
    fixed = np.zeros(n, dtype=bool)
    if grid.recess_count and isinstance(supply.restrictor, DirectSupply):
        fixed[recess] = True
    full = np.ones(n, dtype=bool)
    unknowns = np.zeros(n)
    unknowns[recess] = supply.pressure / 2 if grid.recess_count else 0.0
    visited, iteration = {full.tobytes()}, 0
    for iteration in range(1, MAX_ITERATIONS + 1):
        previous = unknowns
        unknowns = _solve_linear(balance, supply, bearing, recess, fixed, full, unknowns)
        if not np.all(np.isfinite(unknowns)):  # a singular system: an active set with no steady solution
            break
        if cavitation == "jfo":
            # p < 0 in a full cell or 1 − ϑ < 0 in a cavitated one violates complementarity; round-off is not a sign
            scale = np.where(full, max(np.abs(unknowns[full]).max(initial=0.0), 1.0), 1.0)
            switched = (unknowns < -1e-12 * scale) & ~fixed
        else:
            switched = np.zeros(n, dtype=bool)
        # the recess pressures stop changing, to round-off of the larger of the supply and the recess pressures
        tolerance = 1e-10 * max(abs(supply.pressure), np.abs(unknowns[recess]).max(initial=0.0), 1.0) \
            if grid.recess_count else 0.0
        settled = np.abs(unknowns[recess] - previous[recess]) <= tolerance \
            if grid.recess_count and not fixed[recess].all() else np.ones(0, dtype=bool)
        if not switched.any() and (settled.all() or _linear_restrictor(supply)):
            pressure = np.where(full, unknowns, 0.0)
            void = np.where(full, 0.0, unknowns)
            return _solution(grid, state, cavitation, balance, supply, pressure, void, iteration)
        if switched.any():
            full = np.where(switched, ~full, full)
            if full.tobytes() in visited:  # the active set cycles
                break
            visited.add(full.tobytes())
    solved = _globalised(balance, supply, bearing, recess, fixed, cavitation == "jfo")
    if solved is not None:
        return _solution(grid, state, cavitation, balance, supply, *solved, iteration)
    raise FilmNotConverged(f"the film did not settle ({cavitation} cavitation): the iterations cycled, met a singular "
                           f"system or took more than {MAX_ITERATIONS}")


def _solve_linear(balance, supply, bearing, recess, fixed, full, unknowns) -> np.ndarray:
    """The unknowns (p in full cells, 1 − ϑ in cavitated ones) of the balance with this active set and the
    restrictors linearised about ``unknowns``; non-finite where the system is singular."""
    flow, slope = _restrictor_inflow(supply, bearing, recess, fixed, unknowns)
    restrictor_slope, restrictor_constant = -slope, -(flow - slope * unknowns)
    system = (balance.pressure_flux + sp.diags(restrictor_slope)) @ sp.diags(full.astype(float)) \
        + balance.fill_flux @ sp.diags((~full).astype(float))
    right = -(balance.constant + restrictor_constant)
    if fixed.any():
        system = sp.diags((~fixed).astype(float)) @ system + sp.diags(fixed.astype(float))
        right[fixed] = supply.pressure
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", MatrixRankWarning)  # reported as non-finite unknowns
        return spsolve(system.tocsc(), right)


def _restrictor_inflow(supply, bearing, recess, fixed, pressure) -> tuple[np.ndarray, np.ndarray]:
    """Every unknown's restrictor inflow q [m³/s] and its slope dq/dp at the pressures ``pressure`` [Pa]: the recesses'
    (unless all are held at the supply pressure), zero elsewhere."""
    flow, slope = np.zeros(pressure.size), np.zeros(pressure.size)
    if recess.size and not fixed[recess].all():
        for k in recess:
            flow[k], slope[k] = supply.restrictor.inflow(supply.pressure, pressure[k], bearing.viscosity,
                                                         bearing.density)
    return flow, slope


def _globalised(balance, supply, bearing, recess, fixed, cavitating: bool):
    """(pressure, void) by :func:`.newton.solve_balance`, started from the full film (the restrictors linearised about
    half the supply pressure); for the mass-conserving film with linear restrictors then, with the cavitated cells it
    found, the linear system once more, kept where it violates no sign (it is exact where it holds)."""
    n = balance.pressure_flux.shape[0]

    def inflow(pressure):
        return _restrictor_inflow(supply, bearing, recess, fixed, pressure)

    held = supply.pressure if fixed.any() else 0.0
    around = np.full(n, supply.pressure / 2 if supply is not None else 0.0)
    start = _solve_linear(balance, supply, bearing, recess, fixed, np.ones(n, dtype=bool), around)
    start = np.where(np.isfinite(start), start, 0.0)
    scale = max(np.abs(start).max(initial=0.0), abs(held), 1.0)
    solved = solve_balance(balance.pressure_flux, balance.fill_flux, balance.constant, inflow, fixed, held, start, scale,
                           cavitating)
    if solved is None or not cavitating or not _linear_restrictor(supply):
        return solved
    pressure, void = solved
    full = (void <= 0) | fixed
    polished = _solve_linear(balance, supply, bearing, recess, fixed, full, pressure)
    round_off = 1e-12 * np.where(full, max(np.abs(polished[full]).max(initial=0.0), 1.0), 1.0)
    if np.all(np.isfinite(polished)) and not np.any((polished < -round_off) & ~fixed):
        return np.where(full, polished, 0.0), np.where(full, 0.0, polished)
    return pressure, void


def _has_oil_source(grid: FilmGrid, supply: Supply | None) -> bool:
    """Whether oil enters the film: it has recesses, and their supply feeds them (:func:`.restrictors.feeds_oil`)."""
    return bool(grid.recess_count) and feeds_oil(type(supply.restrictor), supply.pressure)


def _linear_restrictor(supply: Supply | None) -> bool:
    return supply is None or is_linear(supply.restrictor)


def _solution(grid, state, cavitation, balance, supply, pressure, void, iterations) -> FilmSolution:
    bearing = grid.bearing
    radius, dx, dz = bearing.radius, bearing.radius * grid.d_theta, grid.dz
    cell_pressure = pressure[balance.unknown]
    fill = 1.0 - void[balance.unknown]
    outflow = balance.pressure_flux @ pressure + balance.fill_flux @ void + balance.constant
    recess = balance.n_land + np.arange(grid.recess_count)
    load_pressure = np.maximum(cell_pressure, 0.0)
    cos, sin = np.cos(grid.theta)[:, None], np.sin(grid.theta)[:, None]
    force = -np.array([np.sum(load_pressure * cos), np.sum(load_pressure * sin)]) * dx * dz
    h = grid.land_film(grid.theta, state.eccentricity)[:, None] + np.where(
        grid.recess_of >= 0, bearing.recesses.depth if bearing.recesses else 0.0, 0.0)
    gradient = (np.roll(load_pressure, -1, axis=0) - np.roll(load_pressure, 1, axis=0)) / (2 * dx)
    shear_fill = fill if cavitation == "jfo" else 1.0
    shear = bearing.viscosity * state.speed * radius * shear_fill / h + h / 2 * gradient
    return FilmSolution(
        grid=grid, state=state, cavitation=cavitation, pressure=cell_pressure, fill=fill,
        recess_pressures=pressure[recess], supply_flows=outflow[recess],
        force=force, edge_outflow=float(balance.edge_conductance @ pressure),
        volume_rate=float(balance.squeeze @ (1.0 - void)),
        friction_torque=float(np.sum(shear) * radius * dx * dz), iterations=iterations)
