r"""Quasi-static cross-check of the dynamic bearing model: static equilibria, stiffness and steady running.

``bearing-mbs static-check SCENARIO.toml --out DIR`` runs :func:`run` (the repository's scenario is
``scenarios/static_check.toml``), prints :func:`report` and writes ``DIR/static_check.json`` (:func:`write`).

The quasi-static planar solver (:func:`bearing_mbs.models.cylindrical_roller.quasistatic.solve_radial`, document 003's displacement
method) is the independent reference: it shares the Palmgren law and the geometry with the dynamic model,
but none of its kinematics, integrators or contact bookkeeping.

Static equilibrium on a dynamic engine
--------------------------------------
Exudyn's static solver is not used: the rollers outside the loaded zone and the cage have no stiffness in
some directions (a singular static Jacobian), and the contact forces come from one ObjectGenericODE2 user
function without an analytic Jacobian. Instead each engine *settles* a resting bearing:

* the inner ring's speed servo holds 0 rpm and every body starts at rest (``initial_state = "rest"``);
* the radial load rises from 0 along a smooth ramp :math:`F(t) = F\,(1 - \cos\pi t/T_r)/2` (a table
  profile of ``ramp_points`` points), which excites the ring's radial mode (~1.3 kHz for the seed bearing)
  only to :math:`\sim(\pi/\omega T_r)^2` of the static displacement, then is held for ``hold`` seconds while
  the contacts' Lankarani–Nikravesh damping and the regularised friction damp what is left;
* the equilibrium is the mean over the last ``window`` seconds: ring displacement, each roller's
  inner-raceway force and orbital angle. It is *settled* when the mean displacements of the two halves of the
  window differ by less than ``drift_tolerance`` of :math:`|u|` (the ``window_drift`` check) and the
  displacement stays within ``amplitude_tolerance`` of its mean (``window_amplitude``), and the run passed its
  own checks: its status (docs/status.md) is then ``success``; a window that has not settled makes it
  ``suspect``. The study's status is its worst run's (:attr:`StaticCheck.status`).

At rest the step residuals are tiny: Exudyn's relative Newton tolerance must not sit at round-off
(``scenarios/static_check.toml`` sets 1e-6; at 1e-8 generalized-α halves its step again and again, 50 times
the cost for the same equilibrium). At rest the rollers do not orbit, so the reference solution has roller 0
at azimuth 0 (as the scene) and no centrifugal force. With gravity, the reference load includes the inner
ring's weight (:func:`bearing_mbs.models.cylindrical_roller.stiffness.quasi_static_load`); ``scenarios/static_check.toml`` turns
gravity off so that the unloaded rollers and the cage rest without rattling.

Linearised stiffness
--------------------
Central differences of static equilibria: :math:`C_{:,i} = (u(F + \Delta F e_i) - u(F - \Delta F e_i))/2\Delta F`,
:math:`K = C^{-1}`, against the analytic tangent matrix of :func:`~bearing_mbs.models.cylindrical_roller.quasistatic.solve_radial` and
against the same differences of the quasi-static solution (which separate the truncation error of the
differences from the dynamic model's error). Palmgren's tangent stiffness :math:`nK\delta^{1/9}` has an
infinite slope at :math:`\delta = 0`, so a roller on the edge of the loaded zone makes finite differences
converge slowly; the check therefore loads the bearing at an angle that puts the zone edges between rollers
(``stiffness_angle``).

Steady running
--------------
:func:`running_comparison` compares a steady run's ``max_roller_load`` (largest inner-raceway force over the
analysis window, reached as a roller passes the load line) with the quasi-static solution with a roller on
the load line, and ``inner_ring_displacement`` (the mean over the window) with the quasi-static
displacement averaged over the rollers' phase; both with the centrifugal force of the drive speed.
"""

from __future__ import annotations

import logging
import math
from dataclasses import dataclass, field, replace
from pathlib import Path

import numpy as np

