"""The ``bearing-mbs`` command.

``bearing-mbs run SCENARIO.toml --out DIR [--engine exudyn|reference] [--set section.key=value ...]``
``bearing-mbs sweep STUDY.toml --out DIR [--scheduler ADDRESS] [--workers N]`` (docs/sensitivity.md)
``bearing-mbs stiffness SCENARIO.toml --out DIR [--set section.key=value ...]`` (docs/quasistatic.md)
``bearing-mbs convergence SCENARIO.toml --out DIR [--set section.key=value ...]`` (docs/numerics.md)
``bearing-mbs stability SCENARIO.toml --out DIR [--reduced] [--cases ...] [--solvers ...]`` (docs/numerics.md)
``bearing-mbs advise SCENARIO.toml [--check-slip] [--set section.key=value ...]`` (docs/numerics.md)
``bearing-mbs numerics-report STUDY_DIR --name NAME --out DIR [--norms ...] [--document-step H]`` (docs/numerics.md)
``bearing-mbs static-check SCENARIO.toml --out DIR [--engines ...] [--loads ...]`` (docs/quasistatic.md)
``bearing-mbs skidding SCENARIO.toml --out DIR [--loads ...] [--cages ...]`` (docs/skidding.md)
``bearing-mbs skidding-map SCENARIO.toml --out DIR [--loads ...] [--temperatures ...] [--speeds ...]``
(docs/skidding.md)
``bearing-mbs cage-models SCENARIO.toml --out DIR [--no-roller-guided]`` (docs/cage-models.md)
``bearing-mbs spatial SCENARIO.toml --out DIR [--engine ...] [--misalignment RAD] [--crown-radius M] ...``
(docs/spatial.md)
``bearing-mbs slewing SCENARIO.toml --out DIR`` (docs/slewing.md)
``bearing-mbs journal SCENARIO.toml --out DIR`` (docs/fluid-film.md)

Exit status (docs/status.md): 0 success; 3 suspect (a run reached its end but failed a check); 1 failed (a run
stopped early; its summary and result are still written); 2 bad input (nothing runs); 130 or 143 interrupted by
SIGINT or SIGTERM (what was computed is written).
"""

from __future__ import annotations

import argparse
import logging
import sys

from bearing_mbs.cli import models, runs, studies
from bearing_mbs.cli.options import BAD_INPUT, exit_code, remove_created_output
from bearing_mbs.core.interrupt import StopRequest, stop_on_signals
from bearing_mbs.core.numba_cache import invalidate_if_stale
from bearing_mbs.core.result import INTERRUPTED
from bearing_mbs.spec import SpecError


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(prog="bearing-mbs", description=__doc__.splitlines()[0])
    commands = parser.add_subparsers(dest="command", required=True)
    handlers = {**runs.register(commands), **studies.register(commands)}
    handlers.update(models.register(commands, taken=handlers))  # each model's own studies and static solutions
    args = parser.parse_args(argv)
    invalidate_if_stale()  # once per process, before anything compiles (never at import)
    logging.basicConfig(level=logging.INFO, format="%(levelname)s %(name)s: %(message)s")
    try:
        with stop_on_signals(StopRequest()) as request:  # a run stops, keeps its output, and so do later ones
            code = handlers[args.command](args)
    except SpecError as error:
        remove_created_output(args)  # bad input found after the output directory was made leaves nothing
        print(f"error: {error}", file=sys.stderr)
        return BAD_INPUT
    return exit_code(INTERRUPTED, request.signal_number) if request.is_set() else code
