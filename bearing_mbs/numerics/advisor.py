r"""Step advisor: the largest stable step of each explicit integrator, estimated from a scene.

``bearing-mbs advise SCENARIO.toml`` prints it; :func:`bearing_mbs.engines.simulate` warns when a fixed explicit
step exceeds it. See ``docs/numerics.md`` for the derivations and the measured limits they are checked against.

What limits an explicit step (EXUDYN_NOTES.md, measured): the regularised friction of the loaded raceway
contacts, not the Hertz stiffness. The advisor linearises the scene at its expected operating point and takes,
for each integrator, the largest step that keeps every linearised mode inside the integrator's stability region.

Operating point (bearing scenes)
--------------------------------
The applied load :math:`F(t)` on the inner ring (its loads and its weight) is read from the scene. The scene
starts with the ring centred and the rollers on the pitch circle, so the load arrives suddenly and overshoots:

* a load :math:`F_0` present at :math:`t = 0` falls through the radial clearance :math:`h = \max(P_d/2, 0)` onto a
  spring of static deflection :math:`\delta_s`; the linear drop formula gives the dynamic factor
  :math:`D_0 = 1 + \sqrt{1 + 2h/\delta_s}` (2 without clearance);
* a later rise :math:`\Delta F` over a ramp of duration :math:`t_r` overshoots by the classical ramp factor
  :math:`D_r = 1 + |\sin(\omega t_r/2)|/(\omega t_r/2)`, :math:`\omega^2 = \lambda_{max}(K_{bearing})/M_{ring}`;
* rollers that start orbiting are thrown outwards by their centrifugal force
  :math:`F_c = m_r (D_{pw}/2)\,\omega_c^2` through the gap :math:`P_d/4`: the same drop formula.

The roller loads at the peak load come from the quasi-static solver (:func:`bearing_mbs.models.cylindrical_roller.quasistatic.solve_radial`,
centrifugal force included): inner load :math:`Q_i` and outer load :math:`Q_o = Q_i + F_c`. A roller carrying no
ring load is pressed on the outer raceway by :math:`F_c` alone.

Linearised modes
----------------
Per raceway contact of normal load :math:`Q`, exponent :math:`n`, stiffness :math:`K` (:math:`\delta = (Q/K)^{1/n}`):

* friction: a viscous coefficient :math:`c_t = \mu Q \varphi'(0)` [N s/m], :math:`\varphi'(0) v_{reg}` from
  :data:`bearing_mbs.contact.friction.ZERO_SLIP_SLOPE` (erf: :math:`4/\sqrt\pi`); rolling resistance adds
  :math:`c_R = \mu_R Q \varphi'(0) r` [N m s] on the roller's spin;
* normal: the tangent stiffness :math:`k = dQ/d\delta = nQ/\delta` and the hysteresis damping at the
  approach-speed floor, :math:`c_n = d\,Q/v_{floor}` (Lankarani–Nikravesh :math:`d = 3(1-e^2)/4`).

The two raceway contacts of a roller act on its tangential translation :math:`u` and spin :math:`\theta`; with
:math:`a_i = (1, -r)`, :math:`a_o = (1, r)`, the friction damping matrix is
:math:`C = c_i a_i a_i^T + c_o a_o a_o^T + \mathrm{diag}(0, c_{R,i} + c_{R,o})` and the mass matrix
:math:`M = \mathrm{diag}(m_r, I_r)`. Its modes decay at the eigenvalues of :math:`M^{-1}C`; the largest is

.. math:: \lambda_f = \tfrac{T}{2} + \sqrt{\tfrac{T^2}{4} - D},\quad
          T = (c_i + c_o)\left(\tfrac{1}{m_r} + \tfrac{r^2}{I_r}\right) + \tfrac{c_{R,i}+c_{R,o}}{I_r},

with :math:`D = \det M^{-1}C`; a lubricant's viscous drag on the roller adds to the diagonal of :math:`C`. For
equal contacts and a solid roller (:math:`I_r = m_r r^2/2`) this is
:math:`\lambda_f = 4c/m_r`, two thirds of the sum :math:`\sum c(1/m_r + r^2/I_r) = 6c/m_r`. The inner ring's share
of the inner contact's compliance (:math:`1/M + R_i^2/I`, under 1 % here) is left out. The roller's radial
motion is an oscillator :math:`\omega^2 = (k_i + k_o)/m_r`, :math:`2\sigma = (c_{n,i} + c_{n,o})/m_r`; the inner
ring on its rollers another, :math:`\omega^2 = \lambda_{max}(K_{bearing})/M_{ring}`; the velocity servo a decay
:math:`\lambda = g/I_{ring} = 1/\tau`. Pocket, land and roller–roller contacts carry no quasi-static load and are
left out (see the stability suite for where that matters).

Stability regions
-----------------
Every mode is the scalar test equation :math:`\ddot q = \alpha q + \beta\dot q` (:math:`\alpha = -\omega^2`,
:math:`\beta = -2\sigma`; a friction mode has :math:`\alpha = 0`, :math:`\beta = -\lambda_f`).

* Runge–Kutta methods act on :math:`(q, \dot q)`: the step :math:`h` is stable while :math:`|R(hs)| \le 1` for both
  roots :math:`s` of :math:`s^2 - \beta s - \alpha`, with the stability polynomial
  :math:`R(z) = 1 + \sum_{k \ge 1} z^k\, b^T A^{k-1}\mathbb 1` of the tableau. On the negative real axis RK4 reaches
  :math:`hλ = 2.785`, DOPRI5 3.307; on the imaginary axis RK4 reaches :math:`h\omega = 2\sqrt2`
  (:func:`axis_limits` computes them).
* The reference engine's central difference (:math:`v_{n+1} = v_n + h f(q_n, v_n)`, :math:`q_{n+1} = q_n + h
  v_{n+1}`) and velocity Verlet (forces at the predicted velocity :math:`v_n + h a_n`, reused as the next
  step's start) are checked through their amplification matrices. Central difference: :math:`h\omega < 2`,
  :math:`h\lambda < 2`. Velocity Verlet: :math:`h\omega < 2`, but :math:`h\lambda < 1` for a pure decay (its
  amplification matrix has the eigenvalue −1 at :math:`h\lambda = 1`), half the naive Heun estimate.

Implicit methods (generalized-alpha, trapezoidal) have no stability limit on this linear test; their step is a
matter of accuracy (docs/numerics.md, work–precision).
"""

