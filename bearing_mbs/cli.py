"""The ``bearing-mbs`` command.

``bearing-mbs run SCENARIO.toml --out DIR [--engine exudyn|reference] [--set section.key=value ...]``

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

    args = parser.parse_args(argv)
    logging.basicConfig(level=logging.INFO, format="%(levelname)s %(name)s: %(message)s")
    try:
        return _run(args)
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


if __name__ == "__main__":
    sys.exit(main())
