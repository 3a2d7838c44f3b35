"""Figures say their status: every figure of a run that is not ``success`` carries the status (and why) on it, so
a figure copied into a report is never read as a valid result; a successful run's figures carry nothing."""

from __future__ import annotations

import pytest

from bearing_mbs.cli import main
from bearing_mbs.core.failures import Failure
from bearing_mbs.core.result import FAILED, SUCCESS, SUSPECT, Result
from bearing_mbs.io import figures

from cases import SCENARIOS


@pytest.fixture
def stamps(monkeypatch):
    """The notes stamped on figures, one per figure drawn with one."""
    notes = []
    original = figures.stamp_status

    def record(figure, note):
        notes.append(note)
        original(figure, note)

    monkeypatch.setattr(figures, "stamp_status", record)
    return notes


def _run(tmp_path, scenario, *overrides):
    out = tmp_path / "run"
    main(["run", str(SCENARIOS / scenario), "--out", str(out), "--quiet", *[a for o in overrides for a in ("--set", o)]])
    pngs = sorted(out.glob("*.png"))
    return Result.load(out / "result.npz"), pngs


def test_a_suspect_bearing_run_stamps_every_figure(tmp_path, stamps):
    # RK4 at 6x the advised stability limit: bounded, but its step and energy checks fail
    result, pngs = _run(tmp_path, "seed_hss_steady.toml", "solver.engine=reference", "solver.reference.step=1e-5",
                        "scenario.end_time=0.002", "analysis.start=0.001")
    assert result.status == SUSPECT and len(pngs) == 4
    assert len(stamps) == len(pngs) and all(note.startswith(SUSPECT) for note in stamps)
    assert all(check.name in stamps[0] for check in result.failed_checks)


def test_a_failed_run_stamps_its_figures_and_a_successful_one_does_not(tmp_path, stamps):
    # case 2's ball on a floor 1e5 times softer: it sinks past the penetration guard and the run stops
    result, pngs = _run(tmp_path, "seed_case2.toml", "contact.wall.stiffness=60", "scenario.end_time=0.1")
    assert result.status == FAILED and result.failure == Failure.PENETRATION and pngs
    assert len(stamps) == len(pngs) and all(note.startswith(FAILED) for note in stamps)
    stamps.clear()
    result, pngs = _run(tmp_path / "good", "seed_case2.toml", "scenario.end_time=0.01")
    assert result.status == SUCCESS and pngs and not stamps


def test_the_stamp_is_drawn_on_the_figure():
    figure, axis = figures.new_figure()
    axis.set_title("a title")
    figures.stamp_status(figure, "failed at t = 0.1 s (blowup): the numbers reach the stop only")
    texts = [text.get_text() for text in figure.texts]
    assert "FAILED" in texts and any(text.startswith("failed at t = 0.1 s") for text in texts)
    assert axis.get_position().y1 < 1 - figures.STATUS_BAND + 1e-9  # the axes made room for the band
