"""Where the CPU of the gearbox grid on two local workers goes: per process and per thread, against the serial grid.

Run: python benchmarks/grid_cpu_breakdown.py [--grid-size=N] [--chunk-points=P] [--dask-defaults]
(default 45 × 45 speeds × torques, 250 points per task: about 20 s of solving; Linux only, it reads /proc).

Prints, for the serial grid, its CPU seconds; for the same grid on the studies' local cluster of two single-thread
worker processes (:func:`thermogear.sweep.executor.execute`), the CPU seconds up to the first result and up to
the last one, of

* the driver's threads (this process: its main thread, the event loop that runs the scheduler, the nannies and the
  client, the store's writer thread);
* each worker's threads (its event loop: Dask's heartbeats, monitors and profiler, the unpickling of the shared
  data; the thread that runs the tasks);

each task's own CPU, and when each worker started its first task and ended its last (a worker idle at the end
waits for the other's last block). ``--dask-defaults``: the cluster at Dask's default background settings instead
of the executor's ``QUIET_LOCAL_CLUSTER``. CPU seconds, unlike seconds, hardly move with another user's load on a
shared machine (the tasks' own CPU rises a little under load: shared caches). Nothing is written.
"""

from __future__ import annotations

import os
import sys
import tempfile
import threading
import time
import warnings
from pathlib import Path

DATA = Path(__file__).resolve().parent.parent / "tests" / "data"


def _option(name: str, default: int) -> int:
    return next((int(a.split("=")[1]) for a in sys.argv if a.startswith(f"--{name}=")), default)


def thread_cpu() -> dict[str, float]:
    """CPU seconds of each thread of this process, by thread name (Linux: /proc/self/task/*/stat)."""
    names = {thread.native_id: thread.name for thread in threading.enumerate()}
    ticks = os.sysconf("SC_CLK_TCK")
    result: dict[str, float] = {}
    for task in os.listdir("/proc/self/task"):
        try:
            fields = Path(f"/proc/self/task/{task}/stat").read_text().rsplit(")", 1)[1].split()
        except OSError:  # the thread ended meanwhile
            continue
        name = names.get(int(task), "other")
        if "Dask-Default-Threads" in name:  # the worker's task thread
            name = "tasks"
        result[name] = result.get(name, 0.0) + (int(fields[11]) + int(fields[12])) / ticks  # utime + stime
    return result


def timed_block(shared, block):
    """The grid's task (:func:`thermogear.sweep.gearbox_grid.solve_block`) with its process, start, end and CPU."""
    from thermogear.sweep.gearbox_grid import solve_block

    start, cpu = time.time(), time.thread_time()
    result = solve_block(shared, block)
    return result, (os.getpid(), start, time.time(), time.thread_time() - cpu)


def _table(title: str, first: dict[str, float], last: dict[str, float]) -> None:
    print(f"  {title}")
    for name in sorted(last, key=lambda key: -last[key]):
        if last[name] >= 0.01:
            print(f"    {name:<24} {first.get(name, 0.0):7.2f} s to the first result, {last[name]:7.2f} s to the last")


def main() -> None:
    import numpy as np

    from thermogear.case import load_case
    from thermogear.gearbox.case_model import gearbox_model_from_case, gearbox_operating_point
    from thermogear.gearbox.sweep import solve_grid
    from thermogear.sweep import executor
    from thermogear.sweep.gearbox_grid import _DIMS, _blocks, _stored_arrays, gearbox_grid_layout
    from thermogear.sweep.task_store import TaskStore

    size, chunk_points = _option("grid-size", 45), _option("chunk-points", 250)
    if "--dask-defaults" in sys.argv:
        executor.QUIET_LOCAL_CLUSTER = {}
    warnings.simplefilter("ignore")
    case = load_case(str(DATA / "gearbox" / "fzg_gearbox.toml"))
    model = gearbox_model_from_case(case)
    ambient = gearbox_operating_point(case.operating_point, case.gearbox).ambient_c
    speeds, torques = np.linspace(300.0, 3000.0, size), np.linspace(10.0, 200.0, size)
    blocks = _blocks((size, size), chunk_points)
    settings = "quiet" if executor.QUIET_LOCAL_CLUSTER else "defaults"
    print(f"gearbox grid {size} x {size} = {size * size} points, {len(blocks)} tasks of up to {chunk_points} points, "
          f"load {os.getloadavg()[0]:.1f}, Dask settings: {settings}")
    solve_grid(model, speeds[:1], torques[:1], ambient)  # the serial run's imports, as in the benchmark
    cpu = time.process_time()
    solve_grid(model, speeds, torques, ambient)
    print(f"serial: {time.process_time() - cpu:.2f} s of CPU")

    shared = (model, speeds, torques, float(ambient))
    with tempfile.TemporaryDirectory(prefix="grid-cpu-") as folder:
        layout = gearbox_grid_layout(model, speeds, torques, ambient, chunk_points, case.name, str(case.source),
                                     case.document)
        store = TaskStore.open(Path(folder) / "grid.zarr", layout)
        tasks: list[tuple] = []
        snapshots: dict[str, dict] = {}

        def finished(index: int, result) -> None:
            arrays, timing = result
            tasks.append((index, *timing, time.time()))
            store.write(index, dict(zip(_DIMS, blocks[index])), _stored_arrays(arrays[0], False))
            if len(tasks) in (1, len(blocks)):
                from distributed import default_client

                key = "first" if len(tasks) == 1 else "last"
                snapshots[key] = {"driver": thread_cpu(), "workers": default_client().run(thread_cpu)}

        before, start = os.times(), time.time()
        executor.execute(timed_block, shared, blocks, finished, "processes", 2)
        after, seconds = os.times(), time.time() - start
    driver = after.user + after.system - before.user - before.system
    workers = after.children_user + after.children_system - before.children_user - before.children_system
    task_cpu = sum(task[4] for task in tasks)
    print(f"two workers: {seconds:.1f} s; CPU: driver {driver:.2f} s, worker processes {workers:.2f} s (their tasks "
          f"{task_cpu:.2f} s, the rest {workers - task_cpu:.2f} s)")
    print("  task CPU [s] in order: " + " ".join(f"{task[4]:.2f}" for task in sorted(tasks)))
    for pid in sorted({task[1] for task in tasks}):
        own = [task for task in tasks if task[1] == pid]
        print(f"  worker {pid}: {len(own)} tasks, first started at {min(t[2] for t in own) - start:.1f} s, "
              f"last ended at {max(t[3] for t in own) - start:.1f} s")
    _table("driver threads (CPU seconds since this process started)", snapshots["first"]["driver"],
           snapshots["last"]["driver"])
    for address, last in snapshots["last"]["workers"].items():
        _table(f"worker {address} threads", snapshots["first"]["workers"].get(address, {}), last)


if __name__ == "__main__":
    main()
