"""``bearing-mbs sweep`` against a real Dask cluster: a ``dask scheduler`` and two ``dask worker``
processes on loopback, started and stopped by this module; and bad input that exits with status 2."""

import os
import signal
import socket
import sqlite3
import subprocess
import sys
import textwrap
from pathlib import Path

import pytest

from bearing_mbs.cli import main
from bearing_mbs.studies.sensitivity.store import DATABASE

ROOT = Path(__file__).resolve().parents[1]
SEED_CASE2 = ROOT / "scenarios" / "seed_case2.toml"
DASK = Path(sys.executable).with_name("dask")


def free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def stop(process: subprocess.Popen) -> None:
    """SIGTERM the process group we started (a worker's nanny and its worker), SIGKILL if it lingers."""
    if process.poll() is not None:
        return
    os.killpg(process.pid, signal.SIGTERM)
    try:
        process.wait(timeout=15)
    except subprocess.TimeoutExpired:
        os.killpg(process.pid, signal.SIGKILL)
        process.wait()


@pytest.fixture(scope="module")
def scheduler(tmp_path_factory):
    from dask.distributed import Client

    logs = tmp_path_factory.mktemp("dask")
    address = f"tcp://127.0.0.1:{free_port()}"
    processes = []

    def start(name, *arguments):
        with (logs / f"{name}.log").open("w") as log:
            processes.append(subprocess.Popen([str(DASK), *arguments], stdout=log, stderr=subprocess.STDOUT,
                                              cwd=ROOT, start_new_session=True))

    try:
        start("scheduler", "scheduler", "--host", "127.0.0.1", "--port", address.rsplit(":", 1)[1],
              "--no-dashboard")
        for i in range(2):
            start(f"worker{i}", "worker", address, "--nthreads", "1", "--nworkers", "1", "--host", "127.0.0.1",
                  "--no-dashboard", "--name", f"worker{i}")
        with Client(address, timeout=60) as client:
            client.wait_for_workers(2, timeout=60)
            pids = set(client.run(os.getpid).values())
        yield address, pids
    finally:
        for process in reversed(processes):
            stop(process)


def small_study(tmp_path) -> Path:
    path = tmp_path / "study.toml"
    path.write_text(textwrap.dedent(f"""
        [study]
        name = "drop_grid"
        scenario = "{SEED_CASE2}"
        overrides = ["solver.reference.method=velocity_verlet", "solver.reference.step=1e-5"]
        outputs = ["restitution_effective"]
        [method]
        sampler = "grid"
        [[parameters]]
        name = "contact.wall.restitution"
        values = [0.6, 0.75, 0.9]
        [[parameters]]
        name = "balls.0.mass"
        values = [0.05, 0.1]
        """))
    return path


def test_sweep_on_a_dask_scheduler_and_two_workers(scheduler, tmp_path, capsys):
    address, worker_pids = scheduler
    out = tmp_path / "out"
    status = main(["sweep", str(small_study(tmp_path)), "--out", str(out), "--scheduler", address,
                   "--workers", "2", "--quiet"])
    assert status == 0, capsys.readouterr().err
    with sqlite3.connect(out / DATABASE) as db:
        rows = db.execute("SELECT status, worker FROM runs").fetchall()
    assert len(rows) == 6 and {s for s, _ in rows} == {"success"}
    assert {int(w.rsplit(":", 1)[1]) for _, w in rows} <= worker_pids  # run by the dask workers
    report = (out / "report" / "report.md").read_text()
    assert "drop_grid" in report and "scatter_restitution_effective.png" in report
    assert main(["sweep", str(small_study(tmp_path)), "--out", str(out), "--scheduler", address, "--quiet"]) == 0
    assert "0 runs evaluated now, 6 already stored" in capsys.readouterr().out


def test_unreachable_scheduler_is_a_clear_error(tmp_path, capsys):
    out = tmp_path / "out"
    status = main(["sweep", str(small_study(tmp_path)), "--out", str(out), "--scheduler",
                   f"tcp://127.0.0.1:{free_port()}", "--quiet"])
    assert status == 2
    assert "--scheduler" in capsys.readouterr().err
    assert not (out / "runs").exists()


def test_bad_study_exits_2_before_anything_runs(tmp_path, capsys):
    path = small_study(tmp_path)
    path.write_text(path.read_text().replace("balls.0.mass", "balls.0.weight"))
    assert main(["sweep", str(path), "--out", str(tmp_path / "out"), "--quiet"]) == 2
    err = capsys.readouterr().err
    assert "parameters.1.name" in err and "balls.0.weight" in err
    assert not (tmp_path / "out").exists()
