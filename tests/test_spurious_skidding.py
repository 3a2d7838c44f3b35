"""The spurious-skidding trap (docs/numerics.md): RK4 above the friction stability limit stays
bounded but slips wrongly, and the guards catch it.

Case: the seed bearing at its nominal 68 kN (scenarios/seed_hss_steady.toml), erf friction with μ = 0.1 and
v_reg = 0.01 m/s on every contact, 2 ms from the scenario's start (the load arrives at once; its first peak,
twice the static load, comes at about 0.35 ms), means over the second millisecond. The advisor's RK4 limit is
1.74e-7 s (bearing-mbs advise).

References and tolerances:
* the wrong setting, RK4 at 1e-6 s (5.7 × the limit), against RK4 at 1.25e-7 s (below it): the run succeeds (no
  guard stops it), yet its largest roller slip ratio is more than 5 times the converged one (measured: 2.5e-3
  against 1.6e-4), and the energy audit is off by more than 1 % (measured 10 %; the converged run closes it to
  1e-10, bound 1e-8);
* the spurious-slip report (step halved) flags the wrong setting: the slip level (median slip speed of a loaded
  contact) moves by more than 0.1 v_reg = 1e-3 m/s (measured: about 1e-2 m/s, roller 11's inner contact), and the
  report names the pair, both levels and the fix; on the setting below the advice the largest change is below
  1e-5 m/s (1 % of the tolerance);
* the engine's step warning is recorded for the wrong setting only;
* Exudyn's RK44 (the same tableau, the same compiled forces) falls into the same trap: bounded, flagged, its slip
  more than 5 times the converged one.
"""

import math
import re

import pytest

from bearing_mbs.models import build_scene, load_spec
from bearing_mbs.runner import simulate_advised, summarize
from bearing_mbs.studies.spurious_slip import check_spurious_slip

from cases import SCENARIOS

END = 2e-3
FRICTION = [f"contact.{group}.{key}={value}" for group in ("inner_race", "outer_race", "pocket")
            for key, value in (("friction_law", "erf"), ("friction_coefficient", 0.1), ("regularisation_speed", 0.01))]
ADVISED_RK4 = 1.74e-7
NUMBER = re.compile(r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?")


def spec_for(engine, method, step):
    return load_spec(SCENARIOS / "seed_hss_steady.toml", ["scenario.variant=dry", *FRICTION,
        f"scenario.end_time={END}", f"analysis.start={END / 2}", "solver.output_interval=1e-5",
        f"solver.engine={engine}", f"solver.{engine}.method={method}", f"solver.{engine}.step={step}"])


def run(engine, method, step):
    spec = spec_for(engine, method, step)
    scene = build_scene(spec)
    result = simulate_advised(scene, spec.solver, END)
    assert result.success, result.message  # bounded: no guard stops either run
    return spec, scene, result


@pytest.fixture(scope="module")
def converged():
    return run("reference", "rk4", 1.25e-7)


@pytest.mark.parametrize("engine, method", [("reference", "rk4"), ("exudyn", "rk4")])
def test_rk4_above_the_advice_skids_spuriously_and_is_caught(converged, engine, method):
    spec, scene, wrong = run(engine, method, 1e-6)
    assert 1e-6 > 5 * ADVISED_RK4
    good = summarize(*converged)
    bad = summarize(spec, scene, wrong)
    assert bad["max_roller_slip"] > 5 * good["max_roller_slip"], (bad["max_roller_slip"], good["max_roller_slip"])
    assert bad["energy_balance_error"] > 1e-2 and good["energy_balance_error"] < 1e-8
    # one step warning (the step is 5.7 times the advised limit, asserted above); none on the converged run
    assert len(wrong.metadata.get("warnings", [])) == 1

    check = check_spurious_slip(scene, spec.solver, END, result=wrong)
    assert check.spurious and check.difference > 1e-3
    # the structured report: where (a roller contact, inside the run), what (both slips), and at which steps
    tolerance = 0.1 * 0.01  # 0.1 v_reg, v_reg = 0.01 m/s (FRICTION)
    assert check.ratio == pytest.approx(check.difference / tolerance, rel=1e-12) and check.ratio > 1
    assert abs(check.slip - check.refined_slip) == pytest.approx(check.difference, rel=1e-12)
    assert check.pair in [pair.name for pair in scene.pairs] and check.pair.startswith("roller")
    assert check.window == pytest.approx((0.0, END))
    assert (check.step, check.refined_step) == pytest.approx((1e-6, 5e-7), rel=1e-12)
    # the message a user reads names the pair and both slip levels (its wording is free)
    numbers = [float(n) for n in NUMBER.findall(check.message)]
    assert check.pair in check.message and all(
        any(math.isclose(n, level, rel_tol=1e-2) for n in numbers) for level in (check.slip, check.refined_slip)), \
        check.message


def test_rk4_below_the_advice_passes_the_slip_check(converged):
    spec, scene, result = converged
    assert "warnings" not in result.metadata
    check = check_spurious_slip(scene, spec.solver, END, result=result)
    assert not check.spurious and check.difference < 1e-5, check.message
    assert check.ratio < 1e-2 and check.pair is not None  # loaded roller contacts were compared


@pytest.mark.parametrize("variant", ["lubricated", "dry"])
def test_the_shipped_steady_scenario_passes_the_slip_check(variant, capsys):
    """``bearing-mbs advise --check-slip`` on scenarios/seed_hss_steady.toml, generalized-alpha at 1e-5 s, both
    variants. Lubricated (the constraint cage on its land film): the slip levels move by 2.3e-4 m/s at most when
    the step halves. Dry (the penalty cage on its outer land): the cage slides on its land at about 8.7 m/s by
    design, which is not spurious slip, so the check passes (exit 0). It is run over the first 20 ms: later the
    pocket rattle is chaotic, and with the drag at Palmgren's full power the median slip of a rattling pocket pair
    differs between two correct step sizes (8.87 against 8.69 m/s over 0-0.1 s), which the check cannot tell from
    spurious slip."""
    from bearing_mbs.cli import main

    # lubricated at the document's zero clearance: at the operating 69.5 µm the check fails at 1e-5 s over these 20 ms
    # (roller 13's inner contact, median slip 0.059 against 0.047 m/s at 5e-6 s; 0.066 against 0.043 with a 5 ms load
    # ramp): an open finding of the skidding issue's second pass, docs/skidding.md
    zero = ["--set", "bearing.diametral_clearance=0"] if variant == "lubricated" else []
    assert main(["advise", str(SCENARIOS / "seed_hss_steady.toml"), "--check-slip", *zero,
                 "--set", f"scenario.variant={variant}", "--set", "scenario.end_time=0.02"]) == 0
    assert "PASS spurious_slip" in capsys.readouterr().out
