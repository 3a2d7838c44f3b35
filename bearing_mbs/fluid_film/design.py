r"""Restrictors sized for a design pressure ratio β = p_r/p_s of the centred bearing.

A hydrostatic bearing's stiffness depends on how its restrictors share the supply pressure with the film: the
classical design point is β = p_r/p_s = 0.5 for capillaries (the stiffness of a capillary-compensated pad is
largest there: W. B. Rowe, *Hydrostatic, Aerostatic and Hybrid Bearing Design*, Butterworth-Heinemann 2012, ch. 4),
and document 001 sizes its capillaries for a 0.5 MPa drop at 1 MPa. With the journal centred the film is linear in
the recess pressure (h is uniform: no hydrodynamic pressure at any speed), so one solve of the film with the recesses
held at β p_s gives each recess's outflow q, and the restrictor that passes q at the drop (1 − β) p_s holds the
recess at β p_s exactly.
"""

from __future__ import annotations

from bearing_mbs.fluid_film.journal import FilmGrid, JournalBearing
from bearing_mbs.fluid_film.restrictors import Capillary, DirectSupply, Orifice, capillary_bore
from bearing_mbs.fluid_film.reynolds import JournalState, Supply, solve_film


def recess_outflow(bearing: JournalBearing, recess_pressure: float, grid: FilmGrid | tuple[int, int]) -> float:
    """The largest recess outflow [m³/s] of the centred bearing with every recess held at ``recess_pressure``
    [Pa] (equal by symmetry for evenly spaced recesses, to the grid's resolution)."""
    film = solve_film(bearing, JournalState(), Supply(recess_pressure, DirectSupply()), grid)
    return float(film.supply_flows.max())


def sized_capillary_bore(bearing: JournalBearing, supply_pressure: float, ratio: float, length: float,
                         grid: FilmGrid | tuple[int, int], entrance_loss: float = 0.0) -> float:
    """The bore [m] of the capillary of this ``length`` [m] (and ``entrance_loss``) that holds the centred recesses
    at ``ratio`` × ``supply_pressure`` (before a :class:`Capillary` checks that it is long enough for it)."""
    return capillary_bore(length, recess_outflow(bearing, ratio * supply_pressure, grid), (1 - ratio) * supply_pressure,
                          bearing.viscosity, bearing.density, entrance_loss)


def sized_capillary(bearing: JournalBearing, supply_pressure: float, ratio: float, length: float,
                    grid: FilmGrid | tuple[int, int], entrance_loss: float = 0.0) -> Capillary:
    """The capillary of this ``length`` [m] (and ``entrance_loss``) that holds the centred recesses at ``ratio`` ×
    ``supply_pressure``."""
    return Capillary(length, sized_capillary_bore(bearing, supply_pressure, ratio, length, grid, entrance_loss),
                     entrance_loss)


def sized_orifice(bearing: JournalBearing, supply_pressure: float, ratio: float, discharge_coefficient: float,
                  grid: FilmGrid | tuple[int, int]) -> Orifice:
    """The orifice (of this discharge coefficient) that holds the centred recesses at ``ratio`` × ``supply_pressure``."""
    return Orifice.passing(recess_outflow(bearing, ratio * supply_pressure, grid), (1 - ratio) * supply_pressure,
                           bearing.density, discharge_coefficient)
