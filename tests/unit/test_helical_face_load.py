"""Load along the face: the slice solver against ISO 6336-1's K_Hβ (its analytic case), crowning, thermal lead
distortion, and the time-varying helical pair."""

from __future__ import annotations

import math
import warnings

import numpy as np
import pytest

from thermogear.errors import ExtrapolationWarning, ModelAssumptionWarning
from thermogear.helical.face_load import (end_relief, face_load, helix_slope_deviation, iso_face_load_factor,
                                          lead_crowning, slice_loads, thermal_lead_deviation, SliceContacts)
from thermogear.helical.geometry import HelicalPair
from thermogear.helical.slices import contact_stiffness
from thermogear.materials import Material

B = 25e-3
C = 15.549e9  # c_γβ [N/m per m] (15.549 N/(mm·μm))
SLICES = 2000
Z = (np.arange(SLICES) + 0.5) * B / SLICES


def _uniform(gap: np.ndarray, line_load: float) -> tuple[float, np.ndarray]:
    delta, loads = slice_loads(np.full(SLICES, C * B / SLICES), gap, line_load * B)
    return delta, loads / (B / SLICES)


@pytest.mark.parametrize("line_load, mismatch", [(364.3e3, 10e-6), (364.3e3, 40e-6), (364.3e3, 60e-6),
                                                 (150e3, 30e-6)])
def test_uniform_stiffness_and_a_linear_mismatch_give_iso_k_h_beta(line_load, mismatch):
    """Both branches of ISO 6336-1's K_Hβ are this solver's exact answers for a uniform c_γβ; 2000 midpoint slices
    place the end of a partial contact within b/2000, which moves the peak by less than 1e-3."""
    _, loads = _uniform(helix_slope_deviation(Z, B, mismatch), line_load)
    assert loads.max() / line_load == pytest.approx(iso_face_load_factor(mismatch, C, line_load), abs=1e-3)


@pytest.mark.parametrize("crowning", [5e-6, 10e-6, 20e-6])
def test_a_crowning_in_full_contact_gives_one_plus_c_c_beta_over_three_w(crowning):
    """w(z) = w_m + c C_β[1/3 − (2z/b − 1)²]: the peak at mid-face is w_m(1 + c C_β/(3 w_m)) (the midpoint rule
    integrates the parabola to (b/N)²/12 of its curvature: 1e-7 here)."""
    line_load = 364.3e3
    _, loads = _uniform(lead_crowning(Z, B, crowning), line_load)
    assert loads.min() > 0.0
    assert loads.max() / line_load == pytest.approx(1.0 + C * crowning / (3.0 * line_load), rel=1e-6)
    np.testing.assert_allclose(loads, loads[::-1], rtol=1e-12)  # symmetric about mid-face


