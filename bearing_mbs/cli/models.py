"""The subcommands the models offer (:attr:`bearing_mbs.models.Model.commands`): each model's studies and static
solutions, registered from the model records, so that the command line names no model."""

from __future__ import annotations

import functools

from bearing_mbs.cli.options import (
    add_output,
    add_overrides,
    exit_code,
    names,
    numbers,
    output_directory,
    progress_meter,
)
from bearing_mbs.cli.static import print_outcome
from bearing_mbs.models import MODELS
from bearing_mbs.models.protocol import CommandLine
from bearing_mbs.studies.services import SERVICES

#: What the command line lends the models' commands.
COMMAND_LINE = CommandLine(services=SERVICES, add_output=add_output, add_overrides=add_overrides,
                           output_directory=output_directory, names=names, numbers=numbers, exit_code=exit_code,
                           progress=progress_meter, print_outcome=print_outcome)


def register(commands, taken=()) -> dict:
    """Add every registered model's subcommands to ``commands`` (argparse subparsers); returns {name: handler}.
    A name already ``taken`` (by the command line's own subcommands) or offered by two models is refused."""
    handlers = {}
    for model in MODELS.values():
        for command in model.commands:
            if command.name in handlers or command.name in taken:
                raise ValueError(f"model {model.name!r} offers the subcommand {command.name!r}, which another "
                                 f"already has")
            command.arguments(commands.add_parser(command.name, help=command.help), COMMAND_LINE)
            handlers[command.name] = functools.partial(command.run, cli=COMMAND_LINE)
    return handlers
