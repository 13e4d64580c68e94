"""No module imports a private name (``_name``) from a module of another package of thermogear.

Private helpers are free to change; a module of another package that imports one (as the sweep's batch kernel
once took ``_transition`` from dynamics) breaks silently when they do. Inside one package private imports between
modules are allowed (they change together), except in ``thermogear.dynamics``, whose solvers are used by every
layer above: there a helper another module needs is public (named and documented).

The scan resolves relative imports (``from ..dynamics.x import _y``), refuses private modules of another package
(``from thermogear.dynamics._kernels import solve``, ``import thermogear.dynamics._kernels``) and private
attributes read through a module of another package (``import thermogear.dynamics.periodic as periodic`` then
``periodic._solve(...)``).
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


def _is_private(name: str) -> bool:
    return name.startswith("_") and not name.startswith("__")


def _absolute(node: ast.ImportFrom, importer: str, is_package: bool) -> str:
    """The absolute module of a ``from … import`` (relative imports resolved against the importing module)."""
    if not node.level:
        return node.module or ""
    base = importer.split(".") if is_package else importer.split(".")[:-1]
    base = base[:len(base) - (node.level - 1)]
    return ".".join(base + ([node.module] if node.module else []))


def _is_module(dotted: str) -> bool:
    relative = Path(*dotted.split(".")[1:])
    return (SOURCE / relative).with_suffix(".py").is_file() or (SOURCE / relative / "__init__.py").is_file()


def _private_cross_package_imports() -> list[str]:
    found = []
    for path in sorted(SOURCE.rglob("*.py")):
        relative = path.relative_to(SOURCE.parent).with_suffix("")
        is_package = relative.name == "__init__"
        importer = ".".join(relative.parts[:-1] if is_package else relative.parts)
        tree = ast.parse(path.read_text(encoding="utf-8"))
        module_aliases: dict[str, str] = {}  # local name -> module of another package
        for node in ast.walk(tree):
            if isinstance(node, ast.Import):
                for alias in node.names:
                    if alias.name.startswith("thermogear") and _package_of(alias.name) != _package_of(importer):
                        if any(_is_private(part) for part in alias.name.split(".")):
                            found.append(f"{importer}: import {alias.name}")
                        if alias.asname:
                            module_aliases[alias.asname] = alias.name
                continue
            if not isinstance(node, ast.ImportFrom):
                continue
            module = _absolute(node, importer, is_package)
            if not module.startswith("thermogear") or _package_of(module) == _package_of(importer):
                continue
            if any(_is_private(part) for part in module.split(".")):
                found.append(f"{importer}: from {module} import {', '.join(a.name for a in node.names)}")
                continue
            for alias in node.names:
                if _is_private(alias.name):
                    found.append(f"{importer}: from {module} import {alias.name}")
                elif _is_module(f"{module}.{alias.name}"):
                    module_aliases[alias.asname or alias.name] = f"{module}.{alias.name}"
        for node in ast.walk(tree):
            if (isinstance(node, ast.Attribute) and isinstance(node.value, ast.Name)
                    and node.value.id in module_aliases and _is_private(node.attr)):
                found.append(f"{importer}: {module_aliases[node.value.id]}.{node.attr}")
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


def test_the_check_finds_relative_private_module_and_attribute_forms(tmp_path, monkeypatch):
    """Relative imports are resolved; a private module and a private attribute of another package's module are
    reported; the same forms inside one package are not."""
    package = tmp_path / "thermogear"
    for folder in ("sweep", "dynamics"):
        (package / folder).mkdir(parents=True)
        (package / folder / "__init__.py").write_text("")
    (package / "dynamics" / "periodic.py").write_text("def _solve():\n    pass\n")
    (package / "sweep" / "relative.py").write_text("from ..dynamics.periodic import _solve\n")
    (package / "sweep" / "module.py").write_text("from thermogear.dynamics._kernels import solve\n")
    (package / "sweep" / "attribute.py").write_text("from thermogear.dynamics import periodic\nperiodic._solve()\n")
    (package / "sweep" / "aliased.py").write_text("import thermogear.dynamics.periodic as p\np._solve()\n")
    (package / "dynamics" / "inside.py").write_text("from . import periodic\nperiodic._solve()\n")
    monkeypatch.setattr(sys.modules[__name__], "SOURCE", package)
    assert sorted(_private_cross_package_imports()) == [
        "thermogear.sweep.aliased: thermogear.dynamics.periodic._solve",
        "thermogear.sweep.attribute: thermogear.dynamics.periodic._solve",
        "thermogear.sweep.module: from thermogear.dynamics._kernels import solve",
        "thermogear.sweep.relative: from thermogear.dynamics.periodic import _solve"]
