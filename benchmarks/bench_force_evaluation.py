"""Cost of one evaluation of all contact forces, for each connector and engine, measured in one run.

Scenes: the document's case 4 (two balls in a box, 7 pairs) with the annex's erf friction. Figures:
* ``kernel`` / ``numpy_twin``: one call from Python of the compiled kernel and of its numpy twin;
* ``exudyn_<connector>``: wall time of an Exudyn RK44 run divided by its force evaluations (everything
  Exudyn does per evaluation is included); for ``native`` (no counter) by 4 × steps;
* ``reference_rk4``: the same for the reference engine.
Ratios are to the compiled kernel in the same run; compare ratios, not seconds, across machines.
"""

from __future__ import annotations

import numpy as np

from bearing_mbs.contact.kernel import N_PAIR_OUTPUTS
from bearing_mbs.elements import pack_scene, scene_forces, scene_forces_twin
from bearing_mbs.engines import simulate
from bearing_mbs.models import build_scene, load_spec

from common import SCENARIOS, best_of, write

END_TIME, STEP = 0.02, 1e-6  # the first ball–floor contacts fall inside the window


def per_call(function, calls):
    return best_of(lambda: [function() for _ in range(calls)]) / calls


def main() -> dict:
    friction = ["contact.wall.friction_law=erf", "contact.ball.friction_law=erf"]
    spec = seed_spec(4, friction + [f"scenario.end_time={END_TIME}"])
    scene = build_scene(spec)
    packed = pack_scene(scene)
    q, v = scene.initial_state()
    q[1] = 0.0049  # ball 1 touching the floor: one active contact
    latched = np.zeros(len(scene.pairs))
    forces, pair_out = np.empty(q.size), np.empty((len(scene.pairs), N_PAIR_OUTPUTS))
    figures = {
        "kernel": per_call(lambda: scene_forces(packed, 0.0, q, v, latched, forces, pair_out), 20000),
        "numpy_twin": per_call(lambda: scene_forces_twin(packed, 0.0, q, v, latched, forces, pair_out), 2000),
    }
    runs = {f"exudyn_{c}": ["solver.engine=exudyn", "solver.exudyn.method=rk4", f"solver.exudyn.step={STEP}",
                            f"solver.exudyn.connector={c}"] for c in ("compiled", "python")}
    runs["reference_rk4"] = ["solver.reference.method=rk4", f"solver.reference.step={STEP}"]
    for name, overrides in runs.items():
        run_spec = seed_spec(4, friction + [f"scenario.end_time={END_TIME}", *overrides])
        simulate(scene, run_spec.solver, END_TIME)  # warm-up (compilation, caches)
        result = min((simulate(scene, run_spec.solver, END_TIME) for _ in range(3)), key=lambda r: r.stats.wall_time_s)
        figures[name] = result.stats.wall_time_s / result.stats.force_evaluations
    # native: normal forces only, so compare it on the frictionless case 2 against the compiled connector there
    native = {}
    for connector in ("compiled", "native"):
        run_spec = seed_spec(2, ["scenario.end_time=0.1", "solver.engine=exudyn", "solver.exudyn.method=rk4",
                                 f"solver.exudyn.step={STEP}", f"solver.exudyn.connector={connector}"])
        case2 = build_scene(run_spec)
        simulate(case2, run_spec.solver, 0.1)
        result = min((simulate(case2, run_spec.solver, 0.1) for _ in range(3)), key=lambda r: r.stats.wall_time_s)
        native[connector] = result.stats.wall_time_s / (4 * result.stats.steps)
    report = {
        "unit": "seconds per force evaluation",
        "case4_7_pairs": figures,
        "case4_ratio_to_kernel": {k: v / figures["kernel"] for k, v in figures.items()},
        "case2_1_pair_rk4_per_stage": native,
        "case2_native_over_compiled": native["native"] / native["compiled"],
    }
    write("force_evaluation", report)
    return report


if __name__ == "__main__":
    main()


def seed_spec(case: int, overrides: list[str]):
    """The primary document's case ``case`` (``scenarios/seed_caseN.toml``) with ``--set``-style overrides."""
    return load_spec(SCENARIOS / f"seed_case{case}.toml", overrides)
