"""bearing_mbs: transient dynamics of rolling bearings on Exudyn, cross-checked by a reference engine."""

__version__ = "0.1.0"
