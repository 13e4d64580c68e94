"""Benchmark: the study kinds of issue 34 on two local worker processes against serial, ratios in one run.

Run: python benchmarks/bench_study_kinds.py [--quick] [--repeats=N]
Prints a table and writes benchmarks/results/bench_study_kinds.json.

1. the drivetrain study over speed × one other key (the two-shaft rotor of tests/data, linear mesh, 32 mesh-grid
   intervals and a 10 kHz modal cut-off; 48 speeds × 2 torques, elastic model): ``thermogear.sweep`` serial and on
   ``--scheduler processes --workers 2`` [>= 1.6×];
2. the gearbox's steady grid of 10⁴ points (FZG test gearbox of tests/data, 100 speeds × 100 torques): serial and
   on two worker processes [>= 1.6×], and the serial grid through the study executor and its store against the
   plain loop of ``steady_sweep`` (what the command ran before) [not slower].

Each ratio is serial seconds / parallel seconds of whole studies (the local cluster's start-up and the store
included), the pairs run back to back and repeated ``REPEATS`` times; the table gives the median pair. The load
average of the machine (shared with other work) is recorded beside each pair.
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


def _drivetrain_case(folder: Path) -> Path:
    text = (DATA / "two_shaft_drivetrain.toml").read_text(encoding="utf-8")
    text = text.replace("[drivetrain]\n", "[drivetrain]\nsweep_points_per_period = 32\nresponse_cutoff_hz = 10000.0\n",
                        1)
    path = folder / "drivetrain.toml"
    path.write_text(text, encoding="utf-8")
    return path


def _timed(function) -> float:
    start = time.perf_counter()
    function()
    return time.perf_counter() - start


def main() -> None:
    import numpy as np

    import thermogear
    from thermogear.case import load_case
    from thermogear.gearbox.case_model import gearbox_model_from_case, gearbox_operating_point
    from thermogear.gearbox.sweep import steady_sweep
    from thermogear.sweep.gearbox_grid import run_gearbox_grid

    quick = "--quick" in sys.argv
    repeats = 1 if quick else next((int(a.split("=")[1]) for a in sys.argv if a.startswith("--repeats=")), REPEATS)
    folder = Path(tempfile.mkdtemp(prefix="bench-study-kinds-"))
    rows: list[dict] = []
    try:
        case = _drivetrain_case(folder)
        speeds = "1000:3000:12" if quick else "1000:3000:48"
        vary = {"speed_rpm": speeds, "torque_nm": [100, 150]}
        points = (12 if quick else 48) * 2

        def drivetrain(scheduler: str, workers) -> None:
            out = folder / f"drivetrain-{scheduler}.zarr"
            shutil.rmtree(out, ignore_errors=True)
            thermogear.sweep(str(case), vary=vary, out=out, model="elastic", scheduler=scheduler, workers=workers)

        gearbox_case = load_case(str(DATA / "gearbox" / "fzg_gearbox.toml"))
        model = gearbox_model_from_case(gearbox_case)
        ambient = gearbox_operating_point(gearbox_case.operating_point, gearbox_case.gearbox).ambient_c
        count = 30 if quick else 100
        grid_speeds, grid_torques = np.linspace(300.0, 3000.0, count), np.linspace(10.0, 200.0, count)

        def grid(scheduler: str, workers) -> None:
            out = folder / f"grid-{scheduler}.zarr"
            shutil.rmtree(out, ignore_errors=True)
            run_gearbox_grid(model, grid_speeds, grid_torques, ambient, scheduler, workers, out=out,
                             case=gearbox_case)

        def plain_loop() -> None:
            steady_sweep(model, grid_speeds, grid_torques, ambient)

        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            for repeat in range(repeats):
                load = os.getloadavg()[0]
                serial, local = _timed(lambda: drivetrain("serial", None)), _timed(lambda: drivetrain("processes", 2))
                rows.append({"study": "drivetrain speed x torque", "points": points, "repeat": repeat,
                             "serial_s": serial, "two_workers_s": local, "ratio": serial / local, "load": load})
                print(json.dumps(rows[-1]), flush=True)
                load = os.getloadavg()[0]
                loop = _timed(plain_loop)
                serial, local = _timed(lambda: grid("serial", None)), _timed(lambda: grid("processes", 2))
                rows.append({"study": "gearbox steady grid", "points": count * count, "repeat": repeat,
                             "serial_s": serial, "two_workers_s": local, "ratio": serial / local,
                             "plain_loop_s": loop, "serial_vs_plain_loop": loop / serial, "load": load})
                print(json.dumps(rows[-1]), flush=True)
    finally:
        shutil.rmtree(folder, ignore_errors=True)
    summary = {}
    for study in ("drivetrain speed x torque", "gearbox steady grid"):
        pairs = sorted((row for row in rows if row["study"] == study), key=lambda row: row["ratio"])
        median = pairs[len(pairs) // 2]
        summary[study] = {**median, "ratios": [round(row["ratio"], 3) for row in pairs]}
        extra = (f", serial through the executor vs the plain loop {median['serial_vs_plain_loop']:.2f}x"
                 if "plain_loop_s" in median else "")
        print(f"{study}: {median['points']} points, serial {median['serial_s']:.1f} s "
              f"({median['points'] / median['serial_s']:.0f} points/s), two workers {median['two_workers_s']:.1f} s: "
              f"{median['ratio']:.2f}x (all pairs {summary[study]['ratios']}; load {median['load']:.1f}){extra}")
    RESULTS.mkdir(exist_ok=True)
    (RESULTS / "bench_study_kinds.json").write_text(json.dumps({"rows": rows, "summary": summary}, indent=1),
                                                    encoding="utf-8")


if __name__ == "__main__":
    main()
