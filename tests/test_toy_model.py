"""A toy model added inside the package touches only the files ``docs/guide-add-a-model.md`` lists, and works.

The test reads the guide's list of files (between its ``files a model touches`` markers), copies the package and
``pyproject.toml`` to a temporary directory, and adds a model ``toy`` (a disc thrown upwards) by writing only
those files: its package, one entry in ``models/registry.py``, the package in the import-linter contracts. Then,
in processes that import the copy:

* every file of the copy that differs from the original is one the guide lists;
* the import-linter contracts hold on the copy (so the toy's package is under the contracts);
* ``bearing-mbs run`` runs a toy scenario, and ``bearing-mbs toy-apex`` (the toy's own subcommand) answers.

Reference (closed form, independent of the code): y(t) = y₀ + v₀t − g t²/2 at the end of the run, to 1e-9 m
(RK4 integrates a quadratic exactly, whatever the step), and the apex y₀ + v₀²/(2g), to 1e-6 m for the run's
metric (sampled every 1e-3 s, about the apex: v is 0 there, so the sampled peak is within g·(5e-4 s)²/2 ≈ 1.2e-6 m;
the run ends exactly at the apex, t = v₀/g, to sample it). The runs are short and numba's compilation is off in
the copy (``NUMBA_DISABLE_JIT=1``), so the copy compiles nothing.
"""

from __future__ import annotations

import filecmp
import json
import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
GUIDE = ROOT / "docs" / "guide-add-a-model.md"
START, END = "<!-- files a model touches: start -->", "<!-- files a model touches: end -->"
G, Y0, V0 = 9.81, 1.0, 2.0

TOY_PACKAGE = {
    "__init__.py": '''"""The ``toy`` model: a disc thrown upwards (the worked example of docs/guide-add-a-model.md)."""

from bearing_mbs.models.protocol import Model
from bearing_mbs.models.toy.build import build, metrics
from bearing_mbs.models.toy.commands import COMMANDS
from bearing_mbs.models.toy.spec import ToySpec

MODEL = Model(name="toy", spec=ToySpec, build=build, metrics=metrics, figures=lambda *args: [],
              units={"apex_height": "m"}, commands=COMMANDS)
''',
    "spec.py": '''"""The toy's sections: ``[disc]``."""

from dataclasses import dataclass, field

from bearing_mbs.spec import Spec
from bearing_mbs.spec.fields import non_negative, positive


@dataclass(frozen=True)
class DiscSpec:
    """``[disc]``: mass [kg] > 0; radius [m] > 0; height [m] and upward speed [m/s] at t = 0."""

    mass: float = 1.0
    radius: float = 0.01
    height: float = 0.0
    speed: float = 0.0

    def __post_init__(self):
        positive("mass", self.mass)
        positive("radius", self.radius)
        non_negative("height", self.height)


@dataclass(frozen=True)
class ToySpec(Spec):
    disc: DiscSpec = field(default_factory=DiscSpec)
''',
    "build.py": '''"""The toy's scene (one disc under gravity) and its metric."""

from bearing_mbs.core.scene import Body, Scene
from bearing_mbs.core.topology import Topology


def build(spec) -> Scene:
    disc = spec.disc
    body = Body("disc", disc.mass, 0.5 * disc.mass * disc.radius**2, (0.0, disc.height, 0.0), (0.0, disc.speed, 0.0))
    return Scene(spec.scenario.name, (body,), gravity=(0.0, -spec.scenario.gravity),
                 topology=Topology(bodies={"disc": [0]}))


def metrics(spec, scene, result) -> dict:
    return {"apex_height": float(result.position[:, 3 * scene.topology.body("disc") + 1].max())}
''',
    "commands.py": '''"""The toy's own subcommand: ``bearing-mbs toy-apex SCENARIO --out DIR`` writes the apex."""

import json

from bearing_mbs.models.protocol import Command


def _arguments(parser, cli) -> None:
    parser.add_argument("scenario")
    cli.add_output(parser, "output directory: apex.json")
    cli.add_overrides(parser)


def _apex(args, cli) -> int:
    spec = cli.services.load_spec(args.scenario, args.set)
    apex = spec.disc.height + spec.disc.speed**2 / (2 * spec.scenario.gravity)
    (cli.output_directory(args) / "apex.json").write_text(json.dumps({"apex_height": apex}))
    return cli.exit_code("success")


COMMANDS = (Command("toy-apex", "the apex of the thrown disc (closed form)", _arguments, _apex),)
''',
}

SCENARIO = f"""
[scenario]
name = "toy"
model = "toy"
end_time = {V0 / G!r}
gravity = {G}

[solver]
engine = "reference"
output_interval = 1e-3

[solver.reference]
method = "rk4"
step = 1e-3

[disc]
mass = 0.2
radius = 0.02
height = {Y0}
speed = {V0}
"""


def listed_files() -> list[str]:
    """The guide's list of the files a model touches, with ``<name>`` as ``toy``; a folder ends with ``/``."""
    text = GUIDE.read_text()
    assert START in text and END in text, f"{GUIDE.name} has no list between {START!r} and {END!r}"
    block = text[text.index(START) + len(START):text.index(END)]
    return [path.replace("<name>", "toy") for path in re.findall(r"^- `([^`]+)`", block, flags=re.MULTILINE)]


