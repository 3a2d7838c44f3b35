"""The study: which inputs vary and how (SALib's problem: names, bounds, distributions), the sampling
and analysis method, the outputs read from each run's summary, and a seed.

A study is validated on construction, before anything runs: every parameter must be a real input of the
model (checked by applying its bounds, or its grid values, to the base input through the model's own
validation), bounds must be finite with low < high, and the analysis must match the sampling.
Errors are :class:`~bearing_mbs.spec.SpecError` naming the study-file field (``parameters.1.bounds``).
See ``docs/sensitivity.md`` for the file format.
"""

from __future__ import annotations

import math
import tomllib
from dataclasses import dataclass, field
from pathlib import Path

from bearing_mbs.spec import SpecError
from bearing_mbs.spec.fields import in_range, one_of, require
from bearing_mbs.spec.loading import apply_override, from_mapping, parse_override
from bearing_mbs.studies.sensitivity.models import BUILTIN_MODELS, EVALUATORS, RunModel, SimulationModel

#: Sampling designs: full-factorial grid, Latin hypercube, Morris trajectories, Sobol'–Saltelli.
SAMPLERS = ("grid", "latin", "morris", "sobol")
#: Analyses each sampling supports (SALib ``analyze`` modules; ``none``: table and scatter plots only).
#: The first is the default.
ANALYZERS = {
    "grid": ("none",),
    "latin": ("rbd_fast", "none"),
    "morris": ("morris",),
    "sobol": ("sobol",),
}
#: SALib distributions whose support is [low, high], so the bounds can be checked against the model.
DISTRIBUTIONS = ("unif", "logunif", "triang", "truncnorm")
#: Samplers that draw random numbers and so need ``[study] seed``.
RANDOM_SAMPLERS = ("latin", "morris", "sobol")


@dataclass(frozen=True)
class Parameter:
    """``[[parameters]]``: one input that varies, named by its dotted path in the model's input.

    name: the path, e.g. ``contact.wall.restitution`` or ``balls.0.position.1`` (list items by index);
    for the Ishigami model ``x1``, ``x2``, ``x3``. bounds: (low, high) in the field's SI unit, finite,
    low < high: the support of the distribution (latin, morris, sobol; or grid with ``[method] levels``).
    distribution: SALib name: ``unif`` (default), ``logunif`` (log-uniform, needs low > 0), ``triang``
    (needs ``peak``: the mode as a fraction of the width, in [0, 1)), ``truncnorm`` (normal truncated to
    the bounds, needs ``mean`` and ``std`` > 0 in the field's unit). values: grid only, the explicit
    values to run (instead of bounds).
    """

    name: str
    bounds: tuple[float, float] | None = None
    distribution: str = "unif"
    values: tuple[int | float, ...] | None = None
    peak: float | None = None
    mean: float | None = None
    std: float | None = None

    def __post_init__(self):
        keys = self.name.split(".")
        require(bool(self.name) and all(k.strip() == k and k for k in keys), "name", self.name,
                "must be a dotted path like section.key")
        one_of("distribution", self.distribution, DISTRIBUTIONS)
        if self.values is not None:
            require(self.bounds is None, "values", list(self.values), "give values or bounds, not both")
            require(len(self.values) > 0, "values", [], "must not be empty")
            for i, value in enumerate(self.values):
                require(not isinstance(value, bool) and isinstance(value, (int, float)) and math.isfinite(value),
                        f"values.{i}", value, "must be a finite number")
            require(len(set(self.values)) == len(self.values), "values", list(self.values), "must not repeat")
        if self.bounds is not None:
            bounds = list(self.bounds)
            require(len(bounds) == 2, "bounds", bounds, "must be [low, high]")
            for i, value in enumerate(bounds):
                require(not isinstance(value, bool) and isinstance(value, (int, float)) and math.isfinite(value),
                        f"bounds.{i}", value, "must be a finite number")
            low, high = bounds
            require(low < high, "bounds", bounds, "must have low < high")
            if self.distribution == "logunif":
                require(low > 0, "bounds", bounds, "must be > 0 for the logunif distribution")
        self._check_shape_parameters()

    def _check_shape_parameters(self):
        needs = {"triang": ("peak",), "truncnorm": ("mean", "std")}.get(self.distribution, ())
        for name in ("peak", "mean", "std"):
            value = getattr(self, name)
            if name not in needs:
                require(value is None, name, value, f"is not used by the {self.distribution} distribution")
                continue
            require(value is not None, name, value, f"the {self.distribution} distribution needs it")
        if self.distribution == "triang":
            in_range("peak", self.peak, 0.0, 1.0, "-", high_open=True)
        if self.distribution == "truncnorm":
            in_range("mean", self.mean, -math.inf, math.inf, "-")
            in_range("std", self.std, 0.0, math.inf, "-", low_open=True)
        if needs:
            require(self.bounds is not None, "bounds", None, f"the {self.distribution} distribution needs bounds")

    @property
    def salib_bounds(self) -> list[float]:
        """The bounds as SALib's ``problem['bounds']`` entry for this distribution."""
        low, high = self.bounds
        if self.distribution == "triang":
            return [low, high, self.peak]
        if self.distribution == "truncnorm":
            return [low, high, self.mean, self.std]
        return [low, high]


