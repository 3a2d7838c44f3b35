"""bearing_mbs: transient dynamics of rolling bearings on Exudyn, cross-checked by a reference engine.

Importing the package changes nothing outside it: no backend switches, no logger levels, no files touched.
"""

__version__ = "0.1.0"
