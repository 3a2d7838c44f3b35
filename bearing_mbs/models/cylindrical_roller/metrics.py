r"""Skidding metrics of the bearing model, in the style of the skidding literature.

All means are taken over the analysis window :math:`t \ge` ``[analysis] start`` (default: the second half),
whose start ``analysis_start`` the summary reports. A run that stopped before its window (interrupted or failed)
keeps that start and has no window metric (None).

* ``cage_speed_ratio``: mean cage speed over the mean epicyclic speed :math:`\omega_i(1 - D_w/D_{pw})/2`
  (for a full-complement bearing, the rollers' mean orbital speed); ``cage_slip`` = 1 − that ratio.
* slip ratio of a roller at a raceway: slip speed over rolling (entrainment) speed at the contact,
  :math:`s = v_{slip}/u`; 0 in pure rolling, ±2 when one surface stands still. Only contacts carrying at least
  ``load_fraction`` of the largest raceway load at that instant count (so a load drop does not hide them),
  and only while the rolling speed exceeds the contact's friction regularisation speed (below it the ratio
  of two vanishing speeds means nothing: a bearing at standstill). ``max_roller_slip`` is the largest
  :math:`|s|`.
* roller loads: inner-raceway contact forces against the roller's orbital angle ψ = atan2(y, x) in [0°, 360°)
  (0 along +x, counter-clockwise: the angle convention of every output), binned every 360/(2Z) degrees, as
  ``{"angle_deg", "load_N"}`` rows. ``max_roller_load`` is the steady load-zone peak: the
  :data:`PEAK_PERCENTILE` th percentile over the window of the largest inner-raceway force at each instant, so
  an impact outlier or the ringing of a suddenly applied load does not set it; ``max_impact_load`` is the
  largest inner-raceway force at any instant of the window, impacts included.
* ``inner_ring_displacement``: magnitude of the mean inner-ring centre position [m] (its components in
  ``inner_ring_offset``).
* ``max_pocket_force``: the largest roller–pocket force, a pocket edge pair's (penalty cage; its metal contact,
  0 while oiled pockets' films hold the rollers off, whose loads are the result's ``pocket_film`` pairs) or a
  constraint's (constraint cage) [N].
* ``energy_balance_error``: see :func:`bearing_mbs.analysis.energy_balance_error`.
* ``max_cage_eccentricity``: the largest distance of the cage centre from the bearing axis [m]; beyond half
  a roller diameter the cage has left its rollers, and ``warnings`` says so.
"""

from __future__ import annotations

import numpy as np

from bearing_mbs.analysis import energy_balance_error
from bearing_mbs.models.cylindrical_roller.geometry import BearingGeometry

#: Percentile of the per-instant largest roller load that ``max_roller_load`` reports [%].
PEAK_PERCENTILE = 95.0

#: Units of :func:`bearing_metrics`' entries.
UNITS = {
    "mean_inner_speed_rpm": "rpm", "cage_speed_ratio": "-", "cage_slip": "-", "max_roller_slip": "-",
    "max_roller_slip_inner": "-", "max_roller_slip_outer": "-", "max_roller_load": "N", "max_impact_load": "N",
    "roller_loads": "angle_deg: deg, load_N: N", "inner_ring_displacement": "m", "inner_ring_offset": "m",
    "max_pocket_force": "N", "energy_balance_error": "-", "max_cage_eccentricity": "m", "analysis_start": "s",
}


def window(spec, result) -> np.ndarray:
    """Boolean mask of the output instants in the analysis window."""
    start = spec.analysis.window_start(spec.scenario.end_time)
    mask = result.time >= start - 1e-12
    return mask if mask.any() else np.ones_like(result.time, dtype=bool)


def roller_indices(scene) -> np.ndarray:
    """Body indices of the rollers, in roller order."""
    return scene.topology.role("rollers")


def pair_columns(scene, group: str) -> np.ndarray:
    """Pair indices of a contact group (``inner_race``, ``outer_race``, ``pocket``, ``land``, ``roller``), flat,
    in roller order."""
    return scene.topology.group(group).ravel()


def cage_speed(scene, result) -> np.ndarray:
    """Cage angular speed [rad/s] (T,): the cage body's, or the rollers' mean orbital speed without a cage."""
    if scene.topology.has("cage"):
        return result.velocity[:, 3 * scene.topology.body("cage") + 2]
    rollers = roller_indices(scene)
    x, y = result.position[:, 3 * rollers], result.position[:, 3 * rollers + 1]
    vx, vy = result.velocity[:, 3 * rollers], result.velocity[:, 3 * rollers + 1]
    return np.mean((x * vy - y * vx) / (x**2 + y**2), axis=1)


def slip_ratios(scene, result, race: str, load_fraction: float) -> np.ndarray:
    """(T, Z) slip ratios at ``race`` ('inner_race' or 'outer_race'); NaN where the contact carries less
    than ``load_fraction`` of the largest roller load."""
    columns = pair_columns(scene, race)
    force = result.pair_series("normal_force")[:, columns]
    slip, rolling = result.pair_series("slip")[:, columns], result.pair_series("rolling_speed")[:, columns]
    raceways = np.concatenate([pair_columns(scene, "inner_race"), pair_columns(scene, "outer_race")])
    largest = result.pair_series("normal_force")[:, raceways].max(axis=1, keepdims=True)
    loaded = (force > 0) & (force >= load_fraction * largest)
    rolling_floor = np.array([scene.pairs[k].law.regularisation_speed for k in columns])
    with np.errstate(divide="ignore", invalid="ignore"):
        ratio = slip / np.abs(rolling)
    return np.where(loaded & (np.abs(rolling) > rolling_floor), ratio, np.nan)


