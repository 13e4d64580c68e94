"""Benchmark: the full FE verification of a case (`thermogear fem CASE`: heat of both gears, whole-gear elastic
runs in plane stress and strain, thermo-elastic runs, expansion check, refinement study at twice the refinement)
on 2 cores, beside the analytical chain it verifies (PEM compliance + Eqs. 8–12 at the same positions).

Run: python benchmarks/bench_fem.py [CASE] [REPEATS]
Prints a table and writes benchmarks/results/bench_fem.json. Target: under 60 s for luo2019 (issue 7).
"""

from __future__ import annotations

import os

for _name in ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_name, "2")

import json  # noqa: E402
import platform  # noqa: E402
import sys  # noqa: E402
import time  # noqa: E402
import warnings  # noqa: E402
from pathlib import Path  # noqa: E402

import numpy as np  # noqa: E402

TARGET_S = 60.0


def _cores() -> int:
    if hasattr(os, "sched_setaffinity"):
        available = sorted(os.sched_getaffinity(0))
        os.sched_setaffinity(0, available[:2])
        return len(os.sched_getaffinity(0))
    return os.cpu_count() or 1


def main(case_name: str = "luo2019", repeats: int = 3) -> dict:
    cores = _cores()
    from thermogear.case import load_case
    from thermogear.fem import verification
    from thermogear.fem.inputs import fem_inputs
    from thermogear.fem.verification import fem_analysis, refinement_change_percent
    from thermogear.stiffness.potential_energy import pair_compliance
    from thermogear.luo2020.thermal.case_inputs import expansion_for_case

    case = load_case(case_name)
    full, analytical = [], []
    for _ in range(repeats):
        verification._CACHE.clear()
        start = time.perf_counter()
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            coarse = fem_analysis(fem_inputs(case))
            fine = fem_analysis(coarse.inputs, 2.0 * coarse.refinement)
            change = refinement_change_percent(coarse, fine)["max"]
        full.append(time.perf_counter() - start)
        start = time.perf_counter()
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            pair_compliance(case.gear_pair, case.material, coarse.roll)
            expansion_for_case(case, coarse.roll)
        analytical.append(time.perf_counter() - start)
    result = {
        "benchmark": "bench_fem",
        "case": case_name,
        "cores": cores,
        "contact_positions": int(coarse.roll.size),
        "elements_pinion_gear": int(coarse.deflection["pinion"].elements),
        "full_fem_verification_s": {"best": min(full), "median": float(np.median(full))},
        "analytical_chain_s": {"best": min(analytical), "median": float(np.median(analytical))},
        "refinement_change_percent": change,
        "figures": [{"name": "full FE verification (2 cores)", "value": float(np.median(full)),
                     "baseline": float(np.median(analytical)), "ratio": float(np.median(full) / np.median(analytical)),
                     "unit": "s"}],
        "target_s": TARGET_S,
        "meets_target": bool(np.median(full) < TARGET_S),
        "python": platform.python_version(),
        "numpy": np.__version__,
        "machine": platform.machine(),
        "processor": platform.processor(),
    }
    print(f"{'quantity':40s} {'best [s]':>10s} {'median [s]':>11s}")
    print(f"{'full FE verification':40s} {min(full):10.3f} {np.median(full):11.3f}")
    print(f"{'analytical chain (PEM + Eqs. 8-12)':40s} {min(analytical):10.4f} {np.median(analytical):11.4f}")
    print(f"cores {cores}, target {TARGET_S} s met: {result['meets_target']}")
    out = Path(__file__).parent / "results" / "bench_fem.json"
    out.parent.mkdir(exist_ok=True)
    out.write_text(json.dumps(result, indent=2) + "\n", encoding="utf-8")
    return result


if __name__ == "__main__":
    main(*(sys.argv[1:2] or ["luo2019"]), *(int(a) for a in sys.argv[2:3]))