from bearing_mbs.core.checks import Check, upper_bound
from bearing_mbs.core.result import SUCCESS
from bearing_mbs.core.scene import Profile
from bearing_mbs.core.status import worst_status
from bearing_mbs.core.topology import Group
from bearing_mbs.io.json import write_json
from bearing_mbs.models.cylindrical_roller.spec import AnalysisSpec, DriveSpec, LoadSpec
from bearing_mbs.models.cylindrical_roller.stiffness import quasi_static_load, require_bearing, solve_scenario
from bearing_mbs.models.protocol import StudyServices
from bearing_mbs.spec import Spec, SpecError
from bearing_mbs.spec.fields import in_range, one_of, positive, require

log = logging.getLogger(__name__)

ENGINES = ("exudyn", "reference")
#: The file :func:`write` writes.
RESULT_FILE = "static_check.json"
#: Load-ramp shapes, profiles from 0 to a value over a duration: ``cosine`` starts and ends with zero slope (the
#: default, :meth:`Profile.smooth_ramp`); ``linear``'s slope jumps excite the ring's radial mode ~15 times more (2 %
#: oscillations at 5 kN).
RAMP_SHAPES = {"cosine": Profile.smooth_ramp,
               "linear": lambda value, duration, points: Profile((0.0, duration), (0.0, value))}
#: Load levels of the check [N]: light, medium and the seed bearing's nominal 68 kN.
DEFAULT_LOADS = (5e3, 20e3, 68e3)


@dataclass(frozen=True)
class SettlingSettings:
    """How a dynamic engine settles a resting bearing (see the module docstring).

    ramp [s] > 0, hold [s] > 0, window [s] in (0, hold]; ramp_points >= 2 and ramp_shape (one of
    :data:`RAMP_SHAPES`) make the table profile of the load; output_interval [s] > 0;
    drift_tolerance, amplitude_tolerance [-] > 0.
    """

    ramp: float = 0.010
    hold: float = 0.015
    window: float = 0.005
    ramp_points: int = 101
    ramp_shape: str = "cosine"
    output_interval: float = 1e-4
    drift_tolerance: float = 2e-4
    amplitude_tolerance: float = 2e-3

    def __post_init__(self):
        for name in ("ramp", "hold", "output_interval", "drift_tolerance", "amplitude_tolerance"):
            positive(name, getattr(self, name))
        in_range("window", self.window, 0.0, self.hold, "s", low_open=True)
        require(self.ramp_points >= 2, "ramp_points", self.ramp_points, "must be >= 2")
        one_of("ramp_shape", self.ramp_shape, tuple(RAMP_SHAPES))
        require(self.window >= 4 * self.output_interval, "window", self.window,
                f"must hold at least 4 output instants ({4 * self.output_interval:g} s)")

    @property
    def end_time(self) -> float:
        return self.ramp + self.hold


def settle_spec(spec: Spec, applied, settings: SettlingSettings = SettlingSettings(),
                engine: str | None = None) -> Spec:
    """The scenario at rest under the external load ``applied`` = (F_x, F_y) [N], ramped smoothly from 0."""
    require_bearing(spec)
    fx, fy = (float(v) for v in applied)
    magnitude = math.hypot(fx, fy)
    ramp = RAMP_SHAPES[settings.ramp_shape](magnitude, settings.ramp, settings.ramp_points)
    load = LoadSpec(radial=magnitude, angle=math.degrees(math.atan2(fy, fx)), profile="table", times=ramp.times,
                    values=ramp.values)
    drive = DriveSpec(kind="speed", profile="constant", speed_rpm=0.0, initial_state="rest",
                      servo_time_constant=spec.drive.servo_time_constant)
    end = settings.end_time
    solver = replace(spec.solver, output_interval=settings.output_interval,
                     **({"engine": engine} if engine is not None else {}))
    return replace(spec, scenario=replace(spec.scenario, end_time=end), solver=solver, drive=drive, load=load,
                   analysis=AnalysisSpec(start=end - settings.window, load_fraction=spec.analysis.load_fraction))


