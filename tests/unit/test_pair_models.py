"""The pair-model seam: one class per thermal model, chosen once from a registry; the mesh model asks it and never
tests a model's name; a fourth model is one class and one registry line."""

from __future__ import annotations

import ast
from dataclasses import dataclass
from pathlib import Path
from typing import ClassVar

import numpy as np
import pytest

from thermogear.case import load_case
from thermogear.errors import CaseError
from thermogear.mesh.model import MeshModel
from thermogear.mesh.pair_models import (PAIR_MODELS, ElasticPair, Luo2020Pair, PairModelBase, ThermoelasticPair,
                                         pair_model_class)
from thermogear.stiffness.table import pair_stiffness_at

MESH = Path(__file__).resolve().parents[2] / "src" / "thermogear" / "mesh"


@pytest.fixture(scope="module")
def luo2019():
    return load_case("luo2019")


def _roll(pair, count=9):
    points = pair.path_points
    return np.linspace(points["A"], points["E"], count)


def test_the_registry_holds_one_class_per_model():
    assert PAIR_MODELS == {"elastic": ElasticPair, "luo2020": Luo2020Pair, "thermoelastic": ThermoelasticPair}


@pytest.mark.parametrize(("model", "thermal_model", "expected"), [
    ("elastic", "luo2020", ElasticPair), ("thermal", "luo2020", Luo2020Pair),
    ("elastic", "thermoelastic", ElasticPair), ("thermal", "thermoelastic", ThermoelasticPair)])
def test_a_model_name_resolves_once_to_its_pair_model(luo2019, model, thermal_model, expected):
    case = luo2019.with_changes(**{"thermal.model": thermal_model})
    assert pair_model_class(model, thermal_model) is expected
    assert type(MeshModel(case, model).pair_model) is expected


def test_a_name_without_a_class_is_a_case_error(luo2019, monkeypatch):
    monkeypatch.delitem(PAIR_MODELS, "luo2020")
    with pytest.raises(CaseError, match="thermal.model"):
        pair_model_class("thermal", luo2019.thermal.model)


def test_elastic_pair_is_the_elastic_stiffness_table(luo2019):
    roll = _roll(luo2019.gear_pair)
    expected = pair_stiffness_at(luo2019.gear_pair, luo2019.material, roll)
    pair = ElasticPair(luo2019)
    assert np.array_equal(pair.pair_stiffness_at(roll, 1e4), expected)
    assert np.array_equal(pair.damping_stiffness_at(roll, 1e4), expected)
    assert pair.temperature is None
    assert np.all(pair.friction_temperature_c(np.zeros(3)) == luo2019.lubricant.reference_temperature_c)


def test_luo2020_pair_without_thermal_strain_is_the_elastic_pair(luo2019):
    # X_te = 0 removes the thermal term of Eq. 18: k_T = k_e (to rounding of the secant's quotient)
    case = luo2019.with_changes(**{"thermal.x_te_source": "given", "thermal.x_te": 0.0})
    roll = _roll(case.gear_pair)
    np.testing.assert_allclose(Luo2020Pair(case).pair_stiffness_at(roll, 1e4),
                               ElasticPair(case).pair_stiffness_at(roll, 1e4), rtol=1e-12)
    assert not np.any(Luo2020Pair(case).pair_deviation_at(roll))


def test_luo2020_pair_lowers_the_stiffness_and_keeps_the_cold_geometry(luo2019):
    pair, elastic = Luo2020Pair(luo2019), ElasticPair(luo2019)
    roll = _roll(luo2019.gear_pair)
    assert np.all(pair.pair_stiffness_at(roll, 1e4) < elastic.pair_stiffness_at(roll, 1e4))
    assert pair.gear_pair is luo2019.gear_pair and pair.stiffness_depends_on_load


def test_thermoelastic_pair_meshes_on_the_hot_pair(luo2019):
    case = luo2019.with_changes(**{"thermal.model": "thermoelastic"})
    pair = ThermoelasticPair(case)
    assert pair.gear_pair is pair.thermoelastic_mesh.gear_pair and pair.gear_pair is not case.gear_pair
    assert pair.backlash == pair.thermoelastic_mesh.backlash_normal
    assert pair.load_shares_depend_on_load and pair.damping_uses_pair_stiffness


