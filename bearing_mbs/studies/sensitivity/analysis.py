"""Sensitivity indices of each output, by the study's SALib analysis, with bootstrap confidence intervals.

- ``morris``: elementary effects: μ* (mean absolute effect, in the output's unit per unit of the
  normalised input range), its confidence interval, μ and σ (Morris 1991; Campolongo et al. 2007).
- ``sobol``: first-order S1 and total ST variance fractions, optional second-order S2 (Saltelli 2002).
- ``rbd_fast``: first-order S1 by random-balance-design FAST (Latin hypercube designs).

Morris and Sobol need every run of the design; outputs with missing values (an errored or failed run, or
a metric a run does not report) are reported without indices. RBD-FAST uses the runs that have a value.
"""

from __future__ import annotations

import logging
from dataclasses import dataclass

import numpy as np
import pandas as pd

from bearing_mbs.studies.sensitivity.study import Study

log = logging.getLogger(__name__)

#: The per-parameter indices of each analysis, as (index, its confidence half-width) pairs and extras.
COLUMNS = {
    "morris": ("mu_star", "mu_star_conf", "mu", "sigma"),
    "sobol": ("S1", "S1_conf", "ST", "ST_conf"),
    "rbd_fast": ("S1", "S1_conf"),
}
#: Analyses that need every run of the design.
COMPLETE_DESIGN = ("morris", "sobol")


@dataclass
class Indices:
    """The indices of one output. ``result`` is SALib's ResultDict (None when the output could not be
    analysed; ``note`` says why); ``runs_used``: runs with a value that entered the analysis."""

    output: str
    analyzer: str
    names: list[str]
    result: dict | None
    runs_used: int
    note: str = ""

    def to_df(self) -> pd.DataFrame:
        """Parameters × indices (``<index>_conf``: half-width of the confidence interval)."""
        if self.result is None:
            return pd.DataFrame(index=pd.Index(self.names, name="parameter"))
        data = {column: np.asarray(self.result[column], dtype=float) for column in COLUMNS[self.analyzer]}
        return pd.DataFrame(data, index=pd.Index(self.names, name="parameter"))

    def second_order_df(self) -> pd.DataFrame | None:
        """Sobol S2 and S2_conf by parameter pair, when computed."""
        if self.result is None or "S2" not in self.result:
            return None
        rows = []
        for i, a in enumerate(self.names):
            for j in range(i + 1, len(self.names)):
                rows.append({"parameter": a, "with": self.names[j], "S2": self.result["S2"][i, j],
                             "S2_conf": self.result["S2_conf"][i, j]})
        return pd.DataFrame(rows)


def output_matrix(study: Study, Y) -> np.ndarray:
    """(n, outputs) float array from a run table (DataFrame with output columns), a mapping of output
    name to values, or an array (1-D for a single output)."""
    if isinstance(Y, pd.DataFrame) or isinstance(Y, dict):
        return np.column_stack([np.asarray(Y[o], dtype=float) for o in study.outputs])
    Y = np.asarray(Y, dtype=float)
    return Y[:, None] if Y.ndim == 1 else Y


def analyze(study: Study, X: np.ndarray, Y) -> dict[str, Indices]:
    """Indices of every output of the study, by its analysis; ``{}`` for ``analyzer = "none"``."""
    method = study.method
    if method.analyzer == "none":
        return {}
    X = np.asarray(X, dtype=float)
    values = output_matrix(study, Y)
    if values.shape != (X.shape[0], len(study.outputs)):
        raise ValueError(f"Y must have {X.shape[0]} rows and {len(study.outputs)} outputs, got {values.shape}")
    return {output: _analyze_one(study, X, values[:, j], output) for j, output in enumerate(study.outputs)}


def _analyze_one(study: Study, X: np.ndarray, y: np.ndarray, output: str) -> Indices:
    method, problem = study.method, study.problem
    problem = {k: v for k, v in problem.items() if k != "outputs"}
    present = np.isfinite(y)
    missing = int((~present).sum())
    indices = Indices(output, method.analyzer, study.names, None, int(present.sum()))
    if method.analyzer in COMPLETE_DESIGN and missing:
        indices.note = (f"{missing} of {y.size} runs have no value (error, failed run, or not in the "
                        f"summary); {method.analyzer} needs every run of the design")
        log.warning("%s: %s", output, indices.note)
        return indices
    if missing:
        X, y = X[present], y[present]
        indices.note = f"{missing} runs without a value left out"
    if y.size < 4:
        indices.note = f"only {y.size} runs have a value"
        return indices
    common = {"conf_level": method.conf_level, "num_resamples": method.resamples, "seed": study.seed}
    try:
        if method.analyzer == "morris":
            from SALib.analyze import morris

            result = morris.analyze(problem, X, y, num_levels=method.levels, **common)
        elif method.analyzer == "sobol":
            from SALib.analyze import sobol

            result = sobol.analyze(problem, y, calc_second_order=method.second_order, **common)
        else:
            from SALib.analyze import rbd_fast

            result = rbd_fast.analyze(problem, X, y, **common)
    except Exception as error:  # SALib's own complaint, kept for the report
        indices.note = f"SALib {method.analyzer} analysis failed: {type(error).__name__}: {error}"
        log.warning("%s: %s", output, indices.note)
        return indices
    indices.result = result
    return indices
