"""Thermal expansion of the flanks (Luo & Li Eqs. 8–12, Timoshenko & Goodier 1951): identities, limits and hand values."""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.integrate import quad

from thermogear.errors import CaseError
from thermogear.luo2020.thermal.expansion import (base_circle_radial_expansion, flank_expansion_along_line_of_action,
                                                  flank_point_displacement, pair_flank_expansion)

ALPHA = 11.5e-6


def test_equal_base_and_bore_rise_is_free_expansion():
    # Timoshenko & Goodier 1951: t_n = t_b = T gives u = λ r_b T (no thermal stress in a uniformly heated free disc).
    assert base_circle_radial_expansion(ALPHA, 0.038, 0.015, 60.0, 60.0) == pytest.approx(ALPHA * 0.038 * 60.0,
                                                                                            rel=1e-14)


@pytest.mark.parametrize("bore, base_rise, bore_rise", [(0.015, 56.0, 52.0), (0.020, 40.0, 70.0),
                                                        (0.005, 80.0, 10.0)])
def test_eq10_equals_the_free_disc_integral(bore, base_rise, bore_rise):
    # u(r_b) = 2λ r_b/(r_b² − r_n²) ∫ T(r) r dr with the logarithmic field between bore and base circle.
    base = 0.0380576

    def field(r):
        return bore_rise + (base_rise - bore_rise) * math.log(r / bore) / math.log(base / bore)

    integral, _ = quad(lambda r: field(r) * r, bore, base, epsabs=0, epsrel=1e-13)
    expected = 2.0 * ALPHA * base / (base**2 - bore**2) * integral
    assert base_circle_radial_expansion(ALPHA, base, bore, base_rise, bore_rise) == pytest.approx(expected, rel=1e-11)


def test_solid_disc_limit():
    # r_n → 0: the log term vanishes and Δr_b → λ r_b t_b; the formula is continuous into the limit.
    solid = base_circle_radial_expansion(ALPHA, 0.04, 0.0, 50.0, 30.0)
    assert solid == pytest.approx(ALPHA * 0.04 * 50.0)
    tiny = base_circle_radial_expansion(ALPHA, 0.04, 1e-12, 50.0, 30.0)
    assert tiny == pytest.approx(solid, rel=0.05)  # the log term decays only like 1/ln(r_b/r_n)


def test_bore_at_or_beyond_the_base_circle_is_refused():
    with pytest.raises(CaseError, match="bore"):
        base_circle_radial_expansion(ALPHA, 0.03, 0.03, 50.0, 30.0)


def test_vectorised_over_rises():
    rises = np.array([10.0, 20.0, 40.0])
    result = base_circle_radial_expansion(ALPHA, 0.038, 0.015, rises, rises - 5.0)
    assert result.shape == (3,)
    for index in range(3):
        assert result[index] == pytest.approx(
            base_circle_radial_expansion(ALPHA, 0.038, 0.015, rises[index], rises[index] - 5.0), rel=1e-15)


def test_uniform_temperature_moves_the_flank_point_radially_by_free_expansion(luo2019):
    # Issue check: uniform temperature, equal bore and base temperatures → the radius of the flank point grows by
    # exactly λ·r·ΔT (Eq. 10: λ r_b ΔT + λ ΔT (r_k − r_b)); Eq. 9's thickness growth only turns it about the axis.
    gear = luo2019.gear_pair.pinion
    radius = np.linspace(gear.base_radius * 1.001, gear.tip_radius, 9)
    half_angle = gear.half_angle_at(radius)
    rise = 57.0
    base = base_circle_radial_expansion(ALPHA, gear.base_radius, gear.bore_radius, rise, rise)
    delta_x, delta_y = flank_point_displacement(ALPHA, radius, half_angle, rise, base, gear.base_radius)
    new_radius = np.hypot(radius * np.sin(half_angle) + delta_x, radius * np.cos(half_angle) + delta_y)
    np.testing.assert_allclose(new_radius - radius, ALPHA * radius * rise, rtol=1e-12)


def test_projection_matches_the_linearised_hand_formula(luo2019):
    # To first order in λΔT: Δ_t = Δr_k sin α_k + Δs_k cos α_k (radial part along the line of action plus the
    # half-thickness growth, Luo & Li (2020) Eq. 8: ω_k + φ_k = α_k). λΔT ~ 7e-4, so agreement to ~1e-3.
    gear = luo2019.gear_pair.pinion
    roll = np.linspace(0.006, 0.021, 7)
    flank_rise, base_rise, bore_rise = 58.0, 56.0, 52.0
    result = flank_expansion_along_line_of_action(gear, roll, flank_rise, base_rise, bore_rise, ALPHA)
    radius = np.hypot(gear.base_radius, roll)
    angle = np.arctan2(roll, gear.base_radius)
    phi = gear.half_angle_at(radius)
    radial = (base_circle_radial_expansion(ALPHA, gear.base_radius, gear.bore_radius, base_rise, bore_rise)
              + ALPHA * flank_rise * (radius - gear.base_radius))
    thickness = ALPHA * flank_rise * radius * phi
    np.testing.assert_allclose(result, radial * np.sin(angle) + thickness * np.cos(angle), rtol=2e-3)


def test_at_the_base_circle_only_the_thickness_growth_projects(luo2019):
    # Roll 0: the contact normal is the tangent to the base circle (α_k = 0): the radial growth does not project;
    # Δ_t = Δs = λ Δt r_b φ_b with φ_b = α2, the half tooth angle at the base circle.
    gear = luo2019.gear_pair.pinion
    result = flank_expansion_along_line_of_action(gear, 0.0, 50.0, 50.0, 50.0, ALPHA)
    expected = ALPHA * 50.0 * gear.base_radius * gear.half_tooth_angle_at_base
    assert float(result) == pytest.approx(expected, rel=1e-3)


def test_heating_gives_interference_and_no_rise_gives_none(luo2019):
    gear = luo2019.gear_pair.wheel
    roll = np.linspace(0.009, 0.026, 5)
    assert np.all(flank_expansion_along_line_of_action(gear, roll, 60.0, 55.0, 50.0, ALPHA) > 0.0)
    np.testing.assert_array_equal(flank_expansion_along_line_of_action(gear, roll, 0.0, 0.0, 0.0, ALPHA), 0.0)


def test_negative_roll_is_refused(luo2019):
    with pytest.raises(CaseError, match="below the base circle"):
        flank_expansion_along_line_of_action(luo2019.gear_pair.pinion, -1e-3, 50.0, 50.0, 50.0, ALPHA)


def test_pair_expansion_uses_each_gear_own_roll(luo2019):
    pair = luo2019.gear_pair
    roll = np.array([pair.path_points["A"], pair.path_points["C"], pair.path_points["E"]])
    pinion, wheel = pair_flank_expansion(pair, roll, 57.0, 58.0, ALPHA, 56.0, 52.0, 55.0, 51.0)
    np.testing.assert_array_equal(pinion, flank_expansion_along_line_of_action(pair.pinion, roll, 57.0, 56.0, 52.0,
                                                                               ALPHA))
    np.testing.assert_array_equal(wheel, flank_expansion_along_line_of_action(
        pair.wheel, pair.line_of_action_length - roll, 58.0, 55.0, 51.0, ALPHA))
    # The pinion flank expands more toward its tip (E), the wheel's toward its tip (A).
    assert pinion[2] > pinion[0] and wheel[0] > wheel[2]
