"""Exact periodic steady state of me·ẍ + c(τ)ẋ + k(τ)x = w with piecewise-constant coefficients.

Floquet theory (Floquet 1883; the monodromy matrix of a periodic linear system, e.g. Nayfeh &
Mook, Nonlinear Oscillations, 1979, ch. 5). With y = [x, ẋ] and constant k, c, w on an interval of length h, the
solution is y(t) = Φ(t)·(y(0) − y_eq) + y_eq with y_eq = [w/k, 0] (the static transmission error) and
Φ(t) = expm(A t), A = [[0, 1], [−k/me, −c/me]], in closed form for a 2×2 matrix:

    Φ(t) = e^{−σt}·[C(t)·I + S(t)·(A + σI)],   σ = c/(2me),   d = σ² − k/me
    C = cos(√−d t), S = sin(√−d t)/√−d   (d < 0, under-damped);   cosh/sinh for d > 0;   C = 1, S = t for d = 0.

The monodromy matrix M = Φ_{n−1}···Φ_0 (time order) and the image b of y = 0 after one period give the periodic
initial state y0 = (I − M)⁻¹·b, unique and attracting iff both Floquet multipliers (eigenvalues of M) lie inside
the unit circle. Nothing here is iterative: the orbit is exact to rounding.

All kernels are numba-compiled and work on plain arrays, so a sweep can call
:func:`periodic_steady_state_batch` for many (k, c, w) sets on one node grid without Python overhead per interval.
"""

from __future__ import annotations

from dataclasses import dataclass

import numba
import numpy as np

from thermogear.dynamics.problem import MeshDynamicsProblem
from thermogear.errors import ProblemError, ModelLimitError

__all__ = ["PeriodicOrbit", "evaluate_orbit", "floquet_multipliers", "periodic_initial_state",
           "periodic_steady_state", "periodic_steady_state_batch"]

_SERIES_LIMIT = 1e-6  # |d|·t² below which C and S use their Taylor series (relative error < 1e-14)


@numba.njit(cache=True, fastmath=False)
def _transition(stiffness: float, damping: float, mass: float, t: float) -> tuple[float, float, float, float]:
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
def _one_period(mass: float, nodes: np.ndarray, stiffness: np.ndarray, damping: np.ndarray,
                force: np.ndarray) -> tuple[float, float, float, float, float, float]:
    """Monodromy M (4 entries, row-major) and b = image of y = 0 after one period."""
    m00, m01, m10, m11 = 1.0, 0.0, 0.0, 1.0
    bx, bv = 0.0, 0.0
    for i in range(stiffness.size):
        h = nodes[i + 1] - nodes[i]
        p00, p01, p10, p11 = _transition(stiffness[i], damping[i], mass, h)
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
def _multipliers_abs(m00: float, m01: float, m10: float, m11: float) -> tuple[float, float]:
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
def _solve_periodic(m00: float, m01: float, m10: float, m11: float, bx: float, bv: float) -> tuple[float, float]:
    """y0 = (I − M)⁻¹ b by Cramer's rule (det(I − M) = (1 − μ1)(1 − μ2) ≠ 0 when stable)."""
    a00 = 1.0 - m00
    a01 = -m01
    a10 = -m10
    a11 = 1.0 - m11
    det = a00 * a11 - a01 * a10
    return (a11 * bx - a01 * bv) / det, (-a10 * bx + a00 * bv) / det


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
        m00, m01, m10, m11, bx, bv = _one_period(mass[j], nodes, stiffness[j], damping[j], force[j])
        first, second = _multipliers_abs(m00, m01, m10, m11)
        if _undamped(damping[j]):
            # |μ1·μ2| = det M = 1 exactly (Liouville), so |μ|max >= 1 in exact arithmetic, whatever rounding gives
            first = max(first, 1.0)
        moduli[j, 0] = first
        moduli[j, 1] = second
        if first < 1.0:
            x0[j], v0[j] = _solve_periodic(m00, m01, m10, m11, bx, bv)
        else:
            x0[j] = np.nan  # flagged by the caller through the multipliers, never returned as an orbit
            v0[j] = np.nan
    return x0, v0, moduli


