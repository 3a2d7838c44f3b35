"""Engine-neutral diagnosis of runs: the output instants, and a failure's message from its kind
(:class:`~bearing_mbs.core.failures.Failure`) and the state where the run stopped.

A message names the time, the body or pair at fault, and a likely fix that names a value and fits what the run
already uses (a quarter of its step; the implicit solver only for a run that is not already implicit).
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


def failure_message(failure: Failure, scene, solver, t: float, culprit: int, q, v, latched, h: float) -> str:
    """The message of a run that stopped at t [s] with ``failure``, from the last good state (q, v, latched).

    ``culprit``: the offending coordinate (non-finite state, blow-up) or pair (penetration); ``h`` [s]: the
    step when it stopped (the adaptive step on an underflow). The fixes quote the active engine's settings.
    """
    settings = solver.active
    if failure == Failure.NONE:
        return ""
    if failure == Failure.INTERRUPTED:
        return interrupted_message(t)
    if failure.diverged:
        return diverged_message(scene, solver, t, culprit, q, v, latched, blown_up=failure == Failure.BLOWUP)
    if failure == Failure.PENETRATION:
        return penetration_message(scene, solver, t, culprit, q, v)
    if failure == Failure.STEP_UNDERFLOW:
        what = ("Newton's method kept failing and generalized-alpha's step" if getattr(settings, "implicit", False)
                else "the adaptive step")
        return (f"t = {t:.6g} s: {what} fell to {h:.3g} s. Likely fix: loosen the tolerance "
                f"(now {settings.tolerance:g}) or raise the friction regularisation speed.")
    if failure == Failure.PROJECTION_FAILED:
        return f"t = {t:.6g} s: the constraint projection did not converge. Likely fix: {smaller_step(solver)}."
    return f"t = {t:.6g} s: the solver stopped (step {h:.3g} s). Likely fix: {smaller_step(solver)}."


def smaller_step(solver) -> str:
    """The usual remedy, naming the value: a quarter of the step (or a hundredth of the tolerance) the run used."""
    settings = solver.active
    if settings.adaptive:
        return f"tighten the tolerance from {settings.tolerance:g} to {settings.tolerance / 100:g}"
    return f"reduce the step from {settings.step:g} s to {settings.step / 4:g} s"


def divergence_fix(solver) -> str:
    """What to change after a divergence, given what the run already uses: an explicit method may switch to the
    implicit solver; an implicit one that diverges needs a smaller step, or the case is beyond the model."""
    if getattr(solver.active, "implicit", False):
        return (f"{smaller_step(solver)}; if it still diverges, the load or speed is beyond what the contacts "
                f"can carry: check [load] and [drive]")
    switch = "" if solver.engine == "exudyn" and solver.active.method == "generalized_alpha" else \
        ", or switch to Exudyn's generalized_alpha (implicit: no stability limit)"
    return f"{smaller_step(solver)} (`bearing-mbs advise` gives the stability limit){switch}"


def interrupted_message(t: float) -> str:
    return f"t = {t:.6g} s: interrupted on request (SIGINT or SIGTERM); the output up to this instant is kept."


def diverged_message(scene, solver, t, coordinate, q, v, latched, blown_up) -> str:
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
    return f"t = {t:.6g} s: body {body!r} {what}; the run diverged.{culprit} Likely fix: {divergence_fix(solver)}."


def penetration_message(scene, solver, t, k, q, v) -> str:
    """Pair k penetrated beyond its guard: its depth [m], the guard [m], and a fix."""
    pair = scene.pairs[k]
    pairs = contact_pairs.pack(scene.pairs)
    depth = -float(twin.pair_geometry(pairs, q, v)[0][k])
    bound = penetration_bounds(pairs, solver.penetration_limit)[k]
    return (f"t = {t:.6g} s: pair {pair.name!r} penetrates {depth:.3g} m, beyond the guard of {bound:.3g} m "
            f"(penetration_limit = {solver.penetration_limit:g} of the radius). Likely fix: {smaller_step(solver)} "
            f"so the contact is resolved, or raise the stiffness (K = {pair.law.stiffness:.3g}).")

