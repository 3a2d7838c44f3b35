"""What a model provides, and the registry that holds the models.

A model turns a validated spec into a scene and its topology (``build``), and turns a result back into what
engineers read (``metrics``, ``figures``). Optional parts (a linearisation for the step advisor, an animation, the
model's own studies and commands) are fields of its :class:`Model` record: the layers above ask the record, never
the model's package, so nothing outside ``models/`` imports a model's package (an import-linter contract).

A model's studies and commands run scenarios, which is the business of the layers above the models (the runner,
the study layer, the command line). A model is handed those services (:class:`StudyServices`,
:class:`CommandLine`) rather than importing them, so that the layers stay one-way.
"""

from __future__ import annotations

from argparse import ArgumentParser, Namespace
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from bearing_mbs.core.registry import Registry
from bearing_mbs.core.result import Result
from bearing_mbs.core.scene import Scene
from bearing_mbs.spec import SpecError


@dataclass(frozen=True)
class StudyServices:
    """What the layers above the models lend a model's studies (built once, in
    :mod:`bearing_mbs.studies.services`):

    * ``load_spec(path, overrides) -> Spec`` — a scenario file with its ``--set`` overrides, validated;
    * ``with_overrides(spec, {dotted path: value}) -> Spec`` — a validated variation of a spec;
    * ``build_scene(spec) -> Scene`` — the scene its model builds;
    * ``run_spec(spec, progress=None) -> (Scene, Result)`` — one run with its checks;
    * ``summarize(spec, scene, result) -> dict`` — the run's summary.json content.
    """

    load_spec: Callable
    with_overrides: Callable
    build_scene: Callable
    run_spec: Callable
    summarize: Callable


@dataclass(frozen=True)
class CommandLine:
    """What the command line lends a model's commands: the options every subcommand shares and its exit codes
    (built once, in :mod:`bearing_mbs.cli.models`).

    * ``services`` — :class:`StudyServices`;
    * ``add_output(parser, what, resumes=False)``, ``add_overrides(parser, what=...)`` — the ``--out DIR``
      (and ``--overwrite``) and ``--set SECTION.KEY=VALUE`` options;
    * ``output_directory(args) -> Path`` — ``--out`` checked and created before anything runs;
    * ``names(text)``, ``numbers(option, text)`` — comma-separated lists;
    * ``exit_code(statuses) -> int`` — the exit code of the worst status (docs/status.md);
    * ``progress(quiet) -> ProgressMeter`` — a progress bar, or none with ``--quiet``;
    * ``print_outcome(summary, describe, out)`` — a static solution's line, status and failed checks.
    """

    services: StudyServices
    add_output: Callable
    add_overrides: Callable
    output_directory: Callable
    names: Callable
    numbers: Callable
    exit_code: Callable
    progress: Callable
    print_outcome: Callable


@dataclass(frozen=True)
class Command:
    """A subcommand a model offers ``bearing-mbs`` (``bearing-mbs NAME SCENARIO.toml --out DIR ...``).

    * ``name``, ``help`` — the subcommand and its one-line help;
    * ``arguments(parser, cli)`` — adds its arguments to its argparse parser (``cli`` is :class:`CommandLine`);
    * ``run(args, cli) -> int`` — does it and returns the exit code (docs/status.md); bad input raises
      :class:`bearing_mbs.spec.SpecError`.
    """

    name: str
    help: str
    arguments: Callable[[ArgumentParser, CommandLine], None]
    run: Callable[[Namespace, CommandLine], int]


@dataclass(frozen=True)
class ErrorNorms:
    """How a work–precision study (:mod:`bearing_mbs.studies.convergence`) measures a run against its reference
    for one model.

    * ``names`` — the norms the model offers (``[convergence] norm``); ``positions`` is every model's;
    * ``window_start(spec) -> float`` — where the study's window starts [s] when ``[convergence] start`` is not
      given;
    * ``errors(spec, scene, run, reference, mask) -> {norm: value}`` — the model's norms of ``run`` (resampled onto
      the reference's instants) against ``reference`` over the window ``mask`` (boolean, per instant); a
      ``positions`` entry replaces the study's own (the first body's centre over its largest excursion);
    * ``scales(spec, scene, reference, mask) -> dict`` — entries of the study's summary that size the norms (the
      largest slip of the reference, say).
    """

    names: tuple[str, ...] = ("positions",)
    window_start: Callable[[Any], float] = field(default=lambda spec: 0.0)
    errors: Callable[..., dict] = field(default=lambda spec, scene, run, reference, mask: {})
    scales: Callable[..., dict] = field(default=lambda spec, scene, reference, mask: {})


@dataclass(frozen=True)
class StabilityCase:
    """A variation of a base scenario for the stability suite (:mod:`bearing_mbs.studies.stability`):
    ``change(data, spec)`` edits a copy of the base's mapping in place (``spec``: the validated base)."""

    name: str
    description: str
    change: Callable[[dict, Any], None] = field(default=lambda data, spec: None)


@dataclass(frozen=True)
class StabilitySuite:
    """A model's stability suite: its ``cases`` (the first is the base itself) and the names of the reduced
    suite's (``reduced``, the default tests' and ``--reduced``)."""

    cases: tuple[StabilityCase, ...]
    reduced: tuple[str, ...]

    @property
    def names(self) -> tuple[str, ...]:
        return tuple(case.name for case in self.cases)


