r"""Ask for an error, get the fastest setting: ``[solver] tolerance`` chooses the method and step from measurements.

A model may own a work–precision table per variant (:class:`bearing_mbs.models.protocol.WorkPrecisionData`: a JSON
file in its package, written by a measurement, ``benchmarks/bench_revolution.py``, never by hand). Each table lists,
for each engine, the settings measured (the engine's whole ``[solver.<engine>]`` section: method, step,
Newton/adaptive tolerance, ...) with

* ``cage_speed_error``: the relative error of the mean cage speed against a fine reference (docs/numerics.md, the
  ``cage_speed`` norm) [-];
* ``slips_converged``: the slip ratios at loaded contacts within the benchmark's bound of the reference;
* ``cost``: wall-clock seconds per simulated second [s/s] on the measuring machine;

and the provenance of the measurement (date, machine, commit, the command that wrote it).

:func:`choose` takes, on the run's engine, the cheapest setting whose measured error is within the asked tolerance,
whose slips converged and whose run succeeded. Its step is capped by every bound of the run (:data:`Bounds`):
the step advisor's recommended stable step for an explicit fixed-step method on this scene (the measurement was
stable on the measured scene, not necessarily on this one), and the largest step the run's spec allows (Exudyn
records output at its steps: ≤ ``output_interval``; any step ≤ the end time). A capped step is shorter than the
measured one, so the error of a convergent method stays within the measured one, and the expected cost is the
measured cost × measured step / capped step (for an adaptive method, whose ``step`` is its largest, an upper
bound). An adaptive explicit method is not capped by the advisor (its error control keeps it stable, as
:func:`bearing_mbs.numerics.advisor.step_against_limit` says).

:func:`choose_solver` applies the choice to a spec: the chosen setting replaces the engine's section (``tolerance``
takes precedence over the section's method and step, so a scenario file that sets both engines' sections, as every
file of the repository does, can be asked for an error with ``--set solver.tolerance=1e-3``; the summary reports
the section it replaced).
"""

from __future__ import annotations

import dataclasses
import functools
import json
import math
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

from bearing_mbs.core.result import SUCCESS
from bearing_mbs.core.scene import Scene
from bearing_mbs.io.json import json_safe
from bearing_mbs.models.registry import MODELS
from bearing_mbs.numerics.advisor import advise
from bearing_mbs.spec import SpecError, from_mapping, methods, to_mapping
from bearing_mbs.spec.solver import ExudynSolver, ReferenceSolver, SolverSpec

#: The spec field this module serves.
FIELD = "solver.tolerance"
#: The version of the tables' file layout.
FORMAT = 1
#: Each engine's section class.
SECTIONS = {methods.REFERENCE: ReferenceSolver, methods.EXUDYN: ExudynSolver}
#: The settings' key that the advisor's stability limit applies to when present (central difference's step while
#: contacts are closed, always in a bearing), else ``step``.
CONTACT_STEP = "contact_step"


@dataclass(frozen=True)
class MeasuredSetting:
    """One measured setting of one engine: its ``[solver.<engine>]`` section as run (``settings``), its
    ``cage_speed_error`` [-] (NaN where the run failed; null in the file), whether its ``slips_converged``, its run's
    ``status`` and its ``cost`` [s of wall time per s simulated]. ``name``: the measurement's name for it."""

    name: str
    engine: str
    settings: dict
    cage_speed_error: float
    slips_converged: bool
    status: str
    cost: float

    @property
    def method(self) -> methods.Method:
        return methods.method_named(self.settings["method"])

    @property
    def sound(self) -> bool:
        """The run succeeded, its slips converged and its error is a number."""
        return self.status == SUCCESS and self.slips_converged and math.isfinite(self.cage_speed_error)

    @property
    def limited_step(self) -> str:
        """The settings' key of the step a stability limit applies to."""
        return CONTACT_STEP if self.settings.get(CONTACT_STEP) else "step"

    def to_dict(self) -> dict:
        return dataclasses.asdict(self)


