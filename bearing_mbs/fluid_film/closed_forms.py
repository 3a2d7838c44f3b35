r"""Closed forms of the plain (ungrooved, unrecessed) journal bearing: short (Ocvirk) and long (Sommerfeld).

Both use Gümbel's condition (negative pressures dropped). In the frame of the eccentricity, with
:math:`h = C(1 - \varepsilon\cos\alpha)`, α measured from the line of centres towards the rotation, the film force on
the journal has a component :math:`F_n` along the eccentricity (pushing the journal back) and :math:`F_t`
perpendicular to it, in the sense of rotation. For a steady journal (:math:`U = \Omega R`):

* short bearing, L/D → 0 (F. W. Ocvirk, NACA TN 2808, 1952; in the form of B. J. Hamrock, S. R. Schmid,
  B. O. Jacobson, *Fundamentals of Fluid Film Lubrication*, 2nd ed., 2004, ch. 10; document 001 quotes the load):

  .. math:: F_n = -\frac{\mu U L^3}{C^2}\,\frac{\varepsilon^2}{(1-\varepsilon^2)^2},\qquad
            F_t = \frac{\mu U L^3}{4C^2}\,\frac{\pi\varepsilon}{(1-\varepsilon^2)^{3/2}},\qquad
            \tan\varphi = \frac{\pi\sqrt{1-\varepsilon^2}}{4\varepsilon};

* long bearing, L/D → ∞ (A. Sommerfeld 1904, half-Sommerfeld; Hamrock et al. ch. 10):

  .. math:: F_n = -\frac{6\mu U R^2 L}{C^2}\,\frac{2\varepsilon^2}{(2+\varepsilon^2)(1-\varepsilon^2)},\qquad
            F_t = \frac{6\mu U R^2 L}{C^2}\,\frac{\pi\varepsilon}{(2+\varepsilon^2)(1-\varepsilon^2)^{1/2}},\qquad
            \tan\varphi = \frac{\pi\sqrt{1-\varepsilon^2}}{2\varepsilon}.

The dynamic short bearing (:func:`short_bearing_force`) keeps the squeeze terms: integrating Reynolds' equation
across the length gives

.. math:: p = \frac{3\mu}{C^2(1-\varepsilon\cos\alpha)^3}\left(\frac{L^2}{4} - z^2\right)
          \left[2\dot\varepsilon\cos\alpha - \varepsilon(\Omega - 2\dot\psi)\sin\alpha\right],

positive on a half-turn :math:`[\alpha_1, \alpha_1 + \pi]`, which a 48-point Gauss–Legendre rule integrates
(ψ is the angle of the eccentricity vector). Petroff's torque of a centred journal is
:math:`T = 2\pi\mu\Omega R^3 L/C`.
"""

from __future__ import annotations

import math

import numpy as np

_NODES, _WEIGHTS = np.polynomial.legendre.leggauss(48)


def short_bearing_components(eccentricity_ratio: float, speed: float, radius: float, length: float,
                             clearance: float, viscosity: float) -> tuple[float, float]:
    """(F_n, F_t) [N] of a steady short bearing at eccentricity ratio ε and speed Ω [rad/s]."""
    eps, base = eccentricity_ratio, viscosity * speed * radius * length**3 / clearance**2
    return -base * eps**2 / (1 - eps**2) ** 2, base * math.pi * eps / (4 * (1 - eps**2) ** 1.5)


def long_bearing_components(eccentricity_ratio: float, speed: float, radius: float, length: float,
                            clearance: float, viscosity: float) -> tuple[float, float]:
    """(F_n, F_t) [N] of a steady long bearing (half-Sommerfeld) at ε and Ω [rad/s]."""
    eps = eccentricity_ratio
    base = 6 * viscosity * speed * radius**3 * length / clearance**2
    return (-base * 2 * eps**2 / ((2 + eps**2) * (1 - eps**2)),
            base * math.pi * eps / ((2 + eps**2) * math.sqrt(1 - eps**2)))


def attitude_angle(components: tuple[float, float]) -> float:
    """Angle [deg] from the load (−F) to the eccentricity, for (F_n, F_t)."""
    normal, tangential = components
    return math.degrees(math.atan2(tangential, -normal))


def petroff_torque(speed: float, radius: float, length: float, clearance: float, viscosity: float) -> float:
    """T = 2π μ Ω R³ L / C [N m] of a centred journal."""
    return 2 * math.pi * viscosity * speed * radius**3 * length / clearance


def sommerfeld_number(load: float, speed: float, radius: float, length: float, clearance: float,
                      viscosity: float) -> float:
    """S = (R/C)² μ N / P with N [rev/s] and P = W/(L D) (Raimondi and Boyd's definition)."""
    return (radius / clearance) ** 2 * viscosity * (speed / (2 * math.pi)) / (load / (2 * radius * length))


def short_bearing_force(eccentricity, eccentricity_rate, speed: float, radius: float, length: float,
                        clearance: float, viscosity: float) -> np.ndarray:
    """Film force (F_x, F_y) [N] on a journal at (e_x, e_y) [m] moving at (ė_x, ė_y) [m/s], turning at Ω [rad/s]."""
    e_x, e_y = eccentricity
    v_x, v_y = eccentricity_rate
    e = math.hypot(e_x, e_y)
    if e == 0.0:
        direction = np.array([v_x, v_y]) / max(math.hypot(v_x, v_y), 1e-300)
        e_x, e_y = 1e-12 * clearance * direction if math.hypot(v_x, v_y) else (1e-12 * clearance, 0.0)
        e = math.hypot(e_x, e_y)
    n = np.array([e_x, e_y]) / e
    t = np.array([-n[1], n[0]])
    eps = e / clearance
    eps_rate = (v_x * n[0] + v_y * n[1]) / clearance
    psi_rate = (v_y * n[0] - v_x * n[1]) / e
    # the bracket A cos α − B sin α = M cos(α + β) is positive on (−π/2 − β, π/2 − β)
    a_coef, b_coef = 2 * eps_rate, eps * (speed - 2 * psi_rate)
    beta = math.atan2(b_coef, a_coef)
    alpha = -beta + _NODES * math.pi / 2
    bracket = a_coef * np.cos(alpha) - b_coef * np.sin(alpha)
    profile = np.maximum(bracket, 0.0) / (1 - eps * np.cos(alpha)) ** 3
    scale = viscosity * radius * length**3 / (2 * clearance**2) * (math.pi / 2)
    f_n = -scale * np.dot(_WEIGHTS, profile * np.cos(alpha))
    f_t = -scale * np.dot(_WEIGHTS, profile * np.sin(alpha))
    return f_n * n + f_t * t
