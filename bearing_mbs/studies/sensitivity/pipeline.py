"""The whole study in one call: sample → evaluate (Dask, persisted, resumable) → analyze → report."""

from __future__ import annotations

import contextlib
import logging
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np
import pandas as pd

from bearing_mbs.core.progress import ProgressMeter
from bearing_mbs.core.status import worst_status
from bearing_mbs.studies.sensitivity.analysis import Indices, analyze
from bearing_mbs.studies.sensitivity.execution import EvaluationStats, connect, evaluate
from bearing_mbs.studies.sensitivity.runs import plan
from bearing_mbs.studies.sensitivity.sampling import sample
from bearing_mbs.studies.sensitivity.store import RunStore
from bearing_mbs.studies.sensitivity.study import Study

log = logging.getLogger(__name__)

REPORT_DIRECTORY = "report"


@dataclass
class StudyResult:
    """X: the design (n, D); table: the table of runs (one row per sample, outputs as columns);
    indices: by output; report: path of report.md (None without report); stats: what was evaluated."""

    X: np.ndarray
    table: pd.DataFrame
    indices: dict[str, Indices]
    report: Path | None
    stats: EvaluationStats = field(default_factory=EvaluationStats)

    @property
    def complete(self) -> bool:
        """Every run is recorded and none ended in an error or stopped early."""
        return bool((self.table["status"] == "success").all())

    @property
    def status(self) -> str:
        """The study's status, its worst run's (docs/status.md); a run that ended in an error or is missing counts
        as ``failed``."""
        return worst_status(self.table.drop_duplicates("key")["status"])


def run_study(study: Study, out, client=None, scheduler: str | None = None, workers: int | None = None,
              progress: ProgressMeter | None = None, retry_errors: bool = False, report: bool = True,
              figures: bool = True) -> StudyResult:
    """Sample, evaluate on Dask (``client``; else a local cluster of ``workers`` processes, or the
    ``scheduler`` at that address), store every run in ``out``, analyse and write ``out/report``.

    Everything is validated, and the store opened, before a cluster is started or any run is submitted.
    Running it again skips the stored runs (with ``retry_errors``, it runs the errors again); when every
    run is stored, no cluster is started and only the analysis and report are redone.
    """
    out = Path(out)
    X = sample(study)
    planned = plan(study, X)  # every sample point is a valid input, before anything starts
    stats = EvaluationStats()
    with RunStore(out) as store:
        done = store.finished(retry_errors)
        if client is not None or all(key in done for key in planned[1]):  # nothing to run: no cluster
            cluster = contextlib.nullcontext(client)
        else:
            cluster = connect(scheduler, workers)
        with cluster as dask:
            table = evaluate(study, X, store, dask, progress=progress, retry_errors=retry_errors, stats=stats,
                             planned=planned)
    indices = analyze(study, X, table) if (table["status"] != "missing").all() else {}
    path = write_report(study, table, indices, out / REPORT_DIRECTORY, figures) if report else None
    log.info("%s: %d evaluated, %d skipped, %d recovered, %d errors%s", study.name, stats.evaluated,
             stats.skipped, stats.recovered, stats.errors, f"; report {path}" if path else "")
    return StudyResult(X, table, indices, path, stats)


def write_report(study: Study, table: pd.DataFrame, indices: dict[str, Indices], directory, figures: bool = True,
                 title_level: int = 1) -> Path:
    """:func:`.report.write_report`, imported on first use (matplotlib is needed only for the report)."""
    from bearing_mbs.studies.sensitivity.report import write_report as write

    return write(study, table, indices, directory, figures, title_level)
