"""The FE verification reads a case once (issue 26): :func:`fem_inputs` resolves it into the frozen FemInputs that
the heat, elastic and thermo-elastic models take, and their memo key follows the case's content."""

from __future__ import annotations

import dataclasses
import warnings

import pytest

from thermogear import load_case
from thermogear.fem.inputs import fem_inputs


@pytest.fixture(scope="module", params=["luo2019", "fzg_type_c"])
def case(request):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return load_case(request.param)


def test_the_inputs_are_what_the_case_gives(case):
    inputs = fem_inputs(case)
    assert inputs.name == case.name
    assert inputs.gear_pair is case.gear_pair and inputs.material is case.material
    assert inputs.settings is case.fem and inputs.lubricant is case.lubricant
    assert inputs.normal_load == case.normal_load  # T1 / r_b1, the same arithmetic
    assert inputs.reference_c == case.temperature.reference_c
    assert inputs.expansion_model == case.thermal.expansion_model
    with pytest.raises(dataclasses.FrozenInstanceError):
        inputs.normal_load = 0.0


def test_the_friction_model_is_the_operating_point_with_the_oil_at_its_operating_temperature(case):
    friction = fem_inputs(case).friction
    assert friction.model == "elastic"
    assert friction.speed_rpm == case.operating_point.speed_rpm
    assert friction.normal_load() == pytest.approx(case.normal_load, rel=1e-15)
    changed = friction.case.lubricant
    assert changed.reference_temperature_c == case.lubricant.operating_temperature_c
    # only that temperature moved: the rest of the oil section is the case's
    assert changed.model_copy(update={"reference_temperature_c": case.lubricant.reference_temperature_c}) \
        == case.lubricant


def test_the_memo_key_follows_the_document_not_the_load(case):
    # two loads of one case share an analysis; another speed (another heat input) does not
    again = load_case(case.source)
    assert again is not case
    assert fem_inputs(again).document_key == fem_inputs(case).document_key
    faster = case.with_changes(**{"operating.speed_rpm": 1.5 * case.operating_point.speed_rpm})
    assert fem_inputs(faster).document_key != fem_inputs(case).document_key
