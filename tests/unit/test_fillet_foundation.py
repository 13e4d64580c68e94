"""Sainsot fillet-foundation compliance: coefficients, the rack-derived root angle, u_f, range warnings."""

from __future__ import annotations

import math
import warnings

import numpy as np
import pytest

from thermogear.errors import CaseError, ExtrapolationWarning
from thermogear.stiffness.fillet_foundation import (check_sainsot_range, fillet_foundation_compliance,
                                                    root_half_angle, root_to_bore_ratio, sainsot_coefficient)

ANGLE = math.radians(20.0)


@pytest.mark.parametrize("name, expected", [("L", 6.89), ("M", 1.24), ("P", 3.21), ("Q", 0.44)])
def test_coefficients_match_the_hand_values_of_the_derivations_page(name, expected):
    # docs/derivations.md: pinion of luo2019 evaluated with h_f = 2.45, θ_f = 0.1048 rad (two decimals given)
    assert float(sainsot_coefficient(name, 2.45, 0.1048)) == pytest.approx(expected, abs=0.006)


def test_root_angle_equals_the_quoted_formula_with_the_tool_addendum():
    # Sainsot et al. (2004): θ_f = [π/2 + 2 tan α (h* − ρ*) + 2ρ*/cos α]/z, here with h* the rack (tool) addendum 1.25
    for teeth in (17, 27, 35, 80):
        quoted = (math.pi / 2 + 2 * math.tan(ANGLE) * (1.25 - 0.38) + 2 * 0.38 / math.cos(ANGLE)) / teeth
        assert root_half_angle(teeth, ANGLE, 1.25, 0.38) == pytest.approx(quoted, rel=1e-14)


def test_root_angle_from_an_independent_construction_of_the_rack_corner():
    """Construct the rack-tip corner circle explicitly (centre at distance ρ from the tip line and from the
    flank) and map the lateral position of its tangency with the tip line onto the gear by rolling."""
    module, teeth, tool_addendum, rho = 1.0, 27, 1.25, 0.38
    # rack tooth (cuts the gear's space): flank x(y) = π/4 − y tan α from the rack tooth middle at depth y
    centre_depth = tool_addendum - rho
    centre_x = math.pi / 4 - centre_depth * math.tan(ANGLE) - rho / math.cos(ANGLE)
    # the corner circle touches the tip line straight below its centre: half-width of the space bottom
    space_half_angle = centre_x / (module * teeth / 2)
    assert root_half_angle(teeth, ANGLE, tool_addendum, rho) == pytest.approx(math.pi / teeth - space_half_angle,
                                                                              rel=1e-12)


def test_full_round_tool_gives_half_the_angular_pitch():
    assert root_half_angle(20, ANGLE, 1.25, 0.6) == pytest.approx(math.pi / 20)


def test_u_f_is_where_the_line_of_action_crosses_the_centreline():
    """With L* = M* = 0 the compliance is P*(1 + Q* tan²α1) cos²α1/(EL); check u_f through the L*, M* terms:
    u_f = r_b/cos α1 − r_f equals d − h_K tan α1 (Sainsot et al. (2004))."""
    r_b, r_f, alpha_2, alpha_1 = 0.038, 0.03675, 0.0731, 0.21
    d = r_b * (math.cos(alpha_1) + (alpha_1 + alpha_2) * math.sin(alpha_1))
    h_k = r_b * ((alpha_1 + alpha_2) * math.cos(alpha_1) - math.sin(alpha_1))
    assert r_b / math.cos(alpha_1) - r_f == pytest.approx(d - h_k * math.tan(alpha_1) - r_f, rel=1e-12)


def test_fillet_compliance_hand_value():
    h_f, theta_f, r_b, r_f, alpha_1 = 2.45, 0.11, 0.038, 0.03675, 0.2
    u_s = (r_b / math.cos(alpha_1) - r_f) / (2 * r_f * theta_f)
    l, m, p, q = (float(sainsot_coefficient(n, h_f, theta_f)) for n in "LMPQ")
    expected = math.cos(alpha_1) ** 2 / 206e9 * (l * u_s**2 + m * u_s + p * (1 + q * math.tan(alpha_1) ** 2))
    value = fillet_foundation_compliance(np.array([alpha_1]), r_b, r_f, h_f, theta_f, 206e9, 1.0)
    assert value[0] == pytest.approx(expected, rel=1e-13)
    # scales with 1/(E L)
    assert fillet_foundation_compliance(alpha_1, r_b, r_f, h_f, theta_f, 103e9, 0.5) == pytest.approx(4 * expected)


def test_negative_bore_refused_with_key_and_solid_gear_is_infinite_ratio():
    # a solid gear (bore 0) is accepted since issue 15 (tests/unit/test_solid_gear_checks.py)
    with pytest.raises(CaseError) as error:
        root_to_bore_ratio(0.036, -0.001, "wheel")
    assert error.value.key == "gears.wheel.bore_radius_mm"
    assert root_to_bore_ratio(0.036, 0.0) == math.inf
    assert root_to_bore_ratio(0.036, 0.015) == pytest.approx(2.4)


def test_extrapolation_warns_but_in_range_does_not():
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        assert check_sainsot_range(2.45, 0.11, "pinion") == []
    with pytest.warns(ExtrapolationWarning, match="θ_f"):
        check_sainsot_range(2.45, 0.19, "pinion")
    with pytest.warns(ExtrapolationWarning) as record:  # h_f = 9 also drives L*, M*, P*, Q* out of their ranges
        check_sainsot_range(9.0, 0.11, "wheel")
    assert any("h_f" in str(item.message) for item in record)
    assert check_sainsot_range(9.0, 0.11, "wheel", warn=False)
