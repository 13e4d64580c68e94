"""Benchmark: the mesh dynamics solvers on the luo2019 thermal operating point, against baselines in the same run.

Run: python benchmarks/bench_dynamics.py [--quick]
Prints a table and writes benchmarks/results/bench_dynamics.json.

Figures (the problem is ``Simulation(load_case("luo2019"), "thermal").problem``: 1024 intervals per mesh period):

1. periodic steady state (Floquet/monodromy, ``periodic_initial_state``: the exact periodic state at τ = 0, from
   which the orbit is known everywhere) in μs per solve after warm-up, against the SciPy reference
   (``reference_solve_ivp``, DOP853 restarted at every node) run from rest for as many mesh periods as it needs to
   agree with the periodic orbit to 1e-6 relative (the count is measured, not assumed). The sampled orbit
   (``periodic_steady_state``, 64 samples per interval, what ``Simulation.run`` uses) is reported too.
2. the whole operating point (``Simulation`` construction → stiffness → damping → periodic orbit → metrics) in ms,
   with the time of each stage, against the sweep fast path (``thermogear.sweep.batch.evaluate_speeds``) per point.
3. the numba RK4 transient (``transient_from_rest``) against the very same loop run as plain Python
   (``transient_python``), per mesh period at the default step (|λ|·h <= 0.05).
"""

from __future__ import annotations

import cProfile
import io
import json
import platform
import pstats
import sys
import time
import warnings
from pathlib import Path

import numpy as np
from timing import wall_times

RESULTS = Path(__file__).resolve().parent / "results"
TOLERANCE = 1e-6  # relative agreement with the periodic orbit that counts as "steady state reached"



def _periods_to_converge(problem, orbit, history) -> int:
    """First number of whole periods after which the period matches the orbit to TOLERANCE (relative)."""
    stride = history.samples_per_period
    scale = float(np.abs(orbit.displacement).max())
    for q in range(history.periods):
        window = history.displacement[q * stride: (q + 1) * stride + 1]
        if np.abs(window - orbit.displacement).max() / scale < TOLERANCE:
            return q + 1
    raise RuntimeError(f"solve_ivp did not reach the periodic orbit to {TOLERANCE} in {history.periods} periods")


def _stage_times(case, repeat: int) -> dict[str, float]:
    """Median time [s] of each stage of one operating point, caches of the chain warm (as in a loop)."""
    from thermogear.dynamics.periodic_orbits.periodic import periodic_steady_state
    from thermogear.dynamics.response import response_from_orbit
    from thermogear.simulation import Simulation

    stages: dict[str, list[float]] = {name: [] for name in
                                      ("mesh state (grid, pair stiffness, damping)", "problem",
                                       "periodic orbit (64 samples/interval)", "metrics")}
    for _ in range(repeat):
        simulation = Simulation(case, "thermal")
        marks = [time.perf_counter()]
        _ = simulation.state
        marks.append(time.perf_counter())
        problem = simulation.problem
        marks.append(time.perf_counter())
        orbit = periodic_steady_state(problem)
        marks.append(time.perf_counter())
        response_from_orbit(problem, orbit, include_damping_force=case.dynamics.include_damping_force)
        marks.append(time.perf_counter())
        for name, a, b in zip(stages, marks[:-1], marks[1:], strict=True):
            stages[name].append(b - a)
    return {name: float(np.median(values)) for name, values in stages.items()}


def _profile(function, top: int = 12) -> str:
    profiler = cProfile.Profile()
    profiler.enable()
    function()
    profiler.disable()
    stream = io.StringIO()
    pstats.Stats(profiler, stream=stream).sort_stats("cumulative").print_stats(top)
    return stream.getvalue()


