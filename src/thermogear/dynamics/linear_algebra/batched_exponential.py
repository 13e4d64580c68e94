"""Matrix exponentials of a stack of small matrices in one vectorised pass (scaling and squaring with a Taylor
polynomial evaluated by the Paterson–Stockmeyer scheme).

The remainder of the degree-12 Taylor polynomial, Σ_{k≥13} X^k/k!, is bounded by Σ_{k≥13} α^k/k! with
α = max(‖X³‖₁^(1/3), ‖X⁴‖₁^(1/4)) (Al-Mohy & Higham, SIAM J. Matrix Anal. Appl. 31 (2009) 970–989, Theorem 4.2: the
powers' norms, not ‖X‖ itself, so that a stiff, strongly non-normal matrix is not over-scaled); with α ≤ θ = 1/2 the
bound is 0.5¹³/13!·e^0.5/(1 − 0.5/14) ≈ 3.4e-14. The stack is scaled by one common power 2⁻ˢ so that every member
satisfies it (the powers already formed are rescaled, not recomputed), and squared back s times (Moler & Van Loan,
SIAM Review 45 (2003) 3–49, §3). The stack is first balanced by one exact diagonal similarity D (e^{DXD⁻¹} =
D e^X D⁻¹): a mechanical state matrix [[0, h·I], [−h·M⁻¹K, ·]] has blocks of very different size, and balancing
brings its norms down to about ω_max·h, saving the squarings that would otherwise lose accuracy and time.
The polynomial costs five products (X², X³, X⁴ and two Horner steps in X⁴: Paterson & Stockmeyer, SIAM J. Comput.
2 (1973) 60–66). Knows nothing of gears: arrays only. Used for the many short pieces of a mesh period, where one
vectorised pass over all pieces replaces a Python loop of ``scipy.linalg.expm`` calls.

:func:`expm_of_rank_updates` serves the case where the pieces differ from one constant matrix only by a low-rank
term (a gear mesh: the mesh stiffness, damping and excitation act through the one mesh vector w, so every piece's
state matrix is the mean one plus a rank-1 term). For X_j = t_j·(X₀ + U R_j), with U (m, r) and R_j (r, m), the
exact identity (telescoping the powers, Xᵖ − X₀ᵖ = Σ_{i+k=p−1} Xⁱ (X − X₀) X₀ᵏ)

    e^{X_j} = e^{t_j X₀} + Σ_{i,k ≥ 0} t_j^{i+k+1}/(i+k+1)! · Y_iʲ Z_kʲ,   Y_iʲ = (X₀ + U R_j)ⁱ U,  Z_kʲ = R_j X₀ᵏ,

turns each piece's exponential into one shared e^{t X₀} (one per distinct t) plus a rank-(d·r) update built from
Krylov blocks. All pieces' Y_i and Z_k come from one matrix product of X₀ with all pieces' blocks at once, so the
per-piece cost is O(d·r·m²) instead of the O(m³) products of a full Taylor polynomial. Truncating at i, k < d
leaves only terms of total degree p = i+k+1 ≥ d+1; with β ≥ ‖t_j X₀‖₁ and ‖t_j(X₀ + U R_j)‖₁ (so ‖t_j U R_j‖₁ ≤ 2β)
and p such pairs (i, k) per degree, their sum is at most 2β·Σ_{q≥d} β^q/q! ≤ 2β·β^d/d!/(1 − β/(d+1)); d is the least
degree that brings this under the unit roundoff 2⁻⁵³, after scaling by 2⁻ˢ so that β ≤ 1 (then squaring s times,
as above). β is max_j t_j(‖X₀‖₁ + ν_j) with ν_j = ‖U‖₁‖R_j‖₁, or where r ≥ 2 a tighter bound of ‖U R_j‖₁
(``_update_norms``). Balancing uses the entrywise bound |X₀| + |U|·max_j|R_j| of every member.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from thermogear.errors import ProblemError

__all__ = ["RankUpdateExponentials", "batched_expm", "expm_of_rank_updates", "rank_update_parts"]

_THETA = 0.5
_COEFFICIENTS = np.array([1.0 / math.factorial(k) for k in range(13)])


def _root_norm(power: np.ndarray, exponent: int) -> float:
    """max over the stack of ‖Xᵏ‖₁^(1/k)."""
    return float(np.abs(power).sum(axis=1).max()) ** (1.0 / exponent) if power.size else 0.0


def _balancing(stack: np.ndarray) -> np.ndarray:
    """Diagonal d (powers of 2, so exact) that balances the entrywise largest matrix of the stack (LAPACK gebal,
    Parlett & Reinsch, Numer. Math. 13 (1969) 293–304); the stack becomes D X D⁻¹."""
    from scipy.linalg import matrix_balance

    if stack.shape[0] == 0:
        return np.ones(stack.shape[1])
    _, (scale, _) = matrix_balance(np.abs(stack).max(axis=0), permute=False, separate=True)
    return 1.0 / scale


def batched_expm(matrices: np.ndarray) -> np.ndarray:
    """e^X of each matrix of a (count, n, n) stack (a single (n, n) matrix is accepted too) [same units]."""
    stack = np.asarray(matrices, dtype=float)
    single = stack.ndim == 2
    if single:
        stack = stack[None]
    if stack.ndim != 3 or stack.shape[1] != stack.shape[2]:
        raise ProblemError("matrices", f"array of shape {np.shape(matrices)}", "(count, n, n) or (n, n)",
                           "a stack of square matrices")
    if not np.all(np.isfinite(stack)):
        raise ProblemError("matrices", "non-finite entries", "finite numbers", "the exponential of NaN is undefined")
    scale = _balancing(stack)
    identity = np.eye(stack.shape[1])
    x1 = stack * (scale[:, None] / scale[None, :])
    x2 = x1 @ x1
    x3 = x2 @ x1
    x4 = x3 @ x1
    alpha = max(_root_norm(x3, 3), _root_norm(x4, 4))
    squarings = max(0, int(math.ceil(math.log2(alpha / _THETA)))) if alpha > _THETA else 0
    x1, x2, x3, x4 = (power / 2.0 ** (squarings * k) for k, power in enumerate((x1, x2, x3, x4), start=1))
    c = _COEFFICIENTS

    def block(k: int) -> np.ndarray:  # c_k I + c_{k+1} X + c_{k+2} X² + c_{k+3} X³
        return c[k] * identity + c[k + 1] * x1 + c[k + 2] * x2 + c[k + 3] * x3

    top = block(8) + c[12] * x4
    result = block(0) + x4 @ (block(4) + x4 @ top)
    for _ in range(squarings):
        result = result @ result
    result = result * (scale[None, :] / scale[:, None])
    return result[0] if single else result


_RANK_THETA = 1.0
_UNIT_ROUNDOFF = 2.0**-53


def _rank_update_degree(beta: float) -> int:
    """Least d with 2β·β^d/d!/(1 − β/(d+1)) ≤ 2⁻⁵³ (see the module docstring; the geometric bound of the tail needs
    d + 1 > β)."""
    degree = max(1, int(math.floor(beta)) + 1)
    while 2.0 * beta * beta**degree / math.factorial(degree) / (1.0 - beta / (degree + 1)) > _UNIT_ROUNDOFF:
        degree += 1
    return degree


@dataclass(frozen=True, eq=False)
class RankUpdateExponentials:
    """The exponentials of :func:`expm_of_rank_updates` held as their parts before squaring and unbalancing: piece j
    is D⁻¹·(E_{which[j]} + L_j·R_j)^(2^squarings)·D, with ``exponentials`` E (k, m, m) the shared e^{t X₀} of the k
    distinct scaled times (balanced), ``which`` (N,), ``left`` L (N, m, q), ``right`` R (N, q, m) the rank-q
    update of each piece (module docstring) and ``scale`` the diagonal of D (m,). Without squarings a piece acts on
    a vector at O(m² + q·m) without its matrix being formed (:mod:`~thermogear.dynamics.linear_algebra.sub_steps`).
    ``times`` (k,): E_k = e^{τ_k·D X₀ D⁻¹} of the unit-width X₀ the parts were formed from, scaled by 2^−squarings (for
    :mod:`~thermogear.dynamics.linear_algebra.modal_chain`, which needs only them: ``exponentials`` is None where they
    were not formed, :func:`rank_update_parts`)."""

    exponentials: np.ndarray | None
    which: np.ndarray
    left: np.ndarray
    right: np.ndarray
    scale: np.ndarray
    squarings: int
    times: np.ndarray | None = None

    def __len__(self) -> int:
        return self.left.shape[0]

    def matrices(self) -> np.ndarray:
        """The (N, m, m) exponentials (what :func:`expm_of_rank_updates` returns)."""
        result = self.left @ self.right  # Σ_ik t^i Y_i H_ik t^{k+1} Z_k
        result += self.exponentials[0] if self.exponentials.shape[0] == 1 else self.exponentials[self.which]
        for _ in range(self.squarings):
            result = result @ result
        result *= self.scale[None, :] / self.scale[:, None]
        return result


def _update_norms(left: np.ndarray, right: np.ndarray, rows: np.ndarray) -> np.ndarray:
    """Bounds (N,) of ‖U R_j‖₁ = ‖U C_j V‖₁ for a rank r ≥ 2, at O(r·m) a piece: with U = Q_U T (QR, Q_U's columns
    q_i), U R_j = Σ_i q_i (T R_j)_i, so ‖U R_j‖₁ ≤ max_k Σ_i ‖q_i‖₁·|(T R_j)_ik| (the triangle inequality, column by
    column); the smaller of this and ‖U‖₁‖R_j‖₁. Where C_j V combines the columns of U with cancellation (a mesh
    whose moments vary: U spans w and the tilt vector) the product of the norms overstates the update many times
    (8.4× on the two-shaft rotor of the benchmarks, one squaring more than the moments held at their means take),
    this bound by 0.8 % (against the norm of the formed update)."""
    orthonormal, triangle = np.linalg.qr(left)
    updates = right @ rows  # R_j (N, r, m)
    columns = (np.abs(orthonormal).sum(axis=0)[None, :, None] * np.abs(triangle @ updates)).sum(axis=1).max(axis=1)
    return np.minimum(columns, float(np.abs(left).sum(axis=0).max()) * np.abs(updates).sum(axis=1).max(axis=1))


def expm_of_rank_updates(base: np.ndarray, left: np.ndarray, right: np.ndarray, times: np.ndarray,
                         rows: np.ndarray | None = None) -> np.ndarray:
    """e^{t_j·(X₀ + U R_j)} for every j: ``base`` X₀ (m, m), ``left`` U (m, r), ``right`` R (N, r, m), ``times``
    t (N,) >= 0 [same units]; returns (N, m, m). With ``rows`` V (q, m), ``right`` holds coefficients C (N, r, q)
    and R_j = C_j V: when every R_j lies in a few fixed rows (a mesh: the stiffness, damping and excitation rows),
    the Krylov blocks Z_k = C_j (V X₀ᵏ) need products with q rows only. Exact to the unit roundoff of the truncated
    series (module docstring); worth it when r ≪ m and N is large."""
    parts = rank_update_parts(base, left, right, times, rows)
    return parts if isinstance(parts, np.ndarray) else parts.matrices()


def rank_update_parts(base: np.ndarray, left: np.ndarray, right: np.ndarray, times: np.ndarray,
                      rows: np.ndarray | None = None, shared: bool = True) -> RankUpdateExponentials | np.ndarray:
    """:func:`expm_of_rank_updates` held as its parts (:class:`RankUpdateExponentials`; an (N, m, m) array where
    there is nothing to hold: no pieces, or every time zero). Without ``shared`` the shared exponentials are not
    formed (``exponentials`` None; their ``times`` are: for a caller that takes e^{τX₀} from an eigenbasis of X₀,
    :mod:`~thermogear.dynamics.linear_algebra.modal_chain`)."""
    base, left = np.asarray(base, dtype=float), np.asarray(left, dtype=float)
    right, times = np.asarray(right, dtype=float), np.asarray(times, dtype=float)
    size = base.shape[0]
    rows = np.eye(size) if rows is None else np.asarray(rows, dtype=float)
    if base.shape != (size, size) or left.ndim != 2 or left.shape[0] != size or right.ndim != 3 \
            or rows.ndim != 2 or rows.shape[1] != size or right.shape[1:] != (left.shape[1], rows.shape[0]) \
            or times.shape != (right.shape[0],):
        raise ProblemError("matrices", f"shapes {base.shape}, {left.shape}, {right.shape}, {rows.shape}, "
                           f"{times.shape}", "X₀ (m, m), U (m, r), C (N, r, q), V (q, m), t (N,)",
                           "pieces X₀ + U C_j V scaled by t_j")
    if not all(np.all(np.isfinite(array)) for array in (base, left, right, rows, times)) or np.any(times < 0.0):
        raise ProblemError("matrices", "non-finite entries or negative times", "finite numbers, t >= 0",
                           "the exponential of NaN is undefined")
    count, rank = right.shape[0], left.shape[1]
    if count == 0:
        return np.zeros((0, size, size))
    magnitude = np.abs(right) @ np.abs(rows)  # entrywise bound of |R_j|: (N, r, m)
    bound = np.abs(base) + np.abs(left) @ magnitude.max(axis=0)
    scale = _balancing(bound[None])
    base = base * (scale[:, None] / scale[None, :])
    left, rows, magnitude = left * scale[:, None], rows / scale[None, :], magnitude / scale[None, None, :]
    longest = float(times.max())
    if longest == 0.0:
        return np.broadcast_to(np.eye(size), (count, size, size)).copy()
    times = times / longest
    base_norm = float(np.abs(base).sum(axis=0).max()) * longest
    if rank == 1:  # ‖u rᵀ‖₁ = ‖u‖₁·max_k|r_k|: the product of the norms is the update's own norm
        right_norms = magnitude.sum(axis=1).max(axis=1) * longest
        beta = float((times * (base_norm + float(np.abs(left).sum(axis=0).max()) * right_norms)).max())
    else:  # ‖U‖₁‖R_j‖₁ can exceed ‖U R_j‖₁ many times over: a bound of the update's own norm
        beta = float((times * (base_norm + _update_norms(left, right, rows) * longest)).max())
    beta = max(beta, base_norm)
    squarings = max(0, int(math.ceil(math.log2(beta / _RANK_THETA)))) if beta > _RANK_THETA else 0
    factor = longest / 2.0**squarings
    base, rows, beta = base * factor, rows * factor, beta / 2.0**squarings
    degree = _rank_update_degree(beta)
    # Krylov blocks of all pieces at once, as rows (N·r, m), each step one product with X₀ᵀ:
    # Y_iᵀ = Y_{i−1}ᵀ X₀ᵀ + (C_j V Y_{i−1})ᵀ Uᵀ; and Z_k = C_j (V X₀ᵏ) from the q rows' own powers
    left_blocks = np.empty((count, rank, size, degree))  # Y_i of every piece, its r columns apart
    krylov = np.broadcast_to(left.T, (count, rank, size)).reshape(count * rank, size)
    for order in range(degree):
        left_blocks[:, :, :, order] = krylov.reshape(count, rank, size)
        if order + 1 < degree:
            projected = (krylov @ rows.T).reshape(count, rank, rows.shape[0])  # (V Y_j)ᵀ: (N, r_b, q)
            coupling = right @ projected.transpose(0, 2, 1)  # C_j V Y_j: (N, r_a, r_b)
            krylov = krylov @ base.T + coupling.transpose(0, 2, 1).reshape(count * rank, rank) @ left.T
    row_powers = [rows]
    for _ in range(degree - 1):
        row_powers.append(row_powers[-1] @ base)
    stacked_rows = np.stack(row_powers, axis=1).reshape(rows.shape[0], degree * size)  # (q, d·m)
    right_blocks = (right.reshape(count * rank, -1) @ stacked_rows).reshape(count, rank, degree, size)
    # t^{i+k+1}/(i+k+1)! = t^i · [1/(i+k+1)!] · t^{k+1}: the Hankel matrix of 1/p! is shared by every piece
    orders = np.arange(degree)
    hankel = 1.0 / np.array([[math.factorial(i + k + 1) for k in orders] for i in orders], dtype=float)
    powers = times[:, None] ** np.arange(degree + 1)[None]  # (N, d+1)
    left_blocks *= powers[:, None, None, :degree]
    right_blocks *= powers[:, None, 1:, None]
    # Σ_i t^i Y_i/(i+k+1)! for each k, then as the columns (r, k) of L_j (N, m, r·d) (a copy where r > 1), the rows
    # (r, k) of R_j as they are formed
    weighted = (left_blocks.reshape(count * rank * size, degree) @ hankel).reshape(count, rank, size, degree)
    weighted = weighted.transpose(0, 2, 1, 3).reshape(count, size, rank * degree)
    distinct, where = np.unique(times, return_inverse=True)
    # (equal widths: one, added without a copy)
    exponentials = batched_expm(distinct[:, None, None] * base[None]) if shared else None
    return RankUpdateExponentials(exponentials, where.ravel(), weighted, right_blocks.reshape(count, rank * degree, size),
                                  scale, squarings, distinct * factor)
