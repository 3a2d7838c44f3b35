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

**Churning** (model ``churning``): each roller moves through an oil–air mixture of oil volume fraction X, of
density :math:`\rho_e = X\rho_{oil} + (1-X)\rho_{air}` and viscosity :math:`\eta_e = X\eta_{oil}` (air's
neglected; so :math:`\nu_e \approx \nu_{oil}`, our choice). Its orbital motion meets form drag, in the form
used for rollers by T. A. Harris and M. N. Kotzalas (Advanced Concepts of Bearing Technology, 5th ed., 2007),
:math:`F = \tfrac12\rho_e C_D D_w L_w v^2` against the roller centre's velocity v, with the drag coefficient of a
circular cylinder in cross flow as fitted by F. M. White (Viscous Fluid Flow, 2nd ed., 1991),
:math:`C_D = 1 + 10\,Re^{-2/3}` for :math:`1 \le Re = vD_w/\nu_e \le 2\cdot10^5`, taken at the epicyclic
orbital speed. Its spin meets the laminar shear of a cylinder turning in an unbounded fluid (the flow
:math:`u_\theta = \omega R_w^2/r` outside it, whose wall stress is :math:`2\eta_e\omega`): torque
:math:`4\pi\eta_e R_w^2 L_w\,\omega`. The orbital drag grows with the square of the speed, Palmgren's
:math:`M_0` only as :math:`n^{2/3}`: this is what makes a faster bearing skid more. :math:`M_0` is then only a
cross-check of the total no-load torque (:func:`no_load_torque`).

The cage's Z bars, between the pockets, move through the same mixture at the cage circle's speed :math:`\omega R_c`:
each meets the form drag :math:`\tfrac12\rho_e C_D t L_w (\omega R_c)^2` on its frontal area (the cage's
radial thickness t times the pocket length), a torque :math:`-c_{\theta 2}|\omega|\omega` on the cage with
:math:`c_{\theta 2} = Z\,\tfrac12\rho_e C_D t L_w R_c^3` (:func:`cage_drag_coefficient`). :math:`C_D = 2`, a
bar of square section broadside to the flow (S. F. Hoerner, Fluid-Dynamic Drag, 1965, ch. 3), is our choice: the
bars' sections are longer than square and sit in the rollers' wakes, which both lower it, so it errs high.

The churning's form drag depends on the mixture's density, hardly on its viscosity (C_D falls 6 % from 40 to
80 °C). With ``viscous_drag_factor`` f_v each roller also gets the linear drag of Palmgren's :math:`M_0` at
:math:`f_0 = f_v` and the oil's viscosity (the form above): the viscous share of the load-independent loss, which
grows as :math:`\nu^{2/3}`.

**Starvation** (:func:`replenishment_factor`): the rolling elements over-roll the raceways faster than oil flows
back into their tracks, so the contacts' inlets are starved. SKF's kinematic replenishment/starvation reduction
factor (SKF, *General Catalogue* 6000 EN, 2005, "The new SKF model for calculating the frictional moment")

.. math:: \phi_{rs} = \exp\left[-K_{rs}\,\nu\,n\,(d + D)\sqrt{\frac{K_Z}{2(D - d)}}\right]

