"""One shaft revolution (0.04 s at 1500 rpm) of the seed bearing with every implicit setting, against today's
baseline and the document's scheme: cost, cage-speed error and converged slips, all measured in one run.

The lubricated model (seed_hss_steady's default variant: EHL raceways, churning drag, cage on its land film,
constraint cage) is measured first, at the document's zero clearance (the case the targets below were set on), the
dry model (variant ``dry``: erf friction, penalty cage) second, and the lubricated model at its shipped operating
clearance (69.5 µm) last, with fewer settings: there the ring drops through the clearance onto its rollers when
the load is applied at t = 0, and the error window is an impact transient. Each run
integrates 0–0.04 s from the scenario's start (load applied at t = 0) after a short warm-up (compilation
excluded). Errors are those of docs/numerics.md, against the scenario's fine reference (``[convergence]
reference``: RK4 at 5e-8 s lubricated, 2.5e-8 s dry) over its ``[convergence]`` window, where two correct runs
agree instant by instant (10–20 ms lubricated; 5–15 ms dry, whose penalty cage's pocket rattle turns chaotic before
20 ms): the mean cage speed's relative error and the largest slip-ratio error at loaded contacts. Slips are
converged when that error is within
:func:`bearing_mbs.studies.numerics_report.sound_slip_bound`: 1e-4, or 1 % of the reference's largest slip ratio
where that is larger (the lubricated rollers slip by up to 6 % entering the load zone).

``runs`` (one entry per setting; ``model`` says which): ``baseline`` is Exudyn generalized-alpha with its numerical
Jacobian at h = 1e-5 s, the setting the docs recommended before this benchmark; ``document`` is the document's
central difference at 1/1.8e6 s. ``best`` is the cheapest run of a model with cage-speed error ≤ 1e-3, converged
slips and a successful status; ``scaling`` is each model's best setting at Z = 15, 30 and 60 rollers (the bearing
scaled with Z at equal roller size and roller load, so each roller's physics is the same), the exponent p of
cost ∝ Z^p fitted to it, and that of the cost per force evaluation (the algorithm's work, apart from the
evaluations and Jacobians that more rollers' contact events ask for).

The measured settings also become the bearing model's work–precision tables, from which ``[solver] tolerance`` chooses
a run's setting (bearing_mbs/models/cylindrical_roller/work_precision.json, :mod:`bearing_mbs.numerics.work_precision`):
each setting's engine section, cage-speed error, converged slips and cost per simulated second, with the
measurement's date, machine and commit. ``python benchmarks/bench_revolution.py`` measures and writes both;
``--table-only`` writes the tables again from benchmarks/out/bearing_revolution.json without measuring.

Targets (the speed issue, on the lubricated model): the best setting ≤ 0.04 s per revolution (faster than the
bearing turns) and ≥ 50× faster than baseline; Exudyn's best within 2.5× of the reference engine's best, each at
cage-speed error ≤ 1e-3 with converged slips, and ≥ 20× faster than baseline. Timings are compared as ratios of one
run, on a shared machine; each setting runs twice and its faster run counts.
"""

from __future__ import annotations

import argparse
import json
import math
import subprocess
from pathlib import Path

import numpy as np

from bearing_mbs.engines import simulate
from bearing_mbs.models import MODELS as REGISTERED_MODELS
from bearing_mbs.models import build_scene, load_spec
from bearing_mbs.numerics.work_precision import MeasuredSetting, WorkPrecisionTable, write_tables
from bearing_mbs.spec import to_mapping
from bearing_mbs.studies.convergence import errors, reference_scales, run_setting
from bearing_mbs.studies.numerics_report import sound_slip_bound

from common import OUT, SCENARIOS, machine, write

REVOLUTION = 2 * math.pi / (1500 * 2 * math.pi / 60)  # 0.04 s
DOCUMENT_STEP = 1 / 1.8e6
COMMON = [f"scenario.end_time={REVOLUTION}", "solver.output_interval=1e-4", "analysis.start=0.005"]
TARGET_ERROR = 1e-3
#: Runs of each setting; the fastest counts.
REPEATS = 2


def exudyn(step: float, jacobian: str = "analytic", spectral_radius: float | None = None,
           tolerance: float | None = None) -> list[str]:
    settings = ["solver.engine=exudyn", "solver.exudyn.method=generalized_alpha", f"solver.exudyn.step={step}",
                f"solver.exudyn.jacobian={jacobian}"]
    settings += [f"solver.exudyn.tolerance={tolerance}"] if tolerance else []
    return settings + ([f"solver.exudyn.spectral_radius={spectral_radius}"] if spectral_radius is not None else [])


