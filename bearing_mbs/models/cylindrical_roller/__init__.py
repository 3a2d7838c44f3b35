"""The ``bearing`` model: the planar caged cylindrical roller bearing of the primary document, with its
geometry, builder, skidding metrics, figures, quasi-static solver and linearisation."""

from bearing_mbs.models.cylindrical_roller.build import build_bearing_scene
from bearing_mbs.models.cylindrical_roller.figures import bearing_figures
from bearing_mbs.models.cylindrical_roller.linearise import linearise
from bearing_mbs.models.cylindrical_roller.metrics import UNITS, bearing_metrics, bearing_warnings
from bearing_mbs.models.cylindrical_roller.spec import BearingModelSpec, with_preset
from bearing_mbs.models.protocol import Model

MODEL = Model(name="bearing", spec=BearingModelSpec, prepare=with_preset, build=build_bearing_scene,
              metrics=bearing_metrics, figures=bearing_figures, linearise=linearise, units=UNITS,
              warnings=bearing_warnings)
