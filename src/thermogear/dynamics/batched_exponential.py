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
"""

from __future__ import annotations

import math

import numpy as np

from thermogear.errors import ProblemError

__all__ = ["batched_expm"]

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
