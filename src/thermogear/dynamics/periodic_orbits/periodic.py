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

The closed-form kernels are in :mod:`thermogear.dynamics.linear_algebra.transition_2x2`, shared with the batch solvers
of :mod:`thermogear.dynamics.periodic_orbits.periodic_batch` (states) and
:mod:`thermogear.dynamics.periodic_orbits.periodic_batch_metrics` (orbit metrics of many points, the sweeps' fast path).
"""

from __future__ import annotations

import numba
import numpy as np

from thermogear.dynamics.linear_algebra.transition_2x2 import one_period_2x2, periodic_state_2x2, transition_2x2
from thermogear.dynamics.problems.problem import MeshDynamicsProblem
from thermogear.dynamics.results.orbit import PeriodicOrbit
from thermogear.errors import ModelLimitError, ProblemError

__all__ = ["PeriodicOrbit", "evaluate_orbit", "floquet_multipliers", "periodic_initial_state",
           "periodic_steady_state"]

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
                p00, p01, p10, p11 = transition_2x2(stiffness[i], damping[i], mass, j * h)
                dx = x_start - equilibrium
                time[p] = nodes[i] + j * h
                x[p] = p00 * dx + p01 * v_start + equilibrium
                v[p] = p10 * dx + p11 * v_start
            interval[p] = i
        p00, p01, p10, p11 = transition_2x2(stiffness[i], damping[i], mass, nodes[i + 1] - nodes[i])
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
        p00, p01, p10, p11 = transition_2x2(stiffness[i], damping[i], mass, nodes[i + 1] - nodes[i])
        dx = xs - force[i] / stiffness[i]
        xs, vs = p00 * dx + p01 * vs + force[i] / stiffness[i], p10 * dx + p11 * vs
    x = np.empty(times.size)
    v = np.empty(times.size)
    for p in range(times.size):
        i = np.searchsorted(nodes, times[p], side="right") - 1
        i = min(max(i, 0), n - 1)
        p00, p01, p10, p11 = transition_2x2(stiffness[i], damping[i], mass, times[p] - nodes[i])
        equilibrium = force[i] / stiffness[i]
        dx = starts_x[i] - equilibrium
        x[p] = p00 * dx + p01 * starts_v[i] + equilibrium
        v[p] = p10 * dx + p11 * starts_v[i]
    return x, v


def _problem_arrays(problem: MeshDynamicsProblem) -> tuple[float, np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    problem.structure.require_scalar_mesh("the closed-form 2×2 kernel (periodic_steady_state and "
                                          "floquet_multipliers take a structure)")
    return (problem.mass, np.ascontiguousarray(problem.nodes), np.ascontiguousarray(problem.stiffness),
            np.ascontiguousarray(problem.damping), np.ascontiguousarray(problem.force_per_interval))


def monodromy(problem: MeshDynamicsProblem) -> tuple[np.ndarray, np.ndarray]:
    """Monodromy matrix M (2×2) and the image b of y = 0 after one period (Floquet theory)."""
    m00, m01, m10, m11, bx, bv = one_period_2x2(*_problem_arrays(problem))
    return np.array([[m00, m01], [m10, m11]]), np.array([bx, bv])


def _eigenvalues_2x2(matrix: np.ndarray) -> np.ndarray:
    half_trace = 0.5 * (matrix[0, 0] + matrix[1, 1])
    determinant = matrix[0, 0] * matrix[1, 1] - matrix[0, 1] * matrix[1, 0]
    root = np.sqrt(complex(half_trace * half_trace - determinant))
    first, second = half_trace + root, half_trace - root
    return np.array([first, second] if abs(first) >= abs(second) else [second, first])


def floquet_multipliers(problem: MeshDynamicsProblem) -> np.ndarray:
    """Floquet multipliers (complex eigenvalues of the monodromy matrix), larger modulus first."""
    if not problem.structure.is_scalar_mesh:
        from thermogear.dynamics.periodic_orbits.periodic_structure import structure_multipliers

        return structure_multipliers(problem)
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
    x0, v0 = periodic_state_2x2(matrix[0, 0], matrix[0, 1], matrix[1, 0], matrix[1, 1], image[0], image[1])
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
    if not problem.structure.is_scalar_mesh:  # the one place that chooses between the 2×2 and the matrix kernels
        from thermogear.dynamics.periodic_orbits.periodic_structure import structure_orbit

        return structure_orbit(problem, int(samples_per_interval))
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
