"""Runs: the unit of work, identity and storage.

A run is a canonical input mapping for a model. Its key is the SHA-256 of the model name and that mapping
(canonical JSON), so a run is the same run whichever study, sample row or spelling produced it: rows of a
design that coincide (Morris trajectories can share points) are evaluated once, and a resumed or enlarged
study finds the runs it already has.

:func:`evaluate_runs` is what a Dask task executes: a pure function of (model, inputs) that never raises
for a failing run; it returns that run's error instead, so one bad run cannot take its batch with it.
"""

from __future__ import annotations

import hashlib
import json
import os
import socket
import time
import traceback
from dataclasses import dataclass

import numpy as np

from bearing_mbs.core.result import FAILED, STATUSES, SUCCESS
from bearing_mbs.studies.sensitivity.models import RunModel
from bearing_mbs.studies.sensitivity.study import Study

#: A run that raised instead of returning a result.
ERROR = "error"
#: A run is attempted at most this often: a failure is retried once, then recorded with its error.
MAX_ATTEMPTS = 2


@dataclass(frozen=True)
class Run:
    """One run to evaluate: key (content hash), the canonical input mapping, the attempt number (1, 2)."""

    key: str
    inputs: dict
    attempt: int = 1


def run_key(model: RunModel, inputs: dict) -> str:
    """SHA-256 hex digest of the model name and the canonical input mapping."""
    text = json.dumps({"model": model.name, "inputs": inputs}, sort_keys=True, separators=(",", ":"),
                      allow_nan=False)
    return hashlib.sha256(text.encode()).hexdigest()


def plan(study: Study, X: np.ndarray) -> tuple[list[str], dict[str, Run]]:
    """The key of every row of X, and the distinct runs by key (first-seen order).

    Every row is validated by the model (a :class:`~bearing_mbs.spec.SpecError` names the row and its
    values), so bad input stops the study before anything runs.
    """
    from bearing_mbs.spec import SpecError

    X = np.asarray(X, dtype=float)
    if X.ndim != 2 or X.shape[1] != len(study.parameters):
        raise ValueError(f"X must be (n, {len(study.parameters)}), got {X.shape}")
    integer = [p.values is not None and all(isinstance(v, int) for v in p.values) for p in study.parameters]
    keys, runs = [], {}
    for row, x in enumerate(X):
        values = [int(v) if is_int else float(v) for v, is_int in zip(x, integer)]
        try:
            inputs = study.model.assign(tuple(study.names), values)
        except SpecError as error:
            point = ", ".join(f"{n}={v:g}" for n, v in zip(study.names, values))
            raise SpecError(f"sample {row}", point, f"is not a valid input: {error}") from None
        key = run_key(study.model, inputs)
        keys.append(key)
        runs.setdefault(key, Run(key, inputs))
    return keys, runs


def evaluate_runs(model: RunModel, runs: list[Run], keep_results: bool = False) -> list[dict]:
    """Evaluate runs one after the other (one Dask task). Each outcome: key, attempt, status
    (a run's own: ``success``, ``suspect``: it reached its end but failed a check, ``failed``: it stopped early,
    ``interrupted``; or ``error``: it raised), summary, error,
    wall_time_s [s], worker, files (name → bytes)."""
    outcomes = []
    for run in runs:
        start = time.perf_counter()
        outcome = {"key": run.key, "attempt": run.attempt, "worker": f"{socket.gethostname()}:{os.getpid()}"}
        try:
            summary, files = model.evaluate(run.inputs, keep_results)
            status = summary.get("status", SUCCESS)
            outcome.update(status=status if status in STATUSES else FAILED, summary=summary, error=None,
                           files=files)
        except Exception as error:  # a run's failure is its result, never the study's
            outcome.update(status=ERROR, summary=None, files={},
                           error=f"{type(error).__name__}: {error}\n{traceback.format_exc()}")
        outcome["wall_time_s"] = time.perf_counter() - start
        outcomes.append(outcome)
    return outcomes


def task_error(runs: list[Run], error: BaseException) -> list[dict]:
    """Outcomes of runs whose whole task failed (lost worker beyond Dask's allowed failures, a task that
    could not be sent, ...)."""
    message = f"{type(error).__name__}: {error} (the Dask task failed)"
    return [{"key": run.key, "attempt": run.attempt, "worker": None, "status": ERROR, "summary": None,
             "error": message, "files": {}, "wall_time_s": None} for run in runs]
