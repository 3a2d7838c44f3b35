r"""Traction of a lubricated rolling–sliding line contact: the ``ehl`` friction law.

The traction coefficient μ of a pair in contact depends on the slip speed :math:`\Delta u` [m/s], the mean
entrainment speed :math:`u` [m/s], the normal force :math:`Q` [N] and the film (:mod:`.ehl`). It blends a
film-shear traction :math:`\mu_f` with boundary friction by the film parameter Λ (mixed lubrication):

.. math:: \mu = \psi(\Lambda)\,\mu_b\,\mathrm{erf}(2\Delta u/v_{reg}) + [1 - \psi(\Lambda)]\,\mu_f,
          \qquad \psi(\Lambda) = e^{-1.8\,\Lambda^{1.2}},

ψ the share of the load carried by asperities: 0.83 at Λ = 0.1, 0.17 at Λ = 1, 0.002 at Λ = 3, so the
boundary friction :math:`\mu_b` fades out between Λ ≈ 1 and 3, where full-film lubrication sets in for bearing
steels (T. A. Harris, M. N. Kotzalas, *Essential Concepts of Bearing Technology*, 2006, ch. 4). The form and its
constants are our choice of a smooth switch over that range, not a fitted law.

Film-shear traction, two models (``TRACTION_MODELS``):

* ``eyring`` — a physically based, isothermal model at the mean Hertz pressure :math:`\bar p`. The oil in the
  contact has the Barus viscosity :math:`\bar\eta = \eta_0 e^{\alpha\bar p}` and shears at
  :math:`\dot\gamma = \Delta u/h` (h the central film). Its viscous stress follows Eyring's law,
  :math:`\tau_v = \tau_0\,\mathrm{asinh}(\bar\eta\dot\gamma/\tau_0)`; its elastic stress in the transit time
  2b/u through the contact is :math:`\tau_e = G\,\Delta u\,b/(u h)` (the linear, viscoelastic branch of
  K. L. Johnson and J. L. Tevaarwerk, "Shear behaviour of elastohydrodynamic oil films", Proc. R. Soc. Lond.
  A 356 (1977) 215–236, with G the oil's effective shear modulus). The two act in series,
  :math:`\tau_{ve} = \tau_v\tau_e/(\tau_v + \tau_e)` (exact in the linear limit, the Eyring stress at large
  slip), and the oil cannot carry more than its limiting shear stress :math:`\tau_L = \Lambda_L\bar p`
  (S. Bair, W. O. Winer, "A rheological model for elastohydrodynamic contacts based on primary laboratory
  data", J. Lubr. Technol. 101 (1979) 258–265):

  .. math:: \mu_f = \mathrm{sign}(\Delta u)\,\frac{\tau_L}{\bar p}\tanh\frac{\tau_{ve}}{\tau_L}.

  At small slip the slope is :math:`\mathrm d\mu_f/\mathrm ds = 1/(\bar p h/(\bar\eta u) + \bar p h/(G b))`
  in the slide-to-roll ratio :math:`s = \Delta u/u`; the ceiling is :math:`\Lambda_L`.
* ``curve`` — the empirical form fitted to measured traction curves by bearing-dynamics codes,
  :math:`\mu_f = \mathrm{sign}(s)\,[(A + B|s|)\,e^{-C|s|} + D]` with :math:`A + D = 0` (no jump at zero slip).

Hydrodynamic rolling resistance (optional, ``ehl_rolling_resistance``): the contact's rolling force :math:`F_R`
(:func:`.ehl.rolling_force`; reduced by the film's inlet-heating factor :math:`\phi_T` when that is on, our choice:
the force is made in the inlet, as the film is) against the entrainment, :math:`f = F_R\,\varphi(u)` with the
boundary friction's regularised sign φ at v_reg. It is the inlet's Poiseuille shear, :math:`-f/2` on each surface
at the contact point (the same direction on both), balanced by the tangential part of the film pressure on the two
curved surfaces, which passes through their centres of curvature and is shared as the contact point's motion is
(:func:`.kinematics.contact_point_share` w): :math:`(1 - w) f` at b's centre, :math:`w f` at a's. Gathered at the
contact point this is a tangential pair force :math:`(1/2 - w) f` on b and a couple :math:`(1 - w) r_b f`
(:func:`rolling_resistance`; a receives the opposite of both). Their power is :math:`-f u` in any motion,
rolling or sliding, since :math:`(1/2 - w)\Delta u + (1 - w) r_b \Delta\omega = -u` is a kinematic identity
(tests/test_kernel.py checks it): the inlet's viscous loss, never a source. A moment against the relative spin
alone would have the right power in pure rolling only, and would pull a stalled roller towards the ring's spin.

Shear heating (optional, ``shear_heating``; ``eyring`` only): the viscous stress is reduced by the Couette film's
Nahme reduction at :math:`Na = (\beta/k)\,\tau_v|\Delta u|h`, the heat the film would make isothermally
(:mod:`.shear_heating`): walls at the oil's temperature, no flash temperature, the elastic branch and the limiting
stress untouched. Starvation: the row's replenishment factor φ_rs multiplies the film (central and minimum, so Λ as
well) and the rolling force, as the inlet heating's φ_T does (1: fully flooded).

The film thickness in the shear rate is floored at the roughness σ: below it the asperities carry the load
(ψ → 1) and the film-shear term would otherwise stiffen without bound as the film vanishes.

Functions are ``register_jitable`` (the compiled contact kernel calls them inline) and take scalars.
"""