@numba.njit(cache=True)
def _sample_kernel(mass: float, nodes: np.ndarray, stiffness: np.ndarray, damping: np.ndarray, force: np.ndarray,
                   x0: float, v0: float, samples: int) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """Exact solution at `samples` equal sub-steps per interval, plus the end of the period."""
    n = stiffness.size
    total = n * samples + 1
    time = np.empty(total)
    x = np.empty(total)
    v = np.empty(total)
    interval = np.empty(total, dtype=np.int64)
    x_start, v_start = x0, v0
    for i in range(n):
        h = (nodes[i + 1] - nodes[i]) / samples
        equilibrium = force[i] / stiffness[i]
        for j in range(samples):
            p = i * samples + j
            if j == 0:
                time[p] = nodes[i]
                x[p] = x_start
                v[p] = v_start
            else:
                p00, p01, p10, p11 = _transition(stiffness[i], damping[i], mass, j * h)
                dx = x_start - equilibrium
                time[p] = nodes[i] + j * h
                x[p] = p00 * dx + p01 * v_start + equilibrium
                v[p] = p10 * dx + p11 * v_start
            interval[p] = i
        p00, p01, p10, p11 = _transition(stiffness[i], damping[i], mass, nodes[i + 1] - nodes[i])
        dx = x_start - equilibrium
        x_start, v_start = p00 * dx + p01 * v_start + equilibrium, p10 * dx + p11 * v_start
    time[total - 1] = nodes[n]
    x[total - 1] = x_start
    v[total - 1] = v_start
    interval[total - 1] = n - 1
    return time, x, v, interval


