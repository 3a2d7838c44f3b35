"""The subcommands the cylindrical roller bearing offers ``bearing-mbs``: ``stiffness`` (its quasi-static solution),
``static-check``, ``skidding``, ``skidding-map`` and ``cage-models`` (its studies), ``spatial`` (a run in three
dimensions). Each is a
:class:`~bearing_mbs.models.protocol.Command`; ``cli`` is the :class:`~bearing_mbs.models.protocol.CommandLine`
the command line lends them (shared options, output directory, exit codes, the study services)."""

from __future__ import annotations

import math

from bearing_mbs.models.protocol import Command
from bearing_mbs.spec import SpecError, methods


def _stiffness_arguments(parser, cli) -> None:
    parser.add_argument("scenario", help="bearing scenario TOML file (model = 'cylindrical_roller')")
    cli.add_output(parser, "output directory (new or empty, or give --overwrite): summary.json and "
                           "load_distribution.png")
    cli.add_overrides(parser)
    parser.add_argument("--no-figures", action="store_true", help="skip the PNG figure")


def _stiffness(args, cli) -> int:
    """Exit 0: success; 3: suspect (a check failed; docs/status.md); 2: bad input, or a load the bearing cannot
    carry (nothing written)."""
    from bearing_mbs.models.cylindrical_roller.stiffness import require_bearing, write_stiffness

    spec = cli.services.load_spec(args.scenario, args.set)
    require_bearing(spec)
    summary = write_stiffness(spec, cli.output_directory(args), figures=not args.no_figures)
    cli.print_outcome(summary, lambda s: (f"{s['scenario']}: displacement {s['radial_displacement']:.4g} m, max "
                                          f"roller load {s['max_roller_load']:.4g} N, K_xx "
                                          f"{s['stiffness_matrix'][0][0]:.4g} N/m, K_yy "
                                          f"{s['stiffness_matrix'][1][1]:.4g} N/m"), args.out)
    return cli.exit_code(summary["status"])


def _static_check_arguments(parser, cli) -> None:
    parser.add_argument("scenario", help="bearing scenario TOML file (the repository's: scenarios/static_check.toml)")
    cli.add_output(parser, "output directory: static_check.json (new or empty, or give --overwrite)")
    parser.add_argument("--engines", default="exudyn,reference", help="comma-separated engines to check")
    parser.add_argument("--loads", default="5e3,20e3,68e3",
                        help="comma-separated external loads [N] along the scenario's [load] angle")
    parser.add_argument("--stiffness-load", type=float, default=20e3, metavar="N",
                        help="load [N] of the finite-difference stiffness (default 20e3)")
    parser.add_argument("--no-stiffness", action="store_true", help="skip the finite-difference stiffness")
    cli.add_overrides(parser, "override any spec field of the scenario (repeatable)")


def _static_check(args, cli) -> int:
    """Exit 0: every run succeeded and settled; 3: some are suspect (a failed check, or a window that did not
    settle); 1: some run stopped early (all are written); 2: bad input, nothing ran."""
    from bearing_mbs.models.cylindrical_roller.studies import static_check

    engines = cli.names(args.engines)
    directory = cli.output_directory(args)
    check = static_check.run(cli.services, args.scenario, cli.numbers("--loads", args.loads), engines,
                             overrides=args.set, stiffness_load=None if args.no_stiffness else args.stiffness_load)
    path = static_check.write(check, directory)
    print(static_check.report(check))
    print(f"-> {path}")
    return cli.exit_code(check.statuses)


def _skidding_arguments(parser, cli) -> None:
    parser.add_argument("scenario", help="bearing scenario TOML file at constant speed, the base of the sweep")
    cli.add_output(parser, "output directory: skidding_vs_load.{csv,md,png} (new or empty, or give --overwrite)")
    parser.add_argument("--loads", default="68000,6800,2000,680,200", help="comma-separated radial loads [N]")
    parser.add_argument("--cages", default="penalty,constraint", help="comma-separated cage models")
    cli.add_overrides(parser, "override any spec field of the base scenario, e.g. scenario.end_time=0.3 "
                              "(repeatable)")
    parser.add_argument("--no-figures", action="store_true", help="skip the PNG figure")
    parser.add_argument("--quiet", action="store_true", help="no progress bar")


def _skidding(args, cli) -> int:
    """Exit 0: every run succeeded; 3: some are suspect (a failed check, or a window that did not settle); 1: some
    stopped early (all are written); 2: bad input, nothing ran."""
    from bearing_mbs.models.cylindrical_roller.studies import skidding

    cages = cli.names(args.cages)
    for name in cages:
        if name not in skidding.CAGES:
            raise SpecError("--cages", name, f"must be among {', '.join(skidding.CAGES)}")
    spec, loads = cli.services.load_spec(args.scenario, args.set), cli.numbers("--loads", args.loads)
    sweeps = skidding.run(cli.services, spec, cli.output_directory(args), loads,
                          {name: skidding.CAGES[name] for name in cages}, figures=not args.no_figures,
                          progress=cli.progress(args.quiet))
    print(skidding.markdown_table(sweeps))
    print(skidding.trend_text(sweeps) + skidding.status_text(sweeps) + f"-> {args.out}")
    return cli.exit_code([row["status"] for rows in sweeps.values() for row in rows])


