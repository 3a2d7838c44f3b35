"""Sections of the ``bearing`` model: the planar caged cylindrical roller bearing.

``[bearing]`` geometry and materials (with presets), ``[cage]`` model, ``[drive]`` of the inner ring,
``[load]`` on it, and ``[analysis]`` settings. All SI: metres, kilograms, newtons, seconds; speeds in rpm
where the key says so.
"""

from __future__ import annotations

import logging
import math
from dataclasses import dataclass, field, replace

from bearing_mbs.contact.line_contact import STEEL_POISSON_RATIO, STEEL_YOUNGS_MODULUS
from bearing_mbs.contact.lubricant import PRESETS as LUBRICANTS
from bearing_mbs.contact.lubricant import Lubricant, LubricantError
from bearing_mbs.core.topology import Group
from bearing_mbs.spec import ContactSpec, Spec
from bearing_mbs.spec.fields import SpecError, finite, in_range, non_negative, one_of, positive, require
from bearing_mbs.spec.loading import to_mapping

log = logging.getLogger(__name__)

CAGE_MODELS = ("penalty", "constraint", "none")
CAGE_GUIDANCE = ("rollers", "inner_land", "outer_land")
SPEED_PROFILES = ("constant", "ramp", "table")
DRIVE_KINDS = ("speed", "gear_train")
LOAD_PROFILES = ("constant", "step", "ramp", "table")
#: Largest pitch-circle speed π D_pw n/60 [m/s] a scenario may ask for: n·d_m ≈ 3.8e6 mm rpm, beyond the fastest
#: rolling bearings (the seed bearing at 1500 rpm: 18 m/s; the stability suite's 10 000 rpm case: 123 m/s).
PITCH_SPEED_LIMIT = 200.0
#: Largest radial load, in multiples of the ISO 76 static load rating C0 (at C0 the contact stress of a roller
#: bearing is 4000 MPa; at 4 C0 about 8000 MPa, far into yield).
LOAD_LIMIT = 4.0
#: Largest mass the inner ring may carry [kg] (a wind-turbine HSS shaft puts tens of kg on this bearing, a main
#: shaft tens of tonnes).
SUPPORTED_MASS_LIMIT = 1e5
#: Largest diametral clearance: P_d <= CLEARANCE_LIMIT · D_w [-].
CLEARANCE_LIMIT = 5e-2
#: Largest preload: −P_d <= PRELOAD_LIMIT · D_w [-]; it keeps the per-contact approach below 1e-3 D_w, beyond the
#: range where Palmgren's fit and rigid-ring quasi-statics are meant to be used.
PRELOAD_LIMIT = 2e-3


@dataclass(frozen=True)
class MaterialSpec:
    """youngs_modulus [Pa] > 0, poisson_ratio in [0, 0.5), density [kg/m³] > 0."""

    youngs_modulus: float
    poisson_ratio: float
    density: float

    def __post_init__(self):
        positive("youngs_modulus", self.youngs_modulus)
        in_range("poisson_ratio", self.poisson_ratio, 0.0, 0.5, "-", high_open=True)
        positive("density", self.density)


#: Bearing steel (100Cr6: the elastic constants of Palmgren's fit; density as the primary document) and the
#: document's bronze cage.
STEEL = MaterialSpec(youngs_modulus=STEEL_YOUNGS_MODULUS, poisson_ratio=STEEL_POISSON_RATIO, density=7850.0)
BRONZE = MaterialSpec(youngs_modulus=110e9, poisson_ratio=0.34, density=8890.0)


