"""DIN 3990-4 / ISO/TR 13989-1 mean friction coefficient: hand values, scaling, units, limits, bad input."""

from __future__ import annotations

import warnings

import numpy as np
import pytest

from thermogear.errors import CaseError, ExtrapolationWarning
from thermogear.friction import mean_friction_coefficient

# ISO/TR 13989-1, the paper's gear at the pitch point (SI): w_Bt 401.47 N/mm, Ra 6.3 μm, η(30 °C) 457.8 mPa·s,
# v_Σ 5.802 m/s, ρ_red 7.820 mm
PITCH = dict(unit_load=401.47e3, roughness=6.3e-6, dynamic_viscosity=0.4578, sum_velocity=5.802,
             relative_radius=7.820e-3)


def test_hand_value_at_the_pitch_point():
    # 0.12·(401.47·6.3/(457.8·5.802·7.820))^0.25 = 0.0709 (docs/derivations.md)
    assert mean_friction_coefficient(**PITCH) == pytest.approx(0.12 * (401.47 * 6.3 / (457.8 * 5.802 * 7.820))
                                                              ** 0.25, rel=1e-12)
    assert mean_friction_coefficient(**PITCH) == pytest.approx(0.0709, abs=5e-5)


@pytest.mark.parametrize("name, factor, exponent", [
    ("unit_load", 16.0, 0.25), ("roughness", 16.0, 0.25), ("dynamic_viscosity", 16.0, -0.25),
    ("sum_velocity", 1.0 / 16.0, -0.25), ("relative_radius", 16.0, -0.25)])
def test_quarter_power_scaling(name, factor, exponent):
    changed = dict(PITCH, **{name: PITCH[name] * factor})
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ExtrapolationWarning)
        ratio = mean_friction_coefficient(**changed) / mean_friction_coefficient(**PITCH)
    assert ratio == pytest.approx(factor ** exponent, rel=1e-12)


def test_lubricant_factor_is_a_plain_factor_and_values_vectorise():
    values = mean_friction_coefficient(PITCH["unit_load"] * np.array([1.0, 1.0]), 6.3e-6, 0.4578, 5.802, 7.82e-3,
                                       lubricant_factor=0.8)
    assert values.shape == (2,)
    assert values == pytest.approx(0.8 * mean_friction_coefficient(**PITCH))


def test_zero_roughness_gives_zero_friction_and_zero_load_is_allowed_without_limits():
    assert mean_friction_coefficient(**dict(PITCH, roughness=0.0)) == 0.0
    assert mean_friction_coefficient(**dict(PITCH, unit_load=0.0), check_limits=False) == 0.0


def test_standstill_is_a_clear_error_naming_the_speed():
    with pytest.raises(CaseError, match="undefined at standstill") as caught:
        mean_friction_coefficient(**dict(PITCH, sum_velocity=0.0))
    assert caught.value.key == "operating.speed_rpm"


@pytest.mark.parametrize("name, value, key", [
    ("roughness", -1e-6, "gears.roughness_ra_um"), ("unit_load", -1.0, "unit_load"),
    ("dynamic_viscosity", 0.0, "lubricant"), ("relative_radius", 0.0, "relative_radius"),
    ("sum_velocity", float("nan"), "operating.speed_rpm")])
def test_bad_inputs_are_refused(name, value, key):
    with pytest.raises(CaseError) as caught:
        mean_friction_coefficient(**dict(PITCH, **{name: value}))
    assert caught.value.key == key


def test_validity_limits_warn_with_the_distance():
    with pytest.warns(ExtrapolationWarning, match=r"10\.0 m/s above"):
        mean_friction_coefficient(**dict(PITCH, sum_velocity=60.0))
    with pytest.warns(ExtrapolationWarning, match=r"50\.0 N/mm below"):
        mean_friction_coefficient(**dict(PITCH, unit_load=100e3))
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        mean_friction_coefficient(**PITCH)
        mean_friction_coefficient(**dict(PITCH, unit_load=100e3), check_limits=False)
