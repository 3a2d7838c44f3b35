"""``[solver]``: which engine runs the scene and how. Both engines' settings live side by side, so a
scenario can be switched with ``--engine`` without editing it."""

from __future__ import annotations

import warnings
from dataclasses import dataclass, field

from bearing_mbs.spec import methods
from bearing_mbs.spec.fields import SpecError, in_range, one_of, positive

#: Reference-engine integrators (``bearing_mbs.engines.reference``), from the catalogue
#: (:mod:`bearing_mbs.spec.methods`).
REFERENCE_METHODS = methods.names(methods.REFERENCE)
#: Of those, the ones that adapt their step to ``tolerance``.
REFERENCE_ADAPTIVE = tuple(m.name for m in methods.ENGINE_METHODS[methods.REFERENCE] if m.adaptive)
#: Of those, the implicit ones (Newton's method on the force elements' Jacobian).
REFERENCE_IMPLICIT = tuple(m.name for m in methods.ENGINE_METHODS[methods.REFERENCE] if m.implicit)

#: Exudyn 1.13.6 ``DynamicSolverType`` members, by our snake-case name: those its ``SolveDynamic`` runs (it has a
#: ``DVERK6`` member too, but raises NotImplementedFeatureError for it, so ``dverk6`` is refused here).
EXUDYN_METHODS = {m.name: m.exudyn for m in methods.ENGINE_METHODS[methods.EXUDYN]}
#: Names a method had before it got the name both engines use: old → new (accepted, with a warning).
RENAMED_METHODS = {old: method.name for old, method in methods.RENAMED.items()}
EXUDYN_IMPLICIT = tuple(m.name for m in methods.ENGINE_METHODS[methods.EXUDYN] if m.implicit)
EXUDYN_ADAPTIVE = tuple(m.name for m in methods.ENGINE_METHODS[methods.EXUDYN] if m.adaptive)
CONNECTORS = ("compiled", "python", "native")
#: How Exudyn's implicit solvers get the force elements' Jacobian: the elements' own (``analytic``) or Exudyn's
#: finite differences of the force user function (``numerical``, 2n evaluations per Jacobian).
JACOBIANS = ("analytic", "numerical")
ENGINES = (methods.REFERENCE, methods.EXUDYN)


@dataclass(frozen=True)
class ReferenceSolver:
    """``[solver.reference]``.

    method: one of :data:`REFERENCE_METHODS`. step [s] > 0: the fixed step, or the first and largest step
    of ``dopri5``. contact_step [s]: ``central_difference`` only, the step used while any pair penetrates
    (the document's variable-step scheme, eq. 58); it must not exceed ``step``. tolerance: relative and
    absolute (SI units) error per step of the adaptive methods, and the Newton tolerance of the implicit ones.
    spectral_radius: generalized-α's ρ∞ in [0, 1].
    """

    method: str = methods.RK4.name
    step: float = 1e-6
    contact_step: float | None = None
    tolerance: float = 1e-8
    spectral_radius: float = 0.9

    def __post_init__(self):
        one_of("method", self.method, REFERENCE_METHODS)
        positive("step", self.step)
        in_range("tolerance", self.tolerance, 0.0, 1.0, "-", low_open=True, high_open=True)
        in_range("spectral_radius", self.spectral_radius, 0.0, 1.0, "-")
        if self.contact_step is not None:
            if self.method != methods.CENTRAL_DIFFERENCE.name:
                raise SpecError("contact_step", self.contact_step, "only the central_difference method uses it")
            in_range("contact_step", self.contact_step, 0.0, self.step, "s", low_open=True)

    @property
    def entry(self) -> methods.Method:
        """The method's entry in the catalogue."""
        return methods.method_named(self.method)

    @property
    def adaptive(self) -> bool:
        return self.entry.adaptive

    @property
    def implicit(self) -> bool:
        return self.entry.implicit