@dataclass(frozen=True)
class BearingSpec:
    """``[bearing]``: geometry, materials and the supported mass.

    rollers: Z >= 3. roller_diameter D_w [m], roller_length L_w [m] (effective contact length).
    Raceways: either ``inner_race_diameter`` and ``outer_race_diameter`` [m], or ``pitch_diameter`` D_pw
    with ``diametral_clearance`` P_d [m] (negative = preload); then d_i = D_pw − D_w − P_d/2 and
    d_o = D_pw + D_w + P_d/2. cage_diameter D_c [m]: the circle of the pocket edges P and Q (document eq. 45),
    inside the rollers' span (D_pw − D_w, D_pw + D_w). pocket_clearance H [m] > 0: the tangential play of a
    roller in its pocket. cage_guidance: ``rollers`` (default), ``inner_land`` or ``outer_land``, with
    land_clearance [m] (diametral). cage_thickness, cage_width [m]: the cage ring's section, radial and axial (its
    mass, and the height of the oiled pocket walls).
    inner_ring_bore, ring_width [m]: the inner ring's section (mass). supported_mass [kg] >= 0: the share of
    the shaft's mass the inner ring carries. Materials: ring_material, roller_material, cage_material.
    """

    rollers: int
    roller_diameter: float
    roller_length: float
    cage_diameter: float
    pocket_clearance: float
    cage_thickness: float
    cage_width: float
    inner_ring_bore: float
    ring_width: float
    pitch_diameter: float | None = None
    diametral_clearance: float | None = None
    inner_race_diameter: float | None = None
    outer_race_diameter: float | None = None
    cage_guidance: str = "rollers"
    land_clearance: float | None = None
    supported_mass: float = 0.0
    ring_material: MaterialSpec = field(default_factory=lambda: STEEL)
    roller_material: MaterialSpec = field(default_factory=lambda: STEEL)
    cage_material: MaterialSpec = field(default_factory=lambda: BRONZE)
    preset: str = ""

    def __post_init__(self):
        require(self.rollers >= 3, "rollers", self.rollers, "must be >= 3")
        for name in ("roller_diameter", "roller_length", "cage_diameter", "pocket_clearance", "cage_thickness",
                     "cage_width", "inner_ring_bore", "ring_width"):
            positive(name, getattr(self, name))
        in_range("supported_mass", self.supported_mass, 0.0, SUPPORTED_MASS_LIMIT, "kg")
        by_pitch = (self.pitch_diameter, self.diametral_clearance)
        by_races = (self.inner_race_diameter, self.outer_race_diameter)
        if all(v is not None for v in by_pitch) == all(v is not None for v in by_races) or (
            any(v is not None for v in by_pitch) and any(v is not None for v in by_races)
        ):
            raise SpecError("pitch_diameter", self.pitch_diameter,
                            "give either pitch_diameter with diametral_clearance, or inner_race_diameter with "
                            "outer_race_diameter")
        for name in ("pitch_diameter", "inner_race_diameter", "outer_race_diameter"):
            if getattr(self, name) is not None:
                positive(name, getattr(self, name))
        if self.diametral_clearance is not None:
            finite("diametral_clearance", self.diametral_clearance)
        self._check_fit()
        one_of("cage_guidance", self.cage_guidance, CAGE_GUIDANCE)
        if self.cage_guidance != "rollers":
            require(self.land_clearance is not None, "land_clearance", None,
                    f"is required with cage_guidance = {self.cage_guidance}")
            in_range("land_clearance", self.land_clearance, 0.0, self.roller_diameter, "m", low_open=True,
                     high_open=True)
        inner = inner_race_diameter(self.pitch, self.roller_diameter, self.clearance)
        require(self.inner_ring_bore < inner, "inner_ring_bore", self.inner_ring_bore,
                f"< the inner raceway diameter {inner:.6g} m (the ring needs a wall)")

    @property
    def pitch(self) -> float:
        """D_pw [m]."""
        if self.pitch_diameter is not None:
            return self.pitch_diameter
        return 0.5 * (self.inner_race_diameter + self.outer_race_diameter)

    @property
    def clearance(self) -> float:
        """P_d [m], negative for preload."""
        if self.diametral_clearance is not None:
            return self.diametral_clearance
        return diametral_clearance(self.inner_race_diameter, self.outer_race_diameter, self.roller_diameter)

    def _check_fit(self):
        d_w, pitch, clearance = self.roller_diameter, self.pitch, self.clearance
        raceway_field = "diametral_clearance" if self.diametral_clearance is not None else "outer_race_diameter"
        raceway_value = self.diametral_clearance if self.diametral_clearance is not None else self.outer_race_diameter
        require(clearance <= CLEARANCE_LIMIT * d_w, raceway_field, raceway_value,
                f"raceways inconsistent with the roller: the diametral clearance {clearance:.4g} m must be "
                f"<= {100 * CLEARANCE_LIMIT:g} % of the roller diameter ({CLEARANCE_LIMIT * d_w:.4g} m)")
        require(clearance >= -PRELOAD_LIMIT * d_w, raceway_field, raceway_value,
                f"preload beyond a sane bound: the diametral interference {-clearance:.4g} m must be "
                f"<= {100 * PRELOAD_LIMIT:g} % of the roller diameter ({PRELOAD_LIMIT * d_w:.4g} m)")
        require(inner_race_diameter(pitch, d_w, clearance) > 0, raceway_field, raceway_value, "leaves no inner raceway")
        require_rollers_fit("rollers", self.rollers, self.rollers, pitch, d_w + 2 * self.pocket_clearance, "D_w + 2H")
        require(pitch - d_w < self.cage_diameter < pitch + d_w, "cage_diameter", self.cage_diameter,
                f"must lie inside the rollers' span ({pitch - d_w:.4g}, {pitch + d_w:.4g}) m")
        cosine = pocket_angle_cosine(pitch, self.cage_diameter, d_w, self.pocket_clearance)
        require(-1 < cosine < 1 and 2 * math.acos(cosine) < 2 * math.pi / self.rollers, "pocket_clearance",
                self.pocket_clearance, "puts the pocket edges of neighbouring rollers past each other")


