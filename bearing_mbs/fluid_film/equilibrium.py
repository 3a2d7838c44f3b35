"""The journal's static equilibrium: where a film's force balances a steady load on the journal.

Powell's hybrid method (scipy's ``root``) on the force balance in units of the clearance, started from the linear
film's answer and then from fixed guesses. Near the centre the film's force is linear in the eccentricity (a stretch
and a turn, to O(ε²)); at large Sommerfeld numbers (fast, viscous, tight) the equilibrium lies orders of magnitude
inside the fixed guesses, where Powell's method stalls on the force's rounding, and below
:data:`LINEAR_ECCENTRICITY` the linear answer is kept.
"""

from __future__ import annotations

import math

import numpy as np
from scipy.optimize import root

from bearing_mbs.fluid_film.reynolds import JournalState

#: Below this eccentricity ratio the film's force is linear in the eccentricity (to O(ε²)), and so is the
#: equilibrium: the linear estimate is kept, where a root finder would stall on the force's rounding.
LINEAR_ECCENTRICITY = 1e-6
#: The largest eccentricity ratio the film is asked for: a solver's trial step beyond it is answered by the balance at
#: this wall plus WALL_SLOPE (in the residual's units per unit ε) times the overshoot, back towards the centre.
WALL = 0.999
WALL_SLOPE = 1e3
#: Film solves per starting point (Powell's method converges in 10–30 where there is an equilibrium; without one it
#: would take scipy's default 600).
MAX_EVALUATIONS = 100
#: Starting points (eccentricity ratios) after the linear one.
GUESSES = ([0.1, -0.3], [0.3, -0.6], [0.1, -0.9])


def film_equilibrium(force, clearance: float, load, speed: float) -> np.ndarray | None:
    """The journal centre (x, y) [m] where ``force(state) -> (F_x, F_y)`` [N] balances the steady ``load``
    (F_x, F_y) [N] on the journal at speed Ω [rad/s]; None where no equilibrium inside the clearance is found."""
    load = np.asarray(load, dtype=float)
    scale = max(np.abs(load).max(), 1.0)

    def balance(x):
        return (force(JournalState(tuple(x * clearance), (0.0, 0.0), speed)) + load) / scale

    def residual(x):
        ratio = math.hypot(*x)
        if ratio < WALL:
            return balance(x)
        # a trial step through the wall: the balance at the wall, pushed further the deeper the step went
        inside = x * (WALL / ratio)
        return balance(inside) - WALL_SLOPE * (ratio - WALL) * inside / WALL

    if not np.any(load):
        return np.zeros(2)
    linear = _linear_guess(residual, -load / scale)
    if np.hypot(*linear) < LINEAR_ECCENTRICITY:  # the linear film's answer, exact to O(ε²), below what root resolves
        return linear * clearance
    for guess in (linear, *GUESSES):
        solution = root(residual, guess, method="hybr", options={"maxfev": MAX_EVALUATIONS})
        if solution.success and np.hypot(*solution.x) < WALL:
            return solution.x * clearance
    return None


def _linear_guess(residual, target: np.ndarray, probe: float = LINEAR_ECCENTRICITY) -> np.ndarray:
    """The eccentricity ratio (x, y)/C where the film's force, taken as linear in the eccentricity near the centre
    (a stretch and a turn: x + iy ↦ a (x + iy), as a film symmetric about the centre is to first order), reaches
    ``target`` (the load's opposite, in the residual's units): ``a`` from the force at an offset ``probe`` (its
    second-order terms turn the answer by about ``probe``)."""
    offset = complex(0.0, -probe)
    lift = residual(np.array([offset.real, offset.imag])) - residual(np.zeros(2))
    a = complex(*lift) / offset
    if not (abs(a) > 0 and math.isfinite(abs(a))):
        return np.array(GUESSES[0])
    guess = complex(*target) / a
    guess *= min(1.0, 0.5 / abs(guess))  # inside the clearance
    return np.array([guess.real, guess.imag])
