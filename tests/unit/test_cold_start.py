"""A cold start (issue 28): gears and housing colder than their assembly temperature under the default
thermo-elastic model — the case loads, the gears contract and stiffen, the backlash follows the housing."""

from __future__ import annotations

import math
import warnings

import pytest

from thermogear.errors import CaseError
from thermogear.thermoelastic.materials import HOUSING_EXPANSION_PER_K
from thermogear.thermoelastic.mesh import ThermoelasticMesh

COLD_C = -30.0  # issue 28: an aluminium housing at −30 °C


@pytest.fixture(scope="module")
def cold_mesh():
    from thermogear import load_case

    case = load_case("fzg_type_c").with_changes(**{
        "thermal.model": "thermoelastic", "temperature.model": "uniform", "temperature.bulk_c": COLD_C,
        "temperature.reference_c": 20.0, "housing.material": "aluminium", "housing.temperature_c": COLD_C})
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # the fits' extrapolation warnings are tested where they are issued
        return case, ThermoelasticMesh.from_case(case)


def test_cold_gears_are_stiffer_by_their_modulus_law(cold_mesh):
    _, mesh = cold_mesh
    for cold, at_temperature, inputs in zip(mesh.youngs_modulus_cold, mesh.youngs_modulus, mesh.gears):
        beta = inputs.modulus_coefficient_per_k
        assert at_temperature > cold  # β_E < 0: E rises as T falls
        # E(T) = E(20 °C)·[1 + β_E (T − 20 °C)] exactly (a product of floats: 1e-12 relative)
        assert at_temperature == pytest.approx(cold * (1.0 + beta * (COLD_C - 20.0)), rel=1e-12)


def test_cold_backlash_follows_the_aluminium_housing(cold_mesh):
    _, mesh = cold_mesh
    pair = mesh.cold_gear_pair
    gear_strain = mesh.gears[0].expansion_per_k * (COLD_C - 20.0)
    housing_strain = HOUSING_EXPANSION_PER_K["aluminium"] * (COLD_C - 20.0)
    assert mesh.strains[2] == pytest.approx(housing_strain, rel=1e-12)
    # first order in the strains: Δj_bn = ε_g·j_bn + 2·a·sin α_w·(ε_h − ε_g) (∂j_bn/∂a = 2 sin α_w); the
    # neglected second-order terms are ~ε²·a ≈ (1e-3)²·0.09 m ≈ 0.1 nm, far inside 0.1 μm
    expected = mesh.backlash_normal_cold * (1.0 + gear_strain) + 2.0 * pair.centre_distance * math.sin(
        pair.operating_pressure_angle) * (housing_strain - gear_strain)
    assert mesh.backlash_normal == pytest.approx(expected, abs=0.1e-6)
    # aluminium contracts faster than steel: the cold backlash is smaller than at assembly (by 35.0 μm here)
    assert mesh.backlash_normal < mesh.backlash_normal_cold - 30e-6


def test_colder_than_the_material_data_is_refused_by_name():
    from thermogear import load_case

    with pytest.raises(CaseError) as caught:
        load_case("fzg_type_c").with_changes(**{"thermal.model": "thermoelastic", "temperature.model": "uniform",
                                                 "temperature.bulk_c": -45.0})
    message = str(caught.value)
    assert caught.value.key == "temperature.bulk_c" and "thermoelastic" in message and "Luo & Li" not in message


def test_the_papers_model_refuses_a_cold_start_by_name():
    from thermogear import load_case

    with pytest.raises(CaseError) as caught:
        load_case("fzg_type_c").with_changes(**{"thermal.model": "luo2020", "thermal.x_te": 1.0,
                                                 "temperature.model": "uniform", "temperature.bulk_c": 0.0})
    assert "thermal.model = 'luo2020'" in str(caught.value)


@pytest.mark.parametrize("changes, key, model", [
    # the base-circle sizing serves both models: the message says so rather than citing the paper alone
    ({"temperature": {"model": "tabulated", "gamma": [-1.5, 0.0, 1.5], "flank_c": [60.0, 60.0, 60.0],
                      "fit_degree": 2}}, "temperature.pinion_base_c", "thermoelastic and luo2020"),
    ({"thermal": {"model": "luo2020", "x_te_source": "given"}}, "thermal.x_te", "thermal.model = 'luo2020'"),
])
def test_refusals_citing_the_paper_name_the_model_they_apply_to(changes, key, model):
    from thermogear import load_case

    with pytest.raises(CaseError) as caught:
        load_case("fzg_type_c").with_changes(**changes)
    assert caught.value.key == key and model in str(caught.value), str(caught.value)


def test_the_coldest_gear_is_the_coldest_start_elsewhere():
    """One cold limit: the gears' (temperature_field), the housing's (schema) and the gearbox warm-up's start."""
    from thermogear.gearbox.model import COLDEST_START_C
    from thermogear.schema.housing import HOUSING_TEMPERATURE_RANGE_C
    from thermogear.temperature.field import MATERIAL_MINIMUM_C, THERMOELASTIC_LIMITS

    assert MATERIAL_MINIMUM_C == HOUSING_TEMPERATURE_RANGE_C[0] == COLDEST_START_C == THERMOELASTIC_LIMITS.lowest_c
