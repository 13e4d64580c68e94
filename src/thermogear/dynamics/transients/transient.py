"""Transient response from rest, me·ẍ + c(τ)ẋ + k(τ)x = w, with a fixed-step classical Runge–Kutta (RK4).

Luo & Li (2020) §4.1 integrate Eq. (6) from x = ẋ = 0 with RK4; this module does the same, compiled with numba,
to show the start-up and the convergence to the periodic steady state
(:mod:`thermogear.dynamics.periodic_orbits.periodic`). The steps are aligned to the nodes (the contact-region
transitions), so the jump of k and c always falls on a step boundary and RK4 keeps its fourth order.

Step-size rule (why ``ω·h <= 1`` is the refusal limit). The right-hand side is linear, y' = A y + f, and the
eigenvalues λ of A have modulus |λ| = sqrt(k/me) = ω_n for an under-damped interval (the larger root
σ + sqrt(σ² − k/me) for an over-damped one). RK4 is stable for |λ|·h up to about 2.78 on the negative real axis
and 2.83 on the imaginary axis. At ω·h = 1 an undamped oscillation loses |R(i)| = sqrt(1 − 1/72 + 1/576) ≈ 0.994,
i.e. 0.6 % of its amplitude per step, and its phase drifts by (ω·h)⁵/120 ≈ 0.8 % of a radian per step — about
4 % artificial damping per natural period, the same order as the physical damping of a lightly damped mesh
(ζ ≈ 0.01–0.1). Beyond that the result is wrong before it is unstable, so the limit is ω·h <= 1, a factor 2.8
inside the stability boundary. The default step (ω·h <= 0.05) keeps the error per step near 3e-9 of the
amplitude, which is what the agreement with the exact periodic orbit to 1e-6 needs.
"""

from __future__ import annotations

from dataclasses import dataclass

import numba
import numpy as np

from thermogear.dynamics.problems.problem import MeshDynamicsProblem
from thermogear.errors import ProblemError, ModelLimitError

__all__ = ["TransientHistory", "default_steps_per_interval", "largest_safe_step", "transient_from_rest",
           "transient_python"]

SAFE_OMEGA_STEP = 1.0      # refusal limit on |λ|·h (see the module docstring)
DEFAULT_OMEGA_STEP = 0.05  # default |λ|·h
MAX_STORED_SAMPLES = 20_000_000


@dataclass(frozen=True)
class TransientHistory:
    """Time history of a transient run (from rest unless stated).

    ``time`` [s] runs over ``periods`` mesh periods with ``steps_per_interval`` equal steps per interval;
    ``interval`` is the interval index of each sample (right-continuous at nodes; the very last sample belongs to
    the last interval). ``displacement`` x [m], ``velocity`` ẋ [m/s].
    """

    time: np.ndarray
    displacement: np.ndarray
    velocity: np.ndarray
    interval: np.ndarray
    periods: int
    steps_per_interval: int
    method: str

    @property
    def samples_per_period(self) -> int:
        """Number of samples per period (without the closing sample)."""
        return (self.time.size - 1) // self.periods

    def period_start_states(self) -> np.ndarray:
        """(periods + 1, 2) state [x, ẋ] at the start of every period, and at the end of the run."""
        stride = self.samples_per_period
        idx = np.arange(self.periods + 1) * stride
        return np.column_stack([self.displacement[idx], self.velocity[idx]])

    def last_period(self) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
        """(time − start, x, ẋ, interval) of the last period, time from 0 to T."""
        stride = self.samples_per_period
        start = self.time.size - 1 - stride
        sl = slice(start, None)
        return self.time[sl] - self.time[start], self.displacement[sl], self.velocity[sl], self.interval[sl]

    def convergence(self) -> np.ndarray:
        """(periods,) change of the period-start displacement from one period to the next, relative to max|x|
        over the run [-]; tends to 0 as the run settles on the periodic orbit."""
        states = self.period_start_states()
        scale = max(float(np.max(np.abs(self.displacement))), np.finfo(float).tiny)
        return np.abs(np.diff(states[:, 0])) / scale


def _eigen_moduli(problem: MeshDynamicsProblem) -> np.ndarray:
    """(n,) largest |λ| of A on each interval [1/s]."""
    problem.structure.require_scalar_mesh("the RK4 transient")
    a = problem.stiffness / problem.mass
    sigma = 0.5 * problem.damping / problem.mass
    d = sigma**2 - a
    return np.where(d < 0.0, np.sqrt(a), sigma + np.sqrt(np.abs(d)))


def largest_safe_step(problem: MeshDynamicsProblem) -> float:
    """Largest RK4 step [s] accepted by :func:`transient_from_rest`: min over intervals of 1/|λ|max."""
    return float(SAFE_OMEGA_STEP / np.max(_eigen_moduli(problem)))


def default_steps_per_interval(problem: MeshDynamicsProblem) -> int:
    """Smallest steps per interval with |λ|·h <= 0.05 on every interval (at least 1)."""
    return int(max(1, np.max(np.ceil(problem.durations * _eigen_moduli(problem) / DEFAULT_OMEGA_STEP))))


