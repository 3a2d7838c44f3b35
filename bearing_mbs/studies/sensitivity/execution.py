"""Evaluating a design on Dask distributed: a local cluster (processes, one thread each) by default, or
any scheduler by its address. Every finished run is recorded in the :class:`~.store.RunStore` as soon as
it arrives, so nothing finished is lost when a worker or the driver dies; runs already in the store are
skipped, so running the same study again resumes it.

Failures: a run that raises is retried once (on whichever worker is free), then recorded with its error;
it never stops the study. A worker that dies takes no run with it: Dask reruns its tasks elsewhere
(``distributed.scheduler.allowed-failures`` times), and a task that still fails counts as a failed attempt
of each of its runs.
"""

from __future__ import annotations

import contextlib
import logging
import os
import uuid
from dataclasses import dataclass

import numpy as np
import pandas as pd

from bearing_mbs.core.progress import ProgressMeter
from bearing_mbs.core.result import FAILED
from bearing_mbs.core.status import failed_check_names
from bearing_mbs.spec import SpecError
from bearing_mbs.studies.sensitivity.runs import ERROR, MAX_ATTEMPTS, Run, evaluate_runs, plan, task_error
from bearing_mbs.studies.sensitivity.store import RunStore
from bearing_mbs.studies.sensitivity.study import Study

log = logging.getLogger(__name__)

#: Seconds to wait for a scheduler given by address before calling it unreachable.
CONNECT_TIMEOUT = 5.0
#: Seconds to wait for the requested number of workers on a scheduler given by address.
WORKERS_TIMEOUT = 60.0


@contextlib.contextmanager
def connect(scheduler: str | None = None, workers: int | None = None, timeout: float = CONNECT_TIMEOUT):
    """A Dask client. Without ``scheduler``: a local cluster of ``workers`` processes (default: one per
    CPU), one thread each, on loopback. With a scheduler address (``tcp://host:8786``): that cluster,
    after waiting for ``workers`` workers if given (:data:`WORKERS_TIMEOUT`). An unreachable scheduler
    raises :class:`~bearing_mbs.spec.SpecError` after ``timeout`` seconds."""
    from dask.distributed import Client, LocalCluster

    if workers is not None and workers < 1:
        raise SpecError("--workers", workers, "must be >= 1")
    if scheduler is None:
        cluster = LocalCluster(n_workers=workers or os.cpu_count() or 1, threads_per_worker=1, processes=True,
                               host="127.0.0.1", dashboard_address=None)
        try:
            with Client(cluster, set_as_default=False) as client:
                yield client
        finally:
            cluster.close()
        return
    try:
        client = Client(scheduler, timeout=timeout, set_as_default=False)
    except (OSError, TimeoutError, ValueError) as error:
        raise SpecError("--scheduler", scheduler,
                        f"no Dask scheduler answered within {timeout:g} s ({type(error).__name__}: {error})") from None
    try:
        if workers:
            try:
                client.wait_for_workers(workers, timeout=WORKERS_TIMEOUT)
            except TimeoutError:
                have = len(client.scheduler_info()["workers"])
                raise SpecError("--workers", workers, f"the scheduler at {scheduler} has {have} worker(s) after "
                                f"waiting {WORKERS_TIMEOUT:g} s") from None
        yield client
    finally:
        client.close()


@dataclass
class EvaluationStats:
    """What one :func:`evaluate` call did: runs planned (distinct keys), skipped (already stored),
    recovered (directory without row), evaluated (recorded now), retried (second attempts), errors."""

    planned: int = 0
    skipped: int = 0
    recovered: int = 0
    evaluated: int = 0
    retried: int = 0
    errors: int = 0


def evaluate(study: Study, X: np.ndarray, out, client, progress: ProgressMeter | None = None,
             retry_errors: bool = False, stats: EvaluationStats | None = None, planned=None) -> pd.DataFrame:
    """Evaluate every row of the design X on ``client``, storing each run in ``out`` (a directory or an
    open :class:`RunStore`) as it finishes; return the table of runs (:func:`run_table`).

    Runs already stored are skipped (with ``retry_errors``, stored errors are run again). ``stats``, if
    given, is filled in. ``progress`` receives the number of runs finished (silent by default).
    ``planned``: the result of :func:`~.runs.plan` for X, if already computed.
    """
    progress = progress or ProgressMeter()
    stats = stats if stats is not None else EvaluationStats()
    keys, runs = planned if planned is not None else plan(study, X)
    owns_store = not isinstance(out, RunStore)
    store = RunStore(out) if owns_store else out
    try:
        finished = store.finished(retry_errors)
        todo = [run for key, run in runs.items() if key not in finished]
        stats.planned, stats.skipped, stats.recovered = len(runs), len(runs) - len(todo), store.recovered
        log.info("%s: %d runs, %d already stored, %d to evaluate", study.name, len(runs), stats.skipped, len(todo))
        if todo:
            _execute(study, todo, store, client, progress, stats)
        return run_table(study, X, keys, store)
    finally:
        if owns_store:
            store.close()


