"""FE verification (issue 7) against the potential energy method, Luo & Li Eqs. 8–12 and the paper's Fig. 3(c)
and Fig. 4 numbers. Coarse default meshes (refinement 1); the refinement study is marked slow."""

from __future__ import annotations

import numpy as np
import pytest

from thermogear.case import load_case
from thermogear.fem.inputs import fem_inputs
from thermogear.fem.verification import (UNIFORM_RISE, cached_analysis, fem_analysis, refinement_change_percent,
                                         stiffness_along_path)
from thermogear.luo2020.thermal.expansion import flank_expansion_along_line_of_action

GEARS = ("pinion", "wheel")


@pytest.fixture(scope="module", params=["luo2019", "fzg_type_c"])
def analysis(request):
    return cached_analysis(fem_inputs(load_case(request.param)))


@pytest.fixture(scope="module")
def luo():
    return cached_analysis(fem_inputs(load_case("luo2019")))


@pytest.mark.parametrize("which", GEARS)
def test_fe_single_tooth_compliance_within_15_percent_of_pem(analysis, which):
    """Issue 7 acceptance: 15 % covers the PEM's beam idealisation (cantilever on a Sainsot foundation fitted
    to FE of its own) against a 2-D continuum of the real rack-generated tooth on a clamped bore."""
    difference = analysis.deflection[which].difference_percent
    assert np.max(np.abs(difference)) < 15.0


def test_fe_flank_expansion_of_a_uniform_rise_is_the_homogeneous_expansion(analysis):
    """A free gear heated uniformly expands homogeneously: the contact point moves along the line of action by
    λ ΔT ρ_k exactly (ρ_k = r_k sin α_k). 0.5 % covers the roller penalty and the P2 discretisation."""
    alpha = analysis.inputs.material.thermal_expansion
    pair = analysis.gear_pair
    for which in GEARS:
        own = analysis.roll if which == "pinion" else pair.line_of_action_length - analysis.roll
        assert np.allclose(analysis.uniform_expansion_fe[which], alpha * UNIFORM_RISE * own, rtol=5e-3)


def test_eqs_8_12_exceed_the_fe_expansion_by_the_angular_term_of_eq_9(analysis):
    """Eqs. 8–12 add Δφ_k = Δs_k/r_k′ (Eq. 9) on top of the radial growth, which already widens the tooth by
    Δs_k: the surplus along the line of action is λ ΔT r_k φ_k cos α_k = λ ΔT r_b φ_k (first order). The FE has no
    such term; the difference between the two must be that term within 2 % of it."""
    alpha = analysis.inputs.material.thermal_expansion
    pair = analysis.gear_pair
    for which in GEARS:
        gear = getattr(pair, which)
        own = analysis.roll if which == "pinion" else pair.line_of_action_length - analysis.roll
        half_angle = np.asarray(gear.half_angle_at(np.hypot(gear.base_radius, own)))
        printed = flank_expansion_along_line_of_action(gear, own, UNIFORM_RISE, UNIFORM_RISE, UNIFORM_RISE, alpha,
                                                       "paper")
        surplus = printed - analysis.uniform_expansion_fe[which]
        assert np.allclose(surplus, alpha * UNIFORM_RISE * gear.base_radius * half_angle, rtol=0.02)


def test_consistent_eqs_8_12_match_the_fe_expansion_within_10_percent(analysis):
    """Issue 7 acceptance, with Eq. 9 in its consistent form (thermal.expansion_model = "consistent"): for a
    uniform rise it is the homogeneous expansion, which the FE reproduces within its 0.5 % discretisation error;
    10 % is the issue's bound. (The printed form misses it by the double-counted term above, up to ~30 %.)"""
    alpha = analysis.inputs.material.thermal_expansion
    pair = analysis.gear_pair
    for which in GEARS:
        gear = getattr(pair, which)
        own = analysis.roll if which == "pinion" else pair.line_of_action_length - analysis.roll
        consistent = flank_expansion_along_line_of_action(gear, own, UNIFORM_RISE, UNIFORM_RISE, UNIFORM_RISE,
                                                          alpha, "consistent")
        assert np.max(np.abs(analysis.uniform_expansion_fe[which] / consistent - 1.0)) < 0.10


def test_fe_temperatures_order_flank_base_bore_oil(luo):
    """Heat enters at the flank and leaves through convection: flank > base circle > bore > oil, both gears."""
    for which in GEARS:
        temperature = luo.temperatures[which]
        flank = temperature.flank_c(luo.roll if which == "pinion"
                                    else luo.gear_pair.line_of_action_length - luo.roll)
        assert np.min(flank) > temperature.base_c > temperature.bore_c > temperature.oil_c


