"""What the subcommands share: the ``--set`` and ``--out`` options, scenario loading, comma-separated lists and
exit codes."""

from __future__ import annotations

import shutil
import signal
from pathlib import Path

from bearing_mbs.core.result import FAILED, INTERRUPTED, SUCCESS, SUSPECT
from bearing_mbs.core.status import worst_status
from bearing_mbs.models import load_spec
from bearing_mbs.spec import SpecError


def add_overrides(parser, what: str = "override any spec field, validated like the file (repeatable)") -> None:
    """The repeatable ``--set SECTION.KEY=VALUE`` option every subcommand shares."""
    parser.add_argument("--set", action="append", default=[], metavar="SECTION.KEY=VALUE", help=what)


def load_with_engine(args):
    """The scenario with its ``--set`` overrides, and ``--engine`` as ``solver.engine`` when given."""
    return load_spec(args.scenario, list(args.set) + ([f"solver.engine={args.engine}"] if args.engine else []))


def progress_meter(quiet: bool):
    """A progress bar on the terminal, or no progress with ``--quiet``."""
    from bearing_mbs.core.progress import ProgressMeter, TqdmProgress

    return ProgressMeter() if quiet else TqdmProgress()


def numbers(option: str, text: str) -> tuple[float, ...]:
    """A comma-separated list of numbers, e.g. ``--loads 68000,2000``."""
    try:
        return tuple(float(item) for item in text.split(",") if item.strip())
    except ValueError:
        raise SpecError(option, text, "must be comma-separated numbers") from None


def names(text: str) -> tuple[str, ...]:
    """A comma-separated list of names, e.g. ``--cages penalty,constraint``."""
    return tuple(item.strip() for item in text.split(",") if item.strip())


#: Exit codes (docs/status.md). Bad input is 2 (nothing ran); an interrupted command exits 128 + the signal's
#: number (130 for SIGINT, 143 for SIGTERM), as a shell reports a process stopped by that signal.
EXIT_CODES = {SUCCESS: 0, FAILED: 1, SUSPECT: 3}
BAD_INPUT = 2


def exit_code(statuses, signal_number: int | None = None) -> int:
    """The exit code of a command whose runs ended with ``statuses`` (one status, or several: the worst counts,
    :func:`bearing_mbs.core.status.worst_status`)."""
    worst = worst_status([statuses] if isinstance(statuses, str) else statuses)
    if worst == INTERRUPTED or signal_number is not None:
        return 128 + (signal_number or signal.SIGINT)
    return EXIT_CODES[worst]


def add_output(parser, what: str, resumes: bool = False) -> None:
    """The ``--out DIR`` option (and ``--overwrite`` where a command does not resume into its directory)."""
    parser.add_argument("--out", required=True, help=what)
    if not resumes:
        parser.add_argument("--overwrite", action="store_true",
                            help="replace what DIR holds (by default a non-empty DIR is refused before anything runs)")


def output_directory(args) -> Path:
    """``args.out`` validated and created before anything runs (:func:`bearing_mbs.runner.outputs.prepare_output`);
    a command that resumes into its directory (no ``--overwrite`` option) accepts one that holds files. What it
    creates is recorded in ``args.created_output``, so that bad input found later leaves nothing behind
    (:func:`remove_created_output`)."""
    from bearing_mbs.runner.outputs import prepare_output

    path = Path(args.out).absolute()
    missing = [p for p in (path, *path.parents) if not p.exists()]
    directory = prepare_output(args.out, overwrite=getattr(args, "overwrite", True))
    args.created_output = missing[-1] if missing else None
    return directory


def remove_created_output(args) -> None:
    """Remove the directories :func:`output_directory` created, if they hold no file."""
    created = getattr(args, "created_output", None)
    if created is not None and created.is_dir() and not any(p.is_file() for p in created.rglob("*")):
        shutil.rmtree(created)
