r"""Work–precision studies: error against cost for every engine, method and step of a scenario.

``bearing-mbs convergence SCENARIO.toml --out DIR`` reads the scenario's ``[convergence]`` section
(:class:`bearing_mbs.spec.convergence.ConvergenceSpec`) and

1. runs the **reference** setting (a much finer step with a high-order method) and a **check** setting
   (a different method, also fine); their distance is reported as the reference's own error, which must be
   well below the smallest target;
2. runs every studied setting, resampled onto the reference's output instants, and measures every norm;
3. writes ``DIR/convergence.csv`` (a row per run, appended as each finishes, so a re-run skips what is done),
   ``DIR/work_precision.png``, and ``DIR/summary.json`` / ``DIR/convergence.md`` with the cheapest setting
   reaching each target error and the observed order of each fixed-step ladder.

Every run integrates to the end of the window (``[convergence] end``, else the scenario's end time). Norms
(relative unless noted), over the window ``[start, end]``:

* ``positions``: max |Δx|, |Δy| of the bodies' centres, over the smallest ball radius (balls model) or over
  the largest reference inner-ring displacement (bearing model);
* ``cage_speed``: |Δ mean cage speed| / reference mean cage speed;
* ``roller_loads``: max |Δ inner-raceway roller load| / largest reference roller load;
* ``slips``: max |Δ slip ratio| at loaded raceway contacts (absolute: slip ratios are already ratios).
"""

from __future__ import annotations

import logging
from pathlib import Path

import numpy as np

from bearing_mbs.core.progress import ProgressMeter
from bearing_mbs.core.result import Result
from bearing_mbs.core.topology import Group
from bearing_mbs.engines import check_supported, simulate
from bearing_mbs.io.figures import new_figure, save_figure
from bearing_mbs.io.json import write_json
from bearing_mbs.models import build_scene
from bearing_mbs.numerics.advisor import step_advice
from bearing_mbs.spec import Spec, SpecError, to_mapping
from bearing_mbs.spec.convergence import RunSettings
from bearing_mbs.studies.common import resample_result, solver_at
from bearing_mbs.studies.table import append_row, number, read_rows, text

log = logging.getLogger(__name__)

COLUMNS = ("engine", "solver", "step", "tolerance", "error", "wall_time_s", "force_evaluations", "steps",
           "status", "positions", "cage_speed", "roller_loads", "slips")
BEARING_NORMS = ("cage_speed", "roller_loads", "slips")


def solver_for(spec: Spec, run: RunSettings, value: float):
    """The spec's solver settings with ``run`` at step [s] or tolerance ``value``."""
    largest = run.step if run.step is not None else spec.solver.output_interval
    changes = {} if run.engine == "reference" else {"connector": run.connector}
    return solver_at(spec.solver, run.engine, run.method, value, largest_step=largest, **changes)


def ladder(run: RunSettings) -> list[tuple[float | None, float | None]]:
    """(step, tolerance) of every setting of a run entry."""
    return [(None, t) for t in run.tolerances] if run.adaptive else [(s, None) for s in run.steps]


def window_mask(spec: Spec, times: np.ndarray) -> np.ndarray:
    study = spec.convergence
    start = study.start
    if start is None:
        start = spec.analysis.window_start(spec.scenario.end_time) if spec.scenario.model == "bearing" else 0.0
    end = study.end if study.end is not None else np.inf
    return (times >= start - 1e-12) & (times <= end + 1e-12)


def errors(spec: Spec, scene, result: Result, reference: Result) -> dict:
    """Every applicable norm of ``result`` against ``reference`` (see the module docstring)."""
    mask = window_mask(spec, reference.time)
    run = resample_result(result, reference.time)
    norms = {}
    if spec.scenario.model == "balls":
        translational = np.concatenate([[3 * i, 3 * i + 1] for i in range(len(scene.bodies))])
        scale = min(ball.radius for ball in spec.balls)
    else:
        translational = np.array([0, 1])
        scale = np.abs(reference.position[mask][:, :2]).max()
    delta = run.position[mask][:, translational] - reference.position[mask][:, translational]
    norms["positions"] = float(np.abs(delta).max() / scale)
    if spec.scenario.model == "bearing":
        from bearing_mbs.models.cylindrical_roller import metrics as skidding

        cage_run, cage_ref = skidding.cage_speed(scene, run)[mask], skidding.cage_speed(scene, reference)[mask]
        norms["cage_speed"] = float(abs(cage_run.mean() - cage_ref.mean()) / abs(cage_ref.mean()))
        inner = skidding.pair_columns(scene, Group.INNER_RACE)
        loads_run = run.pair_series("normal_force")[mask][:, inner]
        loads_ref = reference.pair_series("normal_force")[mask][:, inner]
        norms["roller_loads"] = float(np.abs(loads_run - loads_ref).max() / loads_ref.max())
        fraction = spec.analysis.load_fraction
        slips = [np.abs(skidding.slip_ratios(scene, run, race, fraction)[mask]
                        - skidding.slip_ratios(scene, reference, race, fraction)[mask])
                 for race in (Group.INNER_RACE, Group.OUTER_RACE)]
        both = np.concatenate([s.ravel() for s in slips])
        norms["slips"] = float(np.nanmax(both)) if np.isfinite(both).any() else float("nan")
    return norms


