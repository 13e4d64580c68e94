"""Reference solution with SciPy's adaptive ``solve_ivp`` (tests and benchmarks only).

The coefficients jump at the nodes, so an adaptive integrator run across a node would either lose its order or
shrink its step to resolve the jump. The integration is therefore restarted at every node, interval by interval,
with the state carried over (x and ẋ are continuous; ẍ jumps).
"""

from __future__ import annotations

import numpy as np

from thermogear.dynamics.problems.problem import MeshDynamicsProblem
from thermogear.dynamics.transients.transient import TransientHistory
from thermogear.errors import ProblemError, ModelLimitError

__all__ = ["reference_solve_ivp"]


def reference_solve_ivp(problem: MeshDynamicsProblem, periods: int, rtol: float = 1e-10,
                        atol: float | None = None, samples_per_interval: int = 16, x0: float = 0.0,
                        v0: float = 0.0, method: str = "DOP853") -> TransientHistory:
    """Transient from (x0, v0) over ``periods`` mesh periods with ``solve_ivp``, restarted at every node.

    ``atol`` defaults to ``rtol`` times the scale of each state: the largest static transmission error w/k [m]
    for x, and that times the largest ω_n [m/s] for ẋ. The output is sampled at ``samples_per_interval`` equal
    sub-steps per interval (the same grid as the RK4 and periodic solvers) through the dense output.
    """
    from scipy.integrate import solve_ivp  # noqa: PLC0415  (imported when used: ~0.3 s a sweep never needs)

    problem.structure.require_scalar_mesh("reference_solve_ivp")

    if int(periods) != periods or periods < 1:
        raise ProblemError("periods", periods, "integer >= 1", "number of mesh periods to integrate")
    if not 0.0 < rtol < 1.0:
        raise ProblemError("rtol", rtol, "(0, 1)", "relative tolerance of solve_ivp")
    x_scale = float(np.max(problem.static_transmission_error))
    v_scale = x_scale * float(np.sqrt(np.max(problem.stiffness) / problem.mass))
    if atol is None:
        atol_vector = rtol * np.array([x_scale, v_scale])
    else:
        atol_vector = np.array([atol, atol * v_scale / x_scale])
    n = problem.interval_count
    s = int(samples_per_interval)
    total = int(periods) * n * s + 1
    time = np.empty(total)
    x = np.empty(total)
    v = np.empty(total)
    interval = np.empty(total, dtype=np.int64)
    state = np.array([x0, v0], dtype=float)
    mass = problem.mass
    force = problem.force_per_interval
    p = 0
    for q in range(int(periods)):
        offset = q * problem.period
        for i in range(n):
            k_m, c_m, w_m = problem.stiffness[i] / mass, problem.damping[i] / mass, force[i] / mass

            def rhs(_t: float, y: np.ndarray, k_m: float = k_m, c_m: float = c_m, w_m: float = w_m) -> np.ndarray:
                return np.array([y[1], w_m - c_m * y[1] - k_m * y[0]])

            start, end = offset + problem.nodes[i], offset + problem.nodes[i + 1]
            grid = start + (end - start) * np.arange(s) / s
            solution = solve_ivp(rhs, (start, end), state, method=method, rtol=rtol, atol=atol_vector,
                                 dense_output=True)
            if not solution.success:
                raise ModelLimitError(f"solve_ivp failed on interval {i} of period {q}: {solution.message}")
            values = solution.sol(grid)
            time[p:p + s] = grid
            x[p:p + s] = values[0]
            v[p:p + s] = values[1]
            interval[p:p + s] = i
            p += s
            state = solution.y[:, -1]
    time[p] = int(periods) * problem.period
    x[p], v[p] = state
    interval[p] = n - 1
    if not (np.all(np.isfinite(x)) and np.all(np.isfinite(v))):
        raise ModelLimitError("the reference transient is not finite (parametric instability?)")
    return TransientHistory(time=time, displacement=x, velocity=v, interval=interval, periods=int(periods),
                            steps_per_interval=s, method=f"solve_ivp_{method}")
