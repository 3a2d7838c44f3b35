r"""Stability suite: which engine and solver survive stiff and extreme cases of a model, and up to which step.

``bearing-mbs stability SCENARIO.toml --out DIR [--reduced]`` varies a scenario by its model's cases
(:attr:`bearing_mbs.models.Model.stability`; the cylindrical roller bearing's: contact stiffness ×0.01 to ×100,
v_reg 0.1 to 1e-4 m/s, restitution 0.1 and 1, speed to 10 000 rpm, zero and 5× load, preload and 200 µm clearance,
Z = 8 and 30, a full complement) and, for every engine and solver of
:data:`SOLVERS`, runs short **probes** from the scenario's start: the ring centred, the load applied at once, so
the first load peak (about twice the static load, more with clearance) is inside every probe. A probe lasts
1.25 × the advisor's time of that peak (at least 0.4 ms), and for an explicit method at least 2000 steps of its
largest rung, but no more than 2 ms (longer light-load runs drift apart chaotically, whatever the step).

A probe **passes** when

1. the run guards do not stop it (NaN or blow-up, penetration, solver failure);
2. its energy audit closes (:func:`bearing_mbs.analysis.energy_balance_error`): below ``audit_explicit`` (1e-3;
   ``audit_implicit`` = 1e-2 for generalized-alpha, whose ρ∞ < 1 dissipates numerically) outright, or up to 5e-2
   if it converges at the method's order against the 4× finer run (a first-order method closes its audit only to
   O(h) where it is perfectly stable);
3. its slip is not spurious against a 4× finer setting (:func:`.spurious_slip.compare_slips`: loaded friction
   pairs, slip speeds within 0.1 v_reg at every output instant).

Per solver kind:

* fixed-step explicit methods: a ladder of steps :math:`h_k = h_{adv}\,2^{k/2}` anchored at the advisor's
  stability limit :math:`h_{adv}` (:mod:`bearing_mbs.advisor`), walked up from :math:`k = 0` while probes pass
  (down while they fail); the **measured limit** is the largest passing rung. The 4× finer partner of rung k
  is rung k − 4, so runs are shared;
* generalized-alpha: the same walk by factors of 2 from ``implicit_step`` (1e-5 s);
* adaptive methods: tolerances from ``loose_tolerance`` (1e-4) down by 100 to ``tightest_tolerance`` (1e-8)
  until a probe passes (the finer partner: tolerance / 4⁵; Exudyn's DOPRI5 at 1e-13 did not finish here).

Outputs, written as each cell finishes (a re-run skips finished cells): ``DIR/stability.csv``,
``DIR/stability.md`` (the table), ``DIR/stability.png`` (the heat map), ``DIR/advised_vs_measured.png`` and
``DIR/summary.json`` (with the fraction of cells where the advisor's limit is within a factor of 2 of the
measured one).
"""

from __future__ import annotations

import dataclasses
import logging
import math
import time
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from bearing_mbs.analysis import energy_balance_error
from bearing_mbs.core.failures import Failure
from bearing_mbs.core.progress import ProgressMeter
from bearing_mbs.engines import check_supported, simulate
from bearing_mbs.io.json import write_json
from bearing_mbs.models import MODELS, build_scene, spec_from_mapping
from bearing_mbs.models.protocol import StabilityCase, StabilitySuite
from bearing_mbs.numerics.advisor import advise, step_advice
from bearing_mbs.spec import Spec, SpecError
from bearing_mbs.studies.common import refined_setting, solver_at, spec_mapping, with_overrides
from bearing_mbs.studies.spurious_slip import compare_slips
from bearing_mbs.studies.stability_cases import (  # noqa: F401  (re-exported: the suite's solvers)
    ADAPTIVE,
    IMPLICIT,
    ORDERS,
    REDUCED_SOLVERS,
    SOLVERS,
)
from bearing_mbs.studies.stability_report import advised_figure, heat_map, markdown, summarize
from bearing_mbs.studies.table import append_row, read_rows, text

log = logging.getLogger(__name__)

