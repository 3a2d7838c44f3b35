"""The ``journal_bearing`` model (document 001): hydrostatic, hydrodynamic and hybrid journal bearings, solved
statically by ``bearing-mbs journal`` (:mod:`.static`) on the fluid-film library :mod:`bearing_mbs.fluid_film`.
A scenario of this model has no run of its own: a rotor on journal bearings is the ``rotor`` model."""

from bearing_mbs.models.journal_bearing.commands import COMMANDS
from bearing_mbs.models.journal_bearing.spec import MODEL_NAME, JournalSpec
from bearing_mbs.models.protocol import Model
from bearing_mbs.spec import SpecError


def _no_run(spec):
    raise SpecError("scenario.model", spec.scenario.model, "a static journal bearing: `bearing-mbs journal` solves it "
                                                           "(a run needs a model with bodies)")


MODEL = Model(name=MODEL_NAME, spec=JournalSpec, build=_no_run, metrics=lambda spec, scene, result: {},
              figures=lambda spec, scene, result, directory: [], commands=COMMANDS)
