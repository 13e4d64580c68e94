"""Benchmark: the backlash drivetrain of ``fzg_rig_type_c`` per speed, on every DOF and on the modal cut-off, against
the linear periodic response of the same state in the same run, on one BLAS thread; the motion from rest on the
cut-off per mesh period against the same baseline; ``thermogear run`` on the user's drivetrain
(tests/data/user_drivetrain.toml) against ``thermogear run fzg_rig_type_c`` in the same run (wall time and peak
memory of the process).

Run: python benchmarks/bench_drivetrain_backlash.py [--full] [SPEED_RPM ...]   (--full: also every DOF, ~30 s+)
Prints a table and writes benchmarks/results/bench_drivetrain_backlash.json. With --run-only: only the two
``thermogear run`` processes, interleaved twice, with the user's CPU and peak memory as ratios to fzg_rig_type_c's,
and the chain routes below (benchmarks/results/bench_user_drivetrain_run.json).

The chain routes (every run): the user's drivetrain's backlash response of the elastic model at the case's speed
(as ``run`` solves it, the start-up check included: 1024 pieces of 83 DOF on the chunked route) with the whole
pieces multiplied in the parts' own coordinates (``MODAL_CHAIN`` False: O(m³) a piece, as before the modal chain;
the start-up projector's factored starts need the modal route, so it forms them) and in the modal coordinates of one
mean piece (True, the default), interleaved twice in this process: CPU of each, their
ratio, and the relative difference of Kv and DTE RMS between the two.

Per speed (the elastic mesh model's state, the case's ``points_per_period`` intervals): CPU (user + sys of this
process) and wall seconds of ``drivetrain_backlash_response`` with ``cutoff_hz`` None (every DOF) and with the
section's ``response_cutoff_hz``, and of ``drivetrain_periodic_response`` (linear mesh, the cut-off, as ``run``
solves it), interleaved; the cut-off's relative error in Kv, DTE RMS and the contact-loss fraction against every
DOF. The machine these numbers come from may be loaded: CPU time is printed beside wall.
"""

from __future__ import annotations

import os

for _name in ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_name, "1")  # one core; oversubscribed BLAS threads cost far more than they give

import json  # noqa: E402
import sys  # noqa: E402
import time  # noqa: E402
import warnings  # noqa: E402
from pathlib import Path  # noqa: E402

RESULTS = Path(__file__).resolve().parent / "results"
SPEEDS_RPM = (2175.0, 6000.0)
FULL = "--full" in sys.argv  # every DOF too (about 30 s of CPU per speed)


def _timed(function):
    """(result, CPU seconds, wall seconds) of one call."""
    cpu, wall = time.process_time(), time.perf_counter()
    result = function()
    return result, time.process_time() - cpu, time.perf_counter() - wall


def _relative(value, reference):
    if value is None or reference is None:
        return None
    return abs(value - reference) / max(abs(reference), 1e-300)


