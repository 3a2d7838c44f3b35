r"""The drive of the inner ring: its set speed (one definition, :func:`speed_schedule_rpm`) and the primary
document's two-shaft gear train (eqs. 40–44), with the sign of α1 derived.

Set speed
---------
``[drive]`` gives the inner ring's set speed in rpm as breakpoints, linear in between and constant outside
(:func:`speed_schedule_rpm`). Everything else reads it from there: the servo's target (:func:`speed_profile`), the
initial speed (:func:`initial_speed`), the steady speed the quasi-static solver uses (:func:`steady_speed`) and the
highest speed, the lubricant's reference (:func:`highest_speed_rpm`). With a gear train the schedule is the
initial speed alone (the train sets the speed after that).

Gear train
----------

Shaft 1 (the fast shaft: the bearing's inner ring, pinion radius :math:`r_1`, inertia :math:`I_1`) meshes with
shaft 2 (gear radius :math:`r_2`, inertia :math:`I_2`). The generator resists on shaft 1 with
:math:`T_{R1} = T_{1RA} + T_{1RB} t`; the rotor drives shaft 2 with :math:`T_{M2} = T_{2MA} + T_{2MB} t` (reduced
to shaft 2). With the mesh's tangential force :math:`F_T` and a rigid mesh :math:`\alpha_1 r_1 = \alpha_2 r_2`
(eq. 42), the shafts obey (eq. 41)

.. math:: I_1\alpha_1 = F_T r_1 - T_{R1}, \qquad I_2\alpha_2 = T_{M2} - F_T r_2,

hence (eq. 43) :math:`F_T = (r_1 T_{R1}/I_1 + r_2 T_{M2}/I_2)/(r_1^2/I_1 + r_2^2/I_2)` and

.. math:: \alpha_1 = r_2\,\frac{r_1 T_{M2} - r_2 T_{R1}}{I_1 r_2^2 + I_2 r_1^2}.

**Erratum:** the document's eq. 44 prints :math:`r_2 (T_{R1} r_2 - T_{M2} r_1)/(I_1 r_2^2 + I_2 r_1^2)`, the
opposite sign; with its own eqs. 41–42 a rotor torque larger than the generator's (reduced) must accelerate
shaft 1, as the expression above does. Convention: shaft 1 turns counter-clockwise (positive θ).

The radial mesh force is :math:`F_R = F_T \tan\varphi` (eq. 40). On the pinion the gear pushes along the
rotation at the mesh point (tangential, :math:`F_T\,e^\perp`) and away from the gear (:math:`-F_R\,e`), with
:math:`e` the unit vector from the pinion centre to the gear centre; the bearing carries ``PORC`` % of it.

In the dynamic model the train is reduced to the inner ring: its rotation gets the inertia
:math:`I_1 + I_2 (r_1/r_2)^2` (plus the ring's own) and the torque :math:`T_{M2} r_1/r_2 - T_{R1}`, which
reproduces :math:`\alpha_1` above, while the mesh force acts as a load from eq. 43 (it neglects the bearing's
own friction torque, three orders of magnitude below the drive torques).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from bearing_mbs.core.scene import Profile
from bearing_mbs.models.cylindrical_roller.spec import DriveSpec, GearTrainSpec

#: One revolution per minute [rad/s].
RPM = 2 * math.pi / 60


def speed_schedule_rpm(drive: DriveSpec) -> tuple[tuple[float, ...], tuple[float, ...]]:
    """The inner ring's set speed as breakpoints: (times [s], speeds [rpm]).

    ``constant`` (and a gear train): one point, ``speed_rpm``; ``ramp``: ``from_rpm`` until ``start``, then
    linear to ``speed_rpm`` at ``start + duration``; ``table``: its entries.
    """
    if drive.kind == "gear_train" or drive.profile == "constant":
        return (0.0,), (drive.speed_rpm,)
    if drive.profile == "ramp":
        return (0.0, drive.start, drive.start + drive.duration), (drive.from_rpm, drive.from_rpm, drive.speed_rpm)
    return tuple(drive.times), tuple(drive.speeds_rpm)


def speed_profile(drive: DriveSpec) -> Profile:
    """The servo's target speed [rad/s] against time [s]."""
    times, speeds = speed_schedule_rpm(drive)
    return Profile(times, tuple(s * RPM for s in speeds))


def initial_speed(drive: DriveSpec) -> float:
    """The inner ring's speed at t = 0 [rad/s] (a ramp starts from ``from_rpm``, even one of no duration)."""
    times, speeds = speed_schedule_rpm(drive)
    if drive.kind == "speed" and drive.profile == "table":
        return float(np.interp(0.0, times, speeds)) * RPM
    return speeds[0] * RPM


def steady_speed(drive: DriveSpec) -> float:
    """The speed the drive settles at [rad/s]: the last breakpoint (the end of a ramp, a table's last entry)."""
    return speed_schedule_rpm(drive)[1][-1] * RPM


def highest_speed_rpm(drive: DriveSpec) -> float:
    """The drive's highest |speed| [rpm]: the operating speed of a ramp or table (start-up, stop)."""
    return max(abs(s) for s in speed_schedule_rpm(drive)[1])


@dataclass(frozen=True)
class GearTrain:
    """Torques and forces of the train as functions of time [SI]."""

    spec: GearTrainSpec

    def generator_torque(self, t):
        """T_R1(t) [N m], resisting on shaft 1."""
        return self.spec.generator_torque + self.spec.generator_torque_rate * t

    def rotor_torque(self, t):
        """T_M2(t) [N m], driving shaft 2."""
        return self.spec.rotor_torque + self.spec.rotor_torque_rate * t

    def tangential_force(self, t):
        """F_T [N], eq. 43."""
        r1, r2, i1, i2 = self._numbers()
        return (r1 / i1 * self.generator_torque(t) + r2 / i2 * self.rotor_torque(t)) / (r1**2 / i1 + r2**2 / i2)

    def radial_force(self, t):
        """F_R = F_T tan φ [N], eq. 40."""
        return self.tangential_force(t) * math.tan(math.radians(self.spec.pressure_angle))

    def pinion_acceleration(self, t):
        """α1 [rad/s²], eq. 44 with the sign derived from eqs. 41–42."""
        r1, r2, i1, i2 = self._numbers()
        return r2 * (r1 * self.rotor_torque(t) - r2 * self.generator_torque(t)) / (i1 * r2**2 + i2 * r1**2)

    @property
    def reduced_inertia(self) -> float:
        """I1 + I2 (r1/r2)² [kg m²]: the train's inertia seen by shaft 1."""
        r1, r2, i1, i2 = self._numbers()
        return i1 + i2 * (r1 / r2) ** 2

    def drive_torque(self, t):
        """T_M2 r1/r2 − T_R1 [N m]: the net torque on shaft 1 of the reduced train."""
        r1, r2, _, _ = self._numbers()
        return self.rotor_torque(t) * r1 / r2 - self.generator_torque(t)

    def bearing_load(self, t) -> tuple[float, float]:
        """The share PORC of the mesh force on the pinion, (Fx, Fy) [N], in the world frame."""
        angle = math.radians(self.spec.mesh_angle)
        ex, ey = math.cos(angle), math.sin(angle)
        share = self.spec.load_share / 100
        tangential, radial = self.tangential_force(t), self.radial_force(t)
        return share * (-tangential * ey - radial * ex), share * (tangential * ex - radial * ey)

    def _numbers(self):
        s = self.spec
        return s.pinion_radius, s.gear_radius, s.shaft1_inertia, s.shaft2_inertia
