"""The ``bearing-mbs`` command.

``bearing-mbs run SCENARIO.toml --out DIR [--engine exudyn|reference] [--set section.key=value ...]``
``bearing-mbs sweep STUDY.toml --out DIR [--scheduler ADDRESS] [--workers N]`` (docs/sensitivity.md)
``bearing-mbs stiffness SCENARIO.toml --out DIR [--set section.key=value ...]`` (docs/quasistatic.md)
``bearing-mbs convergence SCENARIO.toml --out DIR [--set section.key=value ...]`` (docs/numerics.md)
``bearing-mbs stability SCENARIO.toml --out DIR [--reduced] [--cases ...] [--solvers ...]`` (docs/numerics.md)
``bearing-mbs advise SCENARIO.toml [--check-slip] [--set section.key=value ...]`` (docs/numerics.md)

Exit status: 0 when the run succeeded, 1 when it stopped early (its summary and result are still
written), 2 for bad input (nothing runs).
"""

from __future__ import annotations

import argparse
import logging
import sys

from bearing_mbs.spec import SpecError
from bearing_mbs.models import load_spec


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(prog="bearing-mbs", description=__doc__.splitlines()[0])
    commands = parser.add_subparsers(dest="command", required=True)

    run = commands.add_parser("run", help="run one scenario and write summary.json, result.npz and figures")
    run.add_argument("scenario", help="scenario TOML file (see docs/scenario-format.md)")
    run.add_argument("--out", required=True, help="output directory")
    run.add_argument("--engine", choices=("exudyn", "reference"), help="override [solver] engine")
    _add_overrides(run)
    run.add_argument("--no-figures", action="store_true", help="skip the PNG figures")
    run.add_argument("--animate", action="store_true", help="also write DIR/animation.gif (bearing model)")
    run.add_argument("--quiet", action="store_true", help="no progress bar")

    _add_sweep(commands)
    _add_stiffness(commands)
    _add_convergence(commands)
    _add_stability(commands)
    _add_advise(commands)

    args = parser.parse_args(argv)
    logging.basicConfig(level=logging.INFO, format="%(levelname)s %(name)s: %(message)s")
    try:
        return {"run": _run, "sweep": _sweep, "stiffness": _stiffness, "convergence": _convergence,
                "stability": _stability, "advise": _advise}[args.command](args)
    except SpecError as error:
        print(f"error: {error}", file=sys.stderr)
        return 2


def _run(args) -> int:
    from bearing_mbs.core.progress import ProgressMeter, TqdmProgress
    from bearing_mbs.runner import run_spec, write_outputs

    spec = _load_with_engine(args)
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


def _add_overrides(parser, what: str = "override any spec field, validated like the file (repeatable)") -> None:
    """The repeatable ``--set SECTION.KEY=VALUE`` option every subcommand shares."""
    parser.add_argument("--set", action="append", default=[], metavar="SECTION.KEY=VALUE", help=what)


def _load_with_engine(args):
    """The scenario with its ``--set`` overrides, and ``--engine`` as ``solver.engine`` when given."""
    return load_spec(args.scenario, list(args.set) + ([f"solver.engine={args.engine}"] if args.engine else []))


def _add_sweep(commands) -> None:
    sweep = commands.add_parser("sweep", help="run a sensitivity study (grid, Latin hypercube, Morris, Sobol) on Dask")
    sweep.add_argument("study", help="study TOML file (see docs/sensitivity.md)")
    sweep.add_argument("--out", required=True, help="output directory: run store and report; re-running resumes")
    sweep.add_argument("--scheduler", metavar="ADDRESS", help="Dask scheduler address (default: a local cluster)")
    sweep.add_argument("--workers", type=int, metavar="N",
                       help="local cluster size (default: one per CPU), or workers to wait for on --scheduler")
    _add_overrides(sweep, "override a study-file field, e.g. method.samples=4 (repeatable)")
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
    _add_overrides(stiffness)
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


