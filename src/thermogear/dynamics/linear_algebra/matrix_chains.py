"""Products along a chain of step matrices, the linear algebra of a period made of pieces (nothing of its system):
the ordered product X_{N−1}···X₀ by pairwise levels, the same chain cut into √N blocks whose products are shared
where blocks repeat, and the states at every node from the blocks' starts. Used by the every-coordinate periodic
route (:mod:`thermogear.dynamics.periodic_orbits.periodic_ndof`)."""

from __future__ import annotations

import math

import numpy as np

__all__ = ["block_products", "ordered_product", "power", "states_at_nodes"]


def power(matrices: np.ndarray, count: int) -> np.ndarray:
    """Each matrix of a (…, m, m) stack to the power ``count`` (≥ 1)."""
    return matrices if count == 1 else np.linalg.matrix_power(matrices, count)


def ordered_product(matrices: np.ndarray) -> np.ndarray:
    """X_{N−1}···X₁X₀ of a (…, N, m, m) stack (leading axes batched), by pairwise products level by level (log₂N
    vectorised passes)."""
    stack = np.asarray(matrices)
    while stack.shape[-3] > 1:
        count = stack.shape[-3]
        even = count - count % 2
        paired = stack[..., 1:even:2, :, :] @ stack[..., 0:even:2, :, :]
        stack = np.concatenate([paired, stack[..., even:, :, :]], axis=-3) if even < count else paired
    return stack[..., 0, :, :]


def block_products(distinct: np.ndarray, where: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The steps ``distinct[where]`` in B ≈ √N consecutive blocks (padded with identities) and each block's ordered
    product: the monodromy is the product of the B block products (the same N − 1 matrix products as one tree), and
    the states at every node follow from B sequential products plus √N batched ones instead of N sequential ones.
    Blocks made of the same sequence of distinct pieces share one product (exact: the same matrices multiplied in
    the same order), so a k(τ) of a few levels — most blocks lie inside one level — costs a few block products:
    the repeated-piece economy exp(A·h)ⁿ of equal pieces without any special case."""
    count, size = where.size, distinct.shape[1]
    block = max(1, int(round(math.sqrt(count))))
    blocks = -(-count // block)
    with_identity = np.concatenate([distinct, np.eye(size)[None]])
    indices = np.concatenate([where, np.full(blocks * block - count, distinct.shape[0])]).reshape(blocks, block)
    padded = with_identity[indices]
    patterns, first, which = np.unique(indices, axis=0, return_index=True, return_inverse=True)
    if patterns.shape[0] == blocks:  # every block differs: one tree over all of them
        return padded, ordered_product(padded)
    return padded, ordered_product(padded[first])[which.ravel()]


def states_at_nodes(padded: np.ndarray, products: np.ndarray, start: np.ndarray, count: int) -> np.ndarray:
    """States at the N + 1 nodes from the state at the first: block starts in sequence, then all blocks at once."""
    starts = np.empty((products.shape[0], start.size))
    state = start
    for index, product in enumerate(products):
        starts[index] = state
        state = product @ state
    inside = np.empty((padded.shape[0], padded.shape[1], start.size))
    current = starts
    for index in range(padded.shape[1]):
        inside[:, index] = current
        current = (padded[:, index] @ current[:, :, None])[:, :, 0]
    return np.vstack([inside.reshape(-1, start.size)[:count], state[None]])
