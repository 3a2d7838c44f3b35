"""Engine-neutral diagnosis of runs: the output instants, and a failure's message from its kind
(:class:`~bearing_mbs.core.failures.Failure`) and the state where the run stopped.

A message names the time, the body or pair at fault, and a likely fix that names a value and fits what the run
already uses. A fix that changes the step quotes ``step_advice``, the run's one step advice that the runner passes
down (:func:`bearing_mbs.numerics.advisor.step_advice`: within the step advisor's stability limit for the method and
scene; engines know no model and cannot compute it); without it, a quarter of the step or a hundredth of the
tolerance.
"""

from __future__ import annotations

import numpy as np

from bearing_mbs.contact import twin
from bearing_mbs.contact.kernel import N_PAIR_OUTPUTS
from bearing_mbs.contact.state import penetration_bounds
from bearing_mbs.core.failures import Failure
from bearing_mbs.elements import contact_pairs, pack_scene, scene_forces

COORDINATE_NAMES = ("x", "y", "theta")


def output_grid(end_time: float, interval: float) -> np.ndarray:
    """Output instants [s] 0, Δ, 2Δ, …, ending exactly at end_time."""
    count = int(np.floor(end_time / interval * (1 + 1e-12)))
    grid = np.arange(count + 1) * interval
    return grid if np.isclose(grid[-1], end_time, rtol=1e-12, atol=0) else np.append(grid, end_time)


def failure_message(failure: Failure, scene, solver, t: float, culprit: int, q, v, latched, h: float,
                    step_advice: str | None = None) -> str:
    """The message of a run that stopped at t [s] with ``failure``, from the last good state (q, v, latched).

    ``culprit``: the offending coordinate (non-finite state, blow-up) or pair (penetration); ``h`` [s]: the
    step when it stopped (the adaptive step on an underflow). The fixes quote the active engine's settings, and
    ``step_advice`` where they change the step (:func:`step_fix`).
    """
    settings = solver.active
    if failure == Failure.NONE:
        return ""
    if failure == Failure.INTERRUPTED:
        return interrupted_message(t)
    if failure.diverged:
        return diverged_message(scene, solver, t, culprit, q, v, latched, failure == Failure.BLOWUP, step_advice)
    if failure == Failure.PENETRATION:
        return penetration_message(scene, solver, t, culprit, q, v, step_advice)
    if failure == Failure.STEP_UNDERFLOW:
        what = ("Newton's method kept failing and generalized-alpha's step" if getattr(settings, "implicit", False)
                else "the adaptive step")
        return (f"t = {t:.6g} s: {what} fell to {h:.3g} s. Likely fix: loosen the tolerance "
                f"(now {settings.tolerance:g}) or raise the friction regularisation speed.")
    if failure == Failure.PROJECTION_FAILED:
        return (f"t = {t:.6g} s: the constraint projection did not converge. Likely fix: "
                f"{step_fix(solver, step_advice)}.")
    return f"t = {t:.6g} s: the solver stopped (step {h:.3g} s). Likely fix: {step_fix(solver, step_advice)}."


def step_fix(solver, step_advice: str | None = None) -> str:
    """The fix that changes the step, naming the value: ``step_advice`` (the runner's, within the step advisor's
    limit) when given; else a quarter of the step (or a hundredth of the tolerance) the run used."""
    if step_advice:
        return step_advice
    settings = solver.active
    if settings.adaptive:
        return f"tighten the tolerance from {settings.tolerance:g} to {settings.tolerance / 100:g}"
    return f"reduce the step from {settings.step:g} s to {settings.step / 4:g} s (`bearing-mbs advise` gives the " \
           f"stability limit)"


def divergence_fix(solver, step_advice: str | None = None) -> str:
    """What to change after a divergence, given what the run already uses: an explicit method may switch to the
    implicit solver (the step advice says so); an implicit one that diverges needs a smaller step, or the case is
    beyond the model."""
    if getattr(solver.active, "implicit", False):
        return (f"{step_fix(solver, step_advice)}; if it still diverges, the load or speed is beyond what the "
                f"contacts can carry: check [load] and [drive]")
    if step_advice:
        return step_advice
    return f"{step_fix(solver)}, or switch to Exudyn's generalized_alpha (implicit: no stability limit)"


def interrupted_message(t: float) -> str:
    return f"t = {t:.6g} s: interrupted on request (SIGINT or SIGTERM); the output up to this instant is kept."


def diverged_message(scene, solver, t, coordinate, q, v, latched, blown_up, step_advice=None) -> str:
    """A run diverged: name the body, the most engaged pair (smallest gap) in the last good state, a fix."""
    body = scene.bodies[coordinate // 3].name
    what = (f"moves faster than speed_limit = {solver.speed_limit:g} m/s" if blown_up
            else f"({COORDINATE_NAMES[coordinate % 3]}) became non-finite")
    culprit = ""
    if scene.pairs:
        pair_out = np.empty((len(scene.pairs), N_PAIR_OUTPUTS))
        scene_forces(pack_scene(scene), t, q, v, latched, np.empty_like(q), pair_out)
        k = int(np.argmin(pair_out[:, 0]))
        culprit = (f" The most engaged pair in the last good state was {scene.pairs[k].name!r} "
                   f"(gap {pair_out[k, 0]:.3g} m, normal force {pair_out[k, 3]:.3g} N).")
    return (f"t = {t:.6g} s: body {body!r} {what}; the run diverged.{culprit} Likely fix: "
            f"{divergence_fix(solver, step_advice)}.")


def penetration_message(scene, solver, t, k, q, v, step_advice=None) -> str:
    """Pair k penetrated beyond its guard: its depth [m], the guard [m], and a fix."""
    pair = scene.pairs[k]
    pairs = contact_pairs.pack(scene.pairs)
    depth = -float(twin.pair_geometry(pairs, q, v)[0][k])
    bound = penetration_bounds(pairs, solver.penetration_limit)[k]
    return (f"t = {t:.6g} s: pair {pair.name!r} penetrates {depth:.3g} m, beyond the guard of {bound:.3g} m "
            f"(penetration_limit = {solver.penetration_limit:g} of the radius). Likely fix: "
            f"{step_fix(solver, step_advice)} so the contact is resolved, or raise the stiffness "
            f"(K = {pair.law.stiffness:.3g}).")