@dataclass(frozen=True)
class ExudynSolver:
    """``[solver.exudyn]``.

    method: one of :data:`EXUDYN_METHODS` (a method both engines have carries one name: ``rk4``; the old
    ``rk44`` is accepted with a warning). step [s] > 0: the fixed step of explicit methods, the largest step
    of the adaptive explicit methods, and the nominal step of implicit methods (which halve it where Newton's
    method fails, e.g. at a stick–slip transition, and recover). tolerance: relative and absolute tolerance of
    adaptive methods and the Newton tolerance of implicit ones. connector: how contact forces reach Exudyn:
    ``compiled`` (the numba kernel in one ObjectGenericODE2), ``python`` (its numpy twin) or ``native``
    (Exudyn's ObjectContactSphereSphere, normal force only). spectral_radius: generalized-alpha ρ∞ in [0, 1].
    jacobian: implicit methods only, one of :data:`JACOBIANS`; ``analytic`` needs every force element of the
    scene to have one (the built-in kinds do) and falls back to ``numerical`` for a kind without one.
    """

    method: str = methods.GENERALIZED_ALPHA.name
    step: float = 1e-5
    tolerance: float = 1e-8
    connector: str = "compiled"
    spectral_radius: float = 0.9
    jacobian: str = "analytic"

    def __post_init__(self):
        if self.method in RENAMED_METHODS:
            renamed = RENAMED_METHODS[self.method]
            warnings.warn(f"solver.exudyn.method = {self.method!r} is now called {renamed!r} (the name both engines "
                          f"use for the same method); the old name will be refused in a later version",
                          FutureWarning, stacklevel=2)
            object.__setattr__(self, "method", renamed)
        one_of("method", self.method, tuple(EXUDYN_METHODS))
        positive("step", self.step)
        in_range("tolerance", self.tolerance, 0.0, 1.0, "-", low_open=True, high_open=True)
        one_of("connector", self.connector, CONNECTORS)
        in_range("spectral_radius", self.spectral_radius, 0.0, 1.0, "-")
        one_of("jacobian", self.jacobian, JACOBIANS)

    @property
    def entry(self) -> methods.Method:
        """The method's entry in the catalogue."""
        return methods.method_named(self.method)

    @property
    def adaptive(self) -> bool:
        return self.entry.adaptive

    @property
    def implicit(self) -> bool:
        return self.entry.implicit


@dataclass(frozen=True)
class SolverSpec:
    """``[solver]``.

    engine: ``reference`` or ``exudyn``. output_interval [s] > 0: spacing of stored output.
    penetration_limit: a run stops when a pair's penetration exceeds this fraction of its smaller radius
    (a guard against steps too large for the stiffness), in (0, 1]. speed_limit [m/s] > 0: a run stops
    when a body's centre moves faster (a blow-up that stays finite). tolerance: optional, the relative error of the
    mean cage speed (docs/numerics.md, the ``cage_speed`` norm) the run is to keep, in (0, 1): the engine's method,
    step and Newton/adaptive tolerance are then chosen from the model's measured work–precision table (the cheapest
    measured setting on ``engine`` within it, with converged slips; :mod:`bearing_mbs.numerics.work_precision`)
    and replace its section's; None (the default) runs the section's settings as written.
    """

    engine: str = "reference"
    output_interval: float = 1e-3
    penetration_limit: float = 0.25
    speed_limit: float = 1e3
    tolerance: float | None = None
    reference: ReferenceSolver = field(default_factory=ReferenceSolver)
    exudyn: ExudynSolver = field(default_factory=ExudynSolver)

    def __post_init__(self):
        one_of("engine", self.engine, ENGINES)
        positive("output_interval", self.output_interval)
        if self.tolerance is not None:
            in_range("tolerance", self.tolerance, 0.0, 1.0, "-", low_open=True, high_open=True)
        in_range("penetration_limit", self.penetration_limit, 0.0, 1.0, "-", low_open=True)
        positive("speed_limit", self.speed_limit)

    @property
    def active(self) -> ReferenceSolver | ExudynSolver:
        """The settings of the selected engine."""
        return self.reference if self.engine == "reference" else self.exudyn
