"""The contact law of the mesh (``[dynamics] mesh``) and the temperature source (``[temperature] model``) are
resolved once (issue 33): outside their registries, :mod:`thermogear.dynamics.problems.mesh_laws` and
:mod:`thermogear.temperature.kinds`, no code compares ``"linear"``/``"nonlinear"`` or ``"uniform"``/``"tabulated"``/
``"fem"``/``"gearbox"`` (it asks ``mesh_law(name).backlash``, ``temperature_source(name).uniform``). The scan is the
model-name scan's (:mod:`test_no_model_name_branches`)."""

from __future__ import annotations

from pathlib import Path

import pytest

import thermogear
from test_no_model_name_branches import model_name_branches
from thermogear.dynamics.problems.mesh_laws import MESH_LAWS
from thermogear.temperature.kinds import TEMPERATURE_SOURCES

SOURCE = Path(thermogear.__file__).parent

#: (registry module, the names it resolves, comparisons left on purpose with their reason: module -> count)
SCANS = {
    "contact law": ("dynamics/problems/mesh_laws.py", frozenset(MESH_LAWS), {}),
    # (cli/warmup.py's `--model gearbox`, a warm-up model, is resolved from its own registry, WARMUP_MODELS)
    "temperature source": ("temperature/kinds.py", frozenset(TEMPERATURE_SOURCES), {}),
}


@pytest.mark.parametrize("scan", sorted(SCANS))
def test_no_module_outside_the_registry_compares_a_name(scan):
    registry, names, known = SCANS[scan]
    hits = {}
    for path in sorted(SOURCE.rglob("*.py")):
        relative = path.relative_to(SOURCE).as_posix()
        if relative != registry and (found := model_name_branches(path.read_text(encoding="utf-8"), names,
                                                                  frozenset())):
            hits[relative] = found
    assert {path: len(found) for path, found in hits.items()} == known, hits


def test_the_scan_finds_the_forms_the_package_held():
    # the forms of fe2cd59 (13 contact-law and 18 temperature-source comparisons), one per line; asking the
    # registry is no branch
    source = ('flag = dynamics.mesh == "nonlinear"\n'
              'other = dynamics.mesh != "nonlinear"\n'
              'linear = any(m.get("mesh") == "nonlinear" for m in metrics)\n'
              'kind = mesh_law(dynamics.mesh).backlash\n'
              'given = section.model in ("uniform", "tabulated")\n'
              'uniform = temperature_source(section.model).uniform\n')
    names = frozenset(MESH_LAWS) | frozenset(TEMPERATURE_SOURCES)
    assert sorted(int(hit.split(":")[0]) for hit in model_name_branches(source, names, frozenset())) == [1, 2, 3, 5]
