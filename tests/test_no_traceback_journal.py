"""Property: ``bearing-mbs journal`` on any valid journal-bearing scenario runs to a status or refuses the input by
name, never a traceback (tests/no_traceback.py says what is checked).

Drawn over the documented range of every key (docs/scenario-format.md, "Journal-bearing scenarios", and
bearing_mbs/models/journal_bearing/spec.py): the bore's diameter and length, the radial clearance up to D/2, the
viscosity and density, speeds from −1e6 to 1e6 rpm (0: hydrostatic), ε in [0, 1) up to 1 − 1e-9, any attitude,
both cavitation models, plain journals and recessed ones of 1 to 12 recesses with every restrictor (a
capillary's or orifice's bore given, or sized for a design pressure ratio); the oil by its viscosity, or now and
then by its viscosity-temperature line ([journal.oil]) at its inlet or effective temperature; now and then the
coefficients over one or two speeds under a static load. The grid is
drawn small (4 to 40 cells around, 4 to 16 along: each solve then takes milliseconds); coarse grids are valid input.
"""

from __future__ import annotations

from hypothesis import example, given
from hypothesis import strategies as st

from bearing_mbs.fluid_film.restrictors import CAPILLARY_MIN_ASPECT

from no_traceback import log_uniform, profile, run_command, uniform

SPEED_LIMIT_RPM = 1e6  # journal.speed_rpm in [-1e6, 1e6]


@st.composite
def recesses(draw, length: float, grid: list[int], source: bool) -> dict:
    """A [journal.recesses] table; mostly resolved by the grid (a cell centre in each recess: else refused), with an
    oil source when ``source`` (else the mass-conserving film is refused)."""
    count = draw(st.integers(1, 12))
    widest = 360.0 if count == 1 else 360.0 / count
    cell_angle, cell_length = 360.0 / grid[0], length / grid[1]
    resolved = draw(st.integers(0, 9)) > 0 and widest > 2 * cell_angle and length > 2 * cell_length
    table = {"count": count,
             "angular_width": draw(uniform(2 * cell_angle, widest, high_open=count > 1) if resolved
                                   else uniform(0.0, widest, low_open=True, high_open=count > 1)),
             "axial_length": draw(uniform(2 * cell_length, length) if resolved
                                  else uniform(0.0, length, low_open=True)),
             "depth": draw(log_uniform(1e-7, 1e-1)),
             "supply_pressure": draw(log_uniform(1e3, 1e8) if source else st.one_of(st.just(0.0),
                                                                                    log_uniform(1e3, 1e8))),
             "first_angle": draw(uniform(-360.0, 360.0))}
    restrictor = draw(st.sampled_from(["capillary", "orifice", "constant_flow", "none"]))
    table["restrictor"] = restrictor
    if restrictor == "capillary":
        diameter = draw(log_uniform(1e-5, 1e-2))
        table.update(capillary_diameter=diameter,
                     capillary_length=diameter * CAPILLARY_MIN_ASPECT * draw(log_uniform(1.0, 100.0)))
    elif restrictor == "orifice":
        table.update(orifice_diameter=draw(log_uniform(1e-5, 1e-2)),
                     discharge_coefficient=draw(uniform(0.0, 1.0, low_open=True)))
    elif restrictor == "constant_flow":
        table["flow"] = draw(log_uniform(1e-10, 1e-2))
    if restrictor in ("capillary", "orifice") and draw(st.integers(0, 3)) == 0:  # the bore sized for a ratio instead
        del table[f"{restrictor}_diameter"]
        table["design_pressure_ratio"] = draw(uniform(0.0, 1.0, low_open=True, high_open=True))
    return table


