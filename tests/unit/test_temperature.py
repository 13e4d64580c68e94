"""TemperatureField and the [temperature] input: fits, table checks, limits, providers."""

from __future__ import annotations

import sys
import types

import warnings

import numpy as np
import pytest

from thermogear.errors import CaseError, ExtrapolationWarning, ModelAssumptionWarning, ThermogearError
import thermogear.temperature.source as temperature_module
from thermogear.temperature.field import LUO2020_LIMITS, MATERIAL_MINIMUM_C, THERMOELASTIC_LIMITS
from thermogear.temperature.source import (MATERIAL_MAXIMUM_C, TemperatureField, check_flank_table,
                                            check_temperatures, temperature_field_from_case)

BODY = dict(pinion_base_c=70.0, pinion_bore_c=65.0, wheel_base_c=70.0, wheel_bore_c=65.0)


def test_uniform_field_is_constant_everywhere():
    field = TemperatureField.uniform(60.0, reference_c=20.0)
    gamma = np.linspace(-2.0, 2.0, 7)
    np.testing.assert_array_equal(field.pinion_flank_c(gamma), 60.0)
    np.testing.assert_array_equal(field.wheel_flank_c(gamma), 60.0)
    assert (field.pinion_base_c, field.pinion_bore_c, field.wheel_base_c, field.wheel_bore_c) == (60.0,) * 4
    assert field.rise(60.0) == pytest.approx(40.0)


def test_fit_reproduces_a_polynomial_of_its_own_degree():
    gamma = np.linspace(-0.6, 0.6, 9)
    flank = 77.0 + 5.0 * gamma**2 - 1.0 * gamma  # exactly quadratic
    field = TemperatureField.from_table(gamma, flank, 2, **BODY)
    probe = np.array([-0.55, -0.1, 0.0, 0.33])
    np.testing.assert_allclose(field.pinion_flank_c(probe), 77.0 + 5.0 * probe**2 - probe, rtol=0, atol=1e-10)
    assert field.fit_range == (-0.6, 0.6)


def test_rank_deficient_fit_is_refused_with_its_key():
    # four distinct positions, three of them 1e-13 apart on a unit span: the scaled Vandermonde matrix of degree 3
    # is singular to double precision, so the fit cannot determine the polynomial (NumPy reports rank 2 or 3 < 4)
    from thermogear.temperature.field import fit_flank_polynomial

    with pytest.raises(CaseError) as raised:
        fit_flank_polynomial([0.0, 1e-13, 2e-13, 1.0], [60.0, 61.0, 62.0, 70.0], 3)
    assert raised.value.key == "temperature.fit_degree"
    assert fit_flank_polynomial([0.0, 0.3, 0.6, 1.0], [60.0, 61.0, 62.0, 70.0], 3).degree() == 3


def test_wheel_flank_offset():
    field = TemperatureField.from_table([-1, 0, 1], [80, 78, 80], 2, wheel_flank_offset_c=-3.0, **BODY)
    assert field.wheel_flank_c(0.0) == pytest.approx(75.0)


@pytest.mark.parametrize("gamma, flank, degree, key, words", [
    ([-0.5, 0.0, 0.0, 0.5], [80, 78, 78, 80], 2, "temperature.gamma", "twice"),
    ([-0.5, 0.2, 0.0, 0.5], [80, 78, 78, 80], 2, "temperature.gamma", "decreases"),
    ([-0.5, 0.0, 0.5], [80, 78, 80], 3, "temperature.fit_degree", "at least 4"),
    ([-0.5, 0.0, 0.5], [80, 78], 1, "temperature.flank_c", "one temperature per"),
    ([0.0], [80.0], 0, "temperature.gamma", "at least two"),
    ([-0.5, np.nan, 0.5], [80, 78, 80], 1, "temperature.gamma", "NaN"),
])
def test_bad_tables_are_refused(gamma, flank, degree, key, words):
    with pytest.raises(CaseError) as caught:
        check_flank_table(gamma, flank, degree)
    assert caught.value.key == key
    assert words in str(caught.value)


def test_evaluation_outside_the_table_warns():
    field = TemperatureField.from_table([-0.5, 0.0, 0.5], [80, 78, 80], 2, **BODY)
    with pytest.warns(ExtrapolationWarning, match="outside the table"):
        field.pinion_flank_c([0.0, 0.7])


