"""How a static command (no simulation: ``stiffness``, ``slewing``, ``journal``) reports its summary: one line,
the status and the failed checks."""

from __future__ import annotations

import sys
from collections.abc import Callable


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