def reference(method: str, step: float, tolerance: float | None = None,
              spectral_radius: float | None = None) -> list[str]:
    settings = ["solver.engine=reference", f"solver.reference.method={method}", f"solver.reference.step={step}"]
    settings += [f"solver.reference.tolerance={tolerance}"] if tolerance else []
    return settings + ([f"solver.reference.spectral_radius={spectral_radius}"] if spectral_radius is not None else [])


#: name → overrides, per model. The steps bracket where each setting stops meeting the 1e-3 target.
SETTINGS = {
    "baseline": exudyn(1e-5, "numerical"),
    "exudyn_generalized_alpha_analytic_1e-5": exudyn(1e-5),
    "exudyn_generalized_alpha_analytic_2e-5": exudyn(2e-5),
    "exudyn_generalized_alpha_analytic_5e-5": exudyn(5e-5),
    "exudyn_generalized_alpha_analytic_1e-4": exudyn(1e-4),
    # Exudyn's Newton stops on its residual reduced by the tolerance: 1e-3 halves the iterations at the same errors
    # (benchmarks/out/exudyn_overhead.json)
    "exudyn_generalized_alpha_analytic_1e-5_newton_1e-3": exudyn(1e-5, tolerance=1e-3),
    "exudyn_generalized_alpha_analytic_2e-5_newton_1e-3": exudyn(2e-5, tolerance=1e-3),
    # more numerical damping, ρ∞ = 0.5: a third of the Jacobian updates at 2e-5 s
    "exudyn_generalized_alpha_analytic_2e-5_newton_1e-3_rho_0.5": exudyn(2e-5, spectral_radius=0.5, tolerance=1e-3),
    "exudyn_generalized_alpha_analytic_3e-5_newton_1e-3_rho_0.5": exudyn(3e-5, spectral_radius=0.5, tolerance=1e-3),
    "reference_generalized_alpha_1e-5": reference("generalized_alpha", 1e-5, 1e-6),
    "reference_generalized_alpha_2e-5": reference("generalized_alpha", 2e-5, 1e-6),
    "reference_generalized_alpha_5e-5": reference("generalized_alpha", 5e-5, 1e-6),
    "reference_generalized_alpha_1e-4": reference("generalized_alpha", 1e-4, 1e-6),
    "reference_generalized_alpha_adaptive_1e-6": reference("generalized_alpha_adaptive", 1e-4, 1e-6),
    "reference_generalized_alpha_adaptive_1e-8": reference("generalized_alpha_adaptive", 1e-4, 1e-8),
    # strong numerical damping (rho_inf = 0.3) and a Newton tolerance at the target error: the steps the
    # contact modes' high-frequency remnants no longer hold back
    "exudyn_generalized_alpha_analytic_rho0.3_5e-5": exudyn(5e-5, spectral_radius=0.3, tolerance=1e-3),
    "exudyn_generalized_alpha_analytic_rho0.3_1e-4": exudyn(1e-4, spectral_radius=0.3, tolerance=1e-3),
    "reference_generalized_alpha_rho0.3_5e-5": reference("generalized_alpha", 5e-5, 1e-3, 0.3),
    "reference_generalized_alpha_rho0.3_1e-4": reference("generalized_alpha", 1e-4, 1e-3, 0.3),
    "reference_generalized_alpha_rho0.3_2e-4": reference("generalized_alpha", 2e-4, 1e-3, 0.3),
    "reference_generalized_alpha_rho0_1e-4": reference("generalized_alpha", 1e-4, 1e-3, 0.0),
    "document": reference("central_difference", DOCUMENT_STEP),
}
#: model → its scenario overrides. ``lubricated`` runs at the document's zero clearance, the case the speed targets
#: were set on; ``lubricated_operating_clearance`` is the shipped variant, whose ring drops through 69.5 µm onto its
#: rollers when the load is applied at t = 0: an impact transient in the error window.
MODELS = {
    "lubricated": ["scenario.variant=lubricated", "bearing.diametral_clearance=0"],
    "dry": ["scenario.variant=dry"],
    "lubricated_operating_clearance": ["scenario.variant=lubricated"],
}
#: The settings run on the operating clearance (all settings run on the others).
OPERATING_CLEARANCE_SETTINGS = ("baseline", "exudyn_generalized_alpha_analytic_5e-5",
                                "exudyn_generalized_alpha_analytic_1e-5_newton_1e-3",
                                "exudyn_generalized_alpha_analytic_rho0.3_1e-4", "reference_generalized_alpha_1e-5",
                                "reference_generalized_alpha_2e-5", "reference_generalized_alpha_rho0.3_5e-5",
                                "reference_generalized_alpha_rho0.3_1e-4", "reference_generalized_alpha_adaptive_1e-8",
                                "document")


