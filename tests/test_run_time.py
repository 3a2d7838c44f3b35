"""An end time far beyond what the machine can run is refused before anything runs, naming ``scenario.end_time``,
with an estimate of the run time (the steps at the run's step, times the cost of a step measured by a short probe);
one beyond an hour is warned about; a sane run costs no probe."""

from __future__ import annotations

import pytest

from bearing_mbs.cli import main
from bearing_mbs.models import build_scene, load_spec
from bearing_mbs.runner import run_spec, run_time
from bearing_mbs.spec import SpecError

from cases import SCENARIOS

STEADY = SCENARIOS / "seed_hss_steady.toml"


def test_an_end_time_of_a_billion_seconds_is_refused_by_name(tmp_path, capsys):
    out = tmp_path / "out"
    code = main(["run", str(STEADY), "--out", str(out), "--quiet", "--set", "scenario.end_time=1e9"])
    assert code == 2 and not out.exists()
    spec = load_spec(STEADY, ["scenario.end_time=1e9"])
    with pytest.raises(SpecError) as refused:
        run_spec(spec)
    assert refused.value.field == "scenario.end_time"


def test_the_estimate_counts_the_steps_and_measures_their_cost():
    spec = load_spec(STEADY, ["solver.engine=reference", "solver.reference.step=1e-6", "scenario.end_time=1e6"])
    estimate = run_time.estimate_run_time(build_scene(spec), spec.solver, 1e6)
    assert estimate.step == 1e-6 and estimate.steps == pytest.approx(1e12, rel=1e-12)
    # a step of the 17-body bearing costs far more than the floor that decides whether to measure
    assert estimate.step_cost > 10 * run_time.MIN_STEP_COST
    assert estimate.run_time == pytest.approx(estimate.steps * estimate.step_cost, rel=1e-12)


def test_an_adaptive_method_is_counted_at_the_advisors_step():
    spec = load_spec(STEADY, ["solver.engine=reference", "solver.reference.method=dopri5",
                              "solver.reference.step=1e-3"])
    scene = build_scene(spec)
    from bearing_mbs.numerics.advisor import advise

    assert run_time.run_step(scene, spec.solver) == pytest.approx(advise(scene).limit("reference", "dopri5"))


def test_a_sane_run_is_not_probed_and_a_long_one_is_warned_about(monkeypatch):
    probes = []
    original = run_time.simulate
    monkeypatch.setattr(run_time, "simulate", lambda *args, **kwargs: probes.append(args) or original(*args, **kwargs))
    spec = load_spec(STEADY, ["solver.engine=reference", "scenario.end_time=0.5"])
    scene = build_scene(spec)
    assert run_time.require_feasible_run_time(scene, spec.solver, 0.5) == [] and not probes
    monkeypatch.setattr(run_time, "WARN_RUN_TIME", 1e-6)  # any measured run is "long"
    monkeypatch.setattr(run_time, "MIN_STEP_COST", 1e-12)
    warnings = run_time.require_feasible_run_time(scene, spec.solver, 0.5)
    assert len(probes) == 1 and len(warnings) == 1
