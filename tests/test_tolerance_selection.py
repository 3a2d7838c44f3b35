"""``[solver] tolerance``: ask for a cage-speed error, get the cheapest measured setting within it
(bearing_mbs/numerics/work_precision.py, docs/numerics.md "Ask for an error").

The choice is checked against small made-up tables whose answers are worked out by hand here (the cheapest setting
on the engine whose measured error is within the tolerance and whose slips converged, its step capped by the
advisor's stable step or the run's largest step, its cost scaled by the step ratio); the refusals by the field
they name; and one real run of the lubricated seed bearing at 1e-3 against a finer run of another method.
"""

from __future__ import annotations

import json
import math

import pytest

from bearing_mbs.cli import main
from bearing_mbs.cli.options import BAD_INPUT
from bearing_mbs.engines import simulate
from bearing_mbs.models import MODELS, build_scene, load_spec
from bearing_mbs.numerics import work_precision
from bearing_mbs.numerics.advisor import advise
from bearing_mbs.numerics.work_precision import Bounds, MeasuredSetting, WorkPrecisionTable, choose
from bearing_mbs.runner import run_spec, spec_for_run, summarize
from bearing_mbs.spec import SpecError
from bearing_mbs.spec.methods import (
    CENTRAL_DIFFERENCE,
    DOPRI5,
    EXUDYN,
    GENERALIZED_ALPHA,
    REFERENCE,
    RK4,
)
from bearing_mbs.studies.common import solver_at
from bearing_mbs.studies.convergence import errors

from cases import SCENARIOS, seed_spec

SEED = SCENARIOS / "seed_hss_steady.toml"


def setting(name, engine, method, step, error, cost, slips=True, status="success", **more) -> MeasuredSetting:
    return MeasuredSetting(name, engine, {"method": method.name, "step": step, "tolerance": 1e-6, **more}, error,
                           slips, status, cost)


#: A made-up table. Reference engine, by cost: "failed" (cost 0.5, its run failed), "loose" (1, error 2e-3),
#: "skids" (2, error 1e-6 but slips not converged), "rk4" (3, error 1e-9, explicit at 1e-6 s), "tight" (5, error
#: 1e-7), "adaptive" (6, dopri5, error 1e-10); Exudyn: "exudyn_slow" (8, 1e-8), "exudyn_fast" (4, 1e-4, at 5e-5 s).
TABLE = WorkPrecisionTable("made_up", {"scenario": "none"}, {"date": "never"}, (
    setting("failed", REFERENCE, GENERALIZED_ALPHA, 1e-4, 1e-9, 0.5, status="failed"),
    setting("loose", REFERENCE, GENERALIZED_ALPHA, 1e-4, 2e-3, 1.0),
    setting("skids", REFERENCE, GENERALIZED_ALPHA, 5e-5, 1e-6, 2.0, slips=False),
    setting("rk4", REFERENCE, RK4, 1e-6, 1e-9, 3.0),
    setting("tight", REFERENCE, GENERALIZED_ALPHA, 2e-5, 1e-7, 5.0),
    setting("adaptive", REFERENCE, DOPRI5, 1e-4, 1e-10, 6.0),
    setting("exudyn_slow", EXUDYN, GENERALIZED_ALPHA, 1e-5, 1e-8, 8.0),
    setting("exudyn_fast", EXUDYN, GENERALIZED_ALPHA, 5e-5, 1e-4, 4.0),
))


def bounds(rk4_recommended=1e-5, largest=math.inf) -> Bounds:
    """The advisor's recommended step for RK4 only (none for any other explicit method)."""
    return Bounds(lambda method: rk4_recommended if method is RK4 else None, largest)


@pytest.mark.parametrize(("engine", "tolerance", "expected"), [
    (REFERENCE, 1e-2, "loose"),  # the cheapest sound setting: 1 s, error 2e-3 <= 1e-2
    (REFERENCE, 1e-3, "rk4"),  # "loose" misses it, "skids" skids, "failed" failed: rk4 at 3 s
    (REFERENCE, 1e-9, "rk4"),  # within, at equality
    (REFERENCE, 5e-10, "adaptive"),  # only the adaptive one: 1e-10
    (EXUDYN, 1e-3, "exudyn_fast"),  # the other engine's table: 4 s against 8 s
    (EXUDYN, 1e-5, "exudyn_slow"),
])
def test_the_choice_is_the_cheapest_sound_setting_within_the_tolerance(engine, tolerance, expected):
    choice = choose(TABLE, engine, tolerance, bounds())
    assert choice.setting.name == expected
    assert choice.caps == () and choice.settings == choice.setting.settings


