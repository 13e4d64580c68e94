"""Luo & Li (2020) Sect. 3 / docs/derivations.md, ASTM D341, ISO/TR 13989-1: oil viscosity, friction at the pitch point and the friction
damping of the luo2019 case. One row per published (or sheet-derived) number, each tolerance argued."""

from __future__ import annotations

import warnings

import pytest
from scipy.optimize import brentq

from thermogear import load_case
from thermogear.luo2020.report.table import paper_reference
from thermogear.summaries.damping import damping_summary
from thermogear.errors import ExtrapolationWarning
from thermogear.lubricant import builtin_lubricant


def _quiet(function, *args, **kwargs):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ExtrapolationWarning)
        return function(*args, **kwargs)


@pytest.fixture(scope="module")
def summary():
    from thermogear.mesh.model import MeshModel
    from thermogear.mesh.model_names import MODELS

    case = load_case("luo2019")
    return _quiet(damping_summary, {model: MeshModel(case, model) for model in MODELS}, case.damping, case.name,
                  count=720)


# The paper's oil (Table 1: 320 / 38.5 cSt at 40 / 100 °C, 870 kg/m³ taken at 15 °C, PAO density coefficient
# −5.5e-4 1/K). docs/derivations.md, given to 4 digits; 1 % covers the rounding of the sheet and the
# choice of density law (with ρ = 870 kg/m³ constant the 80 °C value would be 3.8 % higher, so 1 % still tests
# the law).
@pytest.mark.parametrize("temperature_c, expected_mpa_s", [(30.0, 457.8), (60.0, 115.4), (80.0, 57.0)])
def test_paper_oil_dynamic_viscosity(temperature_c, expected_mpa_s):
    oil = builtin_lubricant("sch632")
    assert _quiet(oil.dynamic_viscosity, temperature_c) * 1e3 == pytest.approx(expected_mpa_s, rel=0.01)


def test_friction_coefficient_at_the_pitch_point_with_oil_at_30_c(summary):
    # docs/derivations.md: 0.0709 (Ra 6.3 μm, w_Bt 401.5 N/mm, X_L = 1). 3 %: the sheet rounds its inputs to 3-4 digits;
    # a 3 % error in μ would need a 12 % error in the load group, well beyond any rounding, so it still tests
    # units and inputs.
    assert summary.pitch["elastic"].friction_coefficient[0] == pytest.approx(0.0709, rel=0.03)


@pytest.mark.parametrize("region, paper_ratio", [("single", 5.72 / 3.41), ("double", 4.03 / 2.40)])
def test_thermal_over_elastic_mean_damping_ratio(summary, region, paper_ratio):
    # Paper: 1.677 (single) and 1.679 (double). With k_e in Eq. 28 for both models (the paper's choice) the ratio
    # is (η(30 °C)/η(T_flank))^0.25 averaged over the region, so it tests the oil law and the temperature input
    # only. ±0.04 (brief): the case's flank temperature is a reconstruction of Fig. 3(c) (77-81 °C) and each
    # kelvin moves the ratio by about 0.015; our single region sits near the 77 °C minimum (ratio ≈ 1.645),
    # the paper's ratio corresponds to 79.6 °C.
    elastic = summary.region_means["elastic"][region]
    thermal = summary.region_means["thermal"][region]
    assert thermal / elastic == pytest.approx(1.68, abs=0.04)
    assert paper_ratio == pytest.approx(1.68, abs=0.005)


def test_paper_ratio_points_to_a_flank_temperature_inside_fig_3():
    # The flank temperature at which (η30/ηT)^0.25 equals the paper's 1.677-1.679 must lie in Fig. 3(c)'s
    # 77-81 °C band (docs/derivations.md finds 79.6 °C): a check of the viscosity law against the paper.
    oil = builtin_lubricant("sch632")
    eta_30 = _quiet(oil.dynamic_viscosity, 30.0)
    for ratio in (5.72 / 3.41, 4.03 / 2.40):
        temperature = brentq(lambda t: (eta_30 / oil.dynamic_viscosity(t)) ** 0.25 - ratio, 40.0, 100.0)
        assert 77.0 <= temperature <= 81.0


@pytest.mark.parametrize("model", ["elastic", "thermal"])
def test_double_region_mean_below_single_region_mean(summary, model):
    # Paper Fig. 7 / Sect. 3: double < single (the opposite of the stiffness), under the paper's rule
    assert summary.rule == "paper"
    means = summary.region_means[model]
    assert means["double"] < means["single"]


@pytest.mark.parametrize("model", ["elastic", "thermal"])
@pytest.mark.parametrize("region", ["single", "double"])
def test_magnitude_beside_the_paper(summary, model, region):
    # Not reproduced exactly: docs/derivations.md derives 1.4-1.7 × the paper's values for bores of 12/15-20/25 mm
    # (the paper gives neither bores nor its stiffness curve; k enters Eq. 28 linearly). The band 1.2-1.9 × is
    # that derivation widened by the flank-temperature reconstruction (±5 % on c_r). A units error (per width,
    # ×b, or total mesh stiffness) would be off by 25× or more.
    paper = paper_reference(load_case("luo2019").citation).mean_damping_n_s_per_m  # the paper table's values
    ratio = summary.region_means[model][region] / paper[model][region]
    assert 1.2 <= ratio <= 1.9
