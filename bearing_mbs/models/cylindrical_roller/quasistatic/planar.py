r"""Planar load distribution and 2×2 radial stiffness of a cylindrical roller bearing.

Each roller :math:`j` sits on the radial line at azimuth :math:`\psi_j` (the cage holds it there) and has
one unknown, its outer approach :math:`t_j = \delta_{o,j}`. With the total approach
:math:`d_j = x\cos\psi_j + y\sin\psi_j - P_d/2` (see :mod:`.rollers`), document 003 eq. 11 reads
:math:`\delta_{i,j} = d_j - t_j`, and the roller's radial equilibrium (eq. 3 reduced to the plane, outward
positive) is

.. math:: R_j(t) = Q_i(d_j - t) + F_c - Q_o(t) = 0,\qquad Q_i = K_i\delta_i^{n_i},\ Q_o = K_o\delta_o^{n_o},

solved by safeguarded Newton–Raphson with :math:`R' = -(k_i + k_o)`, :math:`k = nK\delta^{n-1}` (eqs. 4–5).
Without centrifugal force and with equal exponents this is the series law of
:func:`bearing_mbs.contact.line_contact.series_stiffness`. Condensing the roller (eq. 7) gives the stiffness
the ring sees, :math:`k_j = dQ_{i,j}/dd_j = k_i k_o/(k_i + k_o)`, and the ring's load and tangent stiffness

.. math:: P(x, y) = \sum_j Q_{i,j}\,e_j,\qquad K = \frac{\partial P}{\partial(x, y)} = \sum_j k_j\,e_j e_j^T,
          \qquad e_j = (\cos\psi_j, \sin\psi_j),

analytic, symmetric and positive semi-definite. :func:`solve_radial` finds :math:`(x, y)` with
:math:`P = F` (:mod:`.ring`); :func:`radial_state` is the reverse problem.

Kinematics are linearised in the ring displacement (Harris & Kotzalas 2006, ch. 7): the neglected term of
the inner approach is of order :math:`u_t^2/d_i` (:math:`u_t` the displacement across the roller's radial
line), about 1e-9 m for 10 µm on a 0.2 m raceway.
"""

from __future__ import annotations

from dataclasses import dataclass, replace
from typing import NamedTuple

import numpy as np

from bearing_mbs.contact.line_contact import (
    power_law_energy,
    power_law_force,
    power_law_stiffness,
    series_inner_share,
    series_stiffness,
)
from bearing_mbs.models.cylindrical_roller.quasistatic.ring import solve_ring
from bearing_mbs.models.cylindrical_roller.quasistatic.rollers import (
    NewtonSettings,
    RollerLoads,
    RollerSet,
    check_speed,
    check_vector,
)
from bearing_mbs.models.cylindrical_roller.quasistatic.roots import decreasing_root
from bearing_mbs.spec.fields import SpecError

#: Load-distribution integral J_r(0.5) of a zero-clearance line-contact bearing (n = 10/9), used only for
#: the first guess of the displacement; the tests compute it independently.
_FIRST_GUESS_INTEGRAL = 0.245


class RadialRollerEquilibrium(NamedTuple):
    """Per-roller radial equilibrium, arrays of the shape of the total approach.

    total_approach, inner_approach, outer_approach [m]; inner_load, outer_load [N];
    inner_stiffness, outer_stiffness [N/m] (tangent, :math:`nK\\delta^{n-1}`); stiffness [N/m], the
    condensed :math:`dQ_i/dd`; energy [J], the roller's potential (contact energies minus centrifugal work).
    """

    total_approach: np.ndarray
    inner_approach: np.ndarray
    outer_approach: np.ndarray
    inner_load: np.ndarray
    outer_load: np.ndarray
    inner_stiffness: np.ndarray
    outer_stiffness: np.ndarray
    stiffness: np.ndarray
    energy: np.ndarray


