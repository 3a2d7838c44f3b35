r"""A numerical, isothermal, steady elastohydrodynamic (EHL) line contact: the reference the film formulas of
:mod:`bearing_mbs.contact.ehl` are checked against.

A roller of reduced radius R [m] (in the rolling direction) on a half-space of reduced modulus
:math:`E' = 2/[(1-\nu_1^2)/E_1 + (1-\nu_2^2)/E_2]` [Pa] carries the load per unit length w [N/m]; both surfaces
move at the mean entrainment speed u [m/s] (pure rolling) through an oil of viscosity :math:`\eta_0` [Pa s] at
ambient pressure and pressure–viscosity coefficient α [1/Pa]. Reynolds' equation for the pressure p(x) [Pa], the
film h(x) [m] and the density ρ(p),

.. math:: \frac{\mathrm d}{\mathrm dx}\Bigl(\frac{\rho h^3}{12\eta}\frac{\mathrm dp}{\mathrm dx}\Bigr)
          = u\,\frac{\mathrm d(\rho h)}{\mathrm dx},

with the film of two elastic cylinders (the deflection of an elastic half-space under a line load, K. L. Johnson,
*Contact Mechanics*, 1985, eq. 2.25c)

.. math:: h(x) = h_0 + \frac{x^2}{2R} - \frac{4}{\pi E'}\int p(s)\,\ln|x - s|\,\mathrm ds,

and the load balance :math:`\int p\,\mathrm dx = w`, which fixes :math:`h_0` (it absorbs the deflection's
undetermined constant). Ambient pressure p = 0 at the inlet; Reynolds' (Swift–Stieber) outlet condition as the
complementarity :math:`p \ge 0`, :math:`\mathcal A(p) \ge 0`, :math:`p\,\mathcal A(p) = 0` with
:math:`\mathcal A(p) = -(\rho h^3 p'/12\eta)' + u(\rho h)'` (the film ruptures where the pressure would turn
negative and stays at p = 0 downstream; p = p' = 0 at the rupture point in the limit of a fine grid).

Lubricant (the properties of the numerical solutions that Pan & Hamrock fitted; their fits are therefore checked
against the problem they were fitted to):

* viscosity of C. J. A. Roelands (1966) in Hamrock's form (B. J. Hamrock, *Fundamentals of Fluid Film
  Lubrication*, McGraw-Hill, 1994, eq. 4.10), ``viscosity="roelands"`` (the default):
  :math:`\eta = \eta_0\,(\eta_\infty/\eta_0)^{1 - (1 + p/c_p)^{Z}}`, :math:`\eta_\infty = 6.31\times10^{-5}`
  Pa s, :math:`c_p = 1.96\times10^{8}` Pa, with the index Z chosen so that the viscosity's slope at ambient
  pressure is α: :math:`Z = \alpha c_p/\ln(\eta_0/\eta_\infty)`; or Barus's :math:`\eta = \eta_0 e^{\alpha p}`
  (``viscosity="barus"``, the law of Dowson & Higginson's own solutions);
* density of D. Dowson and G. R. Higginson (*Elasto-Hydrodynamic Lubrication*, 1966/1977):
  :math:`\rho/\rho_0 = 1 + 0.6\times10^{-9}p/(1 + 1.7\times10^{-9}p)`, p in Pa.

Dimensionless form (C. H. Venner, A. A. Lubrecht, *Multilevel Methods in Lubrication*, Elsevier, 2000, ch. 6):
Hertz's half-width :math:`b = (8wR/\pi E')^{1/2}` and peak pressure :math:`p_h = (wE'/2\pi R)^{1/2}`; X = x/b,
P = p/p_h, :math:`H = hR/b^2`, :math:`\bar\rho = \rho/\rho_0`, :math:`\bar\eta = \eta/\eta_0`:

.. math:: \frac{\mathrm d}{\mathrm dX}\Bigl(\varepsilon\frac{\mathrm dP}{\mathrm dX}\Bigr)
          - \frac{\mathrm d(\bar\rho H)}{\mathrm dX} = 0,\quad
          \varepsilon = \frac{\bar\rho H^3}{\bar\eta\lambda},\quad \lambda = \frac{12\eta_0 u R^2}{b^3 p_h},\qquad
          H = H_0 + \frac{X^2}{2} - \frac1\pi\int P(S)\ln|X - S|\,\mathrm dS,\qquad \int P\,\mathrm dX = \frac\pi2.

In the groups of :mod:`bearing_mbs.contact.ehl` (U = η0 u/E'R, W = w/E'R, G = αE'), :math:`h/R = 8WH/\pi`;
Moes's load and lubricant parameters are :math:`M = W(2U)^{-1/2}` and :math:`L = G(2U)^{1/4}`.

Discretisation: a finite-volume scheme on a non-uniform grid (uniform, spacing ℓ/n, through the pressure zone,
ℓ = max(1, (2H_c)^{1/2}) the width of the pressure zone in units of b — Hertz's 1 in the EHL regime, Martin's
:math:`(2Rh_0)^{1/2}` in the rigid one; the spacing grows geometrically towards the inlet). The Poiseuille flux
across a face takes the arithmetic mean of ε at its two nodes; the Couette flux ρH is upwinded to second order
(linear extrapolation from the two upstream nodes), which stays stable where ε vanishes (the Hertz zone, where the
equation turns hyperbolic). The pressure is piecewise linear between nodes; its deflection is integrated exactly
(dense influence matrix) and the load is the exact integral of the same interpolant.

Solution: all unknowns (the nodal pressures and H0) by the semismooth Newton method on
:math:`\min(P_i, \mathcal A_i/d_i) = 0` (d_i the diagonal of the Jacobian of :math:`\mathcal A_i`) and the load
balance, with the dense Jacobian (elastic coupling included) factorised by LU (SuperLU) and the step damped by a backtracking
line search on the residual. The start is Hertz's pressure; the lubricant's piezoviscosity is switched on by a
continuation in α (from isoviscous to the given α) whose steps are halved where Newton fails. If the solved
pressure zone is wider than the grid assumed, the grid is rebuilt and the contact re-solved.

References: B. J. Hamrock, S. R. Schmid, B. O. Jacobson, *Fundamentals of Fluid Film Lubrication*, 2nd ed.,
Marcel Dekker, 2004, ch. 18 and 21 (the rectangular conjunction); C. H. Venner, A. A. Lubrecht (2000, above);
P. Pan, B. J. Hamrock, "Simple formulas for performance parameters used in elastohydrodynamically lubricated line
contacts", J. Tribol. 111 (1989) 246–251; H. M. Martin, "Lubrication of gear teeth", Engineering 102 (1916)
119–121 (the rigid, isoviscous limit :math:`w = 4.895\,\eta_0 u R/h_0`).

Assumptions: isothermal, Newtonian, pure rolling, smooth surfaces, fully flooded inlet (the inlet is many
pressure-zone widths upstream, ``LineSettings.inlet``), steady state, infinitely long contact.
"""

