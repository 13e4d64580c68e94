"""docs/architecture.md cannot go stale: its layers are the import-linter contract's, in the same order, and its
example of adding a model runs as written."""

from __future__ import annotations

import re
import sys
import tomllib
import types
from pathlib import Path

import numpy as np
import pytest

from thermogear.mesh.pair_models import PAIR_MODELS

ROOT = Path(__file__).resolve().parents[2]
PAGE = ROOT / "docs" / "architecture.md"


def _contract_layers(container: str | None = None) -> list[str]:
    """The layers of the package's contract (``container`` None) or of the contract inside one subpackage."""
    config = tomllib.loads((ROOT / "pyproject.toml").read_text(encoding="utf-8"))
    contracts = [contract for contract in config["tool"]["importlinter"]["contracts"] if contract["type"] == "layers"
                 and contract.get("containers", [None]) == [container]]
    assert len(contracts) == 1
    return list(contracts[0]["layers"])


def _page_layers() -> list[str]:
    # the numbered list of the "Layers" section: "1. `thermogear.cli` — ...", siblings that may import each other
    # as the contract writes them: "2. `thermogear.report` : `thermogear.luo2020.report` — ..."
    section = PAGE.read_text(encoding="utf-8").split("## Layers", 1)[1].split("\n## ", 1)[0]
    heads = re.findall(r"^\d+\. (`thermogear[^—]*?) —", section, flags=re.MULTILINE)
    return [" : ".join(re.findall(r"`(thermogear(?:\.\w+)*)`", head)) for head in heads]


def _numbers() -> list[int]:
    section = PAGE.read_text(encoding="utf-8").split("## Layers", 1)[1].split("\n## ", 1)[0]
    return [int(number) for number in re.findall(r"^(\d+)\. ", section, flags=re.MULTILINE)]


def test_the_page_lists_the_contract_layers_in_order():
    layers = _contract_layers()
    assert len(layers) >= 10 and layers[0] == "thermogear.cli" and layers[-1] == "thermogear.dynamics"
    assert _page_layers() == layers
    assert _numbers() == list(range(1, len(layers) + 1))


def test_the_page_lists_the_dynamics_layers_in_order():
    """The bullets after "split by what it solves" name the dynamics contract's layers, siblings on one line."""
    text = PAGE.read_text(encoding="utf-8").split("is split by what it solves", 1)[1].split("\n\n", 2)[1]
    bullets = [re.findall(r"`(\w+)`", line.split(" — ")[0]) for line in text.splitlines() if line.startswith("- ")]
    assert [" | ".join(names) for names in bullets] == _contract_layers("thermogear.dynamics")


def _example() -> str:
    text = PAGE.read_text(encoding="utf-8").split("## Adding a model", 1)[1]
    blocks = re.findall(r"```python\n(.*?)```", text, flags=re.DOTALL)
    assert len(blocks) == 1
    return blocks[0]


def test_the_example_of_adding_a_model_runs(capsys, monkeypatch):
    code = _example()
    lines = [line for line in code.splitlines() if line.strip() and not line.lstrip().startswith(('"""', "#"))]
    assert len(lines) <= 16  # "a ten-line example": imports, the class and the two lines that use it
    saved = dict(PAIR_MODELS)
    module = types.ModuleType("architecture_example")  # a module of its own, as a script would run in
    monkeypatch.setitem(sys.modules, module.__name__, module)
    namespace = module.__dict__
    try:
        exec(compile(code, str(PAGE), "exec"), namespace)  # noqa: S102 - the page's own example, run as written
        assert "softer" in PAIR_MODELS
        from thermogear.simulation import Simulation

        case = namespace["load_case"]("luo2019")
        softer, elastic = Simulation(case, "softer").state, Simulation(case, "elastic").state
    finally:
        PAIR_MODELS.clear()
        PAIR_MODELS.update(saved)
    response = namespace["response"]
    assert response.label == "softer" and np.all(np.abs(response.multipliers) < 1.0)
    assert re.fullmatch(r"Kv = \d+\.\d{4}\n", capsys.readouterr().out)
    # the stiffness is 0.9 k_e everywhere, so the mesh stiffness is 0.9 times the elastic one (rounding only)
    np.testing.assert_allclose(softer.mesh_stiffness, 0.9 * elastic.mesh_stiffness, rtol=1e-12)
    assert "softer" not in PAIR_MODELS


def test_the_page_cites_no_internal_file():
    text = PAGE.read_text(encoding="utf-8")
    assert "/work/" not in text and "design.md" not in text


def test_the_example_of_adding_a_structure_element_runs(capsys, monkeypatch):
    text = PAGE.read_text(encoding="utf-8").split("## Adding a structure element", 1)[1].split("\n## ", 1)[0]
    blocks = re.findall(r"```python\n(.*?)```", text, flags=re.DOTALL)
    assert len(blocks) == 1
    module = types.ModuleType("architecture_element_example")  # dataclasses need their module in sys.modules
    monkeypatch.setitem(sys.modules, module.__name__, module)
    exec(compile(blocks[0], "architecture.md", "exec"), module.__dict__)
    printed = capsys.readouterr().out
    # four modes in Hz and the spring's largest strain-energy share: the new element is in the assembled stiffness
    assert printed.count(" Hz") == 4
    share = float(printed.split()[-1])
    assert 0.0 < share <= 1.0


def _blocks_before_adding_a_model() -> list[str]:
    text = PAGE.read_text(encoding="utf-8").split("**Results are typed.**", 1)[1].split("\n## Adding a", 1)[0]
    return [textwrap_dedent(block) for block in re.findall(r"```python\n(.*?)```", text, flags=re.DOTALL)]


