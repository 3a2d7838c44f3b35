"""No method name is spelled as a string outside the catalogue and the spec parser.

Every fact about an integration method (its order, adaptive or implicit, which engine runs it, Exudyn's solver
type) lives in :mod:`bearing_mbs.spec.methods`; code elsewhere names a method through the catalogue's objects
(``methods.DOPRI5.name``, ``method.key(engine)``). This scans every module of the package for a string constant
equal to a method's name, an old name, an Exudyn ``DynamicSolverType`` member name or an ``engine/method`` key;
docstrings are text and are not scanned.
"""

from __future__ import annotations

import ast
from pathlib import Path

from bearing_mbs.spec import methods

PACKAGE = Path(methods.__file__).resolve().parents[1]
#: The modules that may spell a method's name: the catalogue, and the spec parser that validates against it.
ALLOWED = ("spec/methods.py", "spec/solver.py")


def spelled_names() -> set[str]:
    """Every spelling of a method the scan looks for."""
    found = set()
    for method in methods.METHODS.values():
        found.update((method.name, *method.old_names, *(method.key(engine) for engine in methods.ENGINE_METHODS)))
        if method.exudyn is not None:
            found.add(method.exudyn)
    return found


def _docstrings(tree: ast.AST) -> set[int]:
    """The ids of the docstring constants of a module, its classes and functions."""
    kinds = (ast.Module, ast.ClassDef, ast.FunctionDef, ast.AsyncFunctionDef)
    return {id(node.body[0].value) for node in ast.walk(tree)
            if isinstance(node, kinds) and node.body and isinstance(node.body[0], ast.Expr)
            and isinstance(node.body[0].value, ast.Constant)}


def spellings(root: Path) -> list[str]:
    """``path:line: name`` of each string constant under ``root`` that spells a method, outside :data:`ALLOWED`."""
    names, found = spelled_names(), []
    for path in sorted(root.rglob("*.py")):
        relative = path.relative_to(root).as_posix()
        if relative in ALLOWED:
            continue
        tree = ast.parse(path.read_text(encoding="utf-8"))
        skip = _docstrings(tree)
        found += [f"{relative}:{node.lineno}: {node.value!r}" for node in ast.walk(tree)
                  if isinstance(node, ast.Constant) and isinstance(node.value, str) and node.value in names
                  and id(node) not in skip]
    return found


def test_no_method_name_spelled_outside_the_catalogue():
    found = spellings(PACKAGE)
    assert not found, "method names spelled as strings (use bearing_mbs.spec.methods):\n" + "\n".join(found)


def test_the_scan_sees_a_spelled_name(tmp_path):
    """The scan finds a name in code, not in a docstring."""
    (tmp_path / "module.py").write_text('"""Runs dopri5."""\n\nMETHOD = "dopri5"\n', encoding="utf-8")
    assert spellings(tmp_path) == ["module.py:3: 'dopri5'"]


def test_every_listed_method_is_in_the_catalogue():
    """The engines' listings, the renamed names and the Exudyn members hold together."""
    for listing in methods.ENGINE_METHODS.values():
        assert all(methods.METHODS[method.name] is method for method in listing)
    assert all(method.exudyn for method in methods.ENGINE_METHODS[methods.EXUDYN])
    assert all(method.adaptive == (method.step_control is not None)
               for method in methods.ENGINE_METHODS[methods.REFERENCE])
    assert not set(methods.RENAMED) & set(methods.METHODS)