@dataclass(frozen=True)
class Method:
    """``[method]``: sampling and analysis.

    sampler: ``grid``, ``latin``, ``morris`` or ``sobol``. analyzer: the SALib analysis, one that matches
    the sampler (:data:`ANALYZERS`, default the first). samples: N, the number of Latin-hypercube
    points, Morris trajectories (runs: N (D + 1)) or Sobol base samples (a power of 2; runs: N (D + 2),
    or N (2D + 2) with second_order). levels: Morris grid levels p (even, default 4), or grid points per
    bounded parameter. second_order: Sobol S2 indices (default false). conf_level: of the bootstrap
    confidence intervals, in (0, 1). resamples: bootstrap resamples for the intervals.
    """

    sampler: str
    analyzer: str | None = None
    samples: int | None = None
    levels: int | None = None
    second_order: bool | None = None
    conf_level: float = 0.95
    resamples: int = 1000

    def __post_init__(self):
        one_of("sampler", self.sampler, SAMPLERS)
        allowed = ANALYZERS[self.sampler]
        if self.analyzer is None:
            object.__setattr__(self, "analyzer", allowed[0])
        require(self.analyzer in allowed, "analyzer", self.analyzer,
                f"does not match the {self.sampler} sampling; with sampler = {self.sampler!r} use "
                + " or ".join(repr(a) for a in allowed))
        if self.sampler == "grid":
            require(self.samples is None, "samples", self.samples,
                    "the grid sampler runs every combination; give values or levels instead")
        else:
            require(self.samples is not None, "samples", None, f"the {self.sampler} sampler needs it")
            require(self.samples >= 2, "samples", self.samples, "must be >= 2")
        if self.sampler == "sobol":
            require((self.samples & (self.samples - 1)) == 0, "samples", self.samples,
                    "must be a power of 2 for Sobol' sampling")
        if self.sampler in ("latin", "sobol"):
            require(self.levels is None, "levels", self.levels, "only the grid and morris samplers use it")
        if self.sampler == "morris":
            if self.levels is None:
                object.__setattr__(self, "levels", 4)
            require(self.levels >= 2 and self.levels % 2 == 0, "levels", self.levels, "must be even and >= 2")
        if self.sampler == "grid" and self.levels is not None:
            require(self.levels >= 2, "levels", self.levels, "must be >= 2")
        if self.sampler != "sobol":
            require(self.second_order is None, "second_order", self.second_order, "only the sobol sampler uses it")
        else:
            object.__setattr__(self, "second_order", bool(self.second_order))
        in_range("conf_level", self.conf_level, 0.0, 1.0, "-", low_open=True, high_open=True)
        require(self.resamples >= 10, "resamples", self.resamples, "must be >= 10")


