"""Exponentials of a few large pieces that differ by a low-rank term, over commensurate durations, with one Padé
evaluation of full cost instead of one per piece.

The pieces of a gear mesh period differ only through the mesh: A_j = A₀ + U R_j with U (m, r), r the rank of the
mesh patterns (1 for one mesh). Where their durations are whole multiples of one step, τ_j = n_j·δ (a square-wave
k(τ) with the pair changes at 0.6 and 1 of the period: n = 3 and 2), every piece is scaled to the same δ/2ˢ and
its [13/13] Padé approximant r₁₃ is built from the first piece's by rank updates:

- the scaling and squaring of Higham (SIAM J. Matrix Anal. Appl. 26 (2005) 1179–1193) with the scaling of
  Al-Mohy & Higham (SIAM J. Matrix Anal. Appl. 31 (2009) 970–989): s is the least integer with
  η_j = min(max(d₄, d₆), max(d₆, d₈)) ≤ θ₁₃ = 5.37 for every piece j, d_p = ‖X_j^p‖₁^{1/p} (d₈ estimated by the
  1-norm estimator of Higham & Tisseur 2000, as their algorithm does; the backward error h₂₇ of the diagonal
  Padé approximant is odd, so the bound of their Theorem 4.2 applies to X² with p = 2 and 3);
- every matrix of the Padé evaluation of X_j = X₀ + u R_j (the powers X², X⁴, X⁶ and the polynomials U_j, V_j) is
  X₀'s plus a rank-q term, since (B + L_a R_a)(C + L_b R_b) = BC + (B L_b + L_a R_a L_b) R_b + L_a (R_a C):
  only the first piece's products are full (m³), the others cost O(q·m²) each (q ≤ 61 for r = 1);
- r_j = (V_j − U_j)⁻¹(V_j + U_j) by the Sherman–Morrison–Woodbury identity on the first piece's LU factors, kept
  as r₀ plus a rank update;
- e^{A_j τ_j} = (r_j^{2ˢ})^{n_j}, by squaring and binary powers (Moler & Van Loan, SIAM Review 45 (2003) 3–49, §3):
  the first piece's squares are dense, the others' stay rank updates of them, (B + LR)² = B² + (BL + L·RL)R +
  L·(RB), cut back after each squaring to their numerical rank (singular values below the unit roundoff of ‖B‖_F
  dropped: the difference of two exponentials of a rank-one-perturbed matrix has a rapidly decaying spectrum, 7 to
  11 values above 1e-14 on the 492-DOF rotor), and formed densely where a multiple n_j needs the product of two.
  Where a rank passes an eighth of the size the piece continues with dense products.

The whole stack is first balanced by one exact diagonal similarity (LAPACK gebal of |A₀| + |U|·max_j|R_j|). The
result equals the pieces' separate exponentials to rounding: the same approximant at the same backward error,
evaluated in another order. Knows nothing of gears: matrices only.
"""

from __future__ import annotations

import math

import numpy as np

__all__ = ["SharedPowers", "commensurate_steps", "low_rank_piece_exponentials", "shared_piece_powers"]

_THETA_13 = 5.371920351148152
_PADE_13 = (64764752532480000.0, 32382376266240000.0, 7771770303897600.0, 1187353796428800.0, 129060195264000.0,
            10559470521600.0, 670442572800.0, 33522128640.0, 1323241920.0, 40840800.0, 960960.0, 16380.0, 182.0,
            1.0)
#: Largest multiple n_j of the common step. The powers F^{n_j} replace the scaling squarings a piece's own
#: exponential would take and add a product per further binary digit; measured on 819-square pieces: 0.6/0.4 of the
#: period (n = 3, 2) 0.46 s against 0.78 s for separate exponentials, 0.55/0.45 (11, 9) 0.53 s against 0.78 s,
#: 0.63/0.37 (63, 37) 0.76 s against 0.85 s.
LARGEST_MULTIPLE = 64
#: Relative difference within which a duration counts as n_j·δ (the pieces' ends moved by at most this share).
COMMENSURATE_TOLERANCE = 1e-12


