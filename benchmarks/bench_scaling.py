"""Benchmark: cost per speed of the exact drivetrain solvers against the size of the rotor (issue 38), with the
project's own Newmark integrator on the same systems as the baseline, in one run, on one BLAS thread.

Run: python benchmarks/bench_scaling.py [--quick] [--full] [--every-dof]
Prints a table and writes benchmarks/results/bench_scaling.json (``--every-dof``: only the 492-DOF every-DOF
figures against the route before, one and two threads, one run and within a sweep, and the 1000-interval table:
benchmarks/results/bench_scaling_every_dof.json).

The rotor (``large_rotor.py``): two steel shafts of E Timoshenko elements each, gears at mid-span, four bearings,
a square-wave mesh stiffness (two pieces per mesh period), 3000 rpm (f_m = 1 kHz). E = 4, 40, 166 give 60, 492
and 2004 DOF. Per size:

1. the linear periodic response on the automatic cut-off (harmonics up to 5: f_c = 20 kHz), per speed in a sweep
   of ``SPEEDS`` speeds (2000–4000 rpm) that shares the modal basis and the reduced matrices
   (``drivetrain_cutoff_sweep``), without and with the per-run error estimate (issue 36: the modes above f_c
   driven by the response's own loads; before, a second solve on 2·f_c), and the estimate itself;
2. the backlash orbit (normal backlash 100 um) on the same cut-off, per speed (``drivetrain_backlash_response``);
3. the linear periodic response on every DOF (60 and 492 DOF; 2004 with ``--full``: about 30 exponentials of
   6700-square matrices), and on 492 DOF the route before issue 38 (every coordinate, blocks of pieces, the
   batched Taylor exponentials) in the same run;
4. Newmark (average acceleration, 32 steps per piece, ``dynamics/transients/newmark.py``) from rest to a 1 % steady
state
   (two period ends within 1 %) on the same system with every DOF, and its distance from the exact orbit (the
   exact every-DOF orbit where it was computed, else the cut-off solution); on 492 DOF also Newmark on the
   cut-off's own reduced system, its steady-state tolerance and then its steps per piece tightened
   (``NEWMARK_SETTINGS``) until its orbit is within 1 % of the exact one (equal accuracy), against the cut-off path;
5. on 492 DOF the same square wave as a 1000-interval table, clean and with a 3e-13 scatter, every DOF, interleaved.

Times are CPU seconds of this process (user + sys) with one BLAS thread: the development machine is shared and
its wall times follow its load, the CPU times much less.
"""

from __future__ import annotations

import os

for _name in ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_name, "1")

import contextlib  # noqa: E402
import json  # noqa: E402
import platform  # noqa: E402
import sys  # noqa: E402
import time  # noqa: E402
import warnings  # noqa: E402
from dataclasses import replace  # noqa: E402
from pathlib import Path  # noqa: E402

import numpy as np  # noqa: E402

sys.path.insert(0, str(Path(__file__).resolve().parent))
from large_rotor import rotor, square_wave  # noqa: E402

RESULTS = Path(__file__).resolve().parent / "results"
SIZES = (4, 40, 166)  # elements per shaft: 60, 492, 2004 DOF
SPEEDS = 16
HARMONICS = 5
NEWMARK_STEPS = 32


def cpu(function, repeat: int = 1):
    """(median CPU seconds, last result) of ``repeat`` calls."""
    times, result = [], None
    for _ in range(repeat):
        start = time.process_time()
        result = function()
        times.append(time.process_time() - start)
    return float(np.median(times)), result


@contextlib.contextmanager
def route_before_issue_38():
    """Every coordinate, √N blocks of pieces and the batched Taylor exponentials, as before issue 38."""
    import thermogear.dynamics.periodic_orbits.periodic_ndof as periodic_ndof

    saved = (periodic_ndof.RUN_ROUTE_SIZE, periodic_ndof._SINGLE_ROUTE_SIZE, periodic_ndof.reached_coordinates)
    periodic_ndof.RUN_ROUTE_SIZE = periodic_ndof._SINGLE_ROUTE_SIZE = sys.maxsize
    periodic_ndof.reached_coordinates = lambda system: np.ones(system.size, dtype=bool)
    try:
        yield
    finally:
        periodic_ndof.RUN_ROUTE_SIZE, periodic_ndof._SINGLE_ROUTE_SIZE, periodic_ndof.reached_coordinates = saved