def _compared_model_names(path: Path) -> list[str]:
    names = set(PAIR_MODELS) | {"thermal"}
    tree = ast.parse(path.read_text(encoding="utf-8"))
    operands = [operand for node in ast.walk(tree) if isinstance(node, ast.Compare)
                for operand in (node.left, *node.comparators)]
    return [operand.value for operand in operands if isinstance(operand, ast.Constant) and operand.value in names]


def test_the_mesh_model_and_its_checks_never_test_a_model_name(tmp_path):
    # the seam's promise: the mesh model and its result checks compare no string with a pair model's name (the
    # per-model answers live in pair_models.py)
    assert _compared_model_names(MESH / "model.py") == []  # "is this the thermal model?" is the pair model's answer
    assert _compared_model_names(MESH / "plausibility.py") == []
    planted = tmp_path / "planted.py"  # the scan can fail: a planted test of a model name is found
    planted.write_text('if mesh.thermal_model == "luo2020":\n    pass\n', encoding="utf-8")
    assert _compared_model_names(planted) == ["luo2020"]


@dataclass(frozen=True, eq=False)
class DoubledStiffness(PairModelBase):
    """A fourth model for the test: the elastic pair twice as stiff."""

    name: ClassVar[str] = "doubled"

    def pair_stiffness_at(self, roll, normal_load: float) -> np.ndarray:
        return 2.0 * self.elastic_pair_stiffness_at(roll)


def test_a_fourth_model_is_one_class_and_one_registry_line(luo2019, monkeypatch):
    # the registry line (here in place of the case's thermal model name, which the schema restricts)
    monkeypatch.setitem(PAIR_MODELS, "luo2020", DoubledStiffness)
    doubled = MeshModel(luo2019, "thermal").state(points_per_period=64, damping=False)
    elastic = MeshModel(luo2019, "elastic").state(points_per_period=64, damping=False)
    np.testing.assert_allclose(doubled.mesh_stiffness, 2.0 * elastic.mesh_stiffness, rtol=1e-12)


@pytest.mark.parametrize("load", [{}, {"operating.power_kw": None, "operating.torque_nm": 380.0}])
def test_normal_loads_at_many_speeds_equal_the_one_by_one_loads(luo2019, load):
    # speed and load from one place (the operating point): the vectorised path is the scalar one, bit for bit,
    # under a power (w ∝ 1/n1, the case's own speed giving its own torque) and under a torque
    case = luo2019.with_changes(**load) if load else luo2019
    mesh = MeshModel(case, "elastic")
    speeds = np.array([500.0, 1234.5, case.operating_point.speed_rpm, 6000.0])
    loads = mesh.normal_loads(speeds)
    assert loads.tolist() == [mesh.normal_load(speed) for speed in speeds]
    assert case.operating_point.constant_power == (not load)


def test_every_thermal_model_the_schema_allows_has_a_pair_model():
    # the case file's [thermal] model names (read by the schema from the thermal models' rules, below the mesh
    # model) and the pair-model registry must agree
    import typing

    from thermogear.schema.thermal import ThermalSection

    allowed = set(typing.get_args(ThermalSection.model_fields["model"].annotation))
    assert allowed | {"elastic"} == set(PAIR_MODELS)


def test_each_thermal_pair_model_declares_the_rules_of_its_name():
    # the input rules checked at load time (thermal_model_rules) are the pair model's own: one object per model
    from thermogear.choices.thermal_models import THERMAL_MODEL_RULES

    with_rules = {name: model for name, model in PAIR_MODELS.items() if model.rules is not None}
    assert set(with_rules) == set(THERMAL_MODEL_RULES)
    for name, model in with_rules.items():
        assert model.rules is THERMAL_MODEL_RULES[name] and model.name == name
        assert model.uses_x_te == model.rules.reads_x_te
    assert ElasticPair.rules is None


def test_a_model_with_rules_runs_only_on_a_case_of_its_thermal_model(luo2019):
    # the thermo-elastic case was not checked against the paper's rules (X_te, heating only) when it was loaded
    predictive = luo2019.with_changes(**{"thermal.model": "thermoelastic"})
    with pytest.raises(CaseError, match="thermal.model"):
        pair_model_class("luo2020", predictive.thermal.model)
    assert pair_model_class("luo2020", luo2019.thermal.model) is Luo2020Pair
    with pytest.raises(CaseError, match="unknown model"):
        MeshModel(luo2019, "no_such_model")
