"""Each derived quantity of the bearing has one owner, and what reads it gets the owner's numbers.

References:
* the oil at its operating temperature: the lubricant's own correlations (:mod:`bearing_mbs.contact.lubricant`)
  at ``[lubricant] temperature``, evaluated once per build by :func:`operating_oil`; the built scene's film laws,
  drags and traction rows hold exactly those numbers;
* E* and E′: K. L. Johnson's contact modulus 1/E* = (1 − ν₁²)/E₁ + (1 − ν₂²)/E₂ and the EHL reduced modulus
  E′ = 2E*, by hand for steel on steel;
* the raceway layout: the builder's :attr:`BearingGeometry.raceways` and the layout the linearisation reads back
  from the scene's raceway pairs are the same object;
* topology roles: string constants, equal to and serialised as their text.
"""

import json

import pytest

from bearing_mbs.contact.line_contact import contact_modulus, reduced_modulus
from bearing_mbs.contact.traction import TRACTION_COLUMNS
from bearing_mbs.core.topology import Group, Role, Topology
from bearing_mbs.elements import Drag
from bearing_mbs.elements.journal_bearings import JournalFilm
from bearing_mbs.models import build_scene, load_spec
from bearing_mbs.models.cylindrical_roller.geometry import BearingGeometry
from bearing_mbs.models.cylindrical_roller.linearise import BearingLayout
from bearing_mbs.models.cylindrical_roller.operating_oil import DEFAULT_PALMGREN_VISCOSITY, operating_oil

from cases import SCENARIOS

STEADY = SCENARIOS / "seed_hss_steady.toml"
#: The lubricated steady scenario with every consumer of the oil switched on.
OILED = ["lubricant.model=churning", "lubricant.viscous_drag_factor=2", "lubricant.starvation=true",
         "lubricant.pocket_film=true", "lubricant.land_film=true", "bearing.cage_guidance=outer_land",
         "lubricant.pressure_viscosity_model=roelands"]


def test_the_operating_oil_is_the_lubricants_at_the_temperature():
    spec = load_spec(STEADY, OILED)
    lubricant, temperature = spec.lubricant.lubricant(), spec.lubricant.temperature
    oil = operating_oil(spec.lubricant)
    assert oil.density == lubricant.density(temperature)
    assert oil.kinematic_viscosity == lubricant.kinematic_viscosity(temperature)
    assert oil.dynamic_viscosity == lubricant.dynamic_viscosity(temperature)
    assert oil.pressure_viscosity == lubricant.pressure_viscosity_at(temperature)
    assert oil.temperature_viscosity == lubricant.temperature_viscosity(temperature)
    assert oil.palmgren_viscosity == oil.kinematic_viscosity


def test_every_consumer_of_the_build_reads_the_one_operating_oil():
    spec = load_spec(STEADY, OILED)
    oil = operating_oil(spec.lubricant)
    scene = build_scene(spec)
    films = [scene.pairs[int(k)] for k in scene.topology.group(Group.POCKET_FILM).ravel()]
    assert films and all(pair.law.film[1] == oil.dynamic_viscosity for pair in films)
    (land,) = scene.items_of(JournalFilm)
    assert land.viscosity == oil.dynamic_viscosity
    assert any(drag.quadratic > 0 for drag in scene.items_of(Drag))
    for group in (Group.INNER_RACE, Group.OUTER_RACE):
        law = scene.pairs[int(scene.topology.group(group)[0])].law
        if law.traction:
            row = dict(zip(TRACTION_COLUMNS, law.traction))
            assert row["viscosity"] == oil.dynamic_viscosity
            assert row["pressure_viscosity"] == oil.pressure_viscosity


def test_palmgren_takes_the_given_viscosity_or_a_default_without_an_oil():
    dry = load_spec(STEADY, ["scenario.variant=dry"])
    assert dry.lubricant.lubricant() is None or dry.lubricant.temperature is None
    given = dry.lubricant.viscosity
    assert operating_oil(dry.lubricant).palmgren_viscosity == (given if given is not None
                                                                else DEFAULT_PALMGREN_VISCOSITY)
    assert operating_oil(dry.lubricant).dynamic_viscosity is None


def test_the_contact_and_the_reduced_modulus_of_steel_on_steel():
    youngs, poisson = 208e9, 0.3
    star = youngs / (2 * (1 - poisson**2))
    assert contact_modulus(youngs, poisson, youngs, poisson) == pytest.approx(star, rel=1e-15)
    assert reduced_modulus(youngs, poisson, youngs, poisson) == 2 * contact_modulus(youngs, poisson, youngs, poisson)


def test_the_scene_holds_the_geometrys_raceway_layout():
    spec = load_spec(STEADY, ["scenario.variant=dry"])
    layout = BearingLayout.of(build_scene(spec))
    raceways = BearingGeometry.from_spec(spec.bearing).raceways
    assert layout.raceways == raceways
    assert raceways.clearance == pytest.approx(spec.bearing.clearance, abs=1e-15)
    assert raceways.pitch_diameter == pytest.approx(spec.bearing.pitch, rel=1e-15)


def test_roles_are_their_text():
    topology = Topology(bodies={Role.CAGE: [1]}, pairs={Group.INNER_RACE: [0, 2]})
    assert topology.body("cage") == topology.body(Role.CAGE) == 1
    assert json.dumps(topology.to_dict()) == '{"bodies": {"cage": [1]}, "pairs": {"inner_race": [0, 2]}}'
    assert Topology.from_dict(json.loads(json.dumps(topology.to_dict()))) == topology