@contextlib.contextmanager
def route_before_this_turn():
    """The every-DOF route as it stood before its second turn on issue 38 (commit 98809ca): each large piece's
    exponential by itself (scipy's Padé 13), the monodromy formed and its eigenvalues taken densely."""
    from scipy.linalg import expm

    import thermogear.dynamics.linear_algebra.monodromy_range as monodromy_range
    import thermogear.dynamics.periodic_orbits.periodic_ndof as periodic_ndof

    def separate(system, units, durations, inverse, full_range, powers=False):
        return np.stack([expm(matrix * duration) for matrix, duration in zip(units, durations)])

    saved = (monodromy_range.LARGEST_RANK_SHARE, periodic_ndof._large_pieces)
    monodromy_range.LARGEST_RANK_SHARE = 0.0
    periodic_ndof._large_pieces = separate
    try:
        yield
    finally:
        monodromy_range.LARGEST_RANK_SHARE, periodic_ndof._large_pieces = saved


def _timed(function, threads: int) -> tuple[float, float, object]:
    """(CPU seconds, wall seconds, result) of one call with BLAS on ``threads`` threads."""
    from threadpoolctl import threadpool_limits

    with threadpool_limits(limits=threads, user_api="blas"):
        start, wall = time.process_time(), time.perf_counter()
        result = function()
        return time.process_time() - start, time.perf_counter() - wall, result


def every_dof_figures(repeat: int = 5, sweep_speeds: int = 4) -> dict:
    """The 492-DOF rotor on every DOF, this route against the one before (:func:`route_before_this_turn`), in
    the same process and interleaved (``repeat`` rounds, medians): one ``run`` (one speed) on one and on two BLAS
    threads, and per speed within a sweep of ``sweep_speeds`` speeds (``drivetrain_speed_sweep``, which shares
    the rigid-body reduction); with the largest difference of the two routes' DTE (over its peak-to-peak) and
    Floquet multipliers (moduli, sorted)."""
    from thermogear.drivetrain.response import drivetrain_periodic_response, drivetrain_speed_sweep

    assembled = rotor(40).assemble()
    state = square_wave(3000.0)
    states = [square_wave(float(speed)) for speed in np.linspace(2500.0, 3500.0, sweep_speeds)]
    routes = {"after": contextlib.nullcontext, "before": route_before_this_turn}
    samples: dict[str, list[float]] = {}
    results = {}
    for _ in range(repeat):
        for name, route in routes.items():
            with route():
                for threads in (1, 2):
                    cpu_s, wall_s, results[name] = _timed(lambda: drivetrain_periodic_response(assembled, state),
                                                          threads)
                    samples.setdefault(f"{name}_{threads}_cpu", []).append(cpu_s)
                    samples.setdefault(f"{name}_{threads}_wall", []).append(wall_s)
                cpu_s, _, _ = _timed(lambda: drivetrain_speed_sweep(assembled, states), 1)
                samples.setdefault(f"{name}_sweep_cpu", []).append(cpu_s / sweep_speeds)
    figure = {key: float(np.median(values)) for key, values in samples.items()}
    figure |= {f"{key}_min": float(np.min(values)) for key, values in samples.items()}
    after, before = results["after"], results["before"]
    moduli = [np.sort(np.abs(result.multipliers))[::-1] for result in (after, before)]
    figure |= {"dte_difference": _distance(after.transmission_error, before.transmission_error),
               "multiplier_difference": float(np.abs(moduli[0] - moduli[1]).max()),
               "ratio_1_thread": figure["before_1_cpu"] / figure["after_1_cpu"],
               "ratio_2_threads_wall": figure["before_2_wall"] / figure["after_2_wall"],
               "ratio_sweep": figure["before_sweep_cpu"] / figure["after_sweep_cpu"],
               "repeat": repeat, "sweep_speeds": sweep_speeds}
    return figure