def commensurate_steps(durations: np.ndarray) -> tuple[float, np.ndarray] | None:
    """(δ [s], n (D,)) with durations τ_j = n_j·δ within :data:`COMMENSURATE_TOLERANCE`, n_j ≤
    :data:`LARGEST_MULTIPLE`, the largest such δ; None where there is none."""
    durations = np.asarray(durations, dtype=float)
    shortest = float(durations.min())
    if shortest <= 0.0:
        return None
    for divisor in range(1, LARGEST_MULTIPLE + 1):
        step = shortest / divisor
        counts = np.rint(durations / step)
        if counts.max() <= LARGEST_MULTIPLE and np.all(np.abs(durations - counts * step)
                                                       <= COMMENSURATE_TOLERANCE * durations):
            common = math.gcd(*(int(count) for count in counts))
            return step * common, (counts / common).astype(int)
    return None


class _Updated:
    """base + left @ right for a shared dense base (left (m, q), right (q, m))."""

    def __init__(self, left: np.ndarray, right: np.ndarray):
        self.left, self.right = left, right

    def times(self, other: "_Updated", base: np.ndarray, other_base: np.ndarray) -> "_Updated":
        """(B + L_a R_a)(C + L_b R_b) less BC, for B = ``base``, C = ``other_base``."""
        return _Updated(np.hstack([base @ other.left + self.left @ (self.right @ other.left), self.left]),
                        np.vstack([other.right, self.right @ other_base]))


def _combination(terms: list[tuple[float, _Updated]]) -> _Updated:
    return _Updated(np.hstack([weight * term.left for weight, term in terms]),
                    np.vstack([term.right for _, term in terms]))


def _orthonormal_left(term: _Updated) -> _Updated:
    """The same product with an orthonormal left factor (its columns repeat directions: Woodbury needs them apart)."""
    basis, triangle = np.linalg.qr(term.left)
    return _Updated(basis, triangle @ term.right)


def _compressed(term: _Updated, reference: np.ndarray) -> _Updated | np.ndarray:
    """The rank update L R at its numerical rank: the singular values of L R below the unit roundoff times ‖B‖_F of
    the matrix B it updates are dropped (they are below the rounding of B itself); as the dense B + L R where the
    rank exceeds an eighth of the size (then the update costs more than the dense products)."""
    size = reference.shape[0]
    if term.left.shape[1] > size // 4:
        return reference + term.left @ term.right
    left_basis, left_triangle = np.linalg.qr(term.left)
    right_basis, right_triangle = np.linalg.qr(term.right.T)
    vectors, values, covectors = np.linalg.svd(left_triangle @ right_triangle.T)
    keep = values > 2.0**-53 * float(np.linalg.norm(reference))
    if keep.sum() > size // 8:
        return reference + term.left @ term.right
    return _Updated(left_basis @ (vectors[:, keep] * values[keep]), covectors[keep] @ right_basis.T)


def _power_norm(matrix: np.ndarray, power: int) -> float:
    """‖Xᵖ‖₁ estimated by the block 1-norm estimator (scipy.sparse.linalg.onenormest) without forming Xᵖ."""
    from scipy.sparse.linalg import LinearOperator, onenormest

    def forward(block):
        for _ in range(power):
            block = matrix @ block
        return block

    def backward(block):
        for _ in range(power):
            block = matrix.T @ block
        return block

    size = matrix.shape[0]
    operator = LinearOperator((size, size), matvec=forward, rmatvec=backward, matmat=forward, rmatmat=backward,
                              dtype=float)
    return float(onenormest(operator))


def _row_sparse_product(matrix: np.ndarray):
    """Y ↦ ``matrix`` @ Y taking the rows with at most one nonzero entry as scalings of one row of Y (a state
    matrix [[0, I], [·, ·]]: the velocity rows and the forcing row), so that only the other rows cost a product."""
    nonzero = matrix != 0.0
    sparse = np.flatnonzero(nonzero.sum(axis=1) <= 1)
    dense = np.setdiff1d(np.arange(matrix.shape[0]), sparse)
    columns = np.argmax(nonzero[sparse], axis=1)
    values = matrix[sparse, columns]
    rows = matrix[dense]

    contiguous = dense.size > 0 and dense[-1] - dense[0] + 1 == dense.size

    def product(other: np.ndarray) -> np.ndarray:
        result = np.empty((matrix.shape[0], other.shape[1]))
        result[sparse] = values[:, None] * other[columns]
        if contiguous:  # the product straight into its rows (the state matrix's acceleration rows are a block)
            np.matmul(rows, other, out=result[dense[0]:dense[-1] + 1])
        else:
            result[dense] = rows @ other
        return result

    return product