@dataclass(frozen=True)
class StabilitySettings:
    """Probe and ladder settings.

    probe_time [s]: None = 1.25 × the advisor's time of the first load peak, clamped to
    [min_probe_time, max_probe_time]. output_interval [s]: output spacing of the probes (the slip comparison
    uses every output instant). audit_explicit, audit_implicit: energy-audit error that passes outright; up to
    audit_largest it passes if it converges at the method's order against the 4× finer run (at most
    2·4^p times the finer run's). min_probe_steps: an explicit cell's probes last at least this many steps of
    its top rung (4× the advice), so that a slowly growing instability shows, but no longer than max_probe_time
    (longer light-load runs diverge chaotically, whatever the step).
    refinement: the finer partner's step ratio (4). up_rungs, down_rungs: how far the walk may go from the
    advice (rungs of √2). implicit_step [s]: generalized-alpha's first rung. loose_tolerance: adaptive methods'
    first tolerance. max_steps: per-engine step budget of one probe (a probe above it is not run).
    """

    probe_time: float | None = None
    min_probe_time: float = 4e-4
    max_probe_time: float = 2e-3
    output_interval: float = 1e-5
    audit_explicit: float = 1e-3
    audit_implicit: float = 1e-2
    audit_largest: float = 5e-2
    min_probe_steps: int = 2000
    refinement: int = 4
    up_rungs: int = 4
    down_rungs: int = 6
    implicit_step: float = 1e-5
    loose_tolerance: float = 1e-4
    tightest_tolerance: float = 1e-8
    max_steps: dict = field(default_factory=lambda: {"reference": 3_000_000, "exudyn": 150_000})
    max_probe_wall_time: float = 120.0


# --------------------------------------------------------------------------------------------------------------
# Probes
# --------------------------------------------------------------------------------------------------------------


@dataclass
class Probe:
    """One run: ``setting`` is the step [s] (the tolerance for adaptive methods)."""

    setting: float
    status: str  # "ok" (guards passed), "failed" (a guard or the solver stopped it), "skipped" (over budget)
    reason: str = ""
    audit: float = math.nan
    wall_time_s: float = 0.0
    steps: int = 0
    message: str = ""
    result: object = None


class BudgetExceeded(RuntimeError):
    """Raised by :class:`WallClockBudget` to abandon a probe."""


class WallClockBudget(ProgressMeter):
    """A progress meter that abandons a run after ``seconds`` of wall time."""

    def __init__(self, seconds: float):
        self.seconds, self.exceeded = seconds, False

    def start(self, total: float, description: str = "") -> None:
        self.started = time.perf_counter()

    def update(self, value: float) -> None:
        if time.perf_counter() - self.started > self.seconds:
            self.exceeded = True
            raise BudgetExceeded(f"over {self.seconds:g} s")


#: The label of each kind of stop in the study's tables.
FAILURE_LABELS = {Failure.NONFINITE: "NaN", Failure.BLOWUP: "blow-up", Failure.PENETRATION: "penetration"}


def failure_reason(failure: Failure) -> str:
    """The guard that stopped a run, from its failure kind."""
    return FAILURE_LABELS.get(failure, "solver failure")


