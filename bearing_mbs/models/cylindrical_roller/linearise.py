r"""The bearing model's linearisation: its expected operating point and the linearised modes there.

The step advisor (:mod:`bearing_mbs.numerics.advisor`) asks each model to :func:`linearise` a scene and turns the
modes into step limits. What limits an explicit step on this bearing is the regularised friction of the loaded
raceway contacts, not the Hertz stiffness (docs/numerics.md, measured).

Operating point
---------------
The scene is read through its topology (the ``inner_ring`` and its ``inner_race`` and ``outer_race`` pairs). The
applied load :math:`F(t)` on the inner ring, its weight included (:func:`~.stiffness.carried_load`), is read from
the scene. The scene starts with the ring centred and the rollers on the pitch circle, so the load arrives
suddenly and overshoots:

* a load :math:`F_0` present at :math:`t = 0` falls through the radial clearance :math:`h = \max(P_d/2, 0)` onto a
  spring of static deflection :math:`\delta_s`; the linear drop formula gives the dynamic factor
  :math:`D_0 = 1 + \sqrt{1 + 2h/\delta_s}` (2 without clearance);
* a later rise :math:`\Delta F` over a ramp of duration :math:`t_r` overshoots by the classical ramp factor
  :math:`D_r = 1 + |\sin(\omega t_r/2)|/(\omega t_r/2)`, :math:`\omega^2 = \lambda_{max}(K_{bearing})/M_{ring}`;
* rollers that start orbiting are thrown outwards by their centrifugal force :math:`F_c` through the gap
  :math:`P_d/4`: the same drop formula.

The roller loads at the peak load come from the quasi-static solver
(:func:`bearing_mbs.models.cylindrical_roller.quasistatic.solve_radial`, centrifugal force included): inner load
:math:`Q_i` and outer load :math:`Q_o = Q_i + F_c`. A roller carrying no ring load is pressed on the outer raceway
by :math:`F_c` alone.

Linearised modes
----------------
Per raceway contact of normal load :math:`Q`, exponent :math:`n`, stiffness :math:`K` (:math:`\delta = (Q/K)^{1/n}`):

* friction: a viscous coefficient :math:`c_t = \mu Q \varphi'(0)` [N s/m], :math:`\varphi'(0) v_{reg}` from
  :data:`bearing_mbs.contact.friction.ZERO_SLIP_SLOPE`; rolling resistance adds :math:`c_R = \mu_R Q \varphi'(0) r`
  [N m s] on the roller's spin. The hydrodynamic rolling resistance of an ``ehl`` raceway is left out: its force
  varies with the rolling speed as :math:`F_R \propto u^{0.658}`, a damping of about 1 N s/m for the seed
  bearing (0.66 F_R/u; below 40 N s/m inside the regularisation, :math:`|u| < v_{reg}`), far below the
  :math:`10^4`–:math:`10^7` N s/m of the loaded rollers' traction, which sets the step;
* normal: the tangent stiffness :math:`k = dQ/d\delta` and the hysteresis damping at the approach-speed floor,
  :math:`c_n = d\,Q/v_{floor}`.

The two raceway contacts of a roller act on its tangential translation :math:`u` and spin :math:`\theta`; with
:math:`a_i = (1, -r)`, :math:`a_o = (1, r)`, the friction damping matrix is
:math:`C = c_i a_i a_i^T + c_o a_o a_o^T + \mathrm{diag}(0, c_{R,i} + c_{R,o})` (a lubricant's viscous drag on the
roller adds to its diagonal) and the mass matrix :math:`M = \mathrm{diag}(m_r, I_r)`. Its modes decay at the
eigenvalues of :math:`M^{-1}C`. The inner ring's share of the inner contact's compliance (under 1 % here) is left
out. The roller's radial motion is an oscillator :math:`\omega^2 = (k_i + k_o)/m_r`,
:math:`2\sigma = (c_{n,i} + c_{n,o})/m_r`; the inner ring on its rollers another,
:math:`\omega^2 = \lambda_{max}(K_{bearing})/M_{ring}`; the velocity servo a decay :math:`\lambda = g/I_{ring}`.
Pocket, land and roller–roller contacts carry no quasi-static load and are left out. A pocket's oil film
(``[lubricant] pocket_film``) is stiffest and most damping at its floor :math:`h_f`: there a roller pressed on the
wall oscillates with the film's wedge stiffness :math:`k = -\partial W/\partial h` and squeeze damping
:math:`c = -\partial W/\partial\dot h` (:func:`bearing_mbs.fluid_film.cylinder_plane.film_forces`, by central
differences) at the entrainment of the roller's epicyclic spin in the cage, :math:`u = r|\omega_r - \omega_c|/2`
at the highest shaft speed: :math:`\omega^2 = k/m_r`, :math:`2\sigma = c/m_r`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from bearing_mbs.contact.friction import ZERO_SLIP_SLOPE
from bearing_mbs.contact.line_contact import power_law_stiffness
from bearing_mbs.contact.traction import zero_slip_slope
from bearing_mbs.core.scene import Scene
from bearing_mbs.core.topology import Group, Role
from bearing_mbs.elements import Drag, Load, VelocityServo
from bearing_mbs.fluid_film.cylinder_plane import film_forces
from bearing_mbs.models.cylindrical_roller.geometry import RacewayLayout, roller_centrifugal_force
from bearing_mbs.models.cylindrical_roller.quasistatic import RollerSet, solve_radial
from bearing_mbs.models.cylindrical_roller.stiffness import carried_load


@dataclass(frozen=True)
class Mode:
    r"""A linearised mode :math:`\ddot q = \alpha q + \beta\dot q`: ``alpha`` [1/s²] (−ω²), ``beta`` [1/s]
    (−2σ, or −λ for a pure decay); ``where`` names the body or bodies it belongs to; ``load`` [N] the contact load
    used."""

    name: str
    where: str
    alpha: float
    beta: float
    load: float = 0.0

    @property
    def rate(self) -> float:
        """Largest |eigenvalue| [1/s]."""
        return float(np.max(np.abs(np.roots([1.0, -self.beta, -self.alpha]))))


@dataclass(frozen=True)
class Linearisation:
    """``operating_point``: the loads [N], speeds [rad/s] and first peak time [s] used; ``modes``."""

    operating_point: dict
    modes: tuple[Mode, ...]


def linearise(scene: Scene) -> Linearisation | None:
    """The operating point and modes of a bearing scene; None for a scene that is not one (no ``inner_ring``
    with ``inner_race`` and ``outer_race`` pairs in its topology)."""
    layout = BearingLayout.of(scene)
    if layout is None:
        return None
    point, roller_cases, ring_mode = operating_point(layout)
    modes = []
    for label, inner_load, outer_load in roller_cases:
        modes += roller_modes(layout, label, inner_load, outer_load)
    modes += pocket_film_modes(layout)
    if ring_mode is not None:
        modes.append(ring_mode)
    if layout.servo_gain > 0:
        modes.append(Mode("velocity servo", layout.ring_name, 0.0, -layout.servo_gain / layout.ring_inertia))
    return Linearisation(point, tuple(modes))


@dataclass(frozen=True)
class BearingLayout:
    """What the linearisation reads from a bearing scene: the raceways' layout (:class:`~.geometry.RacewayLayout`,
    from the raceway pairs' radii), masses [kg], inertias [kg m²], raceway laws, servo gain [N m s], highest ring
    speed [rad/s], initial orbit speed [rad/s], roller drag (linear [N s/m], angular [N m s]) and lowest ring speed
    [rad/s]."""

    scene: Scene
    ring: int
    ring_name: str
    ring_mass: float
    ring_inertia: float
    rollers: tuple[int, ...]
    roller_mass: float
    roller_inertia: float
    raceways: RacewayLayout
    inner_law: object
    outer_law: object
    servo_gain: float
    shaft_speed: float
    initial_orbit_speed: float
    roller_drag: tuple[float, float] = (0.0, 0.0)
    lowest_speed: float = 0.0

    @classmethod
    def of(cls, scene: Scene) -> BearingLayout | None:
        topology = scene.topology
        inner, outer = topology.group(Group.INNER_RACE), topology.group(Group.OUTER_RACE)
        if not topology.has(Role.INNER_RING) or inner.size == 0 or inner.size != outer.size:
            return None
        ring = topology.body(Role.INNER_RING)
        inner_pairs = [scene.pairs[k] for k in inner.ravel()]
        outer_pair = scene.pairs[int(outer.ravel()[0])]
        if inner_pairs[0].kind != "circle_circle" or any(p.body_a != ring for p in inner_pairs):
            return None
        rollers = tuple(p.body_b for p in inner_pairs)
        roller = scene.bodies[rollers[0]]
        ring_body = scene.bodies[ring]
        servos = [d for d in scene.items_of(VelocityServo) if d.body == ring]
        speeds = [abs(ring_body.velocity[2])] + [abs(v) for d in servos for v in d.speed.values]
        x, y = roller.position[:2]
        orbit = (x * roller.velocity[1] - y * roller.velocity[0]) / max(x * x + y * y, 1e-300)
        drags = [d for d in scene.items_of(Drag) if d.body == rollers[0]]
        orbit_speed = abs(orbit) * math.hypot(x, y)
        drag = (sum(d.linear + 2 * d.quadratic * orbit_speed for d in drags), sum(d.angular for d in drags))
        return cls(scene, ring, ring_body.name, ring_body.mass, ring_body.inertia, rollers, roller.mass,
                   roller.inertia, RacewayLayout.of_pairs(len(rollers), inner_pairs[0], outer_pair),
                   inner_pairs[0].law, outer_pair.law, sum(d.gain for d in servos), max(speeds), abs(orbit), drag,
                   min(speeds))

    def rolling_speeds(self) -> tuple[float, float]:
        """The raceways' slowest and fastest rolling speeds [m/s] of the run, (ω_i − ω_c) r_i at its lowest and
        highest ring speed with the cage at its epicyclic speed."""
        speeds = (self.lowest_speed, self.shaft_speed)
        return tuple(float((w - self.raceways.epicyclic_cage_speed(w)) * self.raceways.inner_radius) for w in speeds)

    def roller_set(self) -> RollerSet:
        """The bearing for the quasi-static solver, with the scene's raceway laws."""
        raceways = self.raceways
        return RollerSet(rollers=raceways.rollers, pitch_diameter=raceways.pitch_diameter,
                         roller_diameter=raceways.roller_diameter, roller_length=1.0,
                         diametral_clearance=raceways.clearance, roller_mass=self.roller_mass,
                         inner_stiffness=self.inner_law.stiffness, inner_exponent=self.inner_law.exponent,
                         outer_stiffness=self.outer_law.stiffness, outer_exponent=self.outer_law.exponent)

    def centrifugal_force(self, orbit_speed: float) -> float:
        """F_c [N] of a roller orbiting at ``orbit_speed`` [rad/s]."""
        return roller_centrifugal_force(self.roller_mass, self.raceways.pitch_diameter, orbit_speed)

    def applied_load(self) -> tuple[np.ndarray, np.ndarray]:
        """Instants [s] (all load breakpoints) and the load (Fx, Fy) [N] on the rollers there, weight included."""
        loads = [item for item in self.scene.items_of(Load) if item.body == self.ring]
        times = np.unique(np.concatenate([[0.0]] + [np.asarray(item.profile.times, float) for item in loads]))
        applied = np.zeros((times.size, 2))
        for item in loads:
            applied += np.outer(item.profile(times), item.vector[:2])
        return times, carried_load(applied, self.ring_mass, self.scene.gravity)