@dataclass(frozen=True)
class WorkPrecisionTable:
    """The measured settings of one variant of a model. ``measured_on``: the scenario, variant, simulated span and
    error window of the measurement; ``provenance``: date, machine, commit and the command that wrote it."""

    variant: str
    measured_on: dict
    provenance: dict
    settings: tuple[MeasuredSetting, ...]

    def to_dict(self) -> dict:
        return {"variant": self.variant, "measured_on": self.measured_on, "provenance": self.provenance,
                "settings": [setting.to_dict() for setting in self.settings]}

    @classmethod
    def from_dict(cls, data: dict) -> WorkPrecisionTable:
        settings = ({**setting, "cage_speed_error": math.nan if setting["cage_speed_error"] is None
                     else setting["cage_speed_error"]} for setting in data["settings"])
        return cls(data["variant"], data["measured_on"], data["provenance"],
                   tuple(MeasuredSetting(**setting) for setting in settings))


def write_tables(path: str | Path, tables: list[WorkPrecisionTable], description: str) -> Path:
    """Write ``tables`` to ``path`` (JSON; what :func:`read_tables` reads)."""
    path = Path(path)
    document = {"format": FORMAT, "description": description,
                "tables": {table.variant: table.to_dict() for table in tables}}
    path.write_text(json.dumps(json_safe(document), indent=2, allow_nan=False) + "\n")
    read_tables.cache_clear()
    return path


@functools.lru_cache(maxsize=8)
def read_tables(path: Path) -> dict[str, WorkPrecisionTable]:
    """The tables of the file at ``path``, by variant."""
    document = json.loads(Path(path).read_text())
    if document.get("format") != FORMAT:
        raise ValueError(f"{path}: work-precision tables of format {document.get('format')!r}, not {FORMAT}")
    return {variant: WorkPrecisionTable.from_dict(table) for variant, table in document["tables"].items()}


@dataclass(frozen=True)
class Bounds:
    """What caps a chosen setting's step on this run: ``recommended(method) -> float | None``, the step advisor's
    recommended stable step [s] of an explicit method on this scene (None: no advice), and ``largest_step`` [s],
    the largest the run's spec allows."""

    recommended: Callable[[methods.Method], float | None]
    largest_step: float = math.inf


#: What caps a step, in words (a choice's ``caps``).
LARGEST_STEP = "the largest step the run allows"
ADVISED_STEP = "the step advisor's recommended stable step for this scene"


@dataclass(frozen=True)
class Choice:
    """A measured ``setting`` with the ``settings`` the run takes (its steps capped, :func:`choose`): ``caps``, one
    ``{"field": key, "step": [s], "set_by": why}`` per step that was capped, and the ``expected_cost`` [s/s]."""

    setting: MeasuredSetting
    settings: dict
    expected_cost: float
    caps: tuple[dict, ...] = ()


def choose(table: WorkPrecisionTable, engine: str, tolerance: float, bounds: Bounds) -> Choice:
    """The cheapest sound setting of ``engine`` in ``table`` whose measured cage-speed error is ≤ ``tolerance``,
    its step capped by ``bounds`` (module docstring). SpecError naming :data:`FIELD` where none is."""
    sound = [setting for setting in table.settings if setting.engine == engine and setting.sound]
    if not sound:
        raise SpecError(FIELD, tolerance, f"a model variant with a measured sound setting on the {engine} engine; "
                                          f"the {table.variant} table has none (choose the other engine)")
    choices = [choice for choice in (capped(setting, bounds) for setting in sound
                                     if setting.cage_speed_error <= tolerance) if choice is not None]
    if not choices:
        smallest = min(sound, key=lambda setting: setting.cage_speed_error)
        raise SpecError(FIELD, tolerance, f">= {smallest.cage_speed_error:.3g}, the smallest cage-speed error measured "
                                          f"on the {engine} engine for the {table.variant} variant ({smallest.name}), "
                                          f"or a setting of [solver.{engine}] written out (and its error measured by "
                                          f"`bearing-mbs convergence`)")
    return min(choices, key=lambda choice: (choice.expected_cost, choice.setting.cage_speed_error))


def capped(setting: MeasuredSetting, bounds: Bounds) -> Choice | None:
    """``setting`` with its steps capped by ``bounds`` and its cost scaled by the ratio of the step its stability
    limit applies to (module docstring); None for an explicit fixed-step method without the advisor's advice."""
    method, limited = setting.method, setting.limited_step
    caps = [("step", bounds.largest_step, LARGEST_STEP)]
    if method.explicit and not method.adaptive:
        recommended = bounds.recommended(method)
        if recommended is None:
            return None  # stable on the measured scene, but nothing says it is on this one
        caps.append((limited, recommended, ADVISED_STEP))
    settings, applied = dict(setting.settings), []
    for key, bound, why in caps:
        if settings[key] > bound:
            settings[key] = bound
            applied.append({"field": key, "step": bound, "set_by": why})
    if settings.get(CONTACT_STEP):
        settings[CONTACT_STEP] = min(settings[CONTACT_STEP], settings["step"])
    cost = setting.cost * setting.settings[limited] / settings[limited]
    return Choice(setting, settings, cost, tuple(applied))


