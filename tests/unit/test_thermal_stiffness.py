"""Thermal stiffness (Luo & Li Eqs. 13–23): identities on synthetic compliances, X_te resolution, wiring."""

from __future__ import annotations

import sys
import types

import numpy as np
import pytest

from thermogear.case.pieces import call_with_pieces
from thermogear.errors import CaseError, ModelAssumptionWarning, ThermogearError
from thermogear.luo2020.thermal import calibration as calibration_module
from thermogear.luo2020.thermal.calibration import x_te_for_drop
from thermogear.luo2020.thermal.case_stiffness import paper_thermal_model
from thermogear.luo2020.thermal.stiffness import (pair_share_normal_load, thermal_pair_stiffness,
                                                  thermal_stiffness_of_pair, thermal_stiffness_of_tooth)
from thermogear.summaries.thermal import crossing_gammas

# Synthetic per-tooth compliances of a pair along the path (totals, m/N) and expansions (m): orders of magnitude
# of the luo2019 pair (δ ≈ 4e-9 m/N, Δ ≈ 5–15 μm, F_n ≈ 1e4 N).
PINION = np.array([1.2e-9, 1.5e-9, 1.9e-9, 2.4e-9, 3.4e-9])
WHEEL = np.array([3.1e-9, 2.2e-9, 1.7e-9, 1.4e-9, 1.1e-9])
EXPANSION_1 = np.array([6e-6, 9e-6, 10e-6, 11e-6, 14e-6])
EXPANSION_2 = np.array([17e-6, 14e-6, 12.5e-6, 12e-6, 9e-6])
LOAD = 1.0e4


def test_zero_x_te_gives_the_elastic_stiffness_exactly():
    result = thermal_pair_stiffness(PINION, WHEEL, EXPANSION_1, EXPANSION_2, LOAD, 0.0)
    np.testing.assert_array_equal(result.stiffness, 1.0 / (PINION + WHEEL))
    np.testing.assert_array_equal(result.stiffness, result.elastic_stiffness)
    np.testing.assert_array_equal(thermal_stiffness_of_pair(LOAD, 1.0 / (PINION + WHEEL), EXPANSION_1 + EXPANSION_2,
                                                            0.0), 1.0 / (PINION + WHEEL))


@pytest.mark.parametrize("x_te", [0.0, 0.2166, 1.0, 3.0])
def test_eq17_is_the_series_of_eq16_for_both_teeth(x_te):
    stiffness = 1.0 / (PINION + WHEEL)
    total = EXPANSION_1 + EXPANSION_2
    tooth_1 = thermal_stiffness_of_tooth(LOAD, 1.0 / PINION, stiffness, total, EXPANSION_1, x_te)
    tooth_2 = thermal_stiffness_of_tooth(LOAD, 1.0 / WHEEL, stiffness, total, EXPANSION_2, x_te)
    pair = thermal_stiffness_of_pair(LOAD, stiffness, total, x_te)
    np.testing.assert_allclose(tooth_1 * tooth_2 / (tooth_1 + tooth_2), pair, rtol=1e-12)
    # ... and the compliance form (Eqs. 20–23) is the same thing.
    result = thermal_pair_stiffness(PINION, WHEEL, EXPANSION_1, EXPANSION_2, LOAD, x_te)
    np.testing.assert_allclose(result.stiffness, pair, rtol=1e-12)
    np.testing.assert_allclose(result.pinion_stiffness, tooth_1, rtol=1e-12)
    np.testing.assert_allclose(result.wheel_stiffness, tooth_2, rtol=1e-12)
    np.testing.assert_allclose(result.pinion_compliance + result.wheel_compliance, result.compliance, rtol=1e-12)
    np.testing.assert_allclose(result["δ_Tp"], total / LOAD, rtol=1e-15)