(ν [mm²/s], n [rpm], bore d and outside diameter D [mm]; K_rs = 3e-8 for oil jet and low-level oil bath, 6e-8 for
oil–air and grease; K_Z = 5.1 for cylindrical roller bearings with a cage) multiplies SKF's rolling frictional
moment; here it multiplies the films and the hydrodynamic rolling forces of the raceway contacts
(:mod:`bearing_mbs.contact.traction`), which the film thickness sets. It is smaller the more viscous the oil and the
faster the bearing: 0.41 / 0.74 / 0.88 at 40 / 60 / 80 °C for the seed bearing at 1500 rpm in ISO VG 320. The
seed bearing has no outer ring body: its outside diameter is taken as d_o + (d_i − d), an outer ring as thick as the
inner one.
"""

from __future__ import annotations

import math

#: Density of air [kg/m³] at 20 °C and 1 atm.
AIR_DENSITY = 1.2
#: Drag coefficient of a cage bar: a bluff bar of square section broadside to the flow (Hoerner 1965).
BAR_DRAG_COEFFICIENT = 2.0
#: SKF's geometry constant K_Z of a cylindrical roller bearing with a cage (starvation factor).
CYLINDRICAL_ROLLER_GEOMETRY_CONSTANT = 5.1


def replenishment_factor(constant: float, viscosity: float, speed_rpm: float, bore: float,
                         outside_diameter: float) -> float:
    """SKF's φ_rs in (0, 1] for K_rs, the kinematic viscosity [m²/s], the speed [rpm], the bore d and the outside
    diameter D [m] (module docstring)."""
    nu_mm2_s, d_mm, big_d_mm = viscosity * 1e6, bore * 1e3, outside_diameter * 1e3
    root = math.sqrt(CYLINDRICAL_ROLLER_GEOMETRY_CONSTANT / (2 * (big_d_mm - d_mm)))
    return math.exp(-constant * nu_mm2_s * abs(speed_rpm) * (d_mm + big_d_mm) * root)


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


def mixture_density(oil_fraction: float, oil_density: float) -> float:
    """ρ_e [kg/m³] of an oil–air mixture of oil volume fraction X in (0, 1] and oil density [kg/m³]."""
    return oil_fraction * oil_density + (1 - oil_fraction) * AIR_DENSITY


def cylinder_drag_coefficient(reynolds: float) -> float:
    """C_D of a circular cylinder in cross flow (White 1991; fitted for 1 <= Re <= 2e5, held at the
    ends outside)."""
    return 1 + 10 * min(max(reynolds, 1.0), 2e5) ** (-2 / 3)


def orbital_drag_coefficient(density: float, kinematic_viscosity: float, roller_diameter: float,
                             roller_length: float, orbital_speed: float) -> float:
    """c_2 [N s²/m²] of the form drag F = c_2 v² on a roller of diameter and length [m] moving at the orbital
    speed [m/s] through a mixture of density [kg/m³] and kinematic viscosity [m²/s]."""
    reynolds = orbital_speed * roller_diameter / kinematic_viscosity
    return 0.5 * density * cylinder_drag_coefficient(reynolds) * roller_diameter * roller_length


def spin_drag_coefficient(dynamic_viscosity: float, roller_radius: float, roller_length: float) -> float:
    """c_θ [N m s/rad] of the laminar torque 4π η R² L ω on a roller spinning in a fluid of dynamic viscosity
    [Pa s]."""
    return 4 * math.pi * dynamic_viscosity * roller_radius**2 * roller_length


def cage_drag_coefficient(density: float, bars: int, thickness: float, length: float, radius: float) -> float:
    """c_θ2 [N m s²/rad²] of the form drag −c_θ2 |ω| ω on a cage of Z bars, each of radial thickness and length
    [m], on the cage circle of radius [m], in a mixture of density [kg/m³]."""
    return bars * 0.5 * density * BAR_DRAG_COEFFICIENT * thickness * length * radius**3


def no_load_torque(rollers: int, pitch_diameter: float, roller_radius: float, inner_radius: float,
                   inner_speed: float, cage_speed: float, linear: float, quadratic: float, angular: float) -> float:
    """The torque [N m] at the inner ring that supplies the power the drags on Z rollers dissipate when the
    rolling set turns without slip: orbit at the cage speed [rad/s], spin at (ω_i − ω_c) r_i / R_w."""
    orbital = pitch_diameter / 2 * abs(cage_speed)
    spin = abs(inner_speed - cage_speed) * inner_radius / roller_radius
    power = rollers * ((linear + quadratic * orbital) * orbital**2 + angular * spin**2)
    return power / abs(inner_speed)
