"""Subcommands that run one scenario of any model, or a sensitivity study: ``run``, ``advise`` and ``sweep``."""

from __future__ import annotations

import logging
import sys

from bearing_mbs.cli.options import (
    add_output,
    add_overrides,
    exit_code,
    load_with_engine,
    output_directory,
    progress_meter,
)


def register(commands) -> dict:
    """Add the subcommands to ``commands`` (argparse subparsers); returns {name: handler}."""
    _add_run(commands)
    _add_sweep(commands)
    _add_advise(commands)
    return {"run": _run, "sweep": _sweep, "advise": _advise}


def _add_run(commands) -> None:
    run = commands.add_parser("run", help="run one scenario and write summary.json, result.npz and figures")
    run.add_argument("scenario", help="scenario TOML file (see docs/scenario-format.md)")
    add_output(run, "output directory (new or empty, or give --overwrite)")
    run.add_argument("--engine", choices=("exudyn", "reference"), help="override [solver] engine")
    add_overrides(run)
    run.add_argument("--check-slip", action="store_true",
                     help="also run at half the step and add the spurious-slip check (twice the cost)")
    run.add_argument("--no-figures", action="store_true", help="skip the PNG figures")
    run.add_argument("--animate", action="store_true",
                     help="also write DIR/animation.gif (models with an animation: the cylindrical roller bearing)")
    run.add_argument("--quiet", action="store_true", help="no progress bar")


def _run(args) -> int:
    """Exit 0: success; 3: suspect (a check failed); 1: failed (stopped early); 130/143: interrupted by SIGINT/
    SIGTERM (set by :func:`bearing_mbs.cli.main`); 2: bad input, nothing ran. Whatever was computed is written in
    every case but bad input."""
    from bearing_mbs.core.interrupt import stop_requested
    from bearing_mbs.models import MODELS
    from bearing_mbs.runner import run_spec, spec_for_run, write_outputs

    spec = load_with_engine(args)
    animate = MODELS.part(spec.scenario.model, "animate", "an animation", "--animate") if args.animate else None
    directory = output_directory(args)
    scene, result = run_spec(spec, progress_meter(args.quiet))
    run_as, choice = spec_for_run(spec, scene)  # the settings [solver] tolerance chose, if set
    if args.check_slip and result.completed and not stop_requested():
        from bearing_mbs.studies.spurious_slip import check_spurious_slip

        slip = check_spurious_slip(scene, run_as.solver, spec.scenario.end_time, result)
        result.checks = (*result.checks, slip.to_check())
    summary = write_outputs(spec, scene, result, directory, figures=not args.no_figures)
    if args.animate and result.completed:
        animate(spec, scene, result, directory / "animation.gif")
    if choice is not None:
        print(choice.text())
    print(f"{summary['scenario']}: {summary['status']} ({summary['engine']} {summary['solver']}, "
          f"{summary['steps']} steps, {summary['wall_time_s']:.3g} s) -> {summary['written_to']}")
    if result.message:
        print(f"stopped: {result.message}", file=sys.stderr)
    for check in result.failed_checks:
        print(f"check {check.line()}", file=sys.stderr)
    passed = sum(check.passed for check in result.checks)
    if result.checks:
        print(f"checks: {passed} of {len(result.checks)} passed")
    return exit_code(result.status)


def _add_sweep(commands) -> None:
    sweep = commands.add_parser("sweep", help="run a sensitivity study (grid, Latin hypercube, Morris, Sobol) on Dask")
    sweep.add_argument("study", help="study TOML file (see docs/sensitivity.md)")
    add_output(sweep, "output directory: run store and report; re-running resumes", resumes=True)
    sweep.add_argument("--scheduler", metavar="ADDRESS", help="Dask scheduler address (default: a local cluster)")
    sweep.add_argument("--workers", type=int, metavar="N",
                       help="local cluster size (default: one per CPU), or workers to wait for on --scheduler")
    add_overrides(sweep, "override a study-file field, e.g. method.samples=4 (repeatable)")
    sweep.add_argument("--retry-errors", action="store_true", help="run stored runs that ended in an error again")
    sweep.add_argument("--no-figures", action="store_true", help="report without PNG figures")
    sweep.add_argument("--quiet", action="store_true", help="no progress bar")


def _sweep(args) -> int:
    """Exit 0: every run succeeded; 3: some are suspect; 1: some errored or stopped early (all are recorded,
    the report is written); 130/143: interrupted; 2: bad input, nothing ran. The study's status is its worst
    run's (docs/status.md)."""
    import distributed  # noqa: F401  (configures its loggers on import; quieten them after)

    from bearing_mbs.core.progress import ProgressMeter, TqdmRunProgress
    from bearing_mbs.studies.sensitivity import load_study, run_study

    logging.getLogger("distributed").setLevel(logging.WARNING)
    study = load_study(args.study, args.set)
    output_directory(args)
    result = run_study(study, args.out, scheduler=args.scheduler, workers=args.workers,
                       progress=ProgressMeter() if args.quiet else TqdmRunProgress(),
                       retry_errors=args.retry_errors, figures=not args.no_figures)
    counts = result.table.drop_duplicates("key")["status"].value_counts()
    print(f"{study.name}: {len(result.table)} samples, {result.stats.evaluated} runs evaluated now, "
          f"{result.stats.skipped} already stored; {', '.join(f'{n} {s}' for s, n in counts.items())}; "
          f"status {result.status} -> {result.report}")
    return exit_code(result.status)


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
    print(f"check {check.to_check().line()}" + ("" if check.spurious else f": {check.message}"))
    return 1 if check.spurious else 0