@dataclass(frozen=True)
class Execution:
    """``[execution]``: runs_per_task: runs evaluated by one Dask task, >= 1 (1 for simulations; a few
    hundred for cheap test functions, whose runs cost less than a task); keep_results: also keep each
    run's ``result.npz`` (simulation models)."""

    runs_per_task: int = 1
    keep_results: bool = False

    def __post_init__(self):
        require(self.runs_per_task >= 1, "runs_per_task", self.runs_per_task, "must be >= 1")


@dataclass(frozen=True)
class StudyHeader:
    """``[study]``: name; description; scenario: base scenario file, relative to the study file; or
    model: a built-in model (``ishigami``); overrides: ``section.key=value`` strings applied to every run
    (e.g. solver settings); outputs: summary metrics to analyse; seed: of the sampling and bootstrap
    (needed by latin, morris and sobol); evaluate: how a base scenario's sample is evaluated
    (:data:`~.models.EVALUATORS`): ``run`` (default), ``steady_run`` (a bearing run whose analysis window must
    settle) or ``skidding_balance`` (the quasi-static skidding balance instead of a run)."""

    name: str
    outputs: tuple[str, ...]
    scenario: str | None = None
    model: str | None = None
    overrides: tuple[str, ...] = ()
    seed: int | None = None
    description: str = ""
    evaluate: str = "run"

    def __post_init__(self):
        one_of("evaluate", self.evaluate, tuple(EVALUATORS))


@dataclass(frozen=True)
class StudyFile:
    """A whole study TOML file."""

    study: StudyHeader
    method: Method
    parameters: tuple[Parameter, ...]
    execution: Execution = field(default_factory=Execution)


@dataclass(frozen=True)
class Study:
    """A validated sensitivity study: the Python equivalent of a study file.

    model: what one run evaluates (:class:`~.models.SimulationModel` for a scenario); parameters: the
    inputs that vary; outputs: the summary metrics analysed; method: sampling and analysis; seed: of the
    sampling and bootstrap; execution: how runs are batched and what is kept; source: the study file.
    """

    name: str
    model: RunModel
    parameters: tuple[Parameter, ...]
    outputs: tuple[str, ...]
    method: Method
    seed: int | None = None
    execution: Execution = field(default_factory=Execution)
    description: str = ""
    source: str = ""

    def __post_init__(self):
        object.__setattr__(self, "parameters", tuple(self.parameters))
        object.__setattr__(self, "outputs", tuple(self.outputs))
        require(bool(self.name), "study.name", self.name, "must not be empty")
        require(len(self.parameters) > 0, "parameters", [], "a study needs at least one [[parameters]] entry")
        names = [p.name for p in self.parameters]
        for i, name in enumerate(names):
            require(name not in names[:i], f"parameters.{i}.name", name, "is already a parameter")
        require(len(self.outputs) > 0, "study.outputs", [], "name at least one summary metric")
        for i, output in enumerate(self.outputs):
            require(isinstance(output, str) and output != "", f"study.outputs.{i}", output, "must be a name")
            require(output not in self.outputs[:i], f"study.outputs.{i}", output, "is listed twice")
        if self.method.sampler in RANDOM_SAMPLERS:
            require(self.seed is not None, "study.seed", None, f"the {self.method.sampler} sampler needs a seed")
        if self.seed is not None:
            require(0 <= self.seed < 2**32, "study.seed", self.seed, "must be in 0..2**32 - 1")
        for i, parameter in enumerate(self.parameters):
            self._check_parameter(i, parameter)

    def _check_parameter(self, i: int, parameter: Parameter) -> None:
        where = f"parameters.{i}"
        if self.method.sampler == "grid":
            if parameter.values is None:
                require(parameter.bounds is not None, where, parameter.name,
                        "the grid sampler needs values, or bounds and [method] levels")
                require(self.method.levels is not None, f"{where}.values", None,
                        "the grid sampler needs values, or [method] levels for the bounds")
                require(parameter.distribution in ("unif", "logunif"), f"{where}.distribution",
                        parameter.distribution, "a grid over bounds is unif (linear) or logunif (geometric)")
        else:
            require(parameter.values is None, f"{where}.values", list(parameter.values or ()),
                    f"the {self.method.sampler} sampler needs bounds, not values")
            require(parameter.bounds is not None, f"{where}.bounds", None,
                    f"the {self.method.sampler} sampler needs bounds")
        trial = parameter.values if parameter.values is not None else [float(b) for b in parameter.bounds]
        for value in trial:
            try:
                self.model.assign((parameter.name,), (value,))
            except SpecError as error:
                raise SpecError(f"{where}.name", parameter.name,
                                f"is not a valid input of {self.model.describe()} at {value!r}: {error}") from None

    @property
    def names(self) -> list[str]:
        return [p.name for p in self.parameters]

    @property
    def problem(self) -> dict:
        """SALib's problem dict: num_vars, names, bounds, dists, outputs."""
        return {
            "num_vars": len(self.parameters),
            "names": self.names,
            "bounds": [p.salib_bounds if p.bounds is not None else [min(p.values), max(p.values)]
                       for p in self.parameters],
            "dists": [p.distribution for p in self.parameters],
            "outputs": list(self.outputs),
        }