def approach(load: float, law) -> float:
    r"""The contact approach :math:`\delta = (Q/K)^{1/n}` [m] of the power law under ``load`` [N]."""
    return (load / law.stiffness) ** (1 / law.exponent)


def operating_point(layout: BearingLayout):
    """(operating_point dict, roller load cases [(label, Q_i [N], Q_o [N])], ring mode or None)."""
    rollers, clearance = layout.roller_set(), layout.raceways.clearance
    speed = layout.shaft_speed
    solutions = {}

    def solve(load):
        """The quasi-static solution at ``load`` [N] (memoised: a constant load is solved once)."""
        key = (round(float(load[0]), 9), round(float(load[1]), 9))
        if key not in solutions:
            solutions[key] = solve_radial(rollers, key, shaft_speed=speed)
        return solutions[key]

    centrifugal = layout.centrifugal_force(layout.raceways.epicyclic_cage_speed(speed))
    times, force = layout.applied_load()
    magnitude = np.hypot(force[:, 0], force[:, 1])
    biggest = int(np.argmax(magnitude))
    static = float(magnitude[biggest])
    direction = force[biggest] / static if static > 0 else np.array([0.0, -1.0])
    drop = max(clearance / 2, 0.0)

    solution = solve(force[biggest]) if static > 0 or clearance < 0 else None
    ring_frequency = 0.0
    if solution is not None:
        ring_frequency = math.sqrt(max(np.linalg.eigvalsh(solution.stiffness).max(), 0.0) / layout.ring_mass)

    # the load present at t = 0 falls on the rollers; later rises overshoot like a ramp on an oscillator
    peak = magnitude[0]
    if magnitude[0] > 0:
        elastic = max(float(np.hypot(*solve(force[0]).displacement)) - drop, 1e-12)
        peak = (1 + math.sqrt(1 + 2 * drop / elastic)) * magnitude[0]
    for k in range(1, times.size):
        rise, duration = magnitude[k] - magnitude[k - 1], times[k] - times[k - 1]
        if rise > 0:
            phase = 0.5 * ring_frequency * duration
            factor = 2.0 if phase == 0 else 1 + abs(math.sin(phase)) / phase
            peak = max(peak, magnitude[k - 1] + factor * rise)
    peak = max(peak, static)

    cases = []
    at_peak = None
    if peak > 0 or clearance < 0:
        at_peak = solve(peak * direction)
        j = int(np.argmax(at_peak.inner_loads))
        cases.append(("loaded roller", float(at_peak.inner_loads[j]), float(at_peak.outer_loads[j])))
    # rollers that start orbiting are thrown onto the outer raceway
    thrown = layout.centrifugal_force(layout.initial_orbit_speed)
    peak_centrifugal = centrifugal
    if thrown > 0:
        gap = max(clearance / 4, 0.0)
        peak_centrifugal = max(centrifugal, thrown * (1 + math.sqrt(1 + 2 * gap / approach(thrown, layout.outer_law))))
    if peak_centrifugal > 0:
        cases.append(("unloaded roller", 0.0, peak_centrifugal))

    stiffest = max(np.linalg.eigvalsh(at_peak.stiffness).max(), 0.0) if at_peak is not None else 0.0
    ring_mode = None
    if at_peak is not None:
        ring_mode = Mode("inner ring on the rollers", layout.ring_name, -stiffest / layout.ring_mass, 0.0, peak)
    # the first load peak: the ring falls through the clearance, then half a period on its rollers
    drop_time = math.sqrt(2 * drop * layout.ring_mass / static) if static > 0 else 0.0
    peak_time = drop_time + (math.pi * math.sqrt(layout.ring_mass / stiffest) if stiffest > 0 else 0.0)
    point = {
        "first_peak_time": peak_time,
        "static_load": static, "peak_load": float(peak), "load_factor": float(peak / static) if static else 1.0,
        "shaft_speed": speed, "centrifugal_force": centrifugal, "peak_centrifugal_force": peak_centrifugal,
        "max_roller_load": float(solution.max_roller_load) if solution is not None else 0.0,
        "peak_roller_load": cases[0][1] if at_peak is not None else 0.0,
    }
    return point, cases, ring_mode


