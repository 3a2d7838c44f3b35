"""What a rotor run tells: its orbit, eccentricity, whirl growth and frequency, against the linearised rotor."""

from __future__ import annotations

import math
from dataclasses import replace
from pathlib import Path

import numpy as np
from scipy.signal import find_peaks

from bearing_mbs.core.topology import Role
from bearing_mbs.fluid_film.journal import FILM_COLLAPSE
from bearing_mbs.io.figures import new_figure, save_figure
from bearing_mbs.models.rotor.build import equilibrium, map_error, map_orbit_error
from bearing_mbs.models.rotor.linear import critical_speeds, unbalance_amplitude, whirl_threshold
from bearing_mbs.models.rotor.spec import RotorSpec
from bearing_mbs.spec import SpecError

#: Orbits below this fraction of the clearance count as small (linear) motion for the growth rate.
LINEAR_ORBIT = 0.1
#: Fewest output instants in the second half of a run for the orbit's spectrum (whirl_frequency_ratio): below, none.
SPECTRUM_INSTANTS = 4
#: Speed bins of a run-up's unbalance response.
RESPONSE_BINS = 40
#: Instants of a run at which the force map is compared with a Reynolds solve (map_orbit_error).
ORBIT_SAMPLES = 24

UNITS = {"equilibrium_eccentricity_ratio": "-", "mean_eccentricity_ratio": "-", "max_eccentricity_ratio": "-",
         "orbit_radius": "m", "orbit_amplitude": "m, m", "whirl_growth_rate": "1/s", "whirl_frequency_ratio": "-",
         "linear_whirl_threshold_rpm": "rpm", "whirl_onset_rpm": "rpm", "plain_whirl_threshold_rpm": "rpm",
         "map_interpolation_error": "-", "map_orbit_error": "-", "critical_speeds_rpm": "rpm",
         "unbalance_response": "rpm, m, m"}


def _journal(spec: RotorSpec, result):
    index = 3 * int(result.topology.body(Role.ROTOR))
    return result.position[:, index : index + 2], result.velocity[:, index + 2]


def whirl_growth_rate(time, distance, clearance: float) -> float | None:
    """The slope [1/s] of log(distance) through its successive maxima after the first fifth of the run, while the
    motion is small (below :data:`LINEAR_ORBIT` of the clearance): at constant speed, the growth (> 0) or decay of
    the least damped mode. None with fewer than three such maxima."""
    peaks, _ = find_peaks(distance)
    peaks = peaks[(distance[peaks] > 0) & (distance[peaks] < LINEAR_ORBIT * clearance)
                  & (time[peaks] >= time[0] + (time[-1] - time[0]) / 5)]
    if peaks.size < 3:
        return None
    return float(np.polyfit(time[peaks], np.log(distance[peaks]), 1)[0])


def _dominant_ratio(frequencies, spectrum, spin_frequency) -> float | None:
    """The strongest frequency of the orbit above a tenth of the spin frequency (the slow drift of a sweep's
    equilibrium left out), as a fraction of the spin frequency: ≈ 1 for unbalance, ≈ 0.5 for oil whirl."""
    band = frequencies > spin_frequency / 10
    if spin_frequency <= 0 or not band.any():
        return None
    return float(frequencies[band][np.argmax(spectrum[band])] / spin_frequency)


def carried_equilibrium(spec: RotorSpec, speed: float) -> np.ndarray | None:
    """The static equilibrium [m] at Ω [rad/s], or None where the films cannot carry the rotor's weight (a run-down
    below the lift-off speed: valid input, whose run shows the film collapse)."""
    try:
        return equilibrium(spec, speed)
    except SpecError:
        return None


