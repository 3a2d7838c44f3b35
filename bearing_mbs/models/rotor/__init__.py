"""The ``rotor`` model: a rigid rotor in its cylindrical mode on identical fluid-film journal bearings
(:mod:`bearing_mbs.fluid_film` through the ``journal_bearings`` force element), driven by a velocity servo, with an
optional unbalance: spin-up, unbalance response and oil whirl (docs/fluid-film.md)."""

from bearing_mbs.models.protocol import Model
from bearing_mbs.models.rotor.build import build_rotor_scene
from bearing_mbs.models.rotor.metrics import UNITS, rotor_figures, rotor_metrics, rotor_warnings
from bearing_mbs.models.rotor.spec import MODEL_NAME, RotorSpec

MODEL = Model(name=MODEL_NAME, spec=RotorSpec, build=build_rotor_scene, metrics=rotor_metrics, figures=rotor_figures,
              units=UNITS, warnings=rotor_warnings)