def static_load_rating(bearing: BearingSpec) -> float:
    """ISO 76 basic static radial load rating of a radial roller bearing, C0 = 44 (1 − D_w/D_pw) Z L_w D_w [N]
    (contact angle 0, one row; lengths in mm in the standard's formula)."""
    d_w, length = 1e3 * bearing.roller_diameter, 1e3 * bearing.roller_length
    return 44.0 * (1.0 - bearing.roller_diameter / bearing.pitch) * bearing.rollers * length * d_w


def diametral_clearance(inner_race_diameter: float, outer_race_diameter: float, roller_diameter: float) -> float:
    """P_d = d_o − d_i − 2 D_w [m] (negative: preload), from the raceway and roller diameters [m]."""
    return outer_race_diameter - inner_race_diameter - 2 * roller_diameter


def inner_race_diameter(pitch_diameter: float, roller_diameter: float, clearance: float) -> float:
    """d_i = D_pw − D_w − P_d/2 [m]: the clearance split equally between the raceways."""
    return pitch_diameter - roller_diameter - clearance / 2


def outer_race_diameter(pitch_diameter: float, roller_diameter: float, clearance: float) -> float:
    """d_o = D_pw + D_w + P_d/2 [m]."""
    return pitch_diameter + roller_diameter + clearance / 2


def neighbour_chord(pitch_diameter: float, rollers: int) -> float:
    """D_pw sin(π/Z) [m]: the chord between neighbouring roller centres of Z rollers on the pitch circle D_pw [m]."""
    return pitch_diameter * math.sin(math.pi / rollers)


def require_rollers_fit(field: str, value, rollers: int, pitch_diameter: float, width: float, what: str) -> None:
    """Z bodies of tangential ``width`` [m] (``what``: its symbol) fit around the pitch circle D_pw [m] without
    overlapping: width < :func:`neighbour_chord`; else a :class:`SpecError` naming ``field`` and ``value``."""
    chord = neighbour_chord(pitch_diameter, rollers)
    require(width < chord, field, value,
            f"{rollers} rollers do not fit around the pitch circle: {what} = {width:.6g} m must be < the chord "
            f"between neighbours D_pw sin(π/Z) = {chord:.6g} m, or neighbours overlap")


def pocket_angle_cosine(pitch_diameter: float, cage_diameter: float, roller_diameter: float,
                        pocket_clearance: float) -> float:
    r"""cos γ of the pocket edges on the cage circle D_c [m] (document eq. 45, the denominator corrected to
    :math:`D_{pw} D_c/2`): a centred roller is exactly H [m] from each edge."""
    return ((pitch_diameter / 2) ** 2 + (cage_diameter / 2) ** 2 - (roller_diameter / 2 + pocket_clearance) ** 2) / (
        pitch_diameter * cage_diameter / 2)


@dataclass(frozen=True)
class CageSpec:
    """``[cage]``: model = ``penalty`` (a cage body with pocket contacts), ``constraint`` (each roller centre
    held on its pocket's radial line) or ``none`` (full complement, roller–roller contacts)."""

    model: str = "penalty"

    def __post_init__(self):
        one_of("model", self.model, CAGE_MODELS)


@dataclass(frozen=True)
class GearTrainSpec:
    """``[drive.gear_train]``: the document's two-shaft train (eqs. 40–44), inner ring on the fast shaft 1.

    pinion_radius r1, gear_radius r2 [m]; shaft1_inertia I1 (generator side, reduced to shaft 1) and
    shaft2_inertia I2 (rotor side, reduced to shaft 2) [kg m²]; generator torque T_R1 = T1RA + T1RB t
    resisting on shaft 1, rotor torque T_M2 = T2MA + T2MB t driving shaft 2 [N m, N m/s];
    pressure_angle φ [deg]; load_share PORC in [0, 100] %; mesh_angle [deg]: direction from the pinion
    centre to the gear centre.
    """

    pinion_radius: float
    gear_radius: float
    shaft1_inertia: float
    shaft2_inertia: float
    generator_torque: float
    generator_torque_rate: float
    rotor_torque: float
    rotor_torque_rate: float
    pressure_angle: float = 20.0
    load_share: float = 50.0
    mesh_angle: float = 0.0

    def __post_init__(self):
        for name in ("pinion_radius", "gear_radius", "shaft1_inertia", "shaft2_inertia"):
            positive(name, getattr(self, name))
        for name in ("generator_torque", "generator_torque_rate", "rotor_torque", "rotor_torque_rate",
                     "mesh_angle"):
            finite(name, getattr(self, name))
        in_range("pressure_angle", self.pressure_angle, 0.0, 45.0, "deg")
        in_range("load_share", self.load_share, 0.0, 100.0, "%")