def _squarings(eta: float) -> int:
    """Least s >= 0 with η/2ˢ <= θ₁₃."""
    return max(0, int(math.ceil(math.log2(eta / _THETA_13)))) if eta > _THETA_13 else 0


def low_rank_piece_exponentials(units: np.ndarray, left: np.ndarray, left_inverse: np.ndarray,
                                durations: np.ndarray) -> np.ndarray | None:
    """e^{A_j τ_j} (D, m, m) of the pieces ``units`` A_j (D, m, m) over ``durations`` τ_j (D,) [s], where
    A_j − A₀ = U R_j with U = ``left`` (m, r) and R_j = ``left_inverse`` (r, m) @ (A_j − A₀) (left_inverse @ U = I);
    None where the durations are not commensurate (:func:`commensurate_steps`) or a difference does not lie in U's
    range to 1e-12 of its size (the caller then takes separate exponentials). See the module docstring."""
    powers = shared_piece_powers(units, left, left_inverse, durations)
    return None if powers is None else powers.sub_steps()


def shared_piece_powers(units: np.ndarray, left: np.ndarray, left_inverse: np.ndarray,
                        durations: np.ndarray) -> "SharedPowers | None":
    """The powers of the pieces' common-step maps (:class:`SharedPowers`, τ_j = n_j·δ) for the arguments of
    :func:`low_rank_piece_exponentials`, or None where it declines them."""
    from scipy.linalg import lu_factor, lu_solve, matrix_balance

    found = commensurate_steps(durations)
    if found is None:
        return None
    step, counts = found
    units = np.asarray(units, dtype=float)
    count, size = units.shape[0], units.shape[1]
    rights = np.einsum("rm,dmk->drk", left_inverse, units - units[0])
    for index in range(1, count):
        difference = units[index] - units[0]
        if np.abs(difference - left @ rights[index]).max() > 1e-12 * max(np.abs(difference).max(), 1e-300):
            return None
    bound = np.abs(units[0]) + np.abs(left) @ np.abs(rights).max(axis=0)
    _, (scale, _) = matrix_balance(bound, permute=False, separate=True)  # B = T⁻¹ A T, T = diag(scale)
    base = step * units[0] * (scale[None, :] / scale[:, None])
    vector = step * left / scale[:, None]
    rights = rights * scale[None, None, :]
    identity = np.eye(size)
    # powers of the first piece (dense) and of the others (rank updates of it) at the step δ
    product = _row_sparse_product(base)
    x2 = product(base)
    x4 = x2 @ x2
    x6 = x4 @ x2
    pieces = []
    eta = 0.0
    for index in range(count):
        first = _Updated(vector, rights[index])
        second = first.times(first, base, base)
        fourth = second.times(second, x2, x2)
        sixth = fourth.times(second, x4, x2)
        dense4, dense6 = x4 + fourth.left @ fourth.right, x6 + sixth.left @ sixth.right
        d4 = float(np.abs(dense4).sum(axis=0).max()) ** 0.25
        d6 = float(np.abs(dense6).sum(axis=0).max()) ** (1.0 / 6.0)
        piece_eta = max(d4, d6)
        if _squarings(d6) < _squarings(piece_eta):  # d₈ may lower it: max(d₆, d₈) is the other bound
            piece_eta = min(piece_eta, max(d6, _power_norm(dense4, 2) ** 0.125))
        eta = max(eta, piece_eta)
        pieces.append((first, second, fourth, sixth))
    squarings = _squarings(eta)
    factor = 2.0 ** -squarings
    x2, x4, x6 = x2 * factor**2, x4 * factor**4, x6 * factor**6
    b = _PADE_13
    inner_high = b[13] * x6 + b[11] * x4 + b[9] * x2
    z1 = x6 @ inner_high
    inner = z1 + b[7] * x6 + b[5] * x4 + b[3] * x2 + b[1] * identity
    odd = product(inner) * factor  # X·inner of the scaled X
    even_high = b[12] * x6 + b[10] * x4 + b[8] * x2
    z2 = x6 @ even_high
    even = z2 + b[6] * x6 + b[4] * x4 + b[2] * x2 + b[0] * identity
    factors = lu_factor(even - odd)
    approximant = lu_solve(factors, even + odd)
    updates: list[_Updated | np.ndarray] = [approximant]  # piece 0 dense; the others r_j = r₀ + L R
    for first, second, fourth, sixth in pieces[1:]:
        first = _Updated(first.left * factor, first.right)
        second = _Updated(second.left * factor**2, second.right)
        fourth = _Updated(fourth.left * factor**4, fourth.right)
        sixth = _Updated(sixth.left * factor**6, sixth.right)
        high = _combination([(b[13], sixth), (b[11], fourth), (b[9], second)])
        inner_j = _combination([(1.0, sixth.times(high, x6, inner_high)), (b[7], sixth), (b[5], fourth),
                                (b[3], second)])
        odd_j = first.times(inner_j, base * factor, inner)
        even_high_j = _combination([(b[12], sixth), (b[10], fourth), (b[8], second)])
        even_j = _combination([(1.0, sixth.times(even_high_j, x6, even_high)), (b[6], sixth), (b[4], fourth),
                               (b[2], second)])
        numerator = _combination([(1.0, even_j), (1.0, odd_j)])
        denominator = _orthonormal_left(_combination([(1.0, even_j), (-1.0, odd_j)]))
        # (Q₀ + L_Q R_Q)⁻¹(P₀ + L_P R_P) = Z − Q₀⁻¹L_Q (I + R_Q Q₀⁻¹L_Q)⁻¹ R_Q Z, Z = r₀ + (Q₀⁻¹L_P) R_P
        solved_p = lu_solve(factors, numerator.left)
        solved_q = lu_solve(factors, denominator.left)
        capacitance = np.eye(solved_q.shape[1]) + denominator.right @ solved_q
        projected = denominator.right @ approximant + (denominator.right @ solved_p) @ numerator.right
        correction = np.linalg.solve(capacitance, projected)
        updates.append(_compressed(_Updated(np.hstack([solved_p, -solved_q]),
                                            np.vstack([numerator.right, correction])), approximant))
    return SharedPowers(approximant, updates[1:], squarings, counts, scale)


