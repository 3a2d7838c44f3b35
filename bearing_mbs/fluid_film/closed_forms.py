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
from numba.extending import register_jitable

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


@register_jitable
def short_bearing_force(e_x, e_y, v_x, v_y, speed, radius, length, clearance, viscosity):
    """Film force (F_x, F_y) [N] on a journal at (e_x, e_y) [m] moving at (v_x, v_y) [m/s], turning at Ω [rad/s]
    (a tuple; numba-compilable, so the force element and this library share it)."""
    e = math.sqrt(e_x * e_x + e_y * e_y)
    floor = 1e-12 * clearance
    if e < floor:  # centred: the direction of the line of centres is arbitrary, the force vanishes with e
        e_x, e_y, e = floor, 0.0, floor
    n_x, n_y = e_x / e, e_y / e
    eps = e / clearance
    eps_rate = (v_x * n_x + v_y * n_y) / clearance
    psi_rate = (v_y * n_x - v_x * n_y) / e
    # the bracket A cos α − B sin α = M cos(α + β) is positive on (−π/2 − β, π/2 − β)
    a_coef, b_coef = 2.0 * eps_rate, eps * (speed - 2.0 * psi_rate)
    beta = math.atan2(b_coef, a_coef)
    f_n, f_t = 0.0, 0.0
    for k in range(_NODES.size):
        alpha = -beta + _NODES[k] * math.pi / 2
        bracket = a_coef * math.cos(alpha) - b_coef * math.sin(alpha)
        profile = _WEIGHTS[k] * max(bracket, 0.0) / (1.0 - eps * math.cos(alpha)) ** 3
        f_n += profile * math.cos(alpha)
        f_t += profile * math.sin(alpha)
    scale = -viscosity * radius * length**3 / (2.0 * clearance**2) * (math.pi / 2)
    f_n, f_t = scale * f_n, scale * f_t
    return f_n * n_x - f_t * n_y, f_n * n_y + f_t * n_x


@register_jitable
def short_bearing_torque(eccentricity_ratio, speed, radius, length, clearance, viscosity):
    r"""Viscous torque [N m] on the journal about its axis (opposing Ω): the Couette shear μΩR/h over the full
    film, :math:`-2\pi\mu\Omega R^3 L/(C\sqrt{1-\varepsilon^2})` (Petroff's at ε = 0)."""
    return -2.0 * math.pi * viscosity * speed * radius**3 * length / (clearance * math.sqrt(1.0 - eccentricity_ratio**2))


@register_jitable
def journal_motion_slopes(e_x, e_y, v_x, v_y, speed, clearance):
    """The journal's line of centres n, ε, and the squeeze and swirl terms ε̇ and ε(Ω − 2ψ̇) of the film forces,
    with their derivatives over (e_x, e_y, v_x, v_y, Ω): (n_x, n_y, ε, ε̇, ε(Ω − 2ψ̇), ∂n_x, ∂n_y, ∂ε, ∂ε̇,
    ∂[ε(Ω − 2ψ̇)]); e > 0."""
    e = math.sqrt(e_x * e_x + e_y * e_y)
    n_x, n_y = e_x / e, e_y / e
    eps = e / clearance
    eps_rate = (v_x * n_x + v_y * n_y) / clearance
    psi_rate = (v_y * n_x - v_x * n_y) / e
    nx_d = np.array([n_y * n_y / e, -n_x * n_y / e, 0.0, 0.0, 0.0])
    ny_d = np.array([-n_x * n_y / e, n_x * n_x / e, 0.0, 0.0, 0.0])
    eps_d = np.array([n_x / clearance, n_y / clearance, 0.0, 0.0, 0.0])
    eps_rate_d = (v_x * nx_d + v_y * ny_d) / clearance
    eps_rate_d[2], eps_rate_d[3] = n_x / clearance, n_y / clearance
    psi_rate_d = (v_y * nx_d - v_x * ny_d) / e - psi_rate * np.array([n_x, n_y, 0.0, 0.0, 0.0]) / e
    psi_rate_d[2], psi_rate_d[3] = -n_y / e, n_x / e
    swirl = eps * (speed - 2.0 * psi_rate)
    swirl_d = eps_d * (speed - 2.0 * psi_rate) - 2.0 * eps * psi_rate_d
    swirl_d[4] += eps
    return n_x, n_y, eps, eps_rate, swirl, nx_d, ny_d, eps_d, eps_rate_d, swirl_d


@register_jitable
def short_bearing_force_jacobian(e_x, e_y, v_x, v_y, speed, radius, length, clearance, viscosity):
    """∂(F_x, F_y)/∂(e_x, e_y, v_x, v_y, Ω) of :func:`short_bearing_force` (a 2 × 5 array), differentiating its
    quadrature term by term: the bracket's coefficients a = 2ε̇ and b = ε(Ω − 2ψ̇), the denominator's ε and the
    nodes, which move with the positive half-turn's start −β = −atan2(b, a)."""
    jacobian = np.zeros((2, 5))
    if math.sqrt(e_x * e_x + e_y * e_y) < 1e-12 * clearance:
        return jacobian
    n_x, n_y, eps, eps_rate, b_coef, nx_d, ny_d, eps_d, eps_rate_d, b_d = journal_motion_slopes(
        e_x, e_y, v_x, v_y, speed, clearance)
    a_coef, a_d = 2.0 * eps_rate, 2.0 * eps_rate_d
    magnitude2 = a_coef * a_coef + b_coef * b_coef
    beta = math.atan2(b_coef, a_coef)
    beta_d = (a_coef * b_d - b_coef * a_d) / magnitude2 if magnitude2 > 0.0 else np.zeros(5)
    f_n = f_t = 0.0
    f_n_d, f_t_d = np.zeros(5), np.zeros(5)
    for k in range(_NODES.size):
        alpha = -beta + _NODES[k] * math.pi / 2
        cos_a, sin_a = math.cos(alpha), math.sin(alpha)
        bracket = a_coef * cos_a - b_coef * sin_a
        if bracket <= 0.0:
            continue
        denominator = 1.0 - eps * cos_a
        profile = _WEIGHTS[k] * bracket / denominator**3
        # over the bracket, the denominator and the node's angle (which moves as −β)
        by_alpha = _WEIGHTS[k] * ((-a_coef * sin_a - b_coef * cos_a) / denominator**3
                                  - 3.0 * bracket * eps * sin_a / denominator**4)
        by_eps = _WEIGHTS[k] * 3.0 * bracket * cos_a / denominator**4
        f_n += profile * cos_a
        f_t += profile * sin_a
        for i in range(5):  # component by component: array expressions here allocated per node
            profile_d = (_WEIGHTS[k] * (cos_a * a_d[i] - sin_a * b_d[i]) / denominator**3 + by_eps * eps_d[i]
                         - by_alpha * beta_d[i])
            f_n_d[i] += profile_d * cos_a + profile * sin_a * beta_d[i]  # d cos α = −sin α dα, dα = −dβ
            f_t_d[i] += profile_d * sin_a - profile * cos_a * beta_d[i]
    scale = -viscosity * radius * length**3 / (2.0 * clearance**2) * (math.pi / 2)
    f_n, f_t, f_n_d, f_t_d = scale * f_n, scale * f_t, scale * f_n_d, scale * f_t_d
    jacobian[0] = f_n_d * n_x + f_n * nx_d - f_t_d * n_y - f_t * ny_d
    jacobian[1] = f_n_d * n_y + f_n * ny_d + f_t_d * n_x + f_t * nx_d
    return jacobian
