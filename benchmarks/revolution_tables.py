"""Write the tables of docs/numerics.md section 5 ("One revolution", "Scaling with the number of rollers") from
``benchmarks/out/bearing_revolution.json``, between their ``<!-- revolution -->`` and ``<!-- scaling -->`` markers,
so the docs say what the last benchmark run measured: ``python benchmarks/revolution_tables.py``."""

from __future__ import annotations

import json
import re
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
FIGURES = ROOT / "benchmarks" / "out" / "bearing_revolution.json"
DOC = ROOT / "docs" / "numerics.md"
TITLES = {
    "lubricated": "**Lubricated, zero clearance** (the document's; errors over 10–20 ms against RK4 at its fine step",
    "dry": "**Dry** (errors over 5–15 ms against RK4 at its fine step",
    "lubricated_operating_clearance": "**Lubricated, operating clearance** (the shipped variant's 69.5 µm; the load "
                                      "applied at t = 0 drops the ring onto its rollers; errors over 10–20 ms",
}
COLUMNS = "| setting | s per revolution | cage-speed error | slip error | steps | Newton iterations | Jacobians | " \
          "force evaluations |\n|---|---:|---:|---:|---:|---:|---:|---:|"


def run_row(name: str, run: dict) -> str:
    if run["status"] != "success":
        return f"| {name} | {run['wall_time_s_per_revolution']:.3g} | {run['status']} | | {run['steps']} | " \
               f"{run['newton_iterations']} | {run['jacobian_evaluations']} | {run['force_evaluations']} |"
    slips = f"{run['slip_error']:.1e}" + ("" if run["slips_converged"] else " (not converged)")
    return (f"| {name} | {run['wall_time_s_per_revolution']:.3g} | {run['cage_speed_error']:.1e} | {slips} | "
            f"{run['steps']} | {run['newton_iterations']} | {run['jacobian_evaluations']} | "
            f"{run['force_evaluations']} |")


def model_table(model: str, figures: dict) -> str:
    reference = figures["fine_references"][model]
    rows = [run_row(name.split("/")[-1], run) for name, run in figures["runs"].items() if run["model"] == model]
    summary = figures["summary"][model]
    best, exudyn = summary["best"], summary["best_exudyn_analytic"]
    lines = [f"{TITLES[model]}; slips converged within {reference['slip_error_bound']:.1e}):", "", COLUMNS, *rows, ""]
    if best:
        text = (f"Best sound setting at 0.1 %: `{best.split('/')[-1]}`, "
                f"{summary['best_wall_time_s_per_revolution']:.3g} s per revolution, "
                f"{summary['speed_up_best_over_baseline']:.1f}× faster than `baseline`")
        if exudyn:
            text += (f"; Exudyn at its best (`{exudyn.split('/')[-1]}`), "
                     f"{summary['speed_up_exudyn_analytic_over_baseline']:.1f}× faster than `baseline`, "
                     f"{summary['exudyn_best_over_reference_best']:.1f}× the reference engine's best")
        lines.append(text + ".")
    else:
        lines.append("No setting is sound at 0.1 % (cage-speed error ≤ 1e-3 with converged slips).")
    return "\n".join(lines) + "\n"


def scaling_table(figures: dict) -> str:
    lines = [("| model, best setting | Z = 15 | Z = 30 | Z = 60 | p (cost ∝ Z^p) | Jacobians, Z = 15 / 30 / 60 | "
              "wall time per force evaluation [µs], Z = 15 / 30 / 60 | p per evaluation |"),
             "|---|---:|---:|---:|---:|---:|---:|---:|"]
    for model, scaled in figures.get("scaling", {}).items():
        rollers = scaled["rollers"]
        best = figures["summary"][model]["best"].split("/")[-1]
        lines.append(f"| {model}, {best} | " + " | ".join(f"{rollers[z]['wall_time_s_per_revolution']:.2g} s"
                                                         for z in ("15", "30", "60"))
                     + f" | {scaled['cost_exponent_in_rollers']:.1f} | "
                     + " / ".join(str(rollers[z]["jacobian_evaluations"]) for z in ("15", "30", "60")) + " | "
                     + " / ".join(f"{rollers[z]['microseconds_per_force_evaluation']:.0f}" for z in ("15", "30", "60"))
                     + f" | {scaled['cost_per_evaluation_exponent_in_rollers']:.1f} |")
    return "\n".join(lines) + "\n"


def replace_between(text: str, marker: str, body: str) -> str:
    pattern = re.compile(rf"(<!-- {marker} -->\n).*?(<!-- /{marker} -->)", re.DOTALL)
    if not pattern.search(text):
        raise SystemExit(f"{DOC} has no <!-- {marker} --> ... <!-- /{marker} --> section")
    return pattern.sub(lambda m: m.group(1) + body + m.group(2), text)


def main() -> None:
    figures = json.loads(FIGURES.read_text())
    models = [model for model in TITLES if model in figures["fine_references"]]
    targets = figures.get("targets", {})
    target_lines = [f"* {name}: {value['value']:.3g} (target {value['target']})" if value["value"] is not None
                    else f"* {name}: none sound (target {value['target']})" for name, value in targets.items()]
    machine = figures["machine"]
    revolution = (f"Measured {machine['date']} ({machine['cpu_count']} cores, load average "
                  f"{machine['load_average'][0]:.2f} at the end).\n\n"
                  + "\n".join(model_table(model, figures) for model in models)
                  + "\nTargets (lubricated, zero clearance):\n\n" + "\n".join(target_lines) + "\n\n")
    text = replace_between(DOC.read_text(), "revolution", revolution)
    DOC.write_text(replace_between(text, "scaling", scaling_table(figures)))
    print(f"wrote the tables of {DOC}")


if __name__ == "__main__":
    main()