def main(quick: bool = False) -> dict:
    warnings.simplefilter("ignore")
    from thermogear.case import load_case
    from thermogear.dynamics import (periodic_steady_state, reference_solve_ivp, transient_from_rest,
                                     transient_python)
    from thermogear.dynamics.periodic_orbits.periodic import periodic_initial_state
    from thermogear.mesh.model import MeshModel
    from thermogear.simulation import Simulation
    from thermogear.sweep.batch import evaluate_speeds, group_tables

    case = load_case("luo2019")
    problem = Simulation(case, "thermal").problem
    figures = []

    # ---------------------------------------------------------------- 1. periodic vs solve_ivp from rest
    periodic_initial_state(problem)  # compile / load the numba cache
    periodic_steady_state(problem)
    solve = wall_times(lambda: periodic_initial_state(problem), 200 if quick else 2000)
    sampled = wall_times(lambda: periodic_steady_state(problem), 10 if quick else 50)
    orbit = periodic_steady_state(problem, samples_per_interval=1)
    probe = reference_solve_ivp(problem, periods=6, samples_per_interval=1)
    periods_needed = _periods_to_converge(problem, orbit, probe)
    reference = wall_times(lambda: reference_solve_ivp(problem, periods=periods_needed, samples_per_interval=1),
                       1 if quick else 3)
    solve_us = float(np.median(solve)) * 1e6
    reference_us = float(np.median(reference)) * 1e6
    figures.append({"name": f"periodic steady state vs solve_ivp from rest to 1e-6 ({periods_needed} periods)",
                    "value": solve_us, "baseline": reference_us, "unit": "μs per solve",
                    "ratio": reference_us / solve_us})
    sampled_us = float(np.median(sampled)) * 1e6
    figures.append({"name": "sampled periodic orbit (64 samples/interval) vs solve_ivp from rest",
                    "value": sampled_us, "baseline": reference_us, "unit": "μs per solve",
                    "ratio": reference_us / sampled_us})

    # ---------------------------------------------------------------- 2. the whole operating point
    def whole_point():
        simulation = Simulation(case, "thermal")
        return simulation.run("periodic")

    whole_point()  # warm the stiffness-table cache and every numba kernel, as any second point of a study
    whole = wall_times(whole_point, 5 if quick else 30)
    whole_ms = float(np.median(whole)) * 1e3
    stages = _stage_times(case, 5 if quick else 20)

    def whole_point_coarse():
        # the same chain with the orbit sampled once per interval instead of 64 times (each luo2019 interval spans
        # ω·h ≈ 0.05 rad of the natural vibration, so a sampled peak is low by at most (ωh)²/8 ≈ 3e-4 of the swing)
        from thermogear.dynamics.response import response_from_orbit

        problem_here = Simulation(case, "thermal").problem
        return response_from_orbit(problem_here, periodic_steady_state(problem_here, samples_per_interval=1),
                                   include_damping_force=case.dynamics.include_damping_force)

    whole_point_coarse()
    coarse_ms = float(np.median(wall_times(whole_point_coarse, 5 if quick else 30))) * 1e3
    kv_fine = whole_point().metrics["kv"]
    kv_coarse = whole_point_coarse().metrics["kv"]
    profile_text = _profile(whole_point)
    tables = group_tables(MeshModel(case, "thermal"))
    speeds = np.linspace(500.0, 12000.0, 200 if quick else 2000)
    evaluate_speeds(tables, speeds[:4])
    batch = wall_times(lambda: evaluate_speeds(tables, speeds), 3)
    batch_ms = float(np.min(batch)) / speeds.size * 1e3
    tables_ms = float(np.median(wall_times(lambda: group_tables(MeshModel(case, "thermal")), 5 if quick else 10))) * 1e3
    figures.append({"name": "whole operating point (Simulation → metrics) vs sweep fast path (ratio: times slower)",
                    "value": whole_ms, "baseline": batch_ms, "unit": "ms per point",
                    "ratio": whole_ms / batch_ms})

    # ---------------------------------------------------------------- 3. numba RK4 vs plain Python
    rk4_periods = 20 if quick else 100
    python_periods = 1 if quick else 3
    transient_from_rest(problem, periods=1)  # compile / load the numba cache
    compiled = wall_times(lambda: transient_from_rest(problem, periods=rk4_periods), 3) / rk4_periods
    plain = wall_times(lambda: transient_python(problem, periods=python_periods), 1 if quick else 2) / python_periods
    steps = transient_from_rest(problem, periods=1).steps_per_interval
    compiled_ms = float(np.min(compiled)) * 1e3
    plain_ms = float(np.min(plain)) * 1e3
    figures.append({"name": f"numba RK4 transient vs the same loop in plain Python ({steps} step/interval)",
                    "value": compiled_ms, "baseline": plain_ms, "unit": "ms per mesh period",
                    "ratio": plain_ms / compiled_ms})

    result = {
        "benchmark": "bench_dynamics",
        "case": (f"luo2019 thermal at {case.operating_point.speed_rpm:g} rpm, {problem.interval_count} intervals per "
                 f"mesh period, frequency ratio {problem.frequency_ratio:.4f}"),
        "figures": figures,
        "periodic_solve_us": {"median": solve_us, "best": float(solve.min()) * 1e6},
        "periodic_sampled_orbit_us": {"median": sampled_us, "best": float(sampled.min()) * 1e6},
        "solve_ivp_periods_to_steady_state": periods_needed,
        "solve_ivp_tolerance": TOLERANCE,
        "solve_ivp_to_steady_state_us": {"median": reference_us, "best": float(reference.min()) * 1e6},
        "floquet_multipliers_abs": [float(m) for m in np.abs(orbit.multipliers)],
        "periodic_speedup_ratio": reference_us / solve_us,
        "periodic_target_us": 100.0,
        "periodic_target_speedup": 1000.0,
        "periodic_meets_target": bool(solve_us < 100.0 and reference_us / solve_us >= 1000.0),
        "operating_point_ms": {"median": whole_ms, "best": float(whole.min()) * 1e3},
        "operating_point_stage_ms": {name: value * 1e3 for name, value in stages.items()},
        "operating_point_target_ms": 1.0,
        "operating_point_meets_target": bool(whole_ms < 1.0),
        "operating_point_one_sample_per_interval_ms": coarse_ms,
        "kv_64_samples_per_interval": kv_fine,
        "kv_1_sample_per_interval": kv_coarse,
        "sweep_fast_path_ms_per_point": batch_ms,
        "sweep_group_tables_ms": tables_ms,
        "operating_point_profile_top": profile_text.splitlines()[:40],
        "rk4_steps_per_interval": steps,
        "rk4_numba_ms_per_period": compiled_ms,
        "rk4_python_ms_per_period": plain_ms,
        "rk4_speedup_ratio": plain_ms / compiled_ms,
        "python": platform.python_version(),
        "numpy": np.__version__,
        "machine": platform.machine(),
    }
    RESULTS.mkdir(parents=True, exist_ok=True)
    (RESULTS / "bench_dynamics.json").write_text(json.dumps(result, indent=2) + "\n", encoding="utf-8")

    print(f"{'figure':78s} {'value':>12s} {'baseline':>12s} {'ratio':>9s}")
    for figure in figures:
        print(f"{figure['name'][:78]:78s} {figure['value']:12.4g} {figure['baseline']:12.4g} "
              f"{figure['ratio']:9.4g}  {figure['unit']}")
    print(f"\nsolve_ivp from rest needs {periods_needed} mesh periods to reach the periodic orbit to {TOLERANCE:g} "
          f"(Floquet multipliers {np.abs(orbit.multipliers)[0]:.3g}); periodic target < 100 μs and >= 1000x: "
          f"{result['periodic_meets_target']}")
    print(f"whole operating point {whole_ms:.2f} ms (target < 1 ms: {result['operating_point_meets_target']}); "
          "stages [ms]:")
    for name, value in stages.items():
        print(f"  {name:40s} {value * 1e3:8.3f}")
    print(f"same chain sampling the orbit once per interval: {coarse_ms:.2f} ms (Kv {kv_coarse:.6f} vs {kv_fine:.6f})")
    print(f"sweep fast path: {batch_ms * 1e3:.1f} μs per point after one group_tables call of {tables_ms:.1f} ms")
    return result


if __name__ == "__main__":
    main(quick="--quick" in sys.argv[1:])
