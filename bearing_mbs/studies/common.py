"""What the studies share: variations of a spec, solver refinement and resampling onto a common time grid.

* :func:`with_overrides` changes fields of a validated spec by their dotted paths (as ``--set`` does on a
  file), validated again through :func:`bearing_mbs.models.spec_from_mapping`;
* :func:`solver_at`, :func:`refined` and :func:`refined_setting` set or refine a solver's step [s] (fixed-step
  methods) or tolerance (adaptive methods; divided by ``refinement**5``, the error of a fifth-order pair
  shrinking about as a step divided by ``refinement`` would);
* :func:`resample` and :func:`resample_result` interpolate series linearly onto other output instants [s],
  exactly where the instants coincide.
"""

from __future__ import annotations

import copy
import dataclasses
from collections.abc import Mapping

import numpy as np

from bearing_mbs.core.result import Result
from bearing_mbs.models import spec_from_mapping
from bearing_mbs.spec import Spec, SpecError, apply_override, to_mapping
from bearing_mbs.spec.solver import SolverSpec

#: Instants [s] closer than this are the same instant.
SAME_INSTANT = 1e-12

# ----------------------------------------------------------------------------------------------------------------
# Specs
# ----------------------------------------------------------------------------------------------------------------


def spec_mapping(spec: Spec) -> dict:
    """The spec as a fresh plain mapping (:func:`bearing_mbs.spec.to_mapping`) that may be edited and validated
    again with :func:`bearing_mbs.models.spec_from_mapping`."""
    return copy.deepcopy(to_mapping(spec))


def with_overrides(spec: Spec, overrides: Mapping[str, object]) -> Spec:
    """``spec`` with the fields at the dotted paths of ``overrides`` (e.g. ``{"load.radial": 2000.0}``, values in
    the units of the scenario format) replaced, validated like a scenario file. A value of ``None`` removes the
    field, so its default applies (``{"convergence": None}`` drops the section). Raises
    :class:`bearing_mbs.spec.SpecError` naming the field."""
    data = spec_mapping(spec)
    for path, value in overrides.items():
        keys = path.split(".")
        if not all(keys):
            raise SpecError(path, value, "the path must be dotted keys like section.key")
        if value is None:
            _remove(data, keys)
        else:
            apply_override(data, keys, value)
    return spec_from_mapping(data)


def _remove(data: dict, keys: list[str]) -> None:
    node = data
    for key in keys[:-1]:
        node = node.get(key) if isinstance(node, dict) else None
        if node is None:
            return
    if isinstance(node, dict):
        node.pop(keys[-1], None)


# ----------------------------------------------------------------------------------------------------------------
# Solver settings and refinement
# ----------------------------------------------------------------------------------------------------------------


def solver_at(solver: SolverSpec, engine: str, method: str, value: float, *, largest_step: float,
              **changes) -> SolverSpec:
    """``solver`` switched to ``engine`` and its ``method`` at ``value``: the step [s] of a fixed-step method, or
    the tolerance of an adaptive one, whose first and largest step is then ``largest_step`` [s]. ``changes``
    set further fields of the engine's settings (e.g. ``connector``); the reference engine's ``contact_step``
    (central difference's own) is cleared."""
    if engine == "reference":
        changes["contact_step"] = None
    settings = dataclasses.replace(getattr(solver, engine), method=method, **changes)
    if settings.adaptive:
        settings = dataclasses.replace(settings, tolerance=value, step=largest_step)
    else:
        settings = dataclasses.replace(settings, step=value)
    return dataclasses.replace(solver, engine=engine, **{engine: settings})


def refined_setting(value: float, refinement: float, adaptive: bool) -> float:
    """A step [s] divided by ``refinement``, or a tolerance (``adaptive``) divided by ``refinement**5``."""
    return value / refinement**5 if adaptive else value / refinement


def refined(solver: SolverSpec, refinement: float = 2.0) -> SolverSpec:
    """The same settings refined by ``refinement``: the step (and central difference's contact step) divided by
    it, or an adaptive method's tolerance divided by ``refinement**5``."""
    settings = solver.active
    if settings.adaptive:
        changed = dataclasses.replace(settings, tolerance=refined_setting(settings.tolerance, refinement, True))
    else:
        changes = {"step": refined_setting(settings.step, refinement, False)}
        if getattr(settings, "contact_step", None):
            changes["contact_step"] = refined_setting(settings.contact_step, refinement, False)
        changed = dataclasses.replace(settings, **changes)
    return dataclasses.replace(solver, **{solver.engine: changed})


def setting_of(solver: SolverSpec) -> float:
    """What a refinement divides: the step [s] (central difference's contact step where set), or the tolerance of
    an adaptive method."""
    settings = solver.active
    if settings.adaptive:
        return settings.tolerance
    return getattr(settings, "contact_step", None) or settings.step


# ----------------------------------------------------------------------------------------------------------------
# Resampling
# ----------------------------------------------------------------------------------------------------------------


def same_instants(times: np.ndarray, at: np.ndarray) -> bool:
    """Whether two grids of output instants [s] coincide."""
    return times.size == at.size and np.allclose(times, at, rtol=0, atol=SAME_INSTANT)


def resample(times: np.ndarray, series: np.ndarray, at: np.ndarray) -> np.ndarray:
    """``series`` (first axis along ``times`` [s], any further axes) at the instants ``at`` [s]: linear
    interpolation of every column, the series itself where the instants coincide."""
    if same_instants(times, at):
        return series
    flat = series.reshape(series.shape[0], -1)
    columns = np.empty((at.size, flat.shape[1]))
    for j in range(flat.shape[1]):
        columns[:, j] = np.interp(at, times, flat[:, j])
    return columns.reshape((at.size,) + series.shape[1:])


def resample_result(result: Result, at: np.ndarray) -> Result:
    """The result's positions, velocities and pair outputs at the instants ``at`` [s] (see :func:`resample`);
    the result itself where the instants coincide."""
    if same_instants(result.time, at):
        return result
    return dataclasses.replace(result, time=at, position=resample(result.time, result.position, at),
                               velocity=resample(result.time, result.velocity, at),
                               pair_output=resample(result.time, result.pair_output, at))
