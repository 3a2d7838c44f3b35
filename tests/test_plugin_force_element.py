"""A force element registered from outside the package runs on both engines and closes the energy audit, with no
edit to any engine: the checks are in ``tests/isolated_force_element.py`` (references and tolerances there).

They run in a child pytest process with a numba cache directory of its own, so that compiled functions
specialised on the test's own types never enter the package's shared on-disk cache (a Dask worker, which cannot
import the test module, would fail to read such an entry back). That directory is kept between runs, one per
version of the checks' file, and cleared with the package's cache when a compiled source changes.
"""

from __future__ import annotations

import hashlib
import os
import re
import subprocess
import sys
from pathlib import Path

import pytest

from bearing_mbs.core.numba_cache import isolated_cache_dir

CHECKS = Path(__file__).with_name("isolated_force_element.py")


def checks(*arguments) -> str:
    """Run the checks in a child pytest with a numba cache of its own; return its output."""
    version = hashlib.sha256(CHECKS.read_bytes()).hexdigest()[:16]
    environment = {**os.environ, "NUMBA_CACHE_DIR": str(isolated_cache_dir(f"force-element-{version}"))}
    run = subprocess.run([sys.executable, "-m", "pytest", "-q", "-p", "no:cacheprovider", *arguments, str(CHECKS)],
                         env=environment, capture_output=True, text=True, cwd=CHECKS.parent)
    assert run.returncode == 0, run.stdout[-3000:]
    return run.stdout


@pytest.mark.slow
def test_a_spring_registered_from_outside_runs_on_both_engines():
    """Compiled (about a minute of compilation for the test's own scene type, on every clean machine: with the long
    studies). The default suite holds the same path: the built-in kinds go through the one dispatch every compiled
    run uses, and ``tests/test_guide_force_element.py`` adds a kind through it, as Python, on both engines."""
    output = checks()
    assert re.search(r"\b6 passed", output), output[-3000:]


@pytest.mark.slow
def test_a_spring_registered_from_outside_runs_on_both_implicit_solvers():
    """With the spring's own analytic Jacobian, through the same dispatch as the built-in kinds': the reference
    engine's generalized-α and Exudyn's analytic Jacobian use it, neither differentiates numerically."""
    output = checks("-m", "slow")
    assert re.search(r"\b2 passed", output), output[-3000:]
