r"""Journal bearings as a force element: the oil film between a body (the journal) and the ground (the bearing).

The body's position (x, y) relative to the bearing's ``centre`` is the journal's eccentricity, its velocity the
squeeze velocity and its angular velocity the journal speed Ω. The film force comes from
:mod:`bearing_mbs.fluid_film` (one source of each formula, compiled here):

* ``short`` — Ocvirk's dynamic short bearing with Gümbel's condition (:func:`~bearing_mbs.fluid_film.closed_forms.
  short_bearing_force`);
* ``map`` — a finite bearing's Reynolds solution, tabulated (:mod:`bearing_mbs.fluid_film.force_map`).

``count`` identical bearings act together (a rigid rotor on two bearings in its cylindrical mode). The journal also
feels the Couette torque of the full film, :math:`-2\pi\mu\Omega R^3 L/(C\sqrt{1-\varepsilon^2})` per bearing. The
film stores no energy: the power it takes from the bodies is dissipated, ``power[1] -= F·v + TΩ``. An eccentricity
at or beyond the clearance (metal contact, outside the film model) is evaluated at ε = :data:`LARGEST_ECCENTRICITY`;
the rotor model warns well before.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import NamedTuple

import numba
import numpy as np
from numba.extending import register_jitable

from bearing_mbs.core.force_element import ForceElement
from bearing_mbs.fluid_film.closed_forms import short_bearing_force, short_bearing_force_jacobian, short_bearing_torque
from bearing_mbs.fluid_film.force_map import map_force, map_force_jacobian

#: Force sources by their integer code.
SOURCES = ("short", "map")
#: The largest eccentricity ratio the film is evaluated at.
LARGEST_ECCENTRICITY = 0.999


@dataclass(frozen=True)
class JournalFilm:
    """``count`` identical journal bearings between the ground and ``body``: radius R, length L, radial clearance C [m],
    viscosity μ [Pa s], centre (x, y) [m] of the bore; ``source`` ``short`` or ``map`` (then ``map_normal`` and
    ``map_tangential``, ``map_linear``, tables of :class:`~bearing_mbs.fluid_film.force_map.ForceMap`, and
    ``map_axes`` its axes)."""

    name: str
    body: int
    count: int
    radius: float
    length: float
    clearance: float
    viscosity: float
    centre: tuple[float, float] = (0.0, 0.0)
    source: str = "short"
    map_normal: np.ndarray = field(default_factory=lambda: np.zeros((2, 1, 1, 1)), compare=False)
    map_tangential: np.ndarray = field(default_factory=lambda: np.zeros((2, 1, 1, 1)), compare=False)
    map_linear: np.ndarray = field(default_factory=lambda: np.zeros((2, 1, 3, 2)), compare=False)
    map_axes: np.ndarray = field(default_factory=lambda: np.array([1.0, 2 * math.pi, 0.0, 1.0, 1.0, 0.0]),
                                 compare=False)


class JournalFilmArrays(NamedTuple):
    body: np.ndarray  # (J,) int64
    count: np.ndarray  # (J,) float
    geometry: np.ndarray  # (J, 4): R, L, C [m], μ [Pa s]
    centre: np.ndarray  # (J, 2) [m]
    source: np.ndarray  # (J,) int64, index into SOURCES
    map_shape: np.ndarray  # (J, 4) int64: each item's table shape (ε, φ, γ, β)
    map_axes: np.ndarray  # (J, 6): bearing_mbs.fluid_film.force_map.AXES
    map_normal: np.ndarray  # (J, ε, φ, γ, β), zero-padded
    map_tangential: np.ndarray  # (J, ε, φ, γ, β)
    map_linear: np.ndarray  # (J, ε, φ, 3, 2)


def pack(films) -> JournalFilmArrays:
    shapes = np.array([f.map_normal.shape for f in films], dtype=np.int64).reshape(-1, 4)
    largest = tuple(shapes.max(axis=0)) if len(films) else (1, 1, 1, 1)
    normal, tangential = np.zeros((len(films), *largest)), np.zeros((len(films), *largest))
    linear = np.zeros((len(films), *largest[:2], 3, 2))
    for j, f in enumerate(films):
        within = (j, *(slice(0, size) for size in shapes[j]))
        normal[within], tangential[within] = f.map_normal, f.map_tangential
        linear[within[:3]] = f.map_linear
    return JournalFilmArrays(
        body=np.array([f.body for f in films], dtype=np.int64),
        count=np.array([f.count for f in films], dtype=float),
        geometry=np.array([[f.radius, f.length, f.clearance, f.viscosity] for f in films], dtype=float).reshape(-1, 4),
        centre=np.array([f.centre for f in films], dtype=float).reshape(-1, 2),
        source=np.array([SOURCES.index(f.source) for f in films], dtype=np.int64),
        map_shape=shapes, map_axes=np.array([f.map_axes for f in films], dtype=float).reshape(-1, 6),
        map_normal=normal, map_tangential=tangential, map_linear=linear)


@register_jitable
def _tables(films, j):
    """Item j's force-map tables (normal, tangential, linear), without the padding."""
    rows, columns, shares, directions = films.map_shape[j, 0], films.map_shape[j, 1], films.map_shape[j, 2], \
        films.map_shape[j, 3]
    return (films.map_normal[j, :rows, :columns, :shares, :directions],
            films.map_tangential[j, :rows, :columns, :shares, :directions], films.map_linear[j, :rows, :columns])


