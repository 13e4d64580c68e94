"""Thermo-elastic mesh: flank deviations (tip relief, base pitch, thermal distortion) and the loaded static TE."""

from __future__ import annotations

import math
import warnings

import numpy as np
import pytest

from thermogear.case import case_from_document, load_case
from thermogear.geometry import Gear, GearPair
from thermogear.geometry.mesh_cycle import load_shares
from thermogear.thermoelastic.deviations import base_pitch_deviation, flank_distortion, tip_relief
from thermogear.thermoelastic.load_sharing import loaded_transmission_error
from thermogear.thermoelastic.mesh import ThermoelasticMesh

from test_thermoelastic_operating import document, mesh


def test_tip_relief_shapes_by_hand():
    roll = np.array([10e-3, 18e-3, 19e-3, 20e-3])
    # tip at 20 mm, relief 4 mm long, 20 μm deep: starts at 16 mm
    linear = tip_relief(roll, 20e-3, 20e-6, 4e-3, "linear")
    parabolic = tip_relief(roll, 20e-3, 20e-6, 4e-3, "parabolic")
    np.testing.assert_allclose(linear, [0.0, 10e-6, 15e-6, 20e-6], rtol=1e-12, atol=1e-18)
    np.testing.assert_allclose(parabolic, [0.0, 5e-6, 11.25e-6, 20e-6], rtol=1e-12, atol=1e-18)


def test_base_pitch_deviation_steps_by_the_pitch_difference_per_pitch():
    # Two pairs one pinion base pitch apart differ by exactly p_b1 − p_b2 (the next pair meets that much late).
    pitch_1, pitch_2 = 11.81e-3 * (1 + 6e-4), 11.81e-3 * (1 + 5e-4)
    roll = np.linspace(5e-3, 20e-3, 7)
    step = base_pitch_deviation(roll - pitch_1, 12e-3, pitch_1, pitch_2) - base_pitch_deviation(roll, 12e-3,
                                                                                                pitch_1, pitch_2)
    np.testing.assert_allclose(step, pitch_1 - pitch_2, rtol=1e-9)
    assert base_pitch_deviation(12e-3, 12e-3, pitch_1, pitch_2) == 0.0


def test_uniform_field_gives_no_flank_distortion():
    # The consistent Eqs. 8–12 for a uniform rise are the homogeneous expansion λΔT·ρ along the flank normal;
    # what is left after subtracting it is rounding: < 1e-15 m against a total expansion of ~1e-5 m.
    gear = Gear(21, 4e-3, math.radians(20.0), 30e-3, bore_radius=15e-3)
    roll = np.linspace(3e-3, 15e-3, 50)
    residual = flank_distortion(gear, roll, np.full_like(roll, 60.0), 60.0, 60.0, 11.5e-6, 60.0)
    assert np.max(np.abs(residual)) < 1e-15


def test_uniform_field_deviation_is_the_base_pitch_term_only():
    # Pinion hotter than the wheel (different coefficients, same uniform temperature): the deviation is exactly the
    # base-pitch term.
    component = mesh(bulk=80.0, housing=20.0, gear_extra={"pinion": {"thermal_expansion_per_k": 12.5e-6}})
    roll = component.gear_pair.roll_grid(41)
    parts = component.deviation_parts_at(roll)
    assert np.all(parts["thermal_distortion"] == 0.0) and np.all(parts["tip_relief"] == 0.0)
    assert np.array_equal(component.pair_deviation_at(roll), parts["base_pitch"])
    # pinion strain 1e-6·60 larger: slope −(ε1 − ε2)/(1 + ε1) ≈ −6e-5
    slope = np.polyfit(roll, parts["base_pitch"], 1)[0]
    assert slope == pytest.approx(-(60 * 1e-6) / (1 + 60 * 12.5e-6), rel=1e-6)


def test_non_uniform_field_distorts_the_flank_by_a_fraction_of_a_micrometre():
    # luo2019's reconstructed flank field (77–81 °C on a 76 °C body): the varying part of the distortion is a few
    # tenths of a μm (Eqs. 8–12: λ·ΔT_excess·(r − r_b) with ΔT_excess ≲ 5 K, r − r_b ≲ 5 mm → ≲ 0.3 μm per gear).
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        component = ThermoelasticMesh.from_case(load_case("luo2019"))
    spread = float(np.ptp(component.distortion))
    assert 0.02e-6 < spread < 1.0e-6


