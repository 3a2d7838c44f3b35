r"""The blade-pitch scenario: a blade root carried by a slewing bearing under a gusting tilting moment, for
``bearing-mbs run`` on either engine.

One planar body in the bearing's axial plane (x radial, y axial, θ tilt) on a
:class:`~bearing_mbs.elements.slewing_bearings.SlewingBearingJoint` to the ground (rigid or flexible rings, as the
scenario's ``[slewing]`` says); constant radial and axial
loads and a tilting moment M + A sin(2πt/T), all rising from 0 along a half cosine over ``ramp_time``; gravity
along −y. The metrics compare the motion with the quasi-static solution at the same loads, instant by instant
(:mod:`.load_distribution`): a slow gust (T much longer than the bearing's tilt period) must be carried
quasi-statically.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from bearing_mbs.core.scene import Body, Profile, Scene, half_cosine
from bearing_mbs.core.topology import Role, Topology
from bearing_mbs.elements import Load
from bearing_mbs.elements.slewing_bearings import SlewingBearingJoint
from bearing_mbs.io.figures import new_figure, save_figure
from bearing_mbs.models.slewing_bearing.load_distribution import NotConverged, solve
from bearing_mbs.models.slewing_bearing.spec import SlewingSpec
from bearing_mbs.models.slewing_bearing.static import bearing_of, rings_of
from bearing_mbs.spec import SpecError

#: Samples per gust period of the moment's table profile.
SAMPLES_PER_PERIOD = 200
#: Output instants compared with the quasi-static solution.
COMPARED_INSTANTS = 40


def ramp_factor(t, ramp_time: float):
    """The loads' ramp at times t [s]: :func:`~bearing_mbs.core.scene.half_cosine` over ``ramp_time``, 1 without."""
    t = np.asarray(t, dtype=float)
    return half_cosine(t / ramp_time) if ramp_time > 0 else np.ones_like(t)


def applied_loads(spec: SlewingSpec, t) -> np.ndarray:
    """(F_r [N], F_a [N], M [N m]) on the inner ring at times t [s] (T,), gravity on the blade root included."""
    load, pitch = spec.load, spec.pitch
    t = np.asarray(t, dtype=float)
    ramp = ramp_factor(t, pitch.ramp_time)
    moment = load.moment + pitch.gust_amplitude * np.sin(2 * np.pi * t / pitch.gust_period)
    weight = -pitch.blade_mass * spec.scenario.gravity
    return np.stack([ramp * load.radial, ramp * load.axial + weight, ramp * moment], axis=1)


def build_pitch_scene(spec: SlewingSpec) -> Scene:
    if spec.pitch is None:
        raise SpecError("pitch", None, "a [pitch] section (the blade root the bearing carries) for a run; "
                                       "`bearing-mbs slewing` solves the bearing statically")
    bearing, rings, pitch = bearing_of(spec), rings_of(spec), spec.pitch
    body = Body("blade_root", pitch.blade_mass, pitch.blade_inertia, (0.0, 0.0, 0.0))
    joint = SlewingBearingJoint("pitch_bearing", 0, bearing.balls, bearing.pitch_diameter / 2, bearing.centre_distance,
                                bearing.contact_angle, bearing.stiffness, pitch.damping, (0.0, 0.0, 0.0),
                                *((rings.modes, rings.sector) if rings is not None else ()))
    end = spec.scenario.end_time
    times = np.linspace(0.0, end, max(2, int(SAMPLES_PER_PERIOD * end / pitch.gust_period) + 1))
    if pitch.ramp_time > 0:
        times = np.union1d(times, Profile.smooth_ramp(1.0, min(pitch.ramp_time, end)).times)
    ramp = ramp_factor(times, pitch.ramp_time)
    loads = []
    for name, vector, value in (("radial_load", (1.0, 0.0, 0.0), spec.load.radial),
                                ("axial_load", (0.0, 1.0, 0.0), spec.load.axial)):
        if value:
            loads.append(Load(name, 0, vector, Profile(tuple(times), tuple(value * ramp))))
    moment = ramp * (spec.load.moment + pitch.gust_amplitude * np.sin(2 * np.pi * times / pitch.gust_period))
    if np.any(moment):
        loads.append(Load("tilting_moment", 0, (0.0, 0.0, 1.0), Profile(tuple(times), tuple(moment))))
    return Scene(spec.scenario.name, (body,), forces=(joint, *loads), gravity=(0.0, -spec.scenario.gravity),
                 topology=Topology(bodies={Role.BLADE_ROOT: [0]}))


