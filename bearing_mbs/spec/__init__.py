"""What a user describes: validated frozen dataclasses, loaded from TOML scenario files.

Every field documents its unit and valid range; construction raises :class:`SpecError` naming the field
(its dotted path when loaded from a file), the value and what is allowed. See ``docs/scenario-format.md``.

This package holds what every model shares: ``[scenario]``, ``[solver]``, ``[convergence]`` and the contact
settings of one group. Each model's spec is a subclass of :class:`Spec` in its package that adds ``contact``
(its groups) and its own sections; :func:`bearing_mbs.models.load_spec` picks the model's class.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from bearing_mbs.spec.contact import ContactSpec
from bearing_mbs.spec.convergence import ConvergenceSpec, RunSettings
from bearing_mbs.spec.fields import SpecError, non_negative, positive, require
from bearing_mbs.spec.loading import apply_override, from_mapping, parse_override, read_scenario, read_toml, to_mapping
from bearing_mbs.spec.solver import ExudynSolver, ReferenceSolver, SolverSpec


@dataclass(frozen=True)
class Scenario:
    """``[scenario]``: name; model (a registered model, see :data:`bearing_mbs.models.MODELS`); end_time [s] > 0;
    gravity [m/s²] >= 0, acting along −y; description: free text."""

    name: str
    model: str
    end_time: float
    gravity: float = 9.81
    description: str = ""

    def __post_init__(self):
        positive("end_time", self.end_time)
        non_negative("gravity", self.gravity)


@dataclass(frozen=True)
class Spec:
    """The sections every scenario file has. A model's spec subclass adds ``contact`` and its own sections."""

    scenario: Scenario
    solver: SolverSpec = field(default_factory=SolverSpec)
    convergence: ConvergenceSpec | None = None

    def __post_init__(self):
        """What ties the shared sections together (a model's subclass calls this first)."""
        end, solver = self.scenario.end_time, self.solver
        require(solver.output_interval <= end, "solver.output_interval", solver.output_interval,
                f"<= scenario.end_time = {end:g} s (else the run has no output instant but the first and last)")
        step = solver.active.step
        require(step <= end, f"solver.{solver.engine}.step", step, f"<= scenario.end_time = {end:g} s")
        if solver.engine == "exudyn":
            require(step <= solver.output_interval, "solver.exudyn.step", step,
                    f"<= solver.output_interval = {solver.output_interval:g} s (Exudyn records output at its steps)")


__all__ = [
    "ContactSpec",
    "ConvergenceSpec",
    "ExudynSolver",
    "ReferenceSolver",
    "RunSettings",
    "Scenario",
    "SolverSpec",
    "Spec",
    "SpecError",
    "apply_override",
    "from_mapping",
    "parse_override",
    "read_scenario",
    "read_toml",
    "to_mapping",
]
