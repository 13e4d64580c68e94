"""Potential-energy-method tooth compliance: quadrature against adaptive quadrature, closed forms against
direct integration of the beam energy, the two root cases, physical limits (Tian 2004; Chaari et al. 2009)."""

from __future__ import annotations

import math
import warnings

import numpy as np
import pytest
from scipy.integrate import quad

from thermogear.errors import ExtrapolationWarning
from thermogear.geometry import Gear, GearPair
from thermogear.materials import Material
from thermogear.stiffness.potential_energy import (hertz_compliance, involute_end_angle, involute_integrals,
                                                   pair_compliance, root_segment_integrals, tooth_compliance)

STEEL = Material()
ANGLE = math.radians(20.0)


def gear(teeth: int, bore: float = 0.015, **changes) -> Gear:
    values = dict(teeth=teeth, module=0.003, pressure_angle=ANGLE, face_width=0.025, bore_radius=bore)
    values.update(changes)
    return Gear(**values)


def test_hertz_compliance_hand_value():
    # 4 (1 − 0.09) / (π · 206e9 · 1) = 5.6245e-12 m/N  (docs/derivations.md: k_h = 1.778e11 N/m per m)
    assert hertz_compliance(206e9, 0.3, 1.0) == pytest.approx(5.62452e-12, rel=1e-5)
    assert 1.0 / hertz_compliance(206e9, 0.3, 1.0) == pytest.approx(1.778e11, rel=1e-3)


@pytest.mark.parametrize("alpha_1", [-0.05, 0.0, 0.1, 0.3, 0.5])
def test_gauss_legendre_matches_adaptive_quadrature(alpha_1):
    alpha_2 = gear(27).half_tooth_angle_at_base

    def bending(a):
        arm = alpha_2 - a
        return (1.5 * (1 + math.cos(alpha_1) * (arm * math.sin(a) - math.cos(a))) ** 2 * arm * math.cos(a)
                / (math.sin(a) + arm * math.cos(a)) ** 3)

    def normal(a):
        arm = alpha_2 - a
        return arm * math.cos(a) / (math.sin(a) + arm * math.cos(a))

    b, n = involute_integrals(np.array([alpha_1]), alpha_2, alpha_2)
    assert b[0] == pytest.approx(quad(bending, -alpha_1, alpha_2, epsabs=0, epsrel=1e-13)[0], rel=1e-11)
    assert n[0] == pytest.approx(quad(normal, -alpha_1, alpha_2, epsabs=0, epsrel=1e-13)[0], rel=1e-11)


def test_involute_integral_equals_beam_energy_in_the_centreline_coordinate():
    """Check the change of variables of Chaari et al. (2009) independently: integrate the beam formula
    3 (r_b − x cos α1)² / (2 E L h³) over x with x(α), h(α) sampled densely (trapezoid in x)."""
    r_b = 1.0
    alpha_2 = gear(27).half_tooth_angle_at_base
    alpha_1 = 0.25
    alpha = np.linspace(-alpha_1, alpha_2, 200001)
    x = r_b * (np.cos(alpha) - (alpha_2 - alpha) * np.sin(alpha))
    h = r_b * (np.sin(alpha) + (alpha_2 - alpha) * np.cos(alpha))
    integrand = 3.0 * (r_b - x * math.cos(alpha_1)) ** 2 / (2.0 * h**3)
    bending = -np.trapezoid(integrand, x)  # x decreases as α grows
    normal = -np.trapezoid(1.0 / h, x)
    b, n = involute_integrals(np.array([alpha_1]), alpha_2, alpha_2)
    assert b[0] == pytest.approx(bending, rel=1e-6)
    assert n[0] == pytest.approx(normal, rel=1e-6)


def test_root_segment_closed_form_equals_direct_integration():
    g = gear(27)
    r_b, r_f, alpha_2 = g.base_radius, g.root_radius, g.half_tooth_angle_at_base
    alpha_1 = 0.2
    half = r_b * math.sin(alpha_2)
    x_low, x_high = math.sqrt(r_f**2 - half**2), r_b * math.cos(alpha_2)
    bending = quad(lambda x: 3.0 * (r_b - x * math.cos(alpha_1)) ** 2 / (2.0 * half**3), x_low, x_high)[0]
    normal = quad(lambda x: 1.0 / half, x_low, x_high)[0]
    b, n = root_segment_integrals(np.array([alpha_1]), alpha_2, r_b, r_f)
    # both sides are dimensionless: 1/k_b = (this)/(E L)
    assert b[0] == pytest.approx(bending, rel=1e-12)
    assert n[0] == pytest.approx(normal, rel=1e-12)


