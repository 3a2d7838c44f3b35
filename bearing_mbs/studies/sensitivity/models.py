"""What one run evaluates: a pluggable model, a pure function of its canonical input mapping.

A run model turns a raw input mapping (the base input with the sampled parameter values applied by their
dotted paths) into a validated *canonical* mapping, and evaluates a canonical mapping into a summary
dict of named scalars. The canonical mapping is what a run's content hash is taken of, so two spellings
of the same input are one run.

- :class:`SimulationModel`: a ``bearing_mbs`` scenario (any ``[scenario] model``), run by
  :func:`bearing_mbs.runner.run_spec`; its summary is :func:`bearing_mbs.runner.summarize`.
- :class:`SteadyRunModel`: the same run, read for steady values: its checks get its model's settling check (the
  cylindrical roller bearing's ``window_settled``), so a run whose window has not settled is ``suspect``.
- :class:`SkiddingBalanceModel`: the same sample, evaluated by its model's quasi-static steady balance instead of a
  run (the cylindrical roller bearing's skidding balance, a point of its skidding map: seconds where a light-load
  run needs seconds of simulated time to settle); a point without a balance is a ``failed`` run.
- :class:`IshigamiModel`: SALib's Ishigami–Homma test function, whose Sobol indices are known
  analytically; it goes through the same sample → evaluate → persist → analyze pipeline and checks it.

A study file chooses among the three scenario models with ``[study] evaluate`` (:data:`EVALUATORS`). Their
names differ, so the same spec evaluated two ways is two runs (a run's key hashes the model name).

Models are sent to Dask workers by pickling, so a model is a small, picklable object; a Python user
can pass an instance of their own subclass of :class:`RunModel`.
"""

from __future__ import annotations

import contextlib
import copy
import math
import tempfile
from dataclasses import dataclass, field
from pathlib import Path

from bearing_mbs.models import MODELS, spec_from_mapping
from bearing_mbs.models.loading import current_model_name
from bearing_mbs.spec import SpecError, apply_override, read_scenario, to_mapping

RESULT_FILE = "result.npz"


class RunModel:
    """Interface of a run model. Subclasses set ``name`` and implement :meth:`base`,
    :meth:`canonical` and :meth:`evaluate`."""

    name: str = "model"

    def base(self) -> dict:
        """The raw input mapping that sampled parameter values are applied to."""
        raise NotImplementedError

    def canonical(self, data: dict) -> dict:
        """Validate a raw input mapping; return its canonical form. Raises :class:`SpecError`."""
        raise NotImplementedError

    def evaluate(self, data: dict, keep_result: bool = False) -> tuple[dict, dict[str, bytes]]:
        """Run one canonical input: (summary of named scalars with a ``status``, files to keep by name)."""
        raise NotImplementedError

    def describe(self) -> str:
        return self.name

    def outputs(self) -> tuple[str, ...] | None:
        """The names of the numbers its summaries carry, for checking a study's outputs (None: not known)."""
        return None

    def assign(self, names: tuple[str, ...], values) -> dict:
        """The canonical input with ``values`` set at the dotted paths ``names`` of the base input."""
        data = copy.deepcopy(self.base())
        for name, value in zip(names, values):
            apply_override(data, name.split("."), value)
        return self.canonical(data)