def test_eq21_compliance_grows_by_x_te_delta_tp():
    # Eqs. 19–21 by hand at one point: δ_T − δ = X_te (Δ_t1 + Δ_t2)/F_n.
    result = thermal_pair_stiffness(2e-9, 2e-9, 10e-6, 12e-6, 1e4, 0.25)
    assert float(result.compliance - 4e-9) == pytest.approx(0.25 * 22e-6 / 1e4, rel=1e-12)
    # Eq. 23 by hand: δ_T1 = δ1 + (δ1/δ)(1 + X) δ_Tp − Δ1/F = 2e-9 + 0.5·1.25·2.2e-9 − 1e-9
    assert float(result.pinion_compliance) == pytest.approx(2e-9 + 0.5 * 1.25 * 2.2e-9 - 1e-9, rel=1e-12)


def test_eq18_ratio_is_independent_of_the_face_width_convention():
    # Totals (k = b k′, F = b F′) and per-unit-width values give the same k_T/k_e (Δ does not scale with b).
    width = 0.025
    ratio_total = thermal_stiffness_of_pair(LOAD, 1.0 / (PINION + WHEEL), EXPANSION_1 + EXPANSION_2, 0.3) * (
        PINION + WHEEL)
    ratio_per_width = thermal_stiffness_of_pair(LOAD / width, 1.0 / ((PINION + WHEEL) * width),
                                                EXPANSION_1 + EXPANSION_2, 0.3) * (PINION + WHEEL) * width
    np.testing.assert_allclose(ratio_total, ratio_per_width, rtol=1e-13)


def test_heat_softens_the_pair_for_positive_x_te():
    result = thermal_pair_stiffness(PINION, WHEEL, EXPANSION_1, EXPANSION_2, LOAD, 0.2)
    assert np.all(result.stiffness < result.elastic_stiffness)


@pytest.mark.parametrize("x_te", [-0.1, np.nan])
def test_bad_x_te_is_refused(x_te):
    with pytest.raises(CaseError, match="thermal.x_te"):
        thermal_pair_stiffness(PINION, WHEEL, EXPANSION_1, EXPANSION_2, LOAD, x_te)


def test_bad_load_is_refused():
    with pytest.raises(CaseError, match="normal_load"):
        thermal_pair_stiffness(PINION, WHEEL, EXPANSION_1, EXPANSION_2, 0.0, 0.2)


def test_non_physical_single_tooth_compliance_is_reported():
    with pytest.warns(ModelAssumptionWarning, match="δ_Ti"):
        thermal_pair_stiffness(1e-9, 3e-9, 40e-6, 0.0, 1e4, 0.0)  # Δ1/F = 4e-9 > δ1 + its share


def test_x_te_for_drop_round_trip():
    stiffness = 1.0 / (PINION + WHEEL)
    x_te = x_te_for_drop(14.52, LOAD, stiffness[2], EXPANSION_1[2] + EXPANSION_2[2])
    ratio = thermal_stiffness_of_pair(LOAD, stiffness[2], EXPANSION_1[2] + EXPANSION_2[2], x_te) / stiffness[2]
    assert 100.0 * (1.0 - ratio) == pytest.approx(14.52, rel=1e-12)
    with pytest.raises(CaseError, match="no X_te"):
        x_te_for_drop(10.0, LOAD, stiffness[2], 0.0)


def test_pair_share_loads():
    # Two pairs of equal stiffness share equally; a pair alone carries the whole load.
    def constant(roll):
        return np.full(np.shape(roll), 2.0e8)

    roll = np.array([0.0, 0.8, 1.0])  # path [0, 1.6], base pitch 1: the middle point is single contact
    load = pair_share_normal_load(100.0, roll, constant, 0.0, 1.6, 1.0)
    np.testing.assert_allclose(load, [50.0, 100.0, 50.0])


def test_crossings_are_located():
    gamma = np.linspace(-0.5, 0.5, 101)
    assert crossing_gammas(gamma, np.zeros_like(gamma), gamma - 0.123) == [pytest.approx(0.123, abs=1e-12)]
    assert crossing_gammas(gamma, np.zeros_like(gamma), gamma**2 + 0.1) == []


