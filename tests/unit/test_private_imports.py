"""No module imports a private name (``_name``) from a module of another package of thermogear.

Private helpers are free to change; a module of another package that imports one (as the sweep's batch kernel
once took ``_transition`` from dynamics) breaks silently when they do. Inside one package private imports between
modules are allowed (they change together), except in ``thermogear.dynamics``, whose solvers are used by every
layer above: there a helper another module needs is public (named and documented).
"""

from __future__ import annotations

import ast
import sys
from pathlib import Path

import thermogear

SOURCE = Path(thermogear.__file__).parent


def _package_of(module: str) -> str:
    """thermogear.<package> of a dotted module name (the top-level module itself for thermogear/x.py)."""
    parts = module.split(".")
    return ".".join(parts[:2])


def _private_cross_package_imports() -> list[str]:
    found = []
    for path in sorted(SOURCE.rglob("*.py")):
        relative = path.relative_to(SOURCE.parent).with_suffix("")
        importer = ".".join(relative.parts)
        tree = ast.parse(path.read_text(encoding="utf-8"))
        for node in ast.walk(tree):
            if not isinstance(node, ast.ImportFrom) or not node.module or not node.module.startswith("thermogear"):
                continue
            if _package_of(node.module) == _package_of(importer):
                continue
            for alias in node.names:
                if alias.name.startswith("_") and not alias.name.startswith("__"):
                    found.append(f"{importer}: from {node.module} import {alias.name}")
    return found


def test_no_private_name_is_imported_across_packages():
    assert _private_cross_package_imports() == []


def test_no_dynamics_module_imports_a_private_name_of_another_module():
    found = []
    for path in sorted((SOURCE / "dynamics").glob("*.py")):
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            if isinstance(node, ast.ImportFrom) and (node.module or "").startswith("thermogear"):
                found += [f"{path.stem}: {node.module}.{alias.name}" for alias in node.names
                          if alias.name.startswith("_") and not alias.name.startswith("__")]
    assert found == []


def test_the_check_finds_a_private_cross_package_import(tmp_path, monkeypatch):
    """The scan is not vacuous: a planted module that imports a private dynamics name is reported."""
    package = tmp_path / "thermogear"
    (package / "sweep").mkdir(parents=True)
    (package / "sweep" / "planted.py").write_text("from thermogear.dynamics.periodic import _helper\n")
    (package / "sweep" / "inside.py").write_text("from thermogear.sweep.batch import _private\n")
    monkeypatch.setattr(sys.modules[__name__], "SOURCE", package)
    assert _private_cross_package_imports() == ["thermogear.sweep.planted: from thermogear.dynamics.periodic "
                                                "import _helper"]
