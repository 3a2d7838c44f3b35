"""Subcommands of the studies: ``convergence``, ``numerics-report``, ``stability``, ``static-check``,
``skidding``, ``skidding-map`` and ``cage-models``."""

from __future__ import annotations

from bearing_mbs.cli.options import add_output, add_overrides, exit_code, names, numbers, output_directory
from bearing_mbs.models import load_spec
from bearing_mbs.spec import SpecError


def register(commands) -> dict:
    """Add the subcommands to ``commands`` (argparse subparsers); returns {name: handler}."""
    _add_convergence(commands)
    _add_stability(commands)
    _add_numerics_report(commands)
    _add_static_check(commands)
    _add_skidding(commands)
    _add_skidding_map(commands)
    _add_cage_models(commands)
    return {"convergence": _convergence, "stability": _stability, "numerics-report": _numerics_report,
            "static-check": _static_check, "skidding": _skidding, "skidding-map": _skidding_map,
            "cage-models": _cage_models}


def _add_convergence(commands) -> None:
    convergence = commands.add_parser(
        "convergence", help="work-precision study: error against run time for the settings in [convergence]")
    convergence.add_argument("scenario", help="scenario TOML file with a [convergence] section")
    add_output(convergence, "output directory; re-running skips finished runs", resumes=True)
    add_overrides(convergence, "override any spec field (repeatable)")
    convergence.add_argument("--quiet", action="store_true", help="no progress bar")


def _convergence(args) -> int:
    from bearing_mbs.core.progress import ProgressMeter, TqdmProgress
    from bearing_mbs.studies.convergence import study

    spec = load_spec(args.scenario, args.set)
    summary = study(spec, output_directory(args), ProgressMeter() if args.quiet else TqdmProgress())
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
    add_output(stability, "output directory; re-running skips finished cells", resumes=True)
    stability.add_argument("--reduced", action="store_true", help="the reduced suite of the default tests")
    stability.add_argument("--cases", help="comma-separated case names (default: all; see docs/numerics.md)")
    stability.add_argument("--solvers", help="comma-separated engine/method pairs, e.g. reference/rk4,exudyn/rk4")
    add_overrides(stability, "override any spec field of the base scenario (repeatable)")
    stability.add_argument("--no-figures", action="store_true", help="skip the heat map")


def _stability(args) -> int:
    """Exit 0: written (failing cells are results, not errors); 2: bad input."""
    from bearing_mbs.studies import stability

    cases = stability.REDUCED_CASES if args.reduced else stability.CASE_NAMES
    solvers = stability.REDUCED_SOLVERS if args.reduced else stability.SOLVERS
    if args.cases:
        cases = names(args.cases)
        for name in cases:
            if name not in stability.CASE_NAMES:
                raise SpecError("--cases", name, f"case names among {', '.join(stability.CASE_NAMES)}")
    if args.solvers:
        solvers = _solver_pairs(args.solvers)
    spec = load_spec(args.scenario, args.set)
    summary = stability.study(spec, output_directory(args), cases=cases, solvers=solvers,
                              figures=not args.no_figures)
    fraction = summary["fraction_within_factor_2"]
    print(f"{summary['scenario']}: {summary['cells']} cells; advisor within a factor of 2 of the measured limit in "
          f"{summary['within_factor_2']} of {summary['explicit_cells_measured']} explicit cells"
          + (f" ({100 * fraction:.0f} %)" if fraction is not None else "") + f" -> {args.out}")
    return 0


def _solver_pairs(text: str) -> tuple[tuple[str, str], ...]:
    """``--solvers`` as (engine, method) pairs, each an engine and one of its methods."""
    from bearing_mbs.spec import methods as catalogue

    known = {engine: catalogue.names(engine) for engine in catalogue.ENGINE_METHODS}
    pairs = []
    for item in names(text):
        engine, _, method = item.partition("/")
        if method not in known.get(engine, ()):
            raise SpecError("--solvers", item, "engine/method pairs among "
                            + ", ".join(f"{e}/{m}" for e, methods in known.items() for m in methods))
        pairs.append((engine, method))
    return tuple(pairs)


