"""The paper's pair under the predictive thermo-elastic model, beside the paper's model (report section).

Expected from the physics, not from a fit: the teeth are at ~77–81 °C (a ~60 K rise), so E(T) alone takes about
60 K × 3.3e-4 /K ≈ 2 % off the stiffness; the gears hotter than the housing (at the 60 °C oil) shorten the
effective centre distance, which raises the contact ratio a little. So the mean mesh stiffness changes by a few
per cent at most (−4 % … +2 %, the issue's band for a pair at 80 °C), far from the paper's calibrated −13 %, and
the backlash falls (gears hotter than the housing).
"""

from __future__ import annotations

import warnings

import pytest

from thermogear.case import load_case
from thermogear.evaluation import thermoelastic_beside_paper
from thermogear.report.thermoelastic_section import thermoelastic_section
from thermogear.simulation import Simulation


@pytest.fixture(scope="module")
def comparison():
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        case = load_case("luo2019")
        predictive = case.with_changes(**{"thermal.model": "thermoelastic"})
        return thermoelastic_beside_paper({"elastic": Simulation(case, "elastic"), "luo2020": Simulation(case, "thermal"),
                                           "thermoelastic": Simulation(predictive, "thermal")})


def test_predictive_stiffness_change_is_what_e_and_geometry_give(comparison):
    assert -4.0 < comparison["thermoelastic"]["stiffness_change_percent"] < 2.0
    # the paper's secant k_T with its calibrated X_te: the mean over the cycle falls by about the calibrated 14.5 %
    assert comparison["luo2020"]["stiffness_change_percent"] < -10.0


def test_backlash_falls_when_the_gears_are_hotter_than_the_housing(comparison):
    predictive = comparison["thermoelastic"]
    assert predictive["backlash_hot_um"] < predictive["backlash_cold_um"]
    assert predictive["jamming_bulk_temperature_c"] > 100.0 and predictive["flags"] == []
    assert comparison["luo2020"]["backlash_normal_um"] is None  # the paper's model does not expand the geometry


def test_section_shows_the_three_models_side_by_side(comparison):
    page = thermoelastic_section(comparison)
    assert "paper's model (luo2020)" in page and "thermo-elastic" in page and "not modelled" in page
    assert thermoelastic_section(None) == ""