from __future__ import annotations

import functools
import math
from dataclasses import dataclass, field

import numpy as np

from bearing_mbs.contact.friction import ZERO_SLIP_SLOPE
from bearing_mbs.core.scene import Scene

#: Recommended step = SAFETY × the estimated stability limit.
SAFETY = 0.5

# --------------------------------------------------------------------------------------------------------------
# Stability regions
# --------------------------------------------------------------------------------------------------------------

_SQRT5 = math.sqrt(5.0)


def _tableau(rows, weights):
    a = np.zeros((len(weights), len(weights)))
    for i, row in enumerate(rows):
        a[i, : len(row)] = row
    return a, np.array(weights, dtype=float)


#: Explicit Runge–Kutta tableaus (A, b) by "engine/method". The reference engine's come from its own tableaus;
#: Exudyn's as its source defines them (main/src/Solver/CSolverExplicit.cpp, ComputeButcherTableau: Heun's RK33,
#: the classical RK44, Butcher's 7-stage RK67, the third-order solution of Bogacki–Shampine's ODE23, and DOPRI5
#: with the same Dormand–Prince weights as ours).
RK_TABLEAUS: dict[str, tuple[np.ndarray, np.ndarray]] = {
    "exudyn/explicit_euler": _tableau([[]], [1.0]),
    "exudyn/explicit_midpoint": _tableau([[], [0.5]], [0.0, 1.0]),
    "exudyn/rk33": _tableau([[], [1 / 3], [0.0, 2 / 3]], [0.25, 0.0, 0.75]),
    "exudyn/rk44": _tableau([[], [0.5], [0.0, 0.5], [0.0, 0.0, 1.0]], [1 / 6, 1 / 3, 1 / 3, 1 / 6]),
    "exudyn/rk67": _tableau(
        [[], [0.5 - _SQRT5 / 10], [-_SQRT5 / 10, 0.5 + _SQRT5 / 5],
         [7 * _SQRT5 / 20 - 0.75, _SQRT5 / 4 - 0.25, 1.5 - 7 * _SQRT5 / 10],
         [1 / 12 - _SQRT5 / 60, 0.0, 1 / 6, 7 * _SQRT5 / 60 + 0.25],
         [_SQRT5 / 60 + 1 / 12, 0.0, 0.75 - 5 * _SQRT5 / 12, 1 / 6, -0.5 + 3 * _SQRT5 / 10],
         [1 / 6, 0.0, -55 / 12 + 25 * _SQRT5 / 12, -7 * _SQRT5 / 12 - 25 / 12, 5 - 2 * _SQRT5, 2.5 + _SQRT5 / 2]],
        [1 / 12, 0.0, 0.0, 0.0, 5 / 12, 5 / 12, 1 / 12]),
    "exudyn/ode23": _tableau([[], [0.5], [0.0, 0.75], [2 / 9, 1 / 3, 4 / 9]], [2 / 9, 1 / 3, 4 / 9, 0.0]),
}