@dataclass(frozen=True)
class SolverChoice:
    """What ``[solver] tolerance`` chose for a run: the asked ``tolerance``, the :class:`Choice`, the table it came
    from (``variant``, ``measured_on``, ``provenance``, ``source``: the table's file) and the engine section it
    ``replaced``."""

    tolerance: float
    engine: str
    choice: Choice
    variant: str
    measured_on: dict
    provenance: dict
    source: str
    replaced: dict

    def to_dict(self) -> dict:
        """The summary's ``solver_choice`` entry."""
        choice, setting = self.choice, self.choice.setting
        return {
            "tolerance": self.tolerance, "engine": self.engine, "settings": choice.settings,
            "expected_cage_speed_error": setting.cage_speed_error,
            "expected_cost_s_per_s": choice.expected_cost,
            "measured": {"name": setting.name, "settings": setting.settings, "cost_s_per_s": setting.cost},
            "step_caps": list(choice.caps),
            "variant": self.variant, "measured_on": self.measured_on, "provenance": self.provenance,
            "source": self.source, "replaced": self.replaced,
        }

    #: The units of :meth:`to_dict`'s numbers, as a summary's ``units`` map writes a record's fields.
    units = ("tolerance, expected_cage_speed_error: -; expected_cost_s_per_s, cost_s_per_s: s of wall time per s "
             "simulated; settings' step, contact_step and step_caps' step: s")

    def text(self) -> str:
        """One line for the command line."""
        settings = self.choice.settings
        step = f", contact step {settings[CONTACT_STEP]:g} s" if settings.get(CONTACT_STEP) else ""
        return (f"solver.tolerance = {self.tolerance:g}: {self.engine} {settings['method']} at step "
                f"{settings['step']:g} s{step}, tolerance {settings['tolerance']:g} (measured cage-speed error "
                f"{self.choice.setting.cage_speed_error:.2g}, expected cost {self.choice.expected_cost:.3g} s per "
                f"simulated s; {self.variant} table, measured {self.provenance.get('date', '?')})")


def choose_solver(spec, scene: Scene) -> tuple[SolverSpec, SolverChoice | None]:
    """The solver settings a run of ``spec`` takes: its own where ``[solver] tolerance`` is not set; else those
    chosen from its model's work–precision table (:func:`choose`), with the choice. SpecError naming
    :data:`FIELD` for a model without tables, a scene none of its tables describes, and a tolerance no measured
    setting meets: before anything runs."""
    solver = spec.solver
    if solver.tolerance is None:
        return solver, None
    data = MODELS.part(spec.scenario.model, "work_precision", "work-precision data (measured settings to choose "
                       "from)", FIELD)
    variant = data.variant(spec)
    tables = read_tables(Path(data.path))
    if variant is None or variant not in tables:
        described = "; ".join(f"{name}: {words}" for name, words in data.variants.items() if name in tables)
        raise SpecError(FIELD, solver.tolerance, f"a scene of a model variant with a measured work-precision table "
                                                 f"({described}); or the engine's method and step written out")
    table, engine = tables[variant], solver.engine
    largest = min(spec.scenario.end_time, solver.output_interval if engine == methods.EXUDYN else math.inf)
    advice = advise(scene)
    bounds = Bounds(lambda method: advice.recommended(engine, method.name), largest)
    choice = choose(table, engine, solver.tolerance, bounds)
    section = from_mapping(SECTIONS[engine], choice.settings, f"solver.{engine}")
    chosen = dataclasses.replace(solver, **{engine: section})
    return chosen, SolverChoice(solver.tolerance, engine, choice, variant, table.measured_on, table.provenance,
                                _package_path(Path(data.path)), to_mapping(solver.active))


def _package_path(path: Path) -> str:
    """``path`` relative to the package's parent (``bearing_mbs/models/...``), else as it is."""
    root = Path(__file__).resolve().parents[2]
    try:
        return path.resolve().relative_to(root).as_posix()
    except ValueError:
        return str(path)
