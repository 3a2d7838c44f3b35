"""The shape of a model's static command (no simulation; ``bearing-mbs slewing``, ``bearing-mbs journal``): read
the scenario with its overrides, check it is the command's model, write ``summary.json`` (with its ``status`` and
``checks``) and figures, print one line and the failed checks, exit with the status's code (docs/status.md)."""

from __future__ import annotations

from collections.abc import Callable

from bearing_mbs.models.protocol import Command
from bearing_mbs.spec import SpecError


def static_command(name: str, help_text: str, model_name: str, solve: Callable,
                   describe: Callable[[dict], str]) -> Command:
    """Command ``name`` for scenarios of ``model_name``: ``solve(spec, directory, figures=bool) -> summary`` writes
    the outputs, ``describe(summary)`` is the line printed for a summary that has results."""

    def arguments(parser, cli) -> None:
        parser.add_argument("scenario", help=f"scenario TOML file with model = {model_name!r}")
        cli.add_output(parser, "output directory (new or empty, or give --overwrite): summary.json and figures")
        cli.add_overrides(parser)
        parser.add_argument("--no-figures", action="store_true", help="skip the PNG figures")

    def run(args, cli) -> int:
        """Exit 0: success; 3: suspect (a check failed); 1: failed (the solver found no solution; the summary says
        why); 2: bad input (nothing written)."""
        spec = cli.services.load_spec(args.scenario, args.set)
        if spec.scenario.model != model_name:
            raise SpecError("scenario.model", spec.scenario.model, f"{model_name!r} for this command")
        summary = solve(spec, cli.output_directory(args), figures=not args.no_figures)
        cli.print_outcome(summary, describe, args.out)
        return cli.exit_code(summary["status"])

    return Command(name, help_text, arguments, run)
