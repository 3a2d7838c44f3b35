"""The ``balls`` model: discs in a box with walls and distance constraints (the primary document's cases 1–5)."""

from bearing_mbs.models.balls.build import build_balls_scene
from bearing_mbs.models.balls.figures import balls_figures
from bearing_mbs.models.balls.metrics import UNITS, balls_metrics
from bearing_mbs.models.balls.norms import ERROR_NORMS
from bearing_mbs.models.balls.spec import BallsModelSpec
from bearing_mbs.models.protocol import Model

MODEL = Model(name="balls", spec=BallsModelSpec, build=build_balls_scene, metrics=balls_metrics,
              figures=balls_figures, units=UNITS, error_norms=ERROR_NORMS)