# ------------------------------------------------------------------------------------------------- cases
def test_case_with_zero_x_te_equals_the_elastic_pair(luo2019):
    from thermogear.stiffness.potential_energy import pair_compliance

    roll = luo2019.gear_pair.roll_grid(21)
    result = call_with_pieces(paper_thermal_model, luo2019).thermal_stiffness(roll, x_te=0.0)
    np.testing.assert_array_equal(result.stiffness, pair_compliance(luo2019.gear_pair, luo2019.material,
                                                                    roll).stiffness)


def test_dynamics_entry_matches_the_direct_evaluation(luo2019):
    pair = luo2019.gear_pair
    roll = np.linspace(pair.path_points["A"], pair.path_points["E"], 17)
    model = call_with_pieces(paper_thermal_model, luo2019)
    direct = model.thermal_stiffness(roll).stiffness
    # The dynamics entry interpolates the cached PEM table (cubic spline, < 1e-6 relative).
    np.testing.assert_allclose(model.pair_stiffness_at(roll), direct, rtol=1e-5)
    outside = model.pair_stiffness_at(np.array([pair.path_points["A"] - 1e-3, pair.path_points["E"] + 1e-3]))
    np.testing.assert_array_equal(outside, 0.0)


def test_resolve_given(luo2019):
    case = luo2019.with_changes(thermal={"x_te_source": "given", "x_te": 0.3})
    assert call_with_pieces(paper_thermal_model, case).resolve_x_te() == (0.3, "given")
    with pytest.raises(CaseError, match="needs thermal.x_te"):
        call_with_pieces(paper_thermal_model, luo2019.with_changes(thermal={"x_te_source": "given"})).resolve_x_te()


def test_resolve_calibrated_is_labelled_as_a_calibration(luo2019):
    model = call_with_pieces(paper_thermal_model, luo2019)
    value, label = model.resolve_x_te()
    assert label.startswith("calibrated: X_te=") and "14.52 % drop at C" in label
    assert value == pytest.approx(model.calibrate_x_te().x_te, rel=1e-15)
    with pytest.raises(CaseError, match="either given or calibrated"):
        both = luo2019.with_changes(thermal=dict(luo2019.document["thermal"], x_te=0.2))
        call_with_pieces(paper_thermal_model, both).resolve_x_te()


def test_resolve_fem_without_provider(luo2019, monkeypatch):
    # an installation without the FE model: no provider registered, and importing the provider module adds none
    monkeypatch.setattr(calibration_module, "_PROVIDERS", {})
    monkeypatch.setitem(sys.modules, "thermogear.fem.provider", types.ModuleType("thermogear.fem.provider"))
    with pytest.raises(ThermogearError, match="not registered"):
        call_with_pieces(paper_thermal_model, luo2019.with_changes(thermal={"x_te_source": "fem"})).resolve_x_te()
    calibration_module.register_x_te_provider("fem", lambda case: 0.4)
    fem = luo2019.with_changes(thermal={"x_te_source": "fem"})
    assert call_with_pieces(paper_thermal_model, fem).resolve_x_te() == (0.4, "fem")
    calibration_module.register_x_te_provider("fem", lambda case: -0.4)
    with pytest.raises(CaseError, match=">= 0"):
        call_with_pieces(paper_thermal_model, luo2019.with_changes(thermal={"x_te_source": "fem"})).resolve_x_te()


def test_calibration_at_another_point(luo2019):
    model = call_with_pieces(paper_thermal_model, luo2019)
    calibration = model.calibrate_x_te(drop_percent=10.0, point="A")
    result = model.thermal_stiffness(np.array([luo2019.gear_pair.path_points["A"]]), x_te=calibration.x_te)
    assert float(result.drop_percent[0]) == pytest.approx(10.0, rel=1e-9)