@dataclass(frozen=True)
class StaticEquilibrium:
    """A settled dynamic equilibrium: means over the settling window.

    applied: the external load (F_x, F_y) [N]; load: what the rollers carry, applied plus the ring's weight
    [N]; displacement: inner-ring centre (x, y) [m]; roller_angles: orbital angles [rad]; roller_loads:
    inner-raceway forces [N], in roller order; drift, amplitude [-] (relative to |u|); residual_speed: the
    largest inner-ring centre speed in the window [m/s]; settled: the run's status is ``success`` (its own checks
    and the window's passed); status, message and checks: the run's, with ``window_drift`` and
    ``window_amplitude``; steps, wall_time_s: the run's cost.
    """

    engine: str
    method: str
    applied: np.ndarray
    load: np.ndarray
    displacement: np.ndarray
    roller_angles: np.ndarray
    roller_loads: np.ndarray
    drift: float
    amplitude: float
    residual_speed: float
    settled: bool
    status: str
    message: str
    steps: int
    wall_time_s: float
    checks: tuple[Check, ...] = ()

    @property
    def max_roller_load(self) -> float:
        return float(self.roller_loads.max())

    def outcome(self) -> dict:
        """The run's applied load [N], status, message and checks (as dicts)."""
        return {"applied_N": [float(v) for v in self.applied], "status": self.status, "message": self.message,
                "checks": [check.to_dict() for check in self.checks]}


def static_equilibrium(services: StudyServices, spec: Spec, applied, settings: SettlingSettings = SettlingSettings(),
                       engine: str | None = None) -> StaticEquilibrium:
    """Settle the scenario's bearing at rest under ``applied`` = (F_x, F_y) [N] on ``engine`` (default: the
    scenario's) and measure it."""
    from bearing_mbs.models.cylindrical_roller.metrics import pair_columns, roller_orbit_angles

    settled_spec = settle_spec(spec, applied, settings, engine)
    scene, result = services.run_spec(settled_spec)
    mask = result.time >= settled_spec.analysis.start - 1e-12
    ring = result.position[mask][:, :2]
    displacement = ring.mean(axis=0)
    scale = max(float(np.hypot(*displacement)), 1e-12)
    half = len(ring) // 2
    drift = float(np.hypot(*(ring[half:].mean(axis=0) - ring[:half].mean(axis=0)))) / scale
    amplitude = float(np.max(np.hypot(*(ring - displacement).T))) / scale
    angles = np.unwrap(roller_orbit_angles(scene, result)[mask], axis=0).mean(axis=0)
    loads = result.pair_series("normal_force")[mask][:, pair_columns(scene, Group.INNER_RACE)].mean(axis=0)
    speed = float(np.max(np.hypot(*result.velocity[mask][:, :2].T)))
    if result.completed:
        result.checks = (*result.checks, *settling_checks(settings, drift, amplitude))
    settled = result.status == SUCCESS
    if not settled:
        log.warning("%s on %s did not settle: %s, drift %.2e, amplitude %.2e", spec.scenario.name, result.engine,
                    result.message or result.status, drift, amplitude)
    return StaticEquilibrium(
        engine=result.engine, method=result.method, applied=np.asarray(applied, dtype=float),
        load=quasi_static_load(spec, applied), displacement=displacement, roller_angles=np.mod(angles, 2 * np.pi),
        roller_loads=loads, drift=drift, amplitude=amplitude, residual_speed=speed, settled=settled,
        status=result.status, message=result.message, steps=result.stats.steps,
        wall_time_s=result.stats.wall_time_s, checks=result.checks)


def settling_checks(settings: SettlingSettings, drift: float, amplitude: float) -> tuple[Check, Check]:
    """``window_drift`` (the window halves' mean displacements apart, relative to |u|) and ``window_amplitude`` (the
    largest excursion from the mean, relative to |u|) against ``settings``' tolerances."""
    fix = (f"Likely fix: a longer hold (SettlingSettings.hold, {settings.hold:g} s now, e.g. {2 * settings.hold:g} s): "
           "the contacts' damping, proportional to the load, settles a light load slowest")
    return (upper_bound("window_drift", drift, settings.drift_tolerance, "-",
                        f"the ring still moves: its window halves are {drift:.2e} |u| apart. {fix}"),
            upper_bound("window_amplitude", amplitude, settings.amplitude_tolerance, "-",
                        f"the ring still oscillates by {amplitude:.2e} |u| about its mean. {fix}"))


