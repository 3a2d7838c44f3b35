"""What the no-traceback property tests share (tests/test_no_traceback_*.py): run a command through the command
line's entry point, and check that it ran to a status or refused its input by name.

A command given a valid scenario either

* runs to a status: exit code 0, 1 or 3, a ``summary.json`` whose ``status`` is the one the code says (success,
  failed, suspect); or
* refuses the input by name: exit code 2, nothing written, and the error line in the format of
  :class:`bearing_mbs.spec.SpecError`, ``error: FIELD = VALUE: what is allowed`` (its shape is checked, never
  its wording);

and never raises. Any exception is a bug the property found. A command still working after :data:`CPU_LIMIT` CPU
seconds is asked to stop as SIGINT would ask it (valid input may ask for a long run); it must then exit as
interrupted (130) with its summary written.

Profiles: ``no-traceback`` (the default run: derandomized, so CI draws the same examples every time) and
``no-traceback-search`` (random, for a longer search run by hand), chosen by the environment variable
``NO_TRACEBACK_PROFILE``; ``NO_TRACEBACK_EXAMPLES`` sets the search's number of examples per model::

    NO_TRACEBACK_PROFILE=no-traceback-search NO_TRACEBACK_EXAMPLES=3000 \\
        python -m pytest -q tests/test_no_traceback_journal.py --hypothesis-show-statistics
"""

from __future__ import annotations

import contextlib
import copy
import io
import json
import math
import os
import re
import signal
import tempfile
from pathlib import Path

from hypothesis import HealthCheck, event, settings
from hypothesis import strategies as st

from bearing_mbs.cli import main
from bearing_mbs.core.interrupt import active_request

#: Examples per model in the default run.
EXAMPLES = 300
#: The exit codes of a status (docs/status.md), and that of bad input.
STATUS_CODES = {"success": 0, "failed": 1, "suspect": 3}
BAD_INPUT = 2
#: The error line of a refusal: ``error: FIELD = VALUE: what is allowed`` (bearing_mbs.spec.SpecError's format).
REFUSAL = re.compile(r"^error: (?P<field>[^\s=]+) = (?P<value>.*?): (?P<allowed>.+)$")

_HEALTH = [HealthCheck.too_slow, HealthCheck.filter_too_much, HealthCheck.data_too_large]
#: The default profile's name, and that of this run's.
DEFAULT_PROFILE = "no-traceback"
ACTIVE_PROFILE = os.environ.get("NO_TRACEBACK_PROFILE", DEFAULT_PROFILE)
settings.register_profile(DEFAULT_PROFILE, max_examples=EXAMPLES, derandomize=True, database=None, deadline=None,
                          suppress_health_check=_HEALTH, print_blob=True)
settings.register_profile("no-traceback-search", max_examples=int(os.environ.get("NO_TRACEBACK_EXAMPLES", "2000")),
                          derandomize=False, deadline=None, suppress_health_check=_HEALTH, print_blob=True)
#: The profile of this run.
PROFILE = settings.get_profile(ACTIVE_PROFILE)


def profile(examples: int) -> settings:
    """:data:`PROFILE` with ``examples`` per model in the default run (a model whose examples are costly takes
    fewer, for the suite's time budget); the search profile keeps its own number."""
    if ACTIVE_PROFILE != DEFAULT_PROFILE:
        return PROFILE
    return settings(PROFILE, max_examples=examples)


def toml_value(value) -> str:
    """``value`` as a TOML literal (a mapping as an inline table)."""
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, int):
        return str(value)
    if isinstance(value, float):
        if math.isnan(value):
            return "nan"
        return repr(value) if math.isfinite(value) else ("inf" if value > 0 else "-inf")
    if isinstance(value, str):
        return json.dumps(value)
    if isinstance(value, (list, tuple)):
        return "[" + ", ".join(toml_value(v) for v in value) + "]"
    if isinstance(value, dict):
        return "{ " + ", ".join(f"{json.dumps(k)} = {toml_value(v)}" for k, v in value.items()) + " }"
    raise TypeError(f"no TOML literal for {value!r}")


def toml_document(mapping: dict, prefix: str = "") -> str:
    """A nested mapping as a TOML document: its values, then each sub-mapping as a ``[table]``."""
    lines = [f"{json.dumps(k)} = {toml_value(v)}" for k, v in mapping.items() if not isinstance(v, dict)]
    text = (f"[{prefix}]\n" if prefix else "") + "".join(line + "\n" for line in lines)
    for key, value in mapping.items():
        if isinstance(value, dict):
            text += "\n" + toml_document(value, f"{prefix}.{json.dumps(key)}" if prefix else json.dumps(key))
    return text


#: Put at a path by :func:`with_changes`: remove the key.
DELETE = object()


def with_changes(base: dict, changes: dict) -> dict:
    """A copy of the raw scenario ``base`` with ``changes`` (dotted path -> value, or :data:`DELETE`) applied,
    tables created as needed."""
    data = copy.deepcopy(base)
    for path, value in changes.items():
        *tables, key = path.split(".")
        node = data
        for name in tables:
            node = node.setdefault(name, {})
        if value is DELETE:
            node.pop(key, None)
        else:
            node[key] = value
    return data


def overrides(changes: dict) -> list[str]:
    """``--set PATH=VALUE`` arguments for a mapping of dotted paths to values."""
    arguments = []
    for path, value in changes.items():
        arguments += ["--set", f"{path}={toml_value(value)}"]
    return arguments