class CellRunner:
    """Runs the probes of one case and solver, caching them by setting."""

    def __init__(self, spec: Spec, scene, engine: str, method: str, end_time: float, settings: StabilitySettings):
        self.spec, self.scene, self.engine, self.method = spec, scene, engine, method
        self.end_time, self.settings = end_time, settings
        self.adaptive, self.implicit = (engine, method) in ADAPTIVE, (engine, method) in IMPLICIT
        self.audit_limit = settings.audit_implicit if self.implicit else settings.audit_explicit
        self.probes: dict[float, Probe] = {}
        self.advice = advise(scene)

    def solver(self, setting: float):
        """The spec's solver on this cell's engine and method at ``setting`` (step [s] or tolerance)."""
        solver = dataclasses.replace(self.spec.solver, output_interval=self.settings.output_interval)
        return solver_at(solver, self.engine, self.method, setting, largest_step=self.settings.output_interval)

    def expected_steps(self, setting: float) -> float:
        if self.adaptive:  # stability-bound: about one step per advised limit
            limit = self.advice.limit(self.engine, self.method) if self.advice.applies else None
            return self.end_time / limit if limit and math.isfinite(limit) else 0.0
        return self.end_time / setting

    def run(self, setting: float) -> Probe:
        key = float(f"{setting:.12g}")
        if key in self.probes:
            return self.probes[key]
        if self.expected_steps(setting) > self.settings.max_steps[self.engine]:
            probe = Probe(setting, "skipped", "over the step budget")
        else:
            started = time.perf_counter()
            budget = WallClockBudget(self.settings.max_probe_wall_time)
            try:
                solver = self.solver(setting)
                result = simulate(self.scene, solver, self.end_time, budget,
                                  step_advice=step_advice(self.scene, solver).text())
            except BudgetExceeded:
                result = None
            wall = time.perf_counter() - started
            if result is None or budget.exceeded:
                probe = Probe(setting, "skipped", "over the time budget", wall_time_s=wall)
            elif result.success:
                probe = Probe(setting, "ok", audit=energy_balance_error(self.scene, result), wall_time_s=wall,
                              steps=result.stats.steps, result=result)
            else:
                probe = Probe(setting, "failed", failure_reason(result.failure), wall_time_s=wall,
                              steps=result.stats.steps, message=result.message)
        self.probes[key] = probe
        log.debug("%s %s %s=%.3g: probe %s %s", self.engine, self.method, "tolerance" if self.adaptive else "step",
                  setting, "ran to its end" if probe.status == "ok" else probe.status, probe.reason)
        return probe

    def finer(self, setting: float) -> float:
        return refined_setting(setting, self.settings.refinement, self.adaptive)

    def verdict(self, setting: float) -> tuple[str, str]:
        """("pass" | "fail" | "unknown", reason) of one setting (logged)."""
        state, reason = self._verdict(setting)
        log.info("%s %s %s=%.3g: %s%s", self.engine, self.method, "tolerance" if self.adaptive else "step", setting,
                 state, f" ({reason})" if reason else "")
        return state, reason

    def _verdict(self, setting: float) -> tuple[str, str]:
        probe = self.run(setting)
        if probe.status == "skipped":
            return "unknown", probe.reason
        if probe.status == "failed":
            return "fail", probe.reason
        if not probe.audit <= self.settings.audit_largest:
            return "fail", "energy audit"
        partner = self.run(self.finer(setting))
        if partner.status == "skipped":
            return "unknown", "finer run over the " + partner.reason.split("over the ")[-1]
        if partner.status == "failed":
            return "fail", f"finer run: {partner.reason}"
        # above the threshold the audit must at least converge at the method's order (a first-order method closes
        # its audit only to O(h) even where it is stable)
        allowed = 2.0 * self.settings.refinement ** ORDERS.get((self.engine, self.method), 1)
        if probe.audit > self.audit_limit and not probe.audit <= allowed * partner.audit:
            return "fail", "energy audit"
        found = compare_slips(self.scene, probe.result, partner.result)
        if found["ratio"] > 1.0:
            return "fail", "spurious slip"
        return "pass", ""


def walk(runner: CellRunner, rungs: Callable[[int], float], up: int, down: int) -> dict:
    """Walk a ladder from rung 0: up while passing, down while failing. Returns the largest passing setting,
    the smallest failing one above it (with its reason), and every verdict."""
    verdicts = {}

    def judge(k):
        verdicts[k] = runner.verdict(rungs(k))
        return verdicts[k]

    state, reason = judge(0)
    if state == "pass":
        k = 0
        while k < up:
            state, reason = judge(k + 1)
            if state != "pass":
                break
            k += 1
        passing = k
    elif state == "fail":
        k = 0
        while k > -down:
            state, reason = judge(k - 1)
            k -= 1
            if state != "fail":
                break
        passing = k if verdicts[k][0] == "pass" else None
    else:
        passing = None
    failing = min((j for j, v in verdicts.items() if v[0] == "fail" and (passing is None or j > passing)), default=None)
    return {
        "largest_pass": None if passing is None else rungs(passing),
        "first_fail": None if failing is None else rungs(failing),
        "fail_reason": "" if failing is None else verdicts[failing][1],
        "unknown": [verdicts[j][1] for j in verdicts if verdicts[j][0] == "unknown"],
        "verdicts": {rungs(j): v for j, v in sorted(verdicts.items())},
        "capped": passing is not None and passing >= up,
    }