def test_table_must_span_the_path():
    field = TemperatureField.from_table([-0.5, 0.0, 0.4], [80, 78, 80], 2, **BODY)
    with pytest.raises(CaseError, match="does not span the path"):
        check_temperatures(field, -0.54, 0.52)
    check_temperatures(field, -0.5, 0.4)  # exactly spanning is fine


@pytest.mark.parametrize("changes, key", [
    ({"pinion_bore_c": 15.0}, "temperature.pinion_bore_c"),
    ({"wheel_base_c": 10.0}, "temperature.wheel_base_c"),
    ({"wheel_flank_offset_c": -70.0}, "temperature.wheel_flank_offset_c"),
])
def test_below_reference_is_refused_by_the_papers_model(changes, key):
    arguments = dict(BODY, **{k: v for k, v in changes.items() if k in BODY})
    offset = changes.get("wheel_flank_offset_c", 0.0)
    field = TemperatureField.from_table([-1, 0, 1], [80, 78, 80], 2, wheel_flank_offset_c=offset, **arguments)
    with pytest.raises(CaseError, match="below the stress-free reference") as caught:
        check_temperatures(field, -0.5, 0.5, limits=LUO2020_LIMITS)
    assert caught.value.key == key
    assert "thermal.model = 'luo2020'" in str(caught.value) and "Eqs. 13–17" in str(caught.value)
    check_temperatures(field, -0.5, 0.5, limits=THERMOELASTIC_LIMITS)  # contraction: the thermo-elastic model runs


def test_flank_table_below_reference_is_refused_by_the_papers_model():
    field = TemperatureField.from_table([-1, 0, 1], [30, 15, 30], 2, **BODY)
    with pytest.raises(CaseError, match="below the stress-free reference") as caught:
        check_temperatures(field, -0.5, 0.5, limits=LUO2020_LIMITS)
    assert caught.value.key == "temperature.flank_c"


@pytest.mark.parametrize("bulk_c", [0.0, -30.0, MATERIAL_MINIMUM_C])
def test_cold_start_is_evaluated_by_the_thermoelastic_model(bulk_c):
    """Gears colder than their assembly (issue 28: down to −40 °C) contract; the default model evaluates that."""
    check_temperatures(TemperatureField.uniform(bulk_c, reference_c=20.0), -0.5, 0.5)


def test_below_the_material_data_is_refused_naming_the_model():
    field = TemperatureField.uniform(MATERIAL_MINIMUM_C - 0.5, reference_c=20.0)
    with pytest.raises(CaseError, match="thermal.model = 'thermoelastic'") as caught:
        check_temperatures(field, -0.5, 0.5)
    assert caught.value.key == "temperature.bulk_c" and "Luo & Li" not in str(caught.value)


def test_above_material_data_is_refused():
    field = TemperatureField.uniform(MATERIAL_MAXIMUM_C + 1.0)
    with pytest.raises(CaseError, match="material data") as caught:
        check_temperatures(field, -0.5, 0.5)
    assert caught.value.key == "temperature.bulk_c"


def test_above_lubricant_data_warns():
    field = TemperatureField.uniform(120.0)
    with pytest.warns(ExtrapolationWarning, match="lubricant"):
        check_temperatures(field, -0.5, 0.5, lubricant_maximum_c=100.0)


def test_wiggling_fit_is_reported():
    gamma = np.linspace(-0.6, 0.6, 8)
    flank = np.array([80, 78, 80, 78, 80, 78, 80, 78], dtype=float)
    field = TemperatureField.from_table(gamma, flank, 7, **BODY)  # interpolating degree-7: Runge wiggles
    with pytest.warns(ModelAssumptionWarning, match="wiggle"):
        check_temperatures(field, -0.6, 0.6)


# ------------------------------------------------------------------------------------------------ cases
def test_luo2019_field_follows_the_paper_description(luo2019):
    field = temperature_field_from_case(luo2019)
    assert field.source == "tabulated" and field.reference_c == 20.0
    gamma = np.linspace(-0.6, 0.5, 221)
    flank = field.pinion_flank_c(gamma)
    # Fig. 3(c) as described: 77–81 °C over Γ in [−0.6, 0.5] (fit within ±0.2 K of the table's extremes),
    # lowest near the pitch point, highest toward the root and the tip.
    assert 76.8 <= flank.min() and flank.max() <= 81.2
    assert abs(gamma[np.argmin(flank)]) < 0.15
    assert flank[0] > flank[np.argmin(flank)] + 3.0 and flank[-1] > flank[np.argmin(flank)] + 2.0