@dataclass(frozen=True)
class DriveSpec:
    """``[drive]``: how the inner ring turns (the outer ring is fixed).

    kind = ``speed``: a velocity servo (torque gain (speed(t) − ω)) follows ``profile``: ``constant``
    (``speed_rpm``), ``ramp`` (``from_rpm`` to ``speed_rpm`` between ``start`` and ``start + duration`` [s]:
    start-up or stop) or ``table`` (``times`` [s], ``speeds_rpm``). servo_time_constant [s] > 0 sets the gain
    from the inner ring's inertia. kind = ``gear_train``: see :class:`GearTrainSpec`.
    initial_state: ``rolling`` (rollers and cage start at the epicyclic speeds of the initial inner-ring
    speed) or ``rest``.
    """

    kind: str = "speed"
    profile: str = "constant"
    speed_rpm: float = 1500.0
    from_rpm: float = 0.0
    start: float = 0.0
    duration: float = 0.0
    times: tuple[float, ...] = ()
    speeds_rpm: tuple[float, ...] = ()
    servo_time_constant: float = 1e-3
    initial_state: str = "rolling"
    gear_train: GearTrainSpec | None = None

    @property
    def top_rpm(self) -> float:
        """The largest |speed| [rpm] the section declares (the gear train's own acceleration aside)."""
        return max(abs(self.speed_rpm), abs(self.from_rpm), *(abs(v) for v in self.speeds_rpm))

    def __post_init__(self):
        one_of("kind", self.kind, DRIVE_KINDS)
        one_of("profile", self.profile, SPEED_PROFILES)
        one_of("initial_state", self.initial_state, ("rolling", "rest"))
        positive("servo_time_constant", self.servo_time_constant)
        for name in ("speed_rpm", "from_rpm", "start", "duration"):
            finite(name, getattr(self, name))
        non_negative("start", self.start)
        non_negative("duration", self.duration)
        if self.profile == "table":
            require(len(self.times) == len(self.speeds_rpm) > 0, "speeds_rpm", list(self.speeds_rpm),
                    "must have one value per entry of times")
            require(all(b >= a for a, b in zip(self.times, self.times[1:])), "times", list(self.times),
                    "must not decrease")
        if self.kind == "gear_train":
            require(self.gear_train is not None, "gear_train", None, "is required with kind = gear_train")


@dataclass(frozen=True)
class LoadSpec:
    """``[load]``: a radial force on the inner ring.

    radial [N] >= 0 at ``angle`` [deg] (direction of the force on the inner ring; −90 = downwards), scaled
    by ``profile``: ``constant``; ``step`` from ``radial`` to ``final`` [N] at ``start`` over ``duration``
    [s] (a smooth ramp; 0 is not allowed: a jump); ``ramp`` from 0 to ``radial`` over
    [start, start + duration]; ``table`` (``times`` [s], ``values`` [N]). ramp_time [s] >= 0: a ``constant`` or
    ``step`` load applied at t = 0 rises from 0 to ``radial`` over [0, ramp_time] along a half cosine (zero slope
    at both ends); 0 (the default) applies it at once, a step that rings through the whole run (before ``start``
    for ``step``).
    """

    radial: float = 0.0
    angle: float = -90.0
    profile: str = "constant"
    final: float = 0.0
    start: float = 0.0
    duration: float = 1e-3
    times: tuple[float, ...] = ()
    values: tuple[float, ...] = ()
    ramp_time: float = 0.0

    def __post_init__(self):
        non_negative("radial", self.radial)
        non_negative("ramp_time", self.ramp_time)
        if self.ramp_time > 0:
            require(self.profile in ("constant", "step"), "ramp_time", self.ramp_time,
                    f"applies to the constant and step profiles (profile = {self.profile!r}: 0)")
            if self.profile == "step":
                require(self.ramp_time <= self.start, "ramp_time", self.ramp_time,
                        f"<= start = {self.start:g} s (the ramp ends before the step)")
        finite("angle", self.angle)
        one_of("profile", self.profile, LOAD_PROFILES)
        non_negative("final", self.final)
        non_negative("start", self.start)
        if self.profile in ("step", "ramp"):
            positive("duration", self.duration)
        if self.profile == "table":
            require(len(self.times) == len(self.values) > 0, "values", list(self.values),
                    "must have one value per entry of times")


