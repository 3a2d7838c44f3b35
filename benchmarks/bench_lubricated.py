"""One shaft revolution of the lubricated seed bearing (seed_hss_steady, its default variant: EHL raceways, churning
drag, cage on its land film, constraint cage, 1500 rpm, 68 kN) on each engine, and the quasi-static skidding
balance.

Figures:
* wall time per revolution of Exudyn generalized-alpha (compiled connector, 1e-5 s) and of the reference engine's
  RK4 at the step the advisor gives for this scene (half its RK4 stability limit); Exudyn's explicit solvers
  reject the constraint cage's joints;
* the advisor's RK4 stability limit, lubricated and dry (the variant "dry" with the same cage), and their ratio;
* the cost of a step of the reference engine's RK4, lubricated over dry, at one step (1e-7 s) over 2 ms: what
  the EHL traction and the films cost per force evaluation;
* the wall time of the quasi-static skidding balance of the same scene.
Targets: generalized-alpha ≤ 3 s per revolution on a 2-core machine; the lubricated explicit limit ≥ 5× the dry
one; the EHL step cost ≤ 2× the dry one. The revolution starts after a short warm-up (compilation excluded).
"""

from __future__ import annotations

import math
import time

from bearing_mbs.engines import simulate
from bearing_mbs.models import build_scene, load_spec
from bearing_mbs.models.cylindrical_roller.steady_skidding import solve_skidding
from bearing_mbs.numerics.advisor import advise

from common import SCENARIOS, write

REVOLUTION = 2 * math.pi / (1500 * 2 * math.pi / 60)  # 0.04 s
GA_STEP = 1e-5
COST_STEP, COST_TIME = 1e-7, 2e-3


def scene_of(variant: str, overrides: list[str]):
    spec = load_spec(SCENARIOS / "seed_hss_steady.toml", [f"scenario.variant={variant}", "analysis.start=0",
                                                          "solver.output_interval=1e-4", *overrides])
    return spec, build_scene(spec)


def revolution(overrides: list[str]) -> dict:
    spec, scene = scene_of("lubricated", [f"scenario.end_time={REVOLUTION}", *overrides])
    simulate(scene, spec.solver, 1e-3)  # warm-up: compilation and caches
    result = simulate(scene, spec.solver, REVOLUTION)
    stats = result.stats
    return {"status": result.status, "wall_time_s_per_revolution": stats.wall_time_s, "steps": stats.steps,
            "force_evaluations": stats.force_evaluations,
            "microseconds_per_step": stats.wall_time_s / stats.steps * 1e6}


def rk4_limit(variant: str) -> float:
    _, scene = scene_of(variant, ["cage.model=constraint"])
    return advise(scene).limit_and_mode("reference", "rk4")[0]


def step_cost(variant: str) -> float:
    """Microseconds per reference RK4 step at COST_STEP."""
    spec, scene = scene_of(variant, ["cage.model=constraint", f"scenario.end_time={COST_TIME}", "solver.engine=reference",
                                  "solver.reference.method=rk4", f"solver.reference.step={COST_STEP}"])
    simulate(scene, spec.solver, 1e-5)
    result = simulate(scene, spec.solver, COST_TIME)
    return result.stats.wall_time_s / result.stats.steps * 1e6


def main() -> dict:
    lubricated_limit, dry_limit = rk4_limit("lubricated"), rk4_limit("dry")
    explicit = f"{lubricated_limit / 2:.2g}"
    runs = {
        "exudyn_generalized_alpha_compiled": revolution(["solver.engine=exudyn",
                                                         "solver.exudyn.method=generalized_alpha",
                                                         f"solver.exudyn.step={GA_STEP}"]),
        "reference_rk4": revolution(["solver.engine=reference", "solver.reference.method=rk4",
                                     f"solver.reference.step={explicit}"]),
    }
    cost = {"lubricated": step_cost("lubricated"), "dry": step_cost("dry")}
    _, scene = scene_of("lubricated", [])
    start = time.perf_counter()
    slip = solve_skidding(scene).cage_slip
    balance = time.perf_counter() - start
    report = {
        "case": "seed_hss_steady (lubricated), constraint cage, one shaft revolution (0.04 s)",
        "ga_step_s": GA_STEP,
        "explicit_step_s": float(explicit),
        "runs": runs,
        "rk4_limit_s": {"lubricated": lubricated_limit, "dry": dry_limit},
        "reference_rk4_microseconds_per_step": cost,
        "quasi_static_balance": {"wall_time_s": balance, "cage_slip": slip},
        "targets": {
            "generalized_alpha_compiled_s_per_revolution": {
                "value": runs["exudyn_generalized_alpha_compiled"]["wall_time_s_per_revolution"], "target": "<= 3"},
            "explicit_limit_lubricated_over_dry": {"value": lubricated_limit / dry_limit, "target": ">= 5"},
            "step_cost_lubricated_over_dry": {"value": cost["lubricated"] / cost["dry"], "target": "<= 2"},
        },
    }
    write("lubricated_revolution", report)
    return report


if __name__ == "__main__":
    main()
