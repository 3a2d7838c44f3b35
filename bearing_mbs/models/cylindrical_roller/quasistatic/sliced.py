r"""Sliced rollers with crowning and ring tilt: 4×4 radial-and-tilt stiffness (document 003, eqs. 3–7, 11–16).

Kinematics in the radial plane of roller :math:`j` at azimuth :math:`\psi_j` (outer ring fixed)
------------------------------------------------------------------------------------------------
The inner ring moves by :math:`(x, y)` and tilts by the small rotations :math:`(\theta_x, \theta_y)` about
the global x and y axes; a raceway point at axial abscissa :math:`z` moves radially by
:math:`u_r + \varphi z` with

.. math:: u_r = x\cos\psi_j + y\sin\psi_j,\qquad \varphi = \theta_y\cos\psi_j - \theta_x\sin\psi_j

(:math:`\theta\times z e_z`; the axial motion is free: no flanges, no axial load). The roller has two
unknowns, the radial displacement :math:`v` of its centre and its tilt :math:`\beta` in the radial plane.
With :math:`J_b = P_d/4` (eq. 11, :mod:`.rollers`), the inner and outer contacts have

.. math:: \delta_i = u_r - v - J_b,\ \alpha_i = \varphi - \beta;\qquad \delta_o = v - J_b,\ \alpha_o = \beta,

and each is a sliced contact (:func:`bearing_mbs.contact.line_contact.sliced_contact`, eqs. 12, 14–16)
with the crown drops of the roller and of that raceway, :math:`C_f = K/L_e` and exponent :math:`n` of the
:class:`.RollerSet`'s laws (so an uncrowned roller reproduces the planar model exactly).

Roller equilibrium (eqs. 3–5) and condensation (eq. 7)
-------------------------------------------------------
.. math:: R = \begin{pmatrix} Q_i - Q_o + F_c \\ M_i - M_o \end{pmatrix} = 0,\qquad
          \frac{\partial R}{\partial(v, \beta)} = -(K_t^{i} + K_t^{o}),\quad
          K_t = \begin{pmatrix} \partial Q/\partial\delta & \partial Q/\partial\alpha \\
                                \partial M/\partial\delta & \partial M/\partial\alpha \end{pmatrix},

solved by Newton–Raphson on :math:`(v, \beta)` with a backtracking (Armijo) line search on the roller's
potential :math:`E_i + E_o - F_c v` (convex, its gradient is :math:`-R`), started from a bracketed solve in
:math:`v` at the tilt split :math:`\beta_0` of uncrowned rollers. A roller that Newton has not settled in
20 iterations (single-slice contacts make :math:`K_t` singular and the steps zigzag) is solved by the same
Newton–Raphson in block form: :math:`v(\beta)` from :math:`R_1 = 0` exactly, then the reduced moment
balance :math:`g(\beta) = R_2(v(\beta), \beta)`, non-increasing with
:math:`g' = -(H_{22} - H_{12}^2/H_{11})`, :math:`H = K_t^i + K_t^o`; both scalar Newton loops are bracketed
and safeguarded by bisection, so they cannot fail. The gyroscopic moment of document 003
eq. 23 vanishes for a roller whose axis stays parallel to the bearing axis and is left out, as are the
flange contacts (eqs. 17–20), which carry axial load only. Differentiating :math:`R = 0` gives the
condensed stiffness the ring sees,

.. math:: K_j = \frac{\partial(Q_i, M_i)}{\partial(u_r, \varphi)} = K_t^{i}\,(K_t^{i} + K_t^{o})^{-1}\,K_t^{o},

which equals eq. 7 (:math:`K_e(K_e+K_i)^{-1}K_i`) because both factors are symmetric. With
:math:`B_j = \begin{pmatrix}\cos\psi_j & \sin\psi_j & 0 & 0\\ 0 & 0 & -\sin\psi_j & \cos\psi_j\end{pmatrix}`
the ring carries :math:`P = \sum_j B_j^T (Q_{i,j}, M_{i,j})` = :math:`(F_x, F_y, M_x, M_y)` and has the
analytic tangent stiffness :math:`K = \sum_j B_j^T K_j B_j` (4×4, symmetric positive semi-definite).

A roller is *loose* when :math:`F_c = 0` and no slice can touch both raceways,
:math:`\max_k(u_r - 2J_b + \varphi z_k - h_{i,k} - h_{o,k}) \le 0`; it then carries nothing. (For convex
crowns a straight roller axis then fits between the raceways.)
"""

