"""Benchmark: the nonlinear (backlash) mesh solver on luo2019 near its primary resonance, against solve_ivp in the run.

Run: python benchmarks/bench_nonlinear.py [--quick]
Prints a table and writes benchmarks/results/bench_nonlinear.json.

The problem is ``Simulation(load_case("luo2019") at 13 000 rpm, "elastic").problem`` (1024 intervals per mesh
period, frequency ratio 0.97, the linear model parametrically unstable there) with a normal backlash of 100 μm,
damping mode "always". Figures:

All times are CPU seconds of the process (single-threaded code; the development machine is shared, so its wall
clock is stretched by others' load), the solve_ivp baseline included.

1. one periodic response (``periodic_response``: Newton from the linear/static guess, Floquet multipliers, the
   orbit sampled 4 times per interval with every switch and extremum, no metrics) in ms after warm-up, and the
   same from a neighbour's converged state (what a continuation step costs), against the SciPy reference
   (``reference_backlash_solve_ivp``: DOP853, rtol 1e-10, restarted at every node and every contact switch
   located by its event finder) run from rest to the same steady state. The number of mesh periods that takes is
   measured with the exact transient (first period whose state at τ = 0 is within 1e-6, scaled, of the orbit);
   solve_ivp is timed over a few periods only and scaled to that count.
2. a 1000-speed continuation up and then down (2000 solves with metrics; the problems are the 13 000 rpm one with
   its time axis rescaled to each speed from 4 000 to 16 000 rpm, damping kept), on one core, against 2000 times
   the solve_ivp cost of one point. The jump-up and jump-down speeds of the hysteresis are reported.
"""

from __future__ import annotations

import json
import platform
import sys
import time
import warnings
from pathlib import Path

import numpy as np

RESULTS = Path(__file__).resolve().parent / "results"
TOLERANCE = 1e-6  # scaled distance to the orbit at τ = 0 that counts as "steady state reached"
SPEED_RPM = 13000.0
BACKLASH = 100e-6  # [m]


def _times(function, repeat: int) -> np.ndarray:
    """CPU seconds of the process per call (the solvers are single-threaded: one core). CPU time, not wall time,
    because the development machine is shared: others' load stretches the wall clock, not our CPU time."""
    values = []
    for _ in range(repeat):
        start = time.process_time()
        function()
        values.append(time.process_time() - start)
    return np.array(values)


def _periods_to_settle(problem, orbit, limit: int = 5000) -> int:
    """Mesh periods from rest until the state at τ = 0 is within TOLERANCE (scaled) of the orbit's."""
    from thermogear.dynamics.backlash.backlash_periodic import backlash_flow

    target = np.array(orbit.initial_state)
    scale = np.array([problem.displacement_scale, problem.velocity_scale])
    state = np.zeros(2)
    for count in range(1, limit + 1):
        state = backlash_flow(problem, state, 1)[0]
        if np.hypot(*((state - target) / scale)) < TOLERANCE:
            return count
    raise RuntimeError(f"the transient from rest did not reach the orbit to {TOLERANCE} in {limit} periods")


