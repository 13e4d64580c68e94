"""The import contract keeps the solvers free of gears: ``thermogear.dynamics`` imports no case, geometry, schema or
mesh model, directly or through another module (pyproject.toml [tool.importlinter], a *forbidden* contract;
``tests/unit/test_layers.py`` runs import-linter on every contract). This test makes sure the contract stays
declared with all four modules, so that it cannot disappear while the linter still passes."""

from __future__ import annotations

import tomllib
from pathlib import Path

PYPROJECT = Path(__file__).resolve().parents[2] / "pyproject.toml"


def test_the_forbidden_contract_of_dynamics_is_declared():
    contracts = tomllib.loads(PYPROJECT.read_text(encoding="utf-8"))["tool"]["importlinter"]["contracts"]
    forbidden = [item for item in contracts if item["type"] == "forbidden"
                 and item["source_modules"] == ["thermogear.dynamics"]]
    assert len(forbidden) == 1
    assert set(forbidden[0]["forbidden_modules"]) == {"thermogear.case", "thermogear.geometry", "thermogear.schema",
                                                      "thermogear.mesh"}
    assert not forbidden[0].get("allow_indirect_imports", False)  # a chain through another module is refused too
