"""Injectable progress meters: silent in the library, tqdm bars in the command line.

Every long command shows one format: simulated time against end time for a run, runs done against the total for
a study (whose runs also say which one of how many they are), each with an estimated time of arrival.
:func:`notice_if_slow` says what is happening while a one-off cost (compiling the kernels) takes its time.
"""

from __future__ import annotations

import contextlib
import logging
import threading

log = logging.getLogger("bearing_mbs")

#: The run bar: simulated time [s] against the end time, elapsed wall time and estimated time left.
RUN_FORMAT = "{desc}: {percentage:3.0f}%|{bar}| {n:.4g}/{total:.4g} s simulated [{elapsed}<{remaining}]"
#: The study bar: runs done against the total.
STUDY_FORMAT = "{desc}: {percentage:3.0f}%|{bar}| {n:.0f}/{total:.0f} runs [{elapsed}<{remaining}]"


class ProgressMeter:
    """Receives simulated time (or finished runs); the default does nothing."""

    def start(self, total: float, description: str = "") -> None:
        pass

    def update(self, value: float) -> None:
        pass

    def close(self) -> None:
        pass

    def next_run(self, index: int, total: int) -> None:
        """A study announces that run ``index`` (from 1) of ``total`` comes next."""


class TqdmProgress(ProgressMeter):
    """A tqdm bar over simulated time (:data:`RUN_FORMAT`); in a study, prefixed with ``run k/N``."""

    _bar_format = RUN_FORMAT

    def __init__(self):
        self._run = ""

    def start(self, total: float, description: str = "") -> None:
        from tqdm import tqdm

        self._bar = tqdm(total=total, desc=f"{self._run}{description}", bar_format=self._bar_format, leave=False)
        self._value = 0.0

    def update(self, value: float) -> None:
        self._bar.update(value - self._value)
        self._value = value

    def close(self) -> None:
        self._bar.close()

    def next_run(self, index: int, total: int) -> None:
        self._run = f"run {index}/{total} "


class TqdmRunProgress(TqdmProgress):
    """A tqdm bar over finished runs (:data:`STUDY_FORMAT`), for studies that run many at once (a sweep)."""

    _bar_format = STUDY_FORMAT

    def start(self, total: float, description: str = "") -> None:
        from tqdm import tqdm

        self._bar = tqdm(total=int(total), desc=description, bar_format=self._bar_format, smoothing=0.1)
        self._value = 0


@contextlib.contextmanager
def notice_if_slow(message: str, after: float = 2.0):
    """Log ``message`` if the block is still running after ``after`` seconds (a compilation, say)."""
    timer = threading.Timer(after, log.info, (message,))
    timer.daemon = True
    timer.start()
    try:
        yield
    finally:
        timer.cancel()