#: The lubricant's drag on the rolling set (:mod:`bearing_mbs.models.cylindrical_roller.lubrication`).
DRAG_MODELS = ("palmgren", "churning", "none")
#: How α depends on the temperature: held at the oil's value, or carried by Roelands' index
#: (:meth:`bearing_mbs.contact.lubricant.Lubricant.pressure_viscosity_at`).
PRESSURE_VISCOSITY_MODELS = ("constant", "roelands")


@dataclass(frozen=True)
class LubricantSpec:
    """``[lubricant]``: the oil, and the load-independent drag of the lubricant on the rollers
    (:mod:`bearing_mbs.models.cylindrical_roller.lubrication`).

    The oil: ``oil``, a preset of :data:`bearing_mbs.contact.lubricant.PRESETS` (ISO VG 220/320, mineral or PAO), or
    its own viscosity_40 and viscosity_100 [m²/s] (kinematic, at 40 and 100 °C; both, in [2e-6, 1e-2] and
    [2e-6, 1e-3], and viscosity_100 < viscosity_40), with density_15 [kg/m³] (default 870), thermal_expansion
    [1/K] of the density (default 6.4e-4),
    pressure_viscosity α [1/Pa] (default 2e-8) at pressure_viscosity_temperature [°C] (default 60) and
    thermal_conductivity [W/(m K)] (default 0.13) replacing the preset's. temperature [°C]: the operating oil
    temperature, inside the oil's viscosity fit (-10 to 120 °C, refused outside, not extrapolated); lubricated
    traction (``friction_law = "ehl"``) needs it. pressure_viscosity_model: ``constant`` (default: α as given, at
    every temperature) or ``roelands`` (α carried to ``temperature`` at Roelands' constant index).

    starvation (default false): the raceway contacts' inlets are starved by the rolling set's kinematics, a
    replenishment factor φ_rs on their films and hydrodynamic rolling forces
    (:func:`~bearing_mbs.models.cylindrical_roller.lubrication.replenishment_factor`, SKF's), at the oil's viscosity
    and ``reference_rpm``; replenishment_constant K_rs in [1e-8, 1e-7] (default 3e-8, SKF's for oil jet and
    low-level oil bath; 6e-8 for oil–air and grease).

    The drag: model ``palmgren`` (default), ``churning`` or ``none``.

    * ``palmgren``: a linear drag on each roller centre that dissipates Palmgren's M_0. viscosity [m²/s] > 0: the
      kinematic viscosity in Palmgren's formula (default: the oil's at ``temperature``, else 32e-6, an ISO VG 320
      gearbox oil near 80 °C). drag_factor: Palmgren's f_0 in [0.5, 10] (default 2, a cylindrical roller bearing
      with cage, oil-lubricated; larger for an oil bath or more oil). reference_rpm: the speed at which the drag
      equals Palmgren's M_0 (default: the drive's highest speed). drag_moment [N m] >= 0: M_0 itself, replacing
      the formula.
    * ``churning``: each roller's orbital form drag (∝ v²) and spin drag, and the cage bars' form drag (∝ ω²), in
      the oil–air mixture; needs the oil and its temperature. oil_fraction in (0, 1]: the oil's volume fraction
      in the bearing cavity (default 0.05, our choice: no measurement of the seed bearing's cavity is at hand, so
      sweep it). reference_rpm: the speed at which the drag coefficient's Reynolds number is taken (default: the
      drive's highest speed). viscous_drag_factor f_v in [0, 10] (default 0: none): adds to each roller the linear
      drag of Palmgren's M_0 at f_0 = f_v with the oil's viscosity (the viscous share of the churning, which the
      form drag of the mixture lacks; the factor is calibrated as docs/skidding.md states).

    land_film (default false): the cage rides on an oil film on the outer ring's land, a short journal bearing
    (:mod:`bearing_mbs.fluid_film`) of the land clearance, as wide as the cage's side rings together
    (cage_width − roller_length), in the oil at ``temperature``; it carries the cage and shears at the cage's speed.
    The dry land contact stays, for metal contact should the film collapse.

    pocket_film (default false): the rollers of the penalty and the constraint cage run against the oil film of each
    flat pocket wall (a cage model ``none`` has no pockets; the constraint cage holds each roller centred in its
    pocket, where the films shear its spin in the cage),
    at the pocket clearance from the centred roller like the edges, over the roller's length
    (:mod:`bearing_mbs.fluid_film.cylinder_plane`: wedge, squeeze and shear of a cylinder on a plane, fully
    flooded), in the oil at ``temperature``; it cushions a roller striking a bar. Below three times the pocket's
    roughness (``contact.pocket.roughness``, Λ = 3) the film is taken at that floor; the dry edge contacts stay.
    """

    model: str = "palmgren"
    viscosity: float | None = None
    drag_factor: float = 2.0
    reference_rpm: float | None = None
    drag_moment: float | None = None
    oil: str | None = None
    viscosity_40: float | None = None
    viscosity_100: float | None = None
    density_15: float | None = None
    thermal_expansion: float | None = None
    pressure_viscosity: float | None = None
    thermal_conductivity: float | None = None
    temperature: float | None = None
    oil_fraction: float = 0.05
    land_film: bool = False
    pocket_film: bool = False
    pressure_viscosity_temperature: float | None = None
    pressure_viscosity_model: str = "constant"
    starvation: bool = False
    replenishment_constant: float = 3e-8
    viscous_drag_factor: float = 0.0

    def __post_init__(self):
        one_of("model", self.model, DRAG_MODELS)
        in_range("oil_fraction", self.oil_fraction, 0.0, 1.0, "-", low_open=True)
        if self.viscosity is not None:
            positive("viscosity", self.viscosity)
        in_range("drag_factor", self.drag_factor, 0.5, 10.0, "-")
        if self.reference_rpm is not None:
            positive("reference_rpm", self.reference_rpm)
        if self.drag_moment is not None:
            non_negative("drag_moment", self.drag_moment)
        if self.oil is not None:
            one_of("oil", self.oil, tuple(LUBRICANTS))
        own = (self.viscosity_40, self.viscosity_100)
        if self.oil is None and any(v is not None for v in own):
            require(all(v is not None for v in own), "viscosity_100" if self.viscosity_100 is None else "viscosity_40",
                    None, "an oil of its own needs both viscosity_40 and viscosity_100")
        if self.temperature is not None:
            finite("temperature", self.temperature)
            require(self.oil is not None or self.viscosity_40 is not None, "oil", None,
                    "a temperature needs an oil: a preset (" + ", ".join(LUBRICANTS) + ") or viscosity_40 and "
                    "viscosity_100")
        if self.oil is not None or self.viscosity_40 is not None:
            oil = self.lubricant()
            if self.temperature is not None:
                low, high = oil.temperature_range
                in_range("temperature", self.temperature, low, high, "°C")
        if self.model == "churning":
            require(self.temperature is not None, "temperature", None, "the churning drag needs the oil and its "
                    "operating temperature [°C] (its density and viscosity)")
        one_of("pressure_viscosity_model", self.pressure_viscosity_model, PRESSURE_VISCOSITY_MODELS)
        for name in ("starvation", "land_film", "pocket_film"):
            require(isinstance(getattr(self, name), bool), name, getattr(self, name), "must be true or false")
        in_range("replenishment_constant", self.replenishment_constant, 1e-8, 1e-7, "-")
        in_range("viscous_drag_factor", self.viscous_drag_factor, 0.0, 10.0, "-")
        if self.starvation or self.viscous_drag_factor > 0:
            field_name = "starvation" if self.starvation else "viscous_drag_factor"
            require(self.temperature is not None, field_name, getattr(self, field_name),
                    "needs the oil and its operating temperature [°C] (its viscosity)")
        if self.viscous_drag_factor > 0:
            require(self.model == "churning", "viscous_drag_factor", self.viscous_drag_factor,
                    f"adds to the churning drag: needs model = 'churning', not {self.model!r}")

    def lubricant(self) -> Lubricant | None:
        """The oil (a preset with this table's values over it), or None if the table names none; the build carries
        it to the operating temperature once (:func:`~bearing_mbs.models.cylindrical_roller.operating_oil.
        operating_oil`)."""
        if self.oil is None and self.viscosity_40 is None:
            return None
        own = {name: getattr(self, name) for name in ("viscosity_40", "viscosity_100", "density_15",
                                                       "thermal_expansion", "pressure_viscosity",
                                                       "thermal_conductivity", "pressure_viscosity_temperature")
               if getattr(self, name) is not None}
        try:
            if self.oil is not None:
                return replace(LUBRICANTS[self.oil], **own)
            return Lubricant("custom oil", **own, source="the scenario's [lubricant]")
        except LubricantError as error:
            raise SpecError(error.field, error.value, error.allowed) from None


