"""Whether a bearing run's analysis window is steady: the ``window_settled`` check of the studies that read steady
values from a run (``skidding``, ``cage-models``; docs/status.md).

The cage slip's means over the two halves of the window must agree to the pocket-play resolution of a half
window (:func:`pocket_play_resolution`, penalty cage) plus :data:`SETTLED_FRACTION` of the window's mean: a
light-load run still approaching its steady slip drifts by more. A window that has not settled is a failed check
(the run is ``suspect``), never a success.
"""

from __future__ import annotations

import numpy as np

from bearing_mbs.core.checks import Check, upper_bound
from bearing_mbs.models.cylindrical_roller.figures import cage_slip_series
from bearing_mbs.models.cylindrical_roller.geometry import BearingGeometry
from bearing_mbs.models.cylindrical_roller.metrics import window
from bearing_mbs.spec import Spec

#: Fraction of the window's mean cage slip by which its halves may differ on top of the pocket-play resolution.
SETTLED_FRACTION = 0.05


def pocket_play_resolution(spec: Spec, duration: float) -> float:
    """Apparent cage slip [-] that the pocket clearance alone can produce over ``duration`` [s]: the cage's angle
    relative to the roller set varies by up to 2H/(D_pw/2), against the epicyclic angle ω_c,epi · duration.
    Zero for the constraint cage (its angle is locked to the rollers) and without a cage."""
    if spec.cage.model != "penalty":
        return 0.0
    geometry = BearingGeometry.from_spec(spec.bearing)
    inner_speed = spec.drive.speed_rpm * 2 * np.pi / 60
    travel = geometry.epicyclic_cage_speed(inner_speed) * duration
    return float(2 * geometry.pocket_clearance / (geometry.pitch_diameter / 2) / travel)


def window_halves(spec: Spec, scene, result) -> tuple[float, float, float]:
    """(mean cage slip over the first half of the analysis window, over the second half [-], the window's
    duration [s])."""
    mask = window(spec, result)
    slip = cage_slip_series(spec, scene, result)[mask]
    if not np.isfinite(slip).any():  # the cage slip is not defined at rest
        return float("nan"), float("nan"), float(result.time[mask][-1] - result.time[mask][0])
    first, second = (float(np.nanmean(half)) if np.isfinite(half).any() else float("nan")
                     for half in np.array_split(slip, 2))
    return first, second, float(result.time[mask][-1] - result.time[mask][0])


def window_settled(spec: Spec, scene, result) -> Check:
    """The ``window_settled`` check: |first − second half's mean cage slip| [-] within the pocket-play resolution of a
    half window plus :data:`SETTLED_FRACTION` of the halves' mean (an undefined slip fails)."""
    first, second, duration = window_halves(spec, scene, result)
    tolerance = pocket_play_resolution(spec, duration / 2) + SETTLED_FRACTION * abs(first + second) / 2
    end, start = spec.scenario.end_time, spec.analysis.window_start(spec.scenario.end_time)
    return upper_bound("window_settled", abs(first - second), tolerance, "-",
                       f"the cage slip's window halves are {100 * first:.3g} % and {100 * second:.3g} %: the mean is "
                       "not steady (a light-load bearing approaches its steady slip over about a second). Likely fix: "
                       f"scenario.end_time = {2 * end - start:g} with analysis.start = {end:g} (a window of the same "
                       "length, later)")
