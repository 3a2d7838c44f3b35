r"""Spurious-slip report: slip that changes when the step is refined.

Above an explicit method's stability limit for the regularised friction (``bearing_mbs.advisor``) a run can stay
bounded and close its guards yet slip wrongly: a spurious skidding cycle whose slip speed is of the order of the
regularisation speed :math:`v_{reg}`, against a true slip orders of magnitude smaller. Halving the step exposes
it: a converged slip does not move, a spurious one does.

:func:`check_spurious_slip` runs the same scene again at the step divided by ``refinement`` (the tolerance divided
by ``refinement**5`` for adaptive methods) and compares the slip speed of every friction pair at every output
instant where the pair carries at least ``load_fraction`` of the largest normal force of the refined run. The
slip is spurious where the two differ by more than ``slip_tolerance`` :math:`\times v_{reg}` of the pair.
The report names the time, the pair, both slips and a fix.

``bearing-mbs advise SCENARIO.toml --check-slip`` runs it; the stability suite uses the same comparison against
a 4× finer step.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from bearing_mbs.core.result import Result
from bearing_mbs.core.scene import Scene
from bearing_mbs.spec.solver import SolverSpec
from bearing_mbs.studies.common import refined, resample, setting_of

#: Spurious when slips differ by more than this fraction of the pair's regularisation speed.
SLIP_TOLERANCE = 0.1
#: Pairs carrying less than this fraction of the largest normal force are not compared.
LOAD_FRACTION = 0.05


@dataclass(frozen=True)
class SlipCheck:
    """Outcome of a spurious-slip comparison.

    ``spurious``: whether the slips differ beyond the tolerance. ``difference`` [m/s]: the largest slip
    difference over compared instants and pairs, ``ratio`` that difference over the pair's tolerance
    (``SLIP_TOLERANCE`` × v_reg); ``time`` [s], ``pair``, ``slip``, ``refined_slip`` [m/s] where it occurs;
    ``step`` and ``refined_step`` [s] (or tolerances for adaptive methods); ``message``: what a user reads.
    """

    spurious: bool
    difference: float
    ratio: float
    time: float | None
    pair: str | None
    slip: float
    refined_slip: float
    step: float
    refined_step: float
    message: str


def compare_slips(scene: Scene, run: Result, reference: Result, load_fraction: float = LOAD_FRACTION,
                  slip_tolerance: float = SLIP_TOLERANCE) -> dict:
    """Largest slip difference of ``run`` against ``reference`` over loaded friction pairs at the reference's output
    instants (``run`` interpolated linearly onto them where its own instants differ: Exudyn records the first step
    at or after each output instant, and an implicit solver that halves a step shifts them).

    Returns ``ratio`` (difference over slip_tolerance × v_reg, the largest), ``difference`` [m/s], ``time``,
    ``pair`` (index), ``slip``, ``reference_slip``; ``ratio`` is 0 when nothing can be compared.
    """
    friction = np.array([p.law.friction_law != "none" and p.law.friction_coefficient > 0 for p in scene.pairs])
    empty = {"ratio": 0.0, "difference": 0.0, "time": None, "pair": None, "slip": math.nan, "reference_slip": math.nan}
    if not friction.any():
        return empty
    count = int(np.searchsorted(reference.time, run.time[-1] * (1 + 1e-12), side="right")) if run.time.size else 0
    if count == 0:
        return empty
    force = reference.pair_series("normal_force")[:count]
    loaded = (force >= load_fraction * np.nanmax(force)) & friction[None, :] & (force > 0)
    reference_slip = reference.pair_series("slip")[:count]
    slip = resample(run.time, run.pair_series("slip"), reference.time[:count])
    tolerance = slip_tolerance * np.array([p.law.regularisation_speed for p in scene.pairs])
    with np.errstate(invalid="ignore"):
        ratio = np.where(loaded, np.abs(slip - reference_slip) / tolerance[None, :], -1.0)
    ratio = np.where(np.isnan(ratio), np.inf, ratio)  # a non-finite slip is as spurious as it gets
    if not (ratio >= 0).any():
        return empty
    i, k = np.unravel_index(int(np.argmax(ratio)), ratio.shape)
    return {"ratio": float(ratio[i, k]), "difference": float(abs(slip[i, k] - reference_slip[i, k])),
            "time": float(reference.time[i]), "pair": int(k), "slip": float(slip[i, k]),
            "reference_slip": float(reference_slip[i, k])}


def check_spurious_slip(scene: Scene, solver: SolverSpec, end_time: float, result: Result | None = None,
                        refinement: float = 2.0, progress=None) -> SlipCheck:
    """Run ``scene`` at the refined step (and at the given step unless ``result`` is that run) and compare."""
    from bearing_mbs.engines import simulate
    from bearing_mbs.numerics.advisor import advise

    if result is None:
        result = simulate(scene, solver, end_time, progress)
    finer_solver = refined(solver, refinement)
    finer = simulate(scene, finer_solver, end_time, progress)
    found = compare_slips(scene, result, finer)
    step, finer_step = setting_of(solver), setting_of(finer_solver)
    what = "tolerance" if solver.active.adaptive else "step"
    spurious = found["ratio"] > 1.0
    if found["pair"] is None:
        message = "no loaded friction pair to compare"
    else:
        pair = scene.pairs[found["pair"]]
        detail = (f"t = {found['time']:.6g} s: pair {pair.name!r} slips {found['slip']:.3g} m/s at {what} {step:.3g} "
                  f"but {found['reference_slip']:.3g} m/s at {finer_step:.3g}")
        if spurious:
            limit = advise(scene).recommended(solver.engine, solver.active.method)
            advice = f" below the advised {limit:.2g} s" if limit else ""
            message = (f"{detail}: the slip is spurious (it changes by {found['difference']:.3g} m/s, more than "
                       f"{SLIP_TOLERANCE:g} v_reg = {SLIP_TOLERANCE * pair.law.regularisation_speed:.3g} m/s, when the "
                       f"{what} is refined {refinement:g}x). Likely fix: reduce the {what}{advice} "
                       f"(bearing-mbs advise), or use generalized-alpha.")
        else:
            message = f"slip converged: the largest change is {found['difference']:.3g} m/s ({detail})"
    return SlipCheck(spurious, found["difference"], found["ratio"], found["time"],
                     None if found["pair"] is None else scene.pairs[found["pair"]].name, found["slip"],
                     found["reference_slip"], step, finer_step, message)