#: The model whose work–precision tables this benchmark writes.
MODEL = "cylindrical_roller"
REPOSITORY = Path(__file__).resolve().parents[1]
SCENARIO = SCENARIOS / "seed_hss_steady.toml"


def load(model: str, overrides: list[str]):
    """The spec of ``model`` with the benchmark's common settings and ``overrides``."""
    return load_spec(SCENARIO, [*MODELS[model], *COMMON, *overrides])


def spec_of(model: str, overrides: list[str]):
    spec = load(model, overrides)
    return spec, build_scene(spec)


def settings_of(model: str) -> dict:
    if model == "lubricated_operating_clearance":
        return {name: SETTINGS[name] for name in OPERATING_CLEARANCE_SETTINGS}
    return SETTINGS


def fine_reference(model: str):
    """The scenario's own fine reference run over 0 … the window's end (docs/numerics.md)."""
    spec, scene = spec_of(model, [])
    run = spec.convergence.reference
    setting = (None, run.tolerances[0]) if run.adaptive else (run.steps[0], None)
    return run_setting(spec, scene, run, *setting)


def revolution(spec, scene):
    """One revolution after a warm-up (compilation and caches), run twice: the faster run, the less disturbed by
    the shared machine's other load (the runs are deterministic, so only their wall times differ)."""
    simulate(scene, spec.solver, 2e-4)
    return min((simulate(scene, spec.solver, REVOLUTION) for _ in range(REPEATS)), key=lambda r: r.stats.wall_time_s)


def measure(model: str, overrides: list[str], truth, slip_bound: float) -> dict:
    spec, scene = spec_of(model, overrides)
    result = revolution(spec, scene)
    stats = result.stats
    norms = errors(spec, scene, result, truth) if result.success else {}
    return {
        "model": model,
        "settings": to_mapping(spec.solver.active),
        "status": result.status,
        "wall_time_s_per_revolution": stats.wall_time_s,
        "cage_speed_error": norms.get("cage_speed", math.nan),
        "slip_error": norms.get("slips", math.nan),
        "slips_converged": bool(norms.get("slips", math.inf) <= slip_bound),
        "steps": stats.steps,
        "rejected_steps": stats.rejected_steps,
        "newton_iterations": stats.newton_iterations,
        "jacobian_evaluations": stats.jacobian_evaluations,
        "force_evaluations": stats.force_evaluations,
        "microseconds_per_step": stats.wall_time_s / max(stats.steps, 1) * 1e6,
    }


def sound(run: dict, error: float = TARGET_ERROR) -> bool:
    return run["status"] == "success" and run["slips_converged"] and run["cage_speed_error"] <= error


def cheapest(runs: dict, model: str, error: float = TARGET_ERROR, prefix: str = "") -> str | None:
    """The cheapest sound run of ``model`` other than the document's scheme (whose name starts with ``prefix``)
    within ``error``; None if none is."""
    candidates = [name for name, run in runs.items()
                  if run["model"] == model and name.split("/")[-1].startswith(prefix) and sound(run, error)
                  and name.split("/")[-1] != "document"]
    return min(candidates, key=lambda name: runs[name]["wall_time_s_per_revolution"], default=None)


def speed_up(runs: dict, slow: str, fast: str | None) -> float | None:
    if fast is None:
        return None
    return runs[slow]["wall_time_s_per_revolution"] / runs[fast]["wall_time_s_per_revolution"]


def key_of(model: str, name: str) -> str:
    return name if model == next(iter(MODELS)) else f"{model}/{name}"