def _reference_tableaus():
    from bearing_mbs.engines.reference.tableaus import TABLEAUS

    for name, tableau in TABLEAUS.items():
        RK_TABLEAUS[f"reference/{name}"] = (tableau.a, tableau.b)
    RK_TABLEAUS["exudyn/dopri5"] = RK_TABLEAUS["reference/dopri5"]  # the same Dormand–Prince weights


_reference_tableaus()

#: Second-order schemes of the reference engine, checked through their amplification matrices.
SECOND_ORDER = ("reference/central_difference", "reference/velocity_verlet")
#: Methods with no stability limit on the linear test equation.
IMPLICIT = ("exudyn/generalized_alpha", "exudyn/trapezoidal_index2")
#: Methods the advisor has no formula for (Exudyn's velocity Verlet and DVERK6 are not Butcher-tableau solvers
#: we could check).
UNKNOWN = ("exudyn/velocity_verlet", "exudyn/dverk6")


def stability_polynomial(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    r"""Coefficients :math:`c_k` of :math:`R(z) = \sum_k c_k z^k` of an explicit Runge–Kutta tableau."""
    ones = np.ones(b.size)
    coefficients, power = [1.0], ones
    for _ in range(b.size):
        coefficients.append(float(b @ power))
        power = a @ power
    return np.array(coefficients)


@functools.cache
def _polynomial(method: str) -> np.ndarray:
    return stability_polynomial(*RK_TABLEAUS[method])


def _first_exit(low: float, high: float, inside, points: int = 800) -> float:
    """Largest x in [low, high] before ``inside(x)`` (vectorised) first turns False on a geometric grid, refined
    on finer grids (relative precision ~1e-9); inf if it never does, 0 if it already fails at ``low``."""
    grid = np.geomspace(low, high, points)
    for _ in range(5):
        outside = np.flatnonzero(~inside(grid))
        if outside.size == 0:
            return math.inf if grid[-1] >= high else float(grid[-1])
        k = int(outside[0])
        if k == 0:
            return 0.0 if grid[0] <= low else float(grid[0])
        grid = np.linspace(grid[k - 1], grid[k], 100)
    return float(grid[0])


_TOLERANCE = 1e-9


def rk_ray_limit(method: str, angle: float) -> float:
    """Largest r with |R(ρ e^{iθ})| <= 1 for all ρ <= r (θ = ``angle``, π is the negative real axis)."""
    coefficients = _polynomial(method)[::-1]
    direction = complex(math.cos(angle), math.sin(angle))

    def inside(radius):
        return np.abs(np.polyval(coefficients, radius * direction)) <= 1.0 + _TOLERANCE

    return _first_exit(1e-3, 20.0, inside)


def amplification_matrix(method: str, h, alpha: float, beta: float) -> np.ndarray:
    r"""One step of a reference second-order scheme on :math:`\ddot q = \alpha q + \beta\dot q`, as a matrix
    (a stack of matrices for an array of steps ``h``)."""
    h = np.asarray(h, dtype=float)
    one = np.ones_like(h)
    if method == "reference/central_difference":  # state (q, v)
        rows = [[1 + h * h * alpha, h + h * h * beta], [h * alpha, 1 + h * beta]]
    elif method == "reference/velocity_verlet":  # state (q, v, a): a is the stored acceleration
        a1 = [alpha * one, alpha * h + beta, alpha * h * h / 2 + beta * h]
        rows = [[one, h, h * h / 2], [h * a1[0] / 2, 1 + h * a1[1] / 2, h / 2 + h * a1[2] / 2], a1]
    else:
        raise ValueError(f"{method!r} is not a second-order scheme of the reference engine")
    return np.moveaxis(np.array([[np.broadcast_to(x, h.shape) for x in row] for row in rows]), (0, 1), (-2, -1))


@functools.lru_cache(maxsize=4096)
def mode_limit(method: str, alpha: float, beta: float) -> float:
    r"""Largest stable step [s] of ``method`` on :math:`\ddot q = \alpha q + \beta\dot q` (inf: no limit)."""
    roots = np.roots([1.0, -beta, -alpha])
    scale = float(np.max(np.abs(roots)))
    if scale == 0.0:
        return math.inf
    if method in RK_TABLEAUS:
        return min(rk_ray_limit(method, math.atan2(s.imag, s.real)) / abs(s) for s in roots
                   if abs(s) > 1e-12 * scale)
    if method in SECOND_ORDER:
        def inside(x):
            radius = np.abs(np.linalg.eigvals(amplification_matrix(method, x / scale, alpha, beta))).max(axis=-1)
            return radius <= 1.0 + _TOLERANCE

        return _first_exit(1e-3, 20.0, inside, points=400) / scale
    raise ValueError(f"no stability formula for {method!r}")


# --------------------------------------------------------------------------------------------------------------
# Modes and advice
# --------------------------------------------------------------------------------------------------------------


@dataclass(frozen=True)
class Mode:
    r"""A linearised mode :math:`\ddot q = \alpha q + \beta\dot q`: ``alpha`` [1/s²] (−ω²), ``beta`` [1/s] (−2σ, or
    −λ for a pure decay); ``where`` names the pair or body it belongs to; ``load`` [N] the contact load used."""

    name: str
    where: str
    alpha: float
    beta: float
    load: float = 0.0

    @property
    def rate(self) -> float:
        """Largest |eigenvalue| [1/s]."""
        return float(np.max(np.abs(np.roots([1.0, -self.beta, -self.alpha]))))


ADVISED_METHODS = (
    "reference/central_difference", "reference/velocity_verlet", "reference/rk4", "reference/dopri5",
    "exudyn/rk44", "exudyn/rk33", "exudyn/rk67", "exudyn/ode23", "exudyn/dopri5", "exudyn/explicit_midpoint",
    "exudyn/explicit_euler", "exudyn/velocity_verlet", "exudyn/dverk6", "exudyn/generalized_alpha",
    "exudyn/trapezoidal_index2",
)


@dataclass(frozen=True)
class Advice:
    """The advisor's answer for one scene.

    ``applies``: False for scenes the advisor has no model of (``reason`` says why). ``operating_point``: the
    loads [N] and speeds [rad/s] used. ``modes``: the linearised modes. Limits are computed on demand.
    """

    applies: bool
    reason: str = ""
    operating_point: dict = field(default_factory=dict)
    modes: tuple[Mode, ...] = ()

    def limit(self, engine: str, method: str) -> float | None:
        """Estimated largest stable step [s]: inf for implicit methods, None when there is no formula or no
        advice for this scene."""
        return self.limit_and_mode(engine, method)[0]

    def limit_and_mode(self, engine: str, method: str) -> tuple[float | None, str]:
        """(limit [s], the mode that sets it)."""
        key = f"{engine}/{method}"
        if not self.applies or key in UNKNOWN or (key not in RK_TABLEAUS and key not in SECOND_ORDER
                                                  and key not in IMPLICIT):
            return None, ""
        if key in IMPLICIT:
            return math.inf, ""
        best, which = math.inf, ""
        for mode in self.modes:
            value = mode_limit(key, mode.alpha, mode.beta)
            if value < best:
                best, which = value, f"{mode.name} ({mode.where})"
        return float(best), which

    def recommended(self, engine: str, method: str) -> float | None:
        """:data:`SAFETY` × the limit, rounded down to two significant digits [s]; None without a finite limit."""
        limit = self.limit(engine, method)
        if limit is None or not math.isfinite(limit) or limit <= 0:
            return None
        return round_down(SAFETY * limit)

    def limits(self) -> dict:
        """"engine/method" → (limit, recommended, controlling mode) for every advised method."""
        table = {}
        for key in ADVISED_METHODS:
            limit, mode = self.limit_and_mode(*key.split("/"))
            table[key] = (limit, self.recommended(*key.split("/")), mode)
        return table

    def to_dict(self) -> dict:
        def number(value):
            return value if value is None or math.isfinite(value) else "none"

        return {
            "applies": self.applies, "reason": self.reason, "operating_point": self.operating_point,
            "modes": [{"name": m.name, "where": m.where, "alpha": m.alpha, "beta": m.beta, "load": m.load,
                       "rate": m.rate} for m in self.modes],
            "limits": {key: {"limit": number(limit), "recommended": recommended, "set_by": mode}
                       for key, (limit, recommended, mode) in self.limits().items()} if self.applies else {},
        }

    def report(self) -> str:
        """Plain-text advice, for the command line."""
        if not self.applies:
            return f"no advice: {self.reason}"
        op = self.operating_point
        lines = [
            f"operating point: applied load {op['static_load']:.4g} N, peak {op['peak_load']:.4g} N "
            f"(dynamic factor {op['load_factor']:.3g}); shaft {op['shaft_speed']:.4g} rad/s; "
            f"centrifugal force {op['centrifugal_force']:.4g} N (peak {op['peak_centrifugal_force']:.4g} N)",
            f"largest roller load: {op['max_roller_load']:.4g} N static, {op['peak_roller_load']:.4g} N at the peak",
            "",
            "modes (linearised at the peak loads):",
        ]
        for mode in sorted(self.modes, key=lambda m: -m.rate):
            kind = ("decay" if mode.alpha == 0 else
                    f"omega = {math.sqrt(-mode.alpha):.3g} rad/s, 2 sigma = {abs(mode.beta):.3g} 1/s")
            lines.append(f"  {mode.name:<32} {mode.where:<11} |s| = {mode.rate:9.3g} 1/s  ({kind})")
        lines += ["", f"{'engine/method':<30} {'limit [s]':>10} {'advised [s]':>12}  set by"]
        for key, (limit, recommended, mode) in self.limits().items():
            if limit is None:
                lines.append(f"{key:<30} {'-':>10} {'-':>12}  no stability formula for this solver")
            elif not math.isfinite(limit):
                lines.append(f"{key:<30} {'none':>10} {'-':>12}  implicit: choose the step for accuracy "
                             "(bearing-mbs convergence)")
            elif recommended is None:
                lines.append(f"{key:<30} {limit:10.3g} {'-':>12}  {mode}: unstable at any step")
            else:
                lines.append(f"{key:<30} {limit:10.3g} {recommended:12.2g}  {mode}")
        return "\n".join(lines)


def round_down(value: float) -> float:
    """``value`` rounded down to two significant digits."""
    exponent = math.floor(math.log10(value)) - 1
    return math.floor(value / 10**exponent * (1 + 1e-12)) * 10**exponent


def axis_limits(method: str) -> dict:
    """hλ on the negative real axis (a pure decay) and hω on the imaginary axis (an undamped oscillation)."""
    return {"real": mode_limit(method, 0.0, -1.0), "imaginary": mode_limit(method, -1.0, 0.0)}


def advise(scene: Scene) -> Advice:
    """The advice for ``scene`` (cached: scenes are immutable)."""
    try:
        return _advise_cached(scene)
    except TypeError:  # an unhashable scene (never built by our builders)
        return _advise(scene)


@functools.lru_cache(maxsize=32)
def _advise_cached(scene: Scene) -> Advice:
    return _advise(scene)


def _advise(scene: Scene) -> Advice:
    layout = BearingLayout.of(scene)
    if layout is None:
        return Advice(False, "the advisor models bearing scenes (an inner ring with raceway pairs) only")
    operating_point, roller_cases, ring_mode = layout.operating_point()
    modes = []
    for label, inner_load, outer_load in roller_cases:
        modes += layout.roller_modes(label, inner_load, outer_load)
    if ring_mode is not None:
        modes.append(ring_mode)
    if layout.servo_gain > 0:
        modes.append(Mode("velocity servo", layout.ring_name, 0.0, -layout.servo_gain / layout.ring_inertia))
    return Advice(True, "", operating_point, tuple(modes))


def step_warning(scene: Scene, solver) -> str | None:
    """A warning when ``solver``'s fixed explicit step exceeds the advised limit for ``scene``, else None."""
    settings = solver.active
    if getattr(settings, "adaptive", False) or getattr(settings, "implicit", False):
        return None
    if solver.engine == "exudyn" and settings.connector == "native":
        return None  # Exudyn's sphere contacts lag their friction state one step: another stability problem
    step = settings.step
    if solver.engine == "reference" and settings.method == "central_difference" and settings.contact_step:
        step = settings.contact_step  # the step while contacts are closed, i.e. always in a bearing
    advice = advise(scene)
    limit, mode = advice.limit_and_mode(solver.engine, settings.method)
    if limit is None or not step > limit:
        return None
    recommended = advice.recommended(solver.engine, settings.method)
    fix = f"use a step <= {recommended:.2g} s" if recommended else "use another solver"
    return (f"{scene.name}: the {solver.engine} {settings.method} step {step:.3g} s exceeds the advised stability "
            f"limit {limit:.3g} s, set by {mode}: above it a run may stay bounded but slip wrongly (a spurious "
            f"skidding cycle). Likely fix: {fix}, or generalized-alpha (see `bearing-mbs advise`).")


# --------------------------------------------------------------------------------------------------------------
# The bearing's operating point
# --------------------------------------------------------------------------------------------------------------


@dataclass(frozen=True)
class BearingLayout:
    """What the advisor reads from a bearing scene: geometry, masses, raceway laws, loads and speeds."""

    scene: Scene
    ring: int
    ring_name: str
    ring_mass: float
    ring_inertia: float
    rollers: tuple[int, ...]
    roller_mass: float
    roller_inertia: float
    roller_radius: float
    inner_radius: float
    outer_radius: float
    inner_law: object
    outer_law: object
    servo_gain: float
    shaft_speed: float
    initial_orbit_speed: float
    roller_drag: tuple[float, float] = (0.0, 0.0)  # viscous drag on a roller: linear [N s/m], angular [N m s]

    @classmethod
    def of(cls, scene: Scene) -> BearingLayout | None:
        inner = [p for p in scene.pairs if p.name.endswith("-inner_race")]
        outer = [p for p in scene.pairs if p.name.endswith("-outer_race")]
        if not inner or len(inner) != len(outer) or inner[0].kind != "circle_circle":
            return None
        ring = inner[0].body_a
        if ring < 0 or any(p.body_a != ring for p in inner):
            return None
        rollers = tuple(p.body_b for p in inner)
        roller = scene.bodies[rollers[0]]
        ring_body = scene.bodies[ring]
        servo_gain = sum(d.gain for d in scene.drives if d.body == ring)
        speeds = [abs(ring_body.velocity[2])] + [abs(v) for d in scene.drives if d.body == ring for v in d.speed.values]
        x, y = roller.position[:2]
        orbit = (x * roller.velocity[1] - y * roller.velocity[0]) / max(x * x + y * y, 1e-300)
        drags = [d for d in getattr(scene, "drags", ()) if d.body == rollers[0]]
        drag = (sum(d.linear for d in drags), sum(d.angular for d in drags))
        return cls(scene, ring, ring_body.name, ring_body.mass, ring_body.inertia, rollers, roller.mass,
                   roller.inertia, inner[0].radius_b, inner[0].radius_a, outer[0].radius_a, inner[0].law,
                   outer[0].law, servo_gain, max(speeds), abs(orbit), drag)

    # geometry ------------------------------------------------------------------------------------------------
    @property
    def pitch_diameter(self) -> float:
        return self.inner_radius + self.outer_radius

    @property
    def clearance(self) -> float:
        """Diametral clearance P_d [m] (negative: preload)."""
        return 2 * (self.outer_radius - self.inner_radius) - 4 * self.roller_radius

    def roller_set(self):
        from bearing_mbs.models.cylindrical_roller.quasistatic import RollerSet

        return RollerSet(rollers=len(self.rollers), pitch_diameter=self.pitch_diameter,
                         roller_diameter=2 * self.roller_radius, roller_length=1.0,
                         diametral_clearance=self.clearance, roller_mass=self.roller_mass,
                         inner_stiffness=self.inner_law.stiffness, inner_exponent=self.inner_law.exponent,
                         outer_stiffness=self.outer_law.stiffness, outer_exponent=self.outer_law.exponent)

    def centrifugal_force(self, orbit_speed: float) -> float:
        return self.roller_mass * self.pitch_diameter / 2 * orbit_speed**2

    # loads ---------------------------------------------------------------------------------------------------
    def applied_load(self) -> tuple[np.ndarray, np.ndarray]:
        """Instants [s] (all load breakpoints) and the load (Fx, Fy) [N] on the ring there, weight included."""
        loads = [item for item in self.scene.loads if item.body == self.ring]
        times = np.unique(np.concatenate([[0.0]] + [np.asarray(item.profile.times, float) for item in loads]))
        force = np.tile(self.ring_mass * np.asarray(self.scene.gravity, float), (times.size, 1))
        for item in loads:
            force += np.outer(item.profile(times), item.vector[:2])
        return times, force

    def _solve(self, rollers, load, speed):
        """The quasi-static solution at ``load`` (memoised: a constant load is solved once)."""
        from bearing_mbs.models.cylindrical_roller.quasistatic import solve_radial

        key = (round(float(load[0]), 9), round(float(load[1]), 9))
        memo = self.__dict__.setdefault("_solutions", {})
        if key not in memo:
            memo[key] = solve_radial(rollers, key, shaft_speed=speed)
        return memo[key]

    def operating_point(self):
        """(operating_point dict, roller load cases [(label, Q_i, Q_o)], ring mode or None)."""
        rollers = self.roller_set()
        speed = self.shaft_speed
        cage_speed = speed * (1 - 2 * self.roller_radius / self.pitch_diameter) / 2
        centrifugal = self.centrifugal_force(cage_speed)
        times, force = self.applied_load()
        magnitude = np.hypot(force[:, 0], force[:, 1])
        biggest = int(np.argmax(magnitude))
        static = float(magnitude[biggest])
        direction = force[biggest] / static if static > 0 else np.array([0.0, -1.0])
        drop = max(self.clearance / 2, 0.0)

        solution = None
        if static > 0 or self.clearance < 0:
            solution = self._solve(rollers, force[biggest], speed)
        ring_frequency = 0.0
        if solution is not None:
            ring_frequency = math.sqrt(max(np.linalg.eigvalsh(solution.stiffness).max(), 0.0) / self.ring_mass)

        # the load present at t = 0 falls on the rollers; later rises overshoot like a ramp on an oscillator
        peak, factor0 = magnitude[0], 1.0
        if magnitude[0] > 0:
            first = self._solve(rollers, force[0], speed)
            elastic = max(float(np.hypot(*first.displacement)) - drop, 1e-12)
            factor0 = 1 + math.sqrt(1 + 2 * drop / elastic)
            peak = factor0 * magnitude[0]
        for k in range(1, times.size):
            rise, duration = magnitude[k] - magnitude[k - 1], times[k] - times[k - 1]
            if rise > 0:
                phase = 0.5 * ring_frequency * duration
                factor = 2.0 if phase == 0 else 1 + abs(math.sin(phase)) / phase
                peak = max(peak, magnitude[k - 1] + factor * rise)
        peak = max(peak, static)

        cases = []
        at_peak = None
        if peak > 0 or self.clearance < 0:
            at_peak = self._solve(rollers, peak * direction, speed)
            j = int(np.argmax(at_peak.inner_loads))
            cases.append(("loaded roller", float(at_peak.inner_loads[j]), float(at_peak.outer_loads[j])))
        # rollers that start orbiting are thrown onto the outer raceway
        thrown = self.centrifugal_force(self.initial_orbit_speed)
        peak_centrifugal = centrifugal
        if thrown > 0:
            approach = (thrown / self.outer_law.stiffness) ** (1 / self.outer_law.exponent)
            gap = max(self.clearance / 4, 0.0)
            peak_centrifugal = max(centrifugal, thrown * (1 + math.sqrt(1 + 2 * gap / approach)))
        if peak_centrifugal > 0:
            cases.append(("unloaded roller", 0.0, peak_centrifugal))

        ring_mode = None
        if at_peak is not None:
            stiffness = max(np.linalg.eigvalsh(at_peak.stiffness).max(), 0.0)
            ring_mode = Mode("inner ring on the rollers", self.ring_name, -stiffness / self.ring_mass, 0.0, peak)
        # the first load peak: the ring falls through the clearance, then half a period on its rollers
        drop_time = math.sqrt(2 * drop * self.ring_mass / static) if static > 0 else 0.0
        stiffest = max(np.linalg.eigvalsh(at_peak.stiffness).max(), 0.0) if at_peak is not None else 0.0
        peak_time = drop_time + (math.pi * math.sqrt(self.ring_mass / stiffest) if stiffest > 0 else 0.0)
        point = {
            "first_peak_time": peak_time,
            "static_load": static, "peak_load": float(peak), "load_factor": float(peak / static) if static else 1.0,
            "shaft_speed": speed, "centrifugal_force": centrifugal, "peak_centrifugal_force": peak_centrifugal,
            "max_roller_load": float(solution.max_roller_load) if solution is not None else 0.0,
            "peak_roller_load": cases[0][1] if at_peak is not None else 0.0,
        }
        return point, cases, ring_mode

    # modes ---------------------------------------------------------------------------------------------------
    def roller_modes(self, label: str, inner_load: float, outer_load: float) -> list[Mode]:
        """Friction (tangential and spin) and radial modes of one roller with raceway loads Q_i, Q_o [N]."""
        m, inertia, r = self.roller_mass, self.roller_inertia, self.roller_radius
        where = self.scene.bodies[self.rollers[0]].name.rstrip("0123456789") + "s"

        def friction(law, load):
            slope = ZERO_SLIP_SLOPE[law.friction_law] / law.regularisation_speed
            return law.friction_coefficient * load * slope, law.rolling_resistance_arm * load * slope * r

        ci, ri = friction(self.inner_law, inner_load)
        co, ro = friction(self.outer_law, outer_load)
        drag_linear, drag_angular = self.roller_drag
        damping = (ci * np.outer([1, -r], [1, -r]) + co * np.outer([1, r], [1, r])
                   + np.diag([drag_linear, ri + ro + drag_angular]))
        rates = np.linalg.eigvals(np.diag([1 / m, 1 / inertia]) @ damping).real
        modes = [Mode(f"friction, {label}", where, 0.0, -float(rate), max(inner_load, outer_load))
                 for rate in sorted(rates, reverse=True) if rate > 0][:1]

        def normal(law, load):
            if load <= 0:
                return 0.0, 0.0
            approach = (load / law.stiffness) ** (1 / law.exponent)
            return law.exponent * load / approach, law.damping_factor * load / law.approach_speed_floor

        ki, dni = normal(self.inner_law, inner_load)
        ko, dno = normal(self.outer_law, outer_load)
        if ki + ko > 0:
            modes.append(Mode(f"radial contact, {label}", where, -(ki + ko) / m, -(dni + dno) / m,
                              max(inner_load, outer_load)))
        return modes
