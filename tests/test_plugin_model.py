"""A second, trivial model registered from outside the package runs through the command line on both engines,
with no edit to any engine, the spec package or the runner (the worked example of ``docs/guide-add-a-model.md``).

The toy model is a disc thrown upwards under gravity. Reference (closed form, independent of the code under
test): y(t) = y₀ + v₀t − g t²/2, to 1e-9 m at the end of the run; its ``apex_height`` metric must equal
y₀ + v₀²/(2g) to 1e-6 m.
"""

from __future__ import annotations

import json
from dataclasses import dataclass, field

import pytest

from bearing_mbs.cli import main
from bearing_mbs.core.scene import Body, Scene
from bearing_mbs.core.topology import Topology
from bearing_mbs.models import MODELS, Model, load_spec
from bearing_mbs.spec import Spec, SpecError
from bearing_mbs.spec.fields import non_negative, positive


@dataclass(frozen=True)
class DiscSpec:
    """``[disc]``: mass [kg] > 0; radius [m] > 0; height [m] and upward speed [m/s] at t = 0."""

    mass: float
    radius: float
    height: float = 0.0
    speed: float = 0.0

    def __post_init__(self):
        positive("mass", self.mass)
        positive("radius", self.radius)
        non_negative("height", self.height)


@dataclass(frozen=True)
class ThrowSpec(Spec):
    """A ``throw`` scenario: the shared sections plus ``[disc]``."""

    disc: DiscSpec = field(default_factory=lambda: DiscSpec(mass=1.0, radius=0.01))


def build(spec: ThrowSpec) -> Scene:
    disc = spec.disc
    body = Body("disc", disc.mass, 0.5 * disc.mass * disc.radius**2, (0.0, disc.height, 0.0), (0.0, disc.speed, 0.0))
    return Scene(spec.scenario.name, (body,), gravity=(0.0, -spec.scenario.gravity),
                 topology=Topology(bodies={"disc": [0]}))


def metrics(spec, scene, result) -> dict:
    disc = scene.topology.body("disc")
    return {"apex_height": float(result.position[:, 3 * disc + 1].max())}


THROW = Model(name="throw", spec=ThrowSpec, build=build, metrics=metrics, figures=lambda *args: [])

SCENARIO = """
[scenario]
name = "throw"
model = "throw"
end_time = 0.4
gravity = 9.81

[solver]
engine = "{engine}"
output_interval = 1e-4

[solver.reference]
method = "rk4"
step = 1e-4

[solver.exudyn]
method = "rk4"
step = 1e-4

[disc]
mass = 0.2
radius = 0.02
height = 1.0
speed = 2.0
"""


@pytest.fixture
def registered():
    MODELS.register(THROW)
    yield
    MODELS.unregister(THROW.name)


@pytest.mark.parametrize("engine", ["reference", "exudyn"])
def test_a_registered_model_runs_from_the_command_line(registered, engine, tmp_path):
    path = tmp_path / "throw.toml"
    path.write_text(SCENARIO.format(engine=engine))
    assert main(["run", str(path), "--out", str(tmp_path / "out"), "--quiet"]) == 0
    summary = json.loads((tmp_path / "out" / "summary.json").read_text())
    g, y0, v0 = 9.81, 1.0, 2.0
    assert summary["status"] == "success" and summary["scene"]["bodies"] == 1
    assert summary["apex_height"] == pytest.approx(y0 + v0**2 / (2 * g), abs=1e-6)
    from bearing_mbs.core.result import Result

    result = Result.load(tmp_path / "out" / "result.npz")
    t = result.time[-1]
    assert result.position[-1, 1] == pytest.approx(y0 + v0 * t - 0.5 * g * t**2, abs=1e-9)
    assert result.topology.body("disc") == 0


def test_its_sections_are_validated_like_the_packaged_models(registered, tmp_path):
    path = tmp_path / "throw.toml"
    path.write_text(SCENARIO.format(engine="reference").replace("mass = 0.2", "mass = -0.2"))
    with pytest.raises(SpecError) as error:
        load_spec(path)
    assert error.value.field == "disc.mass" and error.value.value == -0.2


def test_an_unregistered_model_is_refused_before_anything_runs(tmp_path):
    path = tmp_path / "throw.toml"
    path.write_text(SCENARIO.format(engine="reference"))
    with pytest.raises(SpecError) as error:
        load_spec(path)
    assert error.value.field == "scenario.model" and error.value.value == "throw"