def roller_orbit_angles(scene, result) -> np.ndarray:
    """(T, Z) orbital angle of each roller [rad] in [0, 2π)."""
    rollers = roller_indices(scene)
    return np.mod(np.arctan2(result.position[:, 3 * rollers + 1], result.position[:, 3 * rollers]), 2 * np.pi)


def load_distribution(scene, result, mask, bins: int) -> tuple[np.ndarray, np.ndarray]:
    """Mean inner-raceway load [N] against orbital angle [deg] (bin centres) over the instants in ``mask``."""
    angle = np.degrees(roller_orbit_angles(scene, result)[mask]).ravel()
    force = result.pair_series("normal_force")[mask][:, pair_columns(scene, "inner_race")].ravel()
    edges = np.linspace(0, 360, bins + 1)
    which = np.clip(np.digitize(angle, edges) - 1, 0, bins - 1)
    sums = np.bincount(which, weights=force, minlength=bins)
    counts = np.bincount(which, minlength=bins)
    with np.errstate(invalid="ignore"):
        return 0.5 * (edges[1:] + edges[:-1]), np.where(counts > 0, sums / np.maximum(counts, 1), np.nan)


def cage_eccentricity(scene, result) -> float | None:
    """The largest distance of the cage centre from the bearing axis over the run [m]; None without a cage."""
    if not scene.topology.has("cage"):
        return None
    cage = scene.topology.body("cage")
    return float(np.hypot(result.position[:, 3 * cage], result.position[:, 3 * cage + 1]).max())


def bearing_warnings(spec, scene, result) -> list[str]:
    """What makes the run's numbers meaningless: a cage more than half a roller diameter off the axis has left
    its rollers (the runner's ``guard_warnings`` check)."""
    eccentricity = cage_eccentricity(scene, result)
    half_roller = spec.bearing.roller_diameter / 2
    if eccentricity is None or not eccentricity > half_roller:
        return []
    return [f"the cage centre moved {eccentricity:.3g} m off the axis, more than half a roller diameter: it has "
            f"left its rollers and its speed is meaningless"]


def bearing_metrics(spec, scene, result) -> dict:
    start = spec.analysis.window_start(spec.scenario.end_time)
    whole_run = {"energy_balance_error": energy_balance_error(scene, result),
                 "max_cage_eccentricity": cage_eccentricity(scene, result), "analysis_start": start,
                 "warnings": bearing_warnings(spec, scene, result)}
    if not (result.time >= start - 1e-12).any():  # stopped before its window: the window stays, its metrics are None
        return {**dict.fromkeys(key for key in UNITS if key not in whole_run), **whole_run}
    geometry = BearingGeometry.from_spec(spec.bearing)
    mask = window(spec, result)
    inner_speed = result.velocity[:, 2]
    epicyclic = geometry.epicyclic_cage_speed(inner_speed)
    ratio = float(np.mean(cage_speed(scene, result)[mask]) / np.mean(epicyclic[mask]))
    fraction = spec.analysis.load_fraction
    slips = {race: slip_ratios(scene, result, race, fraction)[mask] for race in ("inner_race", "outer_race")}
    inner_loads = result.pair_series("normal_force")[mask][:, pair_columns(scene, "inner_race")]
    angles, loads = load_distribution(scene, result, mask, 2 * geometry.rollers)
    offset = result.position[mask][:, :2].mean(axis=0)

    pocket = pair_columns(scene, "pocket")
    if pocket.size:
        max_pocket = float(result.pair_series("normal_force")[mask][:, pocket].max())
    elif scene.constraints:
        max_pocket = float(result.constraint_forces[mask].max())
    else:
        max_pocket = None

    def largest(values):
        return float(np.nanmax(np.abs(values))) if np.isfinite(values).any() else None

    return {
        "mean_inner_speed_rpm": float(np.mean(inner_speed[mask]) * 60 / (2 * np.pi)),
        "cage_speed_ratio": ratio,
        "cage_slip": 1.0 - ratio,
        "max_roller_slip": largest(np.concatenate([slips["inner_race"].ravel(), slips["outer_race"].ravel()])),
        "max_roller_slip_inner": largest(slips["inner_race"]),
        "max_roller_slip_outer": largest(slips["outer_race"]),
        "max_roller_load": float(np.percentile(inner_loads.max(axis=1), PEAK_PERCENTILE)),
        "max_impact_load": float(inner_loads.max()),
        "roller_loads": [{"angle_deg": float(a), "load_N": None if np.isnan(f) else float(f)}
                         for a, f in zip(angles, loads)],
        "inner_ring_displacement": float(np.hypot(*offset)),
        "inner_ring_offset": [float(offset[0]), float(offset[1])],
        "max_pocket_force": max_pocket,
        **whole_run,
        "analysis_start": float(result.time[mask][0]),
    }
