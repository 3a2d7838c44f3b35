"""``bearing-mbs slewing SCENARIO.toml --out DIR``: the quasi-static load distribution of a slewing bearing
(docs/slewing.md)."""

from __future__ import annotations

from bearing_mbs.models.slewing_bearing.spec import MODEL_NAME
from bearing_mbs.models.static_command import static_command


def _solve(spec, directory, figures):
    from bearing_mbs.models.slewing_bearing.static import write_slewing

    return write_slewing(spec, directory, figures=figures)


def _describe(summary) -> str:
    what = (f"{len(summary['axial_curve'])} curve points" if "axial_curve" in summary
            else f"displacement {summary['displacement']}")
    return (f"{summary['scenario']}: {summary['balls']} balls, {summary['rings']} rings, {what}, max ball load "
            f"{summary['max_ball_load']:.4g} N, max contact pressure {summary['max_contact_pressure'] / 1e6:.4g} MPa")


#: The model's subcommands.
COMMANDS = (static_command("slewing", "quasi-static load distribution of a four-point-contact slewing bearing "
                                      "(document 002; no simulation)", MODEL_NAME, _solve, _describe),)
