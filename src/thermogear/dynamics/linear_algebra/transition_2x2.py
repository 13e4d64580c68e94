"""Closed-form kernels of the 1-DOF mesh equation me·ẍ + c·ẋ + k·x = w with constant coefficients (the 1×1 case).

With y = [x, ẋ] and constant k, c, w on an interval, y(t) = Φ(t)·(y(0) − y_eq) + y_eq, y_eq = [w/k, 0], and
Φ(t) = expm(A t), A = [[0, 1], [−k/me, −c/me]], in closed form for a 2×2 matrix (Cayley–Hamilton; Moler &
Van Loan, SIAM Review 45 (2003), method 17):

    Φ(t) = e^{−σt}·[C(t)·I + S(t)·(A + σI)],   σ = c/(2me),   d = σ² − k/me
    C = cos(√−d t), S = sin(√−d t)/√−d   (d < 0, under-damped);   cosh/sinh for d > 0;   C = 1, S = t for d = 0.

The monodromy matrix M = Φ_{n−1}···Φ_0 and the image b of y = 0 after one period give the periodic initial state
y0 = (I − M)⁻¹·b (Floquet 1883; Nayfeh & Mook, Nonlinear Oscillations, 1979, ch. 5). These numba kernels are the
one shared core of the single-point solver (:mod:`thermogear.dynamics.periodic_orbits.periodic`), the batch solvers
(:mod:`thermogear.dynamics.periodic_orbits.periodic_batch`) and the backlash kernel; the n-DOF case takes the matrix
exponential instead (:mod:`thermogear.dynamics.periodic_orbits.periodic_ndof`). Arrays and floats only.
"""

from __future__ import annotations

import numba
import numpy as np

__all__ = ["multiplier_moduli_2x2", "one_period_2x2", "periodic_state_2x2", "transition_2x2"]

_SERIES_LIMIT = 1e-6  # |d|·t² below which C and S use their Taylor series (relative error < 1e-14)


@numba.njit(cache=True, fastmath=False)
def transition_2x2(stiffness: float, damping: float, mass: float, t: float) -> tuple[float, float, float, float]:
    """Closed-form expm(A t) for A = [[0, 1], [−k/m, −c/m]]; returns (Φ00, Φ01, Φ10, Φ11)."""
    a = stiffness / mass
    sigma = 0.5 * damping / mass
    d = sigma * sigma - a
    z = d * t * t
    if abs(z) < _SERIES_LIMIT:
        cosine = 1.0 + 0.5 * z + z * z / 24.0
        sine = t * (1.0 + z / 6.0 + z * z / 120.0)
        decay = np.exp(-sigma * t)
    elif d < 0.0:
        omega = np.sqrt(-d)
        cosine = np.cos(omega * t)
        sine = np.sin(omega * t) / omega
        decay = np.exp(-sigma * t)
    else:
        # over-damped: e^{−σt}cosh(gt) and e^{−σt}sinh(gt)/g with g < σ (k > 0), written without overflow
        g = np.sqrt(d)
        slow = np.exp((g - sigma) * t)
        fast = np.exp(-(g + sigma) * t)
        cosine = 0.5 * (slow + fast)
        sine = 0.5 * (slow - fast) / g
        decay = 1.0
    p00 = decay * (cosine + sigma * sine)
    p01 = decay * sine
    p10 = -decay * a * sine
    p11 = decay * (cosine - sigma * sine)
    return p00, p01, p10, p11


@numba.njit(cache=True)
def one_period_2x2(mass: float, nodes: np.ndarray, stiffness: np.ndarray, damping: np.ndarray,
                force: np.ndarray) -> tuple[float, float, float, float, float, float]:
    """Monodromy M (4 entries, row-major) and b = image of y = 0 after one period."""
    m00, m01, m10, m11 = 1.0, 0.0, 0.0, 1.0
    bx, bv = 0.0, 0.0
    for i in range(stiffness.size):
        h = nodes[i + 1] - nodes[i]
        p00, p01, p10, p11 = transition_2x2(stiffness[i], damping[i], mass, h)
        equilibrium = force[i] / stiffness[i]
        dx = bx - equilibrium
        bx = p00 * dx + p01 * bv + equilibrium
        bv = p10 * dx + p11 * bv
        n00 = p00 * m00 + p01 * m10
        n01 = p00 * m01 + p01 * m11
        n10 = p10 * m00 + p11 * m10
        n11 = p10 * m01 + p11 * m11
        m00, m01, m10, m11 = n00, n01, n10, n11
    return m00, m01, m10, m11, bx, bv


@numba.njit(cache=True)
def multiplier_moduli_2x2(m00: float, m01: float, m10: float, m11: float) -> tuple[float, float]:
    """Moduli of the eigenvalues of a real 2×2 matrix, larger first."""
    half_trace = 0.5 * (m00 + m11)
    determinant = m00 * m11 - m01 * m10
    disc = half_trace * half_trace - determinant
    if disc < 0.0:
        modulus = np.sqrt(max(determinant, 0.0))
        return modulus, modulus
    root = np.sqrt(disc)
    first = abs(half_trace + root)
    second = abs(half_trace - root)
    if first >= second:
        return first, second
    return second, first


@numba.njit(cache=True)
def periodic_state_2x2(m00: float, m01: float, m10: float, m11: float, bx: float, bv: float) -> tuple[float, float]:
    """y0 = (I − M)⁻¹ b by Cramer's rule (det(I − M) = (1 − μ1)(1 − μ2) ≠ 0 when stable)."""
    a00 = 1.0 - m00
    a01 = -m01
    a10 = -m10
    a11 = 1.0 - m11
    det = a00 * a11 - a01 * a10
    return (a11 * bx - a01 * bv) / det, (-a10 * bx + a00 * bv) / det
