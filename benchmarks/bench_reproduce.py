"""Benchmark: the main job, `thermogear reproduce luo2019`, against `python -c "import numpy"` in the same run.

Run: python benchmarks/bench_reproduce.py [REPEATS] [--compare SRC]
Prints a table and writes benchmarks/results/bench_reproduce.json. Each figure is the median of REPEATS fresh
processes (default 3) after one unmeasured warm-up run (file cache, numba's compiled-function cache), as wall
time and as CPU time (user + system of the process and its children: the report runs the FE verification and the
results file in child processes, so wall < CPU on two free cores). The baseline runs interleaved with the command,
so that a machine loaded by other work slows both alike: the ratio to it is the figure to compare across machines.
The stages of the last run (``timings_s`` of summary.json, which cover the whole command) are listed too.

``--compare SRC``: also run the command from another source tree (``SRC/src`` first on PYTHONPATH, e.g. an older
commit checked out with ``git worktree add /tmp/before HEAD~8``), interleaved with this one run for run: an A/B
comparison on a shared machine, also given as the median of the rounds' ratios (this tree over the other). The
target is 5 s wall on two cores.
"""

from __future__ import annotations

import json
import os
import platform
import resource
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent
SOURCE = HERE.parent / "src"
TARGET_S = 5.0


def _children_cpu() -> float:
    usage = resource.getrusage(resource.RUSAGE_CHILDREN)
    return usage.ru_utime + usage.ru_stime


def timed(arguments: list[str], source: Path | None, folder: Path | None = None) -> tuple[float, float]:
    """(wall [s], CPU [s]) of one fresh process; ``source``: the ``src`` folder put first on PYTHONPATH."""
    environment = dict(os.environ)
    if source is not None:
        environment["PYTHONPATH"] = str(source) + os.pathsep + environment.get("PYTHONPATH", "")
    cpu = _children_cpu()
    start = time.perf_counter()
    completed = subprocess.run(arguments, capture_output=True, env=environment, cwd=folder, check=False)
    wall = time.perf_counter() - start
    if completed.returncode != 0:
        raise RuntimeError(f"{' '.join(arguments)} failed: {completed.stderr.decode()[-1000:]}")
    return wall, _children_cpu() - cpu


def main(repeats: int = 3, compare: Path | None = None) -> dict:
    from timing import compile_bytecode

    compile_bytecode(*([compare / "src"] if compare is not None else []))  # as installed (timing.compile_bytecode)
    python = sys.executable
    scratch = Path(tempfile.mkdtemp(prefix="bench-reproduce-"))
    command = [python, "-m", "thermogear", "reproduce", "luo2019", "--out", str(scratch / "report"), "--force",
               "--quiet"]
    runs = {"python -c 'import numpy' (baseline)": ([python, "-c", "import numpy"], None),
            "thermogear reproduce luo2019": (command, SOURCE)}
    if compare is not None:
        other = [*command[:-3], str(scratch / "report-compare"), "--force", "--quiet"]
        runs[f"thermogear reproduce luo2019 ({compare})"] = (other, Path(compare) / "src")
    for arguments, source in runs.values():  # warm-up: file cache, numba cache, the report folder exists
        timed(arguments, source, scratch)
    samples: dict[str, list[tuple[float, float]]] = {name: [] for name in runs}
    for _ in range(repeats):  # interleaved: each round runs every variant once
        for name, (arguments, source) in runs.items():
            samples[name].append(timed(arguments, source, scratch))
    summary = json.loads((scratch / "report" / "summary.json").read_text(encoding="utf-8"))
    wall = {name: statistics.median(w for w, _ in values) for name, values in samples.items()}
    cpu = {name: statistics.median(c for _, c in values) for name, values in samples.items()}
    baseline = wall["python -c 'import numpy' (baseline)"]
    figures = [{"name": f"{name}, wall", "value": wall[name], "baseline": baseline, "ratio": wall[name] / baseline,
                "unit": "s"} for name in runs if "baseline" not in name]
    figures += [{"name": f"{name}, CPU", "value": cpu[name], "baseline": cpu["python -c 'import numpy' (baseline)"],
                 "ratio": cpu[name] / max(cpu["python -c 'import numpy' (baseline)"], 1e-9), "unit": "s"}
                for name in runs if "baseline" not in name]
    main_wall = wall["thermogear reproduce luo2019"]
    paired = {}
    if compare is not None:  # per round, this tree over the other: on a loaded machine steadier than two medians
        mine, other = samples["thermogear reproduce luo2019"], samples[list(runs)[-1]]
        paired = {"wall": statistics.median(a[0] / b[0] for a, b in zip(mine, other)),
                  "cpu": statistics.median(a[1] / b[1] for a, b in zip(mine, other))}
    result = {
        "benchmark": "bench_reproduce",
        "repeats": repeats,
        "median_wall_s": wall,
        "median_cpu_s": cpu,
        "samples_wall_cpu_s": samples,
        "figures": figures,
        "target_s": TARGET_S,
        "meets_target": main_wall <= TARGET_S,
        "paired_ratio_to_compare": paired,
        "timings_s_last_run": summary.get("timings_s"),
        "timings_background_s_last_run": summary.get("timings_background_s"),
        "load_average": os.getloadavg(),
        "cpus": os.cpu_count(),
        "python": platform.python_version(),
        "machine": platform.machine(),
    }
    print(f"{'':60s} {'wall [s]':>9s} {'/ numpy':>8s} {'CPU [s]':>8s}")
    for name in runs:
        print(f"{name:60s} {wall[name]:9.2f} {wall[name] / baseline:8.1f} {cpu[name]:8.2f}")
    if paired:
        print(f"this tree / {compare}, median of the rounds' ratios: wall {paired['wall']:.3f}, "
              f"CPU {paired['cpu']:.3f}")
    stages = summary.get("timings_s") or {}
    print("stages of the last run [s]: " + ", ".join(f"{key} {value:.2f}" for key, value in stages.items())
          + f" (sum {sum(stages.values()):.2f})")
    print(f"load average {result['load_average'][0]:.1f} on {result['cpus']} cores; target {TARGET_S} s wall: "
          + ("met" if result["meets_target"] else "NOT met"))
    out = HERE / "results" / "bench_reproduce.json"
    out.write_text(json.dumps(result, indent=2) + "\n", encoding="utf-8")
    return result


if __name__ == "__main__":
    arguments = sys.argv[1:]
    if "--help" in arguments or "-h" in arguments:
        print(__doc__)
        sys.exit(0)
    other = None
    if "--compare" in arguments:
        index = arguments.index("--compare")
        other = Path(arguments[index + 1])
        del arguments[index:index + 2]
    main(int(arguments[0]) if arguments else 3, other)