@dataclass(frozen=True)
class SteadyBalance:
    """A model's quasi-static steady state, which a sensitivity study may evaluate instead of a run
    (``[study] evaluate = "skidding_balance"``, :mod:`bearing_mbs.studies.sensitivity.models`).

    * ``check(services, spec)`` — raises :class:`bearing_mbs.spec.SpecError` unless the base scenario suits it;
    * ``evaluate(services, spec) -> dict`` — the balance's row: numbers (units in ``units``), a ``status``
      (``success``, or ``failed`` where it has no solution) and a ``message``;
    * ``outputs`` — the row's numeric entries; ``units`` — the unit of each.
    """

    check: Callable[[StudyServices, Any], None]
    evaluate: Callable[[StudyServices, Any], dict]
    outputs: tuple[str, ...]
    units: dict


@dataclass(frozen=True)
class WorkPrecisionData:
    """A model's measured work–precision tables, from which ``[solver] tolerance`` chooses a setting
    (:mod:`bearing_mbs.numerics.work_precision` reads and chooses).

    * ``path`` — the JSON file of its tables, one per variant of the model, each with the settings measured on each
      engine, their cage-speed error and cost, and the provenance of the measurement; written by a measurement
      (``benchmarks/bench_revolution.py``), never by hand;
    * ``variant(spec) -> str | None`` — the table that describes a spec's scene, None where none does;
    * ``variants`` — each table's variant in words (what the refusal of a scene without one lists).
    """

    path: Path
    variant: Callable[[Any], str | None]
    variants: dict[str, str]


@dataclass(frozen=True)
class Model:
    """One model.

    * ``name`` — the ``[scenario] model`` value that selects it;
    * ``spec`` — its spec class: a frozen dataclass subclass of :class:`bearing_mbs.spec.Spec` that adds
      ``contact`` (one :class:`~bearing_mbs.spec.ContactSpec` per contact group, with defaults) and the model's
      sections; it validates itself on construction;
    * ``build(spec) -> Scene`` — the scene, with its topology, and only what the case needs;
    * ``metrics(spec, scene, result) -> dict`` — summary entries (JSON-safe numbers, lists and text);
    * ``figures(spec, scene, result, directory) -> list[Path]`` — PNG files;
    * ``prepare(data) -> data`` — fills model-specific defaults into the raw mapping before validation
      (a preset, say); optional;
    * ``linearise(scene)`` — operating point and modes for the step advisor, ``None`` for a scene it does not
      model; optional;
    * ``units`` — the unit of each entry ``metrics`` returns (``"N"``, ``"m/s"``, ``"-"``, ``"deg"``…), written to
      summary.json's ``units`` map;
    * ``warnings(spec, scene, result) -> list[str]`` — what makes the run's numbers meaningless (the runner's
      ``guard_warnings`` check; cheap: it runs for every run); none by default;
    * ``animate(spec, scene, result, path) -> Path`` — an animated GIF of a run (``bearing-mbs run --animate``);
      optional;
    * ``commands`` — the subcommands the model offers the command line (:class:`Command`: its studies, its
      static solutions); none by default;
    * ``error_norms`` — how a work–precision study measures its runs (:class:`ErrorNorms`; by default the
      positions norm from the start);
    * ``stability`` — its stability suite (:class:`StabilitySuite`); optional;
    * ``settling_check(spec, scene, result) -> Check`` — whether a run's analysis window has settled (a
      sensitivity study's ``steady_run`` evaluator adds it to every run's checks); optional;
    * ``steady_balance`` — its quasi-static steady state (:class:`SteadyBalance`); optional;
    * ``work_precision`` — its measured work–precision tables (:class:`WorkPrecisionData`), which
      ``[solver] tolerance`` needs; optional.
    """

    name: str
    spec: type
    build: Callable[[Any], Scene]
    metrics: Callable[[Any, Scene, Result], dict]
    figures: Callable[[Any, Scene, Result, Path], list]
    prepare: Callable[[dict], dict] = field(default=lambda data: data)
    linearise: Callable[[Scene], Any] | None = None
    units: dict = field(default_factory=dict)
    warnings: Callable[[Any, Scene, Result], list] = field(default=lambda spec, scene, result: [])
    animate: Callable[[Any, Scene, Result, Path], Path] | None = None
    commands: tuple[Command, ...] = ()
    error_norms: ErrorNorms = field(default_factory=ErrorNorms)
    stability: StabilitySuite | None = None
    settling_check: Callable[[Any, Scene, Result], Any] | None = None
    steady_balance: SteadyBalance | None = None
    work_precision: WorkPrecisionData | None = None


class ModelRegistry(Registry[Model]):
    """Models by name. :meth:`register` adds one from outside the package (a plug-in, or a test)."""

    def part(self, name: str, part: str, description: str, field: str = "scenario.model") -> Any:
        """Model ``name``'s optional ``part`` (a field of :class:`Model` that may be None: ``animate``,
        ``stability``, ``settling_check``, ``steady_balance``...). A model without it is refused before anything
        runs: :class:`~bearing_mbs.spec.SpecError` naming ``field``, the model, and the models with ``description``
        (what the caller needs, "a stability suite")."""
        found = getattr(self[name], part)
        if found is None:
            having = [model.name for model in self.values() if getattr(model, part) is not None]
            raise SpecError(field, name, f"a model with {description}: {', '.join(having)}")
        return found