def _skidding_map_arguments(parser, cli) -> None:
    parser.add_argument("scenario", help="lubricated bearing scenario TOML file at constant speed")
    cli.add_output(parser, "output directory: skidding_map.{csv,md,png} and roller_slip.png (new or empty, or give "
                           "--overwrite)")
    parser.add_argument("--loads", default="68000,6800,2000,680,200", help="comma-separated radial loads [N]")
    parser.add_argument("--temperatures", default="40,60,80", help="comma-separated oil temperatures [°C]")
    parser.add_argument("--speeds", default="1000,1500,1800", help="comma-separated shaft speeds [rpm]")
    parser.add_argument("--clearances", default=None,
                        help="comma-separated diametral clearances [m] (bearing.diametral_clearance, about the "
                             "raceways' pitch circle; default: the scenario's own)")
    parser.add_argument("--minimum-load", default=None,
                        help="LOW,HIGH [N]: the catalogue minimum-load band to mark on the figure")
    cli.add_overrides(parser, "override any spec field of the base scenario (repeatable)")
    parser.add_argument("--no-figures", action="store_true", help="skip the PNG figures")
    parser.add_argument("--quiet", action="store_true", help="no progress bar")


def _skidding_map(args, cli) -> int:
    """Exit 0: every point solved; 1: some had no balance (``failed``; all are written); 2: bad input, nothing
    ran."""
    from bearing_mbs.models.cylindrical_roller.studies import skidding_map

    band = None
    if args.minimum_load is not None:
        band = cli.numbers("--minimum-load", args.minimum_load)
        if len(band) != 2 or not 0 < band[0] < band[1]:
            raise SpecError("--minimum-load", args.minimum_load, "LOW,HIGH [N] with 0 < LOW < HIGH")
    spec = cli.services.load_spec(args.scenario, args.set)
    loads, temperatures, speeds = (cli.numbers(name, text) for name, text in (
        ("--loads", args.loads), ("--temperatures", args.temperatures), ("--speeds", args.speeds)))
    clearances = None if args.clearances is None else cli.numbers("--clearances", args.clearances)
    skidding_map.check_grid(cli.services, spec, loads, temperatures, speeds, clearances)
    rows = skidding_map.run(cli.services, spec, cli.output_directory(args), loads, temperatures, speeds, band,
                            figures=not args.no_figures, progress=cli.progress(args.quiet), clearances=clearances)
    print(skidding_map.markdown_table(rows) + f"-> {args.out}")
    return cli.exit_code([row["status"] for row in rows])


def _cage_models_arguments(parser, cli) -> None:
    parser.add_argument("scenario", help="bearing scenario TOML file, the base of the comparison")
    cli.add_output(parser, "output directory: cage_models.{md,csv} and two figures (new or empty, or give "
                           "--overwrite)")
    parser.add_argument("--no-roller-guided", action="store_true",
                        help="only the three cage models, without the two roller-guided runs")
    cli.add_overrides(parser, "override any spec field of the base scenario (repeatable)")
    parser.add_argument("--no-figures", action="store_true", help="skip the PNG figures")
    parser.add_argument("--quiet", action="store_true", help="no progress bar")


def _cage_models(args, cli) -> int:
    """Exit 0: every run succeeded; 3: some are suspect (a failed check, or a window that did not settle); 1: some
    stopped early (all are written); 2: bad input, nothing ran."""
    from bearing_mbs.models.cylindrical_roller.studies import cage_models

    spec = cli.services.load_spec(args.scenario, args.set)
    rows = cage_models.run(cli.services, spec, cli.output_directory(args), roller_guided=not args.no_roller_guided,
                           figures=not args.no_figures, progress=cli.progress(args.quiet))
    print(cage_models.markdown_table(rows) + f"status: {cage_models.comparison_status(rows)} -> {args.out}")
    return cli.exit_code([row["status"] for row in rows])


#: ``spatial``'s default step [s] per method: generalized-α's the cost benchmark finds sound on the seed bearing
#: (benchmarks/bench_spatial.py), RK4's within the dry contacts' explicit limit (docs/spatial.md).
SPATIAL_STEPS = {methods.GENERALIZED_ALPHA.name: 1e-5, methods.RK4.name: 2e-7}