@dataclass(frozen=True)
class AnalysisSpec:
    """``[analysis]``: the window over which means are taken starts at ``start`` [s], or at ``start_fraction``
    in [0, 1) of the end time (give one; default: the second half of the run, fraction 0.5). A ``start`` at or
    after the end time is moved to half the end time, with a logged notice (a run shortened by
    ``--set scenario.end_time=…`` needs no second override). load_fraction: contacts carrying less than this
    fraction of the largest roller load are left out of slip ratios (their rolling speed is not defined by the
    load)."""

    start: float | None = None
    start_fraction: float | None = None
    load_fraction: float = 0.05

    def __post_init__(self):
        if self.start is not None:
            non_negative("start", self.start)
            require(self.start_fraction is None, "start_fraction", self.start_fraction,
                    f"give start [s] or start_fraction, not both (start = {self.start!r})")
        if self.start_fraction is not None:
            in_range("start_fraction", self.start_fraction, 0.0, 1.0, "-", high_open=True)
        in_range("load_fraction", self.load_fraction, 0.0, 1.0, "-")

    def window_start(self, end_time: float) -> float:
        """Where the window starts [s] in a run that ends at ``end_time`` [s]."""
        if self.start is not None:
            return self.start
        return (0.5 if self.start_fraction is None else self.start_fraction) * end_time