def largest_slip(spec: Spec, scene, result: Result) -> float:
    """The largest |slip ratio| of ``result`` at loaded contacts over the study's window (the scale of the
    ``slips`` norm)."""
    from bearing_mbs.models.cylindrical_roller import metrics as skidding

    mask = window_mask(spec, result.time)
    fraction = spec.analysis.load_fraction
    slips = [np.abs(skidding.slip_ratios(scene, result, race, fraction)[mask]) for race in (Group.INNER_RACE, Group.OUTER_RACE)]
    both = np.concatenate([s.ravel() for s in slips])
    return float(np.nanmax(both)) if np.isfinite(both).any() else 0.0


def end_time(spec: Spec) -> float:
    """How far the study integrates [s]: the end of its window (``[convergence] end``), else the scenario's."""
    study = spec.convergence
    return study.end if study is not None and study.end is not None else spec.scenario.end_time


def run_setting(spec: Spec, scene, run: RunSettings, step, tolerance, progress=None) -> Result:
    solver = solver_for(spec, run, tolerance if run.adaptive else step)
    return simulate(scene, solver, end_time(spec), progress, step_advice=step_advice(scene, solver).text())


def study(spec: Spec, directory: str | Path, progress: ProgressMeter | None = None) -> dict:
    """Run the work–precision study of ``spec`` into ``directory``; returns the summary."""
    if spec.convergence is None:
        raise SpecError("convergence", None, "this scenario has no [convergence] section (see docs/numerics.md)")
    directory = Path(directory)
    directory.mkdir(parents=True, exist_ok=True)
    settings = spec.convergence
    scene = build_scene(spec)
    if settings.end is not None and settings.end > spec.scenario.end_time:
        raise SpecError("convergence.end", settings.end, f"<= the scenario's end time {spec.scenario.end_time:g} s")
    if spec.scenario.model == "balls" and settings.norm in BEARING_NORMS:
        raise SpecError("convergence.norm", settings.norm, "the balls model has the positions norm only")

    for run in (settings.reference, *([settings.check] if settings.check is not None else []), *settings.runs):
        for step, tolerance in ladder(run):  # every setting the scene cannot run is refused before the first run
            check_supported(scene, solver_for(spec, run, tolerance if run.adaptive else step))

    progress = progress or ProgressMeter()
    total = 1 + (settings.check is not None) + sum(len(ladder(run)) for run in settings.runs)
    progress.next_run(1, total)
    reference = _cached_run(spec, scene, settings.reference, directory / "reference.npz", progress)
    summary = {"scenario": spec.scenario.name, "norm": settings.norm, "reference": _describe(settings.reference),
               "reference_wall_time_s": reference.stats.wall_time_s}
    if spec.scenario.model == "bearing":
        summary["reference_largest_slip"] = largest_slip(spec, scene, reference)
    if settings.check is not None:
        progress.next_run(2, total)
        check = _cached_run(spec, scene, settings.check, directory / "check.npz", progress)
        summary["check"] = _describe(settings.check)
        summary["reference_error"] = errors(spec, scene, check, reference)
        target = min(settings.targets)
        if summary["reference_error"][settings.norm] > 0.1 * target:
            log.warning("the reference and its check differ by %.3g in %s, not well below the smallest "
                        "target %g: refine the reference", summary["reference_error"][settings.norm],
                        settings.norm, target)

    table = directory / "convergence.csv"
    rows = read_rows(table)
    done = {(r["engine"], r["solver"], r["step"], r["tolerance"]) for r in rows}
    index = 1 + (settings.check is not None)
    for run in settings.runs:
        for step, tolerance in ladder(run):
            index += 1
            key = (run.engine, run.method, text(step), text(tolerance))
            if key in done:
                continue
            progress.next_run(index, total)
            result = run_setting(spec, scene, run, step, tolerance, progress)
            norms = errors(spec, scene, result, reference) if result.success else {}
            row = {"engine": run.engine, "solver": run.method, "step": text(step), "tolerance": text(tolerance),
                   "error": norms.get(settings.norm, float("nan")), "wall_time_s": result.stats.wall_time_s,
                   "force_evaluations": result.stats.force_evaluations, "steps": result.stats.steps,
                   "status": result.status, **{n: norms.get(n, "") for n in COLUMNS[9:]}}
            append_row(table, row, COLUMNS)
            rows.append({k: text(v) if not isinstance(v, str) else v for k, v in row.items()})
            log.info("run %d/%d: %s %s step=%s tol=%s: %s, error %.3g in %.3g s", index, total, run.engine,
                     run.method, step, tolerance, result.status, row["error"], result.stats.wall_time_s)

    summary["cheapest"] = cheapest(rows, settings.targets)
    summary["orders"] = observed_orders(rows)
    write_json(directory / "summary.json", summary)
    (directory / "convergence.md").write_text(markdown(summary, rows))
    work_precision_figure(rows, directory / "work_precision.png", f"{spec.scenario.name}: {settings.norm} error")
    return summary


