"""Benchmark: the study kinds of issue 34 on two local worker processes against serial, ratios in one run.

Run: python benchmarks/bench_study_kinds.py [--quick] [--repeats=N] [--study=drivetrain|gearbox] [--dask-defaults]
[--grid-size=N]
Prints a table and writes benchmarks/results/bench_study_kinds.json. Options:

* ``--quick``: tiny studies, once, nothing written (a check that it runs);
* ``--study``: that study kind only; the file keeps the other kind's last rows;
* ``--dask-defaults``: the gearbox grid also on two workers with Dask's default background settings (without the
  executor's ``QUIET_LOCAL_CLUSTER``), in the same run;
* ``--grid-size=N``: a grid of N speeds × N torques instead of 100 × 100 (a smaller check; nothing written).

The gearbox grid's ratio alone, once, on an idle machine (about 4 min):
``python benchmarks/bench_study_kinds.py --study=gearbox --repeats=1``.

1. the drivetrain study over speed × one other key (the two-shaft rotor of tests/data at its own resolution, linear
   mesh; 128 speeds × 2 torques, elastic model, 8 speeds per task: 32 tasks; the driver's loading and planning,
   about 5 s in both runs, is then small beside the study: 64 points gave 1.52×, 256 points 1.83×):
   ``thermogear.sweep`` serial and on ``--scheduler processes --workers 2`` [>= 1.6×];
2. the gearbox's steady grid of 10⁴ points (FZG test gearbox of tests/data, 100 speeds × 100 torques, 500 points per
   task: 20 tasks, so that the driver's writes stay small beside the solving): serial and on two worker processes
   [>= 1.6×], and the serial grid through the study executor and its store against the plain loop of
   ``steady_sweep`` (what the command ran before) [not slower].

Each ratio is serial seconds / parallel seconds of whole studies (the local cluster's start-up and the store
included), the pairs run back to back and repeated ``REPEATS`` times; the table gives the median pair. Beside the
seconds, each row gives CPU seconds, which another user's load on the machine changes far less: the serial study's
(``serial_cpu_s``), and for two workers the driver's (this process: scheduler, nannies, client and store writes,
``driver_cpu_s``) and the worker processes' (``workers_cpu_s``, their start included; read from the finished child
processes), and what two workers cost beyond the serial study (``extra_cpu_s``). A local
cluster of two workers is also started and closed alone before each pair (``cluster_start_s``): a study gains
from workers only where its serial time is several times that start-up (a ratio of 1.6 on two workers needs a
serial time of at least 8 start-ups), and ``ratio_less_start`` gives the ratio with it taken out. The load
average of the machine (shared with other work) is recorded beside each pair: on a machine without two free cores
no ratio means anything.
"""

from __future__ import annotations

import json
import os
import shutil
import sys
import tempfile
import time
import warnings
from pathlib import Path

HERE = Path(__file__).resolve().parent
DATA = HERE.parent / "tests" / "data"
RESULTS = HERE / "results"
REPEATS = 3


GRID_CHUNK_POINTS = 500


def _cluster_start() -> float:
    """Seconds to start the studies' local cluster of two single-thread worker processes and close it again."""
    from thermogear.sweep.executor import _client

    start = time.perf_counter()
    with _client("processes", 2, None):
        pass
    return time.perf_counter() - start


def _timed(function) -> float:
    start = time.perf_counter()
    function()
    return time.perf_counter() - start


def _measured(function) -> dict:
    """Seconds, this process's CPU seconds and the CPU seconds of the child processes that ended meanwhile (a local
    cluster's workers are reaped when it closes)."""
    before, start = os.times(), time.perf_counter()
    function()
    seconds, after = time.perf_counter() - start, os.times()
    return {"seconds": seconds, "driver_cpu_s": after.user + after.system - before.user - before.system,
            "workers_cpu_s": (after.children_user + after.children_system - before.children_user
                              - before.children_system)}


