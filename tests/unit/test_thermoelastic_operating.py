"""Thermo-elastic mesh: material at temperature, operating geometry, backlash, jamming, stiffness identities."""

from __future__ import annotations

import math
import warnings

import numpy as np
import pytest

from thermogear.case import case_from_document
from thermogear.geometry import Gear, GearPair
from thermogear.thermoelastic.materials import youngs_modulus_at
from thermogear.thermoelastic.mesh import ThermoelasticMesh
from thermogear.thermoelastic.operating import (agma_minimum_backlash, normal_backlash, operating_gear_pair,
                                                scaled_gear)

LAMBDA = 11.5e-6


def document(bulk=80.0, housing=20.0, housing_expansion=None, gear_extra=None, material=None, backlash=None):
    """A z 21/63, m 4 mm pair (not one of the parameter sets) at a uniform bulk temperature."""
    doc = {"case": {"name": "unseen_21_63"},
           "gears": {"module_mm": 4.0, "pressure_angle_deg": 20.0, "face_width_mm": 30.0,
                     "pinion": {"teeth": 21, "bore_radius_mm": 15.0}, "wheel": {"teeth": 63, "bore_radius_mm": 30.0}},
           "operating": {"speed_rpm": 1500.0, "torque_nm": 400.0},
           "temperature": {"model": "uniform", "bulk_c": bulk, "reference_c": 20.0},
           "housing": {"temperature_c": housing}}
    if housing_expansion is not None:
        doc["housing"]["thermal_expansion_per_k"] = housing_expansion
    for name, extra in (gear_extra or {}).items():
        doc["gears"][name].update(extra)
    if material:
        doc["material"] = material
    if backlash is not None:
        doc["gears"]["backlash_normal_um"] = backlash
    return doc


def mesh(**kwargs) -> ThermoelasticMesh:
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return ThermoelasticMesh.from_case(case_from_document(document(**kwargs)))


def mean_stiffness(component: ThermoelasticMesh, cold: bool = False) -> float:
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        grid, values = component.mesh_stiffness(cold=cold)
    return float(grid.time_average(values))


# ------------------------------------------------------------------------------------------- material
def test_youngs_modulus_is_linear_and_exact_at_20c():
    assert youngs_modulus_at(206e9, -3.33e-4, 20.0) == 206e9
    # 100 K above 20 °C: 206·(1 − 0.0333) GPa, by hand
    assert youngs_modulus_at(206e9, -3.33e-4, 120.0) == pytest.approx(206e9 * 0.9667, rel=1e-12)


# ------------------------------------------------------------------------------------------- backlash
@pytest.mark.parametrize("shifts", [(0.0, 0.0), (0.3, -0.1), (0.5, 0.4)])
def test_backlash_is_zero_at_the_tight_mesh_centre_distance(shifts):
    # GearPair.create puts the centre distance at zero backlash from the shifts (inv α_w of ISO 21771); the
    # backlash formula must give 0 there to rounding (1e-12 m = 1e-9 of a module).
    angle = math.radians(20.0)
    pinion = Gear(23, 3e-3, angle, 20e-3, profile_shift=shifts[0], bore_radius=10e-3)
    wheel = Gear(41, 3e-3, angle, 20e-3, profile_shift=shifts[1], bore_radius=15e-3)
    assert abs(normal_backlash(GearPair.create(pinion, wheel))) < 1e-12


def test_backlash_grows_by_two_sin_alpha_w_per_centre_distance():
    # ∂j_bn/∂a = 2 sin α_w (derived in docs/thermal.md): central difference with 1 μm steps; the second derivative
    # is of order 1/a, so the difference quotient matches to ~1e-6 relative.
    angle = math.radians(20.0)
    pinion, wheel = Gear(21, 4e-3, angle, 30e-3), Gear(63, 4e-3, angle, 30e-3)
    tight = GearPair.create(pinion, wheel)
    step = 1e-6
    pairs = [GearPair.create(pinion, wheel, tight.centre_distance + 100e-6 + s) for s in (-step, step)]
    slope = (normal_backlash(pairs[1]) - normal_backlash(pairs[0])) / (2 * step)
    middle = GearPair.create(pinion, wheel, tight.centre_distance + 100e-6)
    assert slope == pytest.approx(2 * math.sin(middle.operating_pressure_angle), rel=1e-6)


def test_default_backlash_is_the_agma_minimum():
    component = mesh(bulk=20.0, housing=20.0)
    a_mm = component.cold_gear_pair.centre_distance * 1e3
    hand = (0.06 + 0.0005 * a_mm + 0.03 * 4.0) * 1e-3  # AGMA 2002-B88 with a = 168 mm, m = 4 mm
    assert agma_minimum_backlash(a_mm * 1e-3, 4e-3) == pytest.approx(hand, rel=1e-12)
    assert component.backlash_normal_cold == pytest.approx(hand, rel=1e-9)
    assert component.backlash_normal == pytest.approx(hand, rel=1e-9)


