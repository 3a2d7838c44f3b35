r"""Load-independent drag of the lubricant on the rolling set (one place for these formulas).

Palmgren's load-independent friction moment of a lubricated rolling bearing (A. Palmgren, Ball and Roller
Bearing Engineering, 3rd ed., 1959; as given in T. A. Harris, M. N. Kotzalas, Essential Concepts of Bearing
Technology, 5th ed., 2006, ch. 9):

.. math:: M_0 = 10^{-7} f_0\,(\nu n)^{2/3} d_m^3\ \mathrm{N\,mm}\quad (\nu n \ge 2000),\qquad
          M_0 = 160\cdot10^{-7} f_0\, d_m^3\ \mathrm{N\,mm}\quad (\nu n < 2000),

with ν the kinematic viscosity [mm²/s], n the speed [rpm], d_m the pitch diameter [mm] and f_0 a factor of
bearing type and lubrication (2–4 for cylindrical roller bearings with a cage, oil-lubricated; Harris &
Kotzalas give the table).

:math:`M_0` is the torque needed at the rotating ring: the bearing dissipates :math:`M_0\,\omega_i`. We apply it
as a viscous drag on each roller's centre, :math:`F = -c\,v`, with c chosen so that the Z rollers orbiting at
the epicyclic cage speed :math:`\omega_c` of the reference inner-ring speed :math:`\omega_i` dissipate that
power: :math:`Z c (R_{pw}\omega_c)^2 = M_0\,\omega_i`, so :math:`c = M_0\,\omega_i / (Z\,R_{pw}^2\,\omega_c^2)`.
(Matching the drag's moment about the axis, :math:`Z c R_{pw}^2\omega_c = M_0`, would give
:math:`\omega_c/\omega_i \approx 0.45` of that power; the model did so until the lubricated-skidding work.)
Linear drag gives a moment proportional to speed where Palmgren's grows as :math:`n^{2/3}`: exact at the
reference speed, an approximation elsewhere.
This load-independent resistance is what makes a lightly loaded bearing skid: the traction that drives the
rolling set falls with the load, the drag does not.
"""

from __future__ import annotations


def palmgren_drag_moment(drag_factor: float, viscosity: float, speed_rpm: float, pitch_diameter: float) -> float:
    """M_0 [N m] for f_0, kinematic viscosity [m²/s], speed [rpm] and pitch diameter [m]."""
    nu_mm2_s, d_m_mm = viscosity * 1e6, pitch_diameter * 1e3
    product = nu_mm2_s * abs(speed_rpm)
    if product >= 2000:
        moment_n_mm = 1e-7 * drag_factor * product ** (2 / 3) * d_m_mm**3
    else:
        moment_n_mm = 160e-7 * drag_factor * d_m_mm**3
    return moment_n_mm * 1e-3


def roller_drag_coefficient(moment: float, inner_speed: float, rollers: int, pitch_diameter: float,
                            cage_speed: float) -> float:
    """c [N s/m] of the viscous drag on each roller centre that dissipates the power of the moment [N m] at the
    inner-ring speed [rad/s] when the rollers orbit at the cage speed [rad/s]."""
    radius = pitch_diameter / 2
    return moment * abs(inner_speed) / (rollers * radius**2 * cage_speed**2)