from __future__ import annotations

import math

import numpy as np
from numba.extending import register_jitable

from bearing_mbs.contact import ehl, friction
from bearing_mbs.contact.shear_heating import nahme_reduction

#: Film-shear traction models in the order of their integer codes.
TRACTION_MODELS = ("eyring", "curve")
_EYRING = TRACTION_MODELS.index("eyring")

#: Columns of a pair's traction row (``PairLaw.traction``), in order: model and film-formula codes, thermal
#: reduction (1/0), η0 [Pa s], α [1/Pa], β [1/K], k [W/(m K)], E' [Pa], R [m], l [m], σ [m], τ0 [Pa], G [Pa],
#: Λ_L [-], the curve's A, B, C, D [-], hydrodynamic rolling resistance (1/0), the film's shear heating (1/0) and
#: the starvation's replenishment factor φ_rs in (0, 1] on film and rolling force (1: fully flooded).
TRACTION_COLUMNS = (
    "model", "film_formula", "thermal", "viscosity", "pressure_viscosity", "temperature_viscosity",
    "conductivity", "modulus", "radius", "length", "roughness", "eyring_stress", "shear_modulus",
    "limiting_shear", "curve_a", "curve_b", "curve_c", "curve_d", "rolling_resistance", "shear_heating",
    "replenishment",
)
N_TRACTION_COLUMNS = len(TRACTION_COLUMNS)
# Column indices, read by numba as compile-time constants (one order: TRACTION_COLUMNS).
(_MODEL, _FORMULA, _THERMAL, _VISCOSITY, _PRESSURE_VISCOSITY, _TEMPERATURE_VISCOSITY, _CONDUCTIVITY, _MODULUS,
 _RADIUS, _LENGTH, _ROUGHNESS, _EYRING_STRESS, _SHEAR_MODULUS, _LIMITING_SHEAR, _CURVE_A, _CURVE_B, _CURVE_C,
 _CURVE_D, _ROLLING_RESISTANCE, _SHEAR_HEATING, _REPLENISHMENT) = range(N_TRACTION_COLUMNS)


@register_jitable
def asperity_share(film_parameter):
    r"""ψ(Λ) = exp(−1.8 Λ^1.2): the share of the load on asperities, 1 at Λ = 0."""
    return np.exp(-1.8 * film_parameter**1.2)


