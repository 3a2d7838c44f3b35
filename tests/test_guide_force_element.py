"""The guide to adding a force element counts the files it touches truly: a toy kind with an analytic Jacobian
(``tests/guide_toy_element.py``) is added to a copy of the package by writing only the files the guide lists, and
runs through both engines' generalized-α with that Jacobian.

References, independent of the code under test: the damped oscillation of m ẍ + c ẋ + k x = 0 from rest, in closed
form (any vibrations text, e.g. Thomson, Theory of Vibration, §2.6), to 1e-4 of the start offset (generalized-α's
phase error at ωh = 6.3e-3 over two periods, about (ωh)²ωt/12, is 4e-5 of it); the toy's Jacobian is the one the
implicit methods use, counted by a profile hook on its code: called once per Jacobian the engine reports forming;
registered without it, the toy is differentiated by forward differences instead (its Jacobian never called, 2n
more force evaluations per Jacobian, the same oscillation).

The copy runs with ``NUMBA_DISABLE_JIT=1``: as Python, in seconds, where compiling the engines for a scene type
of its own would take minutes.
"""

from __future__ import annotations

import hashlib
import json
import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

import guide_toy_element as toy

ROOT = Path(__file__).resolve().parents[1]
GUIDE = ROOT / "docs" / "guide-add-a-force-element.md"
#: The guide's list of the files one edits, between these two marks.
LIST_START, LIST_END = "<!-- files to edit: start -->", "<!-- files to edit: end -->"


def listed_files() -> set[str]:
    """The guide's list of files, with ``<kind>`` the toy's module name."""
    text = GUIDE.read_text()
    listing = text[text.index(LIST_START) + len(LIST_START): text.index(LIST_END)]
    paths = re.findall(r"^\s*\d+\.\s+`([^`]+)`", listing, re.MULTILINE)
    return {path.replace("<kind>", toy.MODULE_NAME) for path in paths}


def snapshot(root: Path) -> dict[str, str]:
    return {path.relative_to(root).as_posix(): hashlib.sha256(path.read_bytes()).hexdigest()
            for path in root.rglob("*") if path.is_file()}


def add_the_toy(copy: Path) -> None:
    """What the guide tells one to write: the kind's module, and its entry (and import) in the registry."""
    (copy / "bearing_mbs" / "elements" / f"{toy.MODULE_NAME}.py").write_text(toy.MODULE)
    registry = copy / "bearing_mbs" / "elements" / "registry.py"
    text = registry.read_text()
    text = text.replace("from bearing_mbs.elements import ", f"from bearing_mbs.elements import {toy.MODULE_NAME}, ", 1)
    start = text.index("BUILT_IN = (")
    end = text.index(")\n", start)
    registry.write_text(f"{text[:end]}, {toy.MODULE_NAME}.ELEMENT{text[end:]}")


def test_a_toy_kind_added_by_the_guides_files_alone_runs_with_its_analytic_jacobian(tmp_path):
    copy = tmp_path / "copy"
    shutil.copytree(ROOT / "bearing_mbs", copy / "bearing_mbs",
                    ignore=shutil.ignore_patterns("__pycache__", "*.nbi", "*.nbc", "*.pyc"))
    before = snapshot(copy)
    add_the_toy(copy)
    after = snapshot(copy)
    written = {path for path in after if before.get(path) != after[path]}
    assert {f"bearing_mbs/elements/{toy.MODULE_NAME}.py", "bearing_mbs/elements/registry.py"} <= written
    assert written == listed_files()

    environment = {**os.environ, "PYTHONPATH": str(copy), "NUMBA_DISABLE_JIT": "1",
                   "NUMBA_CACHE_DIR": str(tmp_path / "numba")}
    run = subprocess.run([sys.executable, str(Path(toy.__file__).resolve())], env=environment, cwd=tmp_path,
                         capture_output=True, text=True, timeout=600, check=False)
    assert run.returncode == 0, run.stderr[-3000:]
    report = json.loads(run.stdout.strip().splitlines()[-1])
    assert Path(report["package"]).is_relative_to(copy)
    assert report["kinds"][-1] == "anchor_springs" and report["analytic"]
    for engine, figures in report["runs"].items():
        assert figures["success"], (engine, figures["message"])
        assert figures["offset_error"] < 1e-4 * toy.X0, (engine, figures)
        assert figures["lateral"] < 1e-12 * toy.X0, (engine, figures)
        calls = figures["calls"]
        if engine == "reference_without_jacobian":  # the forward differences: 2n more evaluations per Jacobian
            assert not figures["analytic"] and calls["jacobian"] == 0, figures
            reference = report["runs"]["reference"]
            assert figures["force_evaluations"] == reference["force_evaluations"] + 2 * 3 * reference[
                "jacobian_evaluations"], (figures, reference)
            continue
        assert calls["jacobian"] > 0, (engine, figures)
        if engine == "reference":
            assert calls["jacobian"] == figures["jacobian_evaluations"], figures
        else:
            # Exudyn calls the Jacobian user function (which calls the toy's) instead of differencing the forces
            assert figures["jacobian"] == "analytic", figures
            assert calls["jacobian"] >= figures["jacobian_user_evaluations"] > 0, figures