def _pair_row(serial: dict, local: dict) -> dict:
    """The seconds and CPU seconds of a serial run and a two-worker run of one study."""
    serial_cpu = serial["driver_cpu_s"] + serial["workers_cpu_s"]
    return {"serial_s": serial["seconds"], "two_workers_s": local["seconds"],
            "ratio": serial["seconds"] / local["seconds"],
            "serial_cpu_s": serial_cpu, "driver_cpu_s": local["driver_cpu_s"], "workers_cpu_s": local["workers_cpu_s"],
            "extra_cpu_s": local["driver_cpu_s"] + local["workers_cpu_s"] - serial_cpu}


def main() -> None:
    import numpy as np

    import thermogear
    from thermogear.case import load_case
    from thermogear.gearbox.case_model import gearbox_model_from_case, gearbox_operating_point
    from thermogear.gearbox.sweep import steady_sweep
    from thermogear.sweep.gearbox_grid import run_gearbox_grid

    quick = "--quick" in sys.argv
    chosen = next((a.split("=")[1] for a in sys.argv if a.startswith("--study=")), None)
    studies = {"drivetrain": "drivetrain speed x torque", "gearbox": "gearbox steady grid"}
    if chosen not in (None, *studies):
        raise SystemExit(f"--study={chosen}: one of {', '.join(studies)}")
    run = {name: chosen in (None, key) for key, name in studies.items()}
    defaults = "--dask-defaults" in sys.argv
    repeats = 1 if quick else next((int(a.split("=")[1]) for a in sys.argv if a.startswith("--repeats=")), REPEATS)
    folder = Path(tempfile.mkdtemp(prefix="bench-study-kinds-"))
    rows: list[dict] = []
    try:
        case = DATA / "two_shaft_drivetrain.toml"
        speeds = "1000:3000:4" if quick else "1000:3000:128"
        vary = {"speed_rpm": speeds, "torque_nm": [100, 150]}
        points = (4 if quick else 128) * 2

        def drivetrain(scheduler: str, workers) -> None:
            out = folder / f"drivetrain-{scheduler}.zarr"
            shutil.rmtree(out, ignore_errors=True)
            thermogear.sweep(str(case), vary=vary, out=out, model="elastic", scheduler=scheduler, workers=workers)

        gearbox_case = load_case(str(DATA / "gearbox" / "fzg_gearbox.toml"))
        model = gearbox_model_from_case(gearbox_case)
        ambient = gearbox_operating_point(gearbox_case.operating_point, gearbox_case.gearbox).ambient_c
        count = next((int(a.split("=")[1]) for a in sys.argv if a.startswith("--grid-size=")), 20 if quick else 100)
        grid_speeds, grid_torques = np.linspace(300.0, 3000.0, count), np.linspace(10.0, 200.0, count)

        def grid(scheduler: str, workers) -> None:
            out = folder / f"grid-{scheduler}.zarr"
            shutil.rmtree(out, ignore_errors=True)
            run_gearbox_grid(model, grid_speeds, grid_torques, ambient, scheduler, workers, out=out,
                             chunk_points=GRID_CHUNK_POINTS, case=gearbox_case)

        def plain_loop() -> None:
            steady_sweep(model, grid_speeds, grid_torques, ambient)

        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            for repeat in range(repeats):
                if run[studies["drivetrain"]]:
                    load = os.getloadavg()[0]
                    cluster = _cluster_start()
                    serial = _measured(lambda: drivetrain("serial", None))
                    local = _measured(lambda: drivetrain("processes", 2))
                    rows.append({"study": studies["drivetrain"], "points": points, "repeat": repeat,
                                 **_pair_row(serial, local), "cluster_start_s": cluster,
                                 "ratio_less_start": serial["seconds"] / max(local["seconds"] - cluster, 1e-9),
                                 "load": load})
                    print(json.dumps(rows[-1]), flush=True)
                if run[studies["gearbox"]]:
                    load = os.getloadavg()[0]
                    cluster = _cluster_start()
                    loop = _timed(plain_loop)
                    serial, local = _measured(lambda: grid("serial", None)), _measured(lambda: grid("processes", 2))
                    rows.append({"study": studies["gearbox"], "points": count * count, "repeat": repeat,
                                 **_pair_row(serial, local), "cluster_start_s": cluster,
                                 "ratio_less_start": serial["seconds"] / max(local["seconds"] - cluster, 1e-9),
                                 "plain_loop_s": loop, "serial_vs_plain_loop": loop / serial["seconds"], "load": load})
                    if defaults:
                        default = _measured(lambda: _with_dask_defaults(lambda: grid("processes", 2)))
                        rows[-1].update({"two_workers_dask_defaults_s": default["seconds"],
                                         "ratio_dask_defaults": serial["seconds"] / default["seconds"],
                                         "extra_cpu_dask_defaults_s": (default["driver_cpu_s"]
                                                                       + default["workers_cpu_s"]
                                                                       - rows[-1]["serial_cpu_s"])})
                    print(json.dumps(rows[-1]), flush=True)
    finally:
        shutil.rmtree(folder, ignore_errors=True)
    summary = {}
    for study in (name for name, chosen_study in run.items() if chosen_study):
        pairs = sorted((row for row in rows if row["study"] == study), key=lambda row: row["ratio"])
        median = pairs[len(pairs) // 2]
        summary[study] = {**median, "ratios": [round(row["ratio"], 3) for row in pairs]}
        extra = (f", serial through the executor vs the plain loop {median['serial_vs_plain_loop']:.2f}x"
                 if "plain_loop_s" in median else "")
        print(f"{study}: {median['points']} points, serial {median['serial_s']:.1f} s "
              f"({median['points'] / median['serial_s']:.0f} points/s), two workers {median['two_workers_s']:.1f} s: "
              f"{median['ratio']:.2f}x (all pairs {summary[study]['ratios']}; cluster start "
              f"{median['cluster_start_s']:.1f} s, ratio without it {median['ratio_less_start']:.2f}x; load "
              f"{median['load']:.1f}){extra}; CPU serial {median['serial_cpu_s']:.1f} s, two workers: driver "
              f"{median['driver_cpu_s']:.1f} s + workers {median['workers_cpu_s']:.1f} s "
              f"({median['extra_cpu_s']:+.1f} s beyond serial)")
        if "ratio_dask_defaults" in median:
            print(f"  with Dask's default background settings: two workers "
                  f"{median['two_workers_dask_defaults_s']:.1f} s, {median['ratio_dask_defaults']:.2f}x, "
                  f"{median['extra_cpu_dask_defaults_s']:+.1f} s of CPU beyond serial")
    if quick or count != 100:  # a check that the benchmark runs, or a smaller grid: not the study's numbers
        return
    RESULTS.mkdir(exist_ok=True)
    path = RESULTS / "bench_study_kinds.json"
    if path.exists() and chosen is not None:  # one study measured: keep the other's last rows
        kept = json.loads(path.read_text(encoding="utf-8"))
        rows = [row for row in kept.get("rows", []) if row["study"] not in summary] + rows
        summary = {**{name: value for name, value in kept.get("summary", {}).items() if name not in summary},
                   **summary}
    path.write_text(json.dumps({"rows": rows, "summary": summary}, indent=1), encoding="utf-8")


def _with_dask_defaults(function) -> None:
    """``function()`` with the study's local cluster at Dask's default background settings (the comparison of
    ``--dask-defaults``)."""
    from thermogear.sweep import executor

    quiet = executor.QUIET_LOCAL_CLUSTER
    executor.QUIET_LOCAL_CLUSTER = {}
    try:
        function()
    finally:
        executor.QUIET_LOCAL_CLUSTER = quiet


if __name__ == "__main__":
    main()