def test_an_explicit_step_above_the_advisors_recommended_step_is_capped_and_costs_more():
    # rk4 measured at 1e-6 s and 3 s/s. Advised 2.5e-7 s: it would run at 2.5e-7 s, 4x the steps, 12 s/s, so
    # "tight" (5 s/s) wins at 1e-3 and "adaptive" (6 s/s) at 5e-9.
    assert choose(TABLE, REFERENCE, 1e-3, bounds(rk4_recommended=2.5e-7)).setting.name == "tight"
    assert choose(TABLE, REFERENCE, 5e-9, bounds(rk4_recommended=2.5e-7)).setting.name == "adaptive"
    # Advised 6e-7 s: 3 x 1e-6 / 6e-7 = 5 s/s, below "adaptive"'s 6: rk4 at 6e-7 s
    choice = choose(TABLE, REFERENCE, 5e-9, bounds(rk4_recommended=6e-7))
    assert choice.setting.name == "rk4"
    assert choice.settings["step"] == 6e-7 and choice.setting.settings["step"] == 1e-6
    assert choice.expected_cost == pytest.approx(5.0, rel=1e-12)
    assert [cap["field"] for cap in choice.caps] == ["step"]
    assert choice.caps[0]["set_by"] == work_precision.ADVISED_STEP


def test_an_explicit_fixed_step_method_without_advice_is_not_chosen():
    # no recommended step for this scene: rk4 is passed over, though cheapest at 1e-3 ("tight" instead)
    assert choose(TABLE, REFERENCE, 1e-3, bounds(rk4_recommended=None)).setting.name == "tight"


def test_the_advisor_caps_the_contact_step_of_the_central_difference():
    table = WorkPrecisionTable("cd", {}, {}, (
        setting("cd", REFERENCE, CENTRAL_DIFFERENCE, 1e-6, 1e-8, 2.0, contact_step=5e-7),))
    choice = choose(table, REFERENCE, 1e-3, Bounds(lambda method: 1e-7))
    assert choice.settings["contact_step"] == 1e-7 and choice.settings["step"] == 1e-6
    assert choice.expected_cost == pytest.approx(10.0, rel=1e-12)  # 2 s/s x 5e-7 / 1e-7


def test_a_step_above_the_largest_the_run_allows_is_capped_and_may_lose_to_another():
    # Exudyn at an output interval of 2e-5 s: exudyn_fast's 5e-5 s capped to 2e-5 s costs 4 x 2.5 = 10 s/s > 8
    choice = choose(TABLE, EXUDYN, 1e-3, bounds(largest=2e-5))
    assert choice.setting.name == "exudyn_slow" and choice.caps == ()
    capped = choose(TABLE, EXUDYN, 1e-3, bounds(largest=4e-5))  # 4 x 1.25 = 5 s/s < 8
    assert capped.setting.name == "exudyn_fast" and capped.settings["step"] == 4e-5
    assert capped.expected_cost == pytest.approx(5.0, rel=1e-12)
    assert capped.caps[0]["set_by"] == work_precision.LARGEST_STEP


def test_a_tolerance_no_measured_setting_meets_is_refused_naming_the_field():
    with pytest.raises(SpecError) as refused:
        choose(TABLE, REFERENCE, 1e-11, bounds())
    assert refused.value.field == "solver.tolerance" and refused.value.value == 1e-11
    assert "1e-10" in refused.value.allowed  # the smallest error measured: the adaptive setting's


def test_an_engine_without_a_sound_setting_is_refused():
    table = WorkPrecisionTable("x", {}, {}, (setting("skids", EXUDYN, GENERALIZED_ALPHA, 1e-5, 1e-8, 1, slips=False),))
    with pytest.raises(SpecError) as refused:
        choose(table, EXUDYN, 1e-3, bounds())
    assert refused.value.field == "solver.tolerance"


