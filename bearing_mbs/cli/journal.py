"""``bearing-mbs journal SCENARIO.toml --out DIR``: the static solution of a fluid-film journal bearing
(docs/fluid-film.md)."""

from __future__ import annotations

from bearing_mbs.cli.options import add_output, add_overrides, output_directory


def register(commands) -> dict:
    journal = commands.add_parser("journal", help="static solution of a hydrostatic, hydrodynamic or hybrid journal "
                                                 "bearing (document 001; no simulation)")
    journal.add_argument("scenario", help="scenario TOML file with model = 'journal_bearing'")
    add_output(journal, "output directory (new or empty, or give --overwrite): summary.json and figures")
    add_overrides(journal)
    journal.add_argument("--no-figures", action="store_true", help="skip the PNG figures")
    return {"journal": _journal}


def _journal(args) -> int:
    """Exit 0: solved and written; 2: bad input (nothing written)."""
    from bearing_mbs.models import load_spec
    from bearing_mbs.models.journal_bearing.spec import MODEL_NAME
    from bearing_mbs.models.journal_bearing.static import write_journal
    from bearing_mbs.spec import SpecError

    spec = load_spec(args.scenario, args.set)
    if spec.scenario.model != MODEL_NAME:
        raise SpecError("scenario.model", spec.scenario.model, f"{MODEL_NAME!r} for this command")
    summary = write_journal(spec, output_directory(args), figures=not args.no_figures)
    for warning in summary["warnings"]:
        print(f"warning: {warning}")
    print(f"{summary['scenario']}: load {summary['load_capacity']:.4g} N at ε = {summary['eccentricity_ratio']:g}, "
          f"attitude {summary['attitude_angle']:.4g} deg, flow {summary['flow']:.4g} m³/s, "
          f"stiffness ΔF/Δe {summary['static_stiffness'] / 1e6:.4g} N/µm -> {args.out}")
    return 0
