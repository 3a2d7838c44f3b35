"""``bearing-mbs slewing SCENARIO.toml --out DIR``: the quasi-static load distribution of a slewing bearing
(docs/slewing.md)."""

from __future__ import annotations

from bearing_mbs.cli.options import add_output, add_overrides, output_directory


def register(commands) -> dict:
    slewing = commands.add_parser("slewing", help="quasi-static load distribution of a four-point-contact slewing "
                                                 "bearing (document 002; no simulation)")
    slewing.add_argument("scenario", help="scenario TOML file with model = 'slewing_bearing'")
    add_output(slewing, "output directory (new or empty, or give --overwrite): summary.json and figures")
    add_overrides(slewing)
    slewing.add_argument("--no-figures", action="store_true", help="skip the PNG figures")
    return {"slewing": _slewing}


def _slewing(args) -> int:
    """Exit 0: solved and written; 2: bad input (nothing written)."""
    from bearing_mbs.models import load_spec
    from bearing_mbs.models.slewing_bearing.spec import MODEL_NAME
    from bearing_mbs.models.slewing_bearing.static import write_slewing
    from bearing_mbs.spec import SpecError

    spec = load_spec(args.scenario, args.set)
    if spec.scenario.model != MODEL_NAME:
        raise SpecError("scenario.model", spec.scenario.model, f"{MODEL_NAME!r} for this command")
    summary = write_slewing(spec, output_directory(args), figures=not args.no_figures)
    what = (f"{len(summary['axial_curve'])} curve points" if "axial_curve" in summary
            else f"displacement {summary['displacement']}")
    print(f"{summary['scenario']}: {summary['balls']} balls, {what}, max ball load {summary['max_ball_load']:.4g} N, "
          f"max contact pressure {summary['max_contact_pressure'] / 1e6:.4g} MPa -> {args.out}")
    return 0