@dataclass(frozen=True)
class SimulationModel(RunModel):
    """A ``bearing_mbs`` scenario: base TOML file plus fixed ``section.key=value`` overrides.

    scenario: path of the base scenario file; overrides: applied to every run before the sampled values,
    validated like ``bearing-mbs run --set``. The base is read and validated on construction.
    """

    scenario: str
    overrides: tuple[str, ...] = ()
    name: str = "simulation"
    _base: dict | None = field(default=None, init=False, repr=False, compare=False)

    def __post_init__(self):
        data = read_scenario(self.scenario, list(self.overrides))
        spec_from_mapping(data)  # raises SpecError naming the field
        object.__setattr__(self, "_base", data)

    def base(self) -> dict:
        return self._base

    def canonical(self, data: dict) -> dict:
        return to_mapping(spec_from_mapping(data))

    def outputs(self) -> tuple[str, ...]:
        """The run's numbers (cost, counts) and the metrics of the scenario's model (their ``units`` keys)."""
        from bearing_mbs.runner.units import RUN_UNITS

        return (*RUN_UNITS, *MODELS[current_model_name(self._base["scenario"]["model"])].units)

    def evaluate(self, data: dict, keep_result: bool = False) -> tuple[dict, dict[str, bytes]]:
        from bearing_mbs.runner import run_spec, summarize

        spec = spec_from_mapping(data)
        scene, result = run_spec(spec)
        if result.completed:  # a run that stopped early has no checks: its failure says why
            result.checks = (*result.checks, *self.study_checks(spec, scene, result))
        summary = summarize(spec, scene, result)
        files = {}
        if keep_result:
            with tempfile.TemporaryDirectory() as directory:
                path = result.save(Path(directory) / RESULT_FILE)
                files[RESULT_FILE] = path.read_bytes()
        return summary, files

    def study_checks(self, spec, scene, result) -> tuple:
        """Checks the study adds to a finished run's own (none here)."""
        return ()

    def describe(self) -> str:
        sets = "".join(f" --set {text}" for text in self.overrides)
        path = Path(self.scenario)
        with contextlib.suppress(ValueError):
            path = path.relative_to(Path.cwd())
        return f"scenario {path}{sets}"

    def __getstate__(self):  # the base mapping is only needed on the driver
        return {"scenario": self.scenario, "overrides": self.overrides, "name": self.name}

    def __setstate__(self, state):
        for key, value in state.items():
            object.__setattr__(self, key, value)
        object.__setattr__(self, "_base", None)


def _model_part(spec, part: str, evaluator: str):
    """The part (a field of :class:`bearing_mbs.models.Model`) of the spec's model that ``evaluator`` needs;
    raises :class:`SpecError` for a model without it."""
    return MODELS.part(spec.scenario.model, part, f"a {part.replace('_', ' ')} (the {evaluator} evaluator)")


@dataclass(frozen=True)
class SteadyRunModel(SimulationModel):
    """A scenario's run read for steady values: :class:`SimulationModel`'s run whose checks get its model's
    settling check (:attr:`bearing_mbs.models.Model.settling_check`; the cylindrical roller bearing's
    ``window_settled``: the cage slip's means over the analysis window's two halves agree to the pocket-play
    resolution plus 5 %). A run still approaching its steady state is ``suspect``, and the study with it. The base
    scenario's model must have a settling check."""

    name: str = "steady_run"

    def __post_init__(self):
        super().__post_init__()
        _model_part(spec_from_mapping(self._base), "settling_check", "steady_run")

    def study_checks(self, spec, scene, result) -> tuple:
        return (MODELS[spec.scenario.model].settling_check(spec, scene, result),)

    def describe(self) -> str:
        return f"{super().describe()}; each run's analysis window held to settle (window_settled)"