def _add_convergence(commands) -> None:
    convergence = commands.add_parser(
        "convergence", help="work-precision study: error against run time for the settings in [convergence]")
    convergence.add_argument("scenario", help="scenario TOML file with a [convergence] section")
    convergence.add_argument("--out", required=True, help="output directory; re-running skips finished runs")
    _add_overrides(convergence, "override any spec field (repeatable)")
    convergence.add_argument("--quiet", action="store_true", help="no progress bar")


def _convergence(args) -> int:
    from bearing_mbs.core.progress import ProgressMeter, TqdmProgress
    from bearing_mbs.studies.convergence import study

    summary = study(load_spec(args.scenario, args.set), args.out, ProgressMeter() if args.quiet else TqdmProgress())
    for target, best in summary["cheapest"].items():
        setting = "not reached" if best is None else (
            f"{best['engine']} {best['solver']} step={best['step'] or '-'} tolerance={best['tolerance'] or '-'} "
            f"({float(best['wall_time_s']):.3g} s)")
        print(f"{summary['norm']} error <= {target}: {setting}")
    return 0


def _add_stability(commands) -> None:
    stability = commands.add_parser(
        "stability", help="stability suite: which solver survives stiff and extreme variations, up to which step")
    stability.add_argument("scenario", help="bearing scenario TOML file, the base of the variations")
    stability.add_argument("--out", required=True, help="output directory; re-running skips finished cells")
    stability.add_argument("--reduced", action="store_true", help="the reduced suite of the default tests")
    stability.add_argument("--cases", help="comma-separated case names (default: all; see docs/numerics.md)")
    stability.add_argument("--solvers", help="comma-separated engine/method pairs, e.g. reference/rk4,exudyn/rk44")
    _add_overrides(stability, "override any spec field of the base scenario (repeatable)")
    stability.add_argument("--no-figures", action="store_true", help="skip the heat map")


def _stability(args) -> int:
    """Exit 0: written (failing cells are results, not errors); 2: bad input."""
    from bearing_mbs.studies import stability

    cases = stability.REDUCED_CASES if args.reduced else stability.CASE_NAMES
    solvers = stability.REDUCED_SOLVERS if args.reduced else stability.SOLVERS
    if args.cases:
        cases = tuple(name.strip() for name in args.cases.split(","))
    if args.solvers:
        solvers = tuple(tuple(item.strip().split("/", 1)) for item in args.solvers.split(","))
        for item in solvers:
            if len(item) != 2:
                raise SpecError("--solvers", "/".join(item), "must be engine/method pairs")
    logging.getLogger("bearing_mbs.engines").setLevel(logging.ERROR)  # the probes exceed the advice on purpose
    summary = stability.study(load_spec(args.scenario, args.set), args.out, cases=cases, solvers=solvers,
                              figures=not args.no_figures)
    fraction = summary["fraction_within_factor_2"]
    print(f"{summary['scenario']}: {summary['cells']} cells; advisor within a factor of 2 of the measured limit in "
          f"{summary['within_factor_2']} of {summary['explicit_cells_measured']} explicit cells"
          + (f" ({100 * fraction:.0f} %)" if fraction is not None else "") + f" -> {args.out}")
    return 0


def _add_advise(commands) -> None:
    advise = commands.add_parser("advise", help="estimate each explicit solver's stability limit and advise a step")
    advise.add_argument("scenario", help="scenario TOML file")
    _add_overrides(advise)
    advise.add_argument("--engine", choices=("exudyn", "reference"), help="override [solver] engine")
    advise.add_argument("--check-slip", action="store_true",
                        help="also run the scenario at its step and at half of it and report spurious slip")
    advise.add_argument("--json", action="store_true", help="print the advice as JSON")


def _advise(args) -> int:
    """Exit 0: advice printed (and, with --check-slip, the slip converged); 1: spurious slip found; 2: bad input."""
    import json

    from bearing_mbs.numerics.advisor import advise
    from bearing_mbs.models import build_scene

    spec = _load_with_engine(args)
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


if __name__ == "__main__":
    sys.exit(main())