def run_cell(spec: Spec, scene, engine: str, method: str, end_time: float, settings: StabilitySettings) -> dict:
    """One case × solver: the ladder walk and its summary row."""
    runner = CellRunner(spec, scene, engine, method, end_time, settings)
    advice = runner.advice
    advised = advice.limit(engine, method) if advice.applies else None
    row = {"engine": engine, "solver": method, "advised_limit": advised, "largest_pass": None,
           "first_fail": None, "fail_reason": "", "ratio": None, "verdict": "", "kind": "explicit"}
    if runner.implicit:
        row["kind"] = "implicit"
        found = walk(runner, lambda k: settings.implicit_step * 2.0**k, up=4, down=3)
    elif runner.adaptive:
        row["kind"] = "adaptive"
        tolerances = 10.0 ** -np.arange(round(-math.log10(settings.loose_tolerance)),
                                        round(-math.log10(settings.tightest_tolerance)) + 1, 2)
        found = _tolerance_walk(runner, list(tolerances))
    else:
        if advised is None or not math.isfinite(advised) or advised <= 0:
            row["verdict"] = "no advice"
            return row
        found = walk(runner, lambda k: advised * 2.0 ** (k / 2), up=settings.up_rungs, down=settings.down_rungs)
    row.update({key: found[key] for key in ("largest_pass", "first_fail", "fail_reason")})
    if found["largest_pass"] is None:
        row["verdict"] = "unknown: " + found["unknown"][0] if found["unknown"] else f"fail: {found['fail_reason']}"
    else:
        row["verdict"] = "pass" + (" (ladder top)" if found["capped"] else "")
    if row["kind"] == "explicit" and row["largest_pass"] is not None:
        row["ratio"] = row["largest_pass"] / advised
    row["wall_time_s"] = sum(p.wall_time_s for p in runner.probes.values())
    row["probes"] = len(runner.probes)
    row["ladder"] = "; ".join(f"{s:.3g}:{v[0]}{'(' + v[1] + ')' if v[1] else ''}" for s, v in found["verdicts"].items())
    return row


def _tolerance_walk(runner: CellRunner, tolerances: list[float]) -> dict:
    """Adaptive methods: from the loosest tolerance down until one passes."""
    verdicts = {}
    passing = None
    for tolerance in tolerances:
        verdicts[tolerance] = runner.verdict(tolerance)
        if verdicts[tolerance][0] == "pass":
            passing = tolerance
            break
        if verdicts[tolerance][0] == "unknown":
            break
    failing = [t for t, v in verdicts.items() if v[0] == "fail"]
    return {"largest_pass": passing, "first_fail": failing[-1] if failing else None,
            "fail_reason": verdicts[failing[-1]][1] if failing else "",
            "unknown": [v[1] for v in verdicts.values() if v[0] == "unknown"], "verdicts": verdicts, "capped": False}


# --------------------------------------------------------------------------------------------------------------
# The suite
# --------------------------------------------------------------------------------------------------------------


def suite(spec: Spec) -> StabilitySuite:
    """The stability suite of the scenario's model; raises :class:`SpecError` for a model without one."""
    return MODELS.part(spec.scenario.model, "stability", "a stability suite")


def case_spec(base: Spec, case: StabilityCase) -> Spec:
    """The base scenario varied by ``case`` (without the base's study section)."""
    data = spec_mapping(base)
    data.pop("convergence", None)
    case.change(data, base)
    data["scenario"]["name"] = f"{base.scenario.name} [{case.name}]"
    return spec_from_mapping(data)


def _with_end_time(spec: Spec, end_time: float) -> Spec:
    return with_overrides(spec, {"scenario.end_time": end_time, "analysis.start": end_time / 2})


