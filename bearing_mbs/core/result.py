"""The result of a simulation, identical in layout for both engines, and its lossless storage.

A result is saved as one ``.npz`` file: the arrays as they are, plus a JSON header with the statistics,
status, names and the spec mapping that produced it. :meth:`Result.load` restores it bit for bit.
"""

from __future__ import annotations

import json
from dataclasses import asdict, dataclass, field, fields
from pathlib import Path

import numpy as np

from bearing_mbs.contact.kernel import PAIR_OUTPUTS
from bearing_mbs.contact.state import EVENT_COLUMNS
from bearing_mbs.core.checks import Check
from bearing_mbs.core.failures import Failure
from bearing_mbs.core.topology import Topology

#: The status values (docs/status.md): ``success`` only when the run reached its end and every check passed;
#: ``suspect`` when it reached its end but a check failed; ``failed`` when it stopped early; ``interrupted``
#: when the user stopped it.
SUCCESS, SUSPECT, FAILED, INTERRUPTED = "success", "suspect", "failed", "interrupted"
STATUSES = (SUCCESS, SUSPECT, FAILED, INTERRUPTED)


@dataclass
class Stats:
    """Cost of a run. ``force_evaluations`` counts evaluations of all scene forces (one per RK stage,
    Newton residual or Jacobian column); ``None`` where an engine cannot count (Exudyn's native connector)."""

    steps: int = 0
    rejected_steps: int = 0
    force_evaluations: int | None = 0
    newton_iterations: int = 0
    jacobian_evaluations: int = 0
    wall_time_s: float = 0.0


@dataclass
class Result:
    """Time series at output instants plus statistics.

    time [s] (T,); position and velocity (T, 3N): (x, y, θ) and (vx, vy, ω) per body; pair_output
    (T, P, len(PAIR_OUTPUTS)): gap [m], gap_rate [m/s], slip [m/s], normal_force [N], friction_force [N],
    rolling_moment [N m], power_loss [W], rolling_speed [m/s]; constraint_forces (T, C): the force of each
    constraint on its second body [N]; work (T, 2): cumulative work supplied by loads and drives and work
    dissipated by the contacts [J], integrated by the engine step by step; events (P, 4): first impact and
    separation of each pair. Sensors a scene does not list (:attr:`bearing_mbs.core.scene.Scene.sensors`) are left
    empty. ``failure`` is the kind of an early stop (:class:`~bearing_mbs.core.failures.Failure`, ``NONE`` when the
    run reached its end); ``message`` says why, in words made from the kind and the state where the run stopped.
    ``checks`` are the checks the finished run was held to (:mod:`bearing_mbs.core.checks`; the runner adds them).
    ``status`` follows from the failure and the checks (:data:`STATUSES`). ``topology`` is the scene's: which body
    and pair is which.
    """

    engine: str
    method: str
    step: float
    time: np.ndarray
    position: np.ndarray
    velocity: np.ndarray
    pair_output: np.ndarray
    constraint_forces: np.ndarray
    work: np.ndarray
    events: np.ndarray
    body_names: tuple[str, ...]
    pair_names: tuple[str, ...]
    stats: Stats = field(default_factory=Stats)
    failure: Failure = Failure.NONE
    message: str = ""
    topology: Topology = field(default_factory=Topology)
    spec: dict | None = None
    metadata: dict = field(default_factory=dict)
    checks: tuple[Check, ...] = ()

    def __post_init__(self):
        self.failure = Failure(self.failure)
        self.checks = tuple(c if isinstance(c, Check) else Check.from_dict(c) for c in self.checks)

    @property
    def status(self) -> str:
        if self.failure == Failure.INTERRUPTED:
            return INTERRUPTED
        if self.failure != Failure.NONE:
            return FAILED
        return SUCCESS if all(check.passed for check in self.checks) else SUSPECT

    @property
    def completed(self) -> bool:
        """The engine reached the end time (whatever the checks say)."""
        return self.failure == Failure.NONE

    @property
    def success(self) -> bool:
        """Reached the end and passed every check."""
        return self.status == SUCCESS

    @property
    def status_note(self) -> str | None:
        """What a figure of this result must say about it: None for ``success``; else the status with the failed
        checks, or where and why the run stopped."""
        status = self.status
        if status == SUCCESS:
            return None
        if status == SUSPECT:
            return f"{status}: failed checks: {', '.join(check.name for check in self.failed_checks)}"
        stopped = f" at t = {float(self.time[-1]):.6g} s" if self.time.size else ""
        return f"{status}{stopped} ({self.failure}): the numbers reach the stop only"

    @property
    def failed_checks(self) -> tuple[Check, ...]:
        return tuple(check for check in self.checks if not check.passed)

    def body(self, name: str) -> int:
        return self.body_names.index(name)

    def pair(self, name: str) -> int:
        return self.pair_names.index(name)

    def pair_series(self, quantity: str) -> np.ndarray:
        """(T, P) series of one of :data:`PAIR_OUTPUTS`."""
        return self.pair_output[:, :, PAIR_OUTPUTS.index(quantity)]

    def event(self, pair: str, column: str) -> float:
        return float(self.events[self.pair(pair), EVENT_COLUMNS.index(column)])

    _ARRAYS = ("time", "position", "velocity", "pair_output", "constraint_forces", "work", "events")

    def save(self, path: str | Path) -> Path:
        """Write ``path`` (``.npz``) atomically: a crash never leaves a half-written file."""
        path = Path(path)
        header = {f.name: getattr(self, f.name) for f in fields(self) if f.name not in self._ARRAYS}
        header["stats"] = asdict(self.stats)
        header["failure"] = int(self.failure)
        header["topology"] = self.topology.to_dict()
        header["checks"] = [check.to_dict() for check in self.checks]
        temporary = path.with_name(path.name + ".part")
        with temporary.open("wb") as handle:
            np.savez_compressed(
                handle, header=np.array(json.dumps(header)), **{name: getattr(self, name) for name in self._ARRAYS}
            )
        temporary.replace(path)
        return path

    @classmethod
    def load(cls, path: str | Path) -> Result:
        with np.load(Path(path), allow_pickle=False) as data:
            header = json.loads(str(data["header"]))
            arrays = {name: data[name] for name in cls._ARRAYS}
        header["stats"] = Stats(**header["stats"])
        header["body_names"] = tuple(header["body_names"])
        header["pair_names"] = tuple(header["pair_names"])
        header["topology"] = Topology.from_dict(header.get("topology", {}))
        return cls(**header, **arrays)
