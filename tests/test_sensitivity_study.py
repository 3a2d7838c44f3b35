"""Study files, sampling and run keys (no cluster): bad input fails with a SpecError that names the field,
before anything runs; designs are SALib's, reproducible from the seed; run keys are content hashes."""

import math
import re
import textwrap
from pathlib import Path

import numpy as np
import pytest

from bearing_mbs.spec import SpecError
from bearing_mbs.studies.sensitivity import (
    IshigamiModel,
    Method,
    Parameter,
    Study,
    ishigami_indices,
    load_study,
    plan,
    run_key,
    sample,
)
from bearing_mbs.studies.sensitivity.sampling import grid_values

ROOT = Path(__file__).resolve().parents[1]
SHIPPED = ROOT / "scenarios" / "study_drop_morris.toml"
SEED_CASE2 = ROOT / "scenarios" / "seed_case2.toml"


def write_study(tmp_path, method: str, parameters: str, study: str = "", execution: str = "") -> Path:
    """A study of seed_case2 with the given [method] and [[parameters]] bodies."""
    text = f"""
    [study]
    name = "t"
    scenario = "{SEED_CASE2}"
    overrides = ["solver.reference.method=velocity_verlet", "solver.reference.step=1e-5"]
    outputs = ["restitution_effective", "max_penetration"]
    {study or 'seed = 3'}
    [method]
    {method}
    {execution}
    """
    path = tmp_path / "study.toml"
    path.write_text(textwrap.dedent(text) + "\n" + textwrap.dedent(parameters))
    return path


RESTITUTION = """
[[parameters]]
name = "contact.wall.restitution"
bounds = [0.5, 0.95]
"""


def test_shipped_study_loads_and_samples_a_morris_design():
    study = load_study(SHIPPED)
    D = len(study.parameters)
    X = sample(study)
    assert X.shape == (study.method.samples * (D + 1), D)
    for j, p in enumerate(study.parameters):
        assert X[:, j].min() >= p.bounds[0] and X[:, j].max() <= p.bounds[1]
    np.testing.assert_array_equal(X, sample(study))  # the seed makes it reproducible
    other = load_study(SHIPPED, ["study.seed=4"])
    assert not np.array_equal(X, sample(other))
    keys, runs = plan(study, X)
    assert len(keys) == len(X) and len(runs) <= len(X)  # Morris trajectories may share points: one run each


@pytest.mark.parametrize("path", sorted((ROOT / "scenarios").glob("study_*.toml")), ids=lambda path: path.stem)
def test_every_shipped_study_validates_and_its_design_points_are_valid_inputs(path):
    """Each shipped study file parses and validates, its design has the sampler's size within the bounds, and every
    design point is a valid input of its evaluator (plan validates them all), without running anything."""
    study = load_study(path)
    D, N = len(study.parameters), study.method.samples
    X = sample(study)
    size = {"morris": N * (D + 1), "sobol": N * (2 * D + 2 if study.method.second_order else D + 2)}
    assert X.shape == (size[study.method.sampler], D)
    for j, p in enumerate(study.parameters):
        assert X[:, j].min() >= p.bounds[0] and X[:, j].max() <= p.bounds[1]
    keys, runs = plan(study, X)
    assert len(keys) == len(X) and set(keys) == set(runs)
    assert set(study.outputs) <= set(study.model.outputs())


@pytest.mark.parametrize(
    "method, parameters, field, message",
    [
        ('sampler = "morris"\nsamples = 4', RESTITUTION.replace("restitution", "restitutio"),
         "parameters.0.name", "unknown key"),
        ('sampler = "morris"\nsamples = 4', RESTITUTION.replace("contact.wall.restitution", "contact.wall"),
         "parameters.0.name", "must be a table"),
        ('sampler = "morris"\nsamples = 4', RESTITUTION.replace("contact.wall.restitution", "balls.3.mass"),
         "parameters.0.name", "index"),
        ('sampler = "morris"\nsamples = 4', RESTITUTION.replace("[0.5, 0.95]", "[0.5, 1.5]"),
         "parameters.0.name", "must be in (0, 1]"),
        ('sampler = "morris"\nsamples = 4', RESTITUTION.replace("[0.5, 0.95]", "[]"),
         "parameters.0.bounds", "array of 2 values"),
        ('sampler = "morris"\nsamples = 4', RESTITUTION.replace("[0.5, 0.95]", "[0.95, 0.5]"),
         "parameters.0.bounds", "low < high"),
        ('sampler = "morris"\nsamples = 4', RESTITUTION.replace("[0.5, 0.95]", "[0.5, 0.5]"),
         "parameters.0.bounds", "low < high"),
        ('sampler = "morris"\nsamples = 4', RESTITUTION.replace("[0.5, 0.95]", "[0.5, inf]"),
         "parameters.0.bounds.1", "finite"),
        ('sampler = "morris"\nsamples = 4', RESTITUTION.replace("bounds = [0.5, 0.95]", "values = [0.5, 0.9]"),
         "parameters.0.values", "needs bounds"),
        ('sampler = "grid"', RESTITUTION, "parameters.0.values", "levels"),
        ('sampler = "latin"\nanalyzer = "sobol"\nsamples = 8', RESTITUTION, "method.analyzer",
         "does not match the latin sampling"),
        ('sampler = "sobol"\nanalyzer = "morris"\nsamples = 8', RESTITUTION, "method.analyzer", "does not match"),
        ('sampler = "sobol"\nsamples = 10', RESTITUTION, "method.samples", "power of 2"),
        ('sampler = "sobol"\nsamples = 8\nlevels = 4', RESTITUTION, "method.levels", "only the grid and morris"),
        ('sampler = "morris"\nsamples = 4\nlevels = 3', RESTITUTION, "method.levels", "even"),
        ('sampler = "morris"', RESTITUTION, "method.samples", "needs it"),
        ('sampler = "halton"\nsamples = 4', RESTITUTION, "method.sampler", "must be one of"),
        ('sampler = "morris"\nsamples = 4\ntrajectories = 4', RESTITUTION, "method.trajectories", "unknown key"),
        ('sampler = "morris"\nsamples = 4', RESTITUTION.replace("bounds", "distribution = 'triang'\nbounds"),
         "parameters.0.peak", "needs it"),
        ('sampler = "morris"\nsamples = 4', RESTITUTION.replace("[0.5, 0.95]", "[-1.0, 0.95]\ndistribution = 'logunif'"),
         "parameters.0.bounds", "> 0"),
    ],
)
def test_bad_input_is_a_spec_error_naming_the_field(tmp_path, method, parameters, field, message):
    with pytest.raises(SpecError) as caught:
        load_study(write_study(tmp_path, method, parameters))
    assert caught.value.field == field, str(caught.value)
    assert message in caught.value.allowed  # what is allowed, not how it is worded around it


