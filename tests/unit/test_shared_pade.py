"""Exponentials of pieces that differ by a low-rank term over commensurate durations from one Padé evaluation
(dynamics/linear_algebra/shared_pade.py): against scipy's expm of each piece, and the cases it must decline."""

from __future__ import annotations

import numpy as np
import pytest
from scipy.linalg import expm

from thermogear.dynamics.linear_algebra.shared_pade import commensurate_steps, low_rank_piece_exponentials


def _pieces(size: int = 60, levels=(2.6e8, 1.6e8), seed: int = 5):
    """Augmented state matrices [[0, I, 0], [−M⁻¹K_j, −M⁻¹C_j, M⁻¹f_j], [0, 0, 0]] of a damped chain whose pieces
    differ by k_j·w wᵀ, c_j·w wᵀ and g_j·w (rank one), with U = [0; M⁻¹w; 0] and its left inverse [0, wᵀM/|w|², 0]."""
    generator = np.random.default_rng(seed)
    masses = generator.uniform(0.5, 2.0, size)
    springs = generator.uniform(0.5e8, 2e8, size + 1)
    stiffness = np.diag(springs[:-1] + springs[1:]) - np.diag(springs[1:-1], 1) - np.diag(springs[1:-1], -1)
    damping = 2e-6 * stiffness + 50.0 * np.diag(masses)
    gyroscopic = np.triu(generator.standard_normal((size, size)), 1) * 5.0
    damping = damping + gyroscopic - gyroscopic.T  # a skew (gyroscopic) part: no symmetry to lean on
    vector = np.zeros(size)
    vector[[size // 2, size // 2 + 1]] = [1.0, -0.7]
    inverse = np.diag(1.0 / masses)
    units = []
    for level, damper, force in zip(levels, (1500.0, 1200.0), (300.0, -200.0)):
        matrix = np.zeros((2 * size + 1, 2 * size + 1))
        matrix[:size, size:2 * size] = np.eye(size)
        matrix[size:2 * size, :size] = -inverse @ (stiffness + level * np.outer(vector, vector))
        matrix[size:2 * size, size:2 * size] = -inverse @ (damping + damper * np.outer(vector, vector))
        matrix[size:2 * size, 2 * size] = inverse @ (np.full(size, 10.0) + force * vector)
        units.append(matrix)
    left = np.zeros((2 * size + 1, 1))
    left[size:2 * size, 0] = inverse @ vector
    left_inverse = np.zeros((1, 2 * size + 1))
    left_inverse[0, size:2 * size] = (np.diag(masses) @ vector) / (vector @ vector)
    return np.array(units), left, left_inverse


@pytest.mark.parametrize("durations", [(3e-5, 2e-5), (2.5e-5, 2.5e-5), (1e-4, 2e-5), (2e-7, 3e-7), (6.3e-5, 3.7e-5)])
def test_shared_pade_equals_each_piece_s_own_exponential(durations):
    units, left, left_inverse = _pieces()
    durations = np.array(durations)
    steps = low_rank_piece_exponentials(units, left, left_inverse, durations)
    assert steps is not None
    for matrix, duration, step in zip(units, durations, steps):
        reference = expm(matrix * duration)
        # the same [13/13] approximant at the same backward error (2⁻⁵³), evaluated in another order and, for the
        # commensurate pieces, as powers of the common step: agreement at rounding times the squarings, 1e-11
        assert np.abs(step - reference).max() < 1e-11 * np.abs(reference).max()


def test_large_pieces_square_as_rank_updates_of_the_first(monkeypatch):
    """Above 4·61 coordinates the other pieces' Padé results, squarings and powers stay rank updates of the first
    piece's (the dense fallback is not taken): still each piece's own exponential."""
    import thermogear.dynamics.linear_algebra.shared_pade as shared_pade

    units, left, left_inverse = _pieces(size=250)
    dense = []
    original = shared_pade._compressed

    def watched(term, reference):
        result = original(term, reference)
        dense.append(isinstance(result, np.ndarray))
        return result

    monkeypatch.setattr(shared_pade, "_compressed", watched)
    durations = np.array([3e-5, 2e-5])
    steps = low_rank_piece_exponentials(units, left, left_inverse, durations)
    assert dense and not any(dense)
    for matrix, duration, step in zip(units, durations, steps):
        reference = expm(matrix * duration)
        assert np.abs(step - reference).max() < 1e-11 * np.abs(reference).max()  # as above


def test_an_update_grown_past_its_share_continues_dense(monkeypatch):
    """Where an update's rank passes its limit (forced here by a zero limit after the Padé step) the piece goes on
    with dense products: the same exponentials."""
    import thermogear.dynamics.linear_algebra.shared_pade as shared_pade

    units, left, left_inverse = _pieces(size=250)
    original = shared_pade._compressed
    calls = []

    def dense_after_first(term, reference):
        calls.append(1)
        return original(term, reference) if len(calls) == 1 else reference + term.left @ term.right

    monkeypatch.setattr(shared_pade, "_compressed", dense_after_first)
    durations = np.array([3e-5, 2e-5])
    steps = low_rank_piece_exponentials(units, left, left_inverse, durations)
    assert len(calls) == 2  # the Padé update, then the first squaring's (dense from there on)
    for matrix, duration, step in zip(units, durations, steps):
        reference = expm(matrix * duration)
        assert np.abs(step - reference).max() < 1e-11 * np.abs(reference).max()


def test_incommensurate_durations_or_a_full_rank_difference_are_declined():
    units, left, left_inverse = _pieces()
    assert low_rank_piece_exponentials(units, left, left_inverse, np.array([3e-5, 3e-5 * np.sqrt(2.0)])) is None
    changed = units.copy()
    changed[1, 70, 3] += 1.0  # outside the range of U: not a rank update
    assert low_rank_piece_exponentials(changed, left, left_inverse, np.array([3e-5, 2e-5])) is None


def test_commensurate_steps():
    step, counts = commensurate_steps(np.array([0.6, 0.4]) * 1e-3 / 8)
    assert step == pytest.approx(0.025e-3, rel=1e-14) and counts.tolist() == [3, 2]
    step, counts = commensurate_steps(np.array([1.0, 1.0 + 1e-13]))
    assert step == pytest.approx(1.0) and counts.tolist() == [1, 1]
    step, counts = commensurate_steps(np.array([0.63, 0.37]))
    assert step == pytest.approx(0.01, rel=1e-12) and counts.tolist() == [63, 37]
    assert commensurate_steps(np.array([1.0, 65.0])) is None  # beyond the largest multiple
    assert commensurate_steps(np.array([1.0, np.sqrt(2.0)])) is None
    assert commensurate_steps(np.array([1.0, 1.0 + 1e-9])) is None
