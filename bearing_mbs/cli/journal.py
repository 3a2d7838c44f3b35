"""``bearing-mbs journal SCENARIO.toml --out DIR``: the static solution of a fluid-film journal bearing
(docs/fluid-film.md)."""

from __future__ import annotations

from bearing_mbs.cli.static import register_static


def register(commands) -> dict:
    return register_static(commands, "journal", "static solution of a hydrostatic, hydrodynamic or hybrid journal "
                                                "bearing (document 001; no simulation)",
                           "journal_bearing", _solve, _describe)


def _solve(spec, directory, figures):
    from bearing_mbs.models.journal_bearing.static import write_journal

    return write_journal(spec, directory, figures=figures)


def _describe(summary) -> str:
    return (f"{summary['scenario']}: load {summary['load_capacity']:.4g} N at ε = {summary['eccentricity_ratio']:g}, "
            f"attitude {summary['attitude_angle']:.4g} deg, flow {summary['flow']:.4g} m³/s, "
            f"stiffness ΔF/Δe {summary['static_stiffness'] / 1e6:.4g} N/µm")