def load_study(path: str | Path, overrides: list[str] = ()) -> Study:
    """Read and validate a study TOML file; ``section.key=value`` overrides apply to the study file
    (e.g. ``method.samples=4``). Raises :class:`SpecError` before anything runs."""
    path = Path(path)
    if path.is_dir():
        raise SpecError("study file", str(path), "a TOML file; this is a directory")
    try:
        data = tomllib.loads(path.read_text())
    except FileNotFoundError:
        raise SpecError("study file", str(path), "file not found") from None
    except tomllib.TOMLDecodeError as error:
        raise SpecError("study file", str(path), f"is not valid TOML: {error}") from None
    if "scenario" in data and "study" not in data:
        raise SpecError("study file", "[scenario]", "a sensitivity study (with [study]); this is a scenario: run it "
                                                   "with `bearing-mbs run`")
    for text in overrides:
        keys, value = parse_override(text)
        apply_override(data, keys, value)
    spec = from_mapping(StudyFile, data)
    header = spec.study
    require((header.scenario is None) != (header.model is None), "study.scenario", header.scenario,
            "give either a base scenario file or a built-in model (" + ", ".join(BUILTIN_MODELS) + ")")
    if header.model is not None:
        one_of("study.model", header.model, tuple(BUILTIN_MODELS))
        require(not header.overrides, "study.overrides", list(header.overrides),
                "overrides apply to a base scenario; set the built-in model's inputs as parameters")
        require(header.evaluate == "run", "study.evaluate", header.evaluate,
                "chooses how a base scenario's samples are evaluated; a built-in model evaluates itself")
        model = BUILTIN_MODELS[header.model]()
    else:
        scenario = (path.parent / header.scenario).resolve()
        try:
            model = SimulationModel(str(scenario), header.overrides)
        except SpecError as error:
            raise SpecError("study.scenario", header.scenario, f"the base scenario is invalid: {error}") from None
        if header.evaluate != "run":
            try:
                model = EVALUATORS[header.evaluate](str(scenario), header.overrides)
            except SpecError as error:
                raise SpecError("study.evaluate", header.evaluate,
                                f"cannot evaluate {model.describe()}: {error}") from None
    known = model.outputs()
    for i, output in enumerate(header.outputs):
        require(known is None or output in known, f"study.outputs.{i}", output,
                f"a number the runs report: one of {', '.join(sorted(known or ()))}")
    return Study(
        name=header.name,
        model=model,
        parameters=spec.parameters,
        outputs=header.outputs,
        method=spec.method,
        seed=header.seed,
        execution=spec.execution,
        description=header.description,
        source=str(path),
    )