@register_jitable
def held_eccentricity(e_x, e_y, clearance):
    """(e_x, e_y [m], ε) of an eccentricity (e_x, e_y) [m] in a clearance [m], held at :data:`LARGEST_ECCENTRICITY`
    beyond it."""
    eps = math.sqrt(e_x * e_x + e_y * e_y) / clearance
    if eps > LARGEST_ECCENTRICITY:
        return e_x * LARGEST_ECCENTRICITY / eps, e_y * LARGEST_ECCENTRICITY / eps, LARGEST_ECCENTRICITY
    return e_x, e_y, eps


@numba.njit(cache=True)
def film_load(films, j, q, v):
    """(F_x, F_y, T) [N, N, N m] of item j on its body."""
    i = 3 * films.body[j]
    radius, length, clearance, viscosity = films.geometry[j, 0], films.geometry[j, 1], films.geometry[j, 2], \
        films.geometry[j, 3]
    e_x, e_y, eps = held_eccentricity(q[i] - films.centre[j, 0], q[i + 1] - films.centre[j, 1], clearance)
    speed = v[i + 2]
    if films.source[j] == 0:
        f_x, f_y = short_bearing_force(e_x, e_y, v[i], v[i + 1], speed, radius, length, clearance, viscosity)
    else:
        normal, tangential, linear = _tables(films, j)
        f_x, f_y = map_force(normal, tangential, linear, films.map_axes[j], e_x, e_y, v[i], v[i + 1], speed, clearance)
    torque = short_bearing_torque(eps, speed, radius, length, clearance, viscosity)
    return films.count[j] * f_x, films.count[j] * f_y, films.count[j] * torque


@numba.njit(cache=True, inline="always")
def add_forces(parameters, t, q, v, forces, power):
    films = parameters
    for j in range(films.body.size):
        f_x, f_y, torque = film_load(films, j, q, v)
        i = 3 * films.body[j]
        forces[i] += f_x
        forces[i + 1] += f_y
        forces[i + 2] += torque
        power[1] -= f_x * v[i] + f_y * v[i + 1] + torque * v[i + 2]


