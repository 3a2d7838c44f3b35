"""The ``bearing-mbs`` command.

``bearing-mbs run SCENARIO.toml --out DIR [--engine exudyn|reference] [--set section.key=value ...]``
``bearing-mbs sweep STUDY.toml --out DIR [--scheduler ADDRESS] [--workers N]`` (docs/sensitivity.md)

Exit status: 0 when the run succeeded, 1 when it stopped early (its summary and result are still
written), 2 for bad input (nothing runs).
"""

from __future__ import annotations

import argparse
import logging
import sys

from .spec import SpecError, load_spec


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(prog="bearing-mbs", description=__doc__.splitlines()[0])
    commands = parser.add_subparsers(dest="command", required=True)

    run = commands.add_parser("run", help="run one scenario and write summary.json, result.npz and figures")
    run.add_argument("scenario", help="scenario TOML file (see docs/scenario-format.md)")
    run.add_argument("--out", required=True, help="output directory")
    run.add_argument("--engine", choices=("exudyn", "reference"), help="override [solver] engine")
    run.add_argument("--set", action="append", default=[], metavar="SECTION.KEY=VALUE",
                     help="override any spec field, validated like the file (repeatable)")
    run.add_argument("--no-figures", action="store_true", help="skip the PNG figures")
    run.add_argument("--quiet", action="store_true", help="no progress bar")

    _add_sweep(commands)

    args = parser.parse_args(argv)
    logging.basicConfig(level=logging.INFO, format="%(levelname)s %(name)s: %(message)s")
    try:
        return _sweep(args) if args.command == "sweep" else _run(args)
    except SpecError as error:
        print(f"error: {error}", file=sys.stderr)
        return 2


def _run(args) -> int:
    from .progress import ProgressMeter, TqdmProgress
    from .runner import run_spec, write_outputs

    overrides = list(args.set) + ([f"solver.engine={args.engine}"] if args.engine else [])
    spec = load_spec(args.scenario, overrides)
    scene, result = run_spec(spec, ProgressMeter() if args.quiet else TqdmProgress())
    summary = write_outputs(spec, scene, result, args.out, figures=not args.no_figures)
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
    sweep.add_argument("--set", action="append", default=[], metavar="SECTION.KEY=VALUE",
                       help="override a study-file field, e.g. method.samples=4 (repeatable)")
    sweep.add_argument("--retry-errors", action="store_true", help="run stored runs that ended in an error again")
    sweep.add_argument("--no-figures", action="store_true", help="report without PNG figures")
    sweep.add_argument("--quiet", action="store_true", help="no progress bar")


def _sweep(args) -> int:
    """Exit 0: every run succeeded; 1: some runs errored or stopped early (all are recorded, the report is
    written); 2: bad input, nothing ran."""
    import distributed  # noqa: F401  (configures its loggers on import; quieten them after)

    from .progress import ProgressMeter
    from .studies.sensitivity import TqdmRunProgress, load_study, run_study

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


if __name__ == "__main__":
    sys.exit(main())