#: Presets: documented coherent bearings (see docs/bearing.md for the sources and choices).
PRESETS = {
    # The primary document's high-speed-shaft bearing made coherent: raceways 0.210/0.260 m kept, so
    # D_w = (0.260 − 0.210)/2 = 0.025 m at zero clearance (the document's 0.047 m does not fit), D_pw = 0.235 m;
    # Z = 15, L_w = 0.055 m, H = 1 mm, bronze cage on the pitch circle's outside as the document's
    # DC = 0.245 m, a 4 mm × 50 mm cage section, an inner ring of bore 0.160 m and width 0.055 m.
    "seed-hss": {
        "rollers": 15, "roller_diameter": 0.025, "roller_length": 0.055, "inner_race_diameter": 0.210,
        "outer_race_diameter": 0.260, "cage_diameter": 0.245, "pocket_clearance": 0.001,
        "cage_thickness": 0.004, "cage_width": 0.050, "inner_ring_bore": 0.160, "ring_width": 0.055,
    },
    # A catalogue-size bearing with the boundary dimensions of an NU 216 (ISO 15 dimension series 02: d = 80 mm,
    # D = 140 mm, B = 26 mm). The internal geometry is ours: D_pw = (d + D)/2 = 110 mm, 16 rollers of
    # 15 mm × 15 mm, raceways 95/125 mm at zero clearance. ISO 76 then gives C0 = 44 (1 − D_w/D_pw) Z L_w D_w
    # = 137 kN, between the static ratings published for NU 216 bearings (120 kN to 166 kN).
    "nu216": {
        "rollers": 16, "roller_diameter": 0.015, "roller_length": 0.015, "inner_race_diameter": 0.095,
        "outer_race_diameter": 0.125, "cage_diameter": 0.114, "pocket_clearance": 0.0004,
        "cage_thickness": 0.0025, "cage_width": 0.016, "inner_ring_bore": 0.080, "ring_width": 0.026,
    },
}

# Contact defaults (docs/bearing.md): Palmgren line contacts, Lankarani–Nikravesh with the approach speed floored at
# 0.1 m/s (a damping ratio near 0.1 in the load zone instead of an overdamped contact), the annex's erf friction with
# μ = 0.1 and v_reg = 0.01 m/s, and on the raceways a rolling-resistance arm of 15 µm (f = μ_R/r ≈ 1.2e-3 for the seed
# roller, the order of catalogue friction coefficients of cylindrical roller bearings, ~0.001).
SLIDING = ContactSpec(normal_law="lankarani_nikravesh", stiffness_model="palmgren", restitution=0.9,
                      approach_speed_floor=0.1, friction_law="erf", friction_coefficient=0.1, regularisation_speed=0.01)
RACEWAY = ContactSpec(**{**to_mapping(SLIDING), "rolling_resistance_arm": 1.5e-5})


@dataclass(frozen=True)
class BearingContact:
    """``[contact]`` of the bearing model: ``inner_race``, ``outer_race``, ``pocket`` (roller–cage), ``land``
    (cage–ring land) and ``roller`` (roller–roller). A partial table is merged over the group's default."""

    inner_race: ContactSpec = RACEWAY
    outer_race: ContactSpec = RACEWAY
    pocket: ContactSpec = SLIDING
    land: ContactSpec = SLIDING
    roller: ContactSpec = SLIDING


#: The contact groups of the bearing model with a ``[contact.<group>]`` table, in the order of :class:`BearingContact`.
CONTACT_GROUPS = (Group.INNER_RACE, Group.OUTER_RACE, Group.POCKET, Group.LAND, Group.ROLLER)


