"""Per-pair state handled once per accepted step, identically by both engines.

After every accepted step an engine calls :func:`advance_pair_state`, which

* latches or resets each pair's approach speed (:func:`bearing_mbs.contact.normal.latch_approach_speed`);
* records the first impact (onset time and approach speed) and the first separation (time and separation
  speed) of each pair, from which the effective restitution follows;
* reports the pair whose penetration exceeds its bound the most (the run guard).

Events are stored in an array of shape (pairs, 4) with the columns of :data:`EVENT_COLUMNS`, NaN until
the event happens.
"""

from __future__ import annotations

import numba
import numpy as np

from bearing_mbs.contact import normal
from bearing_mbs.contact.kernel import body_trigonometry, pair_motion, pair_position

EVENT_COLUMNS = ("impact_time", "impact_speed", "separation_time", "separation_speed")


def new_events(pair_count: int) -> np.ndarray:
    return np.full((pair_count, len(EVENT_COLUMNS)), np.nan)


def initial_pair_state(pairs, penetration_limit: float):
    """(latched approach speeds, event log, penetration bounds) of a run's start, for both engines."""
    count = pairs.kind.size
    return np.zeros(count), new_events(count), penetration_bounds(pairs, penetration_limit)


def penetration_bounds(pairs, fraction: float) -> np.ndarray:
    """Largest admissible penetration per pair [m]: ``fraction`` of the smaller non-zero radius."""
    radius = np.where(pairs.radius_a > 0, np.minimum(pairs.radius_a, pairs.radius_b), pairs.radius_b)
    return fraction * radius


@numba.njit(cache=True)
def advance_pair_state(pairs, q, v, t, latched, events, penetration_bound):
    """Update latches and events after an accepted step at time t.

    Returns (changed, worst): ``changed`` is True when a latch changed (a stage value computed before the
    update is then stale); ``worst`` is the index of the pair that exceeds its penetration bound the most,
    or −1.
    """
    changed = False
    worst, worst_excess = -1, 1.0
    cos_theta, sin_theta = body_trigonometry(q)
    for k in range(pairs.kind.size):
        a, b, kind = pairs.body_a[k], pairs.body_b[k], pairs.kind[k]
        ra, rb = pairs.radius_a[k], pairs.radius_b[k]
        gap, nx, ny, px, py = pair_position(
            kind, a, b, pairs.anchor[k, 0], pairs.anchor[k, 1], pairs.direction[k, 0], pairs.direction[k, 1],
            ra, rb, q, cos_theta[a] if a >= 0 else 1.0, sin_theta[a] if a >= 0 else 0.0)
        was_in_contact = latched[k] > 0.0
        if gap >= 0.0 and not was_in_contact:  # apart before and after: nothing to latch or record
            latched[k] = 0.0
            continue
        gap_rate = pair_motion(kind, a, b, ra, rb, gap, nx, ny, px, py, q, v)[0]
        new = normal.latch_approach_speed(gap, gap_rate, latched[k], pairs.approach_speed_floor[k])
        if new != latched[k]:
            changed = True
        latched[k] = new
        if gap < 0.0 and not was_in_contact and np.isnan(events[k, 0]):
            events[k, 0] = t
            events[k, 1] = -gap_rate
        if gap >= 0.0 and was_in_contact and np.isnan(events[k, 2]):
            events[k, 2] = t
            events[k, 3] = gap_rate
        excess = -gap / penetration_bound[k]
        if excess > worst_excess:
            worst, worst_excess = k, excess
    return changed, worst
