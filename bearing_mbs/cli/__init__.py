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
``bearing-mbs cage-models SCENARIO.toml --out DIR [--no-roller-guided]`` (docs/cage-models.md)

Exit status: 0 when the run succeeded, 1 when it stopped early (its summary and result are still
written), 2 for bad input (nothing runs).
"""

from __future__ import annotations

import argparse
import logging
import sys

from bearing_mbs._numba_cache import invalidate_if_stale
from bearing_mbs.cli import runs, studies
from bearing_mbs.spec import SpecError


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(prog="bearing-mbs", description=__doc__.splitlines()[0])
    commands = parser.add_subparsers(dest="command", required=True)
    handlers = {**runs.register(commands), **studies.register(commands)}
    args = parser.parse_args(argv)
    invalidate_if_stale()  # once per process, before anything compiles (never at import)
    logging.basicConfig(level=logging.INFO, format="%(levelname)s %(name)s: %(message)s")
    try:
        return handlers[args.command](args)
    except SpecError as error:
        print(f"error: {error}", file=sys.stderr)
        return 2