@dataclass(frozen=True)
class BearingModelSpec(Spec):
    """A ``bearing`` scenario: the shared sections plus ``[contact]``, ``[bearing]`` (required), ``[cage]``,
    ``[drive]``, ``[load]``, ``[lubricant]`` and ``[analysis]``."""

    contact: BearingContact = field(default_factory=BearingContact)
    bearing: BearingSpec | None = None
    cage: CageSpec = field(default_factory=CageSpec)
    drive: DriveSpec = field(default_factory=DriveSpec)
    load: LoadSpec = field(default_factory=LoadSpec)
    lubricant: LubricantSpec = field(default_factory=LubricantSpec)
    analysis: AnalysisSpec = field(default_factory=AnalysisSpec)

    def __post_init__(self):
        super().__post_init__()
        require(self.bearing is not None, "bearing", None, "the bearing model needs a [bearing] section")
        pitch_speed = math.pi * self.bearing.pitch * abs(self.drive.top_rpm) / 60
        require(pitch_speed <= PITCH_SPEED_LIMIT, "drive.speed_rpm", self.drive.top_rpm,
                f"a pitch-circle speed π D_pw n/60 <= {PITCH_SPEED_LIMIT:g} m/s (n <= "
                f"{PITCH_SPEED_LIMIT * 60 / (math.pi * self.bearing.pitch):.4g} rpm for D_pw = "
                f"{self.bearing.pitch:g} m): beyond the fastest rolling bearings")
        capacity = static_load_rating(self.bearing)
        for name, value in (("load.radial", self.load.radial), ("load.final", self.load.final)):
            require(value <= LOAD_LIMIT * capacity, name, value,
                    f"<= {LOAD_LIMIT:g} C0 = {LOAD_LIMIT * capacity:.4g} N (ISO 76 static load rating C0 = "
                    f"{capacity:.4g} N of this bearing): beyond it the raceways yield, which the model does not hold")
        for group in CONTACT_GROUPS:
            lubricated = getattr(self.contact, group).friction_law == "ehl"
            if lubricated and group not in (Group.INNER_RACE, Group.OUTER_RACE):
                raise SpecError(f"contact.{group}.friction_law", "ehl",
                                "lubricated (EHL line-contact) traction applies to inner_race and outer_race")
            if lubricated and self.lubricant.temperature is None:
                raise SpecError("lubricant.temperature", None, f"contact.{group} uses friction_law = 'ehl', which "
                                "needs the oil and its operating temperature [°C] in [lubricant]")
        if self.lubricant.land_film:
            self._check_land_film()
        if self.lubricant.pocket_film:
            require(self.lubricant.temperature is not None, "lubricant.temperature", None,
                    "the pocket film (pocket_film = true) needs the oil and its operating temperature [°C]")
        start, end = self.analysis.start, self.scenario.end_time
        if start is not None and not start < end:
            log.warning("analysis.start = %g s is not before scenario.end_time = %g s: the window starts at half the "
                        "end time, %g s, instead (analysis.start_fraction scales with the run)", start, end, end / 2)
            object.__setattr__(self, "analysis", replace(self.analysis, start=None))


    def _check_land_film(self):
        """The cage–land film needs the oil at its temperature, a cage on the outer ring's land, and side rings."""
        bearing = self.bearing
        require(self.lubricant.temperature is not None, "lubricant.temperature", None,
                "the cage-land film (land_film = true) needs the oil and its operating temperature [°C]")
        require(bearing.cage_guidance == "outer_land", "bearing.cage_guidance", bearing.cage_guidance,
                "'outer_land' for the cage-land film (land_film = true): the film is a journal bearing between the "
                "cage and the stationary outer ring")
        require(self.cage.model != "none", "cage.model", self.cage.model, "a cage for the cage-land film")
        require(bearing.cage_width > bearing.roller_length, "bearing.cage_width", bearing.cage_width,
                f"> roller_length = {bearing.roller_length:g} m for the cage-land film: the land runs on the side "
                "rings beside the pockets, cage_width − roller_length wide")


def with_preset(data: dict) -> dict:
    """Put a ``[bearing] preset``'s values under the keys the file does not give (before validation). A file that
    gives ``diametral_clearance`` (or ``pitch_diameter``) describes the raceways by the pitch circle: the preset's
    raceway diameters are then left out, and without a ``pitch_diameter`` the preset's pitch circle is kept."""
    bearing = data.get("bearing")
    if isinstance(bearing, dict) and bearing.get("preset"):
        name = bearing["preset"]
        if not isinstance(name, str) or name not in PRESETS:
            raise SpecError("bearing.preset", name, f"must be one of {', '.join(PRESETS)}")
        given, preset = set(bearing), PRESETS[name]
        if given & {"pitch_diameter", "diametral_clearance"}:  # the user chose the other raceway description
            races = ("inner_race_diameter", "outer_race_diameter")
            bearing.update({k: v for k, v in preset.items() if k not in given and k not in races})
            if "pitch_diameter" not in given and all(k in preset for k in races):
                # a clearance alone keeps the preset's pitch circle, the raceways' mean (d_i + d_o)/2
                bearing["pitch_diameter"] = (preset["inner_race_diameter"] + preset["outer_race_diameter"]) / 2
        else:
            bearing.update({k: v for k, v in PRESETS[name].items() if k not in given})
    return data