from __future__ import annotations

from dataclasses import dataclass, replace
from typing import NamedTuple

import numpy as np

from bearing_mbs.contact.line_contact import (
    SlicedContact,
    slice_coefficient,
    sliced_contact,
)
from bearing_mbs.models.cylindrical_roller.quasistatic.planar import first_guess, require_load_or_preload
from bearing_mbs.models.cylindrical_roller.quasistatic.profiles import CircularCrown, Flat, LogarithmicCrown
from bearing_mbs.models.cylindrical_roller.quasistatic.ring import ARMIJO, MAX_DOUBLINGS, regularised_solve, solve_ring
from bearing_mbs.models.cylindrical_roller.quasistatic.rollers import (
    NewtonSettings,
    RollerLoads,
    RollerSet,
    check_speed,
    check_vector,
)
from bearing_mbs.models.cylindrical_roller.quasistatic.roots import decreasing_root
from bearing_mbs.spec.fields import SpecError, require

PROFILES = (Flat, CircularCrown, LogarithmicCrown)
MAX_SLICES = 10000
#: Largest number of step halvings in a roller's line search.
MAX_HALVINGS = 60
#: Newton iterations on (v, β) before a roller is handed to the bracketed safeguard.
NEWTON_ITERATIONS = 20


@dataclass(frozen=True)
class SlicedRollerSet:
    """A :class:`.RollerSet` with crowned rollers and raceways, cut into slices.

    rollers: the roller set (its ``roller_length`` is the effective length :math:`L_e` that is sliced).
    roller_crown, inner_raceway_crown, outer_raceway_crown: a :class:`.Flat`, :class:`.CircularCrown` or
    :class:`.LogarithmicCrown` profile; the roller's applies to both of its contacts.
    slices: number :math:`N` of slices, integer in [1, 10000].
    """

    rollers: RollerSet
    roller_crown: Flat | CircularCrown | LogarithmicCrown = Flat()
    inner_raceway_crown: Flat | CircularCrown | LogarithmicCrown = Flat()
    outer_raceway_crown: Flat | CircularCrown | LogarithmicCrown = Flat()
    slices: int = 40

    def __post_init__(self):
        require(isinstance(self.rollers, RollerSet), "rollers", self.rollers, "must be a RollerSet")
        names = ", ".join(p.__name__ for p in PROFILES)
        for name in ("roller_crown", "inner_raceway_crown", "outer_raceway_crown"):
            profile = getattr(self, name)
            require(isinstance(profile, PROFILES), name, profile, f"must be one of {names}")
            profile.check_length(name, self.rollers.roller_length)
        is_int = isinstance(self.slices, (int, np.integer)) and not isinstance(self.slices, bool)
        require(
            is_int and 1 <= self.slices <= MAX_SLICES, "slices", self.slices, f"must be an integer in [1, {MAX_SLICES}]"
        )

    @property
    def slice_width(self) -> float:
        """:math:`w = L_e/N` [m]."""
        return self.rollers.roller_length / self.slices

    @property
    def slice_positions(self) -> np.ndarray:
        """Slice centres :math:`z_k = L_e(-1/2 + (k + 1/2)/N)` [m], symmetric about the roller centre, (N,)."""
        return self.rollers.roller_length * (-0.5 + (np.arange(self.slices) + 0.5) / self.slices)

    @property
    def inner_drops(self) -> np.ndarray:
        """Summed crown drops of roller and inner raceway at the slices [m], (N,)."""
        z = self.slice_positions
        return self.roller_crown.drop(z) + self.inner_raceway_crown.drop(z)

    @property
    def outer_drops(self) -> np.ndarray:
        """Summed crown drops of roller and outer raceway at the slices [m], (N,)."""
        z = self.slice_positions
        return self.roller_crown.drop(z) + self.outer_raceway_crown.drop(z)

    @property
    def half_length(self) -> float:
        """:math:`\\ell = L_e/2` [m], the scale between tilts and lengths, moments and forces."""
        return 0.5 * self.rollers.roller_length


