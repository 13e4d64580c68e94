"""Benchmark: sweep throughput in operating points per second per core, against baselines in the same run.

Run: python benchmarks/bench_sweep.py [--quick]
Prints a table and writes benchmarks/results/bench_sweep.json.

Figures (an "operating point" is one speed of one model, elastic or thermal, of luo2019 at its torque, on the
periodic (Floquet) solver with the case's 1024 intervals per mesh period and the full metrics):

1. batch fast path (one process) vs a plain loop of one ``Simulation(case, model).run("periodic")`` per point;
2. the whole study machinery (Study → the local default, threads on all cores → zarr store, progress off) vs
   the same study run serially in this process (``scheduler="serial"``): points per second per core for both;
   beside it a local Dask cluster of worker processes, started by the run and already warm.
"""

from __future__ import annotations

import json
import os
import platform
import shutil
import sys
import tempfile
import time
import warnings
from pathlib import Path

import numpy as np

RESULTS = Path(__file__).resolve().parent / "results"


def _best(function, repeat: int) -> float:
    times = []
    for _ in range(repeat):
        start = time.perf_counter()
        function()
        times.append(time.perf_counter() - start)
    return min(times)


def main(quick: bool = False) -> dict:
    warnings.simplefilter("ignore")
    from thermogear.case import load_case
    from thermogear.sweep import Study, run_study
    from thermogear.mesh.model import MeshModel
    from thermogear.sweep.batch import evaluate_point, evaluate_speeds, group_tables

    case = load_case("luo2019")
    case = case.with_changes(**{"operating.power_kw": None,
                                "operating.torque_nm": float(case.operating_point.torque)})
    cores = os.cpu_count() or 1
    figures = []

    # 1. batch fast path vs one Simulation per point, one process, fixed geometry
    speeds = np.linspace(500.0, 12000.0, 400 if quick else 2000)
    tables = {model: group_tables(MeshModel(case, model)) for model in ("elastic", "thermal")}
    evaluate_speeds(tables["thermal"], speeds[:4])  # compile
    batch_time = _best(lambda: [evaluate_speeds(tables[m], speeds) for m in tables], 3)
    batch_rate = 2 * speeds.size / batch_time
    loop_speeds = speeds[:: max(speeds.size // (20 if quick else 60), 1)]
    cases = [case.with_changes(**{"operating.speed_rpm": float(s)}) for s in loop_speeds]
    evaluate_point(cases[0], "thermal")
    loop_time = _best(lambda: [evaluate_point(c, m) for c in cases for m in tables], 1)
    loop_rate = 2 * len(cases) / loop_time
    figures.append({"name": "sweep fast path (batch periodic) vs one Simulation per point",
                    "value": batch_rate, "baseline": loop_rate, "unit": "points/s/core",
                    "ratio": batch_rate / loop_rate})

    # 2. study machinery: local Dask cluster (all cores) vs serial loop in this process
    grid = "500:12000:600" if quick else "500:12000:2400"
    study = Study.define(load_case("luo2019"), [f"speed_rpm={grid}", "oil_temperature_c=40,60,80,100"],
                         chunk_points=600)
    points = 2 * study.size
    folder = Path(tempfile.mkdtemp(prefix="bench_sweep_"))
    try:
        start = time.perf_counter()
        run_study(study, folder / "serial.zarr", scheduler="serial", progress=False)
        serial_time = time.perf_counter() - start
        start = time.perf_counter()
        local = run_study(study, folder / "local.zarr", progress=False)
        local_time = time.perf_counter() - start
        start = time.perf_counter()
        run_study(study, folder / "processes.zarr", scheduler="processes", progress=False)
        processes_time = time.perf_counter() - start
        serial = run_study(study, folder / "serial.zarr", scheduler="serial", resume=True, progress=False)
        identical = bool(local.dataset.identical(serial.dataset))
        # the same on a cluster that is already running and warm (start-up and first compilation excluded)
        from distributed import LocalCluster

        with LocalCluster(n_workers=cores, threads_per_worker=1, processes=True, dashboard_address=None) as cluster:
            small = Study.define(load_case("luo2019"), ["speed_rpm=500:12000:40", "oil_temperature_c=40,60,80,100"],
                                 chunk_points=10)
            run_study(small, folder / "warm-up.zarr", scheduler=cluster.scheduler_address, progress=False)
            start = time.perf_counter()
            run_study(study, folder / "warm.zarr", scheduler=cluster.scheduler_address, progress=False)
            warm_time = time.perf_counter() - start
    finally:
        shutil.rmtree(folder, ignore_errors=True)
    serial_rate = points / serial_time
    local_rate = points / local_time / cores
    figures.append({"name": f"study on the local default ({cores} threads) vs serial loop, per core",
                    "value": local_rate, "baseline": serial_rate, "unit": "points/s/core",
                    "ratio": local_rate / serial_rate})
    figures.append({"name": f"study on local Dask ({cores} processes, incl. start-up) vs serial loop, per core",
                    "value": points / processes_time / cores, "baseline": serial_rate, "unit": "points/s/core",
                    "ratio": points / processes_time / cores / serial_rate})
    figures.append({"name": f"study on a warm local Dask cluster ({cores} workers) vs serial loop, per core",
                    "value": points / warm_time / cores, "baseline": serial_rate, "unit": "points/s/core",
                    "ratio": points / warm_time / cores / serial_rate})
    figures.append({"name": f"study on the local default ({cores} threads), total", "value": points / local_time,
                    "baseline": serial_rate, "unit": "points/s", "ratio": points / local_time / serial_rate})
    result = {
        "benchmark": "bench_sweep",
        "case": "luo2019 at its 80 kW torque, 1024 intervals per mesh period, the case's 4 samples per interval",
        "figures": figures,
        "batch_points_per_second_per_core": batch_rate,
        "simulation_points_per_second": loop_rate,
        "study_points": points,
        "study_serial_s": serial_time,
        "study_local_dask_s": local_time,
        "study_warm_local_dask_s": warm_time,
        "local_equals_serial": identical,
        "cores": cores,
        "target_points_per_second_per_core": 2000.0,
        "meets_target": batch_rate >= 2000.0,
        "python": platform.python_version(),
        "numpy": np.__version__,
        "machine": platform.machine(),
    }
    RESULTS.mkdir(parents=True, exist_ok=True)
    (RESULTS / "bench_sweep.json").write_text(json.dumps(result, indent=2) + "\n", encoding="utf-8")
    print(f"{'figure':70s} {'value':>12s} {'baseline':>12s} {'ratio':>8s}")
    for figure in figures:
        print(f"{figure['name'][:70]:70s} {figure['value']:12.1f} {figure['baseline']:12.1f} "
              f"{figure['ratio']:8.2f}  {figure['unit']}")
    print(f"local Dask dataset identical to the serial one: {identical}")
    return result


if __name__ == "__main__":
    main(quick="--quick" in sys.argv[1:])