def pitch_metrics(spec: SlewingSpec, scene: Scene, result) -> dict:
    """Over the second half of the run: the mean displacement (radial, axial [m], tilt [rad]) and the
    quasi-static one at the same instants' loads, their relative difference (``quasi_static_error``, of the
    mean tilt and axial displacement), and the largest difference at any compared instant relative to the
    largest quasi-static value (``quasi_static_tracking_error``)."""
    bearing, rings = bearing_of(spec), rings_of(spec)
    window = np.flatnonzero(result.time >= result.time[-1] / 2)
    picked = window[np.linspace(0, window.size - 1, min(COMPARED_INSTANTS, window.size)).round().astype(int)]
    dynamic = result.position[picked, 0:3]
    loads = applied_loads(spec, result.time[picked])
    mean_dynamic = dynamic.mean(axis=0)
    try:
        static = np.array([solve(bearing, load, rings=rings).displacement for load in loads])
    except NotConverged:  # no quasi-static solution to compare with (too few balls to hold the ring): no errors
        static = None
    mean_static = None if static is None else static.mean(axis=0)
    error = [] if static is None else [abs(mean_dynamic[k] / mean_static[k] - 1) for k in (1, 2)
                                       if mean_static[k] != 0]
    tracking = [] if static is None else [np.abs(dynamic[:, k] - static[:, k]).max() / np.abs(static[:, k]).max()
                                          for k in (1, 2) if np.abs(static[:, k]).max() > 0]
    return {
        "mean_displacement": mean_dynamic.tolist(),
        "quasi_static_displacement": None if mean_static is None else mean_static.tolist(),
        "quasi_static_error": max(error) if error else None,
        "quasi_static_tracking_error": max(tracking) if tracking else None,
        "max_tilt": float(np.abs(result.position[:, 2]).max()),
    }


PITCH_UNITS = {"mean_displacement": "m, m, rad", "quasi_static_displacement": "m, m, rad", "quasi_static_error": "-",
               "quasi_static_tracking_error": "-", "max_tilt": "rad"}


def pitch_figures(spec: SlewingSpec, scene: Scene, result, directory) -> list[Path]:
    figure, (axial, tilt) = new_figure(2, 1, figsize=(7, 6), sharex=True)
    axial.plot(result.time, result.position[:, 1] * 1e3, label="run")
    tilt.plot(result.time, np.degrees(result.position[:, 2]), label="run")
    sample = result.time[:: max(1, result.time.size // COMPARED_INSTANTS)]
    try:
        static = np.array([solve(bearing_of(spec), load, rings=rings_of(spec)).displacement
                           for load in applied_loads(spec, sample)])
    except NotConverged:  # nothing quasi-static to draw (pitch_metrics says so)
        static = None
    if static is not None:
        axial.plot(sample, static[:, 1] * 1e3, "o", markersize=3, label="quasi-static at the same load")
        tilt.plot(sample, np.degrees(static[:, 2]), "o", markersize=3, label="quasi-static at the same load")
    axial.set_ylabel("axial displacement [mm]")
    tilt.set_ylabel("tilt [deg]")
    tilt.set_xlabel("time [s]")
    axial.legend()
    axial.set_title(f"{spec.scenario.name}: blade root on the pitch bearing ({spec.slewing.rings} rings)")
    return [save_figure(figure, Path(directory) / "pitch_response.png", status_note=result.status_note)]