@numba.njit(cache=True)
def _evaluate_kernel(mass: float, nodes: np.ndarray, stiffness: np.ndarray, damping: np.ndarray, force: np.ndarray,
                     x0: float, v0: float, times: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Exact solution at arbitrary times in [0, T] (any order)."""
    n = stiffness.size
    starts_x = np.empty(n)
    starts_v = np.empty(n)
    xs, vs = x0, v0
    for i in range(n):
        starts_x[i] = xs
        starts_v[i] = vs
        p00, p01, p10, p11 = _transition(stiffness[i], damping[i], mass, nodes[i + 1] - nodes[i])
        dx = xs - force[i] / stiffness[i]
        xs, vs = p00 * dx + p01 * vs + force[i] / stiffness[i], p10 * dx + p11 * vs
    x = np.empty(times.size)
    v = np.empty(times.size)
    for p in range(times.size):
        i = np.searchsorted(nodes, times[p], side="right") - 1
        i = min(max(i, 0), n - 1)
        p00, p01, p10, p11 = _transition(stiffness[i], damping[i], mass, times[p] - nodes[i])
        equilibrium = force[i] / stiffness[i]
        dx = starts_x[i] - equilibrium
        x[p] = p00 * dx + p01 * starts_v[i] + equilibrium
        v[p] = p10 * dx + p11 * starts_v[i]
    return x, v


@dataclass(frozen=True)
class PeriodicOrbit:
    """The periodic steady state over one mesh period.

    ``time`` [s] has ``samples_per_interval`` equal sub-steps per interval plus the end of the period T (where the
    state equals the initial state); ``interval`` gives the interval of each sample (right-continuous at nodes, the
    last sample belongs to the last interval). ``multipliers`` are the Floquet multipliers (complex), ``stable``
    is True when all lie inside the unit circle (always, for an orbit that was returned).
    """

    time: np.ndarray
    displacement: np.ndarray
    velocity: np.ndarray
    multipliers: np.ndarray
    stable: bool
    initial_state: tuple[float, float]
    interval: np.ndarray
    method: str = "periodic"

    @property
    def multipliers_abs(self) -> np.ndarray:
        """Moduli of the Floquet multipliers, larger first."""
        return np.sort(np.abs(self.multipliers))[::-1]


def _problem_arrays(problem: MeshDynamicsProblem) -> tuple[float, np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    return (problem.mass, np.ascontiguousarray(problem.nodes), np.ascontiguousarray(problem.stiffness),
            np.ascontiguousarray(problem.damping), np.ascontiguousarray(problem.force_per_interval))


def monodromy(problem: MeshDynamicsProblem) -> tuple[np.ndarray, np.ndarray]:
    """Monodromy matrix M (2×2) and the image b of y = 0 after one period (Floquet theory)."""
    m00, m01, m10, m11, bx, bv = _one_period(*_problem_arrays(problem))
    return np.array([[m00, m01], [m10, m11]]), np.array([bx, bv])


def _eigenvalues_2x2(matrix: np.ndarray) -> np.ndarray:
    half_trace = 0.5 * (matrix[0, 0] + matrix[1, 1])
    determinant = matrix[0, 0] * matrix[1, 1] - matrix[0, 1] * matrix[1, 0]
    root = np.sqrt(complex(half_trace * half_trace - determinant))
    first, second = half_trace + root, half_trace - root
    return np.array([first, second] if abs(first) >= abs(second) else [second, first])


def floquet_multipliers(problem: MeshDynamicsProblem) -> np.ndarray:
    """Floquet multipliers (complex eigenvalues of the monodromy matrix), larger modulus first."""
    matrix, _ = monodromy(problem)
    return _eigenvalues_2x2(matrix)


def _instability_message(moduli: np.ndarray, problem: MeshDynamicsProblem | None = None) -> str:
    text = (f"parametric instability: Floquet multiplier moduli {np.array2string(np.asarray(moduli), precision=6)} "
            "(one is >= 1), so the mesh vibration grows from period to period and there is no periodic steady state")
    if problem is not None:
        text += (f" (mesh frequency {problem.mesh_frequency:.6g} Hz, natural frequency "
                 f"{problem.natural_frequency:.6g} Hz, frequency ratio {problem.frequency_ratio:.4g}); "
                 "change the speed or add damping")
    return text


def periodic_initial_state(problem: MeshDynamicsProblem) -> tuple[tuple[float, float], np.ndarray]:
    """Initial state (x0 [m], v0 [m/s]) of the periodic orbit and the Floquet multipliers.

    Raises :class:`ModelLimitError` when a multiplier has modulus >= 1 (parametric resonance), or when the mesh is
    undamped (c = 0 everywhere: det M = 1, free vibrations never decay, no attracting orbit).
    """
    matrix, image = monodromy(problem)
    multipliers = _eigenvalues_2x2(matrix)
    moduli = np.abs(multipliers)
    if not np.any(problem.damping > 0.0):
        # decided on c, not on the computed moduli: those equal 1 only up to rounding and would make the verdict
        # depend on the period
        raise ModelLimitError(
            f"undamped mesh (c = 0 on every interval): the Floquet multiplier moduli "
            f"{np.array2string(moduli, precision=6)} have the product det M = 1, so free vibrations never decay and "
            "there is no attracting periodic steady state; give the mesh some damping or integrate a transient")
    if not np.all(np.isfinite(matrix)) or np.max(moduli) >= 1.0:
        raise ModelLimitError(_instability_message(moduli, problem))
    x0, v0 = _solve_periodic(matrix[0, 0], matrix[0, 1], matrix[1, 0], matrix[1, 1], image[0], image[1])
    return (float(x0), float(v0)), multipliers


def periodic_steady_state(problem: MeshDynamicsProblem, samples_per_interval: int = 64) -> PeriodicOrbit:
    """Exact periodic steady state over one mesh period (Floquet theory), sampled for plots and metrics.

    Parameters
    ----------
    problem:
        The mesh-cycle equation of motion.
    samples_per_interval:
        Equal sub-steps per interval at which the exact solution is evaluated (>= 1). The orbit is exact at
        every sample whatever this number; it only sets how finely peaks inside an interval are resolved.

    Raises
    ------
    ModelLimitError
        If a Floquet multiplier has modulus >= 1 (parametric instability), or c = 0 on every interval (undamped:
        the multipliers lie on the unit circle): there is no attracting periodic orbit to return.
    """
    if int(samples_per_interval) != samples_per_interval or samples_per_interval < 1:
        raise ProblemError("samples_per_interval", samples_per_interval, "integer >= 1",
                        "number of equal sub-steps per interval at which the orbit is evaluated")
    (x0, v0), multipliers = periodic_initial_state(problem)
    time, x, v, interval = _sample_kernel(*_problem_arrays(problem), x0, v0, int(samples_per_interval))
    if not (np.all(np.isfinite(x)) and np.all(np.isfinite(v))):  # pragma: no cover - guarded by the stability test
        raise ModelLimitError("the periodic orbit is not finite; the coefficients are out of numerical range")
    return PeriodicOrbit(time=time, displacement=x, velocity=v, multipliers=multipliers, stable=True,
                         initial_state=(x0, v0), interval=interval)


def evaluate_orbit(problem: MeshDynamicsProblem, initial_state: tuple[float, float],
                   times: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Exact displacement [m] and velocity [m/s] at ``times`` in [0, T] starting from ``initial_state`` at τ = 0."""
    times = np.ascontiguousarray(np.asarray(times, dtype=float))
    return _evaluate_kernel(*_problem_arrays(problem), float(initial_state[0]), float(initial_state[1]), times)


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
