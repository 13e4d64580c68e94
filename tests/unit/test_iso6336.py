"""ISO 6336-1 Method B single and mesh stiffness (ISO 6336-1 clause 9)."""

from __future__ import annotations

import math

import pytest

from thermogear.errors import ExtrapolationWarning
from thermogear.stiffness.iso6336 import (basic_rack_factor, iso6336_flexibility, iso6336_mesh_stiffness,
                                          iso6336_single_stiffness, iso6336_stiffness)

ANGLE = math.radians(20)


def test_flexibility_hand_value_luo2019():
    # docs/derivations.md: q′ = 0.04723 + 0.15551/27 + 0.25791/35 = 0.060358 mm·μm/N
    assert iso6336_flexibility(27, 35, 0, 0) * 1e9 == pytest.approx(0.060358, abs=2e-6)


def test_basic_rack_factor():
    assert basic_rack_factor(1.25, ANGLE) == pytest.approx(0.975)
    assert basic_rack_factor(1.2, ANGLE) == pytest.approx(1.0)
    assert basic_rack_factor(1.2, math.radians(25)) == pytest.approx(1.1)


def test_single_and_mesh_stiffness_luo2019():
    c_prime = iso6336_single_stiffness(27, 35, 0, 0, 206e9)
    assert c_prime / 1e9 == pytest.approx(1 / 0.060358 * 0.8 * 0.975, rel=1e-4)
    assert iso6336_mesh_stiffness(c_prime, 1.658) == pytest.approx(c_prime * (0.75 * 1.658 + 0.25))


def test_modulus_and_light_load_corrections():
    base = iso6336_single_stiffness(27, 35, 0, 0, 206e9)
    assert iso6336_single_stiffness(27, 35, 0, 0, 103e9) == pytest.approx(base / 2)
    # mixed materials: E_r = 2 E1 E2/(E1 + E2) = 137.33 GPa for 206 and 103 GPa
    assert iso6336_single_stiffness(27, 35, 0, 0, 206e9, 103e9) == pytest.approx(base * (2 * 103 / 309))
    # below 100 N/mm the single stiffness falls as (F_t K_A / b / 100)^0.25
    assert iso6336_single_stiffness(27, 35, 0, 0, 206e9, line_load=50e3) == pytest.approx(base * 0.5**0.25)
    assert iso6336_single_stiffness(27, 35, 0, 0, 206e9, line_load=150e3) == pytest.approx(base)


def test_low_contact_ratio_reduction():
    assert iso6336_mesh_stiffness(10.0, 1.1) == pytest.approx(0.9 * 10.0 * (0.75 * 1.1 + 0.25))


def test_shift_outside_the_fit_warns():
    with pytest.warns(ExtrapolationWarning):
        iso6336_single_stiffness(20, 40, -0.2, 0.3, 206e9)


def test_case_wrapper(luo2019):
    result = iso6336_stiffness(luo2019.gear_pair, luo2019.material, luo2019.operating_point)
    assert result["line_load"] > 100e3  # 80 kW at 2000 rpm: no light-load correction
    assert result["c_gamma_alpha"] / result["c_prime"] == pytest.approx(0.75 * luo2019.gear_pair.contact_ratio
                                                                        + 0.25)
