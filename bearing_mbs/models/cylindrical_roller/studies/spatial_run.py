"""``bearing-mbs spatial``: a bearing scenario run in three dimensions (:mod:`..spatial`), its outputs written.

Writes ``summary.json`` (the run's settings, status, cost and outcome: cage slip, the largest slice and rib loads,
the rollers' largest skew and tilt, the energy audit's error), ``series.npz`` (the spatial series) and, unless asked
not to, ``slice_loads.png``, ``attitudes.png`` and ``ribs_smearing.png``. The status is ``success`` when the run reached its end and its
energy audit closed (within :data:`AUDIT_TOLERANCE` of the energy that changed form), ``suspect`` when it reached
its end but the audit did not, ``failed`` when it stopped early, ``interrupted`` on a stop request; the output
computed is written in every case.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np

from bearing_mbs.core.failures import Failure
from bearing_mbs.core.interrupt import active_request
from bearing_mbs.core.result import FAILED, INTERRUPTED, SUCCESS, SUSPECT
from bearing_mbs.core.spatial import energy_audit
from bearing_mbs.engines.exudyn.spatial import simulate_spatial_exudyn
from bearing_mbs.engines.reference.spatial import SPATIAL_METHODS, simulate_spatial_reference
from bearing_mbs.io.json import write_json
from bearing_mbs.models.cylindrical_roller.quasistatic import CircularCrown
from bearing_mbs.models.cylindrical_roller.spatial import build_spatial_bearing
from bearing_mbs.models.cylindrical_roller.spatial_figures import (
    plot_attitudes,
    plot_ribs_and_smearing,
    plot_slice_loads,
)
from bearing_mbs.spec import SpecError, methods

#: The engines that run a spatial scene (both run the same methods).
ENGINES = {"reference": simulate_spatial_reference, "exudyn": simulate_spatial_exudyn}
#: Generalized-α's defaults: the setting the cost benchmark finds sound on the seed bearing
#: (benchmarks/bench_spatial.py).
DEFAULT_SPECTRAL_RADIUS, DEFAULT_TOLERANCE = 0.9, 1e-6
#: The energy audit's error, relative to the energy that changed form, below which a run's status is ``success``
#: (the trapezoid rule of Exudyn's audit reaches a few 1e-4 on the tests' runs: docs/spatial.md).
AUDIT_TOLERANCE = 1e-3


def run(spec, directory: Path, *, engine: str, method: str, step: float, spectral_radius: float | None,
        tolerance: float | None, end_time: float, output_interval: float, slices: int, misalignment: float,
        crown_radius: float | None, damping_time: float, figures: bool, axial_load: float = 0.0,
        progress=None) -> dict:
    """Build the bearing of ``spec`` in three dimensions, run it with ``method`` (a name of
    :data:`SPATIAL_METHODS`; generalized-α with ``spectral_radius``, default 0.9, and on the reference engine the
    Newton ``tolerance``, default 1e-6), write its outputs into ``directory``; returns the summary."""
    if engine not in ENGINES:
        raise SpecError("--engine", engine, f"must be one of {sorted(ENGINES)}")
    names = {m.name: m for m in SPATIAL_METHODS}
    if method not in names:
        raise SpecError("--method", method, f"must be one of {sorted(names)}")
    implicit = names[method] == methods.GENERALIZED_ALPHA
    if spectral_radius is not None and not (implicit and 0.0 <= spectral_radius <= 1.0):
        raise SpecError("--spectral-radius", spectral_radius,
                        f"must be in [0, 1], with {methods.GENERALIZED_ALPHA.name}")
    if tolerance is not None and not (implicit and engine == "reference" and 0.0 < tolerance < 1.0):
        raise SpecError("--tolerance", tolerance, f"must be in (0, 1), with {methods.GENERALIZED_ALPHA.name} on the "
                                                  "reference engine (Exudyn's Newton keeps its own settings)")
    for option, value in (("--step", step), ("--end-time", end_time), ("--output-interval", output_interval)):
        if not (math.isfinite(value) and value > 0):
            raise SpecError(option, value, "must be a finite number of seconds > 0")
    if not (isinstance(slices, int) and slices >= 1):
        raise SpecError("--slices", slices, "must be an integer >= 1")
    if not math.isfinite(misalignment):
        raise SpecError("--misalignment", misalignment, "must be a finite angle [rad]")
    if not (math.isfinite(axial_load) and axial_load >= 0):
        raise SpecError("--axial-load", axial_load, "must be a finite force >= 0 N (along +z, onto the ribs)")
    if not (math.isfinite(damping_time) and damping_time >= 0):
        raise SpecError("--damping-time", damping_time, "must be a finite time >= 0 s")
    if crown_radius is not None and not crown_radius > 0:
        raise SpecError("--crown-radius", crown_radius, "must be > 0 m (leave it out for straight rollers)")
    length = spec.bearing.roller_length
    crown = CircularCrown(radius=crown_radius, straight_length=length / 2) if crown_radius else None
    bearing = build_spatial_bearing(spec, slices=slices, damping_time=damping_time, misalignment=misalignment,
                                    crown=crown, axial_load=axial_load)
    settings = {"method": names[method]}
    if implicit:
        settings["spectral_radius"] = DEFAULT_SPECTRAL_RADIUS if spectral_radius is None else spectral_radius
        if engine == "reference":
            settings["tolerance"] = DEFAULT_TOLERANCE if tolerance is None else tolerance
    series = ENGINES[engine](bearing.scene, step, end_time, output_interval, **settings, progress=progress,
                             stop=active_request())
    summary = _summary(spec, bearing, series, engine, step, misalignment, slices, crown_radius, settings)
    summary["axial_load_N"] = axial_load
    np.savez_compressed(directory / "series.npz", **{name: np.asarray(value) for name, value in
                                                    series._asdict().items() if isinstance(value, np.ndarray)})
    if figures and series.time.size > 1:
        plot_slice_loads(bearing, series, directory / "slice_loads.png")
        plot_attitudes(bearing, series, directory / "attitudes.png")
        plot_ribs_and_smearing(bearing, series, directory / "ribs_smearing.png")
    write_json(directory / "summary.json", summary)
    return summary


def _summary(spec, bearing, series, engine: str, step: float, misalignment: float, slices: int,
             crown_radius: float | None, settings: dict) -> dict:
    audit = energy_audit(bearing.scene, series)
    moved = max(float(np.ptp(audit.kinetic)), float(audit.dissipated[-1]), abs(float(audit.supplied[-1])), 1e-300)
    audit_error = float(np.abs(audit.error).max()) / moved
    if series.success:
        status = SUCCESS if audit_error <= AUDIT_TOLERANCE else SUSPECT
    else:
        status = INTERRUPTED if series.failure == Failure.INTERRUPTED else FAILED
    skew, tilt = bearing.attitudes(series)
    return {
        "scenario": spec.scenario.name, "engine": engine, "method": settings["method"].name, "step_s": step,
        "spectral_radius": settings.get("spectral_radius"), "newton_tolerance": settings.get("tolerance"),
        "newton_iterations": series.newton_iterations, "jacobians": series.jacobians, "slices": slices,
        "misalignment_rad": misalignment, "crown_radius_m": crown_radius, "status": status,
        "failure": series.failure.label, "message": series.message,
        "end_time_s": float(series.time[-1]), "steps": series.steps, "wall_time_s": series.wall_time_s,
        "cage_slip_final": float(bearing.cage_slip(series)[-1]),
        "largest_slice_load_N": float(series.slice_loads.max()) if series.slice_loads.size else 0.0,
        "largest_roller_load_N": float(bearing.roller_loads(series).max()),
        "largest_rib_load_N": float(series.flange_loads.max()) if series.flange_loads.size else 0.0,
        "largest_skew_rad": float(np.abs(skew).max()), "largest_tilt_rad": float(np.abs(tilt).max()),
        "energy_audit_error": audit_error, "energy_audit_tolerance": AUDIT_TOLERANCE,
    }
