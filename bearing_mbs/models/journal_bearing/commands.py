"""``bearing-mbs journal SCENARIO.toml --out DIR``: the static solution of a fluid-film journal bearing
(docs/fluid-film.md)."""

from __future__ import annotations

from bearing_mbs.models.journal_bearing.spec import MODEL_NAME
from bearing_mbs.models.static_command import static_command


def _solve(spec, directory, figures):
    from bearing_mbs.models.journal_bearing.static import write_journal

    return write_journal(spec, directory, figures=figures)


def _describe(summary) -> str:
    def number(key, scale=1.0):  # undefined quantities (an attitude at zero load) are null in the summary
        return "undefined" if summary[key] is None else f"{summary[key] * scale:.4g}"

    return (f"{summary['scenario']}: load {number('load_capacity')} N at ε = {summary['eccentricity_ratio']:g}, "
            f"attitude {number('attitude_angle')} deg, flow {number('flow')} m³/s, "
            f"stiffness ΔF/Δe {number('static_stiffness', 1e-6)} N/µm")


#: The model's subcommands.
COMMANDS = (static_command("journal", "static solution of a hydrostatic, hydrodynamic or hybrid journal bearing "
                                      "(document 001; no simulation)", MODEL_NAME, _solve, _describe),)
