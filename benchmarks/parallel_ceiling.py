"""What two threads can give on this machine right now: the ceiling for the study's two-worker ratio.

Run: python benchmarks/parallel_ceiling.py [--work SECONDS]   (prints one JSON object)

A study on two threads cannot run faster than its parallel part does, and on a shared virtual machine even a
perfectly parallel part does not run twice as fast on two threads: the two virtual cores may share a physical
core or its caches with each other or with other tenants. ``bench_sweep_cli`` runs this script beside each
serial/two-thread pair of studies, so that the study's ratio can be read against what the machine gave in the
same minute. Two workloads, each run twice one after the other on one thread and then once on each of two threads
(``ThreadPoolExecutor(2)``, as the study's threaded scheduler):

* ``arithmetic``: a numba loop of floating-point arithmetic that releases the GIL and touches no memory: the
  machine's ceiling for pure computation;
* ``kernel``: the sweep's own compiled kernel (``sweep.batch.evaluate_loads``) on the luo2019 thermal tables of
  one load at 4000 speeds, repeated: the study's parallel part alone, with no Python between the points.

``work``: seconds of single-thread work per job, roughly (the job sizes are set from a first timed call).
"""

from __future__ import annotations

import json
import math
import sys
import time
import warnings
from concurrent.futures import ThreadPoolExecutor

import numba
import numpy as np


@numba.njit(nogil=True, cache=True)
def _arithmetic(count: int) -> float:
    total = 0.0
    for index in range(count):
        total += math.sin(index * 1e-3) * 1.0000001
    return total


def _ratio(job, repeats: int = 2) -> dict:
    """Seconds of ``repeats`` jobs one after another, and of the same jobs on two threads at once."""
    start = time.perf_counter()
    for _ in range(repeats):
        job()
    serial = time.perf_counter() - start
    with ThreadPoolExecutor(2) as pool:
        start = time.perf_counter()
        list(pool.map(lambda _: job(), range(repeats)))
        threads = time.perf_counter() - start
    return {"serial_s": serial, "threads_s": threads, "ratio": serial / threads}


def _sized(job_of_size, work: float, probe: int):
    """A job of about ``work`` seconds, from a timed call of size ``probe``."""
    job_of_size(probe)
    start = time.perf_counter()
    job_of_size(probe)
    per_unit = (time.perf_counter() - start) / probe
    size = max(1, int(work / per_unit))
    return lambda: job_of_size(size)


def measure(work: float = 1.0) -> dict:
    from thermogear.case import load_case
    from thermogear.mesh.model import MeshModel
    from thermogear.sweep.batch import evaluate_loads, group_tables

    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # the case's warnings (oil below its fitted range) say nothing here
        tables = group_tables(MeshModel(load_case("luo2019"), "thermal"))
    speeds = np.linspace(1000.0, 10000.0, 4000)

    def kernel(repeats: int) -> None:
        for _ in range(repeats):
            evaluate_loads(tables, speeds, tables.normal_load)

    return {"arithmetic": _ratio(_sized(_arithmetic, work, 1_000_000)),
            "kernel": _ratio(_sized(kernel, work, 1))}


if __name__ == "__main__":
    arguments = sys.argv[1:]
    seconds = float(arguments[arguments.index("--work") + 1]) if "--work" in arguments else 1.0
    print(json.dumps(measure(seconds)))
