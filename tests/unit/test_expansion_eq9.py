"""The two forms of Luo & Li Eq. 9 (thermal/expansion.py): the printed one counts the circumferential growth
twice; the consistent one gives the homogeneous expansion of a free gear under a uniform rise."""

from __future__ import annotations

import math

import numpy as np
import pytest

from thermogear.errors import CaseError
from thermogear.geometry import Gear
from thermogear.luo2020.thermal.expansion import flank_expansion_along_line_of_action

ALPHA_TH = 11.5e-6
RISE = 50.0


@pytest.fixture(scope="module")
def gear():
    return Gear(27, 3e-3, math.radians(20.0), 25e-3, bore_radius=15e-3)


@pytest.fixture(scope="module")
def roll(gear):
    return np.linspace(5e-3, 20e-3, 31)  # roll distances on the gear's own base tangent [m]


def test_consistent_uniform_rise_is_the_homogeneous_expansion(gear, roll):
    # homogeneous expansion moves every point radially by alpha dT r at constant angle; projected on the flank
    # normal (the line of action) that is alpha dT r_k sin(alpha_k) = alpha dT * roll distance, exactly
    expansion = flank_expansion_along_line_of_action(gear, roll, RISE, RISE, RISE, ALPHA_TH, "consistent")
    np.testing.assert_allclose(expansion, ALPHA_TH * RISE * roll, rtol=1e-9)


def test_printed_eq9_overstates_by_the_double_counted_angular_term(gear, roll):
    paper = flank_expansion_along_line_of_action(gear, roll, RISE, RISE, RISE, ALPHA_TH, "paper")
    consistent = flank_expansion_along_line_of_action(gear, roll, RISE, RISE, RISE, ALPHA_TH, "consistent")
    radius = np.hypot(gear.base_radius, roll)
    half_angle = gear.half_angle_at(radius)
    # the surplus is the extra angle alpha dT phi_k swept at radius r_k, projected on the normal: alpha dT r_k phi_k
    # cos(phi_k + load angle) to first order, i.e. alpha dT r_b phi_k (cos(alpha_k) = r_b / r_k)
    surplus = ALPHA_TH * RISE * gear.base_radius * half_angle
    np.testing.assert_allclose(paper - consistent, surplus, rtol=2e-3)
    assert np.all(paper > consistent)
    assert (paper / consistent - 1.0)[0] > 0.25  # about +30 % near the root of this pinion


def test_no_rise_no_expansion_in_both_forms(gear, roll):
    for form in ("paper", "consistent"):
        assert np.all(flank_expansion_along_line_of_action(gear, roll, 0.0, 0.0, 0.0, ALPHA_TH, form) == 0.0)


def test_unknown_form_is_refused(gear, roll):
    with pytest.raises(CaseError, match="expansion_model"):
        flank_expansion_along_line_of_action(gear, roll, RISE, RISE, RISE, ALPHA_TH, "exact")