def main(speeds: tuple[float, ...]) -> list[dict]:
    from thermogear.case import load_case
    from thermogear.drivetrain.backlash_response import drivetrain_backlash_response
    from thermogear.drivetrain.case_model import backlash_substeps, case_drivetrain
    from thermogear.drivetrain.response import drivetrain_periodic_response
    from thermogear.drivetrain.transient_response import drivetrain_transient

    warnings.simplefilter("ignore")  # the case's extrapolation warnings are said by `check`
    case = load_case("fzg_rig_type_c")
    built = case_drivetrain(case, ("elastic",))
    assembled, cutoff = built.assembled("elastic"), case.drivetrain.response_cutoff_hz
    # untimed first solves: the process's first ones load numba's compiled kernels, which no later speed pays
    warm = built.models["elastic"].state(speed_rpm=speeds[0], points_per_period=case.dynamics.points_per_period)
    drivetrain_periodic_response(assembled, warm, 4, cutoff)
    drivetrain_backlash_response(assembled, warm, substeps=backlash_substeps(warm.grid.nodes.size - 1),
                                 samples_per_piece=4, cutoff_hz=cutoff)
    rows = []
    for speed in speeds:
        state = built.models["elastic"].state(speed_rpm=speed, points_per_period=case.dynamics.points_per_period)
        substeps = backlash_substeps(state.grid.nodes.size - 1)  # as run solves it
        linear, linear_cpu, linear_wall = _timed(lambda: drivetrain_periodic_response(assembled, state, 4, cutoff))
        cut, cut_cpu, cut_wall = _timed(lambda: drivetrain_backlash_response(assembled, state, substeps=substeps,
                                                                             samples_per_piece=4, cutoff_hz=cutoff))
        startup, startup_cpu, startup_wall = _timed(lambda: drivetrain_backlash_response(
            assembled, state, substeps=substeps, samples_per_piece=4, cutoff_hz=cutoff,
            startup_periods=case.dynamics.transient_periods))
        periods = 10
        _, transient_cpu, transient_wall = _timed(lambda: drivetrain_transient(
            assembled, state, periods, samples_per_piece=4, substeps=substeps, cutoff_hz=cutoff))
        if FULL:
            full, full_cpu, full_wall = _timed(lambda: drivetrain_backlash_response(
                assembled, state, substeps=substeps, samples_per_piece=4))
        else:
            full, full_cpu, full_wall = cut, None, None  # not measured (no --full)
        row = {"speed_rpm": speed, "dof": assembled.size, "intervals": int(state.grid.nodes.size - 1),
               "full": {"cpu_s": full_cpu, "wall_s": full_wall, "converged": full.converged, "kv": full.kv,
                        "contact_loss_fraction": full.contact_loss_fraction, "switches": full.switches},
               "cutoff": {"cpu_s": cut_cpu, "wall_s": cut_wall, "converged": cut.converged, "kv": cut.kv,
                          "contact_loss_fraction": cut.contact_loss_fraction, "switches": cut.switches},
               "linear_cutoff": {"cpu_s": linear_cpu, "wall_s": linear_wall, "kv": linear.kv},
               "cutoff_over_linear_cpu": cut_cpu / linear_cpu,
               "with_startup": {"cpu_s": startup_cpu, "wall_s": startup_wall,
                                "over_linear_cpu": startup_cpu / linear_cpu,
                                "reached_from": startup.metrics.get("startup", {}).get("reached_from")},
               "transient_per_period": {"cpu_s": transient_cpu / periods, "wall_s": transient_wall / periods,
                                        "over_linear_cpu": transient_cpu / periods / linear_cpu},
               "cutoff_error": None if full_cpu is None else {
                   "kv": _relative(cut.kv, full.kv),
                   "dte_rms": _relative(cut.metrics.get("dte_rms"), full.metrics.get("dte_rms")),
                   "contact_loss_fraction": abs(cut.contact_loss_fraction - full.contact_loss_fraction)}}
        rows.append(row)
        measured = "not run" if full_cpu is None else f"{full_cpu:7.2f} s CPU ({full_wall:7.2f} wall)"
        print(f"{speed:7.0f} rpm  full {measured}  cut-off {cut_cpu:6.3f} s CPU "
              f"({cut_wall:6.3f} wall, {cut_cpu / linear_cpu:.2f}× linear)  with the start-up {startup_cpu:6.3f} s "
              f"CPU  transient {transient_cpu / periods:6.3f} s CPU per period  linear {linear_cpu:6.3f} s CPU  "
              f"Kv {full.kv} / {cut.kv} (linear {linear.kv})  contact loss {cut.contact_loss_fraction:.4f}",
              flush=True)
    return rows