def cheapest(rows: list[dict], targets) -> dict:
    """For each target error, the successful row with the smallest wall time reaching it."""
    answer = {}
    for target in targets:
        reaching = [r for r in rows if r["status"] == "success" and number(r["error"]) <= target]
        best = min(reaching, key=lambda r: number(r["wall_time_s"]), default=None)
        answer[f"{target:g}"] = None if best is None else {k: best[k] for k in COLUMNS[:8]}
    return answer


def observed_orders(rows: list[dict]) -> dict:
    """Least-squares slope of log(error) against log(step) of each fixed-step ladder (successful runs)."""
    orders = {}
    for key in sorted({(r["engine"], r["solver"]) for r in rows if r["step"]}):
        ladder_rows = [r for r in rows if (r["engine"], r["solver"]) == key and r["step"] and r["status"] == "success"
                       and number(r["error"]) > 0]
        if len(ladder_rows) >= 3:
            steps = np.log([number(r["step"]) for r in ladder_rows])
            errors_ = np.log([number(r["error"]) for r in ladder_rows])
            orders[" ".join(key)] = float(np.polyfit(steps, errors_, 1)[0])
    return orders


def work_precision_figure(rows: list[dict], path: Path, title: str) -> Path:
    """Error against wall time [s] of every engine and method (log axes)."""
    figure, axis = new_figure(figsize=(7, 5))
    for key in sorted({(r["engine"], r["solver"]) for r in rows}):
        points = sorted((number(r["wall_time_s"]), number(r["error"])) for r in rows
                        if (r["engine"], r["solver"]) == key and r["status"] == "success" and number(r["error"]) > 0)
        if points:
            axis.loglog(*zip(*points), "o-", label=" ".join(key))
    axis.set_xlabel("wall time [s]")
    axis.set_ylabel("error")
    axis.grid(True, which="both", alpha=0.3)
    axis.legend(fontsize="small")
    axis.set_title(title)
    return save_figure(figure, path)


def markdown(summary: dict, rows: list[dict]) -> str:
    lines = [f"# Work–precision: {summary['scenario']} ({summary['norm']} error)", "",
             f"Reference: {summary['reference']}."]
    if "reference_error" in summary:
        lines.append(f"Check: {summary['check']}; distance to the reference: "
                     + ", ".join(f"{k} {v:.2g}" for k, v in summary["reference_error"].items()) + ".")
    lines += ["", "| engine | solver | step [s] | tolerance | error | wall time [s] | force evaluations | status |",
              "|---|---|---|---|---|---|---|---|"]
    for r in rows:
        error = number(r["error"])
        lines.append(f"| {r['engine']} | {r['solver']} | {r['step']} | {r['tolerance']} | "
                     f"{error:.2e} | {number(r['wall_time_s']):.3g} | {r['force_evaluations']} | {r['status']} |")
    lines += ["", "Cheapest setting reaching each target:", ""]
    for target, best in summary["cheapest"].items():
        text = "none of the settings" if best is None else (
            f"{best['engine']} {best['solver']} step {best['step'] or '-'} tolerance {best['tolerance'] or '-'}: "
            f"error {number(best['error']):.2e} in {number(best['wall_time_s']):.3g} s")
        lines.append(f"* {target}: {text}")
    if summary["orders"]:
        lines += ["", "Observed orders (slope of log error against log step): "
                  + ", ".join(f"{k} {v:.2f}" for k, v in summary["orders"].items())]
    return "\n".join(lines) + "\n"


def _cached_run(spec, scene, run: RunSettings, path: Path, progress) -> Result:
    """The reference (or check) run, reused from ``path`` when a previous study of the same spec saved it."""
    step, tolerance = ladder(run)[0]
    if path.exists():
        cached = Result.load(path)
        if cached.spec == to_mapping(spec) and cached.method == run.method and cached.engine == run.engine:
            return cached
    result = run_setting(spec, scene, run, step, tolerance, progress)
    if not result.success:
        raise RuntimeError(f"the reference run failed: {result.message}")
    result.spec = to_mapping(spec)
    result.save(path)
    return result


def _describe(run: RunSettings) -> str:
    step, tolerance = ladder(run)[0]
    what = f"tolerance {tolerance:g}" if run.adaptive else f"step {step:g} s"
    return f"{run.engine} {run.method}, {what}"
