"""Benchmark: a nonlinear-mesh branch study on threads against the same study in the calling thread.

Run: python benchmarks/bench_branch_threads.py [--quick]
Prints a table and writes benchmarks/results/bench_branch_threads.json.

``branch_study`` runs one task per combination of the parameters other than speed (a branch pair up and down)
and, with ``multistart``, one per point and model; the tasks run on a pool of threads, and the backlash
integrator (``integrate_periods``, numba ``nogil``) releases Python's GIL. Figures, each a ratio measured in this
run (the development machine is shared: its wall clock moves with others' load, so each pair of runs is taken
back to back and the ratio of the pair is reported, with the CPU time of the process beside it):

1. the integrator alone: 200-period run-ins of the luo2019 backlash problem (131 μm, 9000 rpm, constant torque)
   from 8 states, on 2 threads against 1 — the ceiling of what threads can give on this machine;
2. the branch study fzg_type_c, torque_nm = 100, 150, 200, 250 × 41 speeds from 8000 to 24000 rpm, elastic model,
   up and down: ``workers=2`` against ``workers=1``;
3. the multi-start search on luo2019 (131 μm) at 9000 and 13 000 rpm, 32 starts: ``workers=2`` against 1.

Ratios above 1: the threads are faster. CPU ratio about 1: the threads add no work.
"""

from __future__ import annotations

import json
import sys
import time
import warnings
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

import numpy as np

RESULTS = Path(__file__).resolve().parent / "results"


def _clock(function) -> tuple[float, float]:
    wall, cpu = time.perf_counter(), time.process_time()
    function()
    return time.perf_counter() - wall, time.process_time() - cpu


def _pairs(serial, threaded, repeat: int) -> dict:
    serial(), threaded()  # warm-up: compilation, caches
    walls, cpus = [], []
    for _ in range(repeat):
        one, two = _clock(serial), _clock(threaded)
        walls.append(one[0] / two[0])
        cpus.append(two[1] / one[1])
    return {"wall_ratio_median": float(np.median(walls)), "wall_ratio_range": [float(min(walls)), float(max(walls))],
            "cpu_threads_over_serial_median": float(np.median(cpus))}


def main(quick: bool = False) -> dict:
    warnings.simplefilter("ignore")
    from thermogear.case import load_case
    from thermogear.dynamics.backlash.backlash_periodic import backlash_flow
    from thermogear.mesh.model import MeshModel
    from thermogear.sweep import Study, branch_study

    repeat = 2 if quick else 3
    luo = load_case("luo2019").with_changes(**{"dynamics.mesh": "nonlinear", "gears.backlash_normal_um": 131.0})
    point = Study.define(luo, {"speed_rpm": [9000.0]}, model="elastic").case_at((9000.0,))
    problem = MeshModel(point, "elastic").state().backlash_problem(point.dynamics.damping_in_flight)
    states = [(problem.backlash * (k / 4.0 - 1.0), 0.0) for k in range(8)]

    def run_in(state):
        return backlash_flow(problem, state, 200)

    def kernel_serial():
        for state in states:
            run_in(state)

    def kernel_threads():
        with ThreadPoolExecutor(2) as pool:
            list(pool.map(run_in, states))

    results = {"kernel_2_threads": _pairs(kernel_serial, kernel_threads, repeat)}
    grid = Study.define(load_case("fzg_type_c"), {"torque_nm": [100.0, 150.0, 200.0, 250.0],
                                                  "speed_rpm": "8000:24000:41"}, model="elastic")
    results["branch_study_2_workers"] = _pairs(lambda: branch_study(grid, workers=1),
                                               lambda: branch_study(grid, workers=2), repeat)
    search = Study.define(luo, {"speed_rpm": [9000.0, 13000.0]}, model="elastic")
    results["multistart_2_workers"] = _pairs(lambda: branch_study(search, workers=1, multistart=32),
                                             lambda: branch_study(search, workers=2, multistart=32), 1 if quick else 2)
    RESULTS.mkdir(exist_ok=True)
    (RESULTS / "bench_branch_threads.json").write_text(json.dumps(results, indent=2))
    print("| figure | 2 threads vs 1, wall (median, range) | CPU threads / serial |")
    print("|---|---:|---:|")
    for name, value in results.items():
        low, high = value["wall_ratio_range"]
        print(f"| {name} | {value['wall_ratio_median']:.2f} ({low:.2f}–{high:.2f}) | "
              f"{value['cpu_threads_over_serial_median']:.2f} |")
    return results


if __name__ == "__main__":
    main(quick="--quick" in sys.argv)
