"""Reference transient of the backlash mesh model with SciPy ``solve_ivp`` and event location (tests, benchmarks).

The right-hand side is written directly from the force law, me·ẍ = w − c_eff·ẋ − Σ k_s⟨x − e_s⟩₊
+ Σ k'_s⟨−x − j − e'_s⟩₊, independent of the closed forms of the exact solver. The integration is restarted at
every node (the coefficients jump there) and at every contact switch, located by ``solve_ivp``'s event finder on
x − threshold. After a switch the crossed threshold only watches for the opposite crossing, so the restart does
not find the switch it starts on again.
"""

from __future__ import annotations

import numpy as np
from scipy.integrate import solve_ivp

from thermogear.dynamics.problems.backlash_problem import BacklashMeshProblem
from thermogear.errors import ProblemError, ModelLimitError

__all__ = ["reference_backlash_solve_ivp"]


def _thresholds(problem: BacklashMeshProblem, i: int) -> np.ndarray:
    driving = problem.pair_deviation[problem.pair_stiffness[:, i] > 0.0, i]
    back = -problem.backlash - problem.back_pair_deviation[problem.back_pair_stiffness[:, i] > 0.0, i]
    return np.unique(np.concatenate([driving, back]))


def reference_backlash_solve_ivp(problem: BacklashMeshProblem, periods: int, initial_state=(0.0, 0.0),
                                 rtol: float = 1e-10, samples_per_interval: int = 8, method: str = "DOP853"
                                 ) -> dict[str, np.ndarray]:
    """Transient over ``periods`` mesh periods; returns time [s], x [m], v [m/s] (grid + switches) and switch times."""
    problem.structure.require_scalar_mesh("reference_backlash_solve_ivp")
    if int(periods) != periods or periods < 1:
        raise ProblemError("periods", periods, "integer >= 1", "number of mesh periods to integrate")
    mass, backlash = problem.mass, problem.backlash
    atol = rtol * np.array([problem.displacement_scale, problem.velocity_scale])
    present_count = np.maximum(np.sum(problem.pair_stiffness > 0.0, axis=0), 1)
    state = np.array(initial_state, dtype=float)
    times, xs, vs, switches = [], [], [], []
    for q in range(int(periods)):
        offset = q * problem.period
        for i in range(problem.interval_count):
            k, e = problem.pair_stiffness[:, i], problem.pair_deviation[:, i]
            kb, eb = problem.back_pair_stiffness[:, i], problem.back_pair_deviation[:, i]
            c, w = problem.damping[i], problem.force_per_interval[i]
            in_contact = problem.damping_contact_only

            def rhs(_t, y, k=k, e=e, kb=kb, eb=eb, c=c, w=w, i=i):
                driving = np.maximum(y[0] - e, 0.0)
                back = np.maximum(-y[0] - backlash - eb, 0.0)
                spring = np.dot(k, driving) - np.dot(kb, back)
                damping = c
                if in_contact:
                    touching = np.sum((k > 0.0) & (y[0] > e)) + np.sum((kb > 0.0) & (y[0] < -backlash - eb))
                    damping = c * min(1.0, touching / present_count[i])
                return np.array([y[1], (w - damping * y[1] - spring) / mass])

            levels = _thresholds(problem, i)
            start, end = offset + problem.nodes[i], offset + problem.nodes[i + 1]
            grid = start + (end - start) * np.arange(int(samples_per_interval)) / int(samples_per_interval)
            # a threshold the state starts on (the previous interval ended on a switch) only watches for a crossing
            # against the motion, as after a switch inside the interval
            motion = float(np.sign(state[1] if state[1] != 0.0 else rhs(start, state)[1]))
            just_crossed = {index: motion for index, level in enumerate(levels) if state[0] == level}
            t = start
            while True:
                events = []
                for index, level in enumerate(levels):
                    def event(_t, y, level=level):
                        return y[0] - level
                    event.terminal = True
                    event.direction = -just_crossed[index] if index in just_crossed else 0.0
                    events.append(event)
                solution = solve_ivp(rhs, (t, end), state, method=method, rtol=rtol, atol=atol, events=events,
                                     dense_output=True)
                if not solution.success:
                    raise ModelLimitError(f"solve_ivp failed on interval {i} of period {q}: {solution.message}")
                stop = solution.t[-1]
                if solution.status == 1 and stop <= t:
                    raise ModelLimitError(f"solve_ivp stalled on a contact switch at t = {t!r} s (interval {i})")
                inside = grid[(grid >= t) & (grid < stop)]
                if inside.size:
                    values = solution.sol(inside)
                    times.extend(inside)
                    xs.extend(values[0])
                    vs.extend(values[1])
                state = solution.y[:, -1].copy()
                if solution.status == 1:
                    index = next(j for j, hit in enumerate(solution.t_events) if hit.size)
                    state[0] = levels[index]
                    motion = float(np.sign(state[1] if state[1] != 0.0 else rhs(stop, state)[1]))
                    just_crossed = {index: motion}
                    switches.append(stop)
                    times.append(stop)
                    xs.append(state[0])
                    vs.append(state[1])
                    t = stop
                    continue
                break
    times.append(periods * problem.period)
    xs.append(state[0])
    vs.append(state[1])
    order = np.argsort(times, kind="stable")
    return {"time": np.array(times)[order], "displacement": np.array(xs)[order], "velocity": np.array(vs)[order],
            "switch_times": np.array(switches)}