def _run_process(case: str, *options: str) -> dict:
    """Wall seconds, CPU seconds and peak resident memory [MB] of ``thermogear run CASE --json [OPTIONS]`` in a child
    process (its own imports included), from that child's own resource usage (os.wait4)."""
    import subprocess

    wall = time.perf_counter()
    child = subprocess.Popen([sys.executable, "-m", "thermogear", "run", case, "--json", "-q", *options],
                             stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    _, status, usage = os.wait4(child.pid, 0)
    wall = time.perf_counter() - wall
    child.returncode = os.waitstatus_to_exitcode(status)
    return {"case": case, "options": list(options), "wall_s": wall, "cpu_s": usage.ru_utime + usage.ru_stime,
            "peak_memory_mb": usage.ru_maxrss / 1024.0, "exit_code": child.returncode}


def chain_route_rows() -> list[dict]:
    """The user's drivetrain's backlash response (elastic model, the case's speed, as ``run`` solves it) with the
    whole pieces' chain in the original and in the modal coordinates, interleaved twice: CPU seconds, the ratio of
    each modal solve to the original-coordinates solve just before it, and the relative difference of Kv and DTE RMS
    (the routes differ only in rounding)."""
    from thermogear.case import load_case
    from thermogear.drivetrain.case_model import case_drivetrain
    from thermogear.dynamics.periodic_orbits import periodic_ndof

    warnings.simplefilter("ignore")
    case = load_case(str(Path(__file__).resolve().parents[1] / "tests" / "data" / "user_drivetrain.toml"))
    rows = []
    try:  # an untimed solve first: the process's first one loads numba's compiled kernels (about 1.5 s)
        case_drivetrain(case, ("elastic",)).backlash_response("elastic")
        for _ in range(2):
            for modal in (False, True):
                periodic_ndof.MODAL_CHAIN = modal
                built = case_drivetrain(case, ("elastic",))  # afresh: nothing of the other route's solve is kept
                response, cpu, wall = _timed(lambda: built.backlash_response("elastic"))
                row = {"modal_chain": modal, "cpu_s": cpu, "wall_s": wall, "kv": response.kv,
                       "dte_rms": response.metrics.get("dte_rms")}
                if modal:
                    before = rows[-1]
                    row.update(cpu_over_original=cpu / before["cpu_s"], kv_relative=_relative(row["kv"], before["kv"]),
                               dte_rms_relative=_relative(row["dte_rms"], before["dte_rms"]))
                rows.append(row)
                route = "modal   " if modal else "original"
                print(f"chain {route} CPU {cpu:6.3f} s  wall {wall:6.3f} s  Kv {row['kv']}"
                      + (f"  ({row['cpu_over_original']:.2f}× the original's CPU; Kv, DTE RMS differ by "
                         f"{row['kv_relative']:.1e}, {row['dte_rms_relative']:.1e})" if modal else ""), flush=True)
    finally:
        periodic_ndof.MODAL_CHAIN = True
    return rows


def run_command_rows() -> list[dict]:
    """``thermogear run`` on the user's drivetrain and on fzg_rig_type_c, interleaved twice: wall, CPU, memory, and
    each user run's CPU and peak memory as ratios to the fzg_rig_type_c run just before it (issue 36's targets:
    3 s and 400 MB, i.e. about the built-in set's own)."""
    from timing import compile_bytecode

    user = str(Path(__file__).resolve().parents[1] / "tests" / "data" / "user_drivetrain.toml")
    compile_bytecode()  # the bytecode an installed package has (timing.compile_bytecode)
    rows = []
    for _ in range(2):
        for case in ("fzg_rig_type_c", user):
            row = _run_process(case)
            if case == user:
                baseline = rows[-1]
                row["cpu_over_fzg_rig_type_c"] = row["cpu_s"] / baseline["cpu_s"]
                row["memory_over_fzg_rig_type_c"] = row["peak_memory_mb"] / baseline["peak_memory_mb"]
            rows.append(row)
            ratios = (f"  ({row['cpu_over_fzg_rig_type_c']:.2f}× CPU, {row['memory_over_fzg_rig_type_c']:.2f}× "
                      "memory of fzg_rig_type_c)") if case == user else ""
            print(f"run {Path(case).name:24s} wall {row['wall_s']:6.2f} s  CPU {row['cpu_s']:6.2f} s  peak "
                  f"memory {row['peak_memory_mb']:7.1f} MB  exit {row['exit_code']}{ratios}", flush=True)
    # the motion from rest over the case's 60 mesh periods, both models (issue 36: it made fzg_rig_type_c hang)
    row = _run_process("fzg_rig_type_c", "--method", "transient")
    row["cpu_over_fzg_rig_type_c"] = row["cpu_s"] / rows[-2]["cpu_s"]
    rows.append(row)
    print(f"run fzg_rig_type_c --method transient wall {row['wall_s']:6.2f} s  CPU {row['cpu_s']:6.2f} s  peak memory "
          f"{row['peak_memory_mb']:7.1f} MB  exit {row['exit_code']}  ({row['cpu_over_fzg_rig_type_c']:.2f}x CPU of "
          "the periodic run)", flush=True)
    return rows


if __name__ == "__main__":
    if "--run-only" in sys.argv:  # only the `thermogear run` rows (issue 36's user drivetrain)
        RESULTS.mkdir(exist_ok=True)
        measured = {"run": run_command_rows(), "chain_routes": chain_route_rows()}
        (RESULTS / "bench_user_drivetrain_run.json").write_text(json.dumps(measured, indent=2), encoding="utf-8")
        sys.exit(0)
    chosen = tuple(float(value) for value in sys.argv[1:] if value != "--full") or SPEEDS_RPM
    results = {"speeds": main(chosen), "run": run_command_rows(), "chain_routes": chain_route_rows()}
    RESULTS.mkdir(exist_ok=True)
    (RESULTS / "bench_drivetrain_backlash.json").write_text(json.dumps(results, indent=2), encoding="utf-8")
