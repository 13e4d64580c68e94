"""The [gearbox] case section and the "gearbox" temperature model (predicted temperatures every command sees)."""

from __future__ import annotations

import json
import tomllib
import warnings
from pathlib import Path

import numpy as np
import pytest

import thermogear.simulation  # noqa: F401  (the composition root registers the "gearbox" temperature provider)
from thermogear.case import case_from_document, load_case
from thermogear.errors import CaseError
from thermogear.gearbox.description import GearboxOperatingPoint
from thermogear.gearbox.case_model import (gearbox_model_from_case,
                                           gearbox_operating_point, predicted_steady_state)
from thermogear.temperature.source import temperature_field_from_case

CASE = Path(__file__).parents[1] / "data" / "gearbox" / "fzg_gearbox.toml"


def document() -> dict:
    return tomllib.loads(CASE.read_text(encoding="utf-8"))


def changed(dotted: str, value) -> dict:
    result = document()
    node = result
    *parents, last = dotted.split(".")
    for part in parents:
        node = node.setdefault(part, {})
    if value is None:
        node.pop(last, None)
    else:
        node[last] = value
    return result


@pytest.fixture(scope="module")
def case():
    return load_case(CASE)


def steady(case):
    """The steady state the case's gearbox model predicts at its operating point."""
    return predicted_steady_state(gearbox_model_from_case(case), gearbox_operating_point(case.operating_point,
                                                                                         case.gearbox))


def test_case_without_gearbox_is_as_before():
    case = load_case("fzg_type_c")
    assert case.gearbox is None
    assert case.temperature.model == "uniform"
    assert case.lubricant.operating_temperature_c == 60.0 and case.housing.temperature_c is None


def test_predicted_temperatures_are_the_steady_state(case):
    state = steady(case)
    assert state.energy_residual < 1e-9  # the network's acceptance: heat out equals the losses
    # every command reads the oil and housing from the case: the predicted values (rounded to 1e-6 K)
    assert case.lubricant.operating_temperature_c == pytest.approx(state.oil_c, abs=1e-6)
    assert case.housing.temperature_c == pytest.approx(state.housing_c, abs=1e-6)
    field = temperature_field_from_case(case)
    assert field.pinion_base_c == pytest.approx(state.pinion_c, abs=1e-6)
    assert float(field.wheel_flank_c(0.0)) == pytest.approx(state.wheel_c, abs=1e-6)
    assert "predicted" in field.source and "mesh" in field.source
    assert any("predicted by the gearbox thermal model" in line for line in case.assumptions)
    # physical order: the gears carry the friction heat, the housing sheds it: gears > oil > housing > ambient
    assert state.pinion_c > state.oil_c > state.housing_c > 20.0


def test_prediction_follows_the_operating_point(case):
    slow = case.with_changes(**{"operating.speed_rpm": 400.0})
    assert slow.lubricant.operating_temperature_c < case.lubricant.operating_temperature_c - 5.0


def test_steady_state_is_solved_once_per_model_and_operating_point(case):
    # the memo is keyed on what determines the state: the same model and operating point give the state solved
    # first (the same object), another operating point of the same model its own solution, bit for bit the
    # model's own (a memo keyed on the model alone would hand back the first point's state)
    model = gearbox_model_from_case(case)
    operating = gearbox_operating_point(case.operating_point, case.gearbox)
    assert predicted_steady_state(model, operating) is predicted_steady_state(model, operating)
    slower = gearbox_operating_point(case.operating_point, case.gearbox, speed_rpm=0.5 * operating.speed_rpm)
    state = predicted_steady_state(model, slower)
    np.testing.assert_array_equal(state.temperatures_c, model.steady_state(slower).temperatures_c)
    assert state.oil_c < predicted_steady_state(model, operating).oil_c  # less speed, less loss, cooler oil


def test_steady_state_memo_raises_its_warnings_again():
    # a model that warns and counts its solutions: solved once, its warning raised again on the second call
    class WarningModel:
        solved = 0

        def steady_state(self, operating):
            WarningModel.solved += 1
            warnings.warn("viscosity fit extrapolated", UserWarning, stacklevel=1)
            return object()

    model, operating = WarningModel(), GearboxOperatingPoint(1000.0, 100.0)
    with pytest.warns(UserWarning, match="extrapolated"):
        first = predicted_steady_state(model, operating)
    with pytest.warns(UserWarning, match="extrapolated"):
        second = predicted_steady_state(model, operating)
    assert first is second and WarningModel.solved == 1


def test_section_values_reach_the_description(case):
    description = gearbox_model_from_case(case).description
    assert description.oil_volume == pytest.approx(1.25e-3, rel=1e-12)
    assert description.housing.length == pytest.approx(0.45, rel=1e-12)
    assert description.housing.expansion == pytest.approx(11.4e-6, rel=1e-12)  # cast iron, thermoelastic table
    assert len(description.bearings) == 4 and sum(b.on_wheel_shaft for b in description.bearings) == 2
    assert description.wheel_immersion == pytest.approx(case.gear_pair.operating_pitch_radii[1], rel=1e-12)
    operating = gearbox_operating_point(case.operating_point, case.gearbox)
    assert (operating.speed_rpm, operating.torque, operating.ambient_c) == (1400.0, 138.0, 20.0)