from __future__ import annotations

import logging
import math
from dataclasses import dataclass, replace

import numpy as np
import scipy.sparse as sp
from scipy.sparse.linalg import splu

log = logging.getLogger(__name__)

#: Viscosity–pressure laws by name.
VISCOSITY_LAWS = ("roelands", "barus")
#: Roelands's limiting viscosity η∞ [Pa s] and pressure constant c_p [Pa] (Hamrock 1994, eq. 4.10).
ROELANDS_LIMIT, ROELANDS_PRESSURE = 6.31e-5, 1.96e8
#: Dowson–Higginson's density constants [1/Pa]: ρ/ρ0 = 1 + a p/(1 + c p).
DOWSON_HIGGINSON_DENSITY = (0.6e-9, 1.7e-9)
#: Martin's rigid, isoviscous load coefficient, w = MARTIN η0 u R/h0 (Reynolds' outlet condition).
MARTIN = 4.895
#: Moes's load parameter M from which the iteration starts from Hertz's pressure rather than the rigid film.
HERTZIAN_M = 20.0
#: Martin's rupture point x_c/(2R h0)^(1/2) of the rigid, isoviscous film.
MARTIN_RUPTURE = 0.4751
#: Nodes past the rupture point started full in each Newton solve (see :func:`_newton`).
FRONTIER = 30
#: The continuation's first step in s (doubled after each Newton solve that takes fewer than 8 iterations).
FIRST_STEP = 0.25


