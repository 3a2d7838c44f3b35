"""Subcommands that run or solve one scenario, or a sensitivity study: ``run``, ``stiffness``, ``advise`` and
``sweep``."""

from __future__ import annotations

import logging
import sys

from bearing_mbs.cli.options import add_overrides, load_with_engine
from bearing_mbs.models import load_spec
from bearing_mbs.spec import SpecError


def register(commands) -> dict:
    """Add the subcommands to ``commands`` (argparse subparsers); returns {name: handler}."""
    _add_run(commands)
    _add_sweep(commands)
    _add_stiffness(commands)
    _add_advise(commands)
    return {"run": _run, "sweep": _sweep, "stiffness": _stiffness, "advise": _advise}


def _add_run(commands) -> None:
    run = commands.add_parser("run", help="run one scenario and write summary.json, result.npz and figures")
    run.add_argument("scenario", help="scenario TOML file (see docs/scenario-format.md)")
    run.add_argument("--out", required=True, help="output directory")
    run.add_argument("--engine", choices=("exudyn", "reference"), help="override [solver] engine")
    add_overrides(run)
    run.add_argument("--no-figures", action="store_true", help="skip the PNG figures")
    run.add_argument("--animate", action="store_true", help="also write DIR/animation.gif (bearing model)")
    run.add_argument("--quiet", action="store_true", help="no progress bar")


def _run(args) -> int:
    from bearing_mbs.core.progress import ProgressMeter, TqdmProgress
    from bearing_mbs.runner import run_spec, write_outputs

    spec = load_with_engine(args)
    if args.animate and spec.scenario.model != "bearing":
        raise SpecError("scenario.model", spec.scenario.model, "--animate draws the bearing model only")
    scene, result = run_spec(spec, ProgressMeter() if args.quiet else TqdmProgress())
    summary = write_outputs(spec, scene, result, args.out, figures=not args.no_figures)
    if args.animate:
        from pathlib import Path

        from bearing_mbs.models.cylindrical_roller.figures import animate

        animate(spec, scene, result, Path(args.out) / "animation.gif")
    print(f"{summary['scenario']}: {summary['status']} ({summary['engine']} {summary['solver']}, "
          f"{summary['steps']} steps, {summary['wall_time_s']:.3g} s) -> {args.out}")
    if not result.success:
        print(f"stopped: {result.message}", file=sys.stderr)
        return 1
    return 0


def _add_sweep(commands) -> None:
    sweep = commands.add_parser("sweep", help="run a sensitivity study (grid, Latin hypercube, Morris, Sobol) on Dask")
    sweep.add_argument("study", help="study TOML file (see docs/sensitivity.md)")
    sweep.add_argument("--out", required=True, help="output directory: run store and report; re-running resumes")
    sweep.add_argument("--scheduler", metavar="ADDRESS", help="Dask scheduler address (default: a local cluster)")
    sweep.add_argument("--workers", type=int, metavar="N",
                       help="local cluster size (default: one per CPU), or workers to wait for on --scheduler")
    add_overrides(sweep, "override a study-file field, e.g. method.samples=4 (repeatable)")
    sweep.add_argument("--retry-errors", action="store_true", help="run stored runs that ended in an error again")
    sweep.add_argument("--no-figures", action="store_true", help="report without PNG figures")
    sweep.add_argument("--quiet", action="store_true", help="no progress bar")


def _sweep(args) -> int:
    """Exit 0: every run succeeded; 1: some runs errored or stopped early (all are recorded, the report is
    written); 2: bad input, nothing ran."""
    import distributed  # noqa: F401  (configures its loggers on import; quieten them after)

    from bearing_mbs.core.progress import ProgressMeter
    from bearing_mbs.studies.sensitivity import TqdmRunProgress, load_study, run_study

    logging.getLogger("distributed").setLevel(logging.WARNING)
    study = load_study(args.study, args.set)
    result = run_study(study, args.out, scheduler=args.scheduler, workers=args.workers,
                       progress=ProgressMeter() if args.quiet else TqdmRunProgress(),
                       retry_errors=args.retry_errors, figures=not args.no_figures)
    counts = result.table.drop_duplicates("key")["status"].value_counts()
    print(f"{study.name}: {len(result.table)} samples, {result.stats.evaluated} runs evaluated now, "
          f"{result.stats.skipped} already stored; {', '.join(f'{n} {s}' for s, n in counts.items())} "
          f"-> {result.report}")
    return 0 if result.complete else 1


def _add_stiffness(commands) -> None:
    stiffness = commands.add_parser(
        "stiffness", help="quasi-static load distribution and 2x2 stiffness of a bearing scenario (no simulation)")
    stiffness.add_argument("scenario", help="bearing scenario TOML file (model = 'bearing')")
    stiffness.add_argument("--out", required=True, help="output directory: summary.json and load_distribution.png")
    add_overrides(stiffness)
    stiffness.add_argument("--no-figures", action="store_true", help="skip the PNG figure")


def _stiffness(args) -> int:
    """Exit 0: solved and written; 2: bad input, or a load the bearing cannot carry (nothing written)."""
    from bearing_mbs.models.cylindrical_roller.stiffness import require_bearing, write_stiffness

    spec = load_spec(args.scenario, args.set)
    require_bearing(spec)
    summary = write_stiffness(spec, args.out, figures=not args.no_figures)
    print(f"{summary['scenario']}: displacement {summary['radial_displacement']:.4g} m, max roller load "
          f"{summary['max_roller_load']:.4g} N, K_xx {summary['stiffness_matrix'][0][0]:.4g} N/m, "
          f"K_yy {summary['stiffness_matrix'][1][1]:.4g} N/m -> {args.out}")
    return 0


def _add_advise(commands) -> None:
    advise = commands.add_parser("advise", help="estimate each explicit solver's stability limit and advise a step")
    advise.add_argument("scenario", help="scenario TOML file")
    add_overrides(advise)
    advise.add_argument("--engine", choices=("exudyn", "reference"), help="override [solver] engine")
    advise.add_argument("--check-slip", action="store_true",
                        help="also run the scenario at its step and at half of it and report spurious slip")
    advise.add_argument("--json", action="store_true", help="print the advice as JSON")


def _advise(args) -> int:
    """Exit 0: advice printed (and, with --check-slip, the slip converged); 1: spurious slip found; 2: bad input."""
    import json

    from bearing_mbs.models import build_scene
    from bearing_mbs.numerics.advisor import advise

    spec = load_with_engine(args)
    scene = build_scene(spec)
    advice = advise(scene)
    print(json.dumps(advice.to_dict(), indent=2) if args.json else advice.report())
    if advice.applies and not args.json:
        from bearing_mbs.numerics.advisor import step_warning

        settings = spec.solver.active
        what = f"tolerance {settings.tolerance:g}" if settings.adaptive else f"step {settings.step:g} s"
        warning = step_warning(scene, spec.solver)
        print(f"\nthis scenario: {spec.solver.engine} {settings.method}, {what}: "
              + (f"WARNING {warning}" if warning else "within the advice"))
    if not args.check_slip:
        return 0
    from bearing_mbs.studies.spurious_slip import check_spurious_slip

    check = check_spurious_slip(scene, spec.solver, spec.scenario.end_time)
    print(("spurious slip: " if check.spurious else "") + check.message)
    return 1 if check.spurious else 0