# ------------------------------------------------------------------------------------- load sharing
def _brute_force(stiffness, deviation, load):
    """Bisection of Σ k⟨δ − e⟩₊ = W per column (independent check of the exact piecewise-linear root)."""
    result = []
    for k, e in zip(stiffness.T, deviation.T):
        low, high = float(np.min(e)), float(np.min(e) + load / k.sum() + np.ptp(e) + 1.0)
        for _ in range(200):
            middle = 0.5 * (low + high)
            if np.sum(k * np.maximum(middle - e, 0.0)) < load:
                low = middle
            else:
                high = middle
        result.append(0.5 * (low + high))
    return np.array(result)


def test_loaded_transmission_error_is_the_exact_root():
    generator = np.random.default_rng(7)
    stiffness = generator.uniform(1e8, 5e8, (3, 200))
    deviation = generator.uniform(-20e-6, 40e-6, (3, 200))
    result = loaded_transmission_error(stiffness, deviation, 5000.0)
    np.testing.assert_allclose(result.approach, _brute_force(stiffness, deviation, 5000.0), rtol=0, atol=1e-15)
    np.testing.assert_allclose(result.load_share.sum(axis=0), 1.0, rtol=1e-12)


def test_without_deviations_load_share_is_proportional_to_stiffness():
    stiffness = np.array([[3e8, 2e8], [1e8, 0.0]])
    active = stiffness > 0
    result = loaded_transmission_error(stiffness, np.zeros_like(stiffness), 1000.0, active)
    np.testing.assert_allclose(result.load_share, load_shares(stiffness, active), rtol=1e-14)
    np.testing.assert_allclose(result.approach, 1000.0 / stiffness.sum(axis=0), rtol=1e-14)
    np.testing.assert_allclose(result.contact_stiffness, stiffness.sum(axis=0), rtol=1e-14)


def test_a_pair_deviating_more_than_the_approach_carries_nothing():
    result = loaded_transmission_error(np.array([[1e8], [1e8]]), np.array([[0.0], [50e-6]]), 1000.0)
    # one pair alone: δ = W/k = 10 μm < 50 μm, so the second pair stays open
    assert result.approach[0] == pytest.approx(10e-6, rel=1e-12)
    assert result.load_share[1, 0] == 0.0 and result.contact_stiffness[0] == 1e8


def test_bad_load_sharing_input_is_refused():
    with pytest.raises(ValueError, match="positive"):
        loaded_transmission_error(np.ones((2, 3)), np.zeros((2, 3)), 0.0)
    with pytest.raises(ValueError, match="no tooth pair"):
        loaded_transmission_error(np.zeros((2, 3)), np.zeros((2, 3)), 1.0)


def test_a_common_deviation_shifts_the_approach_and_keeps_the_shares():
    # Σ k⟨δ − (e + c)⟩₊ = W is solved by δ + c: a deviation common to every pair is a rigid shift of the TE.
    generator = np.random.default_rng(3)
    stiffness = generator.uniform(1e8, 5e8, (3, 50))
    deviation = generator.uniform(0.0, 20e-6, (3, 50))
    base = loaded_transmission_error(stiffness, deviation, 4000.0)
    shifted = loaded_transmission_error(stiffness, deviation + 7e-6, 4000.0)
    np.testing.assert_allclose(shifted.approach - base.approach, 7e-6, rtol=0, atol=1e-17)
    np.testing.assert_allclose(shifted.load_share, base.load_share, rtol=0, atol=1e-9)


def test_wheel_colder_than_pinion_gives_a_base_pitch_deviation():
    # luo2019's field with a wheel body 6 K colder than the pinion's, under the thermo-elastic model: the pinion's
    # base pitch is larger, the entering pair (low roll) meets late: e falls along the roll, zero at C.
    case = load_case("luo2019").with_changes(**{"thermal.model": "thermoelastic", "temperature.wheel_base_c": 70.0,
                                                "temperature.wheel_bore_c": 66.0})
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        component = ThermoelasticMesh.from_case(case)
    assert component.strains[0] > component.strains[1]
    pair = component.gear_pair
    parts = component.deviation_parts_at(np.array([pair.path_points["A"], pair.path_points["C"],
                                                   pair.path_points["E"]]))
    pitch = parts["base_pitch"]
    assert pitch[0] > 0.0 > pitch[2] and abs(pitch[1]) < 1e-18
    # one pitch apart: p_b1 − p_b2 = p_b·(ε1 − ε2)/(1 + ε1)-scaled, a few tenths of a μm for 6 K
    step = float(component.deviation_parts_at(np.array([pair.path_points["A"]]))["base_pitch"][0]
                 - component.deviation_parts_at(np.array([pair.path_points["A"] + pair.base_pitch]))["base_pitch"][0])
    strain_difference = component.strains[0] - component.strains[1]
    assert step == pytest.approx(pair.base_pitch * strain_difference / (1 + component.strains[0]), rel=1e-9)