def test_fe_flank_temperature_has_a_minimum_near_the_pitch_point(luo):
    """Luo & Li Fig. 3(c): lowest near the pitch point, higher toward tip and root. The sliding speed (hence the
    friction heat) vanishes at C; the FE curve has its interior minimum within |Γ| < 0.1."""
    pair = luo.gear_pair
    roll = pair.roll_grid(201)
    gamma = pair.gamma(roll)
    flank = luo.temperatures["pinion"].flank_c(roll)
    inner = (gamma > -0.3) & (gamma < 0.3)
    assert abs(gamma[inner][np.argmin(flank[inner])]) < 0.1
    assert flank[inner].min() < flank[gamma < -0.3].max() and flank[inner].min() < flank[gamma > 0.3].max()


@pytest.mark.xfail(strict=True, reason="known gap: the FE flank is 89-91 °C, the paper's 77-81 °C; the paper's "
                   "convection coefficients and heat partition are unknown (docs/derivations.md) and none is tuned here")
def test_fe_flank_temperature_in_the_papers_range(luo):
    """Paper Fig. 3(c): 77–81 °C along the path (±1 K read from the figure)."""
    flank = luo.flank_temperature_points()
    assert all(76.0 <= value <= 82.0 for value in flank.values())


def test_fe_thermal_stiffness_below_elastic_with_the_largest_drop_at_c(luo):
    """Fig. 15/Fig. 4 statements: kT < ke along the path, the largest drop near the pitch point."""
    curves = stiffness_along_path(cached_analysis(luo.inputs, checks=False))
    assert np.all(curves["thermal"] < curves["elastic"])
    drop = luo.summary()["stiffness_drop_percent"]
    assert drop["C"] > drop["A"] and drop["C"] > drop["E"]


@pytest.mark.xfail(strict=True, reason="known gap: X_te from the FE runs (deformation magnitudes, the paper's "
                   "procedure as read) is about 1.6, giving 50-60 % drops; the paper's 8.53/14.52 % need X_te about "
                   "0.2 (docs/fem.md)")
@pytest.mark.parametrize("point, paper", [("A", 8.53), ("C", 14.52), ("E", 8.53)])
def test_fe_x_te_gives_the_papers_stiffness_drops(luo, point, paper):
    """Paper Fig. 4 drops; ±3 points of percentage for the paper's read-off and the unknown bores."""
    assert luo.summary()["stiffness_drop_percent"][point] == pytest.approx(paper, abs=3.0)


@pytest.mark.slow
def test_reported_quantities_change_less_than_2_percent_on_refinement():
    """Issue 7: the reported quantities (compliances, temperature rises above the oil, FE expansions, X_te)
    change by less than 2 % from refinement 1 to 2 (element sizes halved)."""
    inputs = fem_inputs(load_case("luo2019"))
    changes = refinement_change_percent(cached_analysis(inputs, 1.0), fem_analysis(inputs, 2.0))
    assert changes["max"] < 2.0, changes


def test_the_analysis_without_its_checks_gives_the_same_pair_stiffness(luo):
    """Fig. 15 asks for the analysis without the other plane and the uniform-rise check (the report's FE child
    does half the solves): the pair stiffness it gives is the complete analysis's to the last bit (the same solves
    on the same meshes, only fewer of them), and its summary, which reports the skipped checks, is refused."""
    light = fem_analysis(luo.inputs, checks=False)
    assert not light.checks and not light.deflection_other_plane and not light.uniform_expansion_fe
    complete, trimmed = luo.thermal_result(), light.thermal_result()
    for name in ("elastic_stiffness", "stiffness", "elastic_pinion_compliance", "pinion_stiffness"):
        np.testing.assert_array_equal(getattr(trimmed, name), getattr(complete, name))
    with pytest.raises(ValueError, match="without its checks"):
        light.summary()
    assert cached_analysis(luo.inputs, checks=False) is luo  # a complete analysis in the cache answers too


def test_a_second_load_of_the_case_shares_the_analysis(luo):
    """The memo is keyed on the case document (the inputs are resolved from it), not on the Case object: the
    providers, the report's FE stage and `thermogear fem` each resolve the case afresh and must not solve again."""
    again = fem_inputs(load_case("luo2019"))
    assert again is not luo.inputs
    assert cached_analysis(again) is luo