def add_forces_twin(films, t, q, v, forces, power):
    """The same forces through the library's functions called from Python (no compiled kernel)."""
    for j, body in enumerate(films.body):
        radius, length, clearance, viscosity = films.geometry[j]
        e = q[3 * body : 3 * body + 2] - films.centre[j]
        eps = float(np.hypot(*e)) / clearance
        if eps > LARGEST_ECCENTRICITY:
            e, eps = e * LARGEST_ECCENTRICITY / eps, LARGEST_ECCENTRICITY
        velocity, speed = v[3 * body : 3 * body + 2], v[3 * body + 2]
        if SOURCES[films.source[j]] == "short":
            force = short_bearing_force(*e, *velocity, speed, radius, length, clearance, viscosity)
        else:
            force = map_force(*_tables(films, j), films.map_axes[j], *e, *velocity, speed, clearance)
        torque = short_bearing_torque(eps, speed, radius, length, clearance, viscosity)
        load = films.count[j] * np.array([*force, torque])
        forces[3 * body : 3 * body + 3] += load
        power[1] -= load @ v[3 * body : 3 * body + 3]


@numba.njit(cache=True, inline="always")
def add_jacobian(parameters, t, q, v, force_position, force_velocity):
    """∂F/∂q and ∂F/∂v of each film: its force's slopes in (e_x, e_y, v_x, v_y, Ω)
    (:func:`~bearing_mbs.fluid_film.closed_forms.short_bearing_force_jacobian`,
    :func:`~bearing_mbs.fluid_film.force_map.map_force_jacobian`) and its Couette torque's in ε and Ω; beyond
    :data:`LARGEST_ECCENTRICITY` the eccentricity is held there, so only its direction moves the force."""
    films = parameters
    for j in range(films.body.size):
        i = 3 * films.body[j]
        radius, length, clearance, viscosity = films.geometry[j, 0], films.geometry[j, 1], films.geometry[j, 2], \
            films.geometry[j, 3]
        e_x, e_y = q[i] - films.centre[j, 0], q[i + 1] - films.centre[j, 1]
        e = math.sqrt(e_x * e_x + e_y * e_y)
        eps = e / clearance
        # ∂(evaluated e)/∂e: the identity, or the projection on the direction's change when held at the largest ε
        held = np.eye(2)
        if eps > LARGEST_ECCENTRICITY:
            n_x, n_y = e_x / e, e_y / e
            held = LARGEST_ECCENTRICITY / eps * np.array([[n_y * n_y, -n_x * n_y], [-n_x * n_y, n_x * n_x]])
            e_x, e_y, eps = e_x * LARGEST_ECCENTRICITY / eps, e_y * LARGEST_ECCENTRICITY / eps, LARGEST_ECCENTRICITY
        speed = v[i + 2]
        if films.source[j] == 0:
            slopes = short_bearing_force_jacobian(e_x, e_y, v[i], v[i + 1], speed, radius, length, clearance,
                                                  viscosity)
        else:
            normal, tangential, linear = _tables(films, j)
            slopes = map_force_jacobian(normal, tangential, linear, films.map_axes[j], e_x, e_y, v[i], v[i + 1], speed,
                                        clearance)
        count = films.count[j]
        for r in range(2):
            for c in range(2):
                force_position[i + r, i + c] += count * (slopes[r, 0] * held[0, c] + slopes[r, 1] * held[1, c])
                force_velocity[i + r, i + c] += count * slopes[r, 2 + c]
            force_velocity[i + r, i + 2] += count * slopes[r, 4]
        torque = short_bearing_torque(eps, speed, radius, length, clearance, viscosity)
        force_velocity[i + 2, i + 2] += count * short_bearing_torque(eps, 1.0, radius, length, clearance, viscosity)
        if e > 0.0 and eps < LARGEST_ECCENTRICITY:
            by_eps = torque * eps / (1.0 - eps * eps)
            force_position[i + 2, i] += count * by_eps * e_x / (e * clearance)
            force_position[i + 2, i + 1] += count * by_eps * e_y / (e * clearance)


ELEMENT = ForceElement(name="journal_bearings", item_type=JournalFilm, parameters=JournalFilmArrays, pack=pack,
                       add_forces=add_forces, add_forces_twin=add_forces_twin, add_jacobian=add_jacobian)
