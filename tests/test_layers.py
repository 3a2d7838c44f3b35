"""The layers are a contract, not a hope: import-linter's contracts (``[tool.importlinter]`` in pyproject.toml)
hold, the package has no import cycle (imports inside functions included), and importing it changes no
global state."""

from __future__ import annotations

import subprocess
import sys
import tomllib
from pathlib import Path

import grimp

ROOT = Path(__file__).resolve().parents[1]


def test_import_linter_contracts_hold():
    linter = Path(sys.executable).with_name("lint-imports")
    run = subprocess.run([str(linter), "--config", str(ROOT / "pyproject.toml")], cwd=ROOT, capture_output=True,
                         text=True)
    assert run.returncode == 0, run.stdout[-4000:]


def _contracts() -> dict[str, dict]:
    config = tomllib.loads((ROOT / "pyproject.toml").read_text())
    return {contract["type"] + ": " + contract["name"]: contract
            for contract in config["tool"]["importlinter"]["contracts"]}


def test_every_module_of_the_package_is_in_a_layer():
    """A module outside the layers escapes the contract (the numba cache's invalidation once did)."""
    layers = next(c["layers"] for c in _contracts().values() if c["type"] == "layers")
    named = {name.strip() for layer in layers for name in layer.split("|")}
    package = ROOT / "bearing_mbs"
    modules = {f"bearing_mbs.{p.stem}" for p in package.glob("*.py") if p.stem not in ("__init__", "__main__")}
    modules |= {f"bearing_mbs.{p.name}" for p in package.iterdir() if (p / "__init__.py").exists()}
    assert sorted(modules - named) == []


def test_the_engines_are_independent_of_one_another():
    independent = [set(c["modules"]) for c in _contracts().values() if c["type"] == "independence"]
    assert {"bearing_mbs.engines.exudyn", "bearing_mbs.engines.reference"} in independent


def _cycles(graph) -> list[list[str]]:
    """Strongly connected components of more than one module (Tarjan's algorithm)."""
    index, low, stack, on_stack, components, counter = {}, {}, [], set(), [], [0]

    def visit(module):
        index[module] = low[module] = counter[0]
        counter[0] += 1
        stack.append(module)
        on_stack.add(module)
        for imported in graph.find_modules_directly_imported_by(module):
            if imported not in index:
                visit(imported)
                low[module] = min(low[module], low[imported])
            elif imported in on_stack:
                low[module] = min(low[module], index[imported])
        if low[module] == index[module]:
            component = []
            while True:
                member = stack.pop()
                on_stack.discard(member)
                component.append(member)
                if member == module:
                    break
            if len(component) > 1:
                components.append(sorted(component))

    sys.setrecursionlimit(max(sys.getrecursionlimit(), 10_000))
    for module in sorted(graph.modules):
        if module not in index:
            visit(module)
    return components


def test_no_import_cycles_even_through_imports_inside_functions():
    graph = grimp.build_graph("bearing_mbs", include_external_packages=False)
    assert _cycles(graph) == []


def test_a_cycle_is_found_when_there_is_one():
    class Graph:  # the detector itself, on a known cycle a -> b -> c -> a plus a tail d -> a
        modules = {"a", "b", "c", "d"}
        edges = {"a": {"b"}, "b": {"c"}, "c": {"a"}, "d": {"a"}}

        def find_modules_directly_imported_by(self, module):
            return self.edges[module]

    assert _cycles(Graph()) == [["a", "b", "c"]]


def test_importing_the_package_touches_no_global_state():
    code = ("import logging, matplotlib; backend = matplotlib.get_backend(); "
            "import bearing_mbs, bearing_mbs.cli, bearing_mbs.runner, bearing_mbs.studies; "
            "assert matplotlib.get_backend() == backend, 'backend changed'; "
            "assert logging.getLogger('bearing_mbs').level == logging.NOTSET, 'logger level set'")
    run = subprocess.run([sys.executable, "-c", code], cwd=ROOT, capture_output=True, text=True)
    assert run.returncode == 0, run.stderr[-2000:]
