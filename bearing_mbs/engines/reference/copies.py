"""Copies between arrays of one shape, element by element, for the compiled engine.

numba compiles a slice assignment between arrays (``a[:] = b``, ``a += b``) with a shape check whose error message
is formatted by compiled code: seconds of the first compilation for a check that cannot fail here, where every
array is made for its place (:mod:`bearing_mbs.engines.reference.bundles`).
"""

from __future__ import annotations

import numba
import numpy as np


@numba.njit(cache=True, inline="always")
def copy_into(target, source):
    """target[...] = source, for arrays of the same shape."""
    for index in np.ndindex(source.shape):
        target[index] = source[index]