def radial_roller_equilibrium(
    total_approach, centrifugal_force: float, rollers: RollerSet, settings: NewtonSettings = NewtonSettings()
) -> RadialRollerEquilibrium:
    r"""Solve :math:`Q_i(d - t) + F_c = Q_o(t)` for every roller; ``total_approach`` :math:`d` [m], any shape.

    Bracket: :math:`R(0) = Q_i(d) + F_c \ge 0` and :math:`R(t_+) \le 0` at
    :math:`t_+ = \max(d, 0) + (F_c/K_o)^{1/n_o}`. A roller with :math:`d \le 0` and :math:`F_c = 0` is loose:
    zero loads and stiffness (its radial position is then arbitrary; it is reported at :math:`t = 0`).
    """
    d = np.asarray(total_approach, dtype=float)
    ki, ni = rollers.inner_stiffness, rollers.inner_exponent
    ko, no = rollers.outer_stiffness, rollers.outer_exponent
    fc = float(centrifugal_force)

    def residual(t):
        value = power_law_force(d - t, ki, ni) + fc - power_law_force(t, ko, no)
        slope = -power_law_stiffness(d - t, ki, ni) - power_law_stiffness(t, ko, no)
        return value, slope

    upper = np.maximum(d, 0.0) + (fc / ko) ** (1.0 / no)
    start = np.maximum(d, 0.0) * (1.0 - series_inner_share(ki, ko, no)) + (fc / ko) ** (1.0 / no)
    t, _ = decreasing_root(
        residual,
        np.zeros_like(d),
        upper,
        start,
        tolerance=settings.roller_tolerance,
        max_iterations=settings.roller_max_iterations,
        field="roller_max_iterations",
        what="the radial equilibrium of a roller",
    )
    inner_k = power_law_stiffness(d - t, ki, ni)
    outer_k = power_law_stiffness(t, ko, no)
    total_k = inner_k + outer_k
    with np.errstate(invalid="ignore", divide="ignore"):
        condensed = np.where(total_k > 0.0, inner_k * outer_k / total_k, 0.0)
    return RadialRollerEquilibrium(
        total_approach=d,
        inner_approach=d - t,
        outer_approach=t,
        inner_load=power_law_force(d - t, ki, ni),
        outer_load=power_law_force(t, ko, no),
        inner_stiffness=inner_k,
        outer_stiffness=outer_k,
        stiffness=condensed,
        energy=power_law_energy(d - t, ki, ni) + power_law_energy(t, ko, no) - fc * t,
    )


@dataclass(frozen=True)
class RadialSolution(RollerLoads):
    r"""Load distribution of the planar model.

    rollers: the :class:`RollerSet`; shaft_speed: inner-ring speed [rad/s]; load: :math:`(F_x, F_y)` [N]
    on the inner ring carried by the rollers (:math:`\sum_j Q_{i,j}e_j`; equals the applied load to the
    tolerance); displacement: inner-ring :math:`(x, y)` [m]; roller_angles :math:`\psi_j` [rad];
    inner_loads, outer_loads :math:`Q_{i,j}, Q_{o,j}` [N] (they differ by :math:`F_c`);
    inner_approaches, outer_approaches [m]; roller_stiffnesses: condensed :math:`k_j` [N/m];
    stiffness: :math:`K` [N/m], 2×2; iterations: outer Newton iterations (0 for :func:`radial_state`);
    residual: :math:`\|P - F\|` [N].
    """

    rollers: RollerSet
    shaft_speed: float
    load: np.ndarray
    displacement: np.ndarray
    roller_angles: np.ndarray
    inner_loads: np.ndarray
    outer_loads: np.ndarray
    inner_approaches: np.ndarray
    outer_approaches: np.ndarray
    roller_stiffnesses: np.ndarray
    stiffness: np.ndarray
    energy: float
    iterations: int = 0
    residual: float = 0.0

    @property
    def cage_speed(self) -> float:
        """Epicyclic cage speed [rad/s]."""
        return self.rollers.cage_speed(self.shaft_speed)

    @property
    def loaded_zone_half_angle(self) -> float:
        r"""Half angle :math:`\psi_l` [rad] of the continuous loaded zone of the inner contacts.

        The inner contact at :math:`\psi` (from the displacement direction) is loaded while
        :math:`|u|\cos\psi > P_d/2 + (F_c/K_o)^{1/n_o}` (Harris's :math:`\cos\psi_l = P_d/(2\delta_r)`
        when :math:`F_c = 0`): :math:`\pi/2` at zero clearance, :math:`\pi` when all rollers are loaded.
        """
        rollers = self.rollers
        threshold = rollers.diametral_clearance / 2.0 + (
            self.centrifugal_force / rollers.outer_stiffness
        ) ** (1.0 / rollers.outer_exponent)
        radius = float(np.hypot(*self.displacement))
        if radius == 0.0:
            return float(np.pi) if threshold < 0.0 else 0.0
        return float(np.arccos(np.clip(threshold / radius, -1.0, 1.0)))


