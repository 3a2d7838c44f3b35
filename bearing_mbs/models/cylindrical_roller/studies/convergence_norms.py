"""The bearing's norms for a work–precision study (:mod:`bearing_mbs.studies.convergence`), over the analysis
window (``[analysis]``, the run's steady part) unless ``[convergence] start`` says otherwise:

* ``cage_speed``: |Δ mean cage speed| / reference mean cage speed;
* ``roller_loads``: max |Δ inner-raceway roller load| / largest reference roller load;
* ``slips``: max |Δ slip ratio| at loaded raceway contacts (absolute: slip ratios are already ratios);

and, for the study's summary, ``reference_largest_slip``: the reference's largest |slip ratio| at loaded contacts
(the scale of the ``slips`` norm)."""

from __future__ import annotations

import numpy as np

from bearing_mbs.core.topology import Group
from bearing_mbs.models.cylindrical_roller import metrics as skidding
from bearing_mbs.models.protocol import ErrorNorms

RACES = (Group.INNER_RACE, Group.OUTER_RACE)


def window_start(spec) -> float:
    """The analysis window's start [s] for the scenario's end time."""
    return spec.analysis.window_start(spec.scenario.end_time)


def errors(spec, scene, run, reference, mask) -> dict:
    """``cage_speed``, ``roller_loads`` and ``slips`` of ``run`` against ``reference`` over ``mask``."""
    cage_run, cage_ref = skidding.cage_speed(scene, run)[mask], skidding.cage_speed(scene, reference)[mask]
    norms = {"cage_speed": float(abs(cage_run.mean() - cage_ref.mean()) / abs(cage_ref.mean()))}
    inner = skidding.pair_columns(scene, Group.INNER_RACE)
    loads_run = run.pair_series("normal_force")[mask][:, inner]
    loads_ref = reference.pair_series("normal_force")[mask][:, inner]
    norms["roller_loads"] = float(np.abs(loads_run - loads_ref).max() / loads_ref.max())
    fraction = spec.analysis.load_fraction
    slips = [np.abs(skidding.slip_ratios(scene, run, race, fraction)[mask]
                    - skidding.slip_ratios(scene, reference, race, fraction)[mask]) for race in RACES]
    both = np.concatenate([s.ravel() for s in slips])
    norms["slips"] = float(np.nanmax(both)) if np.isfinite(both).any() else float("nan")
    return norms


def largest_slip(spec, scene, result, mask) -> float:
    """The largest |slip ratio| of ``result`` at loaded contacts over ``mask`` (0 where none is loaded)."""
    fraction = spec.analysis.load_fraction
    slips = [np.abs(skidding.slip_ratios(scene, result, race, fraction)[mask]) for race in RACES]
    both = np.concatenate([s.ravel() for s in slips])
    return float(np.nanmax(both)) if np.isfinite(both).any() else 0.0


#: The bearing's norms (with the positions norm every model has).
ERROR_NORMS = ErrorNorms(names=("positions", "cage_speed", "roller_loads", "slips"), window_start=window_start,
                         errors=errors,
                         scales=lambda spec, scene, reference, mask: {
                             "reference_largest_slip": largest_slip(spec, scene, reference, mask)})