@register_jitable
def eyring_traction(slip, speed, film, mean_pressure, half_width, viscosity, pressure_viscosity, eyring_stress,
                    shear_modulus, limiting_shear, heating=0.0):
    """Film-shear traction coefficient μ_f [-] of the ``eyring`` model (signed like ``slip``); speed u > 0,
    film h > 0 [m], mean pressure [Pa] > 0, half-width b [m]; heating β/k [m/W] (0: isothermal) reduces the
    viscous stress by the Couette film's shear heating (:func:`.shear_heating.nahme_reduction` at
    Na = (β/k) τ_v |Δu| h)."""
    rate = abs(slip) / film
    viscous = 0.0
    if rate > 0.0:
        # asinh(x) with x = eta_0 e^{alpha p} rate/tau_0, through log x: e^{alpha p} alone overflows at extreme loads
        log_x = math.log(viscosity * rate / eyring_stress) + pressure_viscosity * mean_pressure
        viscous = eyring_stress * (log_x + math.log(2.0) if log_x > 20.0 else math.asinh(math.exp(log_x)))
        if heating > 0.0:
            viscous *= nahme_reduction(heating * viscous * abs(slip) * film)[0]
    elastic = shear_modulus * abs(slip) * half_width / (speed * film)
    total = viscous + elastic
    series = viscous * elastic / total if total > 0.0 else 0.0
    limit = limiting_shear * mean_pressure
    return math.copysign(limit * math.tanh(series / limit) / mean_pressure, slip)


@register_jitable
def curve_traction(slide_to_roll, a, b, c, d):
    r"""The empirical curve :math:`\mathrm{sign}(s)[(A + B|s|)e^{-C|s|} + D]` [-]."""
    s = abs(slide_to_roll)
    return math.copysign((a + b * s) * math.exp(-c * s) + d, slide_to_roll)


@register_jitable
def _contact_film(row, rolling, normal_force, regularisation_speed):
    """(entrainment speed u floored at v_reg [m/s], load per length w [N/m], central and minimum film [m] with the
    inlet heating's reduction if on, Murch–Wilson's loading L (0 with it off)) of a lubricated line contact."""
    speed = max(abs(rolling), regularisation_speed)
    viscosity = row[_VISCOSITY]
    load = normal_force / row[_LENGTH]
    central, minimum = ehl.film_thickness(int(row[_FORMULA]), speed, load, viscosity, row[_PRESSURE_VISCOSITY],
                                          row[_MODULUS], row[_RADIUS])
    loading = 0.0
    reduction = row[_REPLENISHMENT]
    if row[_THERMAL] > 0.0:
        loading = ehl.thermal_loading(speed, viscosity, row[_TEMPERATURE_VISCOSITY], row[_CONDUCTIVITY])
        reduction *= ehl.thermal_reduction(loading)
    return speed, load, central * reduction, minimum * reduction, loading


@register_jitable
def _heating(row):
    """β/k [m/W] of the film's shear heating (:func:`eyring_traction`), 0 with it off."""
    return row[_TEMPERATURE_VISCOSITY] / row[_CONDUCTIVITY] if row[_SHEAR_HEATING] > 0.0 else 0.0


@register_jitable
def ehl_traction(row, slip, rolling, normal_force, boundary_coefficient, regularisation_speed):
    """(μ [-], minimum film [m], Λ [-]) of a lubricated line contact.

    ``row``: the pair's traction row (``TRACTION_COLUMNS``); slip Δu and rolling speed u [m/s] from the pair
    kinematics; normal force Q [N] > 0; μ_b and v_reg [m/s] of the boundary friction. The entrainment speed is
    floored at v_reg, where the film and the slide-to-roll ratio lose their meaning.
    """
    speed, load, central, minimum, _ = _contact_film(row, rolling, normal_force, regularisation_speed)
    radius, modulus, viscosity = row[_RADIUS], row[_MODULUS], row[_VISCOSITY]
    pressure_viscosity, roughness = row[_PRESSURE_VISCOSITY], row[_ROUGHNESS]
    film_parameter = ehl.film_parameter(minimum, roughness)
    share = asperity_share(film_parameter)
    if row[_MODEL] == _EYRING:
        mean_pressure = 0.25 * np.pi * ehl.hertz_pressure(load, radius, modulus)
        half_width = ehl.hertz_half_width(load, radius, modulus)
        film = max(central, roughness)
        fluid = eyring_traction(slip, speed, film, mean_pressure, half_width, viscosity, pressure_viscosity,
                                row[_EYRING_STRESS], row[_SHEAR_MODULUS], row[_LIMITING_SHEAR], _heating(row))
    else:
        fluid = curve_traction(slip / speed, row[_CURVE_A], row[_CURVE_B], row[_CURVE_C], row[_CURVE_D])
    boundary = boundary_coefficient * friction.erf_sign(slip, regularisation_speed)
    return share * boundary + (1.0 - share) * fluid, minimum, film_parameter


