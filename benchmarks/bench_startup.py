"""Benchmark: start-up of the command line (`thermogear --help`, `thermogear cases`) against `python -c pass`.

Run: python benchmarks/bench_startup.py [REPEATS]
Prints a table and writes benchmarks/results/bench_startup.json. Every figure is the median wall time of REPEATS
fresh processes (default 9), measured in the same run as the baseline (a bare interpreter) and as the cost of
importing every command module up front (what the command line did before its commands were loaded lazily).
The target is 0.5 s for `--help` and `cases`. The slowest imports of `--help` come from `python -X importtime`.
"""

from __future__ import annotations

import json
import platform
import statistics
import subprocess
import sys
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent
TARGET_S = 0.5
EVERY_COMMAND_MODULE = ("cases", "check", "stiffness", "damping", "vibration", "warmup", "sweep", "reproduce", "run",
                        "fem")


def wall_times(arguments: list[str], repeats: int) -> list[float]:
    """Wall time [s] of ``repeats`` fresh processes (one unmeasured first run warms the file cache)."""
    subprocess.run(arguments, capture_output=True, check=False)
    times = []
    for _ in range(repeats):
        start = time.perf_counter()
        completed = subprocess.run(arguments, capture_output=True, check=False)
        times.append(time.perf_counter() - start)
        if completed.returncode != 0:
            raise RuntimeError(f"{' '.join(arguments)} failed: {completed.stderr.decode()[-500:]}")
    return times


def slowest_imports(arguments: list[str], count: int = 8) -> list[dict]:
    """The top-level imports with the largest cumulative time [ms] (``python -X importtime``)."""
    completed = subprocess.run([sys.executable, "-X", "importtime", *arguments], capture_output=True, text=True,
                               check=False)
    rows = []
    for line in completed.stderr.splitlines():
        if not line.startswith("import time:") or "|" not in line:
            continue
        _, cumulative, name = (part for part in line.split("|"))
        try:
            rows.append({"module": name.strip(), "depth": (len(name) - len(name.lstrip())) // 2,
                         "cumulative_ms": int(cumulative) / 1000})
        except ValueError:
            continue
    top = [row for row in rows if row["depth"] <= 1]
    return sorted(top, key=lambda row: -row["cumulative_ms"])[:count]


def main(repeats: int = 9) -> dict:
    from timing import compile_bytecode

    compile_bytecode()  # the bytecode an installed package has (timing.compile_bytecode)
    python = [sys.executable]
    cases = {
        "python -c pass (baseline)": python + ["-c", "pass"],
        "thermogear --help": python + ["-m", "thermogear", "--help"],
        "thermogear cases": python + ["-m", "thermogear", "cases"],
        "import every command module (before)": python + ["-c", "import thermogear.cli; "
                                                          + "; ".join(f"import thermogear.cli.{name}"
                                                                      for name in EVERY_COMMAND_MODULE)],
    }
    medians: dict[str, float | None] = {}
    for name, arguments in cases.items():
        try:
            medians[name] = statistics.median(wall_times(arguments, repeats))
        except RuntimeError as error:  # only the "before" figure may fail (a command module that does not import)
            if name.startswith("thermogear") or "baseline" in name:
                raise
            print(f"{name}: not measured ({error})")
            medians[name] = None
    baseline = medians["python -c pass (baseline)"]
    figures = [{"name": name, "value": value, "baseline": baseline, "ratio": value / baseline, "unit": "s"}
               for name, value in medians.items() if "baseline" not in name and value is not None]
    result = {
        "benchmark": "bench_startup",
        "repeats": repeats,
        "median_s": medians,
        "figures": figures,
        "target_s": TARGET_S,
        "meets_target": medians["thermogear --help"] <= TARGET_S and medians["thermogear cases"] <= TARGET_S,
        "slowest_imports_help": slowest_imports(["-m", "thermogear", "--help"]),
        "python": platform.python_version(),
        "machine": platform.machine(),
        "processor": platform.processor(),
    }
    print(f"{'':40s} {'median [s]':>10s} {'/ python':>9s}")
    for name, value in medians.items():
        if value is not None:
            print(f"{name:40s} {value:10.3f} {value / baseline:9.2f}")
    print(f"target {TARGET_S} s: {'met' if result['meets_target'] else 'NOT met'}")
    out = HERE / "results" / "bench_startup.json"
    out.write_text(json.dumps(result, indent=2) + "\n", encoding="utf-8")
    return result


if __name__ == "__main__":
    main(int(sys.argv[1]) if len(sys.argv) > 1 else 9)