class SlicedRollerEquilibrium(NamedTuple):
    """Per-roller equilibrium of the sliced model; arrays of shape (Z,) unless stated.

    radial :math:`u_r` [m] and ring_tilt :math:`\\varphi` [rad]: the inputs; roller_displacement :math:`v` [m]
    and roller_tilt :math:`\\beta` [rad]: the solution; inner, outer: :class:`SlicedContact` resultants
    (forces [N], moments [N m], slice forces (Z, N)); stiffness: condensed
    :math:`\\partial(Q_i, M_i)/\\partial(u_r, \\varphi)`, (Z, 2, 2) in [[N/m, N/rad], [N, N m/rad]];
    energy [J]; loose: rollers that carry nothing; iterations: Newton iterations on (v, β), plus those of
    the bracketed safeguard on β if it ran.
    """

    radial: np.ndarray
    ring_tilt: np.ndarray
    roller_displacement: np.ndarray
    roller_tilt: np.ndarray
    inner: SlicedContact
    outer: SlicedContact
    stiffness: np.ndarray
    energy: np.ndarray
    loose: np.ndarray
    iterations: int


def sliced_roller_equilibrium(
    model: SlicedRollerSet, radial, ring_tilt, centrifugal_force: float, settings: NewtonSettings = NewtonSettings()
) -> SlicedRollerEquilibrium:
    """Solve every roller's equilibrium for ring motions ``radial`` :math:`u_r` [m] and ``ring_tilt``
    :math:`\\varphi` [rad] (1-D arrays of equal length) under the centrifugal force [N]: start at the uncrowned
    tilt split, Newton–Raphson on (v, β), the bracketed safeguard for the rollers it has not settled, then the
    condensed stiffness; loose rollers carry nothing."""
    rollers = _RollerContacts(model, radial, ring_tilt, centrifugal_force, settings)
    total = rollers.interference()
    loose = (rollers.fc == 0.0) & (total.max(axis=1) <= 0.0)

    # Start: the tilt split of uncrowned rollers, then the radial equilibrium at that tilt.
    beta = rollers.uncrowned_tilt()
    v = rollers.radial_equilibrium(beta, slice(None), 1e-6)
    v, beta, inner, outer, unsettled, iterations = _newton(rollers, v, beta, ~loose, model.slices)
    if unsettled.any():
        iterations += _tilt_safeguard(rollers, v, beta, np.flatnonzero(unsettled), total)
        inner, outer = rollers.contacts(v, beta)

    ell = rollers.ell
    condensed = _unscaled(_condense(_scaled(inner, ell), _scaled(outer, ell)), ell)
    energy = rollers.potential(inner, outer, v)
    if loose.any():
        zero = np.where(loose, 0.0, 1.0)
        inner, outer = _times_rows(inner, zero), _times_rows(outer, zero)
        condensed = condensed * zero[:, None, None]
        energy = energy * zero
    return SlicedRollerEquilibrium(
        radial=rollers.radial,
        ring_tilt=rollers.ring_tilt,
        roller_displacement=v,
        roller_tilt=beta,
        inner=inner,
        outer=outer,
        stiffness=condensed,
        energy=energy,
        loose=loose,
        iterations=iterations,
    )


