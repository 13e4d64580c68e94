"""Benchmark: parameter-study throughput a user gets from the command line (issue #12, item 3).

Run: python benchmarks/bench_sweep_cli.py [--quick] [--million]
Prints a table and writes benchmarks/results/bench_sweep_cli.json.

Every figure runs the real command line in a subprocess,

    thermogear sweep luo2019 --vary torque_nm=200:400:T --vary speed_rpm=1000:10000:S --out X.zarr --json

with the store written, the default ``--model both`` (a grid point is both models) and the default chunking, and
takes the command's own ``seconds`` (store creation, computing, writing; the summary it prints reads the store with
zarr after its clock stops) beside the wall time of the process (interpreter start-up, imports and the summary
included). Peak resident memory comes from ``/usr/bin/time -v`` where it exists (else the children's
``ru_maxrss``); for Dask runs it is the driver's only.

Figures (targets of the issue in brackets):

1. serial (``--scheduler serial``) on a 10⁵-point speed × torque grid [>= 10 000 points/s on one core];
2. the local default with two workers (``--workers 2``: two threads, the study runs on the fast path) on the
   same grid vs 1. [>= 1.6×]; beside it a local Dask cluster of two worker processes (``--scheduler processes``);
   the three runs are repeated ``REPEATS`` times, interleaved, on a machine shared with other work: the figures
   are the median runs, the unit column adds the median and range of the paired ratios (serial and threads run
   one after the other, so a slow spell of the machine hits both), and the JSON keeps every run;
3. the fast path (1.) vs one Simulation per point (``--method simulation``, serial, on a small grid of the same
   study: it runs at ~10² points/s, so 10⁵ points would take a quarter of an hour) [>= 10×];
4. peak memory at 10⁴, 10⁵ (and 10⁶ points with ``--million``, a few minutes) [flat];
5. the machine's own two-thread ceiling, measured beside each repeat of 2. (``parallel_ceiling.py``): the sweep's
   compiled kernel alone (no Python between points) and a pure arithmetic loop, each on two threads vs one. On a
   shared virtual machine two virtual cores do not give twice one, so the study's ratio is also given as a
   fraction of the kernel's ratio measured in the same minute (its parallel efficiency on this machine);
6. the fixed cost of one study and the two-thread ratio per point: each repeat also runs a 10⁴-point grid on
   both schedulers, and ``seconds = fixed + points × per point`` through the two sizes separates what a study
   costs however small (run once, on one thread: numba's first-use set-up, the store's creation, the last
   block) from what scales with the points. The ratio at 10⁵ points lies between the per-point ratio and 1, the
   nearer the ratio the larger the study;
7. the CPU time (user + system) of the whole command, two threads vs serial, paired per repeat: near 1, the two
   threads do the serial run's work and no more, so what keeps the wall-clock ratio from 2 is the part of a study
   that runs on one thread (6.) and how much of two cores the machine gives (5.), not work added by the threads.

``--quick`` runs a 2·10⁴-point grid instead of 10⁵ (a smoke test of the script, not the issue's figures).
"""

from __future__ import annotations

import json
import math
import os
import platform
import re
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent
REPEATS = 5
SMALL_TORQUES = 10  # the 10⁴-point grid (x 1000 speeds) beside the main one: fixed cost vs cost per point
RESULTS = HERE / "results"
TIME = Path("/usr/bin/time")


def run_cli(out: Path, torques: int, speeds: int, *extra: str) -> dict:
    """Run one study through the command line; returns its JSON summary plus wall time and peak memory."""
    command = [sys.executable, "-m", "thermogear", "sweep", "luo2019", "--vary", f"torque_nm=200:400:{torques}",
               "--vary", f"speed_rpm=1000:10000:{speeds}", "--out", str(out), "--json", *extra]
    timed = [str(TIME), "-v", *command] if TIME.exists() else command
    before = _children_usage()
    start = time.perf_counter()
    completed = subprocess.run(timed, capture_output=True, text=True, cwd=HERE.parent)
    wall = time.perf_counter() - start
    after = _children_usage()  # the finished (waited-for) command's CPU time is added to its parent's record
    cpu = after[0] - before[0]
    if completed.returncode != 0:
        raise RuntimeError(f"{' '.join(command)} failed ({completed.returncode}):\n{completed.stderr[-3000:]}")
    summary = json.loads(completed.stdout[completed.stdout.index("{"):])
    match = re.search(r"Maximum resident set size \(kbytes\): (\d+)", completed.stderr)
    if match:
        peak_mb = int(match.group(1)) / 1024.0
    else:
        peak_mb = after[1] / 1024.0  # max over children so far
    shutil.rmtree(out, ignore_errors=True)
    points = int(summary["points"])
    return {"points": points, "seconds": float(summary["seconds"]), "wall_s": wall, "cpu_s": cpu,
            "peak_rss_mb": peak_mb,
            "points_per_second": points / float(summary["seconds"]), "chunks": int(summary["chunks"]),
            "valid_points": summary.get("valid_points"), "arguments": " ".join(extra)}