def _add_numerics_report(commands) -> None:
    report = commands.add_parser(
        "numerics-report", help="figure and tables of cheapest sound settings from a convergence study's results")
    report.add_argument("study", help="output directory of a bearing-mbs convergence study (with convergence.csv)")
    report.add_argument("--name", required=True, help="scenario name for titles and file names")
    add_output(report, "directory for work_precision_NAME.png and .md (new or empty, or give --overwrite)")
    report.add_argument("--norms", default="cage_speed,slips", help="comma-separated norms to plot and tabulate")
    report.add_argument("--document-step", type=float, default=1 / 1.8e6, metavar="H",
                        help="the document's step for its scheme [s], starred (default 1/1.8e6 s)")


def _numerics_report(args) -> int:
    """Exit 0: written; 2: bad input (no convergence.csv, an unknown norm)."""
    from bearing_mbs.studies.numerics_report import run

    norms = names(args.norms)
    print(run(args.study, args.name, output_directory(args), norms, args.document_step))
    return 0


def _add_static_check(commands) -> None:
    check = commands.add_parser(
        "static-check", help="settled dynamic equilibria and stiffness against the quasi-static solution")
    check.add_argument("scenario", help="bearing scenario TOML file (the repository's: scenarios/static_check.toml)")
    add_output(check, "output directory: static_check.json (new or empty, or give --overwrite)")
    check.add_argument("--engines", default="exudyn,reference", help="comma-separated engines to check")
    check.add_argument("--loads", default="5e3,20e3,68e3",
                       help="comma-separated external loads [N] along the scenario's [load] angle")
    check.add_argument("--stiffness-load", type=float, default=20e3, metavar="N",
                       help="load [N] of the finite-difference stiffness (default 20e3)")
    check.add_argument("--no-stiffness", action="store_true", help="skip the finite-difference stiffness")
    add_overrides(check, "override any spec field of the scenario (repeatable)")


def _static_check(args) -> int:
    """Exit 0: every run succeeded and settled; 3: some are suspect (a failed check, or a window that did not
    settle); 1: some run stopped early (all are written); 2: bad input, nothing ran."""
    from bearing_mbs.studies import static_check

    engines = names(args.engines)
    directory = output_directory(args)
    check = static_check.run(args.scenario, numbers("--loads", args.loads), engines, overrides=args.set,
                             stiffness_load=None if args.no_stiffness else args.stiffness_load)
    path = static_check.write(check, directory)
    print(static_check.report(check))
    print(f"-> {path}")
    return exit_code(check.statuses)


def _add_skidding(commands) -> None:
    skidding = commands.add_parser("skidding", help="cage slip against radial load, per cage model")
    skidding.add_argument("scenario", help="bearing scenario TOML file at constant speed, the base of the sweep")
    add_output(skidding, "output directory: skidding_vs_load.{csv,md,png} (new or empty, or give --overwrite)")
    skidding.add_argument("--loads", default="68000,6800,2000,680,200", help="comma-separated radial loads [N]")
    skidding.add_argument("--cages", default="penalty,constraint", help="comma-separated cage models")
    add_overrides(skidding, "override any spec field of the base scenario, e.g. scenario.end_time=0.3 (repeatable)")
    skidding.add_argument("--no-figures", action="store_true", help="skip the PNG figure")
    skidding.add_argument("--quiet", action="store_true", help="no progress bar")


def _skidding(args) -> int:
    """Exit 0: every run succeeded; 3: some are suspect (a failed check, or a window that did not settle); 1: some
    stopped early (all are written); 2: bad input, nothing ran."""
    from bearing_mbs.core.progress import ProgressMeter, TqdmProgress
    from bearing_mbs.studies import skidding

    cages = names(args.cages)
    for name in cages:
        if name not in skidding.CAGES:
            raise SpecError("--cages", name, f"must be among {', '.join(skidding.CAGES)}")
    spec, loads = load_spec(args.scenario, args.set), numbers("--loads", args.loads)
    sweeps = skidding.run(spec, output_directory(args), loads,
                          {name: skidding.CAGES[name] for name in cages}, figures=not args.no_figures,
                          progress=ProgressMeter() if args.quiet else TqdmProgress())
    print(skidding.markdown_table(sweeps))
    print(skidding.trend_text(sweeps) + skidding.status_text(sweeps) + f"-> {args.out}")
    return exit_code([row["status"] for rows in sweeps.values() for row in rows])