def test_end_reliefs_unload_both_ends_alike():
    gap = end_relief(Z, B, 10e-6, 5e-3)
    assert gap[0] == pytest.approx(10e-6 * (5e-3 - Z[0]) / 5e-3) and gap[SLICES // 2] == 0.0
    _, loads = _uniform(gap, 364.3e3)
    np.testing.assert_allclose(loads, loads[::-1], rtol=1e-12)
    assert loads[0] < loads[SLICES // 2]


def test_the_load_balances():
    stiffness = np.random.default_rng(1).uniform(0.0, 1e8, 50)
    gap = np.random.default_rng(2).uniform(-5e-6, 5e-6, 50)
    delta, loads = slice_loads(stiffness, gap, 3000.0)
    assert loads.sum() == pytest.approx(3000.0, rel=1e-13)
    touching = loads > 0.0
    np.testing.assert_allclose(loads[touching], stiffness[touching] * (delta - gap[touching]), rtol=1e-12)
    assert np.all(gap[~touching] >= delta - 1e-18)


def test_all_rows_at_once_solve_each_row_and_balance_every_load():
    """SliceContacts (prepared once, solved per load) against the equilibrium of each row: rows with slices that
    cannot touch (k = 0), equal gaps, a row touching on one slice only; the load balances and no slice pulls."""
    rng = np.random.default_rng(3)
    stiffness = rng.uniform(0.0, 1e8, (6, 40))
    stiffness[rng.uniform(size=stiffness.shape) < 0.3] = 0.0
    stiffness[5] = 0.0
    stiffness[5, 7] = 2e8
    gap = rng.uniform(-5e-6, 5e-6, (6, 40))
    gap[1, ::2] = 1e-6  # ties
    prepared = SliceContacts.prepare(stiffness, gap)
    for load in (10.0, 3000.0, 5e5):
        delta, loads = prepared.solve(load)
        np.testing.assert_allclose(loads.sum(axis=1), load, rtol=1e-12)
        assert np.all(loads >= 0.0) and np.all(loads[stiffness == 0.0] == 0.0)
        touching = loads > 0.0
        expected = (stiffness * (delta[:, None] - gap))[touching]
        np.testing.assert_allclose(loads[touching], expected, rtol=1e-9)
        idle = (stiffness > 0.0) & ~touching  # could touch but the approach does not reach their gap
        assert np.all((gap - delta[:, None])[idle] >= -1e-15)
        assert delta[5] == pytest.approx(gap[5, 7] + load / 2e8, rel=1e-12)
    with pytest.raises(ValueError, match="at least one slice"):
        SliceContacts.prepare(np.zeros((2, 3)), np.zeros((2, 3)))


# ------------------------------------------------------------------------------------- the helical pair in time
@pytest.fixture(scope="module")
def helical_contacts():
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ExtrapolationWarning)
        warnings.simplefilter("ignore", ModelAssumptionWarning)
        results = {}
        for beta in (0.0, 15.0):
            helical = HelicalPair.create(27, 35, 3e-3, math.radians(20.0), math.radians(beta), B,
                                         bore_radii=(15e-3, 20e-3))
            phase = np.linspace(0.0, helical.transverse_base_pitch, 24, endpoint=False)
            results[beta] = (helical, phase, *contact_stiffness(helical, Material(), phase, 60))
        return results


def test_a_uniform_temperature_rise_moves_the_approach_and_no_slice_load(helical_contacts):
    helical, phase, z, stiffness = helical_contacts[15.0]
    pair = helical.transverse
    cold = face_load(stiffness, z, phase, np.zeros_like(z), 9735.3)
    rise = thermal_lead_deviation(np.full_like(z, 40.0), np.full_like(z, 30.0), pair.operating_pitch_radii,
                                  pair.operating_pressure_angle, (11.5e-6, 11.5e-6))
    hot = face_load(stiffness, z, phase, rise, 9735.3)
    np.testing.assert_allclose(hot.line_load, cold.line_load, rtol=1e-9, atol=1e-9 * cold.line_load.max())
    np.testing.assert_allclose(hot.approach - cold.approach, rise[0], rtol=1e-9)


def test_a_temperature_gradient_across_the_face_moves_the_load_to_the_hot_side(helical_contacts):
    """The hot end grows more and closes its gap first: the load's centre moves towards it."""
    helical, phase, z, stiffness = helical_contacts[15.0]
    pair = helical.transverse
    cold = face_load(stiffness, z, phase, np.zeros_like(z), 9735.3)
    gradient = 20.0 * z / B  # 0 K at z = 0, 20 K at z = b (the pinion only)
    hot = face_load(stiffness, z, phase, thermal_lead_deviation(gradient, 0.0 * z, pair.operating_pitch_radii,
                                                                pair.operating_pressure_angle, (11.5e-6, 11.5e-6)),
                    9735.3)
    slope = thermal_lead_deviation(
        20.0, 0.0, pair.operating_pitch_radii, pair.operating_pressure_angle, (11.5e-6, 11.5e-6))  # e(b) − e(0)
    # in full contact with a uniform stiffness c̄ = K̄_t/b a linear gap −g·z/b moves the centre by c̄ g b/(12 w_m);
    # the slices' stiffness varies along the lines and in time, so the estimate holds to about a tenth
    estimate = stiffness.sum(axis=(1, 2)).mean() / B * (-slope) * B / (12.0 * 9735.3 / B)
    assert hot.load_centre - cold.load_centre == pytest.approx(estimate, rel=0.15)
    assert hot.mean_line_load[-1] > hot.mean_line_load[0] and hot.face_load_factor > cold.face_load_factor


def test_a_spur_pair_with_a_crowning_carries_its_load_symmetrically(helical_contacts):
    """β = 0: every slice of a contact line sits at the same path position, so a symmetric gap gives a symmetric
    load at every instant (exactly)."""
    helical, phase, z, stiffness = helical_contacts[0.0]
    result = face_load(stiffness, z, phase, lead_crowning(z, B, 10e-6), 9735.3)
    np.testing.assert_allclose(result.line_load, result.line_load[:, ::-1], rtol=1e-10)
    assert result.load_centre == pytest.approx(B / 2, rel=1e-12)


def test_a_spur_pairs_approach_rises_by_half_a_linear_mismatch_in_full_contact(helical_contacts):
    """Equal slices, all in contact: δ = (F + Σ k e)/Σ k, so δ rises by the slices' mean gap, F_βy/2 exactly (the
    midpoint rule integrates a linear gap exactly)."""
    helical, phase, z, stiffness = helical_contacts[0.0]
    cold = face_load(stiffness, z, phase, np.zeros_like(z), 9735.3)
    slope = face_load(stiffness, z, phase, helix_slope_deviation(z, B, 10e-6), 9735.3)
    assert slope.line_load.min() > 0.0
    np.testing.assert_allclose(slope.approach - cold.approach, 5e-6, rtol=1e-9)
