"""Subcommands of the studies any model may run: ``convergence``, ``numerics-report`` and ``stability``. A model's
own studies are its commands (:attr:`bearing_mbs.models.Model.commands`, :mod:`bearing_mbs.cli.models`)."""

from __future__ import annotations

from bearing_mbs.cli.options import add_output, add_overrides, names, output_directory, progress_meter
from bearing_mbs.models import load_spec
from bearing_mbs.spec import SpecError


def register(commands) -> dict:
    """Add the subcommands to ``commands`` (argparse subparsers); returns {name: handler}."""
    _add_convergence(commands)
    _add_stability(commands)
    _add_numerics_report(commands)
    return {"convergence": _convergence, "stability": _stability, "numerics-report": _numerics_report}


def _add_convergence(commands) -> None:
    convergence = commands.add_parser(
        "convergence", help="work-precision study: error against run time for the settings in [convergence]")
    convergence.add_argument("scenario", help="scenario TOML file with a [convergence] section")
    add_output(convergence, "output directory; re-running skips finished runs", resumes=True)
    add_overrides(convergence, "override any spec field (repeatable)")
    convergence.add_argument("--quiet", action="store_true", help="no progress bar")


def _convergence(args) -> int:
    from bearing_mbs.studies.convergence import study

    spec = load_spec(args.scenario, args.set)
    summary = study(spec, output_directory(args), progress_meter(args.quiet))
    for target, best in summary["cheapest"].items():
        setting = "not reached" if best is None else (
            f"{best['engine']} {best['solver']} step={best['step'] or '-'} tolerance={best['tolerance'] or '-'} "
            f"({float(best['wall_time_s']):.3g} s)")
        print(f"{summary['norm']} error <= {target}: {setting}")
    return 0


def _add_stability(commands) -> None:
    stability = commands.add_parser(
        "stability", help="stability suite: which solver survives stiff and extreme variations, up to which step")
    stability.add_argument("scenario", help="scenario TOML file of a model with a stability suite (the cylindrical "
                                            "roller bearing's), the base of the variations")
    add_output(stability, "output directory; re-running skips finished cells", resumes=True)
    stability.add_argument("--reduced", action="store_true", help="the reduced suite of the default tests")
    stability.add_argument("--cases", help="comma-separated case names (default: all; see docs/numerics.md)")
    stability.add_argument("--solvers", help="comma-separated engine/method pairs, e.g. reference/rk4,exudyn/rk4")
    add_overrides(stability, "override any spec field of the base scenario (repeatable)")
    stability.add_argument("--no-figures", action="store_true", help="skip the heat map")


def _stability(args) -> int:
    """Exit 0: written (failing cells are results, not errors); 2: bad input."""
    from bearing_mbs.studies import stability

    spec = load_spec(args.scenario, args.set)
    suite = stability.suite(spec)  # the cases are the model's
    cases = suite.reduced if args.reduced else suite.names
    solvers = stability.REDUCED_SOLVERS if args.reduced else stability.SOLVERS
    if args.cases:
        cases = names(args.cases)
        for name in cases:
            if name not in suite.names:
                raise SpecError("--cases", name, f"case names among {', '.join(suite.names)}")
    if args.solvers:
        solvers = _solver_pairs(args.solvers)
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
