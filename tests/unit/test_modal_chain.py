"""The chain of rank-update transitions in the real eigenbasis of their shared state matrix against the same chain in
the original coordinates, and the guard that refuses a nearly defective state matrix."""

from __future__ import annotations

import numpy as np
import pytest

from thermogear.dynamics.linear_algebra.batched_exponential import rank_update_parts
from thermogear.dynamics.linear_algebra.modal_chain import FactoredStarts, modal_basis
from thermogear.dynamics.linear_algebra.sub_steps import DenseSteps, PartedSteps


def _damped_pieces(pieces: int, seed: int = 3):
    """A random damped 6-DOF system ż = A z + b with a rank-1 stiffness, damping and force variation per piece (a
    mesh's pattern): the augmented mean X₀ (13, 13) and the arguments of rank_update_parts."""
    rng = np.random.default_rng(seed)
    n = 6
    root = rng.normal(size=(n, n))
    stiffness = root @ root.T + n * np.eye(n)
    damping = 0.05 * stiffness + 0.2 * np.eye(n)
    vector = rng.normal(size=n)
    size = 2 * n + 1
    base = np.zeros((size, size))
    base[:n, n:2 * n] = np.eye(n)
    base[n:2 * n, :n], base[n:2 * n, n:2 * n] = -stiffness, -damping
    base[n:2 * n, 2 * n] = rng.normal(size=n)
    left = np.zeros((size, 1))
    left[n:2 * n, 0] = vector
    rows = np.zeros((3, size))
    rows[0, :n], rows[1, n:2 * n], rows[2, 2 * n] = vector, vector, 1.0
    coefficients = rng.uniform(-1.0, 1.0, size=(pieces, 1, 3)) * np.array([2.0, 0.1, 0.5])
    times = rng.choice([0.011, 0.017, 0.023], pieces)
    return base, left, coefficients, times, rows


def test_the_modal_chain_equals_the_chain_in_the_original_coordinates():
    pieces = 300
    base, left, coefficients, times, rows = _damped_pieces(pieces)
    basis = modal_basis(base, pieces)
    assert basis is not None
    parts = rank_update_parts(base, left, coefficients, times, rows)
    assert parts.squarings == 0
    which = np.random.default_rng(5).integers(0, pieces, 400)  # pieces in any order, some twice
    start = np.eye(base.shape[0]) + 0.01 * np.random.default_rng(6).normal(size=base.shape)
    reference_starts = np.empty((which.size, *base.shape))
    reference = DenseSteps(parts.matrices(), which).chain(start, reference_starts)
    total, starts = PartedSteps(parts, which, basis).chain_starts(start)
    assert isinstance(starts, FactoredStarts) and len(starts) == which.size
    # both are the exact product up to rounding; the modal route's differs by about κ₁(W)·N·u of the product's norm
    # (modal_chain's docstring: κ₁(W) = basis.condition, N = 400 products; measured 100 times less)
    bound = basis.condition * which.size * 2.0**-53
    assert np.abs(total - reference).max() <= bound * np.abs(reference).max()
    expanded = starts.basis @ starts.coordinates
    assert np.abs(expanded - reference_starts).max() <= bound * np.abs(reference_starts).max()
    # a row block against each start, as the start-up projector uses them, without forming T_j
    probe = np.random.default_rng(7).normal(size=(which.size, 2, base.shape[0]))
    assert np.allclose(starts.left_product(probe), probe @ reference_starts, rtol=0,
                       atol=bound * np.abs(probe @ reference_starts).max())
    # the chain without starts, and with starts asked for as matrices, gives the same product
    parted = PartedSteps(parts, which, basis)
    assert np.array_equal(parted.chain(start), total)


def test_the_guard_refuses_a_nearly_defective_state_matrix():
    # two eigenvalues 2e-10 apart with nearly parallel eigenvectors: κ₁(W) ≈ 1e10, far above ROUTE_TOLERANCE/(N·u)
    nearly = np.array([[-1.0, 1.0, 0.0], [1e-20, -1.0, 0.0], [0.0, 0.0, -3.0]])
    assert modal_basis(nearly, 1024) is None
    # an exact Jordan block: no basis at all
    assert modal_basis(np.array([[-1.0, 1.0], [0.0, -1.0]]), 10) is None
    # a well-separated spectrum passes, and the bound scales with the number of products
    separated = np.array([[-1.0, 1.0, 0.0], [0.0, -2.0, 0.0], [0.0, 0.0, -3.0]])
    basis = modal_basis(separated, 1024)
    assert basis is not None and basis.condition < 10
    assert modal_basis(separated, 10**7, tolerance=basis.condition * 10**6 * 2.0**-53) is None


def test_parts_without_their_shared_exponentials_serve_the_modal_chain():
    base, left, coefficients, times, rows = _damped_pieces(40, seed=9)
    full = rank_update_parts(base, left, coefficients, times, rows)
    lean = rank_update_parts(base, left, coefficients, times, rows, shared=False)
    assert lean.exponentials is None and np.array_equal(lean.times, full.times)
    basis = modal_basis(base, 40)
    which = np.arange(40)
    start = np.eye(base.shape[0])
    assert np.array_equal(PartedSteps(lean, which, basis).chain(start), PartedSteps(full, which, basis).chain(start))
    # without a basis the parts' own route: equal to the modal one to the bound above
    own = PartedSteps(full, which).chain(start)
    assert np.abs(own - PartedSteps(full, which, basis).chain(start)).max() \
        <= basis.condition * 40 * 2.0**-53 * np.abs(own).max()


@pytest.mark.parametrize("seed", [1, 2])
def test_the_basis_diagonalises_the_state_matrix(seed):
    base = _damped_pieces(4, seed)[0]
    basis = modal_basis(base, 100)
    # W⁻¹ X₀ W is the real block-diagonal form of the eigenvalues: the exponential of τ X₀ from the basis' blocks
    from scipy.linalg import expm

    tau = 0.02
    real, imaginary, alone = basis.exponential_blocks(tau)
    pairs = basis.pairs
    block = np.zeros_like(base)
    index = np.arange(pairs)
    block[index, index] = block[pairs + index, pairs + index] = real[:, 0]
    block[index, pairs + index], block[pairs + index, index] = imaginary[:, 0], -imaginary[:, 0]
    block[2 * pairs:, 2 * pairs:] = np.diag(alone[:, 0])
    reference = expm(tau * base)
    assert np.abs(basis.vectors @ block @ basis.inverse - reference).max() < 1e-12 * np.abs(reference).max() \
        * basis.condition