def _round_up(value: float, quantum: float) -> float:
    return math.ceil(value / quantum * (1 - 1e-12)) * quantum


def probe_time(spec: Spec, scene, settings: StabilitySettings) -> float:
    if settings.probe_time is not None:
        return settings.probe_time
    advice = advise(scene)
    peak = advice.operating_point.get("first_peak_time", 0.0) if advice.applies else 0.0
    value = min(max(1.25 * peak, settings.min_probe_time), settings.max_probe_time)
    return _round_up(value, settings.output_interval)


COLUMNS = ("case", "engine", "solver", "kind", "probe_time", "advised_limit", "largest_pass", "ratio", "first_fail",
           "fail_reason", "verdict", "wall_time_s", "probes", "ladder")


def study(base: Spec, directory: str | Path, cases=None, solvers=SOLVERS,
          settings: StabilitySettings = StabilitySettings(), figures: bool = True) -> dict:
    """Run the stability suite of ``base`` into ``directory``; returns the summary. ``cases``: names of the
    model's cases (default: all of them)."""
    cases_of_model = suite(base)
    cases = cases_of_model.names if cases is None else cases
    unknown = [name for name in cases if name not in cases_of_model.names]
    if unknown:
        raise SpecError("cases", unknown, f"must be among: {', '.join(cases_of_model.names)}")
    by_name = {case.name: case for case in cases_of_model.cases}
    for name in cases:  # a solver the engine cannot run on a case is refused before the first probe
        spec = case_spec(base, by_name[name])
        scene = build_scene(spec)
        for engine, method in solvers:
            check_supported(scene, solver_at(spec.solver, engine, method, 1e-6,  # a step [s] or a tolerance
                                             largest_step=settings.output_interval))
    directory = Path(directory)
    directory.mkdir(parents=True, exist_ok=True)
    table = directory / "stability.csv"
    rows = read_rows(table)
    done = {(r["case"], r["engine"], r["solver"]) for r in rows}
    total, cell = len(cases) * len(solvers), 0
    for name in cases:
        if all((name, engine, method) in done for engine, method in solvers):
            cell += len(solvers)
            continue
        spec = case_spec(base, by_name[name])
        end_time = probe_time(spec, build_scene(spec), settings)
        spec = _with_end_time(spec, end_time)
        scene = build_scene(spec)
        advice = advise(scene)
        for engine, method in solvers:
            cell += 1
            if (name, engine, method) in done:
                continue
            duration, cell_spec = end_time, spec
            advised = advice.limit(engine, method) if advice.applies else None
            kind = (engine, method)
            if kind not in ADAPTIVE and kind not in IMPLICIT and advised and math.isfinite(advised):
                top = advised * 2.0 ** (settings.up_rungs / 2)
                duration = min(max(end_time, _round_up(settings.min_probe_steps * top, settings.output_interval)),
                               max(end_time, settings.max_probe_time))
                cell_spec = _with_end_time(spec, duration)
            row = {"case": name, "probe_time": duration,
                   **run_cell(cell_spec, scene, engine, method, duration, settings)}
            rows.append({k: text(row.get(k)) for k in COLUMNS})
            append_row(table, rows[-1], COLUMNS)
            log.info("cell %d/%d: %s | %s %s: %s (advised %s, largest pass %s)", cell, total, name, engine, method,
                     row["verdict"], row["advised_limit"], row["largest_pass"])
    rows = [r for r in rows if r["case"] in cases and (r["engine"], r["solver"]) in set(solvers)]
    summary = summarize(rows)
    summary["scenario"] = base.scenario.name
    summary["settings"] = {k: v for k, v in dataclasses.asdict(settings).items()}
    write_json(directory / "summary.json", summary)
    (directory / "stability.md").write_text(markdown(summary, rows))
    if figures:
        heat_map(rows, directory / "stability.png", f"{base.scenario.name}: measured / advised step limit (explicit); "
                 "passing h or tol, or why none passed (others)")
        advised_figure(rows, directory / "advised_vs_measured.png", base.scenario.name)
    return summary
