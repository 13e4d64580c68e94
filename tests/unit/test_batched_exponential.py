"""The vectorised exponential of a stack of matrices against scipy's expm and closed forms."""

from __future__ import annotations

import numpy as np
import pytest

from thermogear.dynamics.linear_algebra.batched_exponential import batched_expm
from thermogear.errors import ProblemError


@pytest.mark.parametrize("scale", [1e-3, 0.3, 3.0, 40.0])
def test_stack_equals_scipy_expm(scale):
    from scipy.linalg import expm

    matrices = np.random.default_rng(7).normal(size=(12, 7, 7)) * scale
    values, reference = batched_expm(matrices), expm(matrices)
    # the Taylor remainder bound is 3.4e-14 per scaled step; s squarings amplify rounding by ~2^s·‖e^X‖ (s ≤ 9
    # at scale 40), so 1e-11 of the largest entry is a margin of ~20 over what is measured (4e-13)
    error = np.abs(values - reference).max(axis=(1, 2)) / np.abs(reference).max(axis=(1, 2))
    assert error.max() < 1e-11


def test_stiff_oscillator_is_not_over_scaled():
    # ż = [[0, 1], [−ω², −2ζω]] z with ω = 1e7 rad/s, over one period 2π/ω: the closed form of a damped oscillator
    omega, zeta = 1e7, 0.01
    step = 2 * np.pi / omega
    value = batched_expm(np.array([[0.0, 1.0], [-omega**2, -2 * zeta * omega]]) * step)
    damped = omega * np.sqrt(1 - zeta**2)
    decay = np.exp(-zeta * omega * step)
    position = decay * (np.cos(damped * step) + zeta * omega / damped * np.sin(damped * step))
    # ‖X‖₁ = ω·h ≈ 2π·ω: the error relative to the unit response is a few rounding units times the squarings
    assert value[0, 0] == pytest.approx(position, abs=1e-12)


def test_single_matrix_and_bad_input():
    assert np.allclose(batched_expm(np.zeros((3, 3))), np.eye(3), rtol=0, atol=0)
    with pytest.raises(ProblemError, match="matrices"):
        batched_expm(np.ones((2, 3)))
    with pytest.raises(ProblemError, match="matrices"):
        batched_expm(np.full((2, 2), np.nan))


@pytest.mark.parametrize("scale, rank", [(1e-3, 1), (0.3, 1), (3.0, 2), (40.0, 1)])
def test_rank_updates_equal_scipy_expm(scale, rank):
    from scipy.linalg import expm

    from thermogear.dynamics.linear_algebra.batched_exponential import expm_of_rank_updates

    rng = np.random.default_rng(11)
    base, left = rng.normal(size=(9, 9)) * scale, rng.normal(size=(9, rank))
    right = rng.normal(size=(20, rank, 9)) * scale
    times = rng.choice([0.0, 0.3, 0.7, 1.0], 20)
    values = expm_of_rank_updates(base, left, right, times)
    reference = np.array([expm(t * (base + left @ r)) for t, r in zip(times, right)])
    # the truncated series is within 2⁻⁵³ per scaled step (module docstring); the bound ‖X₀‖ + ‖U‖‖R_j‖ can scale
    # one or two steps more than the full exponential, so rounding after s ≤ 11 squarings: 1e-10 of the largest entry
    # (measured 1e-11 at scale 40, 5e-14 at 3)
    error = np.abs(values - reference).max(axis=(1, 2)) / np.abs(reference).max(axis=(1, 2))
    assert error.max() < 1e-10
    # the same pieces given as coefficients on a few fixed rows: R_j = C_j V with V (3, m), as a mesh gives them
    rows = rng.normal(size=(3, 9)) * scale
    coefficients = rng.normal(size=(20, rank, 3))
    values = expm_of_rank_updates(base, left, coefficients, times, rows)
    reference = np.array([expm(t * (base + left @ c @ rows)) for t, c in zip(times, coefficients)])
    error = np.abs(values - reference).max(axis=(1, 2)) / np.abs(reference).max(axis=(1, 2))
    assert error.max() < 1e-10


def test_rank_updates_refuse_bad_shapes():
    from thermogear.dynamics.linear_algebra.batched_exponential import expm_of_rank_updates

    with pytest.raises(ProblemError, match="matrices"):
        expm_of_rank_updates(np.eye(3), np.ones((3, 1)), np.ones((2, 1, 4)), np.ones(2))
    with pytest.raises(ProblemError, match="matrices"):
        expm_of_rank_updates(np.eye(3), np.ones((3, 1)), np.ones((2, 1, 3)), -np.ones(2))
    with pytest.raises(ProblemError, match="matrices"):
        expm_of_rank_updates(np.eye(3), np.ones((3, 1)), np.ones((2, 1, 2)), np.ones(2), rows=np.ones((3, 3)))


def test_rank_two_update_scaled_by_its_own_norm():
    # a rank-2 update whose columns cancel (U = [w, w + δt], R_j = g_j [s; −s]: U R_j = −g_j δ t sᵀ), as a mesh whose
    # moments vary gives it (w and the tilt vector): ‖U‖₁‖R_j‖₁ ≈ 2g_j·max|s| overstates ‖U R_j‖₁ = g_jδ‖t‖₁ max|s|
    # about 100 times; the scaling follows a bound of the update's own norm (three squarings fewer here)
    from scipy.linalg import expm

    from thermogear.dynamics.linear_algebra.batched_exponential import expm_of_rank_updates, rank_update_parts

    rng = np.random.default_rng(5)
    base = rng.normal(size=(9, 9))
    base *= 1.5 / np.abs(base).sum(axis=0).max()
    w, t, s = rng.normal(size=9), rng.normal(size=9), rng.normal(size=9)
    left = np.column_stack([w, w + 0.01 * t])
    gains = rng.uniform(1.0, 3.0, 12)
    right = gains[:, None, None] * np.array([s, -s])[None]
    times = np.ones(12)
    parts = rank_update_parts(base, left, right, times)
    balance = parts.scale[:, None] / parts.scale[None, :]  # the norms are taken after the balancing

    def norm(matrix):
        return np.abs(matrix * balance).sum(axis=0).max()

    update = max(norm(left @ r) for r in right)
    product = (np.abs(left * parts.scale[:, None]).sum(axis=0).max()
               * max(np.abs(r / parts.scale[None, :]).sum(axis=0).max() for r in right))  # ‖U‖₁·max_j‖R_j‖₁
    assert product > 50.0 * update
    assert parts.squarings == int(np.ceil(np.log2(norm(base) + update)))
    assert int(np.ceil(np.log2(norm(base) + product))) >= parts.squarings + 3
    reference = np.array([expm(base + left @ r) for r in right])
    values = expm_of_rank_updates(base, left, right, times)
    error = np.abs(values - reference).max(axis=(1, 2)) / np.abs(reference).max(axis=(1, 2))
    assert error.max() < 1e-13  # the series within 2⁻⁵³ per scaled step, a few units of rounding