def whirl_onset(spec: RotorSpec, time, centre, spin, samples: int = 24) -> float | None:
    """For a balanced rotor's speed sweep, the speed [rpm] at which the journal first strays more than :data:`LINEAR_ORBIT` of the clearance from its
    equilibrium at the current speed (interpolated between ``samples`` speeds), or None if it never does."""
    speeds = np.linspace(spin.min(), spin.max(), samples)
    if speeds[-1] <= speeds[0]:
        return None
    points = [carried_equilibrium(spec, s) for s in speeds]
    if any(point is None for point in points):  # a sweep through speeds the films cannot carry: no linear onset
        return None
    points = np.array(points)
    current = np.stack([np.interp(spin, speeds, points[:, k]) for k in range(2)], axis=1)
    strayed = np.flatnonzero(np.hypot(*(centre - current).T) > LINEAR_ORBIT * spec.bearing.radial_clearance)
    return float(spin[strayed[0]] * 30 / math.pi) if strayed.size else None


def rotor_metrics(spec: RotorSpec, scene, result) -> dict:
    centre, spin = _journal(spec, result)
    clearance = spec.bearing.radial_clearance
    window = result.time >= result.time[-1] / 2
    final = carried_equilibrium(spec, spec.drive.speed_rpm * math.pi / 30)
    orbit = centre[window] - centre[window].mean(axis=0)
    ratio = np.hypot(*centre.T) / clearance
    motion = orbit[:, 0] - orbit[:, 0].mean()
    spacing = np.diff(result.time[window])
    spin_frequency = float(np.mean(spin[window])) / (2 * math.pi)
    whirl_ratio = None  # a spectrum needs a few instants, evenly spaced (a run stopped early may leave one or two)
    if motion.size >= SPECTRUM_INSTANTS and np.all(spacing > 0):
        frequencies = np.fft.rfftfreq(motion.size, d=float(np.mean(spacing)))
        spectrum = np.abs(np.fft.rfft(motion * np.hanning(motion.size)))
        whirl_ratio = _dominant_ratio(frequencies, spectrum, spin_frequency)
    summary = {
        "equilibrium_eccentricity_ratio": None if final is None else float(np.hypot(*final) / clearance),
        "mean_eccentricity_ratio": float(np.hypot(*centre[window].mean(axis=0)) / clearance),
        "max_eccentricity_ratio": float(ratio.max()),
        "orbit_radius": float(np.hypot(*orbit.T).max()),
        "orbit_amplitude": (np.ptp(orbit, axis=0) / 2).tolist(),
        "whirl_growth_rate": (None if final is None
                              else whirl_growth_rate(result.time, np.hypot(*(centre - final).T), clearance)),
        "whirl_frequency_ratio": whirl_ratio,
        "linear_whirl_threshold_rpm": whirl_threshold(spec),
    }
    if spec.drive.ramp_time > 0 and spec.rotor.unbalance == 0:
        summary["whirl_onset_rpm"] = whirl_onset(spec, result.time, centre, spin)
    if spec.bearing.recesses is not None:
        plain = replace(spec, bearing=replace(spec.bearing, recesses=None), drive=replace(spec.drive, start_rpm=None))
        summary["plain_whirl_threshold_rpm"] = whirl_threshold(plain)
    if spec.drive.ramp_time > 0 and spec.rotor.unbalance > 0:
        response = unbalance_response(spec, centre, spin)
        summary["unbalance_response"] = response
        summary["critical_speeds_rpm"] = critical_speeds(np.array(response["speed_rpm"]), np.array(response["linear"]))
    if spec.bearing.force == "map":
        summary["map_interpolation_error"] = map_error(spec)
        samples = np.linspace(0, result.time.size - 1, ORBIT_SAMPLES).astype(int)
        index = 3 * int(result.topology.body(Role.ROTOR))
        summary["map_orbit_error"] = map_orbit_error(spec, result.position[samples, index: index + 2],
                                                     result.velocity[samples, index: index + 3])
    return summary


