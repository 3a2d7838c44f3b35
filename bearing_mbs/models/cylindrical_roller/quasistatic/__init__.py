"""Quasi-static load distribution and stiffness of radial cylindrical roller bearings (document 003's method).

* :mod:`.rollers` — :class:`RollerSet` (geometry, clearance, contact laws), :class:`NewtonSettings`,
  :class:`ConvergenceError`.
* :mod:`.planar` — rigid rollers on their radial lines: roller loads and the 2×2 radial stiffness
  (:func:`solve_radial` for a given load, :func:`radial_state` for a given displacement).
* :mod:`.profiles` — crown drops: :class:`Flat`, :class:`CircularCrown` (eq. 13 corrected),
  :class:`LogarithmicCrown` (Lundberg, Johns–Gohar).
* :mod:`.sliced` — sliced, crowned, tilting rollers: the 4×4 radial-and-tilt stiffness
  (:func:`solve_sliced`, :func:`sliced_state`).
* :mod:`.ring`, :mod:`.roots` — the Newton–Raphson loops.
* :mod:`.figures` — :func:`plot_load_distribution`.

Contact formulas (Palmgren's law, slices, series contacts) live in :mod:`bearing_mbs.contact.line_contact`.
See ``docs/quasistatic.md``.
"""

from bearing_mbs.models.cylindrical_roller.quasistatic.figures import plot_load_distribution
from bearing_mbs.models.cylindrical_roller.quasistatic.planar import (
    RadialRollerEquilibrium,
    RadialSolution,
    radial_roller_equilibrium,
    radial_state,
    solve_radial,
)
from bearing_mbs.models.cylindrical_roller.quasistatic.profiles import CircularCrown, Flat, LogarithmicCrown
from bearing_mbs.models.cylindrical_roller.quasistatic.rollers import ConvergenceError, NewtonSettings, RollerSet
from bearing_mbs.models.cylindrical_roller.quasistatic.sliced import (
    SlicedRollerEquilibrium,
    SlicedRollerSet,
    SlicedSolution,
    sliced_roller_equilibrium,
    sliced_state,
    solve_sliced,
)

__all__ = [
    "CircularCrown",
    "ConvergenceError",
    "Flat",
    "LogarithmicCrown",
    "NewtonSettings",
    "RadialRollerEquilibrium",
    "RadialSolution",
    "RollerSet",
    "SlicedRollerEquilibrium",
    "SlicedRollerSet",
    "SlicedSolution",
    "plot_load_distribution",
    "radial_roller_equilibrium",
    "radial_state",
    "sliced_roller_equilibrium",
    "sliced_state",
    "solve_radial",
    "solve_sliced",
]