def test_a_table_survives_its_file_as_strict_json(tmp_path):
    path = work_precision.write_tables(tmp_path / "tables.json", [TABLE], "made up")
    json.loads(path.read_text(), parse_constant=lambda name: pytest.fail(f"{name} in strict JSON"))
    work_precision.read_tables.cache_clear()
    table = work_precision.read_tables(path)["made_up"]
    assert table == TABLE
    failed = WorkPrecisionTable("nan", {}, {}, (setting("x", REFERENCE, RK4, 1e-6, math.nan, 1.0, status="failed"),))
    path = work_precision.write_tables(tmp_path / "nan.json", [failed], "a failed run")
    assert math.isnan(work_precision.read_tables(path)["nan"].settings[0].cage_speed_error)


def lubricated(overrides=()):
    return load_spec(SEED, ["solver.engine=reference", *overrides])


@pytest.mark.parametrize("value", ["0", "1", "-1e-3", "1.5", "nan", "'abc'", "true"])
def test_bad_tolerances_are_refused_naming_the_field(value):
    with pytest.raises(SpecError) as refused:
        lubricated([f"solver.tolerance={value}"])
    assert refused.value.field == "solver.tolerance"


def test_a_model_without_work_precision_data_is_refused_naming_the_field():
    spec = seed_spec(2, ["solver.tolerance=1e-3"])  # the ball drop (model "balls"): no tables
    with pytest.raises(SpecError) as refused:
        spec_for_run(spec, build_scene(spec))
    assert refused.value.field == "solver.tolerance" and refused.value.value == spec.scenario.model


def test_a_scene_no_table_describes_is_refused_naming_the_field():
    spec = lubricated(["solver.tolerance=1e-3", "cage.model=penalty"])  # EHL raceways with the penalty cage
    with pytest.raises(SpecError) as refused:
        spec_for_run(spec, build_scene(spec))
    assert refused.value.field == "solver.tolerance" and refused.value.value == 1e-3


def test_an_unattainable_tolerance_is_refused_by_the_command_line_before_anything_runs(tmp_path, capsys):
    code = main(["run", str(SEED), "--out", str(tmp_path / "out"), "--quiet", "--set", "solver.tolerance=1e-15"])
    assert code == BAD_INPUT
    assert "solver.tolerance" in capsys.readouterr().err
    assert not (tmp_path / "out" / "summary.json").exists()


def test_without_a_tolerance_the_spec_runs_as_written():
    spec = lubricated()
    assert spec.solver.tolerance is None
    assert spec_for_run(spec, build_scene(spec)) == (spec, None)


def test_the_chosen_setting_replaces_the_section_and_respects_the_real_advisor(monkeypatch):
    # The made-up table as the lubricated bearing's, with the scene's own advisor: rk4 (measured at 1e-6 s, 3 s/s)
    # runs at min(1e-6 s, the recommended step) for 3 s/s x the step ratio, and wins at 1e-3 if that is below
    # "tight"'s 5 s/s, else "tight" wins (either way, worked out from the recommended step here).
    spec = lubricated(["solver.tolerance=1e-3"])
    variant = MODELS[spec.scenario.model].work_precision.variant(spec)
    monkeypatch.setattr(work_precision, "read_tables", lambda path: {variant: TABLE})
    scene = build_scene(spec)
    recommended = advise(scene).recommended(REFERENCE, RK4.name)
    assert recommended is not None
    run_as, choice = spec_for_run(spec, scene)
    expected_rk4_cost = 3.0 * max(1e-6 / recommended, 1.0)
    expected = "rk4" if expected_rk4_cost < 5.0 else "tight"  # "tight": 5 s/s
    assert choice.choice.setting.name == expected
    assert run_as.solver.reference.method == choice.choice.settings["method"]
    assert run_as.solver.reference.step == (min(1e-6, recommended) if expected == "rk4" else 2e-5)
    assert choice.replaced == {"method": RK4.name, "step": 1e-7, "tolerance": 1e-6, "spectral_radius": 0.9}
    assert run_as.solver.exudyn == spec.solver.exudyn  # the other engine's section is untouched


