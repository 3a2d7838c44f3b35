"""The integration methods as objects: the one catalogue of what each method is and which engine runs it.

Every module that needs a fact about a method (its order, whether it adapts its step or is implicit, how the
reference engine controls its step, the member of Exudyn's ``DynamicSolverType`` that runs it) reads it here,
in the manner of scipy's ``solve_ivp`` ``METHODS``; code compares with these objects (``method is DOPRI5``) or their
``name`` rather than spelling a method's name. The names are what a scenario writes in
``[solver.reference]``/``[solver.exudyn]`` ``method``; :mod:`bearing_mbs.spec.solver` validates against them.

A method both engines have (``rk4``, ``dopri5``, ``velocity_verlet``, ``generalized_alpha``) is one object: the same
scheme, each engine with its own code.
"""

from __future__ import annotations

from dataclasses import dataclass

#: The engines' names, as ``[solver] engine`` writes them.
REFERENCE, EXUDYN = "reference", "exudyn"


@dataclass(frozen=True)
class StepControl:
    """How the reference engine's step-size controller (``engines/reference/step_control.py``) changes an adaptive
    method's step from its error norm err (≤ 1 accepts): the next step is h·clip(safety·err^(−1/(p+1)),
    min_factor, max_factor), with p the method's error order; a step whose error is not finite is retried at
    min_factor·h. All three are dimensionless."""

    safety: float
    min_factor: float
    max_factor: float


@dataclass(frozen=True)
class Method:
    """One integration method.

    name: its name in a scenario. order: its convergence order (of the fixed step; the central difference with
    velocity-dependent forces is first order). implicit: it solves for the new state (Newton's method), else it
    is explicit. error_order: the order p of an adaptive method's error estimate (the estimate is O(h^(p+1))),
    None for a fixed-step method. step_control: the reference engine's step-size controller settings of an
    adaptive method it runs. exudyn: the member of Exudyn's ``DynamicSolverType`` of the same scheme (None:
    Exudyn has none). old_names: names it had before, accepted with a warning.
    """

    name: str
    order: int
    implicit: bool = False
    error_order: int | None = None
    step_control: StepControl | None = None
    exudyn: str | None = None
    old_names: tuple[str, ...] = ()

    @property
    def adaptive(self) -> bool:
        """It adapts its step to the tolerance by an error estimate."""
        return self.error_order is not None

    @property
    def explicit(self) -> bool:
        return not self.implicit

    def key(self, engine: str) -> str:
        """This method's :func:`key` in ``engine``."""
        return key(engine, self.name)


def key(engine: str, name: str) -> str:
    """``engine/name``: how the step advisor and the stability regions name a method of an engine."""
    return f"{engine}/{name}"


#: The reference engine's step-size controller of the explicit adaptive Runge–Kutta methods (growth up to 5×).
RUNGE_KUTTA_STEP_CONTROL = StepControl(safety=0.9, min_factor=0.2, max_factor=5.0)
#: Adaptive generalized-α's: it grows its step at most 2× (each new step size re-forms Newton's matrix).
GENERALIZED_ALPHA_STEP_CONTROL = StepControl(safety=0.9, min_factor=0.2, max_factor=2.0)

CENTRAL_DIFFERENCE = Method("central_difference", order=1)
VELOCITY_VERLET = Method("velocity_verlet", order=2, exudyn="VelocityVerlet")
RK4 = Method("rk4", order=4, exudyn="RK44", old_names=("rk44",))
DOPRI5 = Method("dopri5", order=5, error_order=4, step_control=RUNGE_KUTTA_STEP_CONTROL, exudyn="DOPRI5")
GENERALIZED_ALPHA = Method("generalized_alpha", order=2, implicit=True, exudyn="GeneralizedAlpha")
GENERALIZED_ALPHA_ADAPTIVE = Method("generalized_alpha_adaptive", order=2, implicit=True, error_order=2,
                                    step_control=GENERALIZED_ALPHA_STEP_CONTROL)
TRAPEZOIDAL_INDEX2 = Method("trapezoidal_index2", order=2, implicit=True, exudyn="TrapezoidalIndex2")
EXPLICIT_EULER = Method("explicit_euler", order=1, exudyn="ExplicitEuler")
EXPLICIT_MIDPOINT = Method("explicit_midpoint", order=2, exudyn="ExplicitMidpoint")
RK33 = Method("rk33", order=3, exudyn="RK33")
RK67 = Method("rk67", order=6, exudyn="RK67")
ODE23 = Method("ode23", order=3, error_order=2, exudyn="ODE23")
#: Exudyn 1.13.6 has the member, but its ``SolveDynamic`` raises NotImplementedFeatureError for it: no engine runs it
#: (the step advisor lists it, without a formula).
DVERK6 = Method("dverk6", order=6, error_order=5, exudyn="DVERK6")

#: Each engine's methods, in the order its settings list them: which engine runs a method.
ENGINE_METHODS: dict[str, tuple[Method, ...]] = {
    REFERENCE: (CENTRAL_DIFFERENCE, VELOCITY_VERLET, RK4, DOPRI5, GENERALIZED_ALPHA, GENERALIZED_ALPHA_ADAPTIVE),
    EXUDYN: (GENERALIZED_ALPHA, TRAPEZOIDAL_INDEX2, EXPLICIT_EULER, EXPLICIT_MIDPOINT, RK33, RK4, RK67,
             VELOCITY_VERLET, ODE23, DOPRI5),
}
#: Every method, by name.
METHODS: dict[str, Method] = {method.name: method for method in (
    *ENGINE_METHODS[REFERENCE], *ENGINE_METHODS[EXUDYN], DVERK6)}
#: Old name → the method's object (accepted with a warning).
RENAMED: dict[str, Method] = {old: method for method in METHODS.values() for old in method.old_names}


def method_named(name: str) -> Method:
    """The method called ``name`` (KeyError for an unknown one; the spec has validated a scenario's)."""
    return METHODS[name]


def names(engine: str) -> tuple[str, ...]:
    """The names of the methods ``engine`` runs, in its settings' order."""
    return tuple(method.name for method in ENGINE_METHODS[engine])


def runs(engine: str, method: Method) -> bool:
    """``engine`` runs ``method``."""
    return method in ENGINE_METHODS[engine]
