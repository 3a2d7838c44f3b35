"""Output directories that never lose a result (docs/status.md, "Nothing lost").

* :func:`prepare_output` validates and creates the directory before anything runs: a path under a file, one
  this user cannot create or write, or a directory that already holds results (unless ``overwrite``) is bad
  input.
* :class:`Staging` collects a run's files in ``DIR/.incoming`` (each written atomically) and then publishes them:
  a good run (``success`` or ``suspect``) replaces what the directory held, stale figures included; a run that
  failed or was interrupted never replaces a good result: it goes to ``DIR/rejected/`` next to it.
"""

from __future__ import annotations

import json
import os
import shutil
import tempfile
from pathlib import Path

from bearing_mbs.core.result import FAILED, INTERRUPTED
from bearing_mbs.spec import SpecError

STAGING = ".incoming"
REJECTED = "rejected"
SUMMARY_FILE = "summary.json"


def prepare_output(path: str | Path, overwrite: bool = False, field: str = "--out") -> Path:
    """``path`` as a directory that exists, is writable and, unless ``overwrite``, holds nothing yet."""
    path = Path(path)
    for parent in (path, *path.parents):
        if parent.exists() and not parent.is_dir():
            raise SpecError(field, str(path), f"a directory; {parent} is a file")
    try:
        path.mkdir(parents=True, exist_ok=True)
        with tempfile.NamedTemporaryFile(dir=path, prefix=".write-test-"):
            pass
    except OSError as error:
        raise SpecError(field, str(path), f"a directory this user can create and write ({error.strerror})") from None
    held = sorted(entry.name for entry in path.iterdir() if entry.name != STAGING)
    if held and not overwrite:
        raise SpecError(field, str(path), f"a new or empty directory; it holds {', '.join(held[:4])}"
                                          f"{', …' if len(held) > 4 else ''}: give --overwrite to replace them")
    return path


def good_result(directory: Path) -> bool:
    """Whether ``directory`` holds a summary of a run that reached its end (``success`` or ``suspect``)."""
    try:
        status = json.loads((directory / SUMMARY_FILE).read_text()).get("status")
    except (OSError, ValueError, AttributeError):
        return False
    return status not in (None, FAILED, INTERRUPTED)


class Staging:
    """The files of one run, gathered in ``DIR/.incoming`` and published together (module docstring)."""

    def __init__(self, directory: str | Path):
        self.directory = Path(directory)
        self.path = self.directory / STAGING
        if self.path.exists():
            shutil.rmtree(self.path)
        self.path.mkdir(parents=True)

    def publish(self, status: str) -> Path:
        """Move the staged files into place; returns where they went (the directory, or ``DIR/rejected``)."""
        if status in (FAILED, INTERRUPTED) and good_result(self.directory):
            target = self.directory / REJECTED
            if target.exists():
                shutil.rmtree(target)
            os.replace(self.path, target)
            return target
        for entry in self.directory.iterdir():
            if entry.name != STAGING:
                shutil.rmtree(entry) if entry.is_dir() else entry.unlink()
        for entry in self.path.iterdir():
            os.replace(entry, self.directory / entry.name)
        self.path.rmdir()
        return self.directory