def test_seed_and_model_choice_are_checked(tmp_path):
    with pytest.raises(SpecError) as error:
        load_study(write_study(tmp_path, 'sampler = "latin"\nsamples = 4', RESTITUTION, study="# no seed"))
    assert error.value.field == "study.seed" and error.value.value is None
    path = write_study(tmp_path, 'sampler = "latin"\nsamples = 4', RESTITUTION, study='seed = 1\nmodel = "ishigami"')
    with pytest.raises(SpecError) as error:
        load_study(path)
    assert error.value.field == "study.scenario"
    with pytest.raises(SpecError) as error:
        load_study(tmp_path / "missing.toml")
    assert error.value.value == str(tmp_path / "missing.toml")
    bad_base = write_study(tmp_path, 'sampler = "latin"\nsamples = 4', RESTITUTION)
    bad_base.write_text(bad_base.read_text().replace("step=1e-5", "stepp=1e-5"))
    with pytest.raises(SpecError) as error:
        load_study(bad_base)
    assert error.value.field == "study.scenario" and "stepp" in error.value.allowed  # names the unknown key


def test_grid_runs_every_combination(tmp_path):
    parameters = RESTITUTION.replace("bounds = [0.5, 0.95]", "values = [0.6, 0.9]") + """
    [[parameters]]
    name = "contact.wall.stiffness"
    bounds = [1e6, 1e8]
    distribution = "logunif"
    """
    study = load_study(write_study(tmp_path, 'sampler = "grid"\nlevels = 3', textwrap.dedent(parameters)))
    X = sample(study)
    assert X.shape == (6, 2)
    np.testing.assert_allclose(grid_values(study.parameters[1], 3), [1e6, 1e7, 1e8])
    assert study.method.analyzer == "none"


def test_sampled_values_are_validated_before_anything_runs(tmp_path):
    """Each bound is valid alone, but design points with contact_step > step are not: the plan stops."""
    parameters = """
    [[parameters]]
    name = "solver.reference.step"
    bounds = [1e-6, 1e-5]
    [[parameters]]
    name = "solver.reference.contact_step"
    bounds = [1e-6, 1e-5]
    """
    path = write_study(tmp_path, 'sampler = "latin"\nsamples = 8', textwrap.dedent(parameters))
    path.write_text(path.read_text().replace('"solver.reference.method=velocity_verlet"',
                                             '"solver.reference.method=central_difference"'))
    study = load_study(path)
    with pytest.raises(SpecError) as error:
        plan(study, sample(study))
    assert error.value.field.startswith("sample ") and "solver.reference.step" in str(error.value.value)


def test_run_key_is_a_content_hash_of_the_canonical_input():
    model = IshigamiModel()
    base = model.assign((), ())
    assert run_key(model, base) == run_key(model, model.assign(("x1",), (0.0,)))  # same input, other spelling
    assert run_key(model, base) == run_key(model, model.assign(("x1",), (0,)))  # int and float alike
    assert run_key(model, base) != run_key(model, model.assign(("x1",), (1e-12,)))
    assert re.fullmatch(r"[0-9a-f]{64}", run_key(model, base))


def test_python_api_validates_like_the_file():
    bounds = (-math.pi, math.pi)
    study = Study("ishigami", IshigamiModel(), [Parameter(f"x{i}", bounds) for i in (1, 2, 3)], ("y",),
                  Method("sobol", samples=8), seed=1)
    assert sample(study).shape == (8 * 5, 3)
    with pytest.raises(SpecError) as error:
        Study("ishigami", IshigamiModel(), [Parameter("x4", bounds)], ("y",), Method("sobol", samples=8), seed=1)
    assert error.value.field == "parameters.0.name" and error.value.value == "x4"
    with pytest.raises(SpecError) as error:
        Parameter("x1", (1.0, -1.0))
    assert error.value.field == "bounds" and list(error.value.value) == [1.0, -1.0]


def test_ishigami_analytic_indices_match_the_literature():
    """Saltelli et al. (2008), quoted in SALib's Ishigami docstring: S1 = 0.3139, 0.4424, 0."""
    indices = ishigami_indices()
    np.testing.assert_allclose(indices["S1"], [0.3139, 0.4424, 0.0], atol=1e-4)
    np.testing.assert_allclose(indices["ST"], [0.5576, 0.4424, 0.2437], atol=1e-4)
