"""The ``slewing_bearing`` model (document 002): four-point-contact ball slewing bearings of wind turbines.

The condensed ring-stiffness parametrisation (:mod:`.ring_stiffness`), the quasi-static load distribution with
rigid or flexible rings (:mod:`.load_distribution`, :mod:`.flexible`; ``bearing-mbs slewing``: :mod:`.static`,
:mod:`.figures`), and the blade-pitch run (:mod:`.pitch`, ``bearing-mbs run``) on the slewing-bearing force
element.
"""

from bearing_mbs.models.protocol import Model
from bearing_mbs.models.slewing_bearing.commands import COMMANDS
from bearing_mbs.models.slewing_bearing.pitch import PITCH_UNITS, build_pitch_scene, pitch_figures, pitch_metrics
from bearing_mbs.models.slewing_bearing.spec import MODEL_NAME, SlewingSpec

MODEL = Model(name=MODEL_NAME, spec=SlewingSpec, build=build_pitch_scene, metrics=pitch_metrics,
              figures=pitch_figures, units=PITCH_UNITS, commands=COMMANDS)
