"""The status of a command's outputs, for the commands that solve without an engine run (``journal``,
``slewing``, ``stiffness``, the skidding map's points) and for studies of several runs (docs/status.md).

A run's status is :attr:`bearing_mbs.core.result.Result.status`; an output solved without a run follows the same
rule: ``success`` when every check passed, ``suspect`` when one failed, ``failed`` when the solver stopped without
an answer. A study's status is its worst run's (:func:`worst_status`, in the order of
:data:`bearing_mbs.core.result.STATUSES`).
"""

from __future__ import annotations

from collections.abc import Iterable

from bearing_mbs.core.checks import Check
from bearing_mbs.core.result import FAILED, STATUSES, SUCCESS, SUSPECT


def checked_status(checks: Iterable[Check]) -> str:
    """``success`` when every check passed, ``suspect`` otherwise (no check: ``success``)."""
    return SUCCESS if all(check.passed for check in checks) else SUSPECT


def worst_status(statuses: Iterable[str]) -> str:
    """The most severe of ``statuses`` (``success`` < ``suspect`` < ``failed`` < ``interrupted``); an unknown
    status (a study's ``error`` or ``missing`` run) counts as ``failed``; none at all is ``success``."""
    known = [status if status in STATUSES else FAILED for status in statuses]
    return max(known, key=STATUSES.index, default=SUCCESS)


def status_entries(checks: Iterable[Check], failure: str = "") -> dict:
    """The ``status``, ``message`` and ``checks`` entries of a summary: ``failed`` with ``failure`` (why the solver
    stopped) when one is given, else :func:`checked_status`."""
    checks = tuple(checks)
    return {"status": FAILED if failure else checked_status(checks), "message": failure,
            "checks": [check.to_dict() for check in checks]}


def failed_check_names(checks: Iterable[Check | dict]) -> list[str]:
    """The names of the checks that failed (from :class:`Check` objects or their dicts)."""
    checks = [c if isinstance(c, Check) else Check.from_dict(c) for c in checks]
    return [check.name for check in checks if not check.passed]


def status_note(summary: dict) -> str | None:
    """What a figure drawn from ``summary`` (with ``status``, ``checks`` and ``message``) must say about it, as
    :attr:`bearing_mbs.core.result.Result.status_note` says of a run: None for ``success``; else the status with the
    failed checks, or why the solver stopped."""
    status = summary["status"]
    if status == SUCCESS:
        return None
    if status == SUSPECT:
        return f"{status}: failed checks: {', '.join(failed_check_names(summary.get('checks', ())))}"
    return f"{status}: {summary.get('message', '')}"
