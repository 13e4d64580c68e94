"""The chain of products of rank-update transitions in the real eigenbasis of the state matrix they share.

Every piece of a chunk is X_j = D_c⁻¹(E_k + L_j R_j)D_c (:class:`~thermogear.dynamics.linear_algebra.
batched_exponential.RankUpdateExponentials`): a shared exponential E_k = e^{τ_k D_c X₀ D_c⁻¹} of one mean state
matrix X₀ plus a rank-q term, in the chunk's balanced coordinates D_c. With X₀ = W Λ W⁻¹ (Λ in real block-diagonal
form: a 2×2 block [[a, b], [−b, a]] per complex pair a ± ib, Golub & Van Loan, Matrix Computations, 4th ed. 2013,
§7.4.1), the product T_{j+1} = X_j T_j in modal coordinates C = W⁻¹T is

    C_{j+1} = e^{τ_k Λ} C_j + (W⁻¹D_c⁻¹L_j)(R_j D_c W) C_j,

whose first term costs O(m²) (e^{τΛ} is block diagonal: e^{τa}[[cos τb, sin τb], [−sin τb, cos τb]] per pair) and
whose second costs O(q·m²): about 4q·m² operations a piece instead of the 2m³ + 4q·m² of the product with the
piece's parts in the original coordinates. The transitions from the period's start to each piece's start are kept
as their modal coordinates C_j with the one basis W (:class:`FactoredStarts`): a row block r (k, m) acts on T_j as
(r W) C_j, O(k·m²) instead of forming T_j at O(m³).

Accuracy. The route changes only the order of rounding: each step is exact in the modal coordinates to a few units
of roundoff u, and carrying the result back through W multiplies relative errors by at most κ₁(W) = ‖W‖₁‖W⁻¹‖₁; over
N pieces the product differs from the one formed in the original coordinates by about κ₁(W)·N·u of its norm
(Higham, Accuracy and Stability of Numerical Algorithms, 2nd ed. 2002, §3.5 and §14.1: the error of a product of N
matrices grows linearly in N). :func:`modal_basis` takes the route only where that bound stays below
:data:`ROUTE_TOLERANCE` and every eigenvalue is simple enough for W to be well conditioned (a nearly defective X₀
gives nearly parallel eigenvectors and a large κ₁(W): the guard refuses it and the caller keeps the products in the
original coordinates). Knows nothing of gears: matrices only.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

__all__ = ["ROUTE_TOLERANCE", "FactoredStarts", "ModalBasis", "modal_basis"]

#: The largest κ₁(W)·N·u (module docstring) for which :func:`modal_basis` offers the route: the product then agrees
#: with the one formed in the original coordinates to about 1e-10 of its norm, a hundredth of the 1e-8 to which the
#: periodic solvers' results are compared between routes.
ROUTE_TOLERANCE = 1e-10
_UNIT_ROUNDOFF = 2.0**-53


@dataclass(frozen=True, eq=False)
class FactoredStarts:
    """The transitions T_j = ``basis``·``coordinates[j]`` (c, m, m) from the period's start to each piece's start of a
    chunk, held as their modal coordinates and the one basis W (m, m) in which they were formed."""

    basis: np.ndarray
    coordinates: np.ndarray

    def __len__(self) -> int:
        return self.coordinates.shape[0]

    def left_product(self, rows: np.ndarray) -> np.ndarray:
        """rows_j·T_j of every piece j at once, for rows (c, k, m): (rows·W)·C_j."""
        count, height, size = rows.shape
        return (rows.reshape(count * height, size) @ self.basis).reshape(count, height, size) @ self.coordinates


def left_product(rows: np.ndarray, starts) -> np.ndarray:
    """rows_j·T_j of every piece j, for ``starts`` (c, m, m) or :class:`FactoredStarts`."""
    return starts.left_product(rows) if isinstance(starts, FactoredStarts) else rows @ starts


@dataclass(frozen=True, eq=False)
class ModalBasis:
    """X₀ = W Λ W⁻¹ in real form: ``vectors`` W (m, m) (the real and imaginary parts of the ``pairs`` eigenvectors of
    positive imaginary part, then the real eigenvectors; in the original coordinates), ``inverse`` W⁻¹, the
    ``eigenvalues`` (pairs + reals,) complex in the same order, ``condition`` κ₁(W), ``base`` X₀ itself."""

    vectors: np.ndarray
    inverse: np.ndarray
    eigenvalues: np.ndarray
    pairs: int
    condition: float
    base: np.ndarray
    _exponentials: dict = field(default_factory=dict, repr=False)

    def exponential_blocks(self, time: float) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """e^{τΛ} as (a, b, r): the pairs' blocks [[a, b], [−b, a]] (pairs, 1) each, the real eigenvalues' r (·, 1)."""
        factors = np.exp(time * self.eigenvalues)[:, None]
        return factors[:self.pairs].real, factors[:self.pairs].imag, factors[self.pairs:].real

    def exponential(self, time: float, scale: np.ndarray) -> np.ndarray:
        """e^{τ·S X₀ S⁻¹} (m, m) for the diagonal ``scale`` S (m,) of a chunk's balancing (powers of two: exact), e^{τX₀}
        taken once per τ by the Taylor route of :func:`~thermogear.dynamics.linear_algebra.batched_exponential.
        batched_expm` as the chunks took it each. Not from the eigenbasis: W e^{τΛ} W⁻¹ would spread κ₁(W)·u of rounding
        into coordinates X₀ barely couples (a spur pair's axial motion), where the Taylor products keep it small."""
        from thermogear.dynamics.linear_algebra.batched_exponential import batched_expm

        if time not in self._exponentials:
            self._exponentials[time] = batched_expm(time * self.base)
        return self._exponentials[time] * (scale[:, None] / scale[None, :])

    def chain(self, parts, which: np.ndarray, total: np.ndarray,
              keep_starts: bool = False) -> tuple[np.ndarray, FactoredStarts | None]:
        """(X_{c−1}···X₀·``total`` (m, m), the products before each piece as :class:`FactoredStarts` where
        ``keep_starts``) for the pieces ``which`` (c,) of ``parts`` (a :class:`~thermogear.dynamics.linear_algebra.
        batched_exponential.RankUpdateExponentials` without squarings, of this basis' X₀, with its ``times``)."""
        from thermogear.dynamics.linear_algebra.modal_kernel import add_block_product

        size = total.shape[0]
        used, local = np.unique(which, return_inverse=True)
        scale = parts.scale  # the chunk's balancing D_c
        count, rank = used.size, parts.left.shape[2]
        # W⁻¹ D_c⁻¹ L_j and R_j D_c W of the pieces used, in two products
        left = (self.inverse / scale[None, :]) @ parts.left[used].transpose(1, 0, 2).reshape(size, count * rank)
        left = left.reshape(size, count, rank).transpose(1, 0, 2)
        right = ((parts.right[used] * scale[None, None, :]).reshape(count * rank, size) @ self.vectors
                 ).reshape(count, rank, size)
        blocks = [tuple(np.ascontiguousarray(factor[:, 0]) for factor in self.exponential_blocks(time))
                  for time in parts.times]
        # each product written where it is kept: the next piece's start (the last one apart)
        starts = np.empty((which.size + 1, size, size)) if keep_starts else np.empty((2, size, size))
        coordinates = np.matmul(self.inverse, total, out=starts[0])
        for index, piece in enumerate(local.ravel()):
            following = starts[index + 1] if keep_starts else starts[(index + 1) % 2]
            np.matmul(left[piece], right[piece] @ coordinates, out=following)
            add_block_product(following, coordinates, *blocks[parts.which[used[piece]]])
            coordinates = following
        return self.vectors @ coordinates, FactoredStarts(self.vectors, starts[:-1]) if keep_starts else None


def modal_basis(base: np.ndarray, pieces: int, tolerance: float = ROUTE_TOLERANCE) -> ModalBasis | None:
    """The real eigenbasis of ``base`` X₀ (m, m) for chains of ``pieces`` products, or None where it is not to be
    trusted: κ₁(W)·pieces·u above ``tolerance`` (module docstring; a nearly defective X₀), or an eigenvalue not
    finite or not in conjugate pairs. Balanced first (an exact diagonal similarity in powers of two, LAPACK gebal:
    Parlett & Reinsch, Numer. Math. 13 (1969) 293–304), so that κ₁ measures the eigenvectors and not the units of the
    state."""
    from scipy.linalg import matrix_balance

    base = np.asarray(base, dtype=float)
    _, (scale, _) = matrix_balance(base, permute=False, separate=True)
    values, vectors = np.linalg.eig(base * (scale[None, :] / scale[:, None]))
    if not (np.all(np.isfinite(values)) and np.all(np.isfinite(vectors))):
        return None
    upper, real = values.imag > 0.0, values.imag == 0.0
    if 2 * int(upper.sum()) + int(real.sum()) != values.size:
        return None
    paired = vectors[:, upper]
    balanced = np.hstack([paired.real, paired.imag, vectors[:, real].real])  # W_b: X₀ = S W_b Λ W_b⁻¹ S⁻¹
    try:
        inverse = np.linalg.inv(balanced)
    except np.linalg.LinAlgError:
        return None
    condition = float(np.abs(balanced).sum(axis=0).max() * np.abs(inverse).sum(axis=0).max())
    if not np.isfinite(condition) or condition * pieces * _UNIT_ROUNDOFF > tolerance:
        return None
    return ModalBasis(scale[:, None] * balanced, inverse / scale[None, :],
                      np.concatenate([values[upper], values[real]]), int(upper.sum()), condition, base)