@register_jitable
def rolling_force(row, rolling, normal_force):
    """The hydrodynamic rolling force F_R φ_T φ_rs [N] (magnitude) at rolling speed u [m/s] and normal force Q [N]
    (with the inlet heating's and the starvation's factors, as the film has them); 0 with it off or out of
    contact."""
    if row[_ROLLING_RESISTANCE] == 0.0 or normal_force <= 0.0:
        return 0.0
    speed, viscosity, length = abs(rolling), row[_VISCOSITY], row[_LENGTH]
    force = row[_REPLENISHMENT] * ehl.rolling_force(speed, normal_force / length, viscosity,
                                                    row[_PRESSURE_VISCOSITY], row[_MODULUS], row[_RADIUS], length)
    if row[_THERMAL] > 0.0:
        force *= ehl.thermal_reduction(ehl.thermal_loading(speed, viscosity, row[_TEMPERATURE_VISCOSITY],
                                                           row[_CONDUCTIVITY]))
    return force


@register_jitable
def rolling_resistance(force, rolling, regularisation_speed, share, radius_b):
    r"""(tangential force on b [N] along t, couple on b [N m]) of the rolling resistance of magnitude ``force``
    F_R [N] (:func:`rolling_force`) at rolling speed u [m/s], with a's share w of the contact point's motion
    (:func:`.kinematics.contact_point_share`) and b's radius r_b [m]: with :math:`f = F_R\,\mathrm{erf}(2u/v_{reg})`,
    :math:`((1/2 - w) f,\ (1 - w) r_b f)`; a receives the opposite. Scalars or arrays."""
    return inlet_shear_reaction(force * friction.erf_sign(rolling, regularisation_speed), share, radius_b)


@register_jitable
def inlet_shear_reaction(shear, share, radius_b):
    r"""(tangential force on b [N] along t, couple on b [N m]) of a film's Poiseuille shear f [N] (summed over both
    surfaces, positive along t), gathered at the contact point: :math:`((1/2 - w) f,\ (1 - w) r_b f)`, with a's
    share w of the contact point's motion and b's radius r_b [m]; a receives the opposite. Their power is
    :math:`-f u`. Scalars or arrays."""
    return (0.5 - share) * shear, (1.0 - share) * radius_b * shear


def zero_slip_slope(row, rolling, normal_force, boundary_coefficient, regularisation_speed):
    """dμ/dΔu [s/m] of :func:`ehl_traction` at zero slip, where its traction curve is steepest: the friction
    damping Q dμ/dΔu that bounds an explicit step (a centred difference over ±10⁻⁷ v_reg, inside the linear
    range of both the boundary and the film branch even at the heaviest loads)."""
    step = 1e-7 * regularisation_speed
    ahead = ehl_traction(row, step, rolling, normal_force, boundary_coefficient, regularisation_speed)[0]
    behind = ehl_traction(row, -step, rolling, normal_force, boundary_coefficient, regularisation_speed)[0]
    return (ahead - behind) / (2 * step)