def unbalance_response(spec: RotorSpec, centre, spin) -> dict:
    """A run-up's orbit amplitude against speed: in :data:`RESPONSE_BINS` speed bins, the largest distance [m] of the
    journal from the equilibrium at its current speed (``measured``), beside the linear steady orbit's semi-major axis
    at the bin's mid speed (``linear``, :func:`.linear.unbalance_amplitude`). Bins below the speed at which the films
    carry the rotor are left out."""
    edges = np.linspace(spin.min(), spin.max(), RESPONSE_BINS + 1)
    middles = (edges[:-1] + edges[1:]) / 2
    points = [carried_equilibrium(spec, s) for s in middles]
    carried = [k for k, point in enumerate(points) if point is not None]
    current = np.stack([np.interp(spin, middles[carried], np.array([points[k][i] for k in carried]))
                        for i in range(2)], axis=1)
    distance = np.hypot(*(centre - current).T)
    bins = np.clip(np.searchsorted(edges, spin, side="right") - 1, 0, RESPONSE_BINS - 1)
    measured = [float(distance[bins == k].max()) if np.any(bins == k) else math.nan for k in carried]
    return {"speed_rpm": (middles[carried] * 30 / math.pi).tolist(), "measured": measured,
            "linear": [unbalance_amplitude(spec, middles[k]) for k in carried]}


def rotor_warnings(spec: RotorSpec, scene, result) -> list[str]:
    centre, _ = _journal(spec, result)
    largest = float((np.hypot(*centre.T) / spec.bearing.radial_clearance).max())
    if largest > FILM_COLLAPSE:
        return [f"max_eccentricity_ratio = {largest:.3f} > {FILM_COLLAPSE}: the film has nearly collapsed (metal "
                "contact); the film model does not hold there. A smaller load, a higher speed or a more viscous oil "
                "keeps the journal off the wall"]
    return []


def rotor_figures(spec: RotorSpec, scene, result, directory) -> list[Path]:
    centre, spin = _journal(spec, result)
    clearance = spec.bearing.radial_clearance
    figure, (orbit, history) = new_figure(1, 2, figsize=(11, 4.5))
    circle = np.linspace(0, 2 * math.pi, 200)
    orbit.plot(clearance * 1e6 * np.cos(circle), clearance * 1e6 * np.sin(circle), "k-", lw=0.8, label="clearance")
    orbit.plot(centre[:, 0] * 1e6, centre[:, 1] * 1e6, lw=0.7, label="journal centre")
    orbit.set_aspect("equal")
    orbit.set_xlabel("x [µm]")
    orbit.set_ylabel("y [µm]")
    orbit.legend(loc="upper right")
    history.plot(result.time, np.hypot(*centre.T) / clearance, label="eccentricity ratio")
    speed = history.twinx()
    speed.plot(result.time, spin * 30 / math.pi, "C1", lw=0.8)
    speed.set_ylabel("speed [rpm]", color="C1")
    history.set_xlabel("time [s]")
    history.set_ylabel("ε")
    figure.suptitle(f"{spec.scenario.name}: {spec.bearing.force} film force")
    paths = [save_figure(figure, Path(directory) / "orbit.png", status_note=result.status_note)]
    if spec.drive.ramp_time > 0 and spec.rotor.unbalance > 0:
        paths.append(_response_figure(spec, unbalance_response(spec, centre, spin), result, directory))
    return paths


def _response_figure(spec: RotorSpec, response: dict, result, directory) -> Path:
    figure, axes = new_figure(figsize=(7, 4.5))
    speeds = np.array(response["speed_rpm"])
    axes.semilogy(speeds, np.array(response["measured"]) * 1e6, "o-", ms=3, label="run-up: largest distance from "
                  "the equilibrium")
    axes.semilogy(speeds, np.array(response["linear"]) * 1e6, "k--", label="linearised rotor, steady unbalance orbit")
    threshold = whirl_threshold(spec)
    if threshold is not None and threshold <= speeds.max():
        axes.axvline(threshold, color="C3", lw=0.8, label=f"whirl threshold {threshold:.0f} rpm")
    axes.set_xlabel("speed [rpm]")
    axes.set_ylabel("orbit amplitude [µm]")
    axes.legend(loc="best")
    axes.set_title(f"{spec.scenario.name}: unbalance {spec.rotor.unbalance:g} kg m")
    return save_figure(figure, Path(directory) / "unbalance_response.png", status_note=result.status_note)