def _children_usage() -> tuple[float, float]:
    """CPU seconds (user + system) of this process's finished children so far, and their largest resident set
    [kB]; NaN where the platform has no ``resource`` module."""
    try:
        import resource
    except ImportError:  # not on Windows
        return math.nan, math.nan
    usage = resource.getrusage(resource.RUSAGE_CHILDREN)
    return usage.ru_utime + usage.ru_stime, float(usage.ru_maxrss)


def run_ceiling() -> dict:
    """The machine's two-thread ceiling now (``parallel_ceiling.py`` in a subprocess, about 8 s)."""
    completed = subprocess.run([sys.executable, str(HERE / "parallel_ceiling.py"), "--work", "1.5"],
                               capture_output=True, text=True, cwd=HERE.parent, check=True)
    return json.loads(completed.stdout)


def _fixed_and_per_point(runs: dict, repeat: int) -> dict[str, tuple[float, float]]:
    """Per scheduler, (fixed seconds, seconds per point) of ``seconds = fixed + points·per_point`` through the
    small and the main run of one repeat (the same minutes): the fixed part is what a study costs however small
    (numba's first-use set-up, creating the store, opening the result, the last block's tail), and it runs on one
    thread whatever the scheduler."""
    split = {}
    for scheduler, name in (("serial", "serial"), ("threads", "workers_2")):
        small, main = runs[f"{name}_small_{repeat}"], runs[f"{name}_main_{repeat}"]
        per_point = (main["seconds"] - small["seconds"]) / (main["points"] - small["points"])
        split[scheduler] = (small["seconds"] - small["points"] * per_point, per_point)
    return split


