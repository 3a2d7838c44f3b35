"""The ``cylindrical_roller`` model: the planar caged cylindrical roller bearing of the primary document, with its
geometry, builder, skidding metrics, figures, quasi-static solver and linearisation, and its own studies and
subcommands (:mod:`.studies`: stiffness, static check, skidding sweep and map, cage models; its norms for a
work–precision study, its stability cases, its settling check and steady skidding balance; its measured
work–precision tables, :mod:`.work_precision`)."""

from bearing_mbs.models.cylindrical_roller.build import build_bearing_scene
from bearing_mbs.models.cylindrical_roller.figures import animate, bearing_figures
from bearing_mbs.models.cylindrical_roller.linearise import linearise
from bearing_mbs.models.cylindrical_roller.metrics import UNITS, bearing_metrics, bearing_warnings
from bearing_mbs.models.cylindrical_roller.name import MODEL_NAME
from bearing_mbs.models.cylindrical_roller.spec import BearingModelSpec, with_preset
from bearing_mbs.models.cylindrical_roller.studies.balance import STEADY_BALANCE
from bearing_mbs.models.cylindrical_roller.studies.commands import COMMANDS
from bearing_mbs.models.cylindrical_roller.studies.convergence_norms import ERROR_NORMS
from bearing_mbs.models.cylindrical_roller.studies.settling import window_settled
from bearing_mbs.models.cylindrical_roller.studies.stability_cases import STABILITY
from bearing_mbs.models.cylindrical_roller.work_precision import WORK_PRECISION
from bearing_mbs.models.protocol import Model

MODEL = Model(name=MODEL_NAME, spec=BearingModelSpec, prepare=with_preset, build=build_bearing_scene,
              metrics=bearing_metrics, figures=bearing_figures, linearise=linearise, units=UNITS,
              warnings=bearing_warnings, animate=animate, commands=COMMANDS, error_norms=ERROR_NORMS,
              stability=STABILITY, settling_check=window_settled, steady_balance=STEADY_BALANCE,
              work_precision=WORK_PRECISION)
