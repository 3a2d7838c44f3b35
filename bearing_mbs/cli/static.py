"""Static commands (no simulation) of models that solve a scenario on their own: ``bearing-mbs slewing`` and
``bearing-mbs journal``. One shape: read the scenario with its overrides, check it is the command's model, write
``summary.json`` and figures, print one line."""

from __future__ import annotations

from collections.abc import Callable

from bearing_mbs.cli.options import add_output, add_overrides, output_directory


def register_static(commands, name: str, help_text: str, model_name: str, solve: Callable,
                    describe: Callable[[dict], str]) -> dict:
    """Add command ``name`` for scenarios of ``model_name``: ``solve(spec, directory, figures=bool) -> summary`` writes
    the outputs, ``describe(summary)`` is the line printed (warnings in the summary are printed first)."""
    parser = commands.add_parser(name, help=help_text)
    parser.add_argument("scenario", help=f"scenario TOML file with model = {model_name!r}")
    add_output(parser, "output directory (new or empty, or give --overwrite): summary.json and figures")
    add_overrides(parser)
    parser.add_argument("--no-figures", action="store_true", help="skip the PNG figures")

    def handler(args) -> int:
        """Exit 0: solved and written; 2: bad input (nothing written)."""
        from bearing_mbs.models import load_spec
        from bearing_mbs.spec import SpecError

        spec = load_spec(args.scenario, args.set)
        if spec.scenario.model != model_name:
            raise SpecError("scenario.model", spec.scenario.model, f"{model_name!r} for this command")
        summary = solve(spec, output_directory(args), figures=not args.no_figures)
        for warning in summary.get("warnings", []):
            print(f"warning: {warning}")
        print(f"{describe(summary)} -> {args.out}")
        return 0

    return {name: handler}
