r"""Quasi-static skidding: the steady cage and roller speeds of a caged roller bearing, in the style of
T. A. Harris, "An analytical method to predict skidding in high speed roller bearings", ASLE Trans. 9 (1966)
229–241, with the scene's own contact, traction and drag laws.

It cross-checks the dynamic engines on steady lubricated states, as :mod:`.quasistatic` does for the loads:
it shares their force laws (one owner per formula) but none of their integration, constraints or transients.

The state: the cage, centred, turns at :math:`\omega_c`; roller j sits on the pitch circle :math:`R` at
:math:`\psi_j` and spins at :math:`\omega_j` (counter-clockwise positive, like the ring's :math:`\omega_i`).
Its contact loads :math:`Q_{i,j}, Q_{o,j}` come from the planar load distribution at the centrifugal force of
the orbit :math:`\omega_c` (:func:`.quasistatic.solve_radial`). Along the orbit's direction
:math:`e_\theta`, with roller radius r and raceway contact radii :math:`r_i = R - r`, :math:`r_o = R + r`:

* sliding of the roller on the inner ring :math:`\Delta u_i = \omega_c R - \omega_j r - \omega_i r_i`, on the
  outer ring :math:`\Delta u_o = \omega_c R + \omega_j r`;
* rolling (entrainment) speeds, the mean surface speeds relative to the contact points, which move with the
  cage: :math:`u_i = \tfrac12[(\omega_i - \omega_c) r_i + (\omega_c - \omega_j) r]`,
  :math:`u_o = \tfrac12[\omega_c r_o + (\omega_c - \omega_j) r]`;
* tractions on the roller :math:`F = -\mu(\Delta u, u, Q)\,Q` (the pair's law), rolling-resistance moments
  :math:`-a\,Q\,\varphi(\omega_{rel} r)` and, with ``ehl_rolling_resistance``, the hydrodynamic rolling
  resistance's tangential force and couple (:func:`bearing_mbs.contact.kernel.rolling_resistance`), drag
  :math:`-(c + c_2 v) v` on the centre at :math:`v = \omega_c R` and :math:`-(c_\theta + c_{\theta 2}|\omega_j|)
  \omega_j` on the spin.

Each roller's spin follows :math:`I\dot\omega_j = -r F_i + r F_o + M_{R,i} + M_{R,o} - (c_\theta +
c_{\theta 2}|\omega_j|)\omega_j` around
its orbit (:math:`\psi = \omega_c t`, periodic): held at its balance in the load zone, coasting outside it. Its
tangential balance gives the pocket force on it, :math:`P_j = (c + c_2 v) v - F_i - F_o`. The cage's torque
balance, averaged over the orbit (the cage's inertia filters the pitch's ripple), fixes :math:`\omega_c`:
:math:`\langle -R\sum_j P_j\rangle + T_l + T_d = 0`, :math:`T_d` the cage's own drag; the land's torque
:math:`T_l = -\mu_l N r_c\,\varphi(\omega_c r_c)` dry, or
the Couette torque of its oil film (a short journal bearing, :mod:`bearing_mbs.fluid_film`) at the eccentricity
where the film carries N. N is the land's normal force,
the magnitude of the cage's weight plus, with pocket contacts, :math:`-\sum_j P_j e_{\theta,j}` (the constraint
cage holds each roller's orbital angle about the axis, so its pockets put a torque on the cage and no force).

A constraint cage with oiled pockets adds each roller's pocket films (:func:`pocket_film_coefficients`): with the
roller centred, a moment :math:`m_p(\omega_j - \omega_c)` on its spin and a torque :math:`t_p(\omega_j -
\omega_c)` on the cage, averaged over the orbit like the pocket forces.

Left out: the weight of the rollers (its tangential parts cancel around the orbit), the cage's eccentricity and
the inner ring's vibration. Harris (1966) also held each roller at its balance everywhere; here the spin's
inertia outside the load zone is kept, as the dynamic engines keep it.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace
from typing import NamedTuple

import numpy as np
from scipy.integrate import solve_ivp
from scipy.optimize import brentq

from bearing_mbs.contact import kernel
from bearing_mbs.contact.kernel import N_PAIR_OUTPUTS
from bearing_mbs.core.scene import OrbitConstraint, Scene
from bearing_mbs.core.topology import Group, Role
from bearing_mbs.elements import Drag
from bearing_mbs.elements.contact_pairs import PairArrays, add_forces_twin, pack
from bearing_mbs.elements.journal_bearings import LARGEST_ECCENTRICITY, JournalFilm
from bearing_mbs.fluid_film.closed_forms import short_bearing_force, short_bearing_torque
from bearing_mbs.models.cylindrical_roller.linearise import BearingLayout
from bearing_mbs.models.cylindrical_roller.metrics import (
    frictional_power_intensity,
    law_traction,
    pair_columns,
    raceway_contact,
)
from bearing_mbs.models.cylindrical_roller.quasistatic import solve_radial
from bearing_mbs.spec.fields import SpecError

#: Cage speeds, as fractions of the epicyclic one, tried in turn for the lower end of the balance's bracket.
BRACKET_FRACTIONS = (0.98, 0.9, 0.7, 0.5, 0.3, 0.1, 0.03, 0.01)


@dataclass(frozen=True)
class SkiddingSolution:
    """The steady state: cage_speed ω_c and the epicyclic (slip-free) cage speed [rad/s], and the epicyclic roller
    spin in the cage −(ω_i − ω_c,epi) r_i/r [rad/s] (rolling without slip on both raceways); at Z × phases roller
    azimuths around the orbit, sorted: roller_angles ψ [rad], inner_loads, outer_loads Q [N], roller_speeds ω_j
    [rad/s], pocket_forces P [N] (on the roller, along the orbit), inner_traction, outer_traction F [N] (on the
    roller, along the orbit, with the hydrodynamic rolling resistance's tangential force), inner_sliding,
    outer_sliding Δu [m/s], inner_rolling, outer_rolling u [m/s]; land_torque: the land's mean friction torque on
    the cage [N m]; ring_torque: the rollers' mean torque on the inner ring [N m] (the drive supplies −ring_torque:
    the bearing's friction torque); power_loss: the mean power dissipated at the contacts, by the drags and at the
    land [W]."""

    cage_speed: float
    epicyclic_cage_speed: float
    epicyclic_roller_spin: float
    roller_angles: np.ndarray
    inner_loads: np.ndarray
    outer_loads: np.ndarray
    roller_speeds: np.ndarray
    pocket_forces: np.ndarray
    inner_traction: np.ndarray
    outer_traction: np.ndarray
    inner_sliding: np.ndarray
    outer_sliding: np.ndarray
    inner_rolling: np.ndarray
    outer_rolling: np.ndarray
    land_torque: float
    ring_torque: float
    power_loss: float

    @property
    def cage_slip(self) -> float:
        """1 − ω_c/ω_c,epicyclic [-], the quantity ``summarize`` reports as cage slip."""
        return 1.0 - self.cage_speed / self.epicyclic_cage_speed

    @property
    def roller_slip(self) -> np.ndarray:
        """1 − (ω_j − ω_c)/(the epicyclic spin in the cage) [-] at each azimuth: the deficit of the roller's spin in
        the cage, as a roller-speed sensor on the cage measures it (0 rolling at the epicyclic speeds, 1 not
        turning in its pocket)."""
        return 1.0 - (self.roller_speeds - self.cage_speed) / self.epicyclic_roller_spin


def orbit_power_intensity(spec, scene: Scene, solution: SkiddingSolution) -> tuple[np.ndarray, np.ndarray]:
    """(inner, outer) frictional power intensity q = |μQ Δu|/(2 b l) [W/m²] of a roller's raceway contacts at the
    solution's azimuths (:func:`.metrics.frictional_power_intensity`, the dynamic runs' measure): the traction of
    each raceway's law at the solution's loads, sliding and rolling speeds (``inner_traction`` and
    ``outer_traction`` also hold the hydrodynamic rolling resistance's tangential share, which is not sliding);
    0 out of contact. ``spec`` and ``scene`` are those the solution was solved for."""
    sign = {Group.INNER_RACE: 1.0, Group.OUTER_RACE: -1.0}  # the inner pair's tangent is e_θ, the outer's −e_θ
    states = {Group.INNER_RACE: (solution.inner_loads, solution.inner_sliding, solution.inner_rolling),
              Group.OUTER_RACE: (solution.outer_loads, solution.outer_sliding, solution.outer_rolling)}
    intensity = []
    for group, (load, sliding, rolling) in states.items():
        traction = law_traction(scene, int(pair_columns(scene, group)[0]), load, sign[group] * sliding, rolling)
        intensity.append(frictional_power_intensity(traction, sliding, load, raceway_contact(spec, scene, group)))
    return intensity[0], intensity[1]


#: Rows of the packed raceway and land laws (:func:`bearing_mbs.elements.contact_pairs.pack`).
_INNER, _OUTER, _LAND = 0, 1, 2


@dataclass(frozen=True)
class _Bearing:
    """What the balance reads from the scene."""

    layout: BearingLayout
    load: np.ndarray
    drag: tuple[float, float, float, float]  # on a roller: linear [N s/m], quadratic [N s²/m²], angular
    # [N m s/rad], angular quadratic [N m s²/rad²]
    cage_drag: tuple[float, float]  # on the cage: angular [N m s/rad], angular quadratic [N m s²/rad²]
    cage_mass: float
    cage_radius: float
    laws: PairArrays  # the inner and outer raceway pairs' laws, then the land's if the cage has one
    gravity: np.ndarray
    pocket_contacts: bool
    land_film: JournalFilm | None
    pocket_film: tuple[float, float] = (0.0, 0.0)  # a constraint cage's oiled pockets, per rad/s of the roller's spin
    # in the cage: the moment on the roller and the torque on the cage [N m s/rad] (:func:`pocket_film_coefficients`)


def solve_skidding(scene: Scene, *, phases: int = 6) -> SkiddingSolution:
    """The steady cage and roller speeds of a constant-speed, constant-load bearing scene with a cage."""
    bearing = _read(scene)
    layout = bearing.layout
    epicyclic = layout.raceways.epicyclic_cage_speed(layout.shaft_speed)

    def torque(cage_speed):
        return _state(bearing, cage_speed, phases)[0]

    # bracket from the epicyclic speed down: an orbit at a crawling cage speed takes long to integrate
    high = 1.02 * epicyclic
    above = torque(high)
    for fraction in BRACKET_FRACTIONS:
        low = fraction * epicyclic
        if torque(low) * above <= 0:
            break
        high = low
    else:
        raise ArithmeticError(f"{scene.name}: no cage torque balance between {BRACKET_FRACTIONS[-1]:.0%} and 102 % "
                              "of the epicyclic cage speed: the cage slips by more than "
                              f"{1 - BRACKET_FRACTIONS[-1]:.0%} (the drags exceed what the traction carries) or is not "
                              "driven at all")
    cage_speed = brentq(torque, low, high, xtol=1e-10 * epicyclic, rtol=1e-12)
    roller = layout.raceways.epicyclic_spin_in_cage(layout.shaft_speed)
    return SkiddingSolution(cage_speed, epicyclic, roller, **_state(bearing, cage_speed, phases)[1])


def _read(scene: Scene) -> _Bearing:
    layout = BearingLayout.of(scene)
    pairs = scene.topology.pairs if scene.topology is not None else {}
    if layout is None or Role.CAGE not in scene.topology.bodies:
        raise SpecError("cage.model", "none" if layout is not None else scene.name,
                        "a caged roller bearing (inner ring, rollers, cage) for the skidding balance")
    if layout.lowest_speed != layout.shaft_speed:
        raise SpecError("drive.profile", f"{layout.lowest_speed:g} to {layout.shaft_speed:g} rad/s",
                        "a constant shaft speed for a steady state")
    _, applied = layout.applied_load()
    if np.ptp(applied, axis=0).max() > 0:
        raise SpecError("load.profile", "varies in time", "a constant load for a steady state")
    cage_index = scene.topology.body(Role.CAGE)

    def drag_sum(body, *names):
        return tuple(sum(getattr(d, name) for d in scene.items_of(Drag) if d.body == body) for name in names)

    cage = scene.bodies[cage_index]
    land = scene.pairs[int(pairs[Group.LAND][0])] if Group.LAND in pairs else None
    raceways = [scene.pairs[int(pairs[group][0])] for group in (Group.INNER_RACE, Group.OUTER_RACE)]
    constrained = any(isinstance(c, OrbitConstraint) for c in scene.constraints)
    return _Bearing(layout, applied[-1],
                    drag_sum(layout.rollers[0], "linear", "quadratic", "angular", "angular_quadratic"),
                    drag_sum(cage_index, "angular", "angular_quadratic"), cage.mass,
                    land.radius_b if land is not None else 0.0,
                    pack(raceways + ([land] if land is not None else [])),
                    np.asarray(scene.gravity, float), not constrained,
                    next((f for f in scene.items_of(JournalFilm) if f.body == cage_index), None),
                    pocket_film_coefficients(scene, cage_index) if constrained and Group.POCKET_FILM in pairs else (0.0, 0.0))


def pocket_film_coefficients(scene: Scene, cage_index: int) -> tuple[float, float]:
    """(moment on the roller, torque on the cage) [N m s/rad] per rad/s of a roller's spin in the cage, from its
    pocket walls' oil films (the film pairs' own law, :func:`bearing_mbs.elements.contact_pairs.add_forces_twin`) with
    the roller centred in its pocket, where the constraint cage holds it: at a fixed gap the films' forces are linear
    in the speeds (Reynolds' equation is), so one evaluation at 1 rad/s gives both."""
    films = np.asarray(scene.topology.pairs[Group.POCKET_FILM])[0]
    roller = scene.pairs[int(films[0])].body_b
    q = np.array([coordinate for body in scene.bodies for coordinate in body.position], float)
    v = np.zeros_like(q)
    v[3 * roller + 2] = 1.0
    forces = np.zeros_like(q)
    packed = pack([scene.pairs[int(k)] for k in films])
    add_forces_twin(packed, 0.0, q, v, np.zeros(len(films)), forces, np.zeros((len(films), N_PAIR_OUTPUTS)),
                    np.zeros(2), True)
    return float(forces[3 * roller + 2]), float(forces[3 * cage_index + 2])


def _contact(laws: PairArrays, k: int, load, sliding, relative_spin, rolling, orientation, raceway_radius, radius):
    """(tangential force along the pair's tangent [N], moment [N m]) on the roller at contact k: the compiled
    kernel's traction (−μ Q along the slip) and what resists the rolling (the dry arm's moment, the hydrodynamic
    rolling resistance if it is on)."""
    if load <= 0.0:
        return 0.0, 0.0
    law, vreg = laws.friction_law[k], laws.regularisation_speed[k]
    traction = kernel.tangential_force(law, load, laws.friction_coefficient[k], sliding, rolling, vreg,
                                       laws.traction[k])
    return kernel.rolling_resistance(law, traction, load, laws.rolling_resistance_arm[k], relative_spin, rolling,
                                     orientation, raceway_radius, radius, 0.0, vreg, laws.traction[k])


class _RollerForces(NamedTuple):
    moment: float  # on the roller about its centre [N m]
    inner_traction: float  # F_i [N]
    outer_traction: float  # F_o [N]
    inner_sliding: float  # Δu_i [m/s]
    outer_sliding: float  # Δu_o [m/s]
    inner_rolling: float  # u_i [m/s]
    outer_rolling: float  # u_o [m/s]
    pocket_force: float  # P [N]
    ring_torque: float  # the roller's torque on the inner ring [N m]
    power_loss: float  # dissipated at the roller's contacts, by its drags and in its pocket films [W]
    film_torque: float  # its pocket films' torque on the cage [N m] (constraint cage, oiled pockets)


def _roller(bearing: _Bearing, cage_speed: float, spin: float, q_i: float, q_o: float) -> _RollerForces:
    """The forces on a roller spinning at ``spin`` [rad/s] under the contact loads [N] while the cage turns at
    ``cage_speed`` [rad/s]."""
    layout = bearing.layout
    raceways = layout.raceways
    r, orbit, omega_i = raceways.roller_radius, cage_speed * raceways.pitch_diameter / 2, layout.shaft_speed
    r_i, r_o = raceways.inner_radius, raceways.outer_radius
    linear, quadratic, angular, angular_quadratic = bearing.drag
    spin_drag = (angular + angular_quadratic * abs(spin)) * spin
    du_i, du_o = orbit - spin * r - omega_i * r_i, orbit + spin * r
    u_i = 0.5 * ((omega_i - cage_speed) * r_i + (cage_speed - spin) * r)
    u_o = 0.5 * (cage_speed * r_o + (cage_speed - spin) * r)
    # the inner contact's tangent is e_θ, the outer's −e_θ (the slips Δu are along e_θ, the rolling speeds u along
    # the tangents); f_i, f_o are along e_θ
    f_i, m_i = _contact(bearing.laws, _INNER, q_i, du_i, spin - omega_i, u_i, 1.0, r_i, r)
    f_o_tangent, m_o = _contact(bearing.laws, _OUTER, q_o, -du_o, spin, u_o, -1.0, r_o, r)
    f_o = -f_o_tangent
    drag = (linear + quadratic * abs(orbit)) * orbit
    film_moment, film_torque = (coefficient * (spin - cage_speed) for coefficient in bearing.pocket_film)
    loss = (-f_i * du_i - f_o * du_o - m_i * (spin - omega_i) - m_o * spin + drag * orbit + spin_drag * spin
            - film_moment * spin - film_torque * cage_speed)
    return _RollerForces(-r * f_i + r * f_o + m_i + m_o - spin_drag + film_moment, f_i, f_o, du_i, du_o, u_i, u_o,
                         drag - f_i - f_o, -r_i * f_i - m_i, loss, film_torque)


def _loads_around_the_orbit(bearing: _Bearing, cage_speed: float, phases: int):
    """Roller azimuths ψ [rad] in [0, 2π), sorted, and the inner and outer contact loads [N] there, from the
    load distribution with roller 0 at ``phases`` offsets across one roller pitch."""
    layout = bearing.layout
    equivalent_shaft = cage_speed / layout.raceways.epicyclic_cage_speed(1.0)
    pitch = 2 * np.pi / len(layout.rollers)
    solutions = [solve_radial(replace(layout.roller_set(), first_roller_angle=pitch * k / phases), bearing.load,
                              shaft_speed=equivalent_shaft) for k in range(phases)]
    psi = np.concatenate([s.roller_angles for s in solutions]) % (2 * np.pi)
    order = np.argsort(psi)
    q_i = np.concatenate([s.inner_loads for s in solutions])[order]
    q_o = np.concatenate([s.outer_loads for s in solutions])[order]
    return psi[order], q_i, q_o


#: Orbit means integrated alongside a roller's spin: pocket force [N], torque on the ring [N m], power loss [W],
#: pocket films' torque on the cage [N m].
_MEANS = ("pocket_force", "ring_torque", "power_loss", "film_torque")


def _spin_around_the_orbit(bearing: _Bearing, cage_speed: float, psi, q_i, q_o):
    """A roller's spin [rad/s] at the azimuths ψ over its periodic orbit, I dω/dt = M(ω, ψ) with ψ = ω_c t, and
    the orbit means of :data:`_MEANS`.

    In the load zone the tractions hold the spin at its balance within microseconds; outside it the roller
    coasts, slowed by the outer raceway's light traction and its drags, for a time comparable with the orbit
    (a balance at every azimuth would overstate the slip). The orbit starts at the most loaded azimuth, at the
    spin's balance there, and is made periodic by a secant on the spin it ends with. The means are integrated with the
    spin, by the same adaptive steps, so that the sharp spin-up where a roller enters the load zone counts in
    full."""
    layout = bearing.layout
    period = 2 * np.pi / cage_speed
    start = int(np.argmax(q_i))
    psi_from = np.concatenate([psi[start:], psi[:start] + 2 * np.pi]) - psi[start]
    loads_i, loads_o = np.roll(q_i, -start), np.roll(q_o, -start)
    closed = np.append(psi_from, 2 * np.pi)

    def load_at(t, loads):
        return np.interp((cage_speed * t) % (2 * np.pi), closed, np.append(loads, loads[0]))

    def rate(t, y):
        forces = _roller(bearing, cage_speed, y[0], load_at(t, loads_i), load_at(t, loads_o))
        return [forces.moment / layout.roller_inertia, *(getattr(forces, name) for name in _MEANS)]

    times = np.append(psi_from / cage_speed, period)

    def orbit(spin0):
        solution = solve_ivp(rate, (0.0, period), [spin0, 0.0, 0.0, 0.0, 0.0], method="LSODA", rtol=1e-10,
                             atol=np.array([1e-9, 1e-12, 1e-12, 1e-9, 1e-12]), t_eval=times)
        if not solution.success:
            raise ArithmeticError(f"the roller-spin orbit failed at cage speed {cage_speed:g} rad/s: "
                                  f"{solution.message}")
        return solution

    middle, half = _rolling_bracket(bearing, cage_speed)
    spin0 = _bracketed_root(lambda w: _roller(bearing, cage_speed, w, loads_i[0], loads_o[0]).moment, middle, half)
    # the periodic orbit: a secant on ω(T) − ω(0), from the balance at the start and one orbit on
    runs = [orbit(spin0)]
    starts = [spin0, runs[0].y[0, -1]]
    runs.append(orbit(starts[1]))
    gaps = [starts[1] - starts[0], runs[1].y[0, -1] - starts[1]]
    while abs(gaps[-1]) > 1e-10 * abs(starts[-1]) and len(gaps) < 30:
        step = gaps[-1] * (starts[-1] - starts[-2]) / (gaps[-1] - gaps[-2]) if gaps[-1] != gaps[-2] else 0.0
        starts.append(starts[-1] - step)
        runs.append(orbit(starts[-1]))
        gaps.append(runs[-1].y[0, -1] - starts[-1])
    if abs(gaps[-1]) > 1e-6 * abs(starts[-1]):
        raise ArithmeticError(f"the roller-spin orbit at cage speed {cage_speed:g} rad/s did not close: it ends "
                              f"{gaps[-1]:.3g} rad/s from its start after {len(gaps)} orbits")
    periodic = runs[-1]
    return np.roll(periodic.y[0, :-1], start), dict(zip(_MEANS, periodic.y[1:, -1] / period))


def _rolling_bracket(bearing: _Bearing, cage_speed: float):
    """The middle and half width [rad/s] of the spins between rolling on the outer and on the inner raceway."""
    layout = bearing.layout
    raceways = layout.raceways
    orbit, r = cage_speed * raceways.pitch_diameter / 2, raceways.roller_radius
    on_outer, on_inner = -orbit / r, (orbit - layout.shaft_speed * raceways.inner_radius) / r
    return 0.5 * (on_outer + on_inner), 0.5 * abs(on_outer - on_inner) + 1.0


def _state(bearing: _Bearing, cage_speed: float, phases: int):
    """(the cage's mean torque [N m], the steady state's fields of :class:`SkiddingSolution`) at the cage
    speed [rad/s]."""
    layout = bearing.layout
    radius, rollers = layout.raceways.pitch_diameter / 2, layout.raceways.rollers
    psi, q_i, q_o = _loads_around_the_orbit(bearing, cage_speed, phases)
    spins, means = _spin_around_the_orbit(bearing, cage_speed, psi, q_i, q_o)
    rows = _RollerForces(*(np.array(column) for column in zip(*(_roller(bearing, cage_speed, *values)
                                                                     for values in zip(spins, q_i, q_o)))))
    # the land carries the cage's weight and, with pocket contacts, their net force −Σ P_j e_θ,j at each phase
    # (the constraint cage's pockets hold orbital angles about the axis: a pure torque on the cage)
    pocket = rows.pocket_force
    net = np.zeros((phases, 2))
    if bearing.pocket_contacts:
        net = np.stack([pocket * np.sin(psi), -pocket * np.cos(psi)], axis=1).reshape(rollers, phases, 2).sum(axis=0)
    normal = np.hypot(*(net + bearing.cage_mass * bearing.gravity).T)
    land = 0.0
    if bearing.land_film is not None:
        land = float(np.mean([_film_torque(bearing.land_film, cage_speed, load) for load in normal]))
    elif bearing.laws.kind.size > _LAND:
        laws = bearing.laws
        sign = kernel.regularised_sign(laws.friction_law[_LAND], cage_speed * bearing.cage_radius,
                                       laws.regularisation_speed[_LAND])
        land = -laws.friction_coefficient[_LAND] * float(np.mean(normal)) * bearing.cage_radius * sign
    angular, angular_quadratic = bearing.cage_drag
    churning = -(angular + angular_quadratic * abs(cage_speed)) * cage_speed
    torque = -radius * rollers * means["pocket_force"] + rollers * means["film_torque"] + land + churning
    state = {"roller_angles": psi, "inner_loads": q_i, "outer_loads": q_o, "roller_speeds": spins,
             "pocket_forces": pocket, "inner_traction": rows.inner_traction, "outer_traction": rows.outer_traction,
             "inner_sliding": rows.inner_sliding, "outer_sliding": rows.outer_sliding,
             "inner_rolling": rows.inner_rolling, "outer_rolling": rows.outer_rolling, "land_torque": land,
             "ring_torque": rollers * means["ring_torque"],
             "power_loss": rollers * means["power_loss"] - (land + churning) * cage_speed}
    return torque, state


def _film_torque(film: JournalFilm, speed: float, load: float) -> float:
    """The land film's torque [N m] on the cage turning at ``speed`` [rad/s] and carrying ``load`` [N]: at the
    steady eccentricity where the short bearing's force equals the load."""
    def capacity(eps):
        return math.hypot(*short_bearing_force(eps * film.clearance, 0.0, 0.0, 0.0, speed, film.radius, film.length,
                                               film.clearance, film.viscosity)) - load

    eps = 0.0 if load <= 0 else brentq(capacity, 0.0, LARGEST_ECCENTRICITY) if capacity(LARGEST_ECCENTRICITY) > 0 \
        else LARGEST_ECCENTRICITY
    return film.count * short_bearing_torque(eps, speed, film.radius, film.length, film.clearance, film.viscosity)


def _bracketed_root(function, middle: float, half: float) -> float:
    """The root of a decreasing function of the roller speed, searched in middle ± half, widened until it
    changes sign (the speeds that roll on either raceway bracket it unless the drags dominate)."""
    for _ in range(40):
        low, high = middle - half, middle + half
        if function(low) >= 0 >= function(high):
            return brentq(function, low, high, xtol=1e-12 * (abs(middle) + half), rtol=1e-14)
        half *= 2
    raise ArithmeticError(f"no roller-speed balance within {middle:g} ± {half:g} rad/s")