class _RollerContacts:
    """The rollers' two sliced contacts at ring motions :math:`(u_r, \\varphi)` [m, rad] (Z,) under the
    centrifugal force :math:`F_c` [N], as functions of the rollers' unknowns :math:`(v, \\beta)`: the one
    place that holds the slices, the crown drops, :math:`C_f`, :math:`n` and :math:`J_b` of the set."""

    def __init__(self, model: SlicedRollerSet, radial, ring_tilt, centrifugal_force: float, settings: NewtonSettings):
        rollers = model.rollers
        self.radial = np.atleast_1d(np.asarray(radial, dtype=float))
        self.ring_tilt = np.atleast_1d(np.asarray(ring_tilt, dtype=float))
        self.fc = float(centrifugal_force)
        self.settings = settings
        self.z, self.w, self.ell = model.slice_positions, model.slice_width, model.half_length
        self.hi, self.ho = model.inner_drops, model.outer_drops
        self.ci = slice_coefficient(rollers.inner_stiffness, rollers.roller_length)
        self.co = slice_coefficient(rollers.outer_stiffness, rollers.roller_length)
        self.ni, self.no = rollers.inner_exponent, rollers.outer_exponent
        self.jb = rollers.contact_clearance

    def contacts(self, v, beta, rows=slice(None)) -> tuple[SlicedContact, SlicedContact]:
        """Inner and outer contacts of the rollers ``rows`` at (v [m], β [rad]): δ_i = u_r − v − J_b,
        α_i = φ − β; δ_o = v − J_b, α_o = β."""
        inner = sliced_contact(self.radial[rows] - v - self.jb, self.ring_tilt[rows] - beta, self.z, self.hi, self.w,
                               self.ci, self.ni)
        outer = sliced_contact(v - self.jb, beta, self.z, self.ho, self.w, self.co, self.no)
        return inner, outer

    def residual(self, inner: SlicedContact, outer: SlicedContact) -> np.ndarray:
        """:math:`(R_1, R_2/\\ell) = (Q_i - Q_o + F_c, (M_i - M_o)/\\ell)` [N], (Z, 2)."""
        return np.stack([inner.force - outer.force + self.fc, (inner.moment - outer.moment) / self.ell], axis=1)

    def potential(self, inner: SlicedContact, outer: SlicedContact, v) -> np.ndarray:
        """The rollers' potential :math:`E_i + E_o - F_c v` [J] (its gradient is :math:`-R`)."""
        return inner.energy + outer.energy - self.fc * v

    def interference(self) -> np.ndarray:
        """:math:`u_r - 2J_b + \\varphi z_k - h_{i,k} - h_{o,k}` [m], (Z, N): positive where a slice of a straight
        roller would touch both raceways."""
        return self.radial[:, None] - 2.0 * self.jb + self.ring_tilt[:, None] * self.z - self.hi - self.ho

    def uncrowned_tilt(self) -> np.ndarray:
        """The tilt split :math:`\\beta_0` [rad] of uncrowned rollers, the start of the solve."""
        return self.ring_tilt / (1.0 + (self.co / self.ci) ** (1.0 / self.no))

    def length_scale(self, v, beta) -> np.ndarray:
        """The lengths [m] an interference is made of, per roller: the round-off level of a Newton step."""
        return (np.abs(self.radial) + np.abs(v) + abs(self.jb) + self.ell * (np.abs(self.ring_tilt) + np.abs(beta))
                + max(self.hi.max(), self.ho.max()))

    def radial_equilibrium(self, beta, rows, tolerance: float) -> np.ndarray:
        """v [m] solving R1 = 0 at tilts β for the rollers ``rows`` (bracketed: no outer contact at ``lower``, no
        inner one and an outer load >= F_c at ``upper``)."""
        z, jb = self.z, self.jb

        def residual(v):
            inner, outer = self.contacts(v, beta, rows)
            return inner.force - outer.force + self.fc, -inner.force_approach - outer.force_approach

        lower = np.min(jb + self.ho - beta[:, None] * z, axis=1)
        inner_free = np.max(self.radial[rows, None] - jb + (self.ring_tilt[rows] - beta)[:, None] * z - self.hi,
                            axis=1)
        upper = np.maximum(inner_free, lower + (self.fc / (self.co * self.w)) ** (1.0 / self.no))
        v, _ = decreasing_root(
            residual,
            lower,
            upper,
            0.5 * (lower + upper),
            tolerance=tolerance,
            max_iterations=self.settings.roller_max_iterations,
            field="roller_max_iterations",
            what="the radial equilibrium of a sliced roller",
        )
        return v


