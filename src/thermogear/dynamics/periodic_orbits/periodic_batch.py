"""Periodic initial states of many operating points that share one node grid (the batch form of
:func:`thermogear.dynamics.periodic_orbits.periodic.periodic_initial_state`).

Per point, the monodromy matrix and the image of y = 0 after one period from the closed-form 2×2 transitions of
:mod:`thermogear.dynamics.linear_algebra.transition_2x2` (the kernels of the single-point solver, so a point gives the
numbers of ``periodic_initial_state`` to rounding), then y0 = (I − M)⁻¹·b (Floquet theory; Nayfeh & Mook, Nonlinear
Oscillations, 1979, ch. 5). The orbit metrics of many points are in
:mod:`thermogear.dynamics.periodic_orbits.periodic_batch_metrics`.
"""

from __future__ import annotations

import numba
import numpy as np

from thermogear.dynamics.linear_algebra.transition_2x2 import multiplier_moduli_2x2, one_period_2x2, periodic_state_2x2
from thermogear.errors import ProblemError

__all__ = ["periodic_steady_state_batch"]


@numba.njit(cache=True)
def _undamped(damping: np.ndarray) -> bool:
    """True when c = 0 on every interval: then det M = exp(−∫c/me) = 1, no multiplier is strictly inside the unit
    circle and free vibrations never decay, so there is no attracting periodic orbit (Liouville's formula)."""
    for value in damping:
        if value != 0.0:
            return False
    return True


@numba.njit(cache=True)
def _batch_kernel(mass: np.ndarray, nodes: np.ndarray, stiffness: np.ndarray, damping: np.ndarray,
                  force: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    count = stiffness.shape[0]
    x0 = np.empty(count)
    v0 = np.empty(count)
    moduli = np.empty((count, 2))
    for j in range(count):
        m00, m01, m10, m11, bx, bv = one_period_2x2(mass[j], nodes, stiffness[j], damping[j], force[j])
        first, second = multiplier_moduli_2x2(m00, m01, m10, m11)
        if _undamped(damping[j]):
            # |μ1·μ2| = det M = 1 exactly (Liouville), so |μ|max >= 1 in exact arithmetic, whatever rounding gives
            first = max(first, 1.0)
        moduli[j, 0] = first
        moduli[j, 1] = second
        if first < 1.0:
            x0[j], v0[j] = periodic_state_2x2(m00, m01, m10, m11, bx, bv)
        else:
            x0[j] = np.nan  # flagged by the caller through the multipliers, never returned as an orbit
            v0[j] = np.nan
    return x0, v0, moduli


def periodic_steady_state_batch(mass: float | np.ndarray, nodes: np.ndarray, stiffness: np.ndarray,
                                damping: np.ndarray, force: float | np.ndarray
                                ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Periodic initial states of many operating points that share one node grid (for sweeps).

    Parameters
    ----------
    mass:
        me [kg], scalar or (m,).
    nodes:
        (n+1,) node times [s] shared by all points.
    stiffness, damping:
        (m, n) [N/m], [N·s/m].
    force:
        w [N], scalar, (m,) or (m, n).

    Returns
    -------
    x0, v0, multipliers_abs:
        (m,) periodic initial displacement [m] and velocity [m/s] at τ = 0, and (m, 2) Floquet multiplier moduli
        (larger first). Points with a modulus >= 1 are unstable: their x0, v0 are NaN and must be reported as
        parametric instability by the caller (check ``multipliers_abs[:, 0] < 1``).
    """
    nodes = np.ascontiguousarray(np.asarray(nodes, dtype=float))
    stiffness = np.ascontiguousarray(np.atleast_2d(np.asarray(stiffness, dtype=float)))
    count, n = stiffness.shape
    if nodes.shape != (n + 1,):
        raise ProblemError("nodes", f"shape {nodes.shape}", f"shape ({n + 1},)", "one more node than intervals")
    damping = np.ascontiguousarray(np.broadcast_to(np.asarray(damping, dtype=float), (count, n)))
    force_array = np.asarray(force, dtype=float)
    if force_array.ndim == 1 and force_array.shape[0] == count and count != n:
        force_array = force_array[:, None]
    elif force_array.ndim == 1 and count == n and count != 1:
        raise ProblemError("force", f"shape {force_array.shape}", f"scalar, ({count}, 1) or ({count}, {n})",
                        "with as many points as intervals a 1-D force is ambiguous; pass it 2-D")
    force_array = np.ascontiguousarray(np.broadcast_to(force_array, (count, n)))
    mass_array = np.ascontiguousarray(np.broadcast_to(np.asarray(mass, dtype=float), (count,)))
    if np.any(stiffness <= 0.0) or np.any(damping < 0.0) or np.any(mass_array <= 0.0):
        raise ProblemError("stiffness/damping/mass", "non-positive value", "k > 0, c >= 0, me > 0",
                        "the linear mesh model needs positive stiffness and mass and non-negative damping")
    if not (np.all(np.isfinite(stiffness)) and np.all(np.isfinite(damping)) and np.all(np.isfinite(force_array))):
        raise ProblemError("stiffness/damping/force", "non-finite value", "finite numbers", "NaN has no meaning here")
    return _batch_kernel(mass_array, nodes, stiffness, damping, force_array)