def _distance(response_dte: np.ndarray, reference_dte: np.ndarray) -> float:
    """max |δ − δ_ref| / peak-to-peak of δ_ref."""
    return float(np.abs(response_dte - reference_dte).max() / np.ptp(reference_dte))


def newmark_run(assembled, state, reference) -> dict:
    """Newmark from rest to a 1 % steady state on the every-DOF system; its DTE at the exact orbit's samples."""
    from thermogear.drivetrain.response import drivetrain_periodic_system
    from thermogear.dynamics.transients.newmark import newmark_steady_state

    system, reduction = drivetrain_periodic_system(assembled, state)
    seconds, run = cpu(lambda: newmark_steady_state(system, NEWMARK_STEPS, tolerance=1e-2))
    w = reduction.project_vector(assembled.mesh_vectors[0])
    dte = run.displacement @ w
    step = NEWMARK_STEPS // 8  # the reference has 8 samples per piece
    return {"seconds": seconds, "periods": run.periods, "distance": _distance(dte[::step], reference)}


#: (steps per piece, steady-state tolerance) tried in turn until Newmark's orbit is within 1 % of the exact one: the
#: tolerance first (the settling), then the steps (64 per piece left the orbit 1.05 % away at every tolerance down
#: to 1e-4, the average-acceleration rule's own period error on the reduced system's highest modes).
NEWMARK_SETTINGS = ((64, 1e-2), (64, 1e-3), (64, 1e-4), (128, 1e-4), (128, 3e-5), (256, 3e-5))


def newmark_to_accuracy(assembled, state, cutoff: float) -> dict:
    """Newmark on the cut-off solver's own reduced system, from rest, with its steps per piece and steady-state
    tolerance tightened (``NEWMARK_SETTINGS``) until its orbit lies within 1 % of the exact orbit of that system
    (sampled at the same steps): the seconds of the first run that does (each run from rest, so its time is what
    Newmark needs with that stopping rule), or of the last one tried with its distance."""
    from thermogear.drivetrain.response import drivetrain_periodic_system
    from thermogear.dynamics.modes.modal_reduction import modal_basis
    from thermogear.dynamics.periodic_orbits.periodic_ndof import periodic_response
    from thermogear.dynamics.transients.newmark import newmark_steady_state

    system, reduction = drivetrain_periodic_system(assembled, state)
    basis = modal_basis(system, 2.0 * np.pi * cutoff)
    reduced = basis.reduce(system)
    w = basis.basis.T @ reduction.project_vector(assembled.mesh_vectors[0])
    exact = {steps: periodic_response(reduced, steps).displacement @ w for steps in {s for s, _ in NEWMARK_SETTINGS}}
    figure = {}
    for steps, tolerance in NEWMARK_SETTINGS:
        seconds, run = cpu(lambda: newmark_steady_state(reduced, steps, tolerance=tolerance, max_periods=20000))
        distance = _distance(run.displacement @ w, exact[steps])
        figure = {"seconds": seconds, "periods": run.periods, "tolerance": tolerance, "steps_per_piece": steps,
                  "distance": distance, "coordinates": reduced.size}
        if distance <= 0.01:
            break
    return figure


