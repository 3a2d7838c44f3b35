"""Stopping a run on request (SIGINT, SIGTERM) without losing what it computed.

Engines poll a :class:`StopRequest` between steps (Exudyn, in its post-step function) or between short compiled
chunks (the reference engine) and end the run with :attr:`~bearing_mbs.core.failures.Failure.INTERRUPTED`,
keeping every output instant already computed. :func:`stop_on_signals` turns SIGINT and SIGTERM into such a
request for the duration of a block (a command, or one run); a second signal of the same kind restores the
default behaviour, so a user can still force an exit. Inside the block, :func:`active_request` is the request:
every later run of the block sees it set and stops at its start, so a study ends with what it computed;
:func:`stop_requested` lets a command skip follow-up work.
"""

from __future__ import annotations

import contextlib
import contextvars
import signal
import threading

_ACTIVE: contextvars.ContextVar[StopRequest | None] = contextvars.ContextVar("bearing_mbs_stop_request",
                                                                             default=None)


class StopRequest:
    """A flag an engine polls; ``signal_number`` is the signal that set it (None: set from code)."""

    def __init__(self):
        self._event = threading.Event()
        self.signal_number: int | None = None

    def set(self, signal_number: int | None = None) -> None:
        self.signal_number = signal_number
        self._event.set()

    def is_set(self) -> bool:
        return self._event.is_set()


def active_request() -> StopRequest | None:
    """The request of the innermost :func:`stop_on_signals` block, or None outside any."""
    return _ACTIVE.get()


def stop_requested() -> bool:
    """Whether the user asked the current block to stop."""
    request = _ACTIVE.get()
    return request is not None and request.is_set()


@contextlib.contextmanager
def stop_on_signals(request: StopRequest, signals=(signal.SIGINT, signal.SIGTERM)):
    """While the block runs, SIGINT and SIGTERM set ``request`` instead of raising; outside the main thread
    (a Dask worker) nothing is installed and the block runs as it is."""
    token = _ACTIVE.set(request)
    if threading.current_thread() is not threading.main_thread():
        try:
            yield request
        finally:
            _ACTIVE.reset(token)
        return
    previous = {number: signal.getsignal(number) for number in signals}

    def handle(number, frame):
        if request.is_set():  # asked twice: give the signal its default meaning back
            signal.signal(number, previous[number])
            signal.raise_signal(number)
            return
        request.set(number)

    for number in signals:
        signal.signal(number, handle)
    try:
        yield request
    finally:
        for number, handler in previous.items():
            signal.signal(number, handler)
        _ACTIVE.reset(token)