class LineContactNotConverged(RuntimeError):
    """Newton's method did not meet ``LineSettings.tolerance`` within ``LineSettings.iterations``, even with the
    continuation's smallest step."""


@dataclass(frozen=True)
class LineContact:
    """The contact: entrainment ``speed`` u [m/s] > 0 (mean of the two surfaces), ``load`` w per unit length [N/m]
    > 0, ``viscosity`` η0 [Pa s] > 0 at ambient pressure, ``pressure_viscosity`` α [1/Pa] >= 0,
    ``reduced_modulus`` E' [Pa] > 0 (:func:`~bearing_mbs.contact.line_contact.reduced_modulus`), reduced ``radius``
    R [m] > 0, ``viscosity_law`` in :data:`VISCOSITY_LAWS` and ``compressible`` (Dowson–Higginson density, else
    ρ = ρ0)."""

    speed: float
    load: float
    viscosity: float
    pressure_viscosity: float
    reduced_modulus: float
    radius: float
    viscosity_law: str = "roelands"
    compressible: bool = True

    def __post_init__(self):
        for name in ("speed", "load", "viscosity", "reduced_modulus", "radius"):
            _require(name, getattr(self, name), lambda v: v > 0, "a finite number > 0")
        _require("pressure_viscosity", self.pressure_viscosity, lambda v: 0 <= v < 1e-6,
                 "a finite number in [0, 1e-6) 1/Pa")
        if self.viscosity_law not in VISCOSITY_LAWS:
            raise ValueError(f"viscosity_law = {self.viscosity_law!r}: must be one of {VISCOSITY_LAWS}")
        if self.viscosity_law == "roelands" and not self.viscosity > ROELANDS_LIMIT:
            raise ValueError(f"viscosity = {self.viscosity!r}: Roelands's law needs η0 > η∞ = {ROELANDS_LIMIT} Pa s")

    @property
    def half_width(self) -> float:
        """Hertz's b = (8wR/πE')^(1/2) [m]."""
        return math.sqrt(8 * self.load * self.radius / (math.pi * self.reduced_modulus))

    @property
    def hertz_pressure(self) -> float:
        """Hertz's p_h = (wE'/2πR)^(1/2) [Pa]."""
        return math.sqrt(self.load * self.reduced_modulus / (2 * math.pi * self.radius))

    @property
    def groups(self) -> tuple[float, float, float]:
        """(U, G, W) = (η0 u/E'R, αE', w/E'R) [-]."""
        scale = self.reduced_modulus * self.radius
        return self.viscosity * self.speed / scale, self.pressure_viscosity * self.reduced_modulus, self.load / scale

    @property
    def moes(self) -> tuple[float, float]:
        """Moes's (M, L) = (W(2U)^(-1/2), G(2U)^(1/4)) [-]."""
        u, g, w = self.groups
        return w / math.sqrt(2 * u), g * (2 * u) ** 0.25

    @property
    def speed_number(self) -> float:
        """λ = 12 η0 u R²/(b³ p_h) [-]."""
        return 12 * self.viscosity * self.speed * self.radius**2 / (self.half_width**3 * self.hertz_pressure)


