"""One shaft revolution of seed_hss_steady's dry model (its variant "dry": the primary document's friction and
drag, penalty cage, 1500 rpm, 68 kN) on each engine's connectors and explicit loops, in one run: what a step costs
on each (the implicit settings against their errors are bench_revolution.py's).

Figures: wall time per revolution of
* Exudyn generalized-alpha, compiled connector, at the step that holds the cage speed to 0.1 % (``GA_STEP``,
  from the work–precision study in docs/numerics.md), and the same with the python connector;
* Exudyn RK44 (explicit), compiled connector, and the reference engine's RK4, at the same explicit step
  (``EXPLICIT_STEP``, below the explicit friction limit at this load).
Targets: generalized-alpha compiled ≤ 2 s per revolution on a 2-core machine; the reference engine ≥ 5× faster
per step than Exudyn explicit at the same step. The revolution starts after a short settling run (warm-up
and compilation excluded), from the settled state of each engine's own run.
"""

from __future__ import annotations

import math

from bearing_mbs.engines import simulate
from bearing_mbs.models import build_scene, load_spec

from common import SCENARIOS, write

REVOLUTION = 2 * math.pi / (1500 * 2 * math.pi / 60)  # 0.04 s
GA_STEP = 1e-5
EXPLICIT_STEP = 1e-7
RUNS = {
    "exudyn_generalized_alpha_compiled": ["solver.engine=exudyn", "solver.exudyn.method=generalized_alpha",
                                          f"solver.exudyn.step={GA_STEP}"],
    "exudyn_generalized_alpha_python": ["solver.engine=exudyn", "solver.exudyn.method=generalized_alpha",
                                        f"solver.exudyn.step={GA_STEP}", "solver.exudyn.connector=python"],
    "exudyn_rk4_compiled": ["solver.engine=exudyn", "solver.exudyn.method=rk4", f"solver.exudyn.step={EXPLICIT_STEP}"],
    "reference_rk4": ["solver.engine=reference", "solver.reference.method=rk4", f"solver.reference.step={EXPLICIT_STEP}"],
}


def measure(overrides: list[str]) -> dict:
    spec = load_spec(SCENARIOS / "seed_hss_steady.toml",
                     ["scenario.variant=dry", f"scenario.end_time={REVOLUTION}", "analysis.start=0",
                      "solver.output_interval=1e-4", *overrides])
    scene = build_scene(spec)
    simulate(scene, spec.solver, 1e-3)  # warm-up: compilation and caches
    result = simulate(scene, spec.solver, REVOLUTION)
    stats = result.stats
    return {"status": result.status, "wall_time_s_per_revolution": stats.wall_time_s, "steps": stats.steps,
            "force_evaluations": stats.force_evaluations, "newton_iterations": stats.newton_iterations,
            "microseconds_per_step": stats.wall_time_s / stats.steps * 1e6}


def main() -> dict:
    figures = {name: measure(overrides) for name, overrides in RUNS.items()}
    per_step = (figures["exudyn_rk4_compiled"]["microseconds_per_step"]
                / figures["reference_rk4"]["microseconds_per_step"])
    report = {
        "case": "seed_hss_steady (dry), penalty cage, one shaft revolution (0.04 s)",
        "ga_step_s": GA_STEP,
        "explicit_step_s": EXPLICIT_STEP,
        "runs": figures,
        "targets": {
            "generalized_alpha_compiled_s_per_revolution": {
                "value": figures["exudyn_generalized_alpha_compiled"]["wall_time_s_per_revolution"], "target": "<= 2"},
            "reference_speed_up_per_step_over_exudyn_explicit": {"value": per_step, "target": ">= 5"},
        },
    }
    write("engine_step_cost", report)
    return report


if __name__ == "__main__":
    main()