@dataclass(frozen=True)
class SkiddingBalanceModel(SimulationModel):
    """A scenario evaluated by its model's quasi-static steady balance (:attr:`bearing_mbs.models.Model.
    steady_balance`) instead of a run: the spec is built exactly as for a run (the base, its overrides, the sampled
    values), and its summary is the balance's row, with a ``status``: ``success``, or ``failed`` where the balance
    has no solution (its ``message`` says why; its values are null). The cylindrical roller bearing's is the
    skidding map's point (:mod:`bearing_mbs.models.cylindrical_roller.studies.balance`: cage slip, largest roller
    slips in and out of the load zone, slide-to-roll ratio, friction torque, power loss); its base scenario must be a
    caged bearing with a lubricant temperature, at constant speed and load."""

    name: str = "skidding_balance"

    def __post_init__(self):
        from bearing_mbs.studies.services import SERVICES

        super().__post_init__()
        spec = spec_from_mapping(self._base)
        _model_part(spec, "steady_balance", "skidding_balance").check(SERVICES, spec)

    def outputs(self) -> tuple[str, ...]:
        """The balance's numeric entries."""
        return MODELS[current_model_name(self._base["scenario"]["model"])].steady_balance.outputs

    def evaluate(self, data: dict, keep_result: bool = False) -> tuple[dict, dict[str, bytes]]:
        from bearing_mbs.io.json import json_safe, rounded
        from bearing_mbs.studies.services import SERVICES

        spec = spec_from_mapping(data)
        row = MODELS[spec.scenario.model].steady_balance.evaluate(SERVICES, spec)
        return rounded(json_safe(row)), {}

    def describe(self) -> str:
        return f"{super().describe()}; evaluated by the quasi-static skidding balance"


@dataclass(frozen=True)
class IshigamiModel(RunModel):
    """SALib's Ishigami–Homma function y = sin x1 + a sin² x2 + b x3⁴ sin x1 (dimensionless).

    Inputs ``x1, x2, x3`` (usually uniform on [−π, π]) and the constants ``a`` (7) and ``b`` (0.1);
    the one output is ``y``. :func:`ishigami_indices` gives its analytic Sobol indices.
    """

    a: float = 7.0
    b: float = 0.1
    name: str = "ishigami"

    KEYS = ("x1", "x2", "x3", "a", "b")

    def base(self) -> dict:
        return {"x1": 0.0, "x2": 0.0, "x3": 0.0, "a": self.a, "b": self.b}

    def outputs(self) -> tuple[str, ...]:
        return ("y",)

    def canonical(self, data: dict) -> dict:
        for key, value in data.items():
            if key not in self.KEYS:
                raise SpecError(key, value, f"unknown key; allowed keys: {', '.join(self.KEYS)}")
            if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value):
                raise SpecError(key, value, "must be a finite number")
        return {key: float(data[key]) for key in self.KEYS}

    def evaluate(self, data: dict, keep_result: bool = False) -> tuple[dict, dict[str, bytes]]:
        import numpy as np
        from SALib.test_functions import Ishigami

        x = np.array([[data["x1"], data["x2"], data["x3"]]])
        y = float(Ishigami.evaluate(x, A=data["a"], B=data["b"])[0])
        return {"status": "success", "y": y}, {}


def ishigami_indices(a: float = 7.0, b: float = 0.1) -> dict[str, list[float]]:
    """Analytic first-order ``S1`` and total ``ST`` Sobol indices of the Ishigami function, inputs
    uniform on [−π, π] (Ishigami & Homma 1990; Saltelli et al. 2008, *Global Sensitivity Analysis:
    The Primer*, §4.8)."""
    pi4, pi8 = math.pi**4, math.pi**8
    variance = a**2 / 8 + b * pi4 / 5 + b**2 * pi8 / 18 + 0.5
    v1 = 0.5 * (1 + b * pi4 / 5) ** 2
    v2 = a**2 / 8
    v13 = b**2 * pi8 * (1 / 18 - 1 / 50)
    return {
        "S1": [v1 / variance, v2 / variance, 0.0],
        "ST": [(v1 + v13) / variance, v2 / variance, v13 / variance],
    }


#: Built-in models a study file can name with ``[study] model = ...`` (a scenario file means simulation).
BUILTIN_MODELS = {"ishigami": IshigamiModel}
#: How a study evaluates the samples of its base scenario, ``[study] evaluate = ...``: a run (the default), a run
#: whose analysis window must settle, or the quasi-static skidding balance.
EVALUATORS = {"run": SimulationModel, "steady_run": SteadyRunModel, "skidding_balance": SkiddingBalanceModel}