def _newton(rollers: _RollerContacts, v, beta, active, slices: int):
    """Newton–Raphson on (v, β) of the ``active`` rollers, in scaled unknowns (v, ℓβ) and residuals (R1, R2/ℓ),
    each step shortened by :func:`_line_search`. A roller has converged when its residual is below the tolerance
    relative to the largest roller load of the set (a roller carrying 1e-5 of it need not be solved to 1e-13 of
    its own load), or when its step is at the round-off level of the lengths involved (the interference
    δ + αz − h loses digits to cancellation). Returns (v, β, inner, outer, unsettled, iterations): the rollers
    still unsettled after :data:`NEWTON_ITERATIONS`."""
    settings, ell = rollers.settings, rollers.ell
    inner, outer = rollers.contacts(v, beta)
    floor = max(settings.roller_tolerance, 16 * np.finfo(float).eps * slices)
    newton_limit = min(settings.roller_max_iterations, NEWTON_ITERATIONS)
    iterations = 0
    while True:
        residual = rollers.residual(inner, outer)
        norm = np.linalg.norm(residual, axis=1)
        scale = max(inner.force.max(), outer.force.max(), rollers.fc)
        step = regularised_solve(_scaled(inner, ell) + _scaled(outer, ell), residual)
        active &= (norm > floor * scale) & (np.linalg.norm(step, axis=1) > 1e-14 * rollers.length_scale(v, beta))
        if not active.any() or iterations >= newton_limit:
            return v, beta, inner, outer, active, iterations
        iterations += 1
        step[~active] = 0.0
        v, beta = _line_search(rollers, v, beta, inner, outer, residual, norm, step, active)
        inner, outer = rollers.contacts(v, beta)


def _line_search(rollers: _RollerContacts, v, beta, inner, outer, residual, norm, step, active):
    """Backtracking per roller along the Newton step: halve α until the potential decreases by the Armijo
    fraction of the slope (up to its round-off) or the residual norm shrinks by it; returns the new (v, β)."""
    fc, ell = rollers.fc, rollers.ell
    potential = rollers.potential(inner, outer, v)
    slope = -np.einsum("ij,ij->i", residual, step)
    roundoff = 1e-13 * (inner.energy + outer.energy + np.abs(fc * v))
    alpha = np.ones_like(v)
    pending = active.copy()
    new_v, new_beta = v.copy(), beta.copy()
    for _ in range(MAX_HALVINGS):
        trial_v, trial_beta = v + alpha * step[:, 0], beta + alpha * step[:, 1] / ell
        trial_inner, trial_outer = rollers.contacts(trial_v, trial_beta)
        trial_potential = rollers.potential(trial_inner, trial_outer, trial_v)
        trial_norm = np.hypot(
            trial_inner.force - trial_outer.force + fc, (trial_inner.moment - trial_outer.moment) / ell
        )
        accept = pending & (
            (trial_potential <= potential + ARMIJO * alpha * slope + roundoff)
            | (trial_norm <= (1.0 - ARMIJO * alpha) * norm)
        )
        new_v, new_beta = np.where(accept, trial_v, new_v), np.where(accept, trial_beta, new_beta)
        pending &= ~accept
        if not pending.any():
            break
        alpha = np.where(pending, 0.5 * alpha, alpha)
    return new_v, new_beta


def _tilt_safeguard(rollers: _RollerContacts, v, beta, rows, total) -> int:
    """Safeguard for the rollers ``rows`` Newton has not settled (single-slice contacts make K_t singular and the
    step zigzag): eliminate v exactly, R1(v(β), β) = 0, and solve the reduced moment balance
    g(β) = R2(v(β), β) = 0, non-increasing in β with g' = −(H22 − H12²/H11) (H = K_t^i + K_t^o, the Schur
    complement of a positive semi-definite matrix), by bracketed, safeguarded Newton. Writes their v and β;
    returns its iterations."""
    ell = rollers.ell

    def reduced(trial_beta):
        trial_v = rollers.radial_equilibrium(trial_beta, rows, 1e-15)
        inner, outer = rollers.contacts(trial_v, trial_beta, rows)
        h11 = inner.force_approach + outer.force_approach
        h12 = inner.force_tilt + outer.force_tilt
        h22 = inner.moment_tilt + outer.moment_tilt
        with np.errstate(divide="ignore", invalid="ignore"):
            schur = np.where(h11 > 0.0, h22 - h12**2 / np.where(h11 > 0.0, h11, 1.0), h22)
        return inner.moment - outer.moment, -schur

    start = beta[rows]
    reach = np.maximum(np.abs(rollers.ring_tilt[rows]), (np.abs(total[rows]).max(axis=1) + abs(rollers.jb)) / ell)
    lower, upper = _tilt_bracket(reduced, start, reach + 1e-12)
    beta_rows, extra = decreasing_root(
        reduced,
        lower,
        upper,
        start,
        tolerance=1e-15,
        max_iterations=rollers.settings.roller_max_iterations,
        field="roller_max_iterations",
        what="the tilt of a sliced roller",
        residual_scale=lambda b: 1.0 / ell,
    )
    beta[rows] = beta_rows
    v[rows] = rollers.radial_equilibrium(beta_rows, rows, 1e-15)
    return extra


