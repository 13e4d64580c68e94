"""Lubricant: ASTM D341 fit, density law, dynamic viscosity, built-in library, case wiring, bad input."""

from __future__ import annotations

import math
import re
import warnings

import numpy as np
import pytest

from thermogear.errors import CaseError, ExtrapolationWarning
from thermogear.lubricant import (Lubricant, builtin_lubricant, builtin_lubricant_names, linear_density,
                                  lubricant_from_case, walther_constants, walther_kinematic_viscosity)

PAPER_POINTS = [[40.0, 320.0], [100.0, 38.5]]


def test_two_point_walther_constants_match_hand_values():
    # docs/derivations.md: A = 6.84743, B = 2.58376 for 320 cSt @ 40 °C and 38.5 cSt @ 100 °C
    a, b = walther_constants(PAPER_POINTS)
    assert a == pytest.approx(6.84743, abs=2e-5)
    assert b == pytest.approx(2.58376, abs=2e-5)


def test_two_point_fit_passes_through_its_points():
    a, b = walther_constants([[20.0, 150.0], [90.0, 12.0]])
    assert walther_kinematic_viscosity([20.0, 90.0], a, b) * 1e6 == pytest.approx([150.0, 12.0], rel=1e-12)


def test_least_squares_fit_recovers_the_line_from_three_points():
    a, b = 8.5, 3.3
    temperatures = np.array([25.0, 60.0, 110.0])
    viscosity = walther_kinematic_viscosity(temperatures, a, b) * 1e6
    fitted = walther_constants(np.column_stack([temperatures, viscosity]))
    assert fitted == pytest.approx((a, b), rel=1e-9)


def test_point_order_does_not_matter():
    assert walther_constants(PAPER_POINTS[::-1]) == pytest.approx(walther_constants(PAPER_POINTS))


def test_density_law_and_dynamic_viscosity():
    oil = Lubricant.from_points("x", PAPER_POINTS, density=870.0, density_coefficient=-5.5e-4, base_oil="pao")
    assert oil.density(15.0) == pytest.approx(870.0)
    assert oil.density(30.0) == pytest.approx(870.0 * (1 - 5.5e-4 * 15.0))
    assert linear_density(115.0, 900.0, 15.0, -6e-4) == pytest.approx(900.0 * 0.94)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        eta = oil.dynamic_viscosity(60.0)
    assert eta == pytest.approx(oil.kinematic_viscosity(60.0) * oil.density(60.0))
    # SI: 136 cSt = 1.36e-4 m²/s
    assert oil.kinematic_viscosity(60.0) == pytest.approx(1.3596e-4, rel=1e-3)


def test_viscosity_falls_monotonically_with_temperature():
    oil = builtin_lubricant("iso_vg_220_mineral")
    values = oil.kinematic_viscosity(np.linspace(40.0, 100.0, 61))
    assert np.all(np.diff(values) < 0)


def test_extrapolation_warns_and_says_by_how_much():
    oil = Lubricant.from_points("x", PAPER_POINTS, density=870.0, base_oil="pao")
    with pytest.warns(ExtrapolationWarning, match=r"10\.0 K below the fitted range 40–100 °C"):
        oil.dynamic_viscosity(30.0)
    with pytest.warns(ExtrapolationWarning, match=r"20\.0 K above"):
        oil.kinematic_viscosity(120.0)


@pytest.mark.parametrize("points, reason", [
    ([[40.0, 320.0]], "at least two points"),
    ([], "at least two points"),
    ([[40.0, 38.5], [100.0, 320.0]], "thins when heated"),
    ([[40.0, 100.0], [100.0, 100.0]], "thins when heated"),
    ([[40.0, 100.0], [40.0, 90.0]], "share a temperature"),
    ([[40.0, 10.0], [100.0, 1.5]], "2 mm²/s"),
])
def test_bad_viscosity_points_are_refused(points, reason):
    with pytest.raises(CaseError, match=re.escape(reason)) as caught:
        walther_constants(points)
    assert caught.value.key == "lubricant.viscosity_points"


def test_positive_density_coefficient_refused():
    with pytest.raises(CaseError, match="density_coefficient"):
        Lubricant.from_points("x", PAPER_POINTS, density=870.0, density_coefficient=1e-4)


def test_library_contains_the_required_oils_with_sources():
    names = builtin_lubricant_names()
    required = {"sch632", "iso_vg_100_mineral"} | {f"iso_vg_{g}_mineral" for g in (32, 46, 68, 100, 150, 220,
                                                                                   320, 460)}
    assert required <= set(names)
    assert sum(name.endswith("_pao") for name in names) >= 3
    for name in names:
        oil = builtin_lubricant(name)
        assert len(oil.source) > 40, name
        assert oil.fitted_range_c == (40.0, 100.0)


@pytest.mark.parametrize("name", [n for n in builtin_lubricant_names() if n.startswith("iso_vg_")])
def test_builtin_grades_lie_in_their_iso_3448_band(name):
    # ISO 3448: the 40 °C viscosity of grade VG g lies within ±10 % of g
    grade = int(name.split("_")[2])
    nu_40 = builtin_lubricant(name).kinematic_viscosity(40.0) * 1e6
    assert 0.9 * grade <= nu_40 <= 1.1 * grade
    # PAO thins less with temperature than mineral oil of the same grade (higher viscosity index)
    if name.endswith("_pao") and f"iso_vg_{grade}_mineral" in builtin_lubricant_names():
        mineral = builtin_lubricant(f"iso_vg_{grade}_mineral").kinematic_viscosity(100.0)
        assert builtin_lubricant(name).kinematic_viscosity(100.0) > mineral


def test_lubricant_factor_from_base_oil():
    assert builtin_lubricant("iso_vg_100_mineral").lubricant_factor == 1.0
    assert builtin_lubricant("sch632").lubricant_factor == 0.8


def test_unknown_builtin_name_suggests_the_closest():
    with pytest.raises(CaseError, match="did you mean 'sch632'"):
        builtin_lubricant("sch623")


def test_case_selects_builtin_or_defines_its_own(luo2019):
    oil = lubricant_from_case(luo2019)
    assert oil.name == "sch632"
    custom = luo2019.with_changes(**{"lubricant": {"name": "mine", "viscosity_points": [[40, 100], [100, 11]],
                                                   "density_kg_m3": 880.0, "base_oil": "mineral"}})
    oil = lubricant_from_case(custom)
    assert oil.name == "mine" and oil.density(15.0) == pytest.approx(880.0)
    assert oil.kinematic_viscosity(100.0) * 1e6 == pytest.approx(11.0)


def test_case_with_increasing_viscosity_points_is_refused(luo2019):
    with pytest.raises(CaseError) as caught:  # refused when the case is loaded (issue 15)
        luo2019.with_changes(**{"lubricant": {"viscosity_points": [[40, 10], [100, 30]], "base_oil": "pao"}})
    assert caught.value.key == "lubricant.viscosity_points"


def test_case_override_of_builtin_density(luo2019):
    case = luo2019.with_changes(**{"lubricant.density_kg_m3": 860.0})
    assert lubricant_from_case(case).density(15.0) == pytest.approx(860.0)
    assert math.isclose(lubricant_from_case(luo2019).density(15.0), 870.0)