def summarize(runs: dict, model: str) -> dict:
    best = cheapest(runs, model)
    best_exudyn = cheapest(runs, model, prefix="exudyn_generalized_alpha_analytic")
    best_reference = cheapest(runs, model, prefix="reference_")
    baseline = key_of(model, "baseline")
    summary = {
        "best": best,
        "best_wall_time_s_per_revolution": runs[best]["wall_time_s_per_revolution"] if best else None,
        "best_exudyn_analytic": best_exudyn,
        "best_reference": best_reference,
        "speed_up_best_over_baseline": speed_up(runs, baseline, best),
        "speed_up_exudyn_analytic_over_baseline": speed_up(runs, baseline, best_exudyn),
        "exudyn_best_over_reference_best": speed_up(runs, best_exudyn, best_reference) if best_exudyn else None,
    }
    document = key_of(model, "document")
    if document in runs:
        at_document_error = cheapest(runs, model, error=runs[document]["cage_speed_error"])
        summary |= {"best_at_document_error": at_document_error,
                    "speed_up_over_document_at_its_error": speed_up(runs, document, at_document_error),
                    "speed_up_best_over_document": speed_up(runs, document, best)}
    return summary


def scaled_bearing(model: str, rollers: int) -> list[str]:
    """The seed bearing of ``model`` with ``rollers`` rollers of the same size, its pitch circle (and rings, cage
    and load) scaled by Z/15, so the rollers' spacing and loads are the seed bearing's; its raceways given as the
    model's are (by pitch and clearance, or by their diameters)."""
    k = rollers / 15
    pitch = 0.235 * k
    bearing = load(model, []).bearing
    raceways = [f"bearing.pitch_diameter={pitch}"] if bearing.diametral_clearance is not None else [
        f"bearing.inner_race_diameter={pitch - 0.025}", f"bearing.outer_race_diameter={pitch + 0.025}"]
    return [f"bearing.rollers={rollers}", *raceways, f"bearing.cage_diameter={pitch + 0.010}",
            f"bearing.inner_ring_bore={pitch - 0.075}", f"load.radial={68000.0 * k}"]


def scaling(model: str, overrides: list[str]) -> dict:
    figures = {}
    for rollers in (15, 30, 60):
        spec, scene = spec_of(model, [*overrides, *scaled_bearing(model, rollers)])
        result = revolution(spec, scene)
        stats = result.stats
        figures[str(rollers)] = {"status": result.status, "wall_time_s_per_revolution": stats.wall_time_s,
                                 "steps": stats.steps, "coordinates": scene.coordinate_count,
                                 "newton_iterations": stats.newton_iterations,
                                 "jacobian_evaluations": stats.jacobian_evaluations,
                                 "force_evaluations": stats.force_evaluations,
                                 "microseconds_per_force_evaluation": stats.wall_time_s / stats.force_evaluations * 1e6}
    counts = np.log([15, 30, 60])

    def exponent(key):
        return float(np.polyfit(counts, np.log([figures[z][key] for z in ("15", "30", "60")]), 1)[0])

    # the cost per revolution, and per force evaluation (the work of the algorithm, apart from how many
    # evaluations and Jacobians the contact events of more rollers ask for)
    return {"model": model, "overrides": overrides, "rollers": figures,
            "cost_exponent_in_rollers": exponent("wall_time_s_per_revolution"),
            "cost_per_evaluation_exponent_in_rollers": exponent("microseconds_per_force_evaluation")}


def git(*arguments: str) -> str:
    return subprocess.run(["git", *arguments], cwd=REPOSITORY, capture_output=True, text=True, check=True).stdout.strip()


def commit() -> dict:
    """The commit the measurement runs on, and whether the work tree differs from it."""
    return {"commit": git("rev-parse", "HEAD"), "work_tree_modified": bool(git("status", "--porcelain", "--",
                                                                             "bearing_mbs"))}