def roller_modes(layout: BearingLayout, label: str, inner_load: float, outer_load: float) -> list[Mode]:
    """Friction (tangential and spin) and radial modes of one roller with raceway loads Q_i, Q_o [N]."""
    m, inertia, r = layout.roller_mass, layout.roller_inertia, layout.raceways.roller_radius

    def friction(law, load):
        slope = ZERO_SLIP_SLOPE[law.friction_law] / law.regularisation_speed
        damping = law.friction_coefficient * load * slope
        if law.friction_law == "ehl" and load > 0:  # the film's slope, steepest at the slowest rolling
            damping = load * max(zero_slip_slope(np.asarray(law.traction), speed, load, law.friction_coefficient,
                                                 law.regularisation_speed) for speed in layout.rolling_speeds())
        return damping, law.rolling_resistance_arm * load * slope * r

    ci, ri = friction(layout.inner_law, inner_load)
    co, ro = friction(layout.outer_law, outer_load)
    drag_linear, drag_angular = layout.roller_drag
    damping = (ci * np.outer([1, -r], [1, -r]) + co * np.outer([1, r], [1, r])
               + np.diag([drag_linear, ri + ro + drag_angular]))
    rates = np.linalg.eigvals(np.diag([1 / m, 1 / inertia]) @ damping).real
    modes = [Mode(f"friction, {label}", str(Role.ROLLERS), 0.0, -float(rate), max(inner_load, outer_load))
             for rate in sorted(rates, reverse=True) if rate > 0][:1]

    def normal(law, load):
        if load <= 0:
            return 0.0, 0.0
        stiffness = power_law_stiffness(approach(load, law), law.stiffness, law.exponent)
        return stiffness, law.damping_factor * load / law.approach_speed_floor

    ki, dni = normal(layout.inner_law, inner_load)
    ko, dno = normal(layout.outer_law, outer_load)
    if ki + ko > 0:
        modes.append(Mode(f"radial contact, {label}", str(Role.ROLLERS), -(ki + ko) / m, -(dni + dno) / m,
                          max(inner_load, outer_load)))
    return modes


def pocket_film_modes(layout: BearingLayout) -> list[Mode]:
    """The mode of a roller on a pocket wall's oil film at the film's floor (none without pocket films)."""
    films = layout.scene.topology.group(Group.POCKET_FILM)
    if films.size == 0:
        return []
    pair = layout.scene.pairs[int(np.ravel(films)[0])]
    length, viscosity, half_width, floor = pair.law.film
    raceways = layout.raceways
    cage = raceways.epicyclic_cage_speed(layout.shaft_speed)
    entrainment = raceways.roller_radius * abs(-cage * raceways.pitch_diameter / raceways.roller_diameter - cage) / 2

    def load(gap, rate):
        return film_forces(viscosity, entrainment, 0.0, rate, pair.radius_b, length, half_width, gap)[0]

    gap_step, rate_step = 1e-3 * floor, 1e-6 * max(entrainment, 1.0)
    stiffness = -(load(floor + gap_step, 0.0) - load(floor - gap_step, 0.0)) / (2 * gap_step)
    damping = -(load(floor, rate_step) - load(floor, -rate_step)) / (2 * rate_step)
    mass = layout.roller_mass
    return [Mode("pocket film, at its floor", str(Role.ROLLERS), -stiffness / mass, -damping / mass)]
