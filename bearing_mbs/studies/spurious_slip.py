r"""Spurious-slip report: slip that changes when the step is refined.

Above an explicit method's stability limit for the regularised friction (``bearing_mbs.advisor``) a run can stay
bounded and close its guards yet slip wrongly: a spurious skidding cycle whose slip speed is of the order of the
regularisation speed :math:`v_{reg}`, against a true slip orders of magnitude smaller. Halving the step exposes
it: a converged slip does not move, a spurious one does.

:func:`check_spurious_slip` runs the same scene again at the step divided by ``refinement`` (the tolerance divided
by ``refinement**5`` for adaptive methods) and compares, for every friction pair, the *level* of its slip: the
median slip speed over the output instants where the pair carries at least ``load_fraction`` of the run's largest
normal force (:func:`compare_slip_levels`). The slip is spurious where the two levels differ by more than
``slip_tolerance`` :math:`\times v_{reg}` of the pair. Levels, not instants: a caged bearing with pocket impacts is
chaotic beyond a few milliseconds (two converged runs at different steps drift apart event by event), while a
spurious skidding cycle lifts the whole distribution of a loaded roller's slip. The report names the pair, both
levels, the window and a fix.

Pairs whose sliding is their normal state (the cage on its land, a roller end on a flange) slide at metres per
second whatever the step: where both levels exceed :data:`SATURATION` :math:`v_{reg}` the friction force is
saturated at :math:`\mu N` and does not depend on the slip, so the levels are compared relatively, within
:data:`SLIDING_TOLERANCE` of the refined one.

``bearing-mbs advise SCENARIO.toml --check-slip`` and ``bearing-mbs run --check-slip`` run it. The stability suite
compares its short probes (2 ms, inside the predictability horizon) instant by instant against a 4× finer step
(:func:`compare_slips`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from bearing_mbs.core.checks import Check, judged
from bearing_mbs.core.result import Result
from bearing_mbs.core.scene import Scene
from bearing_mbs.spec.solver import SolverSpec
from bearing_mbs.studies.common import refined, resample, setting_of

#: Spurious when slips differ by more than this fraction of the pair's regularisation speed.
SLIP_TOLERANCE = 0.1
#: Pairs carrying less than this fraction of the largest normal force are not compared.
LOAD_FRACTION = 0.05
#: Slips beyond this multiple of v_reg in both runs, of one sign, are saturated sliding [-].
SATURATION = 10.0
#: Saturated sliding is converged when the slips differ by less than this fraction of the refined one [-].
SLIDING_TOLERANCE = 1e-2


@dataclass(frozen=True)
class SlipCheck:
    """Outcome of a spurious-slip comparison.

    ``spurious``: whether the slip levels differ beyond the tolerance. ``difference`` [m/s]: the largest level
    difference over the pairs, ``ratio`` that difference over the pair's tolerance (``SLIP_TOLERANCE`` × v_reg, or
    the relative one of saturated sliding); ``window`` (first, last instant compared) [s], ``pair``, ``slip`` and
    ``refined_slip`` (its two levels [m/s]);
    ``step`` and ``refined_step`` [s] (or tolerances for adaptive methods); ``message``: what a user reads.
    """

    spurious: bool
    difference: float
    ratio: float
    window: tuple[float, float]
    pair: str | None
    slip: float
    refined_slip: float
    step: float
    refined_step: float
    message: str

    def to_check(self) -> Check:
        """The ``spurious_slip`` check of a run: the largest slip change over its tolerance, bound 1."""
        return judged("spurious_slip", self.ratio, 1.0, not self.spurious, "-", self.message)


def slip_tolerances(slip, reference_slip, regularisation, slip_tolerance: float = SLIP_TOLERANCE) -> np.ndarray:
    """How far ``slip`` may sit from ``reference_slip`` [m/s] and still be converged: ``slip_tolerance`` × v_reg,
    or, where both slide the same way faster than :data:`SATURATION` v_reg (saturated friction), also
    :data:`SLIDING_TOLERANCE` of the reference. Arrays broadcast."""
    sliding = (np.abs(reference_slip) > SATURATION * regularisation) & (slip * reference_slip > 0) \
        & (np.abs(slip) > SATURATION * regularisation)
    absolute = slip_tolerance * regularisation
    return np.where(sliding, np.maximum(absolute, SLIDING_TOLERANCE * np.abs(reference_slip)), absolute)


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
    regularisation = np.array([p.law.regularisation_speed for p in scene.pairs])[None, :]
    tolerance = slip_tolerances(slip, reference_slip, regularisation, slip_tolerance)
    with np.errstate(invalid="ignore"):
        ratio = np.where(loaded, np.abs(slip - reference_slip) / tolerance, -1.0)
    ratio = np.where(np.isnan(ratio), np.inf, ratio)  # a non-finite slip is as spurious as it gets
    if not (ratio >= 0).any():
        return empty
    i, k = np.unravel_index(int(np.argmax(ratio)), ratio.shape)
    return {"ratio": float(ratio[i, k]), "difference": float(abs(slip[i, k] - reference_slip[i, k])),
            "time": float(reference.time[i]), "pair": int(k), "slip": float(slip[i, k]),
            "reference_slip": float(reference_slip[i, k])}


def compare_slip_levels(scene: Scene, run: Result, reference: Result, load_fraction: float = LOAD_FRACTION,
                        slip_tolerance: float = SLIP_TOLERANCE) -> dict:
    """The slip level of every friction pair in ``run`` against ``reference`` (module docstring): the median slip
    speed [m/s] over the instants where the pair carries at least ``load_fraction`` of the run's largest normal
    force. Returns ``ratio`` (the largest level difference over its tolerance), ``difference`` [m/s], ``pair``
    (index, None when no pair is loaded in both runs), ``slip`` and ``reference_slip`` (the two levels [m/s]) and
    ``window`` (first and last output instant compared [s])."""
    friction = np.array([p.law.friction_law != "none" and p.law.friction_coefficient > 0 for p in scene.pairs])
    levels = []
    for result in (run, reference):
        force = result.pair_series("normal_force")
        loaded = (force > 0) & (force >= load_fraction * np.nanmax(force, initial=0.0)) & friction[None, :]
        speeds = np.where(loaded, np.abs(result.pair_series("slip")), np.nan)
        levels.append(np.array([np.median(column[np.isfinite(column)]) if np.isfinite(column).any() else np.nan
                                for column in speeds.T]))
    level, reference_level = levels
    regularisation = np.array([p.law.regularisation_speed for p in scene.pairs])
    tolerance = slip_tolerances(level, reference_level, regularisation, slip_tolerance)
    with np.errstate(invalid="ignore", divide="ignore"):
        ratio = np.abs(level - reference_level) / tolerance
    window = (float(reference.time[0]), float(min(run.time[-1], reference.time[-1])))
    if not np.isfinite(ratio).any():
        return {"ratio": 0.0, "difference": 0.0, "pair": None, "slip": math.nan, "reference_slip": math.nan,
                "window": window}
    k = int(np.nanargmax(ratio))
    return {"ratio": float(ratio[k]), "difference": float(abs(level[k] - reference_level[k])), "pair": k,
            "slip": float(level[k]), "reference_slip": float(reference_level[k]), "window": window}


def check_spurious_slip(scene: Scene, solver: SolverSpec, end_time: float, result: Result | None = None,
                        refinement: float = 2.0, progress=None) -> SlipCheck:
    """Run ``scene`` at the refined step (and at the given step unless ``result`` is that run) and compare the slip
    levels (:func:`compare_slip_levels`)."""
    from bearing_mbs.numerics.advisor import step_advice
    from bearing_mbs.runner import simulate_advised

    if result is None:
        result = simulate_advised(scene, solver, end_time, progress)
    finer_solver = refined(solver, refinement)
    finer = simulate_advised(scene, finer_solver, end_time, progress)
    found = compare_slip_levels(scene, result, finer)
    step, finer_step = setting_of(solver), setting_of(finer_solver)
    what = "tolerance" if solver.active.adaptive else "step"
    spurious = found["ratio"] > 1.0
    if found["pair"] is None:
        message = "no loaded friction pair to compare"
    else:
        pair = scene.pairs[found["pair"]]
        start, end = found["window"]
        detail = (f"pair {pair.name!r}: median slip {found['slip']:.3g} m/s at {what} {step:.3g} but "
                  f"{found['reference_slip']:.3g} m/s at {finer_step:.3g}, over t = {start:.6g}…{end:.6g} s")
        if spurious:
            message = (f"{detail}: the slip is spurious (its level changes by {found['difference']:.3g} m/s, more "
                       f"than {SLIP_TOLERANCE:g} v_reg = {SLIP_TOLERANCE * pair.law.regularisation_speed:.3g} m/s, "
                       f"when the {what} is refined {refinement:g}x). Likely fix: "
                       f"{step_advice(scene, solver).text()}.")
        else:
            message = f"slip converged: the largest change of a slip level is {found['difference']:.3g} m/s ({detail})"
    return SlipCheck(spurious, found["difference"], found["ratio"], found["window"],
                     None if found["pair"] is None else scene.pairs[found["pair"]].name, found["slip"],
                     found["reference_slip"], step, finer_step, message)
