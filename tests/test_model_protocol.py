"""The layers above the models ask the model record, never the model's name or package.

* no module outside ``bearing_mbs/models/`` spells a registered model's name (the import-linter contract
  "Nothing outside models/ imports a model's package" covers the imports, tests/test_layers.py);
* the command line offers every model's own subcommands;
* a study that needs a part of the record a model lacks refuses its scenario before anything runs, naming the
  field: a norm it does not have (convergence), stability cases (stability), an animation (``run --animate``),
  a settling check or a steady balance (the sensitivity evaluators). The balls model has none of these.
"""

from __future__ import annotations

import ast
from pathlib import Path

import pytest

from bearing_mbs.cli import main
from bearing_mbs.core.topology import Role
from bearing_mbs.models import MODELS, load_spec
from bearing_mbs.spec import SpecError
from bearing_mbs.studies import convergence, stability
from bearing_mbs.studies.sensitivity.models import SkiddingBalanceModel, SteadyRunModel

from cases import SCENARIOS

PACKAGE = Path(__file__).resolve().parents[1] / "bearing_mbs"
BALLS = SCENARIOS / "seed_case5.toml"


#: Body roles that share a model's name ("balls", "rotor"): the topology's vocabulary, not a model's name.
ROLES = PACKAGE / "core" / "topology.py"


def test_no_module_outside_models_spells_a_model_name():
    found = []
    for path in sorted(PACKAGE.rglob("*.py")):
        if path.relative_to(PACKAGE).parts[0] == "models":
            continue
        for node in ast.walk(ast.parse(path.read_text())):
            if isinstance(node, ast.Constant) and node.value in MODELS and not (
                    path == ROLES and node.value in set(Role)):
                found.append(f"{path.relative_to(PACKAGE)}:{node.lineno}: {node.value!r}")
    assert found == []


@pytest.mark.parametrize("name", [command.name for model in MODELS.values() for command in model.commands])
def test_the_command_line_offers_every_models_commands(name, capsys):
    with pytest.raises(SystemExit) as exit_:
        main([name, "--help"])
    assert exit_.value.code == 0 and f"usage: bearing-mbs {name}" in capsys.readouterr().out


def test_a_norm_the_model_does_not_have_is_refused(tmp_path):
    spec = load_spec(BALLS, ["convergence.norm=cage_speed"])
    with pytest.raises(SpecError) as error:
        convergence.study(spec, tmp_path)
    assert error.value.field == "convergence.norm"


def test_the_stability_suite_needs_a_model_with_cases(tmp_path):
    with pytest.raises(SpecError) as error:
        stability.study(load_spec(BALLS), tmp_path)
    assert error.value.field == "scenario.model" and error.value.value == "balls"


def test_an_animation_needs_a_model_that_draws_one(tmp_path):
    assert main(["run", str(BALLS), "--out", str(tmp_path / "out"), "--animate", "--quiet"]) == 2
    assert not (tmp_path / "out").exists()


@pytest.mark.parametrize("evaluator", [SteadyRunModel, SkiddingBalanceModel])
def test_the_sensitivity_evaluators_need_the_models_part(evaluator):
    with pytest.raises(SpecError) as error:
        evaluator(str(BALLS))
    assert error.value.field == "scenario.model" and error.value.value == "balls"
