r"""Step advisor: the largest stable step of each explicit integrator, estimated from a scene.

``bearing-mbs advise SCENARIO.toml`` prints it; :func:`step_warning` says when a fixed explicit step exceeds it.
See ``docs/numerics.md`` for the derivations and the measured limits they are checked against.

The advisor asks the registered models to linearise the scene (a model's ``linearise(scene)``: its operating point
and linearised modes :math:`\ddot q = \alpha q + \beta\dot q`, or None for a scene it does not model; the bearing's
is :mod:`bearing_mbs.models.cylindrical_roller.linearise`). For each integrator it takes the largest step that keeps
every mode inside the integrator's stability region (:mod:`bearing_mbs.numerics.stability_regions`) and recommends
:data:`SAFETY` times it.
"""

from __future__ import annotations

import functools
import math
from dataclasses import dataclass, field

from bearing_mbs.core.scene import Scene
from bearing_mbs.models.registry import MODELS
from bearing_mbs.numerics.advice_report import advice_report
from bearing_mbs.numerics.stability_regions import IMPLICIT, RK_TABLEAUS, SECOND_ORDER, UNKNOWN, mode_limit
from bearing_mbs.spec import methods
from bearing_mbs.spec.methods import EXUDYN, REFERENCE

#: Recommended step = SAFETY × the estimated stability limit [-].
SAFETY = 0.5

#: The "engine/method" keys the advice lists.
ADVISED_METHODS = (
    *(method.key(REFERENCE) for method in (methods.CENTRAL_DIFFERENCE, methods.VELOCITY_VERLET, methods.RK4,
                                           methods.DOPRI5)),
    *(method.key(EXUDYN) for method in (methods.RK4, methods.RK33, methods.RK67, methods.ODE23, methods.DOPRI5,
                                        methods.EXPLICIT_MIDPOINT, methods.EXPLICIT_EULER, methods.VELOCITY_VERLET,
                                        methods.DVERK6, methods.GENERALIZED_ALPHA, methods.TRAPEZOIDAL_INDEX2)),
)


@dataclass(frozen=True)
class Advice:
    """The advisor's answer for one scene.

    ``applies``: False for scenes no model linearises (``reason`` says why). ``operating_point``: the loads [N]
    and speeds [rad/s] used. ``modes``: the linearised modes (``name``, ``where``, ``alpha`` [1/s²], ``beta``
    [1/s], ``load`` [N], ``rate`` [1/s]). Limits are computed on demand.
    """

    applies: bool
    reason: str = ""
    operating_point: dict = field(default_factory=dict)
    modes: tuple = ()

    def limit(self, engine: str, method: str) -> float | None:
        """Estimated largest stable step [s]: inf for implicit methods, None when there is no formula or no
        advice for this scene."""
        return self.limit_and_mode(engine, method)[0]

    def limit_and_mode(self, engine: str, method: str) -> tuple[float | None, str]:
        """(limit [s], the mode that sets it)."""
        key = methods.key(engine, method)
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
        """"engine/method" → (limit [s], recommended [s], controlling mode) for every advised method."""
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
        return advice_report(self.applies, self.reason, self.operating_point, self.modes, self.limits())


def round_down(value: float) -> float:
    """``value`` rounded down to two significant digits."""
    exponent = math.floor(math.log10(value)) - 1
    return math.floor(value / 10**exponent * (1 + 1e-12)) * 10**exponent


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
    for model in MODELS.values():
        linearisation = model.linearise(scene) if model.linearise is not None else None
        if linearisation is not None:
            return Advice(True, "", linearisation.operating_point, tuple(linearisation.modes))
    return Advice(False, f"no model linearises this scene (models with a linearisation: "
                         f"{', '.join(m.name for m in MODELS.values() if m.linearise is not None) or 'none'})")


@dataclass(frozen=True)
class StepAgainstLimit:
    """A fixed explicit step [s] (the contact step for central difference) against the advised stability
    ``limit`` [s] set by ``mode``, with the ``recommended`` step [s] (None without a finite one)."""

    step: float
    limit: float
    recommended: float | None
    mode: str

    @property
    def exceeded(self) -> bool:
        return self.step > self.limit


def step_against_limit(scene: Scene, solver) -> StepAgainstLimit | None:
    """The run's fixed explicit step against the advised limit, or None where no limit applies (adaptive or
    implicit methods, Exudyn's native contacts, a scene no model linearises)."""
    settings = solver.active
    if getattr(settings, "adaptive", False) or getattr(settings, "implicit", False):
        return None
    if solver.engine == "exudyn" and settings.connector == "native":
        return None  # Exudyn's sphere contacts lag their friction state one step: another stability problem
    advice = advise(scene)
    limit, mode = advice.limit_and_mode(solver.engine, settings.method)
    if limit is None:
        return None
    return StepAgainstLimit(_fixed_step(solver), limit, advice.recommended(solver.engine, settings.method), mode)


