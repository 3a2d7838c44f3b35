"""``[convergence]``: settings of a work–precision study (``bearing-mbs convergence``)."""

from __future__ import annotations

from dataclasses import dataclass

from bearing_mbs.spec import methods
from bearing_mbs.spec.fields import SpecError, in_range, one_of, positive, require
from bearing_mbs.spec.solver import CONNECTORS, ENGINES

#: Error norms (docs/numerics.md): positions for every model; the bearing's skidding quantities.
NORMS = ("positions", "cage_speed", "roller_loads", "slips")


@dataclass(frozen=True)
class RunSettings:
    """One engine and method, with a ladder of fixed ``steps`` [s] or adaptive ``tolerances``.

    For the reference solution and its check a single ``step`` or ``tolerance`` is used (the first of each
    list). Adaptive methods take ``step`` as their largest step (default: the output interval).
    """

    engine: str
    method: str
    steps: tuple[float, ...] = ()
    tolerances: tuple[float, ...] = ()
    step: float | None = None
    connector: str = "compiled"

    def __post_init__(self):
        one_of("engine", self.engine, ENGINES)
        one_of("method", self.method, methods.names(self.engine))
        one_of("connector", self.connector, CONNECTORS)
        for name in ("steps", "tolerances"):
            for i, value in enumerate(getattr(self, name)):
                positive(f"{name}.{i}", value)
        if self.step is not None:
            positive("step", self.step)
        require(bool(self.steps) != bool(self.tolerances), "steps", list(self.steps),
                "give either steps (fixed-step methods) or tolerances (adaptive methods)")

    @property
    def adaptive(self) -> bool:
        return bool(self.tolerances)


@dataclass(frozen=True)
class ConvergenceSpec:
    """``[convergence]``.

    reference: the run taken as exact, much finer than any studied setting and of high order; check: a
    second, different method at a fine setting: its distance to the reference is reported and must be well
    below the smallest target. runs: the settings studied. norm: the error reported in the ``error`` column
    (all norms are written). start, end [s]: the window over which errors are taken (default: the spec's
    analysis window for the bearing, the whole run otherwise). targets: relative errors for which the
    cheapest setting is reported.
    """

    reference: RunSettings
    runs: tuple[RunSettings, ...]
    check: RunSettings | None = None
    norm: str = "positions"
    start: float | None = None
    end: float | None = None
    targets: tuple[float, ...] = (1e-2, 1e-3, 1e-4)

    def __post_init__(self):
        one_of("norm", self.norm, NORMS)
        require(len(self.runs) > 0, "runs", [], "needs at least one [[convergence.runs]] entry")
        for i, target in enumerate(self.targets):
            in_range(f"targets.{i}", target, 0.0, 1.0, "-", low_open=True, high_open=True)
        if self.start is not None and self.end is not None and not self.end > self.start:
            raise SpecError("end", self.end, "must be after start")