def quasi_static_rest(spec: Spec, applied):
    """The reference of a resting bearing: roller 0 at azimuth 0 as in the scene, no centrifugal force."""
    solution, _ = solve_scenario(spec, applied, speed=0.0, first_roller_angle=0.0)
    return solution


@dataclass(frozen=True)
class StaticComparison:
    """A dynamic static equilibrium against the quasi-static solution of the same load.

    displacement_error: |u_dyn − u_qs| / |u_qs| (the vector difference, so it bounds the magnitude's and the
    direction's errors); max_roller_load_error: (Q_max,dyn − Q_max,qs)/Q_max,qs; roller_load_error: the
    largest |Q_j,dyn − Q_j,qs| over the rollers, divided by Q_max,qs.
    """

    equilibrium: StaticEquilibrium
    solution: object  # RadialSolution

    @property
    def displacement_error(self) -> float:
        reference = self.solution.displacement
        return float(np.linalg.norm(self.equilibrium.displacement - reference) / np.linalg.norm(reference))

    @property
    def max_roller_load_error(self) -> float:
        return (self.equilibrium.max_roller_load - self.solution.max_roller_load) / self.solution.max_roller_load

    @property
    def roller_load_error(self) -> float:
        difference = np.abs(self.equilibrium.roller_loads - self.solution.inner_loads)
        return float(difference.max() / self.solution.max_roller_load)

    def row(self) -> dict:
        eq, qs = self.equilibrium, self.solution
        return {
            "engine": eq.engine, "method": eq.method, "load_N": float(np.hypot(*eq.load)),
            "displacement_dynamic_m": float(np.hypot(*eq.displacement)),
            "displacement_quasi_static_m": float(np.hypot(*qs.displacement)),
            "displacement_error": self.displacement_error,
            "max_roller_load_dynamic_N": eq.max_roller_load, "max_roller_load_quasi_static_N": qs.max_roller_load,
            "max_roller_load_error": self.max_roller_load_error, "roller_load_error": self.roller_load_error,
            "settled": eq.settled, "drift": eq.drift, "amplitude": eq.amplitude,
            "residual_speed_m_s": eq.residual_speed, "steps": eq.steps, "wall_time_s": eq.wall_time_s,
            "status": eq.status, "message": eq.message, "checks": [check.to_dict() for check in eq.checks],
        }


def compare_static(services: StudyServices, spec: Spec, applied, settings: SettlingSettings = SettlingSettings(),
                   engine: str | None = None) -> StaticComparison:
    """Settle ``applied`` on ``engine`` and compare with :func:`quasi_static_rest`."""
    return StaticComparison(static_equilibrium(services, spec, applied, settings, engine),
                            quasi_static_rest(spec, applied))


@dataclass(frozen=True)
class StiffnessCheck:
    """Linearised 2×2 stiffness [N/m] at the external load ``applied`` [N].

    dynamic: central differences of the engine's static equilibria with steps ±``step`` [N] along x and y;
    secant: the same differences of the quasi-static solution; analytic: the tangent matrix of
    :func:`~bearing_mbs.models.cylindrical_roller.quasistatic.solve_radial`. Errors are spectral norms relative to ‖analytic‖.
    """

    engine: str
    applied: np.ndarray
    step: float
    dynamic: np.ndarray
    secant: np.ndarray
    analytic: np.ndarray
    equilibria: tuple[StaticEquilibrium, ...] = field(repr=False)

    @property
    def error(self) -> float:
        return float(np.linalg.norm(self.dynamic - self.analytic, 2) / np.linalg.norm(self.analytic, 2))

    @property
    def secant_error(self) -> float:
        """Truncation of the differences alone: quasi-static secant against the analytic tangent."""
        return float(np.linalg.norm(self.secant - self.analytic, 2) / np.linalg.norm(self.analytic, 2))

    @property
    def settled(self) -> bool:
        return all(eq.settled for eq in self.equilibria)

    @property
    def status(self) -> str:
        """The worst status of its four runs."""
        return worst_status(eq.status for eq in self.equilibria)

    def row(self) -> dict:
        return {"engine": self.engine, "load_N": [float(v) for v in self.applied], "step_N": self.step,
                "dynamic": self.dynamic.tolist(), "secant": self.secant.tolist(), "analytic": self.analytic.tolist(),
                "error": self.error, "secant_error": self.secant_error, "settled": self.settled,
                "status": self.status, "runs": [eq.outcome() for eq in self.equilibria]}