def _median_run(runs: list[dict]) -> dict:
    """The run of median time among repeated runs of one command."""
    return sorted(runs, key=lambda run: run["seconds"])[len(runs) // 2]


def main(quick: bool = False, million: bool = False) -> dict:
    folder = Path(tempfile.mkdtemp(prefix="bench_sweep_cli_"))
    torques = 20 if quick else 100
    runs: dict[str, dict] = {}
    ceilings: list[dict] = []
    try:
        run_cli(folder / "warm.zarr", 2, 10, "--scheduler", "serial")  # numba's cache and the OS file cache
        for repeat in range(REPEATS):  # interleaved, so that a slow spell of the machine hits all of them
            runs[f"serial_main_{repeat}"] = run_cli(folder / "b.zarr", torques, 1000, "--scheduler", "serial")
            runs[f"workers_2_main_{repeat}"] = run_cli(folder / "c.zarr", torques, 1000, "--workers", "2")
            runs[f"serial_small_{repeat}"] = run_cli(folder / "a.zarr", SMALL_TORQUES, 1000, "--scheduler", "serial")
            runs[f"workers_2_small_{repeat}"] = run_cli(folder / "a.zarr", SMALL_TORQUES, 1000, "--workers", "2")
            runs[f"processes_2_main_{repeat}"] = run_cli(folder / "c.zarr", torques, 1000, "--scheduler",
                                                         "processes", "--workers", "2")
            ceilings.append(run_ceiling())
        for name in ("serial_main", "workers_2_main", "processes_2_main", "serial_small", "workers_2_small"):
            runs[name] = _median_run([runs[f"{name}_{repeat}"] for repeat in range(REPEATS)])
        runs["simulation_small"] = run_cli(folder / "d.zarr", 2, 20, "--scheduler", "serial", "--method",
                                           "simulation")
        runs["batch_small"] = run_cli(folder / "e.zarr", 2, 20, "--scheduler", "serial")
        if million:
            runs["serial_1e6"] = run_cli(folder / "f.zarr", 1000, 1000, "--scheduler", "serial")
            runs["workers_2_1e6"] = run_cli(folder / "g.zarr", 1000, 1000, "--workers", "2")
    finally:
        shutil.rmtree(folder, ignore_errors=True)
    serial, workers, processes = runs["serial_main"], runs["workers_2_main"], runs["processes_2_main"]
    paired = sorted(runs[f"serial_main_{repeat}"]["seconds"] / runs[f"workers_2_main_{repeat}"]["seconds"]
                    for repeat in range(REPEATS))
    simulation = runs["simulation_small"]
    size = serial["points"]
    serial_rates = sorted(runs[f"serial_main_{repeat}"]["points_per_second"] for repeat in range(REPEATS))
    kernel = sorted(ceiling["kernel"]["ratio"] for ceiling in ceilings)
    arithmetic = sorted(ceiling["arithmetic"]["ratio"] for ceiling in ceilings)
    efficiency = sorted(runs[f"serial_main_{repeat}"]["seconds"] / runs[f"workers_2_main_{repeat}"]["seconds"]
                        / ceilings[repeat]["kernel"]["ratio"] for repeat in range(REPEATS))
    split = [_fixed_and_per_point(runs, repeat) for repeat in range(REPEATS)]
    fixed_serial = sorted(item["serial"][0] for item in split)
    fixed_threads = sorted(item["threads"][0] for item in split)
    per_point = sorted(item["serial"][1] / item["threads"][1] for item in split)
    cpu = sorted(runs[f"workers_2_main_{repeat}"]["cpu_s"] / runs[f"serial_main_{repeat}"]["cpu_s"]
                 for repeat in range(REPEATS))
    middle = REPEATS // 2
    figures = [
        {"name": f"CLI serial, {size:,} points (speed x torque, both models)", "value": serial["points_per_second"],
         "baseline": 10_000.0, "ratio": serial["points_per_second"] / 10_000.0,
         "unit": f"points/s (target 10 000; the {REPEATS} runs {serial_rates[0]:,.0f}-{serial_rates[-1]:,.0f})"},
        {"name": f"CLI local default, 2 workers (threads) vs serial, {size:,} points",
         "value": workers["points_per_second"], "baseline": serial["points_per_second"],
         "ratio": workers["points_per_second"] / serial["points_per_second"],
         "unit": f"points/s (ratio of the median runs; target 1.6; median of the {REPEATS} paired ratios "
                 f"{paired[len(paired) // 2]:.2f}, range {paired[0]:.2f}-{paired[-1]:.2f})"},
        {"name": "this machine: the sweep kernel alone on 2 threads vs 1 (no Python; beside each pair above)",
         "value": kernel[len(kernel) // 2], "baseline": 1.0, "ratio": kernel[len(kernel) // 2],
         "unit": f"x (median; {kernel[0]:.2f}-{kernel[-1]:.2f}; arithmetic loop {arithmetic[0]:.2f}-"
                 f"{arithmetic[-1]:.2f})"},
        {"name": "CLI 2 threads vs serial as a fraction of the kernel alone on 2 threads (same minute)",
         "value": efficiency[len(efficiency) // 2], "baseline": 1.0, "ratio": efficiency[len(efficiency) // 2],
         "unit": f"(median of pairs; {efficiency[0]:.2f}-{efficiency[-1]:.2f})"},
        {"name": "CLI 2 threads vs serial, per point (fixed cost of a study taken out: 10^4 and 10^5 runs)",
         "value": per_point[middle], "baseline": 1.0, "ratio": per_point[middle],
         "unit": f"x (median of the {REPEATS} repeats; {per_point[0]:.2f}-{per_point[-1]:.2f})"},
        {"name": "CLI fixed cost of one study (seconds at 0 points): serial; baseline 2 threads",
         "value": fixed_serial[middle], "baseline": fixed_threads[middle],
         "ratio": fixed_serial[middle] / fixed_threads[middle],
         "unit": f"s (serial {fixed_serial[0]:.2f}-{fixed_serial[-1]:.2f}, threads {fixed_threads[0]:.2f}-"
                 f"{fixed_threads[-1]:.2f})"},
        {"name": f"CLI 2 threads vs serial, CPU time of the whole command (user + system), {size:,} points",
         "value": cpu[middle], "baseline": 1.0, "ratio": cpu[middle],
         "unit": f"x (median of the {REPEATS} pairs; {cpu[0]:.2f}-{cpu[-1]:.2f}; 1: two threads spend the CPU "
                 "time of one)"},
        {"name": f"CLI local Dask cluster, 2 worker processes vs serial, {size:,} points",
         "value": processes["points_per_second"], "baseline": serial["points_per_second"],
         "ratio": processes["points_per_second"] / serial["points_per_second"], "unit": "points/s"},
        {"name": "CLI fast path (serial, above) vs --method simulation (serial, 40 points)",
         "value": serial["points_per_second"], "baseline": simulation["points_per_second"],
         "ratio": serial["points_per_second"] / simulation["points_per_second"], "unit": "points/s (target ratio 10)"},
        {"name": "CLI fast path vs --method simulation on the same 40 points (fixed costs included)",
         "value": runs["batch_small"]["points_per_second"], "baseline": simulation["points_per_second"],
         "ratio": runs["batch_small"]["points_per_second"] / simulation["points_per_second"], "unit": "points/s"},
        {"name": f"CLI serial peak memory, {size:,} vs 10,000 points", "value": serial["peak_rss_mb"],
         "baseline": runs["serial_small"]["peak_rss_mb"],
         "ratio": serial["peak_rss_mb"] / runs["serial_small"]["peak_rss_mb"], "unit": "MB"},
    ]
    if million:
        big, big_workers = runs["serial_1e6"], runs["workers_2_1e6"]
        figures.append({"name": "CLI local default, 2 workers (threads) vs serial, 1,000,000 points",
                        "value": big_workers["points_per_second"], "baseline": big["points_per_second"],
                        "ratio": big_workers["points_per_second"] / big["points_per_second"],
                        "unit": "points/s (target ratio 1.6)"})
        figures.append({"name": f"CLI serial peak memory, 1,000,000 vs {size:,} points", "value": big["peak_rss_mb"],
                        "baseline": serial["peak_rss_mb"], "ratio": big["peak_rss_mb"] / serial["peak_rss_mb"],
                        "unit": "MB"})
    result = {
        "benchmark": "bench_sweep_cli",
        "case": "luo2019, torque 200-400 N m x speed 1000-10000 rpm, both models, 1024 intervals per mesh period",
        "measured": "the command's own JSON 'seconds' (store written); wall_s adds interpreter start-up",
        "figures": figures,
        "runs": runs,
        "ceilings": ceilings,
        "cores": os.cpu_count(),
        "load_average_at_end": os.getloadavg() if hasattr(os, "getloadavg") else None,
        "quick": quick,
        "python": platform.python_version(),
        "machine": platform.machine(),
    }
    RESULTS.mkdir(parents=True, exist_ok=True)
    (RESULTS / "bench_sweep_cli.json").write_text(json.dumps(result, indent=2) + "\n", encoding="utf-8")
    print(f"{'figure':78s} {'value':>10s} {'baseline':>10s} {'ratio':>7s}")
    for figure in figures:
        print(f"{figure['name'][:78]:78s} {figure['value']:10.1f} {figure['baseline']:10.1f} "
              f"{figure['ratio']:7.2f}  {figure['unit']}")
    for name, run in runs.items():
        if name.endswith(("_main", "_small")):
            continue  # the medians, printed among the repeats
        print(f"  {name:18s} {run['points']:>9,} points {run['seconds']:7.2f} s (wall {run['wall_s']:6.2f} s) "
              f"{run['points_per_second']:9.0f} points/s, peak {run['peak_rss_mb']:6.0f} MB {run['arguments']}")
    return result


if __name__ == "__main__":
    import argparse

    parser = argparse.ArgumentParser(description="Parameter-study throughput through the command line "
                                     "(writes benchmarks/results/bench_sweep_cli.json).")
    parser.add_argument("--quick", action="store_true", help="a 2·10⁴-point grid instead of 10⁵ (a smoke test)")
    parser.add_argument("--million", action="store_true", help="also the 10⁶-point pair (a few minutes more)")
    arguments, _ = parser.parse_known_args()  # run_all.py passes its extra arguments to every benchmark
    main(quick=arguments.quick, million=arguments.million)