def _spatial_arguments(parser, cli) -> None:
    parser.add_argument("scenario", help="bearing scenario TOML file (a penalty cage, dry contacts: docs/spatial.md)")
    cli.add_output(parser, "output directory: summary.json, series.npz, slice_loads.png, attitudes.png, "
                           "ribs_smearing.png (new or empty, or give --overwrite)")
    parser.add_argument("--engine", default="reference", help="reference (default) or exudyn")
    parser.add_argument("--method", default=methods.GENERALIZED_ALPHA.name,
                        help=f"{methods.GENERALIZED_ALPHA.name} (default: Lie-group, implicit) or {methods.RK4.name}")
    parser.add_argument("--step", type=float, default=None, metavar="S",
                        help="step [s] (default: " + ", ".join(f"{step:g} with {name}" for name, step
                                                               in SPATIAL_STEPS.items()) + ")")
    parser.add_argument("--spectral-radius", type=float, default=None, metavar="RHO",
                        help="generalized-α's high-frequency spectral radius (default 0.9)")
    parser.add_argument("--tolerance", type=float, default=None, metavar="TOL",
                        help="the reference engine's Newton tolerance for generalized-α (default 1e-6)")
    parser.add_argument("--end-time", type=float, default=None, metavar="S",
                        help="simulated time [s] (default: the scenario's end time)")
    parser.add_argument("--output-interval", type=float, default=1e-4, metavar="S",
                        help="output spacing [s] (default 1e-4)")
    parser.add_argument("--slices", type=int, default=10, help="slices per roller contact (default 10)")
    parser.add_argument("--misalignment", type=float, default=0.0, metavar="RAD",
                        help="the inner ring's tilt about x [rad] (default 0)")
    parser.add_argument("--axial-load", type=float, default=0.0, metavar="N",
                        help="axial load on the inner ring along +z [N], carried by the ribs (default 0)")
    parser.add_argument("--crown-radius", type=float, default=None, metavar="M",
                        help="the rollers' circular crown radius [m] over their outer quarters (default: straight)")
    parser.add_argument("--damping-time", type=float, default=0.0, metavar="S",
                        help="stiffness-proportional contact damping [s] on top of the scenario's laws (default 0)")
    cli.add_overrides(parser, "override any spec field of the scenario (repeatable)")
    parser.add_argument("--no-figures", action="store_true", help="skip the PNG figures")
    parser.add_argument("--quiet", action="store_true", help="no progress bar")


def _spatial(args, cli) -> int:
    """Exit 0: success; 3: suspect (the energy audit did not close); 1: stopped early (what was computed is
    written); 2: bad input, nothing ran."""
    from bearing_mbs.models.cylindrical_roller.studies import spatial_run

    spec = cli.services.load_spec(args.scenario, args.set)
    directory = cli.output_directory(args)
    step = SPATIAL_STEPS.get(args.method, math.nan) if args.step is None else args.step
    summary = spatial_run.run(spec, directory, engine=args.engine, method=args.method, step=step,
                              spectral_radius=args.spectral_radius, tolerance=args.tolerance,
                              end_time=spec.scenario.end_time if args.end_time is None else args.end_time,
                              output_interval=args.output_interval, slices=args.slices,
                              misalignment=args.misalignment, axial_load=args.axial_load,
                              crown_radius=args.crown_radius,
                              damping_time=args.damping_time, figures=not args.no_figures,
                              progress=cli.progress(args.quiet))
    print(f"{summary['scenario']} in three dimensions ({summary['engine']} {summary['method']}): "
          f"{summary['status']} at "
          f"{summary['end_time_s']:.4g} s, cage slip {summary['cage_slip_final']:.4g}, largest slice load "
          f"{summary['largest_slice_load_N']:.4g} N, largest skew {summary['largest_skew_rad']:.3g} rad, "
          f"{summary['wall_time_s']:.3g} s wall time")
    if summary["message"]:
        print(summary["message"])
    print(f"-> {directory}")
    return cli.exit_code(summary["status"])


#: The model's subcommands, in the order ``bearing-mbs --help`` lists them.
COMMANDS = (
    Command("spatial", "run the bearing in three dimensions (skew, tilt, slice loads, ribs): docs/spatial.md",
            _spatial_arguments, _spatial),
    Command("stiffness", "quasi-static load distribution and 2x2 stiffness of a bearing scenario (no simulation)",
            _stiffness_arguments, _stiffness),
    Command("static-check", "settled dynamic equilibria and stiffness against the quasi-static solution",
            _static_check_arguments, _static_check),
    Command("skidding", "cage slip against radial load, per cage model", _skidding_arguments, _skidding),
    Command("skidding-map", "steady cage and roller slip over load x oil temperature x speed (x clearance), from "
            "the quasi-static skidding balance", _skidding_map_arguments, _skidding_map),
    Command("cage-models", "compare the penalty, constraint and no-cage models", _cage_models_arguments,
            _cage_models),
)
