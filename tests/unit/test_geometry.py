"""Involute geometry: hand values (ISO 21771; docs/derivations.md), identities and limits."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from thermogear.errors import CaseError
from thermogear.geometry import (Gear, GearPair, RigidPair, disc_polar_inertia, involute, inverse_involute,
                                 operating_pressure_angle_from_shifts)

ALPHA = math.radians(20.0)


def pair(z1=27, z2=35, m=3e-3, x1=0.0, x2=0.0, b=25e-3, a=None, **kwargs):
    return GearPair.create(Gear(z1, m, ALPHA, b, x1, bore_radius=10e-3),
                           Gear(z2, m, ALPHA, b, x2, bore_radius=10e-3), a, **kwargs)


def test_inverse_involute_round_trip():
    angles = np.linspace(0.01, 1.2, 50)
    assert np.allclose(inverse_involute(involute(angles)), angles, atol=1e-13)


def test_luo2019_radii_match_physics_sheet():
    # docs/derivations.md: r_a1 43.5, r_f1 36.75, r_a2 55.5, r_f2 48.75 mm, p_b 8.8564 mm, g_alpha 14.685 mm
    p = pair()
    assert p.pinion.tip_radius == pytest.approx(43.5e-3, abs=1e-9)
    assert p.pinion.root_radius == pytest.approx(36.75e-3, abs=1e-9)
    assert p.wheel.tip_radius == pytest.approx(55.5e-3, abs=1e-9)
    assert p.wheel.root_radius == pytest.approx(48.75e-3, abs=1e-9)
    assert p.base_pitch == pytest.approx(8.8564e-3, abs=1e-7)
    assert p.path_length == pytest.approx(14.685e-3, abs=1e-6)


def test_zero_shift_gives_standard_centre_distance():
    assert pair().centre_distance == pytest.approx(93e-3, rel=1e-12)


def test_shifted_centre_distance_from_operating_angle():
    # FZG C shifts: a = 91.5 mm (ISO 14635-1); the shift formula gives 91.50008 mm
    angle = operating_pressure_angle_from_shifts(16, 24, 0.1817, 0.1715, ALPHA)
    assert 90e-3 * math.cos(ALPHA) / math.cos(angle) == pytest.approx(91.5e-3, abs=1e-6)


def test_gamma_is_zero_at_pitch_point_and_round_trips():
    p = pair()
    assert p.gamma(p.path_points["C"]) == pytest.approx(0.0, abs=1e-15)
    rolls = p.roll_grid(11)
    assert np.allclose(p.roll(p.gamma(rolls)), rolls)


def test_time_mapping_moves_one_base_pitch_per_mesh_period():
    p = pair()
    period = p.mesh_period(2000.0)
    assert period == pytest.approx(1.1111e-3, rel=1e-4)
    assert p.roll_at_time(period, 2000.0) - p.path_points["A"] == pytest.approx(p.base_pitch, rel=1e-12)
    assert p.time_at_roll(p.roll_at_time(0.3e-3, 2000.0), 2000.0) == pytest.approx(0.3e-3)


def test_sliding_vanishes_at_pitch_point():
    p = pair()
    assert p.sliding_speed(p.path_points["C"], 2000.0) == pytest.approx(0.0, abs=1e-12)
    v1, v2 = p.rolling_speeds(p.path_points["C"], 2000.0)
    # docs/derivations.md: sum of rolling speeds at C = 5.802 m/s
    assert v1 + v2 == pytest.approx(5.802, abs=1e-3)


def test_tooth_thickness_on_reference_circle():
    gear = Gear(27, 3e-3, ALPHA, 25e-3, 0.2)
    expected = 3e-3 * (math.pi / 2 + 2 * 0.2 * math.tan(ALPHA))
    assert float(gear.thickness_at(gear.reference_radius)) == pytest.approx(expected, rel=1e-12)


def test_equivalent_mass_of_equal_discs():
    inertia = disc_polar_inertia(7850.0, 0.05, 0.0, 0.02)
    assert inertia == pytest.approx(7850 * math.pi * 0.02 * 0.05**4 / 2)
    # identical gears: me = J / (2 rb²); and 1/(wᵀM⁻¹w) of the pair's matrices for unequal ones
    assert RigidPair(inertia, inertia, 0.04, 0.04).mesh_mass == pytest.approx(inertia / (2 * 0.04**2), rel=1e-15)
    rigid = RigidPair(inertia, 3.0 * inertia, 0.04, 0.07)
    w = rigid.mesh_vector()
    assert rigid.mesh_mass == pytest.approx(1.0 / (w @ np.linalg.solve(rigid.mass_matrix(), w)), rel=1e-14)


def test_one_to_one_pair_is_symmetric_about_pitch_point():
    p = pair(30, 30)
    points = p.path_points
    assert points["C"] - points["A"] == pytest.approx(points["E"] - points["C"], rel=1e-12)


@settings(max_examples=60, deadline=None)
@given(z1=st.integers(18, 60), ratio=st.floats(1.0, 4.0), module_mm=st.floats(1.0, 10.0),
       x1=st.floats(0.0, 0.5), x2=st.floats(-0.2, 0.5))
def test_valid_pairs_have_ordered_path_and_contact_ratio_above_one(z1, ratio, module_mm, x1, x2):
    z2 = int(round(z1 * ratio))
    try:
        p = pair(z1, z2, module_mm * 1e-3, x1, x2, b=20e-3)
    except CaseError:
        return  # refused geometries are covered by the bad-input tests
    points = p.path_points
    assert 0 < points["A"] < points["C"] < points["E"] < p.line_of_action_length
    assert points["A"] < points["D"] and points["B"] < points["E"]
    assert p.contact_ratio > 1.0
    assert p.pinion.form_roll_distance <= points["A"]


def test_high_contact_ratio_pair_is_accepted():
    # long addendum, small pressure angle: a high-contact-ratio pair (epsilon > 2)
    alpha = math.radians(16.0)
    p = GearPair.create(Gear(40, 2e-3, alpha, 20e-3, addendum_coefficient=1.3, dedendum_coefficient=1.6,
                             bore_radius=10e-3),
                        Gear(60, 2e-3, alpha, 20e-3, addendum_coefficient=1.3, dedendum_coefficient=1.6,
                             bore_radius=10e-3))
    assert p.contact_ratio > 2.0
