"""Nothing is lost when a worker or the driver dies mid-study: the study completes on re-running, with
every run present exactly once, and runs finished before the crash are neither repeated nor lost.

One local cluster (2 worker processes under nannies, loopback) serves the module; the killed driver is a
``bearing-mbs sweep`` subprocess attached to it by its scheduler address.
"""

import os
import signal
import sqlite3
import subprocess
import sys
import textwrap
import time
from pathlib import Path

import pytest

from bearing_mbs.core.progress import ProgressMeter
from bearing_mbs.studies.sensitivity import RunStore, connect, load_study, run_study
from bearing_mbs.studies.sensitivity.store import DATABASE

ROOT = Path(__file__).resolve().parents[1]
SEED_CASE2 = ROOT / "scenarios" / "seed_case2.toml"


@pytest.fixture(scope="module")
def client():
    with connect(workers=2) as client:
        yield client


def latin_study(tmp_path, samples: int) -> Path:
    """A Latin-hypercube study of seed_case2 (about 0.2 s a run), table and scatter plots only."""
    path = tmp_path / "study.toml"
    path.write_text(textwrap.dedent(f"""
        [study]
        name = "drop_latin"
        scenario = "{SEED_CASE2}"
        overrides = ["solver.reference.method=velocity_verlet", "solver.reference.step=1e-5"]
        outputs = ["restitution_effective", "max_penetration"]
        seed = 99
        [method]
        sampler = "latin"
        analyzer = "none"
        samples = {samples}
        [[parameters]]
        name = "contact.wall.restitution"
        bounds = [0.5, 0.95]
        [[parameters]]
        name = "contact.wall.stiffness"
        bounds = [2e6, 2e7]
        """))
    return path


def stored(out: Path) -> tuple[dict[str, str], int]:
    """({key: finished_at} of the rows, number of run directories) of an output directory."""
    with sqlite3.connect(f"file:{out / DATABASE}?mode=ro", uri=True) as db:
        rows = dict(db.execute("SELECT key, finished_at FROM runs"))
    directories = [d for d in (out / "runs").glob("*/*") if d.is_dir()]
    return rows, len(directories)


def rows_stored(out: Path) -> int:
    """Rows stored so far by a running driver (0 before its table exists)."""
    try:
        with sqlite3.connect(f"file:{out / DATABASE}?mode=ro", uri=True) as db:
            return db.execute("SELECT COUNT(*) FROM runs").fetchone()[0]
    except sqlite3.OperationalError:
        return 0


def assert_every_run_once(out: Path, planned: int) -> None:
    with sqlite3.connect(out / DATABASE) as db:
        total, distinct = db.execute("SELECT COUNT(*), COUNT(DISTINCT key) FROM runs").fetchone()
        statuses = dict(db.execute("SELECT status, COUNT(*) FROM runs GROUP BY status"))
    directories = [d.name for d in (out / "runs").glob("*/*")]
    assert total == distinct == planned == len(directories) == len(set(directories))
    assert statuses == {"success": planned}


class KillWorkerAfter(ProgressMeter):
    """Progress meter that SIGKILLs one worker process once ``after`` runs are stored."""

    def __init__(self, client, after: int):
        self.client, self.after, self.killed = client, after, None

    def update(self, value: float) -> None:
        if value >= self.after and self.killed is None:
            address, pid = sorted(self.client.run(os.getpid).items())[0]
            os.kill(pid, signal.SIGKILL)
            self.killed = (address, pid)


def test_killed_worker_loses_no_run(client, tmp_path):
    study = load_study(latin_study(tmp_path, 16))
    meter = KillWorkerAfter(client, after=3)
    result = run_study(study, tmp_path / "out", client=client, progress=meter, report=False)
    assert meter.killed is not None
    assert result.complete and result.stats.evaluated == 16
    assert_every_run_once(tmp_path / "out", 16)
    client.wait_for_workers(2, timeout=60)  # the nanny restarts the killed worker


def test_killed_driver_resumes_without_repeating_finished_runs(client, tmp_path):
    path = latin_study(tmp_path, 40)
    out = tmp_path / "out"
    log = (tmp_path / "driver.log").open("w")
    command = [sys.executable, "-m", "bearing_mbs.cli", "sweep", str(path), "--out", str(out),
               "--scheduler", client.scheduler.address, "--quiet", "--no-figures"]
    driver = subprocess.Popen(command, cwd=ROOT, stdout=log, stderr=subprocess.STDOUT, start_new_session=True)
    try:
        deadline = time.monotonic() + 120
        while rows_stored(out) < 3:
            assert driver.poll() is None, (tmp_path / "driver.log").read_text()
            assert time.monotonic() < deadline, "the driver stored no runs in 120 s"
            time.sleep(0.05)
        driver.kill()  # SIGKILL: no cleanup of any kind
        driver.wait(timeout=30)
    finally:
        if driver.poll() is None:
            os.killpg(driver.pid, signal.SIGKILL)
            driver.wait()
        log.close()
    rows_before, directories_before = stored(out)
    assert len(rows_before) < 40, "the driver finished before it was killed"

    result = run_study(load_study(path), out, client=client, report=False)

    assert result.complete
    assert result.stats.recovered == directories_before - len(rows_before)  # directory without row
    assert result.stats.evaluated == 40 - directories_before  # only what was not finished
    assert_every_run_once(out, 40)
    rows_after, _ = stored(out)
    assert {k: rows_after[k] for k in rows_before} == rows_before  # finished runs were not run again
    with RunStore(out) as store:  # and a third pass has nothing left to do
        assert store.finished() == set(rows_after)
