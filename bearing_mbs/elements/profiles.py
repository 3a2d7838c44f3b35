"""Time profiles (:class:`bearing_mbs.core.scene.Profile`) packed into flat tables, and their compiled value."""

from __future__ import annotations

import numba
import numpy as np


def pack_profiles(profiles) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(index (n, 2) int64 of start and length per profile, flat times [s], flat values) of ``profiles``."""
    index, start = [], 0
    for profile in profiles:
        index.append((start, len(profile.times)))
        start += len(profile.times)
    return (np.array(index, dtype=np.int64).reshape(-1, 2),
            np.array([t for p in profiles for t in p.times], dtype=float),
            np.array([v for p in profiles for v in p.values], dtype=float))


@numba.njit(cache=True)
def profile_value(times, values, start, count, t):
    """Value at time t of the piecewise-linear profile stored at [start, start + count) of the tables."""
    return np.interp(t, times[start : start + count], values[start : start + count])