# At 1 kN the wheel's single-tooth compliance of Eq. 23 turns negative towards E (the warning's case, tested
# above); the pair stiffness these tests check is defined all the same.
@pytest.mark.filterwarnings("ignore::thermogear.errors.ModelAssumptionWarning")
@pytest.mark.parametrize("basis", ["external", "pair_share"])
def test_a_calibrated_x_te_makes_k_t_the_same_at_every_load(luo2019, basis):
    # The calibration is solved at the load asked for (Eq. 18 for X_te): X_te = g·F_n(P)/(k_e(P)·ΣΔ_t(P)), so
    # X_te·δ_Tp = X_te·ΣΔ_t/F_n does not depend on the load and neither does k_T (F_n(s)/F_n(P) is a ratio of
    # elastic shares under 'pair_share'). The two loads differ by 8×; the spline of each load is built on its own.
    case = luo2019.with_changes(thermal=dict(luo2019.document["thermal"], load_basis=basis))
    pair = case.gear_pair
    roll = np.linspace(pair.path_points["A"], pair.path_points["E"], 23)
    model = call_with_pieces(paper_thermal_model, case)
    light, heavy = (model.pair_stiffness_at(roll, normal_load=load) for load in (1.0e3, 8.0e3))
    # equal to rounding: X_te is one multiplication and one division by the load away from the other's
    np.testing.assert_allclose(light, heavy, rtol=1e-13, atol=0.0)
    point = np.array([pair.path_points[case.thermal.calibration_point]])
    drop = 1.0 - model.pair_stiffness_at(point, normal_load=1.0e3) / model.thermal_stiffness(point, x_te=0.0).stiffness
    # the calibration target at its point, at the other load too; 1e-6: the dynamics entry is a cubic spline of the
    # PEM table (test_dynamics_entry_matches_the_direct_evaluation), the reference the direct Eq. 8-23 evaluation
    target = case.thermal.calibration_drop_percent / 100.0
    assert float(drop[0]) == pytest.approx(target, rel=1e-6)


@pytest.mark.filterwarnings("ignore::thermogear.errors.ModelAssumptionWarning")
def test_a_given_x_te_makes_the_secant_k_t_depend_on_the_load(luo2019):
    # k_T = F_n·k_e/(F_n + X_te·k_e·ΣΔ_t) (Eq. 17): the drop shrinks as the load grows
    # the X_te that luo2019's calibration gives at its own load, now given
    case = luo2019.with_changes(thermal={"x_te_source": "given",
                                         "x_te": call_with_pieces(paper_thermal_model, luo2019).resolve_x_te()[0]})
    roll = np.array([case.gear_pair.path_points["C"]])
    model = call_with_pieces(paper_thermal_model, case)
    elastic = model.thermal_stiffness(roll, x_te=0.0).stiffness
    drops = [float(1.0 - model.pair_stiffness_at(roll, normal_load=load)[0] / elastic[0])
             for load in (1.0e3, 8.0e3)]
    assert drops[0] > 2.0 * drops[1] > 0.0


@pytest.mark.filterwarnings("ignore::thermogear.errors.ModelAssumptionWarning")
def test_the_resolved_model_keeps_no_case_alive(luo2019):
    # what paper_thermal_model computes once per case (splines, the own X_te) is memoised per case (the piece
    # paper_thermal_memo) without a reference back to it: a case asked for its k_T is freed with its memo (a sweep
    # makes thousands of cases)
    import gc
    import weakref

    from thermogear.luo2020.thermal.case_stiffness import paper_thermal_memo

    case = luo2019.with_changes(**{"operating.speed_rpm": 1500.0})
    key = id(case)
    roll = np.array([case.gear_pair.path_points["C"]])
    first = call_with_pieces(paper_thermal_model, case)
    value = first.pair_stiffness_at(roll)
    # the memo is the case's: a second resolution reuses the spline and the X_te of the first
    assert call_with_pieces(paper_thermal_model, case).memo is first.memo and first.memo["splines"]
    np.testing.assert_array_equal(call_with_pieces(paper_thermal_model, case).pair_stiffness_at(roll), value)
    alive = weakref.ref(case)
    del case, first
    gc.collect()
    assert alive() is None
    assert key not in paper_thermal_memo.cases()  # the memo went with its case: the table does not grow over a sweep


def test_only_the_papers_pair_model_uses_x_te():
    from thermogear.mesh.pair_models import PAIR_MODELS

    assert {name for name, model in PAIR_MODELS.items() if model.uses_x_te} == {"luo2020"}