def tables(report: dict, command: str) -> Path:
    """The bearing model's work–precision tables from ``report`` (this benchmark's figures), written where its
    model record says (:class:`bearing_mbs.models.protocol.WorkPrecisionData`)."""
    provenance = {"date": report["machine"]["date"], "machine": report["machine"], "command": command,
                  **report.get("measured_at", {})}
    written = []
    for model in MODELS:
        spec = load(model, [])
        reference = spec.convergence.reference
        settings = []
        for name, overrides in settings_of(model).items():
            run = report["runs"][key_of(model, name)]
            solver = load(model, overrides).solver
            section = run.get("settings") or to_mapping(solver.active)
            engine = solver.engine
            settings.append(MeasuredSetting(
                name=name, engine=engine, settings=section, cage_speed_error=run["cage_speed_error"],
                slips_converged=run["slips_converged"], status=run["status"],
                cost=run["wall_time_s_per_revolution"] / REVOLUTION))
        fine = report["fine_references"][model]
        measured_on = {
            "scenario": spec.scenario.name, "variant": model, "speed_rpm": spec.drive.speed_rpm,
            "radial_load_N": spec.load.radial, "simulated_s": [0.0, REVOLUTION],
            "error_window_s": fine["error_window_s"],
            "reference": f"{reference.engine} {reference.method} at {reference.steps[0]:g} s",
            "slip_error_bound": fine["slip_error_bound"],
            "cost": "the faster of two runs' wall time per simulated second, compilation excluded",
        }
        written.append(WorkPrecisionTable(model, measured_on, provenance, tuple(settings)))
    path = REGISTERED_MODELS[MODEL].work_precision.path
    write_tables(path, written, "Measured work-precision tables of the cylindrical roller bearing, one per variant "
                                "(written by benchmarks/bench_revolution.py; do not edit by hand)")
    print(f"wrote {path}")
    return path


def tables_from_file() -> Path:
    """The tables from the last measurement (benchmarks/out/bearing_revolution.json), without measuring. For a report
    from before the commit was recorded, the provenance names the commit that holds its figures and the commits
    that changed the scenario since (the tables then describe the scenario as it was)."""
    path = OUT / "bearing_revolution.json"
    report = json.loads(path.read_text())
    if "measured_at" not in report:
        committed = git("log", "-1", "--format=%H", "--", str(path.relative_to(REPOSITORY)))
        changed = git("log", "--format=%h", f"{committed}..HEAD", "--", str(SCENARIO.relative_to(REPOSITORY)))
        report["measured_at"] = {"commit": None, "figures_committed_in": committed,
                                 "scenario_changed_since_by": changed.split()}
    return tables(report, "python benchmarks/bench_revolution.py --table-only")


def main() -> dict:
    report = {
        "case": "seed_hss_steady, one shaft revolution (0.04 s) from the start; lubricated (constraint cage) at zero "
                "clearance, dry (penalty cage), lubricated at the operating clearance",
        "target_cage_speed_error": TARGET_ERROR,
        "measured_at": commit(),
        "fine_references": {},
        "runs": {},
    }
    runs = report["runs"]
    for model in MODELS:
        truth = fine_reference(model)
        spec, scene = spec_of(model, [])
        largest = reference_scales(spec, scene, truth)["reference_largest_slip"]
        slip_bound = sound_slip_bound(largest)
        report["fine_references"][model] = {
            "wall_time_s": truth.stats.wall_time_s, "steps": truth.stats.steps,
            "error_window_s": [spec.convergence.start, spec.convergence.end], "largest_slip_ratio": largest,
            "slip_error_bound": slip_bound}
        for name, overrides in settings_of(model).items():
            key = key_of(model, name)
            runs[key] = measure(model, overrides, truth, slip_bound)
            write("bearing_revolution", report)  # what is measured is kept, whatever happens next
            print(key, {k: runs[key][k] for k in ("status", "wall_time_s_per_revolution", "cage_speed_error",
                                                  "slips_converged")})
    summary = report["summary"] = {model: summarize(runs, model) for model in MODELS}
    lubricated = summary["lubricated"]
    report["targets"] = {
        "best_wall_time_s_per_revolution": {"value": lubricated["best_wall_time_s_per_revolution"],
                                            "target": "<= 0.04"},
        "best_over_baseline": {"value": lubricated["speed_up_best_over_baseline"], "target": ">= 50"},
        "exudyn_best_over_reference_best": {"value": lubricated["exudyn_best_over_reference_best"],
                                            "target": "<= 2.5"},
        "exudyn_best_over_baseline": {"value": lubricated["speed_up_exudyn_analytic_over_baseline"],
                                      "target": ">= 20"},
    }
    write("bearing_revolution", report)
    tables({**report, "machine": machine()}, "python benchmarks/bench_revolution.py")
    report["scaling"] = {}
    for model in ("lubricated", "dry"):  # the lubricated model's constraint cage against the dry model's penalty cage
        if summary[model]["best"] is not None:
            report["scaling"][model] = scaling(model, SETTINGS[summary[model]["best"].split("/")[-1]])
            write("bearing_revolution", report)
    return report


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--table-only", action="store_true",
                        help="write the work-precision tables from benchmarks/out/bearing_revolution.json, no runs")
    tables_from_file() if parser.parse_args().table_only else main()