class SharedPowers:
    """The powers B_j^(2^k) of the pieces' common-step maps B_j = e^{A_j δ}
    (:mod:`~thermogear.dynamics.linear_algebra.piece_powers`), in the balanced coordinates of the Padé evaluation: the
    first piece's dense, the others' rank updates of them while their rank stays low ((B + LR)² = B² + (BL + L·RL)R +
    L·(RB), cut back after each squaring as the Padé
    updates are), formed densely on request. Built from the approximants r_j of e^{A_j δ/2ˢ} by s squarings."""

    def __init__(self, approximant: np.ndarray, updates: list, squarings: int, counts: np.ndarray,
                 scale: np.ndarray):
        self.multiples = np.asarray(counts, dtype=int)
        self._ratio = scale[:, None] / scale[None, :]  # X = D X_b D⁻¹ (the raw LAPACK scale, powers of 2)
        self.scale = scale / scale[-1]  # the augmented state's last entry unscaled
        self._current, self._updates = approximant, list(updates)
        for _ in range(squarings):
            self._square()
        self._dense = [self._current]
        self._chains = [[update] for update in self._updates]
        self._formed: dict[tuple[int, int], np.ndarray] = {}

    def _square(self) -> None:
        following = self._current @ self._current
        for index, update in enumerate(self._updates):
            self._updates[index] = (update @ update if isinstance(update, np.ndarray) else
                                    _compressed(update.times(update, self._current, self._current), following))
        self._current = following

    def power(self, piece: int, level: int) -> np.ndarray:
        """B_j^(2^level) (m, m), balanced, squared from the level below on first request."""
        while len(self._dense) <= level:
            self._square()
            self._dense.append(self._current)
            for chain, update in zip(self._chains, self._updates):
                chain.append(update)
        if piece == 0:
            return self._dense[level]
        update = self._chains[piece - 1][level]
        if isinstance(update, np.ndarray):
            return update
        if (piece, level) not in self._formed:
            self._formed[(piece, level)] = self._dense[level] + update.left @ update.right
        return self._formed[(piece, level)]

    def sub_steps(self) -> np.ndarray:
        """S_j = B_j^(n_j) (D, m, m) in the original coordinates."""
        results = np.empty((self.multiples.size, *self._current.shape))
        for index, count in enumerate(self.multiples.tolist()):
            power = None
            for level in range(int(count).bit_length()):
                if count >> level & 1:
                    square = self.power(index, level)
                    power = square if power is None else square @ power
            results[index] = power * self._ratio
        return results
