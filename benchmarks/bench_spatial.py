"""The bearing in three dimensions against the planar model: wall time per revolution (issue 31's last acceptance
line: one revolution at most 10 times the planar model's best setting).

The seed HSS bearing, its dry variant as the scenario has it (penalty cage on its outer land, Lankarani–Nikravesh
contacts, rolling resistance, Palmgren's drag), 68 kN, 1500 rpm, from rolling start, 10 straight slices per roller
contact and the planar laws alone, explicit RK4 at 2e-7 s (the dry planar model's advised RK4
limit is 1.74e-7 s: docs/numerics.md) on both engines, over ``SPAN`` and scaled to a revolution (0.04 s); the planar
model on the reference engine's RK4 at the same step over the same span, and the planar model's best setting per
revolution of the dry bearing from ``benchmarks/out/bearing_revolution.json`` (its generalized-α, measured there).
Writes ``benchmarks/out/spatial_revolution.json``.
"""

from __future__ import annotations

import json
import time

from bearing_mbs.engines import simulate
from bearing_mbs.engines.exudyn.spatial import simulate_spatial_exudyn
from bearing_mbs.engines.reference.spatial import simulate_spatial_reference
from bearing_mbs.models import build_scene, load_spec
from bearing_mbs.models.cylindrical_roller.spatial import build_spatial_bearing

from common import OUT, SCENARIOS, machine, write

REVOLUTION = 60 / 1500  # s
STEP, SPAN = 2e-7, 2e-3  # s
OVERRIDES = ["scenario.variant=dry", "solver.engine=reference", "solver.reference.method=rk4",
             f"solver.reference.step={STEP}", "solver.output_interval=1e-4"]


def timed(run) -> float:
    """Wall time [s] of ``run()`` after a short warm-up run (compilation outside the figure)."""
    run(1e-5)
    started = time.perf_counter()
    run(SPAN)
    return time.perf_counter() - started


def planar_best() -> float | None:
    """The planar model's best setting per revolution of the dry bearing [s], from the revolution benchmark."""
    path = OUT / "bearing_revolution.json"
    if not path.exists():
        return None
    return json.loads(path.read_text())["summary"]["dry"]["best_wall_time_s_per_revolution"]


def main() -> dict:
    spec = load_spec(SCENARIOS / "seed_hss_steady.toml", OVERRIDES)
    scene, bearing = build_scene(spec), build_spatial_bearing(spec, damping_time=0.0)
    per_revolution = REVOLUTION / SPAN
    figures = {
        "spatial_reference_rk4": timed(lambda end: simulate_spatial_reference(bearing.scene, STEP, end, 1e-4))
        * per_revolution,
        "spatial_exudyn_rk4": timed(lambda end: simulate_spatial_exudyn(bearing.scene, STEP, end, 1e-4))
        * per_revolution,
        "planar_reference_rk4": timed(lambda end: simulate(scene, spec.solver, end)) * per_revolution,
    }
    best = planar_best()
    report = {
        "unit": "wall time [s] per revolution (0.04 s at 1500 rpm), scaled from the span",
        "step_s": STEP, "span_s": SPAN, "slices": 10, "bodies": len(bearing.scene.bodies),
        "sliced_contacts": len(bearing.scene.raceways), "flange_contacts": len(bearing.scene.flanges),
        "figures": figures,
        "planar_best_per_revolution_s": best,
        "spatial_over_planar_same_step": figures["spatial_reference_rk4"] / figures["planar_reference_rk4"],
        "spatial_best_over_planar_best": (min(figures["spatial_reference_rk4"], figures["spatial_exudyn_rk4"]) / best
                                          if best else None),
        "target_ratio": 10.0,
        "machine_load_at_start": machine()["load_average"],
    }
    write("spatial_revolution", report)
    for name, value in figures.items():
        print(f"{name}: {value:.2f} s per revolution")
    if best:
        print(f"3-D best / planar best: {report['spatial_best_over_planar_best']:.0f} (target 10)")
    return report


if __name__ == "__main__":
    main()