def size_figures(elements: int, full: bool, quick: bool) -> dict:
    from thermogear.drivetrain.backlash_response import drivetrain_backlash_response
    from thermogear.drivetrain.cutoff import cutoff_for_harmonics, drivetrain_cutoff_sweep
    from thermogear.drivetrain.response import drivetrain_periodic_response

    assembled = rotor(elements).assemble()
    speeds = np.linspace(2000.0, 4000.0, SPEEDS)
    states = [square_wave(float(speed)) for speed in speeds]
    state = square_wave(3000.0)
    cutoff = cutoff_for_harmonics(state.mesh_frequency_hz, HARMONICS)
    figure = {"elements_per_shaft": elements, "dof": assembled.size, "cutoff_hz": cutoff}
    plain, _ = cpu(lambda: drivetrain_cutoff_sweep(assembled, states, cutoff, estimate=False))
    estimated, swept = cpu(lambda: drivetrain_cutoff_sweep(assembled, states, cutoff))
    middle = swept[SPEEDS // 2]
    figure |= {"cutoff_s": plain / SPEEDS, "cutoff_with_estimate_s": estimated / SPEEDS,
               "coordinates": middle.error.coordinates, "check_coordinates": middle.error.check_coordinates,
               "estimate_dte": max(result.error.transmission_error for result in swept),
               "estimate_bearing_force": max(result.error.bearing_force for result in swept)}
    at_speed = drivetrain_cutoff_sweep(assembled, [state], cutoff)[0]
    reference = at_speed.response.transmission_error
    figure["reference"] = "cut-off"
    if full or elements <= 40:
        seconds, exact = cpu(lambda: drivetrain_periodic_response(assembled, state))
        figure |= {"every_dof_s": seconds, "cutoff_distance": _distance(reference, exact.transmission_error),
                   "reference": "every DOF"}
        reference = exact.transmission_error
        if elements == 40:
            with route_before_issue_38():
                figure["every_dof_before_s"], _ = cpu(lambda: drivetrain_periodic_response(assembled, state))
    backlash_state = replace(state, backlash=1e-4)
    figure["backlash_cutoff_s"], orbit = cpu(lambda: drivetrain_backlash_response(assembled, backlash_state,
                                                                                  cutoff_hz=cutoff))
    figure["backlash_kv"] = orbit.metrics.get("kv")
    if not (quick and elements > 40):
        figure["newmark"] = newmark_run(assembled, state, reference)
        figure["newmark_over_cutoff"] = figure["newmark"]["seconds"] / figure["cutoff_s"]
        figure["newmark_over_cutoff_with_estimate"] = figure["newmark"]["seconds"] / figure["cutoff_with_estimate_s"]
    if elements == 40 and not quick:
        figure["newmark_accurate"] = newmark_to_accuracy(assembled, state, cutoff)
        figure["accurate_newmark_over_cutoff"] = figure["newmark_accurate"]["seconds"] / figure["cutoff_s"]
        figure["accurate_newmark_over_cutoff_with_estimate"] = (figure["newmark_accurate"]["seconds"]
                                                                / figure["cutoff_with_estimate_s"])
    return figure


def table_figures(repeat: int) -> dict:
    """The 492-DOF rotor fed the square wave as a 1000-interval table, clean and scattered by 3e-13, every DOF."""
    from thermogear.drivetrain.response import drivetrain_periodic_response

    assembled = rotor(40).assemble()
    clean, noisy = square_wave(3000.0, 1000), square_wave(3000.0, 1000, noise=3e-13)
    times = {"clean": [], "noisy": []}
    results = {}
    for _ in range(repeat):
        for name, state in (("clean", clean), ("noisy", noisy)):
            seconds, results[name] = cpu(lambda state=state: drivetrain_periodic_response(assembled, state))
            times[name].append(seconds)
    clean_s, noisy_s = float(np.median(times["clean"])), float(np.median(times["noisy"]))
    return {"clean_s": clean_s, "noisy_s": noisy_s, "ratio": noisy_s / clean_s,
            "difference": _distance(results["noisy"].transmission_error, results["clean"].transmission_error)}


def main(quick: bool = False, full: bool = False) -> dict:
    warnings.simplefilter("ignore")
    from thermogear.drivetrain.cutoff import drivetrain_cutoff_sweep

    drivetrain_cutoff_sweep(rotor(2).assemble(), [square_wave(3000.0)])  # imports and first calls outside the timings
    sizes = [size_figures(elements, full, quick) for elements in SIZES]
    table = table_figures(1 if quick else 2)
    payload = {"machine": platform.platform(), "python": sys.version.split()[0], "sizes": sizes, "table": table,
               "blas_threads": os.environ.get("OPENBLAS_NUM_THREADS")}
    RESULTS.mkdir(exist_ok=True)
    (RESULTS / "bench_scaling.json").write_text(json.dumps(payload, indent=2), encoding="utf-8")
    print(f"{'DOF':>5} {'coords':>6} {'cut-off':>9} {'+estimate':>9} {'estimate':>9} {'backlash':>9} "
          f"{'every DOF':>9} {'before':>8} {'Newmark':>8} {'periods':>7} {'NM error':>8} {'NM/cut':>7}")
    for row in sizes:
        newmark = row.get("newmark", {})
        print(f"{row['dof']:>5} {row['coordinates']:>6} {row['cutoff_s'] * 1e3:>7.1f}ms "
              f"{row['cutoff_with_estimate_s'] * 1e3:>7.1f}ms {row['estimate_dte']:>9.1e} "
              f"{row['backlash_cutoff_s']:>8.2f}s {row.get('every_dof_s', float('nan')):>8.2f}s "
              f"{row.get('every_dof_before_s', float('nan')):>7.2f}s {newmark.get('seconds', float('nan')):>7.2f}s "
              f"{newmark.get('periods', 0):>7} {newmark.get('distance', float('nan')):>8.2e} "
              f"{row.get('newmark_over_cutoff', float('nan')):>7.0f}")
    for row in sizes:
        if "newmark_accurate" in row:
            accurate = row["newmark_accurate"]
            print(f"{row['dof']} DOF, Newmark ({accurate['steps_per_piece']} steps per piece) on the cut-off's own "
                  f"{accurate['coordinates']} coordinates to {accurate['distance']:.2%} of the exact orbit: "
                  f"{accurate['seconds']:.1f} s ({accurate['periods']} periods, steady-state tolerance "
                  f"{accurate['tolerance']:g}); {row['accurate_newmark_over_cutoff']:.0f}x the cut-off path, "
                  f"{row['accurate_newmark_over_cutoff_with_estimate']:.0f}x with its estimate")
    print(f"1000-interval table, 492 DOF, every DOF: clean {table['clean_s']:.2f} s, 3e-13 scatter "
          f"{table['noisy_s']:.2f} s (ratio {table['ratio']:.2f}), DTE difference {table['difference']:.1e}")
    return payload


def main_every_dof() -> dict:
    """Only the every-DOF figures of the 492-DOF rotor (:func:`every_dof_figures`) and the 1000-interval table;
    writes benchmarks/results/bench_scaling_every_dof.json."""
    warnings.simplefilter("ignore")
    from thermogear.drivetrain.response import drivetrain_periodic_response

    drivetrain_periodic_response(rotor(2).assemble(), square_wave(3000.0))  # imports outside the timings
    figure = every_dof_figures()
    table = table_figures(2)
    payload = {"machine": platform.platform(), "python": sys.version.split()[0], "every_dof": figure,
               "table": table, "load_average": os.getloadavg()}
    RESULTS.mkdir(exist_ok=True)
    (RESULTS / "bench_scaling_every_dof.json").write_text(json.dumps(payload, indent=2), encoding="utf-8")
    print("492 DOF, every DOF, per speed: before -> after (ratio)")
    print(f"  one run, 1 BLAS thread (CPU): {figure['before_1_cpu']:.2f} s -> {figure['after_1_cpu']:.2f} s "
          f"({figure['ratio_1_thread']:.2f}x; fastest of {figure['repeat']}: {figure['before_1_cpu_min']:.2f} s -> "
          f"{figure['after_1_cpu_min']:.2f} s)")
    print(f"  one run, 2 BLAS threads (CPU of both): {figure['before_2_cpu']:.2f} s -> {figure['after_2_cpu']:.2f} s")
    print(f"  one run, 2 BLAS threads (wall): {figure['before_2_wall']:.2f} s -> {figure['after_2_wall']:.2f} s "
          f"({figure['ratio_2_threads_wall']:.2f}x)")
    print(f"  within a sweep of {figure['sweep_speeds']} speeds, 1 thread (CPU): {figure['before_sweep_cpu']:.2f} s "
          f"-> {figure['after_sweep_cpu']:.2f} s ({figure['ratio_sweep']:.2f}x)")
    print(f"  DTE difference {figure['dte_difference']:.1e} of its peak-to-peak, multipliers "
          f"{figure['multiplier_difference']:.1e}")
    print(f"1000-interval table: clean {table['clean_s']:.2f} s, 3e-13 scatter {table['noisy_s']:.2f} s "
          f"(ratio {table['ratio']:.2f}), DTE difference {table['difference']:.1e}")
    return payload


if __name__ == "__main__":
    if "--every-dof" in sys.argv:
        main_every_dof()
    else:
        main(quick="--quick" in sys.argv, full="--full" in sys.argv)