@dataclass(frozen=True)
class LineSettings:
    """Numerics: ``nodes`` n > 0 per pressure-zone width ℓ in the uniform part of the grid (spacing ℓ/n; the
    inlet's spacing grows by 1 + ``stretch``/n per node); the grid spans X from −``inlet`` ℓ to ``outlet`` ℓ
    (``inlet`` >= 3, ``outlet`` >= 1.2); Newton stops when the largest scaled residual is below ``tolerance``
    (> 0) or gives up after ``iterations``; the α continuation takes at most ``continuation_steps`` halvings."""

    nodes: int = 100
    inlet: float = 20.0
    outlet: float = 1.6
    stretch: float = 4.0
    tolerance: float = 1e-9
    iterations: int = 60
    continuation_steps: int = 12

    def __post_init__(self):
        _require("nodes", self.nodes, lambda v: v >= 10 and float(v).is_integer(), "an integer >= 10")
        _require("inlet", self.inlet, lambda v: v >= 3, "a finite number >= 3 (pressure-zone widths)")
        _require("outlet", self.outlet, lambda v: v >= 1.2, "a finite number >= 1.2 (pressure-zone widths)")
        _require("stretch", self.stretch, lambda v: 0 <= v <= 20, "a finite number in [0, 20]")
        _require("tolerance", self.tolerance, lambda v: 0 < v < 1e-3, "a finite number in (0, 1e-3)")
        _require("iterations", self.iterations, lambda v: v >= 1 and float(v).is_integer(), "an integer >= 1")
        _require("continuation_steps", self.continuation_steps, lambda v: v >= 0 and float(v).is_integer(),
                 "an integer >= 0")


@dataclass(frozen=True)
class LineContactSolution:
    """A solved contact. ``x`` [m] the grid (0 at the undeformed gap's narrowest point), ``pressure`` p [Pa] and
    ``film`` h [m] on it; ``central_film`` h(x = 0) and ``minimum_film`` min h [m]; ``rigid_gap`` h0 [m] (the film
    without deflection's constant); ``iterations`` Newton iterations in all; ``residual`` the largest scaled
    residual at the end [-]; ``load_error`` (∫p dx − w)/w [-]."""

    contact: LineContact
    x: np.ndarray
    pressure: np.ndarray
    film: np.ndarray
    central_film: float
    minimum_film: float
    iterations: int
    residual: float
    load_error: float

    @property
    def dimensionless(self) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """(X = x/b, P = p/p_h, H = hR/b²) [-]."""
        c = self.contact
        b = c.half_width
        return self.x / b, self.pressure / c.hertz_pressure, self.film * c.radius / b**2

    @property
    def film_groups(self) -> tuple[float, float]:
        """(H_c, H_min) = (h_c/R, h_min/R) [-], the groups of :mod:`bearing_mbs.contact.ehl`."""
        return self.central_film / self.contact.radius, self.minimum_film / self.contact.radius


def _require(name, value, ok, allowed):
    if not (isinstance(value, (int, float)) and not isinstance(value, bool) and math.isfinite(value) and ok(value)):
        raise ValueError(f"{name} = {value!r}: must be {allowed}")


# --- the lubricant -------------------------------------------------------------------------------------------------

def _viscosity(contact: LineContact, pressure: np.ndarray, alpha: float) -> tuple[np.ndarray, np.ndarray]:
    """(ln η/η0, d ln η/dp [1/Pa]) at ``pressure`` [Pa] with pressure–viscosity coefficient ``alpha``."""
    p = np.maximum(pressure, 0.0)
    if contact.viscosity_law == "barus":
        return alpha * p, np.full_like(p, alpha)
    depth = math.log(contact.viscosity / ROELANDS_LIMIT)
    index = alpha * ROELANDS_PRESSURE / depth
    ratio = 1.0 + p / ROELANDS_PRESSURE
    return depth * (ratio**index - 1.0), alpha * ratio ** (index - 1.0)