def test_case_uniform_field(luo2019):
    case = luo2019.with_changes(temperature={"model": "uniform", "bulk_c": 60.0})
    field = temperature_field_from_case(case)
    assert field.pinion_flank_c(0.3) == pytest.approx(60.0) and field.wheel_bore_c == 60.0


def test_case_uniform_refuses_table_keys(luo2019):
    # refused when the case is loaded (issue 15: one set of checks, at load time)
    with pytest.raises(CaseError, match="pinion_base_c"):
        luo2019.with_changes(temperature={"model": "uniform", "bulk_c": 60.0, "pinion_base_c": 50.0})
    # without bulk_c the gears are at the oil's operating temperature (issue 24: the documented-optional section
    # used to be refused), and the case says so in a note
    defaulted = luo2019.with_changes(temperature={"model": "uniform"})
    assert defaulted.temperature.bulk_c == luo2019.lubricant.operating_temperature_c
    assert temperature_field_from_case(defaulted).pinion_flank_c(0.0) == pytest.approx(
        luo2019.lubricant.operating_temperature_c, rel=1e-12)
    assert len(defaulted.notes) == 1 and "lubricant.operating_temperature_c" in defaulted.notes[0]


def test_case_table_from_csv(luo2019, tmp_path):
    path = tmp_path / "flank.csv"
    path.write_text("# flank temperatures\ngamma,flank_c\n-0.6,81\n-0.2,78\n0.0,77\n0.3,78\n0.6,80.5\n")
    document = dict(luo2019.document["temperature"])
    del document["gamma"], document["flank_c"]
    document.update(csv=str(path), fit_degree=2)
    field = temperature_field_from_case(luo2019.with_changes(temperature=document))
    assert field.source == "tabulated (csv)" and field.fit_range == (-0.6, 0.6)
    with pytest.raises(CaseError, match="no such file"):
        temperature_field_from_case(luo2019.with_changes(temperature=dict(document, csv=str(tmp_path / "x.csv"))))


def test_case_missing_wheel_temperatures_are_assumed_with_a_warning(luo2019):
    document = dict(luo2019.document["temperature"])
    del document["wheel_base_c"], document["wheel_bore_c"]
    with pytest.warns(ModelAssumptionWarning, match="taken equal to the pinion"):
        field = temperature_field_from_case(luo2019.with_changes(temperature=document))
    assert field.wheel_base_c == field.pinion_base_c


def test_case_table_too_short_for_the_path(luo2019):
    document = dict(luo2019.document["temperature"], gamma=[-0.6, 0.0, 0.5], flank_c=[81, 77, 80], fit_degree=2)
    with pytest.raises(CaseError, match="does not span the path"):
        temperature_field_from_case(luo2019.with_changes(temperature=document))


def test_fem_without_provider_is_a_clear_error(luo2019, monkeypatch):
    # an installation without the FE model: no provider registered, and importing the provider module adds none
    monkeypatch.setattr(temperature_module, "_PROVIDERS", {})
    monkeypatch.setitem(sys.modules, "thermogear.fem.provider", types.ModuleType("thermogear.fem.provider"))
    with pytest.raises(ThermogearError, match="finite-element bulk-temperature model is not registered"):
        temperature_field_from_case(luo2019.with_changes(temperature={"model": "fem"}))


def test_registered_provider_is_used_and_checked(luo2019, monkeypatch):
    monkeypatch.setattr(temperature_module, "_PROVIDERS", {})
    temperature_module.register_temperature_provider("fem", lambda case: TemperatureField.uniform(55.0))
    field = temperature_field_from_case(luo2019.with_changes(temperature={"model": "fem"}))
    assert field.pinion_base_c == 55.0
    temperature_module.register_temperature_provider("fem", lambda case: TemperatureField.uniform(10.0))
    with pytest.raises(CaseError, match="below the stress-free"):
        temperature_field_from_case(luo2019.with_changes(temperature={"model": "fem"}))


def test_no_warning_for_the_luo2019_set(luo2019):
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        temperature_field_from_case(luo2019)
