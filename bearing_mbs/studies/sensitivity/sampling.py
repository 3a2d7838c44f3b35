"""Sampling designs: X, an (n, D) array of parameter values, one row per run, columns in the study's
parameter order, in the parameters' own units.

Latin hypercube, Morris and Sobol' are SALib's samplers, seeded with the study's seed; the grid is the
full factorial of each parameter's values (or ``levels`` points over its bounds).
"""

from __future__ import annotations

import itertools

import numpy as np

from bearing_mbs.studies.sensitivity.study import Parameter, Study


def grid_values(parameter: Parameter, levels: int | None) -> list:
    """A grid parameter's values: its explicit ``values``, or ``levels`` points over its bounds, evenly
    spaced (``unif``) or geometrically spaced (``logunif``)."""
    if parameter.values is not None:
        return list(parameter.values)
    low, high = parameter.bounds
    space = np.geomspace if parameter.distribution == "logunif" else np.linspace
    return [float(v) for v in space(low, high, levels)]


def sample_grid(study: Study) -> np.ndarray:
    axes = [grid_values(p, study.method.levels) for p in study.parameters]
    return np.array(list(itertools.product(*axes)), dtype=float)


def sample_latin(study: Study) -> np.ndarray:
    from SALib.sample import latin

    return latin.sample(study.problem, study.method.samples, seed=study.seed)


def sample_morris(study: Study) -> np.ndarray:
    from SALib.sample import morris

    return morris.sample(study.problem, study.method.samples, num_levels=study.method.levels, seed=study.seed)


def sample_sobol(study: Study) -> np.ndarray:
    from SALib.sample import sobol

    return sobol.sample(study.problem, study.method.samples, calc_second_order=study.method.second_order,
                        scramble=True, seed=study.seed)


SAMPLE = {"grid": sample_grid, "latin": sample_latin, "morris": sample_morris, "sobol": sample_sobol}


def sample(study: Study) -> np.ndarray:
    """The study's design X (n, D): reproducible for a given study and seed."""
    return np.asarray(SAMPLE[study.method.sampler](study), dtype=float)
