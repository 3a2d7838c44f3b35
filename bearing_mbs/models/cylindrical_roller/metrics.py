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
* ``max_frictional_power_intensity`` (and ``_inner``, ``_outer`` per raceway) [W/mm²]: the largest frictional
  power per unit contact area of a raceway contact over the window, the smearing measure of docs/smearing.md
  (:func:`frictional_power_intensity`): the traction of the pair's own law at the recorded load, slip and rolling
  speed times the slip, over the Hertz contact 2 b l. The recorded ``friction_force`` is not used: for a
  lubricated pair with hydrodynamic rolling resistance it also holds that resistance's tangential share, whose
  power is the inlet's rolling loss, not sliding in the contact.

The frictional power intensity of a line contact of length l under the load Q, with the traction μQ and the
sliding speed Δu, is

.. math:: q = \frac{\mu Q\,|\Delta u|}{2 b l} = \bar\tau\,|\Delta u|,
          \qquad b = \sqrt{\frac{8 (Q/l) R}{\pi E'}}

(:func:`bearing_mbs.contact.ehl.hertz_half_width`: K. L. Johnson, *Contact Mechanics*, 1985, §4.2), the mean shear
stress of the contact times the sliding speed: the frictional power intensity of scuffing and smearing criteria
(e.g. J. H. Horng, J. F. Lin, K. Y. Li, J. Tribol. 118 (1996) 669–675, who divide by the real area of contact
instead). E' and R are a raceway's (:func:`raceway_contact`).
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

from bearing_mbs.analysis import energy_balance_error
from bearing_mbs.contact import kernel
from bearing_mbs.contact.ehl import hertz_half_width
from bearing_mbs.contact.traction import TRACTION_COLUMNS
from bearing_mbs.core.topology import Group, Role
from bearing_mbs.elements.contact_pairs import pack
from bearing_mbs.models.cylindrical_roller.build import raceway_line_contact
from bearing_mbs.models.cylindrical_roller.geometry import BearingGeometry

#: Percentile of the per-instant largest roller load that ``max_roller_load`` reports [%].
PEAK_PERCENTILE = 95.0

#: Units of :func:`bearing_metrics`' entries.
UNITS = {
    "mean_inner_speed_rpm": "rpm", "cage_speed_ratio": "-", "cage_slip": "-", "max_roller_slip": "-",
    "max_roller_slip_inner": "-", "max_roller_slip_outer": "-", "max_roller_load": "N", "max_impact_load": "N",
    "roller_loads": "angle_deg: deg, load_N: N", "inner_ring_displacement": "m", "inner_ring_offset": "m",
    "max_pocket_force": "N", "energy_balance_error": "-", "max_cage_eccentricity": "m", "analysis_start": "s",
    "max_frictional_power_intensity": "W/mm²", "max_frictional_power_intensity_inner": "W/mm²",
    "max_frictional_power_intensity_outer": "W/mm²",
}

#: The raceway contact groups, in the order of the ``_inner``, ``_outer`` entries.
RACEWAYS = (Group.INNER_RACE, Group.OUTER_RACE)
#: W/m² in one W/mm², the unit of the frictional power intensity in the outputs.
W_PER_MM2 = 1e6


class LineContact(NamedTuple):
    """The Hertz line contact of a roller on a raceway: reduced modulus E' = 2/[(1 − ν₁²)/E₁ + (1 − ν₂²)/E₂] [Pa],
    reduced radius R [m] in the rolling direction and length l [m]."""

    reduced_modulus: float
    radius: float
    length: float


def raceway_contact(spec, scene, group: str) -> LineContact:
    """E', R and l of the raceway ``group`` ('inner_race' or 'outer_race'): the lubricated pair's traction row
    carries them; for another law, the builder's :func:`~bearing_mbs.models.cylindrical_roller.build.
    raceway_line_contact`, which makes that row."""
    pair = scene.pairs[int(pair_columns(scene, group)[0])]
    if pair.law.traction:
        row = dict(zip(TRACTION_COLUMNS, pair.law.traction))
        return LineContact(row["modulus"], row["radius"], row["length"])
    return LineContact(*raceway_line_contact(spec, BearingGeometry.from_spec(spec.bearing), group))


def frictional_power_intensity(traction, sliding, load, contact: LineContact) -> np.ndarray:
    """q = |F Δu|/(2 b l) [W/m²] of line contacts carrying ``load`` Q [N] with the traction F [N] at the sliding
    speed Δu [m/s] (arrays of one shape); 0 where Q <= 0 (no contact)."""
    traction, sliding = np.broadcast_arrays(*(np.asarray(x, float) for x in (traction, sliding)))
    return power_intensity(traction * sliding, load, contact)


def power_intensity(power, load, contact: LineContact) -> np.ndarray:
    """q = |P|/(2 b l) [W/m²] of line contacts carrying ``load`` Q [N] whose friction dissipates ``power`` P [W]
    (arrays of one shape), b Hertz's half-width at Q/l; 0 where Q <= 0 (no contact)."""
    power, load = np.broadcast_arrays(*(np.asarray(x, float) for x in (power, load)))
    touching = load > 0
    half_width = hertz_half_width(np.where(touching, load, 1.0) / contact.length, contact.radius, contact.reduced_modulus)
    return np.where(touching, np.abs(power) / (2 * half_width * contact.length), 0.0)


def law_traction(scene, pair: int, load, sliding, rolling) -> np.ndarray:
    """The traction μQ [N] (along the pair's tangent) that pair ``pair``'s friction law gives at each load Q [N],
    slip Δu and rolling speed u [m/s] (arrays of one shape): the kernel's own law, without what resists the rolling;
    0 where Q <= 0."""
    laws = pack([scene.pairs[pair]])
    law, coefficient, regularisation, row = (laws.friction_law[0], laws.friction_coefficient[0],
                                             laws.regularisation_speed[0], laws.traction[0])
    load, sliding, rolling = np.broadcast_arrays(*(np.asarray(x, float) for x in (load, sliding, rolling)))
    traction = np.zeros(load.shape)
    for index in np.ndindex(load.shape):
        if load[index] > 0:
            traction[index] = kernel.tangential_force(law, load[index], coefficient, sliding[index], rolling[index],
                                                      regularisation, row)
    return traction


def raceway_power_intensity(spec, scene, result, mask, group: str) -> np.ndarray:
    """(T, Z) frictional power intensity [W/m²] of the raceway ``group``'s contacts at the instants in ``mask``."""
    contact = raceway_contact(spec, scene, group)
    columns = pair_columns(scene, group)
    load, slip, rolling = (result.pair_series(name)[mask][:, columns]
                           for name in ("normal_force", "slip", "rolling_speed"))
    traction = np.column_stack([law_traction(scene, int(k), load[:, j], slip[:, j], rolling[:, j])
                                for j, k in enumerate(columns)]) if columns.size else np.zeros(load.shape)
    return frictional_power_intensity(traction, slip, load, contact)


def window(spec, result) -> np.ndarray:
    """Boolean mask of the output instants in the analysis window."""
    start = spec.analysis.window_start(spec.scenario.end_time)
    mask = result.time >= start - 1e-12
    return mask if mask.any() else np.ones_like(result.time, dtype=bool)


def roller_indices(scene) -> np.ndarray:
    """Body indices of the rollers, in roller order."""
    return scene.topology.role(Role.ROLLERS)


def pair_columns(scene, group: str) -> np.ndarray:
    """Pair indices of a contact group (``inner_race``, ``outer_race``, ``pocket``, ``land``, ``roller``), flat,
    in roller order."""
    return scene.topology.group(group).ravel()


def cage_speed(scene, result) -> np.ndarray:
    """Cage angular speed [rad/s] (T,): the cage body's, or the rollers' mean orbital speed without a cage."""
    if scene.topology.has(Role.CAGE):
        return result.velocity[:, 3 * scene.topology.body(Role.CAGE) + 2]
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
    raceways = np.concatenate([pair_columns(scene, Group.INNER_RACE), pair_columns(scene, Group.OUTER_RACE)])
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
    force = result.pair_series("normal_force")[mask][:, pair_columns(scene, Group.INNER_RACE)].ravel()
    edges = np.linspace(0, 360, bins + 1)
    which = np.clip(np.digitize(angle, edges) - 1, 0, bins - 1)
    sums = np.bincount(which, weights=force, minlength=bins)
    counts = np.bincount(which, minlength=bins)
    with np.errstate(invalid="ignore"):
        return 0.5 * (edges[1:] + edges[:-1]), np.where(counts > 0, sums / np.maximum(counts, 1), np.nan)


def cage_eccentricity(scene, result) -> float | None:
    """The largest distance of the cage centre from the bearing axis over the run [m]; None without a cage."""
    if not scene.topology.has(Role.CAGE):
        return None
    cage = scene.topology.body(Role.CAGE)
    return float(np.hypot(result.position[:, 3 * cage], result.position[:, 3 * cage + 1]).max())


def bearing_warnings(spec, scene, result) -> list[str]:
    """What makes the run's numbers meaningless: a cage more than half a roller diameter off the axis has left
    its rollers (the runner's ``guard_warnings`` check)."""
    eccentricity = cage_eccentricity(scene, result)
    half_roller = spec.bearing.roller_diameter / 2
    if eccentricity is None or not eccentricity > half_roller:
        return []
    return [(f"the cage centre moved {eccentricity:.3g} m off the axis, more than half a roller diameter: it has "
             f"left its rollers and its speed is meaningless")]


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
    slips = {race: slip_ratios(scene, result, race, fraction)[mask] for race in RACEWAYS}
    inner_loads = result.pair_series("normal_force")[mask][:, pair_columns(scene, Group.INNER_RACE)]
    angles, loads = load_distribution(scene, result, mask, 2 * geometry.rollers)
    offset = result.position[mask][:, :2].mean(axis=0)

    pocket = pair_columns(scene, Group.POCKET)
    if pocket.size:
        max_pocket = float(result.pair_series("normal_force")[mask][:, pocket].max())
    elif scene.constraints:
        max_pocket = float(result.constraint_forces[mask].max())
    else:
        max_pocket = None

    def largest(values):
        return float(np.nanmax(np.abs(values))) if np.isfinite(values).any() else None

    intensity = {group: largest(raceway_power_intensity(spec, scene, result, mask, group) / W_PER_MM2)
                 for group in RACEWAYS}

    return {
        "mean_inner_speed_rpm": float(np.mean(inner_speed[mask]) * 60 / (2 * np.pi)),
        "cage_speed_ratio": ratio,
        "cage_slip": 1.0 - ratio,
        "max_roller_slip": largest(np.concatenate([slips[Group.INNER_RACE].ravel(), slips[Group.OUTER_RACE].ravel()])),
        "max_roller_slip_inner": largest(slips[Group.INNER_RACE]),
        "max_roller_slip_outer": largest(slips[Group.OUTER_RACE]),
        "max_roller_load": float(np.percentile(inner_loads.max(axis=1), PEAK_PERCENTILE)),
        "max_impact_load": float(inner_loads.max()),
        "roller_loads": [{"angle_deg": float(a), "load_N": None if np.isnan(f) else float(f)}
                         for a, f in zip(angles, loads)],
        "inner_ring_displacement": float(np.hypot(*offset)),
        "inner_ring_offset": [float(offset[0]), float(offset[1])],
        "max_pocket_force": max_pocket,
        "max_frictional_power_intensity": max((q for q in intensity.values() if q is not None), default=None),
        "max_frictional_power_intensity_inner": intensity[Group.INNER_RACE],
        "max_frictional_power_intensity_outer": intensity[Group.OUTER_RACE],
        **whole_run,
        "analysis_start": float(result.time[mask][0]),
    }
