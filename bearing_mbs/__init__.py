"""bearing_mbs: transient dynamics of rolling bearings on Exudyn, cross-checked by a reference engine."""

from bearing_mbs._numba_cache import invalidate_if_stale

invalidate_if_stale()

__version__ = "0.1.0"