@register_jitable
def eyring_traction_slopes(slip, speed, film, mean_pressure, half_width, viscosity, pressure_viscosity,
                           eyring_stress, shear_modulus, limiting_shear, heating=0.0):
    r""":func:`eyring_traction`'s value, computed as it computes it (to the bit), and its derivatives: (μ_f,
    ∂μ_f/∂Δu [s/m], ∂μ_f/∂ln u, ∂μ_f/∂ln h, ∂μ_f/∂ln p̄, ∂μ_f/∂ln b).
    With V the Eyring stress, E the elastic one and S = VE/(V + E): :math:`\mu_f = \mathrm{sign}(\Delta u)\Lambda_L
    \tanh(S/\Lambda_L\bar p)`, V a function of :math:`\ln x = \ln(\eta_0|\Delta u|/h\tau_0) + \alpha\bar p`, E of
    :math:`|\Delta u| b/(u h)`; at zero slip S grows as :math:`|\Delta u|\,v_1e_1/(v_1 + e_1)`. With shear heating
    V = V_iso R(Na), Na ∝ V_iso |Δu| h: d ln V = (1 + g) d ln V_iso + g (d ln|Δu| + d ln h), g = d ln R/d ln Na."""
    magnitude = abs(slip)
    viscous = viscous_log = viscous_magnitude = 0.0
    if magnitude > 0.0:
        rate = magnitude / film
        log_x = math.log(viscosity * rate / eyring_stress) + pressure_viscosity * mean_pressure
        if log_x > 20.0:
            viscous = eyring_stress * (log_x + math.log(2.0))
            viscous_log, viscous_magnitude = eyring_stress, eyring_stress / magnitude
        else:
            x = math.exp(log_x)
            viscous = eyring_stress * math.asinh(x)
            viscous_log = eyring_stress * x / math.sqrt(1.0 + x * x)
            viscous_magnitude = eyring_stress * math.exp(log_x - math.log(magnitude)) / math.sqrt(1.0 + x * x)
    else:  # x = a |Δu|
        viscous_magnitude = eyring_stress * math.exp(math.log(viscosity / (film * eyring_stress))
                                                     + pressure_viscosity * mean_pressure)
    viscous_film, viscous_pressure = -viscous_log, viscous_log * pressure_viscosity * mean_pressure  # over ln h, ln p̄
    if heating > 0.0 and viscous > 0.0:
        reduction, exponent = nahme_reduction(heating * viscous * magnitude * film)
        viscous_magnitude = reduction * ((1.0 + exponent) * viscous_magnitude + exponent * viscous / magnitude)
        viscous_film = reduction * ((1.0 + exponent) * viscous_film + exponent * viscous)
        viscous_pressure *= reduction * (1.0 + exponent)
        viscous *= reduction
    elastic_magnitude = shear_modulus * half_width / (speed * film)
    elastic = shear_modulus * magnitude * half_width / (speed * film)
    total = viscous + elastic
    if total > 0.0:
        series = viscous * elastic / total
        series_v, series_e = (elastic / total) ** 2, (viscous / total) ** 2
        series_magnitude = series_v * viscous_magnitude + series_e * elastic_magnitude
    else:
        series = series_v = series_e = 0.0
        series_magnitude = viscous_magnitude * elastic_magnitude / (viscous_magnitude + elastic_magnitude)
    limit = limiting_shear * mean_pressure
    y = series / limit
    tanh = math.tanh(y)
    sech2 = 1.0 - tanh**2
    sign = math.copysign(1.0, slip)
    per_series = sign * sech2 / mean_pressure
    return (math.copysign(limit * tanh / mean_pressure, slip),
            sech2 / mean_pressure * series_magnitude,
            per_series * series_e * (-elastic),
            per_series * (series_v * viscous_film + series_e * (-elastic)),
            per_series * series_v * viscous_pressure - sign * limiting_shear * sech2 * y,
            per_series * series_e * elastic)