def _add_skidding_map(commands) -> None:
    parser = commands.add_parser("skidding-map", help="steady cage and roller slip over load x oil temperature x "
                                 "speed (x clearance), from the quasi-static skidding balance")
    parser.add_argument("scenario", help="lubricated bearing scenario TOML file at constant speed")
    add_output(parser, "output directory: skidding_map.{csv,md,png} and roller_slip.png (new or empty, or give "
                       "--overwrite)")
    parser.add_argument("--loads", default="68000,6800,2000,680,200", help="comma-separated radial loads [N]")
    parser.add_argument("--temperatures", default="40,60,80", help="comma-separated oil temperatures [°C]")
    parser.add_argument("--speeds", default="1000,1500,1800", help="comma-separated shaft speeds [rpm]")
    parser.add_argument("--clearances", default=None,
                        help="comma-separated diametral clearances [m] (bearing.diametral_clearance, about the "
                             "raceways' pitch circle; default: the scenario's own)")
    parser.add_argument("--minimum-load", default=None,
                        help="LOW,HIGH [N]: the catalogue minimum-load band to mark on the figure")
    add_overrides(parser, "override any spec field of the base scenario (repeatable)")
    parser.add_argument("--no-figures", action="store_true", help="skip the PNG figures")
    parser.add_argument("--quiet", action="store_true", help="no progress bar")


def _skidding_map(args) -> int:
    """Exit 0: every point solved; 1: some had no balance (``failed``; all are written); 2: bad input, nothing
    ran."""
    from bearing_mbs.core.progress import ProgressMeter, TqdmProgress
    from bearing_mbs.studies import skidding_map

    band = None
    if args.minimum_load is not None:
        band = numbers("--minimum-load", args.minimum_load)
        if len(band) != 2 or not 0 < band[0] < band[1]:
            raise SpecError("--minimum-load", args.minimum_load, "LOW,HIGH [N] with 0 < LOW < HIGH")
    spec = load_spec(args.scenario, args.set)
    loads, temperatures, speeds = (numbers(name, text) for name, text in (
        ("--loads", args.loads), ("--temperatures", args.temperatures), ("--speeds", args.speeds)))
    clearances = None if args.clearances is None else numbers("--clearances", args.clearances)
    skidding_map.check_grid(spec, loads, temperatures, speeds, clearances)
    rows = skidding_map.run(spec, output_directory(args), loads, temperatures, speeds, band,
                            figures=not args.no_figures, progress=ProgressMeter() if args.quiet else TqdmProgress(),
                            clearances=clearances)
    print(skidding_map.markdown_table(rows) + f"-> {args.out}")
    return exit_code([row["status"] for row in rows])


def _add_cage_models(commands) -> None:
    cages = commands.add_parser("cage-models", help="compare the penalty, constraint and no-cage models")
    cages.add_argument("scenario", help="bearing scenario TOML file, the base of the comparison")
    add_output(cages, "output directory: cage_models.{md,csv} and two figures (new or empty, or give --overwrite)")
    cages.add_argument("--no-roller-guided", action="store_true",
                       help="only the three cage models, without the two roller-guided runs")
    add_overrides(cages, "override any spec field of the base scenario (repeatable)")
    cages.add_argument("--no-figures", action="store_true", help="skip the PNG figures")
    cages.add_argument("--quiet", action="store_true", help="no progress bar")


def _cage_models(args) -> int:
    """Exit 0: every run succeeded; 3: some are suspect (a failed check, or a window that did not settle); 1: some
    stopped early (all are written); 2: bad input, nothing ran."""
    from bearing_mbs.core.progress import ProgressMeter, TqdmProgress
    from bearing_mbs.studies import cage_models

    spec = load_spec(args.scenario, args.set)
    rows = cage_models.run(spec, output_directory(args), roller_guided=not args.no_roller_guided,
                           figures=not args.no_figures, progress=ProgressMeter() if args.quiet else TqdmProgress())
    print(cage_models.markdown_table(rows) + f"status: {cage_models.comparison_status(rows)} -> {args.out}")
    return exit_code([row["status"] for row in rows])