def _fixed_step(solver) -> float:
    """The step [s] a fixed-step run takes while its contacts are closed: central difference's contact step if it
    has one (always closed in a bearing), else its step."""
    settings = solver.active
    if solver.engine == REFERENCE and settings.method == methods.CENTRAL_DIFFERENCE.name and settings.contact_step:
        return settings.contact_step
    return settings.step


#: A step within the advice is divided by this when a run still needs a finer one (an energy audit that does not
#: close, a penetration, a divergence below the stability limit) [-].
REFINEMENT = 4.0
#: An adaptive method's tolerance is divided by this instead [-].
TOLERANCE_REFINEMENT = 100.0


@dataclass(frozen=True)
class StepAdvice:
    """The one step advice of a run: every message that advises a step or a tolerance quotes it (the
    divergence and penetration messages, the ``step_limit``, ``energy_audit`` and ``spurious_slip`` checks, the
    step warning), so they never disagree.

    Set ``field`` (a spec path) from ``current`` to ``value`` (at most; [s] for a step, [-] for a tolerance).
    ``limit`` [s] is the step advisor's stability limit for the run's method and scene (None where none applies:
    adaptive and implicit methods, a scene no model linearises), set by ``mode``; ``value`` never exceeds it, so
    following the advice passes the ``step_limit`` check. ``explicit``: the method has a stability limit at all,
    so switching to the implicit solver is an alternative. ``reason``: why there is no limit, when there is none.
    """

    field: str
    current: float
    value: float
    limit: float | None = None
    mode: str = ""
    explicit: bool = True
    reason: str = ""

    @property
    def tolerance(self) -> bool:
        return self.field.endswith(".tolerance")

    def text(self) -> str:
        """The advice in words: the value to set, the advisor's limit it respects, and the alternative."""
        if self.tolerance:
            return f"tighten {self.field} from {self.current:g} to {self.value:g}"
        if self.limit is not None:
            words = (f"set {self.field} to {self.value:.2g} s or less (now {self.current:g} s; the step advisor's "
                     f"stability limit for this method and scene is {self.limit:.3g} s, set by {self.mode})")
        else:
            words = f"reduce {self.field} from {self.current:g} s to {self.value:g} s ({self.reason})"
        return words + (", or switch to Exudyn's generalized_alpha (implicit: no stability limit)"
                        if self.explicit else "")

    def to_dict(self) -> dict:
        return {"field": self.field, "current": self.current, "value": self.value, "limit": self.limit,
                "set_by": self.mode}

    @property
    def units(self) -> str:
        """The units of :meth:`to_dict`'s numbers, as a summary's ``units`` map writes a record's fields."""
        setting = "-" if self.tolerance else "s"
        return f"current: {setting}, value: {setting}, limit: s"


def step_advice(scene: Scene, solver) -> StepAdvice:
    """The step advice for running ``scene`` with ``solver`` (:class:`StepAdvice`): within the advisor's
    stability limit, the recommended step when the run's step exceeds it, else :data:`REFINEMENT` times finer;
    an adaptive method's tolerance :data:`TOLERANCE_REFINEMENT` times tighter."""
    settings = solver.active
    prefix = f"solver.{solver.engine}"
    if settings.adaptive:
        return StepAdvice(f"{prefix}.tolerance", settings.tolerance, settings.tolerance / TOLERANCE_REFINEMENT,
                          explicit=not settings.implicit)
    step = _fixed_step(solver)
    name = "contact_step" if step != settings.step else "step"
    if settings.implicit:
        return StepAdvice(f"{prefix}.{name}", step, step / REFINEMENT, explicit=False,
                          reason=f"{settings.method} has no stability limit; a shorter step resolves the dynamics "
                                 "better")
    against = step_against_limit(scene, solver)
    if against is None or against.recommended is None:
        why = advise(scene).reason or "the step advisor has no stability limit for this method"
        return StepAdvice(f"{prefix}.{name}", step, step / REFINEMENT, reason=why)
    value = against.recommended if step > against.recommended else step / REFINEMENT
    return StepAdvice(f"{prefix}.{name}", step, value, against.limit, against.mode)


def step_warning(scene: Scene, solver) -> str | None:
    """A warning when ``solver``'s fixed explicit step exceeds the advised limit for ``scene``, else None."""
    check = step_against_limit(scene, solver)
    if check is None or not check.exceeded:
        return None
    return (f"{scene.name}: the {solver.engine} {solver.active.method} step {check.step:.3g} s exceeds the advised "
            f"stability limit {check.limit:.3g} s, set by {check.mode}: above it a run may stay bounded but slip "
            f"wrongly (a spurious skidding cycle). Likely fix: {step_advice(scene, solver).text()} "
            f"(see `bearing-mbs advise`).")
