"""The run store: one directory per finished run and one row per run in an SQLite table.

Layout of a study's output directory::

    runs.sqlite                  table ``runs``: one row per run key (the primary key)
    runs/<k[:2]>/<key>/run.json  the row's content (inputs, status, summary, error, cost, provenance)
    runs/<k[:2]>/<key>/summary.json and, if kept, result.npz

Recording a run is two atomic steps, in this order: its directory is written under a temporary name and
renamed into place; then its row is inserted in one SQLite transaction (WAL journal, which survives a
killed process). A driver killed between the two leaves a directory without a row: :meth:`RunStore.recover`
inserts the row from ``run.json`` without re-running. A killed writer can leave only temporary
directories, which are removed. The key is the table's primary key, so a run is present at most once.
"""

from __future__ import annotations

import datetime
import fcntl
import json
import logging
import os
import shutil
import sqlite3
from pathlib import Path

from bearing_mbs import __version__
from bearing_mbs.io.json import json_safe, write_json
from bearing_mbs.spec import SpecError
from bearing_mbs.studies.sensitivity.runs import ERROR, Run

log = logging.getLogger(__name__)

DATABASE = "runs.sqlite"
RUNS = "runs"
RUN_FILE = "run.json"
SUMMARY_FILE = "summary.json"
LOCK_FILE = ".lock"
_TEMPORARY = ".part-"

COLUMNS = ("key", "status", "model", "attempts", "wall_time_s", "worker", "finished_at", "error",
           "summary", "inputs", "version")
_SCHEMA = """
CREATE TABLE IF NOT EXISTS runs (
    key TEXT PRIMARY KEY,
    status TEXT NOT NULL,
    model TEXT NOT NULL,
    attempts INTEGER NOT NULL,
    wall_time_s REAL,
    worker TEXT,
    finished_at TEXT NOT NULL,
    error TEXT,
    summary TEXT,
    inputs TEXT NOT NULL,
    version TEXT
)"""


class RunStore:
    """Finished runs of one output directory. Opening it takes an exclusive lock on the directory (one
    driver at a time; the lock dies with its process) and recovers runs whose row was not written."""

    def __init__(self, directory: str | Path):
        self.directory = Path(directory)
        self.directory.mkdir(parents=True, exist_ok=True)
        self._lock = open(self.directory / LOCK_FILE, "w")
        try:
            fcntl.flock(self._lock, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except BlockingIOError:
            self._lock.close()
            raise SpecError("--out", str(self.directory), "another sweep is running on this directory") from None
        self._db = sqlite3.connect(self.directory / DATABASE, isolation_level=None)
        self._db.execute("PRAGMA journal_mode=WAL")
        self._db.execute("PRAGMA synchronous=NORMAL")
        self._db.execute(_SCHEMA)
        self.recovered = self.recover()

    # -- life cycle -------------------------------------------------------------------------------------
    def close(self) -> None:
        if self._db is not None:
            self._db.close()
            self._db = None
            self._lock.close()

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()

    # -- writing ----------------------------------------------------------------------------------------
    def run_directory(self, key: str) -> Path:
        return self.directory / RUNS / key[:2] / key

    def record(self, model: str, run: Run, outcome: dict) -> dict:
        """Write a finished run: its directory (atomically), then its row. Returns the row."""
        row = {
            "key": run.key,
            "status": outcome["status"],
            "model": model,
            "attempts": outcome["attempt"],
            "wall_time_s": outcome.get("wall_time_s"),
            "worker": outcome.get("worker"),
            "finished_at": datetime.datetime.now(datetime.UTC).isoformat(timespec="milliseconds"),
            "error": outcome.get("error"),
            "summary": json_safe(outcome.get("summary")),
            "inputs": run.inputs,
            "version": __version__,
        }
        final = self.run_directory(run.key)
        final.parent.mkdir(parents=True, exist_ok=True)
        temporary = final.parent / f"{_TEMPORARY}{run.key}-{os.getpid()}"
        if temporary.exists():
            shutil.rmtree(temporary)
        temporary.mkdir()
        write_json(temporary / RUN_FILE, row)
        if row["summary"] is not None:
            write_json(temporary / SUMMARY_FILE, row["summary"])
        for name, content in (outcome.get("files") or {}).items():
            (temporary / name).write_bytes(content)
        if final.exists():  # replacing an errored run (retry_errors): old directory out of the way first
            stale = final.parent / f"{_TEMPORARY}{run.key}-stale-{os.getpid()}"
            final.replace(stale)
            shutil.rmtree(stale)
        temporary.replace(final)
        self._insert(row)
        return row

    def _insert(self, row: dict) -> None:
        values = [json.dumps(row[c], allow_nan=False) if c in ("summary", "inputs") and row[c] is not None
                  else row[c] for c in COLUMNS]
        with self._transaction():
            self._db.execute(
                f"INSERT INTO runs ({', '.join(COLUMNS)}) VALUES ({', '.join('?' * len(COLUMNS))}) "
                f"ON CONFLICT(key) DO UPDATE SET {', '.join(f'{c}=excluded.{c}' for c in COLUMNS[1:])}",
                values,
            )

    def _transaction(self):
        db = self._db

        class _Transaction:
            def __enter__(self):
                db.execute("BEGIN IMMEDIATE")

            def __exit__(self, kind, value, tb):
                db.execute("COMMIT" if kind is None else "ROLLBACK")

        return _Transaction()

    def recover(self) -> int:
        """Insert the rows of run directories that have none; remove temporary directories. Returns the
        number of rows recovered."""
        root = self.directory / RUNS
        if not root.is_dir():
            return 0
        known = self.keys()
        recovered = 0
        for bucket in root.iterdir():
            if not bucket.is_dir():
                continue
            for entry in bucket.iterdir():
                if entry.name.startswith(_TEMPORARY):
                    shutil.rmtree(entry, ignore_errors=True)
                    continue
                if entry.name in known:
                    continue
                try:
                    row = json.loads((entry / RUN_FILE).read_text())
                except (OSError, ValueError):
                    log.warning("%s: no readable %s, ignored", entry, RUN_FILE)
                    continue
                self._insert(row)
                recovered += 1
        if recovered:
            log.info("recovered %d run(s) whose row was not written", recovered)
        return recovered

    # -- reading ----------------------------------------------------------------------------------------
    def keys(self, status: str | None = None) -> set[str]:
        if status is None:
            return {k for (k,) in self._db.execute("SELECT key FROM runs")}
        return {k for (k,) in self._db.execute("SELECT key FROM runs WHERE status = ?", (status,))}

    def finished(self, retry_errors: bool = False) -> set[str]:
        """Keys that need no evaluation: every recorded run, or all but the errors with retry_errors."""
        if not retry_errors:
            return self.keys()
        return {k for (k,) in self._db.execute("SELECT key FROM runs WHERE status != ?", (ERROR,))}

    def rows(self, keys=None) -> dict[str, dict]:
        """Rows by key (all, or those of ``keys``), with summary and inputs decoded."""
        cursor = self._db.execute(f"SELECT {', '.join(COLUMNS)} FROM runs")
        wanted = None if keys is None else set(keys)
        rows = {}
        for values in cursor:
            row = dict(zip(COLUMNS, values))
            if wanted is not None and row["key"] not in wanted:
                continue
            for column in ("summary", "inputs"):
                row[column] = json.loads(row[column]) if row[column] is not None else None
            rows[row["key"]] = row
        return rows

    def count(self) -> int:
        return self._db.execute("SELECT COUNT(*) FROM runs").fetchone()[0]
