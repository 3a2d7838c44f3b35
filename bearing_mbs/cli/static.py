"""Static commands (no simulation) of models that solve a scenario on their own: ``bearing-mbs slewing`` and
``bearing-mbs journal``. One shape: read the scenario with its overrides, check it is the command's model, write
``summary.json`` (with its ``status`` and ``checks``) and figures, print one line and the failed checks, exit
with the status's code (docs/status.md)."""

from __future__ import annotations

import sys
from collections.abc import Callable

from bearing_mbs.cli.options import add_output, add_overrides, exit_code, output_directory


def register_static(commands, name: str, help_text: str, model_name: str, solve: Callable,
                    describe: Callable[[dict], str]) -> dict:
    """Add command ``name`` for scenarios of ``model_name``: ``solve(spec, directory, figures=bool) -> summary`` writes
    the outputs, ``describe(summary)`` is the line printed for a summary that has results."""
    parser = commands.add_parser(name, help=help_text)
    parser.add_argument("scenario", help=f"scenario TOML file with model = {model_name!r}")
    add_output(parser, "output directory (new or empty, or give --overwrite): summary.json and figures")
    add_overrides(parser)
    parser.add_argument("--no-figures", action="store_true", help="skip the PNG figures")

    def handler(args) -> int:
        """Exit 0: success; 3: suspect (a check failed); 1: failed (the solver found no solution; the summary says
        why); 2: bad input (nothing written)."""
        from bearing_mbs.models import load_spec
        from bearing_mbs.spec import SpecError

        spec = load_spec(args.scenario, args.set)
        if spec.scenario.model != model_name:
            raise SpecError("scenario.model", spec.scenario.model, f"{model_name!r} for this command")
        summary = solve(spec, output_directory(args), figures=not args.no_figures)
        print_outcome(summary, describe, args.out)
        return exit_code(summary["status"])

    return {name: handler}


def print_outcome(summary: dict, describe: Callable[[dict], str], out) -> None:
    """The summary's line (or why the solver stopped), its status and its failed checks."""
    from bearing_mbs.core.checks import Check

    if summary.get("message"):
        print(f"{summary['scenario']}: {summary['status']} -> {out}")
        print(f"stopped: {summary['message']}", file=sys.stderr)
    else:
        print(f"{describe(summary)}: {summary['status']} -> {out}")
    checks = [Check.from_dict(check) for check in summary.get("checks", [])]
    for check in checks:
        if not check.passed:
            print(f"check {check.line()}", file=sys.stderr)
    if checks:
        print(f"checks: {sum(check.passed for check in checks)} of {len(checks)} passed")