def _tilt_bracket(reduced, start, reach):
    """Widen (start − reach, start + reach) by doubling until the non-increasing g changes sign across it."""
    lower, upper = start - reach, start + reach
    for _ in range(MAX_DOUBLINGS):
        low, high = reduced(lower)[0] < 0.0, reduced(upper)[0] > 0.0
        if not (low.any() or high.any()):
            break
        reach = np.where(low | high, 2.0 * reach, reach)
        lower, upper = np.where(low, start - reach, lower), np.where(high, start + reach, upper)
    return lower, upper


def _times_rows(contact: SlicedContact, factor: np.ndarray) -> SlicedContact:
    """Every field of ``contact`` times a per-roller ``factor`` (Z,) (slice forces row by row)."""
    return SlicedContact(*(field * (factor[:, None] if field.ndim == 2 else factor) for field in contact))


def _scaled(contact: SlicedContact, ell: float) -> np.ndarray:
    """Tangent matrix in the scaled unknowns (δ, ℓα) and resultants (Q, M/ℓ): all entries in N/m, (Z, 2, 2)."""
    off = contact.force_tilt / ell
    return np.stack(
        [np.stack([contact.force_approach, off], axis=-1), np.stack([off, contact.moment_tilt / ell**2], axis=-1)],
        axis=-2,
    )


def _unscaled(matrix: np.ndarray, ell: float) -> np.ndarray:
    """Back to (Q, M) against (δ, α): [[N/m, N/rad], [N, N m/rad]]."""
    return matrix * np.array([[1.0, ell], [ell, ell**2]])


def _condense(inner: np.ndarray, outer: np.ndarray) -> np.ndarray:
    """Eq. 7: :math:`K_i (K_i + K_o)^+ K_o` per roller (pseudo-inverse for rollers without contact)."""
    return inner @ np.linalg.pinv(inner + outer, rcond=1e-13, hermitian=True) @ outer


@dataclass(frozen=True)
class SlicedSolution(RollerLoads):
    r"""Load distribution and 4×4 stiffness of the sliced model.

    model: the :class:`SlicedRollerSet`; shaft_speed [rad/s]; load :math:`(F_x, F_y, M_x, M_y)` [N, N, N m,
    N m] carried by the rollers; displacement :math:`(x, y, \theta_x, \theta_y)` [m, m, rad, rad];
    roller_angles [rad]; inner_loads, outer_loads [N]; inner_moments, outer_moments [N m] (about the roller
    centre, :math:`\sum Q_k z_k`); roller_displacements :math:`v` [m]; roller_tilts :math:`\beta` [rad];
    inner_slice_loads, outer_slice_loads [N], (Z, N); roller_stiffnesses (Z, 2, 2) (see
    :class:`SlicedRollerEquilibrium`); stiffness: 4×4, rows and columns (x, y, θx, θy), in N/m, N/rad,
    N m/m, N m/rad; iterations: outer Newton iterations; residual: :math:`\|(F, M/\ell) - P\|` [N].
    """

    model: SlicedRollerSet
    shaft_speed: float
    load: np.ndarray
    displacement: np.ndarray
    roller_angles: np.ndarray
    inner_loads: np.ndarray
    outer_loads: np.ndarray
    inner_moments: np.ndarray
    outer_moments: np.ndarray
    roller_displacements: np.ndarray
    roller_tilts: np.ndarray
    inner_slice_loads: np.ndarray
    outer_slice_loads: np.ndarray
    roller_stiffnesses: np.ndarray
    stiffness: np.ndarray
    energy: float
    iterations: int = 0
    residual: float = 0.0

    @property
    def rollers(self) -> RollerSet:
        return self.model.rollers

    @property
    def slice_positions(self) -> np.ndarray:
        return self.model.slice_positions


