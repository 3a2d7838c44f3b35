"""The units of a run summary's entries, and the digits they are written with.

Floats are written with :data:`bearing_mbs.io.json.DIGITS` significant digits (:func:`~bearing_mbs.io.json.rounded`).
Each model adds the units of its own metrics (:attr:`bearing_mbs.models.protocol.Model.units`); summary.json
carries the map of the entries it holds as ``units``.
"""

from __future__ import annotations

#: Units of the entries every run summary has.
RUN_UNITS = {
    "step": "s",
    "end_time": "s",
    "wall_time_s": "s",
    "steps": "count",
    "rejected_steps": "count",
    "force_evaluations": "count",
    "newton_iterations": "count",
}