@st.composite
def journal_scenarios(draw) -> dict:
    diameter = draw(log_uniform(1e-3, 2.0))
    length = diameter * draw(log_uniform(1e-2, 1e2))
    grid = [draw(st.integers(4, 40)), draw(st.integers(4, 16))]
    cavitation = draw(st.sampled_from(["gumbel", "jfo"]))
    journal = {
        "diameter": diameter, "length": length,
        "radial_clearance": diameter * draw(uniform(0.0, 0.5, low_open=True, high_open=True, margin=1e-6)
                                            | log_uniform(1e-5, 1e-2)),
        "viscosity": draw(log_uniform(1e-6, 10.0)),
        "density": draw(log_uniform(1.0, 2e4)),
        "speed_rpm": draw(st.one_of(st.just(0.0), uniform(-SPEED_LIMIT_RPM, SPEED_LIMIT_RPM),
                                    log_uniform(1.0, SPEED_LIMIT_RPM))),
        "eccentricity_ratio": draw(st.one_of(uniform(0.0, 1.0, high_open=True),
                                             st.sampled_from([0.0, 0.9, 0.99, 0.999, 1 - 1e-6]))),
        "attitude": draw(uniform(-360.0, 360.0)),
        "cavitation": cavitation,
        "grid": grid,
    }
    # the mass-conserving film needs an oil source: mostly drawn with one (without, it is refused by name)
    if draw(st.booleans()) or (cavitation == "jfo" and draw(st.integers(0, 9)) > 0):
        journal["recesses"] = draw(recesses(length, grid, source=cavitation == "jfo" and draw(st.integers(0, 9)) > 0))
    if draw(st.integers(0, 19)) == 0:  # the coefficients over speed under a static load (now and then: slow)
        journal["coefficient_speeds_rpm"] = draw(st.lists(uniform(-SPEED_LIMIT_RPM, SPEED_LIMIT_RPM), min_size=1,
                                                          max_size=2))
        journal["static_load"] = [draw(uniform(-1e6, 1e6)), draw(st.one_of(st.just(0.0), uniform(-1e6, 1e6)))]
    if draw(st.integers(0, 3)) == 0:  # the oil by its viscosity-temperature line instead, now and then thermal
        del journal["viscosity"], journal["density"]
        viscosity_40 = draw(log_uniform(2e-6, 1e-2))
        journal["oil"] = {"viscosity_40": viscosity_40,
                          "viscosity_100": viscosity_40 * draw(log_uniform(0.01, 0.999)),
                          "density_15": draw(uniform(600.0, 1200.0)), "specific_heat": draw(log_uniform(1e2, 1e4)),
                          "inlet_temperature": draw(uniform(-10.0, 120.0))}
        journal["thermal"] = draw(st.sampled_from(["isothermal", "effective"]))
    return {"scenario": {"name": "drawn_journal", "model": "journal_bearing", "end_time": 1.0}, "journal": journal}


#: The seed's journal (document 001, Table 2), coarse.
SEED = {"diameter": 0.075, "length": 0.075, "radial_clearance": 35e-6, "speed_rpm": 1000.0, "viscosity": 0.028,
        "density": 860.0, "eccentricity_ratio": 0.25, "attitude": 0.0, "cavitation": "gumbel", "grid": [24, 8],
        "recesses": {"count": 4, "angular_width": 45.0, "axial_length": 0.06, "depth": 1e-3, "first_angle": 0.0,
                     "supply_pressure": 1e6, "restrictor": "capillary", "capillary_length": 0.02,
                     "capillary_diameter": 0.6e-3}}


def scenario(**journal) -> dict:
    return {"scenario": {"name": "example", "model": "journal_bearing", "end_time": 1.0},
            "journal": {**SEED, **journal}}


#: Examples in the default run: a journal example costs about 0.3 s (a film solve, often its stiffness and a
#: transient; about 7 % run to the 1 s watchdog), three times a bearing example, so it takes half the others' 300 to
#: keep `make test` within its budget; the search profile (no_traceback.py) draws thousands.
EXAMPLES = 150


@profile(EXAMPLES)
@given(journal_scenarios())
# issue 25: the stiffness's finite-difference step crossed the clearance at ε = 0.999 (a ValueError, and an empty
# output folder)
@example(scenario(eccentricity_ratio=0.999))
def test_journal_runs_to_a_status_or_refuses_by_name(drawn):
    run_command("journal", drawn)