def finite_difference_stiffness(services: StudyServices, spec: Spec, applied, relative_step: float = 0.05,
                                settings: SettlingSettings = SettlingSettings(),
                                engine: str | None = None) -> StiffnessCheck:
    """Central-difference stiffness of the engine's static equilibria around ``applied`` (F_x, F_y) [N];
    steps of ``relative_step`` · |F| along x and y (four runs)."""
    applied = np.asarray(applied, dtype=float)
    in_range("relative_step", relative_step, 0.0, 0.5, "-", low_open=True)
    step = relative_step * float(np.hypot(*applied))
    positive("applied", step)
    equilibria, dynamic, secant = [], np.zeros((2, 2)), np.zeros((2, 2))
    for i, axis in enumerate(np.eye(2)):
        plus = static_equilibrium(services, spec, applied + step * axis, settings, engine)
        minus = static_equilibrium(services, spec, applied - step * axis, settings, engine)
        equilibria += [plus, minus]
        dynamic[:, i] = (plus.displacement - minus.displacement) / (2 * step)
        secant[:, i] = (quasi_static_rest(spec, applied + step * axis).displacement
                        - quasi_static_rest(spec, applied - step * axis).displacement) / (2 * step)
    return StiffnessCheck(engine=equilibria[0].engine, applied=applied, step=step, dynamic=np.linalg.inv(dynamic),
                          secant=np.linalg.inv(secant), analytic=quasi_static_rest(spec, applied).stiffness,
                          equilibria=tuple(equilibria))


def running_comparison(spec: Spec, scene, result, phases: int = 12) -> dict:
    """A steady run's metrics against the quasi-static solution at the drive speed (module docstring).

    Returns the dynamic and quasi-static values and the relative errors ``max_roller_load_error``,
    ``displacement_error`` (magnitudes), and ``cage_speed_error`` = cage_speed_ratio − 1.
    """
    from bearing_mbs.models.cylindrical_roller.metrics import bearing_metrics

    require(phases >= 1, "phases", phases, "must be >= 1")
    metrics = bearing_metrics(spec, scene, result)
    on_line, law = solve_scenario(spec)
    pitch = 2 * math.pi / spec.bearing.rollers
    start = on_line.rollers.first_roller_angle
    averaged = np.mean([solve_scenario(spec, first_roller_angle=start + pitch * k / phases)[0].displacement
                        for k in range(phases)], axis=0)
    displacement = float(np.hypot(*averaged))
    return {
        "engine": result.engine, "raceway_law": law, "load_N": [float(v) for v in on_line.load],
        "centrifugal_force_N": on_line.centrifugal_force,
        "cage_speed_ratio": metrics["cage_speed_ratio"], "cage_speed_error": metrics["cage_speed_ratio"] - 1.0,
        "max_roller_load_dynamic_N": metrics["max_roller_load"],
        "max_roller_load_quasi_static_N": on_line.max_roller_load,
        "max_roller_load_error": metrics["max_roller_load"] / on_line.max_roller_load - 1.0,
        "displacement_dynamic_m": metrics["inner_ring_displacement"],
        "displacement_quasi_static_m": displacement,
        "displacement_quasi_static_on_line_m": float(np.hypot(*on_line.displacement)),
        "displacement_error": metrics["inner_ring_displacement"] / displacement - 1.0,
        "analysis_start_s": metrics["analysis_start"],
    }


@dataclass(frozen=True)
class StaticCheck:
    """Everything :func:`run` measured: one comparison per engine and load level, one stiffness per engine."""

    comparisons: tuple[StaticComparison, ...]
    stiffness: tuple[StiffnessCheck, ...]

    @property
    def statuses(self) -> list[str]:
        """The status of every run."""
        return [c.equilibrium.status for c in self.comparisons] + [eq.status for s in self.stiffness
                                                                   for eq in s.equilibria]

    @property
    def status(self) -> str:
        """The study's status: its worst run's (docs/status.md)."""
        return worst_status(self.statuses)

    def to_dict(self) -> dict:
        return {"status": self.status, "static": [c.row() for c in self.comparisons],
                "stiffness": [s.row() for s in self.stiffness]}


