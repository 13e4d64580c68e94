"""Periodic, subharmonic and non-periodic responses of the backlash mesh model by shooting (numba flow).

Shooting: Newton on R(y0) = φ_{N·T}(y0) − y0 = 0 with the exact Jacobian ∂φ/∂y0 − I, ∂φ/∂y0 the monodromy
carried through every contact switch with its saltation matrix (:mod:`thermogear.dynamics.backlash.backlash_kernel`).
The Floquet multipliers are the eigenvalues of the monodromy at the converged state; the orbit is kept only when
all lie strictly inside the unit circle (an attracting, physically observable orbit).

Search order (:func:`periodic_response`): Newton for N = 1 from the given state or from the linear periodic
solution with every pair in contact; if that fails or is unstable, a transient run-in from the same state, then
N = 1, 2, …, ``max_period_count``; if none converges to a stable orbit, a longer transient and one more round of
Newton from its end; otherwise the response is classified "non-periodic" and the last periods of the transient are
returned with ``converged`` False. An orbit is never returned unconverged under another name. A transient that
grows beyond 10⁶ static deflections raises :class:`~thermogear.errors.ModelLimitError` (a parametric instability
that the backlash cannot bound).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from thermogear.dynamics.backlash.backlash_kernel import integrate_periods
from thermogear.dynamics.problems.backlash_problem import BacklashMeshProblem
from thermogear.errors import ProblemError, ModelLimitError

__all__ = ["BacklashHistory", "BacklashOrbit", "backlash_flow", "backlash_transient", "least_period",
           "linear_initial_state", "orbit_from_shot", "periodic_response", "scaled_distance", "shoot",
           "shot_is_stable"]

SCAN_FRACTION = 1.0 / 16.0  # scan step / natural period of the active set (backlash_kernel docstring)
_UNBOUNDED = 1e6  # scaled |state| beyond which a transient is taken as growing without bound


@dataclass(frozen=True)
class BacklashHistory:
    """Exactly integrated motion sampled over whole mesh periods.

    ``time`` [s] from 0, ``displacement`` x [m], ``velocity`` ẋ [m/s], ``driving_contacts`` / ``back_contacts``
    the number of pairs touching on each flank, ``interval`` the interval of the mesh period, ``kind`` of each
    record (0 grid sample, 1 contact switch, 2 extremum of x, 3 interval end with its interval's coefficients),
    ``switch_times`` [s] the exact contact switches. ``free_flight_time`` [s] is the time without driving-flank
    contact, ``back_contact_time`` [s] with back-flank contact.
    """

    time: np.ndarray
    displacement: np.ndarray
    velocity: np.ndarray
    driving_contacts: np.ndarray
    back_contacts: np.ndarray
    interval: np.ndarray
    kind: np.ndarray
    switch_times: np.ndarray
    periods: int
    free_flight_time: float
    back_contact_time: float
    final_state: tuple[float, float]


@dataclass(frozen=True)
class BacklashOrbit:
    """Steady response: ``response`` "periodic" | "subharmonic" | "non-periodic".

    ``period_count`` N: the orbit repeats after N mesh periods (1 = periodic; for "non-periodic" the number of
    recorded periods). ``converged``: Newton met the tolerance and the orbit is stable; ``residual`` the scaled
    |φ_{NT}(y0) − y0| (x by the static deflection, ẋ by it times ω_n). ``multipliers`` the Floquet multipliers of
    the N-period monodromy (NaN when not converged). ``history`` the orbit sampled over its N periods (time from 0).
    """

    problem: BacklashMeshProblem
    response: str
    period_count: int
    converged: bool
    residual: float
    multipliers: np.ndarray
    initial_state: tuple[float, float]
    history: BacklashHistory
    iterations: int

    @property
    def largest_multiplier(self) -> float:
        """Largest Floquet multiplier modulus (NaN when not converged)."""
        return float(np.max(np.abs(self.multipliers)))

    @property
    def stable(self) -> bool:
        """True for a converged orbit with every multiplier inside the unit circle."""
        return bool(self.converged and self.largest_multiplier < 1.0)

    @property
    def switch_times(self) -> np.ndarray:
        """Exact contact-switch times [s] within the N periods."""
        return self.history.switch_times


def _kernel_arrays(problem: BacklashMeshProblem) -> tuple:
    problem.structure.require_scalar_mesh("the backlash shooting solver")
    return (problem.mass, np.ascontiguousarray(problem.nodes), problem.pair_stiffness, problem.pair_deviation,
            problem.back_pair_stiffness, problem.back_pair_deviation, problem.backlash, problem.damping,
            problem.force_per_interval, int(problem.damping_contact_only))


_EMPTY_F = np.empty(0)
_EMPTY_I = np.empty(0, dtype=np.int64)


def backlash_flow(problem: BacklashMeshProblem, state: tuple[float, float], periods: int = 1,
                  scan_fraction: float = SCAN_FRACTION) -> tuple[np.ndarray, np.ndarray, dict]:
    """φ_{periods·T}(state): end state [m, m/s], monodromy (2×2) and {switches, free_flight_time, back_contact_time}."""
    x, v, m00, m01, m10, m11, free, back, switches, _, status = integrate_periods(
        *_kernel_arrays(problem), float(state[0]), float(state[1]), int(periods), float(scan_fraction), False, 1,
        _EMPTY_F, _EMPTY_F, _EMPTY_F, _EMPTY_I, _EMPTY_I, _EMPTY_I, _EMPTY_I)
    if status == 2:
        raise ModelLimitError("the backlash mesh motion is not finite or chatters (more than 10 000 contact "
                              "switches in one interval); the coefficients are out of numerical range")
    return (np.array([x, v]), np.array([[m00, m01], [m10, m11]]),
            {"switches": int(switches), "free_flight_time": float(free), "back_contact_time": float(back)})


def _record(problem: BacklashMeshProblem, state: tuple[float, float], periods: int,
            samples_per_interval: int) -> BacklashHistory:
    if int(samples_per_interval) != samples_per_interval or samples_per_interval < 1:
        raise ProblemError("samples_per_interval", samples_per_interval, "integer >= 1",
                        "equal sub-steps per interval at which the exact motion is sampled")
    capacity = int(periods) * problem.interval_count * (int(samples_per_interval) + 4) + 16
    while True:
        arrays = (np.empty(capacity), np.empty(capacity), np.empty(capacity), np.empty(capacity, dtype=np.int64),
                  np.empty(capacity, dtype=np.int64), np.empty(capacity, dtype=np.int64),
                  np.empty(capacity, dtype=np.int64))
        x, v, _, _, _, _, free, back, _, count, status = integrate_periods(
            *_kernel_arrays(problem), float(state[0]), float(state[1]), int(periods), SCAN_FRACTION, True,
            int(samples_per_interval), *arrays)
        if status == 2:
            raise ModelLimitError("the backlash mesh motion is not finite or chatters; no history to return")
        if status == 0:
            break
        capacity = 2 * count
    order = np.argsort(arrays[0][:count], kind="stable")
    time, xs, vs, driving, backs, interval, kind = (a[:count][order] for a in arrays)
    time = np.append(time, periods * problem.period)
    last = interval[-1] if interval.size else problem.interval_count - 1
    return BacklashHistory(time=time, displacement=np.append(xs, x), velocity=np.append(vs, v),
                           driving_contacts=np.append(driving, driving[-1]), back_contacts=np.append(backs, backs[-1]),
                           interval=np.append(interval, last), kind=np.append(kind, 0),
                           switch_times=time[:-1][kind == 1], periods=int(periods), free_flight_time=float(free),
                           back_contact_time=float(back), final_state=(float(x), float(v)))


def backlash_transient(problem: BacklashMeshProblem, periods: int, samples_per_interval: int = 4,
                       initial_state: tuple[float, float] = (0.0, 0.0)) -> BacklashHistory:
    """Exact transient over ``periods`` mesh periods, from rest (x = ẋ = 0, as Luo & Li) unless told otherwise."""
    if int(periods) != periods or periods < 1:
        raise ProblemError("periods", periods, "integer >= 1", "number of mesh periods to integrate")
    return _record(problem, initial_state, int(periods), samples_per_interval)


def linear_initial_state(problem: BacklashMeshProblem) -> tuple[float, float]:
    """Periodic state at τ = 0 of the linear model with every pair in contact; static equilibrium if unavailable."""
    from thermogear.dynamics.periodic_orbits.periodic_batch import periodic_steady_state_batch

    problem.structure.require_scalar_mesh("the backlash shooting solver")
    linear = problem.linear_problem()
    if linear is not None:
        x0, v0, moduli = periodic_steady_state_batch(linear.mass, linear.nodes, linear.stiffness[None, :],
                                                     linear.damping[None, :], linear.force_per_interval[None, :])
        if moduli[0, 0] < 1.0 and np.isfinite(x0[0]):
            return float(x0[0]), float(v0[0])
    return problem.displacement_scale, 0.0


def scaled_distance(problem: BacklashMeshProblem, difference: np.ndarray) -> float:
    """Length of a state difference (Δx, Δv) in units of the problem's displacement and velocity scales [-]."""
    return float(np.hypot(difference[0] / problem.displacement_scale, difference[1] / problem.velocity_scale))


def shoot(problem: BacklashMeshProblem, initial_state: tuple[float, float], period_count: int = 1,
          tolerance: float = 1e-10, max_iterations: int = 30) -> dict:
    """Newton on φ_{N·T}(y0) − y0 with the exact monodromy; returns state, monodromy, residual, converged, iterations.

    Each step is damped (halved up to 8 times) until the scaled residual decreases, since the flow is only
    piecewise smooth. ``converged`` is True when the scaled residual is <= ``tolerance``.
    """
    state = np.array(initial_state, dtype=float)
    end, matrix, _ = backlash_flow(problem, state, period_count)
    residual = scaled_distance(problem, end - state)
    iterations = 0
    while residual > tolerance and iterations < max_iterations:
        iterations += 1
        jacobian = matrix - np.eye(2)
        if not np.all(np.isfinite(jacobian)) or abs(np.linalg.det(jacobian)) == 0.0:
            break
        step = np.linalg.solve(jacobian, -(end - state))
        scale = 1.0
        for _ in range(9):
            trial = state + scale * step
            trial_end, trial_matrix, _ = backlash_flow(problem, trial, period_count)
            trial_residual = scaled_distance(problem, trial_end - trial)
            if trial_residual < residual:
                break
            scale *= 0.5
        else:
            break
        state, end, matrix, residual = trial, trial_end, trial_matrix, trial_residual
    return {"state": state, "monodromy": matrix, "residual": residual, "converged": residual <= tolerance,
            "iterations": iterations}


def orbit_from_shot(problem: BacklashMeshProblem, result: dict, period_count: int, samples_per_interval: int,
                    iterations: int) -> BacklashOrbit:
    """The :class:`BacklashOrbit` of a converged shooting result (its state, monodromy and iteration count)."""
    multipliers = np.linalg.eigvals(result["monodromy"])
    multipliers = multipliers[np.argsort(-np.abs(multipliers))]
    state = (float(result["state"][0]), float(result["state"][1]))
    history = _record(problem, state, period_count, samples_per_interval)
    return BacklashOrbit(problem=problem, response="periodic" if period_count == 1 else "subharmonic",
                         period_count=period_count, converged=True, residual=float(result["residual"]),
                         multipliers=multipliers, initial_state=state, history=history, iterations=iterations)


def shot_is_stable(result: dict, problem: BacklashMeshProblem) -> bool:
    """Converged with every multiplier inside the unit circle. Undamped (c = 0 everywhere): det M = 1 by Liouville,
    so |μ|max >= 1 in exact arithmetic whatever rounding gives; decided on c, as the linear solver does."""
    return bool(result["converged"] and np.all(np.isfinite(result["monodromy"])) and np.any(problem.damping > 0.0)
                and np.max(np.abs(np.linalg.eigvals(result["monodromy"]))) < 1.0)


def least_period(problem: BacklashMeshProblem, state: np.ndarray, period_count: int, tolerance: float) -> int:
    """Smallest divisor d of N with φ_{dT}(y0) = y0 to tolerance (an N-orbit that is really a d-orbit)."""
    for divisor in range(1, period_count):
        if period_count % divisor == 0:
            end, _, _ = backlash_flow(problem, state, divisor)
            if scaled_distance(problem, end - state) <= 100.0 * tolerance:
                return divisor
    return period_count


def periodic_response(problem: BacklashMeshProblem, initial_state: tuple[float, float] | None = None,
                      max_period_count: int = 4, tolerance: float = 1e-10, max_iterations: int = 30,
                      run_in_periods: int = 200, classify_periods: int = 400,
                      samples_per_interval: int = 4) -> BacklashOrbit:
    """Steady response of the backlash model (module docstring for the search order).

    Parameters
    ----------
    problem:
        The nonsmooth mesh model.
    initial_state:
        (x0 [m], v0 [m/s]) at τ = 0 to start Newton from (e.g. a neighbour's orbit in a continuation); default the
        linear periodic solution with every pair in contact.
    max_period_count:
        Largest N tried for subharmonic orbits.
    tolerance:
        Scaled residual |φ_{NT}(y0) − y0| accepted as converged (the flow is exact, so 1e-10 is reachable).
    run_in_periods, classify_periods:
        Transient lengths before the subharmonic search and before the non-periodic verdict [mesh periods].
    samples_per_interval:
        Equal sub-steps per interval in the returned history (switches and extrema of x are always included).
    """
    if int(max_period_count) != max_period_count or max_period_count < 1:
        raise ProblemError("max_period_count", max_period_count, "integer >= 1", "largest subharmonic order tried")
    start = linear_initial_state(problem) if initial_state is None else tuple(float(a) for a in initial_state)
    if not np.all(np.isfinite(start)):
        raise ProblemError("initial_state", start, "finite (x [m], v [m/s])", "Newton needs a finite start")
    total = 0
    first = shoot(problem, start, 1, tolerance, max_iterations)
    total += first["iterations"]
    if shot_is_stable(first, problem):
        return orbit_from_shot(problem, first, 1, samples_per_interval, total)
    state = start
    for run_in in (run_in_periods, classify_periods):
        end, _, _ = backlash_flow(problem, state, run_in)
        state = (float(end[0]), float(end[1]))
        if scaled_distance(problem, end) > _UNBOUNDED:
            raise ModelLimitError(
                f"the backlash mesh response grows without bound (|x| reached {abs(end[0]):.3g} m, "
                f"{abs(end[0]) / problem.displacement_scale:.3g} static deflections, after {run_in} mesh periods): "
                "at large amplitude both flanks act like one linear mesh, so a parametric instability of the "
                "linear model persists; change the speed or add damping")
        for count in range(1, int(max_period_count) + 1):
            result = shoot(problem, state, count, tolerance, max_iterations)
            total += result["iterations"]
            if shot_is_stable(result, problem):
                least = least_period(problem, result["state"], count, tolerance)
                if least != count:
                    result = shoot(problem, result["state"], least, tolerance, max_iterations)
                    if not shot_is_stable(result, problem):
                        continue
                return orbit_from_shot(problem, result, least, samples_per_interval, total)
    # non-periodic: the attractor is neither a stable period-N orbit (N <= max) nor reachable by Newton
    record_periods = int(max_period_count)
    history = _record(problem, state, record_periods, samples_per_interval)
    mismatch = min(scaled_distance(problem, backlash_flow(problem, state, count)[0] - np.array(state))
                   for count in range(1, int(max_period_count) + 1))
    return BacklashOrbit(problem=problem, response="non-periodic", period_count=record_periods, converged=False,
                         residual=float(mismatch), multipliers=np.full(2, np.nan + 0j), initial_state=state,
                         history=history, iterations=total)