def test_gears_and_housing_equally_hot_scale_backlash_and_keep_stiffness_per_width():
    # Same coefficient, same temperature: the whole mesh is the cold one scaled by (1 + λΔT). Backlash scales by
    # (1 + λΔT) and the stiffness per unit face width changes only through E (PEM compliances are dimensionless
    # integrals over E·width): both to 1e-9 (rounding and the 1e-6 spline of the tables cancel between the two
    # identical, scaled tables).
    rise = 60.0
    hot = mesh(bulk=20.0 + rise, housing=20.0 + rise, housing_expansion=LAMBDA)
    strain = LAMBDA * rise
    assert hot.backlash_normal == pytest.approx(hot.backlash_normal_cold * (1 + strain), rel=1e-9)
    per_width_hot = mean_stiffness(hot) / hot.gear_pair.face_width
    per_width_cold = mean_stiffness(hot, cold=True) / hot.cold_gear_pair.face_width
    assert per_width_hot / per_width_cold == pytest.approx(hot.modulus_ratios[0], rel=1e-9)
    assert hot.gear_pair.contact_ratio == pytest.approx(hot.cold_gear_pair.contact_ratio, rel=1e-9)


def test_cold_housing_closes_backlash_by_two_a_lambda_dt_sin_alpha():
    # Gears at +60 K in a housing at the reference: to first order the backlash falls by 2·a·λ·ΔT·sin α_w. The
    # neglected term is λΔT·j_bn (j_bn/(2a sin α_w) ≈ 0.3 % here) plus second order: 2 % is ample and still far
    # below the size of the effect.
    rise = 60.0
    component = mesh(bulk=20.0 + rise, housing=20.0)
    pair = component.cold_gear_pair
    expected = 2 * pair.centre_distance * LAMBDA * rise * math.sin(pair.operating_pressure_angle)
    fall = component.backlash_normal_cold - component.backlash_normal
    assert fall == pytest.approx(expected, rel=0.02)


def test_jamming_temperature_closes_the_backlash():
    from thermogear.thermoelastic.operating import backlash_at

    component = mesh(bulk=80.0, housing=20.0)
    jam = component.jamming_bulk_temperature_c
    assert jam is not None and jam > 80.0
    rise = jam - 20.0
    value = backlash_at(component.cold_gear_pair, component.allowance, LAMBDA * rise, LAMBDA * rise, 0.0)
    assert abs(value) < 1e-12  # secant iteration to 1e-9 K on a slope of ~1.3 μm/K


def test_gears_that_do_not_expand_never_jam():
    component = mesh(bulk=80.0, housing=20.0, material={"thermal_expansion_per_k": 0.0})
    assert component.jamming_bulk_temperature_c is None


def test_scaled_gear_is_the_gear_with_a_larger_module():
    gear = Gear(21, 4e-3, math.radians(20.0), 30e-3, profile_shift=0.2, bore_radius=15e-3, tip_radius=47e-3)
    scaled = scaled_gear(gear, 1e-3)
    assert scaled.base_radius == pytest.approx(gear.base_radius * 1.001, rel=1e-14)
    assert scaled.root_radius == pytest.approx(gear.root_radius * 1.001, rel=1e-14)
    assert float(scaled.thickness_at(scaled.tip_radius)) == pytest.approx(
        float(gear.thickness_at(gear.tip_radius)) * 1.001, rel=1e-12)


# ------------------------------------------------------------------------------------------- stiffness
def test_zero_rise_is_the_elastic_model_bit_for_bit():
    component = mesh(bulk=20.0, housing=20.0)
    assert component.gear_pair is component.cold_gear_pair
    roll = component.cold_gear_pair.roll_grid(57)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        assert np.array_equal(component.pair_stiffness_at(roll), component.elastic_pair_stiffness_at(roll))
    assert np.array_equal(component.pair_deviation_at(roll), np.zeros_like(roll))
    assert component.backlash_normal == component.backlash_normal_cold


def test_youngs_modulus_alone_scales_stiffness():
    # No expansion at all (λ = 0 for gears and the lowest housing coefficient at the reference): the geometry stays
    # cold and k scales by E(T)/E(20 °C) exactly (every compliance ∝ 1/E).
    component = mesh(bulk=100.0, housing=20.0, material={"thermal_expansion_per_k": 0.0})
    assert component.gear_pair is component.cold_gear_pair
    expected = youngs_modulus_at(1.0, -3.33e-4, 100.0)
    roll = component.cold_gear_pair.roll_grid(33)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        ratio = component.pair_stiffness_at(roll) / component.elastic_pair_stiffness_at(roll)
    np.testing.assert_allclose(ratio, expected, rtol=1e-14)


def test_different_moduli_combine_tooth_compliances_in_series():
    # Pinion β_E = 0, wheel the default: the pair compliance is δ1 + δ2/(E2/E20), between the two limits.
    component = mesh(bulk=120.0, housing=20.0, material={"thermal_expansion_per_k": 0.0},
                     gear_extra={"pinion": {"youngs_modulus_temperature_coefficient_per_k": 0.0}})
    roll = component.cold_gear_pair.roll_grid(9)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        ratio = component.pair_stiffness_at(roll) / component.elastic_pair_stiffness_at(roll)
    wheel_ratio = component.modulus_ratios[1]
    assert component.modulus_ratios[0] == 1.0 and wheel_ratio < 1.0
    assert np.all((ratio > wheel_ratio) & (ratio < 1.0))