def is_listed(path: str, listed: list[str]) -> bool:
    return any(path.startswith(item) if item.endswith("/") else path == item for item in listed)


def write_listed(copy: Path, relative: str, text: str, listed: list[str]) -> None:
    """Write a file of the copy, refusing any the guide does not list."""
    assert is_listed(relative, listed), f"the toy model would touch {relative}, which the guide does not list"
    path = copy / relative
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(text)


def add_toy_model(copy: Path, listed: list[str]) -> None:
    for name, text in TOY_PACKAGE.items():
        write_listed(copy, f"bearing_mbs/models/toy/{name}", text, listed)
    registry = (copy / "bearing_mbs/models/registry.py").read_text()
    registry = registry.replace("from bearing_mbs.models.slewing_bearing import MODEL as SLEWING_BEARING\n",
                                "from bearing_mbs.models.slewing_bearing import MODEL as SLEWING_BEARING\n"
                                "from bearing_mbs.models.toy import MODEL as TOY\n")
    registry, entries = re.subn(r"(MODELS = ModelRegistry\(\([^)]*)\)\)", r"\1, TOY))", registry)
    assert entries == 1, "models/registry.py no longer lists its models as MODELS = ModelRegistry((...))"
    write_listed(copy, "bearing_mbs/models/registry.py", registry, listed)
    project = (copy / "pyproject.toml").read_text()
    project, contracts = re.subn(r'"bearing_mbs\.models\.rotor"\]',
                                 '"bearing_mbs.models.rotor", "bearing_mbs.models.toy"]', project)
    assert contracts == 2, "pyproject.toml should name the model packages in two import-linter contracts"
    write_listed(copy, "pyproject.toml", project, listed)


def changed_files(original: Path, copy: Path) -> list[str]:
    """Files of the copy's package and pyproject.toml that are new or differ from the original's."""
    changed = [] if filecmp.cmp(original / "pyproject.toml", copy / "pyproject.toml", shallow=False) \
        else ["pyproject.toml"]
    for path in sorted((copy / "bearing_mbs").rglob("*.py")):
        relative = path.relative_to(copy)
        source = original / relative
        if not source.exists() or not filecmp.cmp(source, path, shallow=False):
            changed.append(relative.as_posix())
    return changed


@pytest.fixture(scope="module")
def copy_with_toy(tmp_path_factory) -> Path:
    copy = tmp_path_factory.mktemp("toy_model")
    shutil.copytree(ROOT / "bearing_mbs", copy / "bearing_mbs", ignore=shutil.ignore_patterns("__pycache__"))
    shutil.copy2(ROOT / "pyproject.toml", copy / "pyproject.toml")
    add_toy_model(copy, listed_files())
    return copy


def in_copy(copy: Path, *arguments: str) -> subprocess.CompletedProcess:
    environment = {**os.environ, "PYTHONPATH": str(copy), "NUMBA_DISABLE_JIT": "1"}
    return subprocess.run(arguments, cwd=copy, env=environment, capture_output=True, text=True, timeout=300,
                          check=False)


def test_the_guide_lists_the_package_the_registry_and_the_contracts():
    listed = listed_files()
    assert {"bearing_mbs/models/toy/", "bearing_mbs/models/registry.py", "pyproject.toml"} <= set(listed), listed


def test_the_toy_model_touches_only_the_files_the_guide_lists(copy_with_toy):
    changed = changed_files(ROOT, copy_with_toy)
    listed = listed_files()
    assert changed, "the toy model changed nothing"
    assert [path for path in changed if not is_listed(path, listed)] == []


def test_the_contracts_hold_with_the_toy_model_under_them(copy_with_toy):
    linter = Path(sys.executable).with_name("lint-imports")
    run = in_copy(copy_with_toy, str(linter), "--config", str(copy_with_toy / "pyproject.toml"))
    assert run.returncode == 0, run.stdout[-4000:]
    project = (copy_with_toy / "pyproject.toml").read_text()
    assert project.count('"bearing_mbs.models.toy"') == 2


def test_the_toy_model_runs_and_offers_its_command_through_the_command_line(copy_with_toy, tmp_path):
    scenario = tmp_path / "toy.toml"
    scenario.write_text(SCENARIO)
    run = in_copy(copy_with_toy, sys.executable, "-m", "bearing_mbs.cli", "run", str(scenario), "--out",
                  str(tmp_path / "run"), "--quiet", "--no-figures")
    assert run.returncode == 0, run.stderr[-4000:]
    summary = json.loads((tmp_path / "run" / "summary.json").read_text())
    assert summary["status"] == "success" and summary["scene"]["bodies"] == 1
    assert summary["apex_height"] == pytest.approx(Y0 + V0**2 / (2 * G), abs=1e-6)
    import numpy as np

    result = np.load(tmp_path / "run" / "result.npz")
    t, y = float(result["time"][-1]), float(result["position"][-1, 1])
    assert y == pytest.approx(Y0 + V0 * t - 0.5 * G * t**2, abs=1e-9)

    command = in_copy(copy_with_toy, sys.executable, "-m", "bearing_mbs.cli", "toy-apex", str(scenario), "--out",
                      str(tmp_path / "apex"))
    assert command.returncode == 0, command.stderr[-4000:]
    apex = json.loads((tmp_path / "apex" / "apex.json").read_text())["apex_height"]
    assert apex == pytest.approx(Y0 + V0**2 / (2 * G), rel=1e-12)
