"""Benchmark: the interference (Campbell) diagram of a geared drivetrain over 100 pinion speeds, against the route
before (the full damped, spinning eigen-solve of every DOF at every speed and at every trial speed of the crossings'
root search, modes by rank), in the same run, on one BLAS thread.

Run: python benchmarks/bench_campbell.py [--quick]
Prints a table and writes benchmarks/results/bench_campbell.json.

Per drivetrain (the built-in ``fzg_rig_type_c`` set, 108 DOF, and the two-shaft case of the tests, 144 DOF):

1. ``campbell_diagram`` (basis fixed at rest: the undamped modes up to 1.5× the highest mode drawn plus the
   quasi-static vectors of the damping and gyroscopic forces; one small eigen-solve per speed, modes followed by
   MAC): wall and CPU seconds for 100 speeds (12 modes, harmonics 1–3), the best of three.
2. the route before, on the same speeds: ``drivetrain_modes(damped=True)`` (every DOF, labels and energy shares) at
   every speed, and at every trial speed of Brent's method per crossing (modes by rank).
3. the accuracy: each frequency of the new route against the nearest of the full eigen-solve at every speed
   (relative), and the crossing speeds against those of the full basis (``basis_cutoff_hz = math.inf``).

The issue's target: 100 speeds in 2 s or less. The machine these numbers come from may be loaded: CPU time
(user + sys of this process) is printed beside wall.
"""

from __future__ import annotations

import os

for _name in ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_name, "1")  # one core; oversubscribed BLAS threads only contend on small matrices

import json  # noqa: E402
import math  # noqa: E402
import platform  # noqa: E402
import sys  # noqa: E402
import time  # noqa: E402
import warnings  # noqa: E402
from pathlib import Path  # noqa: E402

import numpy as np  # noqa: E402

RESULTS = Path(__file__).resolve().parent / "results"
ROOT = Path(__file__).resolve().parents[1]
SPEEDS = 100
MODES = 12
HARMONICS = (1, 2, 3)


def _timed(function):
    """(result, wall s, CPU s) of one call."""
    wall, cpu = time.perf_counter(), time.process_time()
    result = function()
    return result, time.perf_counter() - wall, time.process_time() - cpu


def previous_route(assembled, speeds: np.ndarray, teeth: int) -> list[float]:
    """The crossing speeds [rpm] by the route before: every DOF's damped modes at each speed and at each trial speed
    of Brent's method, the i-th mode by rank."""
    from scipy.optimize import brentq

    from thermogear.drivetrain.modes import drivetrain_modes

    cache: dict[float, np.ndarray] = {}

    def frequencies(speed: float) -> np.ndarray:
        if speed not in cache:
            cache[speed] = drivetrain_modes(assembled, speed=speed * math.pi / 30.0, damped=True,
                                            count=MODES).frequencies_hz
        return cache[speed]

    table = np.array([frequencies(float(speed)) for speed in speeds])
    found = []
    for harmonic in HARMONICS:
        for mode in range(table.shape[1]):
            gap = table[:, mode] - harmonic * teeth * speeds / 60.0
            for index in np.flatnonzero(np.sign(gap[:-1]) * np.sign(gap[1:]) < 0):
                found.append(brentq(lambda n, m=mode, j=harmonic: frequencies(float(n))[m] - j * teeth * n / 60.0,
                                    speeds[index], speeds[index + 1], xtol=1e-9 * speeds[-1], rtol=1e-12))
    return sorted(found)


def _drivetrains():
    from thermogear.case import load_case
    from thermogear.drivetrain.case_model import case_drivetrain

    for name, source, top in (("fzg_rig_type_c", "fzg_rig_type_c", 15000.0),
                              ("two_shaft", str(ROOT / "tests" / "data" / "two_shaft_drivetrain.toml"), 20000.0)):
        built = case_drivetrain(load_case(source), ("elastic",))
        yield name, built.assembled("elastic"), built.teeth, top


def main(quick: bool) -> dict:
    from thermogear.drivetrain.campbell import campbell_diagram
    from thermogear.drivetrain.modes import drivetrain_modes

    results = {"python": platform.python_version(), "machine": platform.machine(), "speeds": SPEEDS,
               "modes": MODES, "harmonics": list(HARMONICS), "drivetrains": {}, "figures": []}
    for name, assembled, teeth, top in _drivetrains():
        speeds = np.linspace(0.0, top, 20 if quick else SPEEDS)
        runs = [_timed(lambda: campbell_diagram(assembled, speeds, teeth, HARMONICS, MODES))
                for _ in range(1 if quick else 3)]
        diagram, wall, cpu = min(runs, key=lambda run: run[2])
        before, before_wall, before_cpu = _timed(lambda: previous_route(assembled, speeds, teeth))
        full = campbell_diagram(assembled, speeds, teeth, HARMONICS, MODES, basis_cutoff_hz=math.inf)
        error = 0.0
        for index in range(0, speeds.size, max(1, speeds.size // 10)):
            exact = drivetrain_modes(assembled, speed=speeds[index] * math.pi / 30.0, damped=True,
                                     count=3 * MODES).frequencies_hz
            found = diagram.frequencies_hz[index]
            error = max(error, float((np.min(np.abs(found[:, None] - exact[None, :]), axis=1) / found).max()))
        mine = np.array([c.speed_rpm for c in diagram.crossings])
        theirs = np.array([c.speed_rpm for c in full.crossings])
        crossing_error = (float(np.max(np.abs(np.sort(mine) - np.sort(theirs)) / np.sort(theirs)))
                          if mine.size == theirs.size else None)
        results["drivetrains"][name] = {
            "dof": assembled.size, "basis": diagram.basis_size, "speeds": int(speeds.size),
            "crossings": len(diagram.crossings), "crossings_previous_route": len(before),
            "new_wall_s": wall, "new_cpu_s": cpu, "previous_wall_s": before_wall, "previous_cpu_s": before_cpu,
            "speedup_cpu_ratio": before_cpu / cpu, "speedup_wall_ratio": before_wall / wall,
            "frequency_error_relative": error, "crossing_error_relative": crossing_error}
        row = results["drivetrains"][name]
        results["figures"].append({"name": f"{name}: {speeds.size} speeds, CPU", "value": cpu, "baseline": before_cpu,
                                   "ratio": before_cpu / cpu, "unit": "s"})
        print(f"{name}: {assembled.size} DOF, basis {diagram.basis_size}, {speeds.size} speeds, "
              f"{len(diagram.crossings)} crossings ({len(before)} by the route before)")
        print(f"  new: {wall:.3f} s wall, {cpu:.3f} s CPU; before: {before_wall:.2f} s wall, {before_cpu:.2f} s CPU;"
              f" speed-up {row['speedup_cpu_ratio']:.1f}x CPU, {row['speedup_wall_ratio']:.1f}x wall")
        print(f"  frequencies within {error:.2e} of the full solve; crossings within {crossing_error} of the full "
              "basis")
    return results


if __name__ == "__main__":
    warnings.simplefilter("ignore")
    quick = "--quick" in sys.argv[1:]
    output = main(quick)
    if not quick:
        RESULTS.mkdir(exist_ok=True)
        (RESULTS / "bench_campbell.json").write_text(json.dumps(output, indent=1), encoding="utf-8")