def _execute(study: Study, todo: list[Run], store: RunStore, client, progress: ProgressMeter,
             stats: EvaluationStats) -> None:
    from dask.distributed import as_completed

    session = uuid.uuid4().hex[:8]
    size = study.execution.runs_per_task
    pending = as_completed(loop=client.loop)
    batches = {}

    def submit(batch: list[Run]) -> None:
        key = f"bearing-mbs-run-{batch[0].key[:16]}-a{batch[0].attempt}-{session}"
        future = client.submit(evaluate_runs, study.model, batch, study.execution.keep_results, key=key,
                               pure=False)
        batches[future] = batch
        pending.add(future)

    progress.start(len(todo), f"{study.name}")
    done, checked_outputs = 0, False
    try:
        for i in range(0, len(todo), size):
            submit(todo[i : i + size])
        for future in pending:
            batch = batches.pop(future)
            try:
                outcomes = future.result()
            except Exception as error:  # the task itself failed (e.g. KilledWorker)
                log.warning("task %s failed: %s", future.key, error)
                outcomes = task_error(batch, error)
            future.release()
            by_key = {run.key: run for run in batch}
            for outcome in outcomes:
                run = by_key[outcome["key"]]
                if outcome["status"] == ERROR and run.attempt < MAX_ATTEMPTS:
                    log.info("run %s failed (attempt %d), retrying: %s", run.key[:12], run.attempt,
                             outcome["error"].splitlines()[0])
                    stats.retried += 1
                    submit([Run(run.key, run.inputs, run.attempt + 1)])
                    continue
                if outcome["status"] != ERROR and not checked_outputs:
                    checked_outputs = True
                    _check_outputs(study, outcome["summary"])
                store.record(study.model.name, run, outcome)
                if outcome["status"] == ERROR:
                    stats.errors += 1
                    log.error("run %s failed after %d attempts: %s", run.key[:12], run.attempt,
                              outcome["error"].splitlines()[0])
                done += 1
                stats.evaluated += 1
                progress.update(done)
    finally:
        if batches:  # interrupted: do not leave our tasks running on a shared cluster
            client.cancel(list(batches))
        progress.close()


def _check_outputs(study: Study, summary: dict) -> None:
    """Warn at the first finished run about outputs its summary does not have (a misspelt metric): the
    study goes on, and the analysis can be redone from the stored summaries without running again."""
    missing = [o for o in study.outputs if o not in summary]
    if missing:
        available = sorted(k for k, v in summary.items() if isinstance(v, (int, float)) and not isinstance(v, bool))
        log.warning("outputs %s are not in the run summary; numeric metrics are: %s", ", ".join(missing),
                    ", ".join(available))


def run_table(study: Study, X: np.ndarray, keys: list[str], store: RunStore) -> pd.DataFrame:
    """The table of runs, one row per sample (row of X): the parameter values, the run key, status,
    attempts, cost [s], the outputs (NaN where a run has no finite value), the error message (of a failed run: why it
    stopped or found no solution) and the names of the run's failed checks (docs/status.md)."""
    rows = store.rows(keys)
    records = []
    for i, (x, key) in enumerate(zip(np.asarray(X, dtype=float), keys)):
        row = rows.get(key)
        record = dict(zip(study.names, x))
        record.update(key=key, status=row["status"] if row else "missing",
                      attempts=row["attempts"] if row else 0,
                      wall_time_s=row["wall_time_s"] if row else None)
        summary = (row or {}).get("summary") or {}
        for output in study.outputs:
            record[output] = _number(summary.get(output)) if row and row["status"] != FAILED else np.nan
        # an error's message, or why a run stopped early (or found no solution): its summary's message
        error = ((row["error"] or (summary.get("message") if row["status"] == FAILED else None)) if row else None) or ""
        record["error"] = error.splitlines()[0] if error else ""
        record["failed_checks"] = ", ".join(failed_check_names(summary.get("checks") or ()))
        records.append(record)
    table = pd.DataFrame.from_records(records)
    table.index.name = "sample"
    return table


def _number(value) -> float:
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        return np.nan
    return float(value)
