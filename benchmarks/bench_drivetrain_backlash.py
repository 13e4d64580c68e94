"""Benchmark: the backlash drivetrain of ``fzg_rig_type_c`` per speed, on every DOF and on the modal cut-off, against
the linear periodic response of the same state in the same run, on one BLAS thread.

Run: python benchmarks/bench_drivetrain_backlash.py [SPEED_RPM ...]
Prints a table and writes benchmarks/results/bench_drivetrain_backlash.json.

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

    warnings.simplefilter("ignore")  # the case's extrapolation warnings are said by `check`
    case = load_case("fzg_rig_type_c")
    built = case_drivetrain(case, ("elastic",))
    assembled, cutoff = built.assembled("elastic"), case.drivetrain.response_cutoff_hz
    rows = []
    for speed in speeds:
        state = built.models["elastic"].state(speed_rpm=speed, points_per_period=case.dynamics.points_per_period)
        substeps = backlash_substeps(state.grid.nodes.size - 1)  # as run solves it
        full, full_cpu, full_wall = _timed(lambda: drivetrain_backlash_response(assembled, state, substeps=substeps,
                                                                                samples_per_piece=4))
        cut, cut_cpu, cut_wall = _timed(lambda: drivetrain_backlash_response(assembled, state, substeps=substeps,
                                                                             samples_per_piece=4, cutoff_hz=cutoff))
        linear, linear_cpu, linear_wall = _timed(lambda: drivetrain_periodic_response(assembled, state, 4, cutoff))
        row = {"speed_rpm": speed, "dof": assembled.size, "intervals": int(state.grid.nodes.size - 1),
               "full": {"cpu_s": full_cpu, "wall_s": full_wall, "converged": full.converged, "kv": full.kv,
                        "contact_loss_fraction": full.contact_loss_fraction, "switches": full.switches},
               "cutoff": {"cpu_s": cut_cpu, "wall_s": cut_wall, "converged": cut.converged, "kv": cut.kv,
                          "contact_loss_fraction": cut.contact_loss_fraction, "switches": cut.switches},
               "linear_cutoff": {"cpu_s": linear_cpu, "wall_s": linear_wall, "kv": linear.kv},
               "cutoff_error": {"kv": _relative(cut.kv, full.kv),
                                "dte_rms": _relative(cut.metrics.get("dte_rms"), full.metrics.get("dte_rms")),
                                "contact_loss_fraction": abs(cut.contact_loss_fraction
                                                             - full.contact_loss_fraction)}}
        rows.append(row)
        print(f"{speed:7.0f} rpm  full {full_cpu:7.2f} s CPU ({full_wall:7.2f} wall)  cut-off {cut_cpu:6.2f} s CPU "
              f"({cut_wall:6.2f} wall)  linear {linear_cpu:5.2f} s CPU  Kv {full.kv} / {cut.kv} (linear "
              f"{linear.kv})  cut-off error in Kv {row['cutoff_error']['kv']}  contact loss "
              f"{full.contact_loss_fraction:.4f}", flush=True)
    return rows


if __name__ == "__main__":
    chosen = tuple(float(value) for value in sys.argv[1:]) or SPEEDS_RPM
    results = main(chosen)
    RESULTS.mkdir(exist_ok=True)
    (RESULTS / "bench_drivetrain_backlash.json").write_text(json.dumps(results, indent=2), encoding="utf-8")