def test_the_real_tables_are_described_and_provenanced():
    data = MODELS[lubricated().scenario.model].work_precision
    tables = work_precision.read_tables(data.path)
    assert set(tables) == set(data.variants)
    for table in tables.values():
        assert table.provenance["date"] and table.provenance["machine"] and table.provenance["command"]
        assert "commit" in table.provenance
        assert {s.engine for s in table.settings} == {REFERENCE, EXUDYN}
        assert all(s.cost > 0 and s.settings["step"] > 0 for s in table.settings)


def test_the_lubricated_seed_bearing_at_1e_3_runs_the_chosen_setting_within_it():
    """One real run: seed_hss_steady lubricated, ``solver.tolerance = 1e-3`` on the reference engine, to 20 ms; its
    mean cage speed over the scenario's error window (10-20 ms, ``[convergence]``) against the reference engine's
    RK4 at its advised stability limit 1.6e-6 s, a method of another order and far more accurate than 1e-3 (it agrees
    with RK4 at 8e-7 s to 2.9e-7 on this window, measured 2026-11-27): the error must be within the tolerance
    asked, whichever setting the table gives."""
    end = ["scenario.end_time=0.02", "analysis.start=0.01", "solver.output_interval=1e-4"]
    spec = lubricated(["solver.tolerance=1e-3", *end])
    scene, result = run_spec(spec)
    assert result.status == "success"
    summary = summarize(spec, scene, result)
    chosen = summary["solver_choice"]["settings"]
    assert result.method == chosen["method"] == summary["solver"]
    assert result.step == pytest.approx(chosen["step"], rel=1e-7) and summary["step"] == chosen["step"]
    assert (result.method, result.step) != (spec.solver.reference.method, spec.solver.reference.step)
    assert summary["solver_choice"]["expected_cage_speed_error"] <= 1e-3
    assert summary["solver_choice"]["source"] == "bearing_mbs/models/cylindrical_roller/work_precision.json"
    finer = simulate(scene, solver_at(spec.solver, REFERENCE, RK4.name, 1.6e-6, largest_step=1.6e-6),
                     spec.scenario.end_time)
    assert finer.success
    assert errors(spec, scene, result, finer)["cage_speed"] <= 1e-3


@pytest.mark.slow
def test_the_dry_seed_bearing_at_1e_3_on_exudyn_runs_within_it():
    """The other engine and variant: seed_hss_steady dry, ``solver.tolerance = 1e-3`` on Exudyn, to 15 ms; its mean
    cage speed over the dry variant's error window (5-15 ms) against the reference engine's RK4 at 1e-7 s (below the
    dry bearing's advised RK4 limit 1.74e-7 s; docs/numerics.md: RK4 at 1.6e-7 s is within 1.1e-9 of RK4 at
    2.5e-8 s)."""
    spec = load_spec(SEED, ["scenario.variant=dry", "solver.engine=exudyn", "solver.tolerance=1e-3",
                            "scenario.end_time=0.015", "analysis.start=0.005", "solver.output_interval=1e-4"])
    scene, result = run_spec(spec)
    assert result.success and result.engine == EXUDYN
    assert summarize(spec, scene, result)["solver_choice"]["variant"] == "dry"
    finer = simulate(scene, solver_at(spec.solver, REFERENCE, RK4.name, 1e-7, largest_step=1e-7),
                     spec.scenario.end_time)
    assert finer.success
    assert errors(spec, scene, result, finer)["cage_speed"] <= 1e-3


@pytest.mark.parametrize(("overrides", "variant"), [
    (["bearing.diametral_clearance=0"], "lubricated"),
    (["bearing.diametral_clearance=-1e-5"], "lubricated"),  # a preload does not rattle either
    ([], "lubricated_operating_clearance"),  # the shipped 69.5 um
    (["scenario.variant=dry"], "dry"),
])
def test_a_lubricated_bearing_with_a_clearance_takes_its_own_table(overrides, variant):
    """Its rollers rattle in the clearance: steps sound at zero clearance are not there (docs/numerics.md)."""
    spec = lubricated(overrides)
    assert MODELS[spec.scenario.model].work_precision.variant(spec) == variant