def sliced_state(
    model: SlicedRollerSet, displacement, *, shaft_speed: float = 0.0, settings: NewtonSettings = NewtonSettings()
) -> SlicedSolution:
    """The reverse problem: loads and stiffness at inner-ring displacement (x [m], y [m], θx [rad], θy [rad])."""
    displacement = check_vector("displacement", displacement, 4)
    shaft_speed = check_speed(shaft_speed)
    return _evaluate(model, displacement, shaft_speed, settings)


def solve_sliced(
    model: SlicedRollerSet, load, *, shaft_speed: float = 0.0, settings: NewtonSettings = NewtonSettings()
) -> SlicedSolution:
    r"""Inner-ring displacement and tilt under the load :math:`(F_x, F_y, M_x, M_y)` [N, N, N m, N m].

    Raises :class:`~bearing_mbs.spec.fields.SpecError` for a zero load without preload and
    :class:`.ConvergenceError` when a Newton loop reaches its iteration limit.
    """
    load = check_vector("load", load, 4)
    shaft_speed = check_speed(shaft_speed)
    rollers = model.rollers
    require_load_or_preload(rollers, load)
    if model.slices == 1 and np.any(load[2:] != 0.0):
        raise SpecError(
            "load",
            tuple(float(v) for v in load),
            "the moments (M_x, M_y) must be 0 with slices = 1: a single slice at the roller centre has no tilt "
            "stiffness; use slices >= 2 (40 or more for accurate moments)",
        )
    ell = model.half_length
    scale = np.array([1.0, 1.0, ell, ell])
    _, state, iterations, residual = solve_ring(
        lambda u: _evaluate(model, u, shaft_speed, settings),
        load,
        scale,
        first_guess(rollers, float(np.linalg.norm(load / scale)), shaft_speed),
        settings,
    )
    return replace(state, iterations=iterations, residual=residual)


def _evaluate(model: SlicedRollerSet, displacement: np.ndarray, shaft_speed: float, settings) -> SlicedSolution:
    rollers = model.rollers
    angles = rollers.roller_angles
    cos, sin = np.cos(angles), np.sin(angles)
    zero = np.zeros_like(angles)
    # B_j maps (x, y, θx, θy) to (u_r, φ) of roller j, shape (Z, 2, 4).
    b = np.stack([np.stack([cos, sin, zero, zero], axis=1), np.stack([zero, zero, -sin, cos], axis=1)], axis=1)
    radial, tilt = np.einsum("jab,b->ja", b, displacement).T
    eq = sliced_roller_equilibrium(model, radial, tilt, rollers.centrifugal_force(shaft_speed), settings)
    resultants = np.stack([eq.inner.force, eq.inner.moment], axis=1)
    stiffness = np.einsum("jai,jab,jbk->ik", b, eq.stiffness, b)
    return SlicedSolution(
        model=model,
        shaft_speed=shaft_speed,
        load=np.einsum("jai,ja->i", b, resultants),
        displacement=np.array(displacement, dtype=float),
        roller_angles=angles,
        inner_loads=eq.inner.force,
        outer_loads=eq.outer.force,
        inner_moments=eq.inner.moment,
        outer_moments=eq.outer.moment,
        roller_displacements=eq.roller_displacement,
        roller_tilts=eq.roller_tilt,
        inner_slice_loads=eq.inner.slice_forces,
        outer_slice_loads=eq.outer.slice_forces,
        roller_stiffnesses=eq.stiffness,
        stiffness=0.5 * (stiffness + stiffness.T),
        energy=float(eq.energy.sum()),
    )