def textwrap_dedent(block: str) -> str:
    import textwrap

    return textwrap.dedent(block)


def test_the_examples_of_the_typed_results_and_of_a_solver_run(capsys, monkeypatch):
    # issue 33: "where to add" with a short runnable example each (the pair model's is the test above)
    blocks = _blocks_before_adding_a_model()
    assert len(blocks) == 2
    results_block, solver_block = blocks
    namespace: dict = {}
    exec(compile(results_block, str(PAGE), "exec"), namespace)  # noqa: S102 - the page's own example
    results = namespace["results"]
    printed = capsys.readouterr().out
    assert "kv" in printed and "pair" in printed and "thermal" in printed
    assert results.to_dataframe().loc[("pair", "thermal"), "kv"] == results.pair["thermal"].kv
    module = types.ModuleType("architecture_solver_example")
    monkeypatch.setitem(sys.modules, module.__name__, module)
    exec(compile(solver_block, str(PAGE), "exec"), module.__dict__)  # noqa: S102
    response = module.__dict__["response"]
    assert re.fullmatch(r"Kv = \d+\.\d{4}\n", capsys.readouterr().out)
    # the denser sampling of the same exact orbit: the same Kv to how finely the peak is sampled (the orbit is exact
    # at every sample, so only the peak's position between samples differs: 1e-3 is far above that, far below Kv-1)
    assert response.metrics["kv"] == pytest.approx(results.pair["thermal"].kv, rel=1e-3)


def _run_section(title: str, monkeypatch, name: str) -> dict:
    """Run the one python block of the section ``title`` as a module of its own; its namespace."""
    text = PAGE.read_text(encoding="utf-8").split(f"## {title}\n", 1)[1].split("\n## ", 1)[0]
    blocks = re.findall(r"```python\n(.*?)```", text, flags=re.DOTALL)
    assert len(blocks) == 1
    module = types.ModuleType(name)  # dataclasses need their module in sys.modules
    monkeypatch.setitem(sys.modules, module.__name__, module)
    exec(compile(blocks[0], str(PAGE), "exec"), module.__dict__)  # noqa: S102 - the page's own example
    return module.__dict__


def test_the_example_of_adding_a_bearing_model_runs(capsys, monkeypatch):
    import math

    namespace = _run_section("Adding a bearing model", monkeypatch, "architecture_bearing_example")
    printed = capsys.readouterr().out
    assert re.fullmatch(r"bearings \d+\.\d W, oil \d+\.\d °C\n", printed)
    case, description, state = namespace["case"], namespace["description"], namespace["state"]
    # the network dissipates exactly M·ω of each bearing: μ·(its share of the tooth normal force)·d/2 at its
    # shaft's speed (the Coulomb model has no viscous part, so the oil temperature does not enter)
    operating = namespace["gearbox_operating_point"](case.operating_point, case.gearbox)
    normal_force = operating.torque / case.gear_pair.pinion.base_radius
    expected = sum(0.0011 * mounted.load_fraction * normal_force * 15e-3 * 2.0 * math.pi / 60.0
                   * (operating.speed_rpm / case.gear_pair.gear_ratio if mounted.on_wheel_shaft
                      else operating.speed_rpm) for mounted in description.bearings)
    assert state.losses.bearings == pytest.approx(expected, rel=1e-9)


def test_the_example_of_adding_a_loss_correlation_runs(capsys, monkeypatch):
    from thermogear.friction.models import FRICTION_MODELS, friction_law

    saved = dict(FRICTION_MODELS)
    try:
        _run_section("Adding a loss correlation", monkeypatch, "architecture_loss_example")
        assert friction_law("modified_schlenk").name == "modified_schlenk"
    finally:
        FRICTION_MODELS.clear()
        FRICTION_MODELS.update(saved)
    rows = re.findall(r"^(\w+): mesh (\d+\.\d) W, pinion (\d+\.\d) °C$", capsys.readouterr().out, flags=re.MULTILINE)
    assert [row[0] for row in rows] == ["schlenk", "modified_schlenk"]
    (_, mesh, pinion), (_, lower_mesh, lower_pinion) = rows
    # less friction: less mesh loss and a cooler pinion (not 0.75 of the loss: the cooler oil is more viscous)
    assert float(lower_mesh) < float(mesh) and float(lower_pinion) < float(pinion)


def test_the_example_of_adding_a_study_kind_runs(capsys, monkeypatch, tmp_path):
    import xarray as xr

    from thermogear.case import load_case
    from thermogear.simulation import Simulation
    from thermogear.sweep import api

    monkeypatch.chdir(tmp_path)
    monkeypatch.setattr(api, "_REGISTERED", [])
    _run_section("Adding a study kind", monkeypatch, "architecture_kind_example")
    assert [kind.name for kind in api.study_kinds()][0] == "mean_stiffness"
    capsys.readouterr()
    stored = xr.open_dataset(tmp_path / "stiffness.nc", engine="h5netcdf")
    # the point at the case's own flank temperatures is the case's own mean stiffness; the cooler flank another
    as_given = Simulation(load_case("luo2019"), "thermal").state.mean_mesh_stiffness
    thermal = stored["mean_stiffness"].sel(model="thermal")
    assert float(thermal.sel(flank_temperature_offset_c=0.0)) == pytest.approx(as_given, rel=1e-12)
    assert float(thermal.sel(flank_temperature_offset_c=-20.0)) != pytest.approx(as_given, rel=1e-6)
    stored.close()