def test_root_above_base_circle_has_no_segment_and_ends_on_the_root_circle():
    g = gear(60)
    assert g.root_radius > g.base_radius
    b, n = root_segment_integrals(np.array([0.1]), g.half_tooth_angle_at_base, g.base_radius, g.root_radius)
    assert b[0] == 0.0 and n[0] == 0.0
    end = involute_end_angle(g.half_tooth_angle_at_base, g.base_radius, g.root_radius)
    radius = g.base_radius * math.sqrt(1.0 + (g.half_tooth_angle_at_base - end) ** 2)
    assert radius == pytest.approx(g.root_radius, rel=1e-12)


def test_compliance_is_continuous_where_the_root_circle_crosses_the_base_circle():
    # r_f = r_b when h_f* = z(1 − cos α)/2 (x = 0): just below and just above give nearly the same tooth.
    teeth = 40
    crossing = teeth * (1 - math.cos(ANGLE)) / 2
    below = gear(teeth, dedendum_coefficient=crossing + 1e-4)
    above = gear(teeth, dedendum_coefficient=crossing - 1e-4)
    assert below.root_radius < below.base_radius and above.root_radius > above.base_radius
    alpha_1 = np.linspace(0.05, 0.4, 5)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        c_below = tooth_compliance(below, alpha_1, STEEL, 1.0).total
        c_above = tooth_compliance(above, alpha_1, STEEL, 1.0).total
    np.testing.assert_allclose(c_below, c_above, rtol=2e-4)


def test_compliance_scales_as_one_over_modulus_and_face_width():
    g = gear(27)
    alpha_1 = np.linspace(0.0, 0.4, 7)
    base = tooth_compliance(g, alpha_1, STEEL, 0.02).total
    stiff = tooth_compliance(g, alpha_1, Material(youngs_modulus=2 * STEEL.youngs_modulus), 0.02).total
    wide = tooth_compliance(g, alpha_1, STEEL, 0.06).total
    np.testing.assert_allclose(stiff, base / 2, rtol=1e-13)
    np.testing.assert_allclose(wide, base / 3, rtol=1e-13)


def test_every_component_grows_toward_the_tip():
    g = gear(27)
    alpha_1 = np.linspace(0.1, 0.45, 20)  # larger α1 = contact nearer the tip
    tooth = tooth_compliance(g, alpha_1, STEEL, 1.0)
    for part in (tooth.bending, tooth.shear, tooth.fillet, tooth.total):
        assert np.all(np.diff(part) > 0)


def test_pair_compliance_splits_hertz_in_half_and_sums(luo2019):
    pair = luo2019.gear_pair
    roll = pair.roll_grid(11)
    pc = pair_compliance(pair, luo2019.material, roll)
    np.testing.assert_allclose(pc.pinion_total + pc.wheel_total, pc.total, rtol=1e-15)
    np.testing.assert_allclose(pc.stiffness, 1 / pc.total)
    assert pc.hertz == pytest.approx(hertz_compliance(206e9, 0.3, 0.025))
    # pinion compliance grows along the path (contact moves to its tip), the wheel's falls
    assert np.all(np.diff(pc.pinion.total) > 0) and np.all(np.diff(pc.wheel.total) < 0)


def test_one_to_one_pair_is_symmetric_about_the_pitch_point():
    g = gear(30)
    pair = GearPair.create(g, g)
    points = pair.path_points
    offsets = np.linspace(0.0, points["C"] - points["A"], 9)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        k_before = pair_compliance(pair, STEEL, points["C"] - offsets).stiffness
        k_after = pair_compliance(pair, STEEL, points["C"] + offsets).stiffness
    np.testing.assert_allclose(k_before, k_after, rtol=1e-12)
    assert points["C"] - points["A"] == pytest.approx(points["E"] - points["C"], rel=1e-12)


def test_solid_gear_has_a_finite_compliance():
    # issue 15: a solid gear (bore 0) is evaluated at the nominal seat 0.3 r_f (docs/stiffness.md), not refused
    pair = GearPair.create(gear(27, bore=0.0), gear(35))
    with pytest.warns(ExtrapolationWarning, match="solid gear"):
        compliance = pair_compliance(pair, STEEL, pair.roll_grid(3))
    assert np.all(np.isfinite(compliance.total)) and np.all(compliance.total > 0)


def test_profile_shift_stiffens_the_tooth():
    # a positive shift thickens the root: the same contact radius loads a stiffer tooth
    plain, shifted = gear(20), gear(20, profile_shift=0.4)
    radius = plain.reference_radius + 0.5 * plain.module  # the same contact radius on both flanks
    tan_pressure = math.sqrt(radius**2 - plain.base_radius**2) / plain.base_radius
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        c_plain = tooth_compliance(plain, tan_pressure - plain.half_tooth_angle_at_base, STEEL, 1.0).total
        c_shift = tooth_compliance(shifted, tan_pressure - shifted.half_tooth_angle_at_base, STEEL, 1.0).total
    assert c_shift < c_plain
