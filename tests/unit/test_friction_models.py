"""Mean tooth friction laws as a choice (thermogear.friction.models): each law against a hand calculation in its
source's units, its power-law identities, the lubricant factors, the registry and the validity warnings."""

from __future__ import annotations

import math
import warnings

import pytest

from thermogear.errors import CaseError, ExtrapolationWarning
from thermogear.friction.models import (FRICTION_MODELS, SCHLENK_LUBRICANT_FACTORS, PitchContact, friction_law)

# FZG type C at T1 = 265 N·m, 2250 rpm (the FVA 54/7 point): F_bt = T1/r_b1 = 265/0.033829 = 7834 N over b = 14 mm,
# v_ΣC = 2·v_t·sin α_wt = 6.58 m/s, ρ_C = 8.38 mm; R_a 0.6 μm, η 20 mPa·s (SI below)
POINT = PitchContact(unit_load=7834.0 / 14e-3, roughness=0.6e-6, viscosity=20e-3, sum_velocity=6.58,
                     relative_radius=8.38e-3, lubricant_factor=1.0)


def test_schlenk_hand_calculation():
    # 0.048·(559.6 N/mm / (6.58 m/s · 8.38 mm))^0.2 · 20^−0.05 · 0.6^0.25 · 1, written out in the law's units
    group = (7834.0 / 14.0) / (6.58 * 8.38)
    expected = 0.048 * group**0.2 * 20.0**-0.05 * 0.6**0.25
    assert friction_law("schlenk").coefficient(POINT) == pytest.approx(expected, rel=1e-12)
    assert expected == pytest.approx(0.0578, abs=5e-5)  # the value derived for this point by hand, 3 digits


def test_iso_tr_13989_2_hand_calculation():
    # 0.045·(w_Bt/(v_Σ ρ))^0.2 · η^−0.05 · X_R · X_L with X_R = 2.2·(R_a/ρ)^0.25, K_Bγ = 1 (spur)
    group = (7834.0 / 14.0) / (6.58 * 8.38)
    expected = 0.045 * group**0.2 * 20.0**-0.05 * 2.2 * (0.6 / 8.38)**0.25
    assert friction_law("iso_tr_13989_2").coefficient(POINT) == pytest.approx(expected, rel=1e-12)


def test_paper_law_hand_calculation():
    # Luo & Li Eq. 27: 0.12·(w·R_a/(η·v_Σ·ρ))^0.25·X_L
    expected = 0.12 * ((7834.0 / 14.0) * 0.6 / (20.0 * 6.58 * 8.38))**0.25
    assert friction_law("paper").coefficient(POINT) == pytest.approx(expected, rel=1e-12)


@pytest.mark.parametrize("name, load, viscosity, roughness", [("schlenk", 0.2, -0.05, 0.25),
                                                              ("iso_tr_13989_2", 0.2, -0.05, 0.25),
                                                              ("paper", 0.25, -0.25, 0.25)])
def test_power_law_exponents(name, load, viscosity, roughness):
    law = friction_law(name)
    base = law.coefficient(POINT)
    doubled = {"unit_load": 2.0 * POINT.unit_load, "viscosity": 2.0 * POINT.viscosity,
               "roughness": 2.0 * POINT.roughness}
    for field, exponent in (("unit_load", load), ("viscosity", viscosity), ("roughness", roughness)):
        changed = PitchContact(**{**POINT.__dict__, field: doubled[field]})
        assert law.coefficient(changed) / base == pytest.approx(2.0**exponent, rel=1e-12), field
    assert law.viscosity_exponent == viscosity
    # μ ∝ (w/v_Σ)^p: the exponent the friction damping's speed and load scaling is built on
    assert law.load_exponent == load
    faster = PitchContact(**{**POINT.__dict__, "sum_velocity": 2.0 * POINT.sum_velocity})
    assert law.coefficient(faster) / base == pytest.approx(2.0**-load, rel=1e-12)


@pytest.mark.parametrize("name", ["schlenk", "iso_tr_13989_2", "paper", "constant"])
def test_every_law_takes_arrays_as_the_damping_does(name):
    # the damping evaluates a law along the path of contact: arrays give, point by point, the scalar values
    import numpy as np

    law = friction_law(name)
    loads = np.array([0.3, 1.0, 1.7]) * POINT.unit_load
    speeds = np.array([5.0, 6.58, 8.0])
    contact = PitchContact(loads, POINT.roughness, POINT.viscosity, speeds, POINT.relative_radius, 1.0)
    values = np.broadcast_to(law.law(contact, 0.05), loads.shape)
    for index in range(3):
        single = PitchContact(float(loads[index]), POINT.roughness, POINT.viscosity, float(speeds[index]),
                              POINT.relative_radius, 1.0)
        assert values[index] == pytest.approx(law.law(single, 0.05), rel=1e-14)



@pytest.mark.parametrize("name", ["schlenk", "iso_tr_13989_2", "paper"])
def test_an_array_with_a_standstill_point_is_refused(name):
    import numpy as np

    speeds = np.array([5.0, 0.0, 8.0])
    with pytest.raises(CaseError, match="operating.speed_rpm"):
        friction_law(name).law(PitchContact(POINT.unit_load, POINT.roughness, POINT.viscosity, speeds,
                                            POINT.relative_radius, 1.0), None)


def test_temperature_sensitivity_from_40_to_90_c():
    # ISO VG 100 mineral oil thins about 8-fold from 40 to 90 °C: the paper's law rises by 64 %, Schlenk's by 10 %
    from thermogear.lubricant import builtin_lubricant

    oil = builtin_lubricant("iso_vg_100_mineral")
    ratio = float(oil.dynamic_viscosity(90.0, warn=False) / oil.dynamic_viscosity(40.0, warn=False))
    rise = {name: ratio**FRICTION_MODELS[name].viscosity_exponent - 1.0 for name in ("paper", "schlenk")}
    assert rise["paper"] == pytest.approx(0.64, abs=0.01) and rise["schlenk"] == pytest.approx(0.10, abs=0.01)


def test_lubricant_factors_per_law():
    assert friction_law("schlenk").lubricant_factor("mineral") == SCHLENK_LUBRICANT_FACTORS["mineral"] == 0.846
    assert friction_law("paper").lubricant_factor("pao") == 0.8  # ISO/TR 13989-1's table
    assert friction_law("schlenk").lubricant_factor("traction", given=1.1) == 1.1
    with pytest.raises(CaseError, match="gearbox.lubricant_factor"):
        friction_law("schlenk").lubricant_factor("traction")


def test_constant_law_and_registry():
    assert friction_law("constant").coefficient(POINT, 0.05) == 0.05
    with pytest.raises(CaseError, match="friction_coefficient"):
        friction_law("constant").coefficient(POINT, None)
    with pytest.raises(CaseError, match="gearbox.friction_model"):
        friction_law("stribeck")


def test_validity_warnings_name_the_law():
    light = PitchContact(**{**POINT.__dict__, "unit_load": 100e3})  # 100 N/mm < 150 N/mm
    with pytest.warns(ExtrapolationWarning, match="schlenk.*100.0 N/mm"):
        friction_law("schlenk").coefficient(light)
    fast = PitchContact(**{**POINT.__dict__, "sum_velocity": 60.0})
    with pytest.warns(ExtrapolationWarning, match="60.0 m/s"):
        friction_law("iso_tr_13989_2").coefficient(fast)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        friction_law("constant").coefficient(light, 0.05)  # a given value has no range
        assert math.isfinite(friction_law("schlenk").coefficient(POINT))
