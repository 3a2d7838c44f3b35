r"""The rotor linearised about its static equilibrium: whirl threshold, eigenvalues, unbalance response.

Small motions x about the equilibrium at speed Ω obey :math:`M\ddot x + C\dot x + K x = f`, with M = m I and K, C the
bearings' eight coefficients there (:func:`~bearing_mbs.fluid_film.coefficients.dynamic_coefficients` of the run's
film force, all bearings together).

* The whirl threshold is the lowest speed at which an eigenvalue of the free system crosses into the right half plane.
* The unbalance m_u r_u turning at Ω pushes with :math:`m_u r_u\Omega^2(\cos\Omega t, \sin\Omega t)`: the steady
  orbit is :math:`\mathrm{Re}(X e^{i\Omega t})`, :math:`X = (K - \Omega^2 M + i\Omega C)^{-1} m_u r_u \Omega^2
  (1, -i)`, an ellipse whose semi-major axis is the orbit's amplitude.
* Critical speeds are the speeds at which that amplitude peaks (API 684: the rotor-bearing system in resonance); a
  rotor whose films damp its modes beyond resonance (an overdamped rotor on hybrid bearings) has none.
"""

from __future__ import annotations

import math

import numpy as np
from scipy.optimize import brentq

from bearing_mbs.fluid_film.coefficients import dynamic_coefficients
from bearing_mbs.fluid_film.reynolds import JournalState
from bearing_mbs.models.rotor.build import equilibrium, film_force
from bearing_mbs.models.rotor.spec import RotorSpec
from bearing_mbs.spec import SpecError


def coefficients(spec: RotorSpec, speed: float) -> tuple[np.ndarray, np.ndarray]:
    """(K [N/m], C [N s/m]) of all the bearings about the equilibrium at Ω [rad/s]."""
    state = JournalState(tuple(equilibrium(spec, speed)), (0.0, 0.0), speed)
    return dynamic_coefficients(film_force(spec), state, spec.bearing.radial_clearance)


def eigenvalues(spec: RotorSpec, speed: float) -> np.ndarray:
    """The four eigenvalues [1/s] of the free linearised rotor at Ω [rad/s]."""
    stiffness, damping = coefficients(spec, speed)
    mass = spec.rotor.mass
    system = np.block([[np.zeros((2, 2)), np.eye(2)], [-stiffness / mass, -damping / mass]])
    return np.linalg.eigvals(system)


def growth_rate(spec: RotorSpec, speed: float) -> float:
    """The largest real part [1/s] of the linearised rotor's eigenvalues about its equilibrium at Ω [rad/s]."""
    return float(eigenvalues(spec, speed).real.max())


def whirl_threshold(spec: RotorSpec, low_rpm: float = 100.0, high_rpm: float = 1e5) -> float | None:
    """The lowest speed [rpm] in [low, high] at which the linearised rotor becomes unstable (None if never); speeds
    too low for the films to carry the rotor are skipped."""
    speeds = np.geomspace(low_rpm, high_rpm, 40) * math.pi / 30
    rates = []
    for speed in speeds:
        try:
            rates.append(growth_rate(spec, speed))
        except SpecError:
            rates.append(math.nan)
    for k in range(1, len(speeds)):
        if rates[k - 1] < 0 <= rates[k]:
            return brentq(lambda s: growth_rate(spec, s), speeds[k - 1], speeds[k], xtol=1e-6) * 30 / math.pi
    return None


def unbalance_amplitude(spec: RotorSpec, speed: float) -> float:
    """The semi-major axis [m] of the steady linear unbalance orbit at Ω [rad/s]."""
    stiffness, damping = coefficients(spec, speed)
    dynamic = stiffness - speed**2 * spec.rotor.mass * np.eye(2) + 1j * speed * damping
    response = np.linalg.solve(dynamic, spec.rotor.unbalance * speed**2 * np.array([1.0, -1j]))
    return float(np.linalg.svd(np.column_stack([response.real, -response.imag]), compute_uv=False)[0])


def critical_speeds(speeds_rpm: np.ndarray, amplitudes: np.ndarray) -> list[float]:
    """The speeds [rpm] of the interior peaks of the unbalance response ``amplitudes`` over ``speeds_rpm``."""
    peaks = np.flatnonzero((amplitudes[1:-1] > amplitudes[:-2]) & (amplitudes[1:-1] > amplitudes[2:])) + 1
    return [float(speeds_rpm[k]) for k in peaks]
