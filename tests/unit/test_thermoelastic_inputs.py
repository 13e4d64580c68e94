"""Thermo-elastic inputs: defaults named, bad input refused at load time with key, value, range and reason."""

from __future__ import annotations

import pytest

from thermogear.case import case_from_document, load_case
from thermogear.errors import CaseError

from test_thermoelastic_operating import document


@pytest.mark.parametrize("change, key, words", [
    (lambda d: d["housing"].update(thermal_expansion_per_k=40e-6), "housing.thermal_expansion_per_k", "<="),
    (lambda d: d["housing"].update(thermal_expansion_per_k=2e-6), "housing.thermal_expansion_per_k", ">="),
    (lambda d: d["housing"].update(temperature_c=350.0), "housing.temperature_c", "<="),
    (lambda d: d["gears"].update(backlash_normal_um=-5.0), "gears.backlash_normal_um", ">="),
    (lambda d: d["gears"].update(backlash_normal_um=12000.0), "gears.backlash_normal_um", "base pitch"),
    (lambda d: d["gears"]["pinion"].update(tip_relief_um=20.0, tip_relief_length_mm=25.0),
     "gears.pinion.tip_relief_length_mm", "path of contact"),
    (lambda d: (d["gears"].update(module_mm=1.0), d["gears"]["pinion"].update(bore_radius_mm=3.0),
                d["gears"]["wheel"].update(bore_radius_mm=8.0, tip_relief_um=500.0, tip_relief_length_mm=1.0)),
     "gears.wheel.tip_relief_um", "tip thickness"),  # m 1 mm: the wheel's tip half-thickness is ≈ 0.36 mm
    (lambda d: d["gears"]["wheel"].update(tip_relief_um=20.0), "gears.wheel.tip_relief_length_mm", "length"),
    (lambda d: d["temperature"].update(bulk_c=230.0), "temperature.bulk_c", "200"),  # refused by the schema or the material check
    (lambda d: d["material"].update(youngs_modulus_temperature_coefficient_per_k=-5e-3),
     "material.youngs_modulus_temperature_coefficient_per_k", ">="),
    (lambda d: (d["gears"].update(backlash_normal_um=20.0), d["temperature"].update(bulk_c=150.0)),
     "temperature.bulk_c", "jam"),
])
def test_bad_input_is_refused_at_load_time(change, key, words):
    doc = document()
    doc.setdefault("material", {})
    change(doc)
    with pytest.raises(CaseError) as raised:
        case_from_document(doc)
    error = raised.value
    assert error.key == key
    assert words in f"{error.allowed} {error.reason}"


def test_jamming_message_names_the_closing_temperature():
    doc = document(bulk=150.0, backlash=20.0)
    with pytest.raises(CaseError, match="closes at a bulk temperature of"):
        case_from_document(doc)


def test_given_backlash_below_the_centre_distance_backlash_is_refused():
    doc = document()
    doc["gears"]["centre_distance_mm"] = 168.2  # 0.2 mm above the tight mesh: ≈ 137 μm of backlash
    doc["gears"]["backlash_normal_um"] = 50.0
    with pytest.raises(CaseError) as raised:
        case_from_document(doc)
    assert raised.value.key == "gears.backlash_normal_um"


def test_parameter_sets_name_their_thermal_model():
    assert load_case("luo2019").thermal.model == "luo2020"  # the paper's report does not move
    assert load_case("fzg_type_c").thermal.model == "thermoelastic"
    assert case_from_document(document()).thermal.model == "thermoelastic"  # the default