def _rk4_loop(mass: float, nodes: np.ndarray, stiffness: np.ndarray, damping: np.ndarray, force: np.ndarray,
              periods: int, steps: int, x0: float, v0: float, time: np.ndarray, x: np.ndarray, v: np.ndarray,
              interval: np.ndarray) -> None:
    """Classical RK4 on [x, ẋ]' = [ẋ, (w − c ẋ − k x)/me], steps aligned to the nodes; fills the output arrays."""
    n = stiffness.shape[0]
    period = nodes[n]
    xs = x0
    vs = v0
    p = 0
    for q in range(periods):
        offset = q * period
        for i in range(n):
            k_m = stiffness[i] / mass
            c_m = damping[i] / mass
            w_m = force[i] / mass
            h = (nodes[i + 1] - nodes[i]) / steps
            for j in range(steps):
                time[p] = offset + nodes[i] + j * h
                x[p] = xs
                v[p] = vs
                interval[p] = i
                p += 1
                a1x = vs
                a1v = w_m - c_m * vs - k_m * xs
                x2 = xs + 0.5 * h * a1x
                v2 = vs + 0.5 * h * a1v
                a2x = v2
                a2v = w_m - c_m * v2 - k_m * x2
                x3 = xs + 0.5 * h * a2x
                v3 = vs + 0.5 * h * a2v
                a3x = v3
                a3v = w_m - c_m * v3 - k_m * x3
                x4 = xs + h * a3x
                v4 = vs + h * a3v
                a4x = v4
                a4v = w_m - c_m * v4 - k_m * x4
                xs = xs + h / 6.0 * (a1x + 2.0 * a2x + 2.0 * a3x + a4x)
                vs = vs + h / 6.0 * (a1v + 2.0 * a2v + 2.0 * a3v + a4v)
    time[p] = periods * period
    x[p] = xs
    v[p] = vs
    interval[p] = n - 1


_rk4_kernel = numba.njit(cache=True)(_rk4_loop)


def _prepare(problem: MeshDynamicsProblem, periods: int, steps_per_interval: int | None) -> tuple[int, int]:
    if int(periods) != periods or periods < 1:
        raise ProblemError("periods", periods, "integer >= 1", "number of mesh periods to integrate")
    if steps_per_interval is None:
        steps = default_steps_per_interval(problem)
    else:
        if int(steps_per_interval) != steps_per_interval or steps_per_interval < 1:
            raise ProblemError("steps_per_interval", steps_per_interval, "integer >= 1",
                            "equal RK4 steps in each interval between nodes")
        steps = int(steps_per_interval)
    step = np.max(problem.durations * _eigen_moduli(problem) / steps)
    if step > SAFE_OMEGA_STEP:
        safe = largest_safe_step(problem)
        needed = int(np.max(np.ceil(problem.durations * _eigen_moduli(problem) / SAFE_OMEGA_STEP)))
        raise ProblemError("steps_per_interval", steps, f">= {needed} (largest safe step {safe:.4g} s)",
                        f"the RK4 step gives |λ|·h = {step:.3g} > {SAFE_OMEGA_STEP} (|λ| up to "
                        f"{np.max(_eigen_moduli(problem)):.6g} rad/s): too coarse to be accurate "
                        "(RK4 stability ends at 2.78)")
    total = int(periods) * problem.interval_count * steps + 1
    if total > MAX_STORED_SAMPLES:
        raise ProblemError("periods", periods, f"periods × intervals × steps <= {MAX_STORED_SAMPLES}",
                        f"the history would hold {total} samples; use the periodic solver for the steady state")
    return int(periods), steps


def _run(loop, problem: MeshDynamicsProblem, periods: int, steps_per_interval: int | None, x0: float, v0: float,
         method: str) -> TransientHistory:
    periods, steps = _prepare(problem, periods, steps_per_interval)
    if not (np.isfinite(x0) and np.isfinite(v0)):
        raise ProblemError("x0/v0", (x0, v0), "finite", "the initial state must be a number")
    total = periods * problem.interval_count * steps + 1
    time = np.empty(total)
    x = np.empty(total)
    v = np.empty(total)
    interval = np.empty(total, dtype=np.int64)
    loop(problem.mass, np.ascontiguousarray(problem.nodes), np.ascontiguousarray(problem.stiffness),
         np.ascontiguousarray(problem.damping), np.ascontiguousarray(problem.force_per_interval), periods, steps,
         float(x0), float(v0), time, x, v, interval)
    if not (np.all(np.isfinite(x)) and np.all(np.isfinite(v))):
        raise ModelLimitError("the transient grew without bound (overflow): the operating point is parametrically "
                              "unstable; see the Floquet multipliers of the periodic solver")
    return TransientHistory(time=time, displacement=x, velocity=v, interval=interval, periods=periods,
                            steps_per_interval=steps, method=method)


def transient_from_rest(problem: MeshDynamicsProblem, periods: int, steps_per_interval: int | None = None,
                        x0: float = 0.0, v0: float = 0.0) -> TransientHistory:
    """Transient from x = x0, ẋ = v0 (rest by default, as the paper) over ``periods`` mesh periods, numba RK4.

    ``steps_per_interval`` equal steps in every interval (default: |λ|·h <= 0.05). A step with |λ|·h > 1 is
    refused with :class:`ProblemError` stating the largest safe step (see the module docstring for the argument).
    """
    return _run(_rk4_kernel, problem, periods, steps_per_interval, x0, v0, "transient_rk4")


def transient_python(problem: MeshDynamicsProblem, periods: int, steps_per_interval: int | None = None,
                     x0: float = 0.0, v0: float = 0.0) -> TransientHistory:
    """The very same RK4 loop run as plain Python (the uncompiled source); only for benchmarks and tests."""
    return _run(_rk4_loop, problem, periods, steps_per_interval, x0, v0, "transient_rk4_python")
