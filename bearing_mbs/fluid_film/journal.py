r"""A journal bearing's geometry, its recesses, and the finite-volume grid of its unwrapped film.

The bearing is fixed; the journal (radius R = D/2) turns at Ω [rad/s] about its centre, which sits at
:math:`(e_x, e_y)` from the bearing's centre. θ is measured in the bearing from +x towards +y, z along the axis
from −L/2 to L/2. The land film is

.. math:: h(\theta) = C - e_x\cos\theta - e_y\sin\theta,

plus the recess depth inside a recess; its rate is :math:`\dot h = -\dot e_x\cos\theta - \dot e_y\sin\theta`.

Recesses (pockets) are ``count`` equal rectangles, ``angular_width`` [deg] by ``axial_length`` [m], centred
axially and spaced evenly around the bore from ``first_angle`` [deg] (the centre of the first); a single recess
of 360° is a circumferential groove. A recess is deep
(depth ≫ C), so its pressure is uniform: the solver carries it as one unknown. The grid's θ-faces are shifted so
that the first recess's edges fall on faces; a cell belongs to a recess when its centre lies inside it, and
:attr:`FilmGrid.recess_areas` gives the areas the grid actually resolves.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

#: Largest eccentricity ratio a film model is trusted at: beyond it the film is below 5 % of the clearance and metal
#: contact is near (asperities, form errors and elastic deflection, which a rigid smooth film leaves out, decide).
FILM_COLLAPSE = 0.95
#: The most cells a film grid may have (n_theta × n_z): 28 times the journal's default 240 × 60, beyond any
#: convergence the load needs (0.3 % on the default grid, docs/status.md). The journal command on 1000 × 400 cells
#: took 0.8 GB and 100 s; a mutated grid of 7e7 × 60 asked numpy for 31 GiB before any check.
MAX_CELLS = 400_000


@dataclass(frozen=True)
class Recesses:
    """``count`` recesses of ``angular_width`` [deg] × ``axial_length`` [m], ``depth`` [m] deep, the first centred at
    ``first_angle`` [deg]."""

    count: int
    angular_width: float
    axial_length: float
    depth: float
    first_angle: float = 0.0

    def centres(self) -> np.ndarray:
        """Centre angle of each recess [rad]."""
        return np.radians(self.first_angle + 360.0 * np.arange(self.count) / self.count)

    def problems(self, length: float) -> list[tuple[str, object, str]]:
        """(field, value, allowed) for every way these recesses do not fit a bearing of this length."""
        found = []
        if not (isinstance(self.count, int) and self.count >= 1):
            found.append(("count", self.count, "an integer >= 1"))
            return found
        if self.count == 1 and not 0 < self.angular_width <= 360.0:
            found.append(("angular_width", self.angular_width, "must be in (0, 360] deg (360: a circumferential groove)"))
        if self.count > 1 and not 0 < self.angular_width < 360.0 / self.count:
            found.append(("angular_width", self.angular_width,
                          f"must be in (0, {360.0 / self.count:g}) deg: {self.count} recesses must not overlap"))
        if not 0 < self.axial_length <= length:
            found.append(("axial_length", self.axial_length, f"must be in (0, {length:g}] m (the bearing length)"))
        if not self.depth > 0:
            found.append(("depth", self.depth, "must be > 0"))
        return found


@dataclass(frozen=True)
class JournalBearing:
    """``diameter`` D [m] and ``length`` L [m] of the bore, ``radial_clearance`` C [m], ``viscosity`` μ [Pa s],
    ``density`` ρ [kg/m³] (for orifices and flow checks), and optional :class:`Recesses`."""

    diameter: float
    length: float
    radial_clearance: float
    viscosity: float
    density: float = 860.0
    recesses: Recesses | None = None

    def __post_init__(self):
        for name in ("diameter", "length", "radial_clearance", "viscosity", "density"):
            value = getattr(self, name)
            if not (math.isfinite(value) and value > 0):
                raise ValueError(f"{name} = {value!r}: must be a finite number > 0")
        if self.radial_clearance >= self.diameter / 2:
            raise ValueError(f"radial_clearance = {self.radial_clearance!r}: must be < the radius {self.diameter / 2:g}")
        if self.recesses is not None:
            for name, value, allowed in self.recesses.problems(self.length):
                raise ValueError(f"recesses.{name} = {value!r}: {allowed}")

    @property
    def radius(self) -> float:
        return self.diameter / 2


@dataclass(frozen=True)
class FilmGrid:
    """Cell-centred grid of ``n_theta`` × ``n_z`` cells on the unwrapped film, and which recess owns each cell.

    ``theta`` [rad] and ``z`` [m] are cell centres; ``theta_faces[i]`` is the face between cells i−1 and i;
    ``recess_of[i, j]`` is the recess index of cell (i, j), or −1 on the lands.
    """

    bearing: JournalBearing
    n_theta: int
    n_z: int
    theta: np.ndarray
    theta_faces: np.ndarray
    z: np.ndarray
    recess_of: np.ndarray

    @classmethod
    def build(cls, bearing: JournalBearing, n_theta: int = 120, n_z: int = 30) -> FilmGrid:
        for name, value in (("n_theta", n_theta), ("n_z", n_z)):
            if not (isinstance(value, int | np.integer) and value >= 4):
                raise ValueError(f"grid {name} = {value!r}: must be an integer >= 4")
        step = 2 * math.pi / n_theta
        recesses = bearing.recesses
        offset = 0.0 if recesses is None else (recesses.centres()[0] - math.radians(recesses.angular_width) / 2) % step
        theta_faces = offset + step * np.arange(n_theta)
        theta = theta_faces + step / 2
        dz = bearing.length / n_z
        z = -bearing.length / 2 + dz * (np.arange(n_z) + 0.5)
        recess_of = np.full((n_theta, n_z), -1, dtype=np.int64)
        if recesses is not None:
            half_width = math.radians(recesses.angular_width) / 2
            inside_z = np.abs(z) < recesses.axial_length / 2
            for k, centre in enumerate(recesses.centres()):
                inside_theta = np.abs(np.angle(np.exp(1j * (theta - centre)))) < half_width
                recess_of[np.ix_(inside_theta, inside_z)] = k
        return cls(bearing, n_theta, n_z, theta, theta_faces, z, recess_of)

    @property
    def d_theta(self) -> float:
        return 2 * math.pi / self.n_theta

    @property
    def dz(self) -> float:
        return self.bearing.length / self.n_z

    @property
    def cell_area(self) -> float:
        """Area of one cell on the bore [m²]."""
        return self.bearing.radius * self.d_theta * self.dz

    @property
    def recess_count(self) -> int:
        return 0 if self.bearing.recesses is None else self.bearing.recesses.count

    @property
    def recess_areas(self) -> np.ndarray:
        """The area of each recess as the grid resolves it [m²]."""
        return np.array([np.count_nonzero(self.recess_of == k) for k in range(self.recess_count)]) * self.cell_area

    def land_film(self, theta: np.ndarray, eccentricity: tuple[float, float]) -> np.ndarray:
        """h [m] of the land at angles θ [rad] for the journal centre (e_x, e_y) [m]."""
        e_x, e_y = eccentricity
        return self.bearing.radial_clearance - e_x * np.cos(theta) - e_y * np.sin(theta)

    def film_rate(self, theta: np.ndarray, eccentricity_rate: tuple[float, float]) -> np.ndarray:
        """ḣ [m/s] at angles θ for the journal centre's velocity (ė_x, ė_y) [m/s]."""
        v_x, v_y = eccentricity_rate
        return -v_x * np.cos(theta) - v_y * np.sin(theta)