@register_jitable
def ehl_traction_slopes(row, slip, rolling, normal_force, boundary_coefficient, regularisation_speed):
    """(μ [-], ∂μ/∂Δu [s/m], ∂μ/∂u [s/m], ∂μ/∂Q [1/N]) of :func:`ehl_traction` (Q > 0): the film's and Λ's power
    laws in the speed and load (:func:`.ehl.film_thickness_exponents`, the inlet heating's log slope), the blend by
    ψ(Λ), and the film-shear model's slopes. The entrainment speed is floored at v_reg, where ∂μ/∂u is 0."""
    speed, load, central, minimum, loading = _contact_film(row, rolling, normal_force, regularisation_speed)
    speed_rolling = math.copysign(1.0, rolling) if abs(rolling) > regularisation_speed else 0.0
    radius, modulus, viscosity = row[_RADIUS], row[_MODULUS], row[_VISCOSITY]
    pressure_viscosity, roughness = row[_PRESSURE_VISCOSITY], row[_ROUGHNESS]
    (central_u, central_w), (minimum_u, minimum_w) = ehl.film_thickness_exponents(int(row[_FORMULA]))
    thermal = 2.0 * ehl.thermal_reduction_slope(loading) if row[_THERMAL] > 0.0 else 0.0  # d ln φ_T / d ln u
    film_parameter = ehl.film_parameter(minimum, roughness)
    share = asperity_share(film_parameter)
    share_log = -1.8 * 1.2 * film_parameter**1.2 * share  # dψ/d ln Λ
    share_speed, share_load = share_log * (minimum_u + thermal), share_log * minimum_w  # over ln u, ln Q
    boundary = boundary_coefficient * friction.erf_sign(slip, regularisation_speed)
    boundary_slip = boundary_coefficient * friction.erf_sign_slope(slip, regularisation_speed)
    if row[_MODEL] == _EYRING:
        mean_pressure = 0.25 * np.pi * ehl.hertz_pressure(load, radius, modulus)
        half_width = ehl.hertz_half_width(load, radius, modulus)
        film = max(central, roughness)
        floored = central <= roughness
        film_speed = 0.0 if floored else central_u + thermal
        film_load = 0.0 if floored else central_w
        heating = _heating(row)
        fluid, fluid_slip, by_speed, by_film, by_pressure, by_width = eyring_traction_slopes(
            slip, speed, film, mean_pressure, half_width, viscosity, pressure_viscosity, row[_EYRING_STRESS],
            row[_SHEAR_MODULUS], row[_LIMITING_SHEAR], heating)
        fluid_speed = by_speed + by_film * film_speed  # over ln u
        fluid_load = by_film * film_load + 0.5 * (by_pressure + by_width)  # over ln Q: p̄ and b grow as Q^(1/2)
    else:
        ratio = slip / speed
        a, b, c = row[_CURVE_A], row[_CURVE_B], row[_CURVE_C]
        fluid = curve_traction(ratio, a, b, c, row[_CURVE_D])
        curve_slope = (b - c * (a + b * abs(ratio))) * math.exp(-c * abs(ratio))
        fluid_slip, fluid_speed, fluid_load = curve_slope / speed, -curve_slope * ratio, 0.0
    return (share * boundary + (1.0 - share) * fluid,
            share * boundary_slip + (1.0 - share) * fluid_slip,
            (share_speed * (boundary - fluid) + (1.0 - share) * fluid_speed) / speed * speed_rolling,
            (share_load * (boundary - fluid) + (1.0 - share) * fluid_load) / normal_force)


@register_jitable
def signed_rolling_force_slopes(row, rolling, normal_force, regularisation_speed):
    """(f, ∂f/∂u, ∂f/∂Q) of the signed rolling force f = F_R erf(2u/v_reg) (:func:`rolling_force`,
    :func:`rolling_resistance`): F_R is a power law in u and Q (:func:`.ehl.rolling_force_exponents`, the inlet
    heating's log slope); at u = 0 both slopes vanish with F_R."""
    force = rolling_force(row, rolling, normal_force)
    if force <= 0.0:
        return 0.0, 0.0, 0.0
    speed, viscosity, length = abs(rolling), row[_VISCOSITY], row[_LENGTH]
    exponent_u, exponent_w = ehl.rolling_force_exponents(speed, normal_force / length, viscosity,
                                                         row[_PRESSURE_VISCOSITY], row[_MODULUS], row[_RADIUS],
                                                         length)
    if row[_THERMAL] > 0.0:
        exponent_u += 2.0 * ehl.thermal_reduction_slope(ehl.thermal_loading(speed, viscosity,
                                                                             row[_TEMPERATURE_VISCOSITY],
                                                                             row[_CONDUCTIVITY]))
    sign = friction.erf_sign(rolling, regularisation_speed)
    signed = force * sign
    by_rolling = force * exponent_u * sign / rolling + force * friction.erf_sign_slope(rolling, regularisation_speed)
    return signed, by_rolling, signed * exponent_w / normal_force