def radial_state(
    rollers: RollerSet, displacement, *, shaft_speed: float = 0.0, settings: NewtonSettings = NewtonSettings()
) -> RadialSolution:
    """The reverse problem: roller loads, resultant load and stiffness at inner-ring displacement (x, y) [m]."""
    displacement = check_vector("displacement", displacement, 2)
    shaft_speed = check_speed(shaft_speed)
    return _evaluate(rollers, displacement, shaft_speed, settings)


def solve_radial(
    rollers: RollerSet, load, *, shaft_speed: float = 0.0, settings: NewtonSettings = NewtonSettings()
) -> RadialSolution:
    r"""Inner-ring displacement and roller loads under the radial load :math:`(F_x, F_y)` [N].

    ``shaft_speed``: inner-ring speed [rad/s] for the roller centrifugal force (0: none).
    Raises :class:`~bearing_mbs.spec.fields.SpecError` for a zero load without preload, and
    :class:`.ConvergenceError` when a Newton loop reaches its iteration limit.
    """
    load = check_vector("load", load, 2)
    shaft_speed = check_speed(shaft_speed)
    require_load_or_preload(rollers, load)
    u, state, iterations, residual = solve_ring(
        lambda u: _evaluate(rollers, u, shaft_speed, settings),
        load,
        np.ones(2),
        first_guess(rollers, float(np.linalg.norm(load)), shaft_speed),
        settings,
    )
    return replace(state, iterations=iterations, residual=residual)


def first_guess(rollers: RollerSet, load_magnitude: float, shaft_speed: float) -> float:
    """Starting ring displacement [m] for the Newton loop: half the clearance, the outer approach under the
    centrifugal force, and the approach of a zero-clearance bearing under ``load_magnitude`` [N]."""
    fc = rollers.centrifugal_force(shaft_speed)
    equivalent = series_stiffness(rollers.inner_stiffness, rollers.outer_stiffness, rollers.outer_exponent)
    return (
        max(rollers.diametral_clearance / 2.0, 0.0)
        + (fc / rollers.outer_stiffness) ** (1.0 / rollers.outer_exponent)
        + (load_magnitude / (_FIRST_GUESS_INTEGRAL * rollers.rollers * equivalent)) ** (1.0 / rollers.outer_exponent)
    )


def require_load_or_preload(rollers: RollerSet, load: np.ndarray) -> None:
    """:class:`SpecError` for an all-zero ``load`` on a bearing without preload (undetermined position)."""
    if np.all(load == 0.0) and rollers.diametral_clearance >= 0.0:
        raise SpecError(
            "load",
            tuple(float(v) for v in load),
            "must be nonzero unless the bearing is preloaded (diametral_clearance < 0): with "
            f"diametral_clearance = {rollers.diametral_clearance:g} m and no load no roller is compressed, the "
            "contact stiffness dQ/dδ = nKδ^(n-1) vanishes, so the stiffness matrix is zero and, with clearance, "
            "the ring's position is not determined",
        )


def _evaluate(rollers: RollerSet, displacement: np.ndarray, shaft_speed: float, settings) -> RadialSolution:
    angles = rollers.roller_angles
    directions = np.stack([np.cos(angles), np.sin(angles)], axis=1)
    total = directions @ displacement - rollers.diametral_clearance / 2.0
    rollers_eq = radial_roller_equilibrium(total, rollers.centrifugal_force(shaft_speed), rollers, settings)
    return RadialSolution(
        rollers=rollers,
        shaft_speed=shaft_speed,
        load=directions.T @ rollers_eq.inner_load,
        displacement=np.array(displacement, dtype=float),
        roller_angles=angles,
        inner_loads=rollers_eq.inner_load,
        outer_loads=rollers_eq.outer_load,
        inner_approaches=rollers_eq.inner_approach,
        outer_approaches=rollers_eq.outer_approach,
        roller_stiffnesses=rollers_eq.stiffness,
        stiffness=_symmetric((directions.T * rollers_eq.stiffness) @ directions),
        energy=float(rollers_eq.energy.sum()),
    )


def _symmetric(matrix: np.ndarray) -> np.ndarray:
    """Remove the round-off asymmetry of a matrix that is symmetric in exact arithmetic."""
    return 0.5 * (matrix + matrix.T)