def main(quick: bool = False) -> dict:
    warnings.simplefilter("ignore")
    from thermogear.case import load_case
    from thermogear.dynamics.backlash.backlash_continuation import follow_branch
    from thermogear.dynamics.backlash.backlash_metrics import orbit_metrics
    from thermogear.dynamics.backlash.backlash_periodic import periodic_response
    from thermogear.dynamics.problems.backlash_problem import BacklashMeshProblem
    from thermogear.dynamics.transients.backlash_reference import reference_backlash_solve_ivp
    from thermogear.simulation import Simulation

    case = load_case("luo2019").with_changes(**{"operating.speed_rpm": SPEED_RPM})
    linear = Simulation(case, "elastic").problem
    problem = BacklashMeshProblem.from_linear(linear, backlash=BACKLASH)
    figures = []

    # ---------------------------------------------------------------- 1. one periodic response
    orbit = periodic_response(problem)  # compile / load the numba cache
    cold = _times(lambda: periodic_response(problem), 10 if quick else 50)
    warm = _times(lambda: periodic_response(problem, initial_state=orbit.initial_state), 10 if quick else 50)
    metrics = orbit_metrics(orbit)
    settle = _periods_to_settle(problem, orbit)
    probe_periods = 1 if quick else 3
    probe = _times(lambda: reference_backlash_solve_ivp(problem, probe_periods, samples_per_interval=1), 1)
    ivp_per_period = float(probe[0]) / probe_periods
    ivp_point = ivp_per_period * settle
    cold_ms, warm_ms = float(np.median(cold)) * 1e3, float(np.median(warm)) * 1e3
    figures.append({"name": f"periodic response, Newton from the static guess, vs solve_ivp+events from rest "
                            f"({settle} periods to 1e-6)", "value": cold_ms, "baseline": ivp_point * 1e3,
                    "unit": "ms per point", "ratio": ivp_point * 1e3 / cold_ms})
    figures.append({"name": "periodic response from a neighbour's state (continuation step) vs the same baseline",
                    "value": warm_ms, "baseline": ivp_point * 1e3, "unit": "ms per point",
                    "ratio": ivp_point * 1e3 / warm_ms})

    # ---------------------------------------------------------------- 2. continuation up and down
    count = 200 if quick else 1000
    speeds = np.linspace(4000.0, 16000.0, count)
    problems = [problem.with_changes(nodes=problem.nodes * (SPEED_RPM / speed)) for speed in speeds]
    wall_start, start = time.perf_counter(), time.process_time()
    up = follow_branch(problems, "up", speeds)
    middle = time.process_time()
    down = follow_branch(problems, "down", speeds)
    end, wall_end = time.process_time(), time.perf_counter()
    sweep_s = end - start
    baseline_s = 2 * count * ivp_point
    figures.append({"name": f"{count}-speed continuation up + down (4000–16000 rpm) vs solve_ivp per point",
                    "value": sweep_s, "baseline": baseline_s, "unit": "s", "ratio": baseline_s / sweep_s})
    swing_up, swing_down = up["dte_peak_to_peak"], down["dte_peak_to_peak"]
    jump_up = int(np.argmax(np.diff(swing_up)))
    jump_down = int(np.argmax(np.diff(swing_down)))

    def jumps(swing):
        """Speed pairs [rpm] across which the swing grows by more than 30 % with speed: a jump up in the up sweep,
        a jump down (going down) in the down sweep. Not a slope: the 1000 speeds are 12 rpm apart."""
        return [[float(speeds[k]), float(speeds[k + 1])] for k in np.flatnonzero(swing[1:] > 1.3 * swing[:-1])]

    result = {
        "benchmark": "bench_nonlinear",
        "case": (f"luo2019 elastic at {SPEED_RPM:g} rpm, backlash {BACKLASH * 1e6:g} μm, {problem.interval_count} "
                 f"intervals per mesh period, frequency ratio {linear.frequency_ratio:.4f}"),
        "figures": figures,
        "periodic_response_ms": {"median": cold_ms, "best": float(cold.min()) * 1e3, "newton_iterations":
                                 orbit.iterations},
        "periodic_response_from_neighbour_ms": {"median": warm_ms, "best": float(warm.min()) * 1e3},
        "periodic_response_target_ms": 5.0,
        "periodic_response_meets_target": bool(cold_ms <= 5.0),
        "solve_ivp_seconds_per_mesh_period": ivp_per_period,
        "solve_ivp_periods_to_steady_state": settle,
        "solve_ivp_tolerance": TOLERANCE,
        "solve_ivp_seconds_per_point": ivp_point,
        "periodic_speedup_ratio": ivp_point * 1e3 / cold_ms,
        "orbit": {"response": orbit.response, "largest_multiplier": orbit.largest_multiplier,
                  "contact_loss_fraction": metrics["contact_loss_fraction"], "kv": metrics["kv"],
                  "dte_peak_to_peak_um": metrics["dte_peak_to_peak"] * 1e6,
                  "switches_per_period": metrics["switches_per_period"]},
        "continuation_points": int(count),
        "continuation_seconds_up_down": sweep_s,
        "continuation_wall_seconds_up_down": wall_end - wall_start,
        "timing_clock": "process CPU time (time.process_time), single-threaded code on a shared machine",
        "continuation_seconds_up": middle - start,
        "continuation_seconds_down": end - middle,
        "continuation_target_seconds": 10.0 if count == 1000 else None,
        "continuation_meets_target": bool(sweep_s <= 10.0) if count == 1000 else None,
        "continuation_speedup_ratio": baseline_s / sweep_s,
        "continuation_converged_points": int(np.sum(up.converged) + np.sum(down.converged)),
        "continuation_non_periodic_points": int(np.sum(up.response == "non-periodic")
                                                + np.sum(down.response == "non-periodic")),
        "jump_up_rpm": [float(speeds[jump_up]), float(speeds[jump_up + 1])],
        "all_jumps_up_rpm": jumps(swing_up),
        "all_jumps_down_rpm": jumps(swing_down),
        "jump_down_rpm": [float(speeds[jump_down]), float(speeds[jump_down + 1])],
        "responses_up": sorted(set(up.response.tolist())),
        "responses_down": sorted(set(down.response.tolist())),
        "python": platform.python_version(),
        "numpy": np.__version__,
        "machine": platform.machine(),
    }
    RESULTS.mkdir(parents=True, exist_ok=True)
    (RESULTS / "bench_nonlinear.json").write_text(json.dumps(result, indent=2) + "\n", encoding="utf-8")

    print(f"{'figure':86s} {'value':>10s} {'baseline':>10s} {'ratio':>9s}")
    for figure in figures:
        print(f"{figure['name'][:86]:86s} {figure['value']:10.4g} {figure['baseline']:10.4g} "
              f"{figure['ratio']:9.4g}  {figure['unit']}")
    print(f"orbit: {orbit.response}, |μ|max {orbit.largest_multiplier:.4f}, contact loss "
          f"{metrics['contact_loss_fraction']:.3f} of the period, Kv {metrics['kv']:.3f}; solve_ivp needs {settle} "
          f"periods from rest ({ivp_per_period:.3g} s each)")
    print(f"jump up between {speeds[jump_up]:.0f} and {speeds[jump_up + 1]:.0f} rpm, jump down between "
          f"{speeds[jump_down + 1]:.0f} and {speeds[jump_down]:.0f} rpm")
    return result


if __name__ == "__main__":
    main(quick="--quick" in sys.argv[1:])