def test_outer_area_is_a_cube_of_that_area():
    side = 0.35
    base = changed("gearbox.housing.length_mm", side * 1e3)
    base["gearbox"]["housing"].update(width_mm=side * 1e3, height_mm=side * 1e3)
    by_area = changed("gearbox.housing.length_mm", None)
    for key in ("width_mm", "height_mm"):
        by_area["gearbox"]["housing"].pop(key)
    by_area["gearbox"]["housing"]["outer_area_m2"] = 5.0 * side**2  # four walls and the top
    first = steady(case_from_document(base))
    second = steady(case_from_document(by_area))
    np.testing.assert_allclose(first.temperatures_c, second.temperatures_c, rtol=1e-9)


def test_other_temperature_model_keeps_given_temperatures_and_the_gearbox_still_works():
    document_uniform = changed("temperature.model", "uniform")
    document_uniform["temperature"]["bulk_c"] = 70.0
    case = case_from_document(document_uniform)
    assert case.lubricant.operating_temperature_c == 60.0 and temperature_field_from_case(case).pinion_base_c == 70.0
    state = gearbox_model_from_case(case).steady_state(gearbox_operating_point(case.operating_point, case.gearbox))
    assert state.oil_c > 20.0


@pytest.mark.parametrize("dotted, value, key", [
    ("gearbox.housing.length_mm", -5.0, "gearbox.housing.length_mm"),
    ("gearbox.housing.emissivity", 1.5, "gearbox.housing.emissivity"),
    ("gearbox.housing.mass_kg", None, "gearbox.housing.mass_kg"),
    ("gearbox.housing.outer_area_m2", 2.0, "gearbox.housing.outer_area_m2"),
    ("gearbox.oil.volume_l", 0.0, "gearbox.oil.volume_l"),
    ("gearbox.oil.lubrication", "spray", "gearbox.oil.lubrication"),
    ("gearbox.oil.lubrication", "injection", "gearbox.oil.injection_flow_l_min"),  # no jet given
    ("gearbox.oil.jet_speed_m_s", 5.0, "gearbox.oil.jet_speed_m_s"),  # a jet under dip lubrication
    ("gearbox.oil.jet_position", "outlet", "gearbox.oil.jet_position"),  # likewise
    ("gearbox.oil.injection_flow_l_min", 0.0, "gearbox.oil.injection_flow_l_min"),
    ("gearbox.ambient_c", 120.0, "gearbox.ambient_c"),
    ("gearbox.internal.gear_oil_w_per_m2_k", -1.0, "gearbox.internal.gear_oil_w_per_m2_k"),
    ("gearbox.oil.wheel_immersion_mm", 500.0, "gearbox.oil.wheel_immersion_mm"),
    ("gearbox.oil.pinion_immersion_mm", 90.0, "gearbox.oil.pinion_immersion_mm"),
    ("gearbox.housing.speed", 3.0, "gearbox.housing.speed"),
    ("housing.temperature_c", 50.0, "housing.temperature_c"),
    ("lubricant.operating_temperature_c", 60.0, "lubricant.operating_temperature_c"),
])
def test_bad_values_name_key_value_and_range(dotted, value, key):
    with pytest.raises(CaseError) as error:
        case_from_document(changed(dotted, value))
    assert error.value.key == key


def test_bearing_needs_designation_or_constants():
    bad = document()
    bad["gearbox"]["bearings"][0] = {"shaft": "pinion", "type": "cylindrical_roller", "bore_mm": 30.0}
    with pytest.raises(CaseError) as error:
        case_from_document(bad)
    assert error.value.key == "gearbox.bearings.outside_mm"
    bad["gearbox"]["bearings"][0] = {"shaft": "pinion", "designation": "NJ406", "bore_mm": 30.0}
    with pytest.raises(CaseError) as error:
        case_from_document(bad)
    assert error.value.key == "gearbox.bearings.bore_mm"


def test_explicit_bearing_constants_equal_the_designation():
    explicit = document()
    constants = dict(shaft="pinion", count=2, type="cylindrical_roller", bore_mm=30.0, outside_mm=90.0,
                     width_mm=23.0, rolling_constant=1.00e-6, sliding_constants=[0.16, 0.0015],
                     geometry_constant=5.1, drag_variable=1.49e-4)
    explicit["gearbox"]["bearings"][0] = constants
    first = steady(case_from_document(document()))
    second = steady(case_from_document(explicit))
    assert second.losses.bearings == pytest.approx(first.losses.bearings, rel=1e-12)


def test_gearbox_model_needs_the_section():
    bad = document()
    del bad["gearbox"]
    with pytest.raises(CaseError) as error:
        case_from_document(bad)
    assert error.value.key == "gearbox"


def test_run_says_the_temperatures_were_predicted():
    from typer.testing import CliRunner

    import thermogear.cli.run  # noqa: F401
    from thermogear.cli.app import app

    result = CliRunner().invoke(app, ["run", str(CASE), "--model", "thermal", "--json"])
    assert result.exit_code == 0, result.output
    payload = json.loads(result.stdout[result.stdout.index("{"):])
    assert payload["temperatures"].startswith("temperatures predicted by the gearbox thermal model")
    assert "mesh" in payload["temperatures"] and "churning" in payload["temperatures"]


def test_gearbox_section_is_checked_under_another_temperature_model():
    bad = changed("gearbox.oil.wheel_immersion_mm", 500.0)
    bad["temperature"] = {"model": "uniform", "bulk_c": 70.0, "reference_c": 20.0}
    with pytest.raises(CaseError) as error:
        case_from_document(bad)
    assert error.value.key == "gearbox.oil.wheel_immersion_mm"