def _density(contact: LineContact, pressure: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """(ρ/ρ0, d(ρ/ρ0)/dp [1/Pa])."""
    if not contact.compressible:
        return np.ones_like(pressure), np.zeros_like(pressure)
    a, c = DOWSON_HIGGINSON_DENSITY
    p = np.maximum(pressure, 0.0)
    return 1.0 + a * p / (1.0 + c * p), a / (1.0 + c * p) ** 2


# --- the grid and the elastic film ---------------------------------------------------------------------------------

def _grid(width: float, settings: LineSettings) -> np.ndarray:
    """Nodes X: uniform spacing width/n over [−1.5 width, outlet·width], stretched geometrically to −inlet·width."""
    step = width / settings.nodes
    start, end = -1.5 * width, settings.outlet * width
    core = start + step * np.arange(math.ceil((end - start) / step) + 1)
    ratio, inlet, spacing, x = 1.0 + settings.stretch / settings.nodes, -settings.inlet * width, step, start
    upstream = []
    while x > inlet:
        spacing *= ratio
        x -= spacing
        upstream.append(max(x, inlet))
    return np.concatenate([upstream[::-1], core])


def _log_primitives(t):
    """(∫ ln|t| dt, ∫ t ln|t| dt) at t, continuous through t = 0."""
    safe = np.where(t == 0.0, 1.0, np.abs(t))
    log_t = np.log(safe)
    return t * log_t - t, 0.5 * t * t * log_t - 0.25 * t * t


def _influence(x: np.ndarray) -> np.ndarray:
    r"""K with (K P)_j = −(1/π)∫ P(S) ln|X_j − S| dS for P piecewise linear between the nodes ``x``: exact."""
    left, right = x[:-1], x[1:]
    length = right - left
    t_a, t_b = left[None, :] - x[:, None], right[None, :] - x[:, None]
    f0_a, f1_a = _log_primitives(t_a)
    f0_b, f1_b = _log_primitives(t_b)
    whole = f0_b - f0_a                                   # ∫ ln|X − S| over the segment
    ramp = (f1_b - f1_a - t_a * whole) / length[None, :]  # ∫ (S − s_a)/L ln|X − S|
    k = np.zeros((x.size, x.size))
    k[:, :-1] += whole - ramp
    k[:, 1:] += ramp
    return -k / math.pi


def _load_weights(x: np.ndarray) -> np.ndarray:
    """Trapezoidal weights: the exact integral of the piecewise-linear interpolant."""
    d = np.diff(x)
    w = np.zeros(x.size)
    w[:-1] += d / 2
    w[1:] += d / 2
    return w


# --- the discrete equations ----------------------------------------------------------------------------------------

@dataclass(frozen=True)
class _Problem:
    contact: LineContact
    x: np.ndarray
    influence: np.ndarray
    weights: np.ndarray
    upwind: tuple[np.ndarray, np.ndarray]  # Couette face value = c1 (ρH)_i + c2 (ρH)_{i-1} on face i+1/2


def _problem(contact: LineContact, x: np.ndarray) -> _Problem:
    dx = np.diff(x)
    c1, c2 = np.ones(dx.size), np.zeros(dx.size)
    slope = 0.5 * dx[1:] / dx[:-1]  # linear extrapolation to face i+1/2 from nodes i-1, i (i >= 1)
    c1[1:] += slope
    c2[1:] -= slope
    return _Problem(contact, x, _influence(x), _load_weights(x), (c1, c2))


def _film(problem: _Problem, pressure: np.ndarray, h0: float) -> np.ndarray:
    return h0 + 0.5 * problem.x**2 + problem.influence @ pressure


def _equations(problem: _Problem, pressure: np.ndarray, h0: float, alpha: float, jacobian: bool):
    """The film H and A_i (interior nodes) of Reynolds' equation, with dA/d(P, H0) if ``jacobian``."""
    contact, x = problem.contact, problem.x
    ph = contact.hertz_pressure
    film = _film(problem, pressure, h0)
    log_eta, dlog_eta = _viscosity(contact, pressure * ph, alpha)
    rho, drho = _density(contact, pressure * ph)
    inv_eta = np.exp(-log_eta) / contact.speed_number
    eps = rho * film**3 * inv_eta
    dx = np.diff(x)
    eps_face = 0.5 * (eps[:-1] + eps[1:])
    gradient = np.diff(pressure) / dx
    mass = rho * film
    c1, c2 = problem.upwind
    couette = c1 * mass[:-1] + c2 * np.concatenate([[0.0], mass[:-2]])
    flux = eps_face * gradient - couette
    balance = flux[:-1] - flux[1:]  # A_i at nodes 1..N-2
    if not jacobian:
        return film, balance, None
    # ∂ε/∂P (local, through ρ and η) and ∂ε/∂H; ∂(ρH)/∂P, ∂(ρH)/∂H = ρ
    deps_dp = eps * (drho / rho - dlog_eta) * ph * (pressure > 0)
    deps_dh = 3 * rho * film**2 * inv_eta
    k = problem.influence
    d_eps = deps_dh[:, None] * k
    d_eps[np.diag_indices_from(d_eps)] += deps_dp
    d_mass = rho[:, None] * k
    d_mass[np.diag_indices_from(d_mass)] += drho * ph * film * (pressure > 0)
    n = x.size
    d_flux = 0.5 * (d_eps[:-1] + d_eps[1:]) * gradient[:, None]
    idx = np.arange(n - 1)
    d_flux[idx, idx] -= eps_face / dx
    d_flux[idx, idx + 1] += eps_face / dx
    d_flux -= c1[:, None] * d_mass[:-1]
    d_flux[1:] -= c2[1:, None] * d_mass[:-2]
    d_balance = d_flux[:-1] - d_flux[1:]
    # H0 enters every H with slope 1
    e_h0 = 0.5 * (deps_dh[:-1] + deps_dh[1:]) * gradient - (c1 * rho[:-1] + c2 * np.concatenate([[0.0], rho[:-2]]))
    return film, balance, (d_balance, e_h0[:-1] - e_h0[1:])


def _system(problem: _Problem, pressure: np.ndarray, h0: float, alpha: float, fixed_gap: bool = False,
            scale: np.ndarray | None = None):
    r"""Residual F, the film H, the row scale d and (unless ``scale`` is given, which then is d) the Jacobian J.

    F: the complementarity :math:`\min(P_i, \mathcal A_i/d_i)` at the interior nodes (d_i the diagonal of
    :math:`\partial\mathcal A_i/\partial P`), P = 0 at both ends, and the load (or H0 held, ``fixed_gap``)."""
    film, balance, derivatives = _equations(problem, pressure, h0, alpha, scale is None)
    n = pressure.size
    inner = np.arange(1, n - 1)
    if scale is None:
        d_balance, d_h0 = derivatives
        scale = np.abs(d_balance[np.arange(n - 2), inner])
        scale = np.where(scale > 0, scale, 1.0)
    scaled = balance / scale
    active = pressure[inner] <= scaled  # the film has ruptured here: P = 0 is the equation
    residual = np.empty(n + 1)
    residual[0], residual[n - 1] = pressure[0], pressure[n - 1]
    residual[inner] = np.where(active, pressure[inner], scaled)
    residual[n] = 0.0 if fixed_gap else problem.weights @ pressure - math.pi / 2
    if derivatives is None:
        return residual, film, scale, None
    jac = np.zeros((n + 1, n + 1))
    jac[0, 0] = jac[n - 1, n - 1] = 1.0
    jac[inner, :n] = d_balance / scale[:, None]
    jac[inner, n] = d_h0 / scale
    rows = inner[active]
    jac[rows, :] = 0.0
    jac[rows, rows] = 1.0
    if fixed_gap:
        jac[n, n] = 1.0
    else:
        jac[n, :n] = problem.weights
    return residual, film, scale, jac


def _newton(problem: _Problem, pressure: np.ndarray, h0: float, alpha: float, settings: LineSettings,
            fixed_gap: bool = False):
    """Semismooth Newton damped by backtracking on max|F|: (P, H0, iterations, max|F|), or None where it does not
    converge within ``settings.iterations``.

    The rupture point moves downstream by at most one node per iteration (a node held at P = 0 fills only once
    its upstream neighbour's pressure reaches it), but upstream by many (every node whose step goes below zero is
    held at the next). So the iteration starts with the film full for :data:`FRONTIER` nodes past the rupture
    (a pressure of 1e-9 there) and lets the rupture come back."""
    pressure = pressure.copy()
    full = np.flatnonzero(pressure > 0)
    if full.size:
        end = full[-1]
        pressure[end + 1:min(end + 1 + FRONTIER, pressure.size - 1)] = 1e-9

    def merit(step, damping, scale):
        trial_p, trial_h0 = pressure + damping * step[:-1], h0 + damping * step[-1]
        trial, film, _, _ = _system(problem, trial_p, trial_h0, alpha, fixed_gap, scale)
        value = np.max(np.abs(trial))
        return (value if np.isfinite(value) and np.min(film) > 0 else np.inf), trial_p, trial_h0

    def newton_step(jac, residual):
        # SuperLU on the (dense, elastically coupled) Jacobian: single-threaded, so a loaded machine does not
        # oversubscribe a threaded BLAS (LAPACK's getrf was 10x slower than this in a shared test run)
        try:
            step = splu(sp.csc_matrix(jac)).solve(-residual)
        except RuntimeError:  # singular
            return None
        return step if np.all(np.isfinite(step)) else None

    for iteration in range(1, settings.iterations + 1):
        residual, _, scale, jac = _system(problem, pressure, h0, alpha, fixed_gap)
        norm = np.max(np.abs(residual))
        if norm < settings.tolerance:
            return pressure, h0, iteration - 1, norm
        step = newton_step(jac, residual)
        if step is None:
            return None
        damping = 1.0
        while damping > 1e-4:
            value, trial_p, trial_h0 = merit(step, damping, scale)
            if value < (1 - 1e-4 * damping) * norm:
                break
            damping *= 0.5
        else:
            return None
        pressure, h0 = trial_p, trial_h0
    return None


def _start(problem: _Problem, rigid: bool) -> tuple[np.ndarray, float]:
    """The first iterate (P, H0): the ``rigid`` film (no deflection; Martin's gap H0 = 4.895 λ/6π and a small
    pressure up to his rupture point X_c = 0.4751 (2 H0)^(1/2) to mark where the film is full), else Hertz's
    pressure with a gap that keeps the film open."""
    x = problem.x
    rigid_gap = MARTIN * problem.contact.speed_number / (6 * math.pi)
    if rigid:
        rupture = MARTIN_RUPTURE * math.sqrt(2 * rigid_gap)
        return np.where((x > x[0]) & (x < rupture), 1e-3, 0.0), rigid_gap
    pressure = np.sqrt(np.clip(1.0 - x**2, 0.0, None))
    pressure *= (math.pi / 2) / (problem.weights @ pressure)
    deformed = _film(problem, pressure, 0.0)
    return pressure, max(rigid_gap, 0.1) - np.min(deformed)


def _path(s: float, rigid: bool) -> tuple[float, float]:
    """(deflection factor κ, fraction of α) at the continuation parameter s in [0, 1]: from the rigid start the
    deflection is switched on over the first half and the piezoviscosity over the second; from Hertz's, the
    piezoviscosity alone."""
    if rigid:
        return min(1.0, 2 * s), max(0.0, 2 * s - 1)
    return 1.0, s


def _continuation(problem: _Problem, rigid: bool, settings: LineSettings):
    """(P, H0, iterations, residual) by the continuation of :func:`_path` from :func:`_start`."""
    alpha = problem.contact.pressure_viscosity
    pressure, h0 = _start(problem, rigid)
    level, step, iterations, halvings = 0.0, FIRST_STEP, 0, 0
    if rigid:  # the rigid film's pressure at Martin's gap first: with P = 0 the gap has no say in the balance
        result = _newton(_scaled(problem, 0.0), pressure, h0, 0.0, settings, fixed_gap=True)
        if result is not None:
            pressure, h0, iterations, _ = result
    result = _newton(_scaled(problem, _path(0.0, rigid)[0]), pressure, h0, 0.0, settings)
    if result is None:
        raise LineContactNotConverged("Newton's method did not converge at the continuation's start "
                                      f"({'rigid' if rigid else 'Hertzian'}, isoviscous)")
    pressure, h0, used, norm = result
    iterations += used
    while level < 1.0:
        target = min(1.0, level + step)
        elastic, fraction = _path(target, rigid)
        result = _newton(_scaled(problem, elastic), pressure, h0, fraction * alpha, settings)
        if result is None:
            halvings += 1
            if halvings > settings.continuation_steps:
                raise LineContactNotConverged(f"Newton's method did not converge at the continuation's s = "
                                              f"{target:.4g} (from {level:.4g}; deflection x{elastic:.3g}, α = "
                                              f"{fraction * alpha:.3g} 1/Pa) after {halvings - 1} halvings")
            step /= 2
            continue
        pressure, h0, used, norm = result
        iterations += used
        level = target
        step = min(2 * step, 1.0) if used < 8 else step
    return pressure, h0, iterations, norm


def _solve_on(problem: _Problem, start: tuple[np.ndarray, float] | None, settings: LineSettings):
    """Newton from ``start`` (at the full α) if given and it converges; else the continuation from the start
    that suits the load (Hertz's where Moes's M >= :data:`HERTZIAN_M`, else the rigid film), and from the other
    start if that fails."""
    if start is not None:
        result = _newton(problem, *start, problem.contact.pressure_viscosity, settings)
        if result is not None:
            return result
    rigid = problem.contact.moes[0] < HERTZIAN_M
    try:
        return _continuation(problem, rigid, settings)
    except LineContactNotConverged as failure:
        log.debug("%s; starting again from the %s film", failure, "Hertzian" if rigid else "rigid")
        return _continuation(problem, not rigid, settings)


def _scaled(problem: _Problem, elastic: float) -> _Problem:
    return problem if elastic == 1.0 else replace(problem, influence=elastic * problem.influence)


def solve_line_contact(contact: LineContact, settings: LineSettings | None = None) -> LineContactSolution:
    """Solve the EHL line contact ``contact`` with ``settings`` (default :class:`LineSettings`): see the module."""
    settings = settings or LineSettings()
    if not isinstance(contact, LineContact):
        raise TypeError(f"contact = {contact!r}: must be a LineContact")
    width = max(1.0, math.sqrt(2 * MARTIN * contact.speed_number / (6 * math.pi)))
    start, iterations = None, 0
    for _ in range(4):
        problem = _problem(contact, _grid(width, settings))
        pressure, h0, used, norm = _solve_on(problem, start, settings)
        iterations += used
        film = _film(problem, pressure, h0)
        central = float(np.interp(0.0, problem.x, film))
        needed = max(1.0, math.sqrt(2 * central))
        if needed <= 1.25 * width:
            break
        log.debug("pressure zone %.3g b wider than the grid's %.3g b: rebuilding", needed, width)
        old_x = problem.x
        width = needed
        new_x = _grid(width, settings)
        start = (np.interp(new_x, old_x, pressure, left=0.0, right=0.0), h0)
    b = contact.half_width
    scale = b**2 / contact.radius
    load_error = float(problem.weights @ pressure / (math.pi / 2) - 1.0)
    return LineContactSolution(contact=contact, x=problem.x * b, pressure=pressure * contact.hertz_pressure,
                               film=film * scale, central_film=central * scale,
                               minimum_film=float(np.min(film)) * scale, iterations=iterations, residual=float(norm),
                               load_error=load_error)
