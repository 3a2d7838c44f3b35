"""What both engines do around their own stepping: one place for the run guards and the :class:`Result`.

An engine owns how it steps (the reference engine's compiled driver, Exudyn's solver) and how it sees the state
(a compiled guard, a post-step function). Everything around that is the same for both and lives here:

* the run's frame (:func:`timed_run`): the progress meter started and always closed, and the wall time [s] of the
  stepping alone (compilation is done before it);
* the guards on the state (:func:`state_guard`, for an engine that sees its state in Python): a non-finite
  coordinate, then a body faster than ``speed_limit``, stop the run, the kinds the reference driver's compiled
  guard (``integrators.check_state``) gives; the stop's message is made from the kind and the state where the
  run stopped (:func:`bearing_mbs.engines.diagnosis.failure_message`), whichever engine stopped;
* the output a stopped run keeps (:class:`Series`, :meth:`Series.kept`): every output instant computed, then the
  state where the run stopped;
* the :class:`~bearing_mbs.core.result.Result` itself (:func:`assemble_result`), of the same layout for both.

Interrupts (SIGINT, SIGTERM) reach both engines as a :class:`~bearing_mbs.core.interrupt.StopRequest` that each
polls where it can (:func:`stop_request`).
"""

from __future__ import annotations

import contextlib
import time
from dataclasses import dataclass
from typing import NamedTuple

import numpy as np

from bearing_mbs.core.failures import Failure
from bearing_mbs.core.interrupt import StopRequest
from bearing_mbs.core.progress import ProgressMeter
from bearing_mbs.core.result import Result, Stats
from bearing_mbs.core.scene import Scene


def progress_meter(progress: ProgressMeter | None) -> ProgressMeter:
    """The caller's meter, or the silent default."""
    return progress or ProgressMeter()


def stop_request(stop: StopRequest | None) -> StopRequest:
    """The caller's stop request, or one nobody sets (a run called outside :func:`bearing_mbs.engines.simulate`)."""
    return stop or StopRequest()


@dataclass
class RunClock:
    """The wall time [s] of a run's stepping, set when its :func:`timed_run` block ends."""

    wall_time_s: float = 0.0


@contextlib.contextmanager
def timed_run(progress: ProgressMeter, end_time: float, description: str):
    """Start the meter over simulated time [0, ``end_time``] [s], time the block, and close the meter however
    the block ends (a stop, a failure, an exception)."""
    progress.start(end_time, description)
    clock = RunClock()
    started = time.perf_counter()
    try:
        yield clock
    finally:
        clock.wall_time_s = time.perf_counter() - started
        progress.close()


def state_guard(q: np.ndarray, v: np.ndarray, speed_limit: float) -> tuple[Failure, int]:
    """The guard on a state of planar bodies (x, y, θ per body): ``NONFINITE`` with the first non-finite
    coordinate, else ``BLOWUP`` with the x coordinate of the fastest body when it moves faster than
    ``speed_limit`` [m/s], else ``NONE`` and -1."""
    finite = np.isfinite(q) & np.isfinite(v)
    if not finite.all():
        return Failure.NONFINITE, int(np.flatnonzero(~finite)[0])
    speed = np.hypot(v[0::3], v[1::3])
    if speed.max() > speed_limit:
        return Failure.BLOWUP, 3 * int(np.argmax(speed))
    return Failure.NONE, -1


class Series(NamedTuple):
    """A run's output, one row per output instant: time [s] (T,), position and velocity (T, 3N), pair outputs
    (T, P, K), work supplied and dissipated [J] (T, 2), constraint forces [N] (T, C)."""

    time: np.ndarray
    position: np.ndarray
    velocity: np.ndarray
    pair_output: np.ndarray
    work: np.ndarray
    constraint_forces: np.ndarray

    @classmethod
    def from_rows(cls, rows) -> Series:
        """Stack rows ``(t, q, v, pair_output, work, constraint_forces)`` into series."""
        return cls(*(np.array([row[i] for row in rows]) for i in range(len(cls._fields))))

    def kept(self, computed: int, stop_row=None) -> Series:
        """What a stopped run keeps: the first ``computed`` rows (the output instants it reached), then
        ``stop_row``, the state where it stopped, when given (None: the last instant is already where it
        stopped)."""
        head = Series(*(a[:computed] for a in self))
        if stop_row is None:
            return head
        return Series(*(np.concatenate([a, np.asarray(b)[None]]) for a, b in zip(head, stop_row)))


def assemble_result(engine: str, settings, scene: Scene, series: Series, events: np.ndarray, stats: Stats,
                    failure: Failure, message: str, spec: dict | None, metadata: dict | None = None) -> Result:
    """The :class:`Result` of a run of ``scene`` by ``engine`` with its ``settings`` (method and step [s]): the
    series, the pairs' events, the cost, how it ended, and the names and topology that say which body and pair
    is which."""
    return Result(
        engine=engine, method=settings.method, step=settings.step, time=series.time, position=series.position,
        velocity=series.velocity, pair_output=series.pair_output, constraint_forces=series.constraint_forces,
        work=series.work, events=events, body_names=tuple(b.name for b in scene.bodies),
        pair_names=tuple(p.name for p in scene.pairs), stats=stats, failure=failure, message=message, spec=spec,
        topology=scene.topology, metadata=metadata if metadata is not None else {},
    )
