"""What the subcommands share: the ``--set`` option, scenario loading and comma-separated lists."""

from __future__ import annotations

from bearing_mbs.models import load_spec
from bearing_mbs.spec import SpecError


def add_overrides(parser, what: str = "override any spec field, validated like the file (repeatable)") -> None:
    """The repeatable ``--set SECTION.KEY=VALUE`` option every subcommand shares."""
    parser.add_argument("--set", action="append", default=[], metavar="SECTION.KEY=VALUE", help=what)


def load_with_engine(args):
    """The scenario with its ``--set`` overrides, and ``--engine`` as ``solver.engine`` when given."""
    return load_spec(args.scenario, list(args.set) + ([f"solver.engine={args.engine}"] if args.engine else []))


def numbers(option: str, text: str) -> tuple[float, ...]:
    """A comma-separated list of numbers, e.g. ``--loads 68000,2000``."""
    try:
        return tuple(float(item) for item in text.split(",") if item.strip())
    except ValueError:
        raise SpecError(option, text, "must be comma-separated numbers") from None


def names(text: str) -> tuple[str, ...]:
    """A comma-separated list of names, e.g. ``--cages penalty,constraint``."""
    return tuple(item.strip() for item in text.split(",") if item.strip())