def run(services: StudyServices, scenario: str | Path, loads=DEFAULT_LOADS, engines=ENGINES, *, overrides=(),
        stiffness_load: float | None = 20e3, stiffness_angle: float = -84.0, relative_step: float = 0.05,
        settings: SettlingSettings = SettlingSettings()) -> StaticCheck:
    """The whole cross-check: loads [N] along ``[load] angle`` on each engine, then the finite-difference
    stiffness at ``stiffness_load`` [N] along ``stiffness_angle`` [deg] (None: skip it).

    With the defaults (scenarios/static_check.toml): 2 engines × (3 + 4) settled runs of 25 ms.
    """
    spec = services.load_spec(scenario, list(overrides))
    require_bearing(spec)
    for engine in engines:
        if engine not in ENGINES:
            raise SpecError("engines", engine, f"must be one of {', '.join(ENGINES)}")
    for load in loads:
        positive("loads", load)
    if stiffness_load is not None:
        positive("stiffness_load", stiffness_load)
    angle = math.radians(spec.load.angle)
    direction = np.array([math.cos(angle), math.sin(angle)])
    comparisons = tuple(compare_static(services, spec, load * direction, settings, engine) for engine in engines
                        for load in loads)
    stiffness = ()
    if stiffness_load is not None:
        applied = stiffness_load * np.array([math.cos(math.radians(stiffness_angle)),
                                             math.sin(math.radians(stiffness_angle))])
        stiffness = tuple(finite_difference_stiffness(services, spec, applied, relative_step, settings, engine)
                          for engine in engines)
    return StaticCheck(comparisons, stiffness)


def report(check: StaticCheck) -> str:
    """The check as a plain-text table: displacements [µm] and largest roller loads [N], dynamic against
    quasi-static, then each engine's stiffness matrix [N/m]."""
    lines = [f"{'engine':10} {'F [N]':>8} {'|u| dyn [um]':>13} {'|u| qs [um]':>12} {'err u':>9} "
             f"{'Qmax dyn [N]':>13} {'Qmax qs [N]':>12} {'err Qmax':>9} {'settled':>7} {'status':>11}"]
    for row in (c.row() for c in check.comparisons):
        lines.append(f"{row['engine']:10} {row['load_N']:8.0f} {row['displacement_dynamic_m'] * 1e6:13.4f} "
                     f"{row['displacement_quasi_static_m'] * 1e6:12.4f} {row['displacement_error']:9.2e} "
                     f"{row['max_roller_load_dynamic_N']:13.1f} {row['max_roller_load_quasi_static_N']:12.1f} "
                     f"{row['max_roller_load_error']:9.2e} {row['settled']!s:>7} {row['status']:>11}")
    for item in check.stiffness:
        lines.append(f"{item.engine}: K dynamic [N/m] {np.array2string(item.dynamic, precision=4)}\n"
                     f"  analytic {np.array2string(item.analytic, precision=4)}\n"
                     f"  error {item.error:.2e} (quasi-static secant {item.secant_error:.2e}); runs {item.status}")
    runs = [c.equilibrium for c in check.comparisons] + [eq for s in check.stiffness for eq in s.equilibria]
    lines += [f"check {eq.engine} at {np.hypot(*eq.applied):.0f} N: {item.line()}" for eq in runs
              for item in eq.checks if not item.passed]
    lines.append(f"status: {check.status} (the worst of {len(runs)} runs; docs/status.md)")
    return "\n".join(lines)


def write(check: StaticCheck, directory: str | Path) -> Path:
    """Write ``static_check.json`` (:meth:`StaticCheck.to_dict`) into ``directory``; returns its path."""
    directory = Path(directory)
    directory.mkdir(parents=True, exist_ok=True)
    return write_json(directory / RESULT_FILE, check.to_dict())