def run_command(command: str, scenario: dict | Path, changes: dict | None = None, *extra: str) -> int:
    """Run ``bearing-mbs COMMAND FILE --out NEW --no-figures --set PATH=VALUE... EXTRA`` in this process and check
    its outcome (module docstring); the exit code. ``scenario`` is a file, or a raw mapping written as one;
    ``changes`` (dotted path -> value) become ``--set`` overrides, which win over the file's variant."""
    with tempfile.TemporaryDirectory() as tmp:
        out = Path(tmp) / "out"
        if isinstance(scenario, dict):
            path = Path(tmp) / "scenario.toml"
            path.write_text(toml_document(scenario))
        else:
            path = scenario
        errors = io.StringIO()
        argv = [command, str(path), "--out", str(out), "--no-figures", *extra, *overrides(changes or {})]
        with contextlib.redirect_stderr(errors), watchdog(CPU_LIMIT) as expired:
            code = main(argv)
        event(f"{command}: exit code {code}")
        if expired:
            event(f"{command}: interrupted by the watchdog")
            check_interrupted(code, out)
        else:
            check_outcome(code, out, errors.getvalue())
    return code


#: CPU seconds an example may take before the watchdog asks the command to stop, as SIGINT would: valid input may
#: ask for a long run (a stiff film under an adaptive explicit method, a 1e-12 tolerance), and the property is about
#: how a command ends, not how long it takes.
CPU_LIMIT = float(os.environ.get("NO_TRACEBACK_CPU_LIMIT", "1"))
INTERRUPTED_CODE = 128 + signal.SIGINT


@contextlib.contextmanager
def watchdog(seconds: float):
    """While the block runs, after ``seconds`` of the process's CPU time set the command's stop request (the one
    SIGINT sets, :func:`bearing_mbs.core.interrupt.active_request`); yields a list that is non-empty once it has."""
    expired = []

    def expire(number, frame):
        request = active_request()
        if request is not None and not request.is_set():
            expired.append(True)
            request.set(signal.SIGINT)
        else:  # not inside the command's stop_on_signals block (loading, output): look again shortly
            signal.setitimer(signal.ITIMER_PROF, 0.05)

    previous = signal.signal(signal.SIGPROF, expire)
    signal.setitimer(signal.ITIMER_PROF, seconds)
    try:
        yield expired
    finally:
        signal.setitimer(signal.ITIMER_PROF, 0)
        signal.signal(signal.SIGPROF, previous)


def check_interrupted(code: int, out: Path) -> None:
    """A command the watchdog stopped exits as an interrupted one and keeps what it computed."""
    assert code == INTERRUPTED_CODE, code
    assert (out / "summary.json").exists(), "an interrupted command wrote no summary"


def check_outcome(code: int, out: Path, stderr: str) -> None:
    """A status with its summary, or a refusal by name that wrote nothing."""
    if code == BAD_INPUT:
        assert not out.exists() or not any(p.is_file() for p in out.rglob("*")), "a refused input wrote files"
        lines = [line for line in stderr.splitlines() if line.startswith("error: ")]
        assert lines and REFUSAL.match(lines[-1]), f"a refusal names no field: {stderr[-500:]!r}"
        event(f"refused: {REFUSAL.match(lines[-1])['field']}")
        return
    assert code in STATUS_CODES.values(), f"exit code {code}"
    summary = json.loads((out / "summary.json").read_text())
    status = summary["status"]
    assert STATUS_CODES[status] == code, (status, code)
    event(f"status {status}")


# Strategies over a documented range, with its edges.

def log_uniform(low: float, high: float) -> st.SearchStrategy[float]:
    """Floats from ``low`` to ``high`` (> 0), uniform in their logarithm, with both edges drawn often."""
    inside = st.floats(math.log10(low), math.log10(high)).map(lambda x: min(max(10.0**x, low), high))
    return st.one_of(inside, st.sampled_from([low, high]))


def uniform(low: float, high: float, *, low_open: bool = False, high_open: bool = False,
            margin: float = 1e-9) -> st.SearchStrategy[float]:
    """Floats in the interval, with the edges drawn often: a closed edge itself, an open one approached to within
    ``margin`` of the interval's width."""
    width = high - low
    first = low + margin * width if low_open else low
    last = high - margin * width if high_open else high
    return st.one_of(st.floats(first, last), st.sampled_from([first, last]))


def solver_table(draw, end: float, engine: str, method: str, steps: int) -> dict:
    """A ``[solver]`` table for a run of ``end`` [s] with ``engine``'s ``method``: 1 to 20 output instants, at most
    ``steps`` steps (Exudyn at least one per output instant), and now and then a tolerance, a spectral radius and
    Exudyn's Jacobian."""
    outputs = draw(st.integers(1, 20))
    count = draw(st.integers(outputs if engine == "exudyn" else 1, steps))
    table = {"engine": engine, "output_interval": end / outputs, engine: {"method": method, "step": end / count}}
    if draw(st.booleans()):
        table[engine]["tolerance"] = draw(log_uniform(1e-12, 0.5))
    if draw(st.booleans()):
        table[engine]["spectral_radius"] = draw(uniform(0.0, 1.0))
    if engine == "exudyn":
        table["exudyn"]["jacobian"] = draw(st.sampled_from(["analytic", "numerical"]))
    return table


def optional(changes: dict, strategy: st.SearchStrategy, path: str, draw) -> None:
    """Put a value of ``strategy`` at ``path`` of ``changes`` half the time."""
    if draw(st.booleans()):
        changes[path] = draw(strategy)
