"""Sensitivity studies: parameter sweeps, Latin hypercube, Morris and Sobol with SALib, run on Dask
distributed, persisted run by run and resumable.

The pipeline follows SALib's sample → evaluate → analyze::

    from bearing_mbs.studies.sensitivity import analyze, connect, evaluate, load_study, sample, write_report

    study = load_study("scenarios/study_drop_morris.toml")
    X = sample(study)                                   # (n, D) design, seeded
    with connect(workers=2) as client:                  # local cluster; or connect("tcp://host:8786")
        Y = evaluate(study, X, "out/drop_morris", client)   # table of runs; stored, resumable
    Si = analyze(study, X, Y)                           # {output: Indices}, Si[o].to_df()
    write_report(study, Y, Si, "out/drop_morris/report")

or all at once: ``run_study(study, "out/drop_morris", workers=2)``; on the command line:
``bearing-mbs sweep STUDY.toml --out DIR [--scheduler ADDRESS] [--workers N]``.
See ``docs/sensitivity.md``.
"""

from bearing_mbs.studies.sensitivity.analysis import Indices, analyze
from bearing_mbs.studies.sensitivity.execution import EvaluationStats, connect, evaluate, run_table
from bearing_mbs.studies.sensitivity.models import (
    BUILTIN_MODELS,
    EVALUATORS,
    IshigamiModel,
    RunModel,
    SimulationModel,
    SkiddingBalanceModel,
    SteadyRunModel,
    ishigami_indices,
)
from bearing_mbs.studies.sensitivity.pipeline import StudyResult, run_study, write_report
from bearing_mbs.studies.sensitivity.runs import Run, plan, run_key
from bearing_mbs.studies.sensitivity.sampling import sample
from bearing_mbs.studies.sensitivity.store import RunStore
from bearing_mbs.studies.sensitivity.study import (
    ANALYZERS,
    DISTRIBUTIONS,
    SAMPLERS,
    Execution,
    Method,
    Parameter,
    Study,
    load_study,
)

__all__ = [
    "ANALYZERS",
    "BUILTIN_MODELS",
    "DISTRIBUTIONS",
    "EVALUATORS",
    "SAMPLERS",
    "EvaluationStats",
    "Execution",
    "Indices",
    "IshigamiModel",
    "Method",
    "Parameter",
    "Run",
    "RunModel",
    "RunStore",
    "SimulationModel",
    "SkiddingBalanceModel",
    "SteadyRunModel",
    "Study",
    "StudyResult",
    "analyze",
    "connect",
    "evaluate",
    "ishigami_indices",
    "load_study",
    "plan",
    "run_key",
    "run_study",
    "run_table",
    "sample",
    "write_report",
]
