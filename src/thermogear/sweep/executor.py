"""The one executor of every study kind: a list of independent tasks run on Dask, their results handed back in order
of completion to the driver (the only writer of the store).

A task is ``function(shared, task)``: ``function`` a module-level function (it travels to worker processes by
name), ``shared`` what every task of the study reads (the study, the case document; sent once per worker) and
``task`` the small description of one task (a block, a group, a chunk of points). Each result returns to the
calling thread through ``on_result(index, result)`` as soon as its task finishes, so the driver writes a chunk and
advances the progress bar while the other tasks run. Where a task runs never changes a bit of its result: every
task runs with one BLAS thread (:func:`run_task`), and a task is a pure function of ``(shared, task)``.

Schedulers (:data:`thermogear.sweep.schedulers.SCHEDULERS`, chosen once by name; anything else is a
``dask.distributed`` scheduler address):

* ``"serial"``: a plain loop in the calling thread (debugging; the baseline of the benchmarks);
* ``"threads"``: Dask's threaded scheduler in this process (``workers`` threads, all cores by default): tasks whose
  kernels release Python's global interpreter lock (the compiled fast path, the backlash integrator) share the
  per-case tables and start at once;
* ``"processes"``: a ``distributed.LocalCluster`` of single-thread worker processes (all cores by default), started
  here and closed when the study ends; each worker watches this process and ends itself if it disappears
  (:class:`~thermogear.sweep.driver_watch.DriverWatch`), so killing the driver, SIGKILL included, leaves no worker behind;
* ``"tcp://host:port"``: the workers of an existing scheduler (they need thermogear importable).
"""

from __future__ import annotations

import os
import warnings
from collections.abc import Callable, Sequence
from contextlib import ExitStack, contextmanager
from functools import partial
from typing import Any

from thermogear.errors import CaseError
from thermogear.sweep.schedulers import Placement, SCHEDULERS, Scheduler, scheduler_help
from thermogear.sweep.schedulers import scheduler as resolve_scheduler

__all__ = ["LOCAL_SCHEDULERS", "QUIET_LOCAL_CLUSTER", "check_scheduler_address", "execute", "run_task",
           "run_task_on_worker"]

#: The schedulers of this machine (:data:`thermogear.sweep.schedulers.SCHEDULERS`); any other value is the address
#: of a ``dask.distributed`` scheduler.
LOCAL_SCHEDULERS = tuple(SCHEDULERS)
_THREAD_VARIABLES = ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS")


def run_task(function: Callable[..., Any], shared: Any, task: Any, *previous: Any) -> Any:
    """One task (``previous``: the result of the task it follows, in a chain). In this process it runs inside the
    one-BLAS-thread limit :func:`execute` holds; a task's numbers do not depend on the thread count of the linear
    algebra it calls, so a task gives the same bits in the driver, on a thread or in a worker process."""
    return function(shared, task, *previous)


_WORKER_LIMITED: list = []


def run_task_on_worker(function: Callable[..., Any], shared: Any, task: Any, *previous: Any) -> Any:
    """:func:`run_task` in a worker process: its BLAS is set to one thread the first time (a worker process runs
    only tasks, so the limit stays)."""
    if not _WORKER_LIMITED:
        from threadpoolctl import threadpool_limits

        _WORKER_LIMITED.append(threadpool_limits(limits=1, user_api="blas"))
    return function(shared, task, *previous)


def execute(function: Callable[..., Any], shared: Any, tasks: Sequence[Any],
            on_result: Callable[[int, Any], None], scheduler: str | Scheduler = "serial", workers: int | None = None,
            dashboard: str | None = None, follows: Sequence[int | None] | None = None) -> None:
    """Run ``function(shared, task)`` for every task on ``scheduler`` (module docstring) and call
    ``on_result(index, result)`` in the calling thread as each finishes. ``follows[i]``: the index (< i) of the
    task whose result task i continues from, called ``function(shared, task, previous_result)`` once that one is
    done (a branch followed point by point); None: independent. A task's error is raised here; the tasks not yet
    started are cancelled when one fails or the run is interrupted."""
    if not tasks:
        return
    follows = list(follows) if follows is not None else [None] * len(tasks)
    if any(f is not None and not 0 <= f < i for i, f in enumerate(follows)):
        raise ValueError("a task follows an earlier task only")
    kind = resolve_scheduler(scheduler)
    if kind.in_this_process:
        from threadpoolctl import threadpool_limits

        with threadpool_limits(limits=1, user_api="blas"):  # for the study only: restored after it
            if kind.placement is Placement.THREADS:
                _threads(function, shared, tasks, follows, on_result, kind.worker_count(workers))
                return
            kind.worker_count(workers)  # the calling thread: one worker
            results: dict[int, Any] = {}
            followed = {follow for follow in follows if follow is not None}
            for index, task in enumerate(tasks):
                previous = () if follows[index] is None else (results[follows[index]],)
                results[index] = run_task(function, shared, task, *previous)
                on_result(index, results[index])
                if index not in followed:  # no task continues from it: let it go
                    results.pop(index)
        return
    with _client(kind, workers, dashboard) as client:
        _distributed(client, function, shared, tasks, follows, on_result)


def _threads(function, shared, tasks, follows, on_result, count: int) -> None:
    """Dask's threaded scheduler; each result reaches ``on_result`` from Dask's post-task callback, which runs in
    the calling thread."""
    import dask
    from dask.callbacks import Callback

    keys = [f"thermogear-task-{index}" for index in range(len(tasks))]
    graph = {key: (partial(run_task, function, shared, task),) + (() if follow is None else (keys[follow],))
             for key, task, follow in zip(keys, tasks, follows)}
    numbers = {key: index for index, key in enumerate(keys)}

    class _Handed(Callback):
        def _posttask(self, key, result, graph, state, worker_id) -> None:
            on_result(numbers[key], result)

    from dask.threaded import get

    with dask.config.set(scheduler="threads"), _Handed():
        get(graph, keys, num_workers=min(count, len(tasks)))


def _distributed(client, function, shared, tasks, follows, on_result) -> None:
    import uuid

    from distributed import as_completed

    remote = client.scatter(shared, broadcast=True, hash=False)
    run = uuid.uuid4().hex
    submitted: list = []
    for index, task in enumerate(tasks):
        previous = () if follows[index] is None else (submitted[follows[index]],)
        submitted.append(client.submit(run_task_on_worker, function, remote, task, *previous, pure=False,
                                       key=f"thermogear-task-{run}-{index}"))
    futures = {future: index for index, future in enumerate(submitted)}
    try:
        for future in as_completed(futures):
            on_result(futures.pop(future), future.result())
    finally:
        client.cancel(list(futures))


_TRIM = "MALLOC_TRIM_THRESHOLD_"


@contextmanager
def _one_blas_thread_environment():
    """The worker processes start with one BLAS thread (NumPy reads the variables when it is first imported), and
    with glibc's own heap trimming: the nanny's default ``MALLOC_TRIM_THRESHOLD_`` (65536) also fixes the mmap
    threshold, so every array above it is mapped afresh and faulted in page by page — the drivetrain's chunks of
    exponentials ran 1.4× slower in a worker than in a plain process (3.1–3.9 s against 2.1–2.9 s a task)."""
    import dask

    saved = {name: os.environ.get(name) for name in (*_THREAD_VARIABLES, _TRIM)}
    os.environ.update({name: "1" for name in _THREAD_VARIABLES})
    os.environ.pop(_TRIM, None)  # a cluster started before in this process leaves the nanny's value in os.environ
    environment = {name: value for name, value in dask.config.get("distributed.nanny.pre-spawn-environ", {}).items()
                   if name != _TRIM}
    try:
        with dask.config.set({"distributed.nanny.pre-spawn-environ": environment}):
            yield
    finally:
        for name, value in saved.items():
            if value is None:
                os.environ.pop(name, None)
            else:
                os.environ[name] = value


#: Dask's settings for a study's own local cluster when it serves no dashboard. Measured on two cores (a gearbox
#: grid of 2000 points in blocks of 250 on two workers, CPU seconds from the first result to the last): the driver's
#: event loop (scheduler, nannies, client) 0.9–1.1 s and each worker's event loop 0.7–0.8 s with Dask's defaults,
#: 0.3 s and 0.15 s with these; an idle cluster took 1.3 s of CPU per 10 s with the defaults, 0.1–0.14 s with them.
#: That CPU is taken from the workers' cores. Each setting only feeds what a dashboard shows or a check that keeps
#: its meaning at the longer interval:
#:
#: * the workers' statistical profiler (a sample of the running task's stack every 10 ms, for the dashboard's
#:   profile page);
#: * the event-loop tick every 1 s instead of 20 ms (it measures how long the loop was blocked; Dask warns only
#:   beyond ``distributed.admin.tick.limit``, 3 s, which 1 s still resolves);
#: * the system monitor (CPU, memory, network and disk counters for the dashboard) every 5 s instead of 0.5 s;
#: * the memory monitors of the workers and their nannies (pause, spill, terminate) every 0.5 s instead of 0.1 s.
QUIET_LOCAL_CLUSTER = {
    "distributed.worker.profile.enabled": False,
    "distributed.admin.tick.interval": "1s",
    "distributed.admin.system-monitor.interval": "5s",
    "distributed.worker.memory.monitor-interval": "500ms",
}


@contextmanager
def _client(scheduler: str | Scheduler, workers: int | None, dashboard: str | None):
    """A ``distributed.Client`` on a new LocalCluster (closed with it) or on a scheduler address."""
    from distributed import Client, LocalCluster

    kind = resolve_scheduler(scheduler)
    count = kind.worker_count(workers)  # a count a remote scheduler cannot take is refused before connecting
    with ExitStack() as stack:
        if kind.placement is Placement.LOCAL_CLUSTER:
            import logging

            # a worker that takes a moment to stop when the study closes the cluster is no news to the user
            logging.getLogger("distributed.nanny").setLevel(logging.ERROR)
            import dask

            quiet = QUIET_LOCAL_CLUSTER if dashboard is None else {}  # a dashboard shows what they feed
            # the nannies hand the settings of their creation to the worker processes they spawn
            with warnings.catch_warnings(), _one_blas_thread_environment(), dask.config.set(quiet):
                warnings.simplefilter("ignore")
                cluster = stack.enter_context(LocalCluster(
                    n_workers=count, threads_per_worker=1, processes=True,
                    dashboard_address=dashboard))
                client = stack.enter_context(Client(cluster))
            from thermogear.sweep.driver_watch import DriverWatch

            client.register_plugin(DriverWatch(os.getpid()))
        else:
            client = stack.enter_context(Client(kind.name, timeout="30s"))
        yield client


def check_scheduler_address(address: str | None, timeout: float = 5.0) -> None:
    """Refuse a ``tcp://host:port`` scheduler that does not accept connections, before anything is written (one
    connection attempt naming the address, instead of the client's retries for its whole timeout)."""
    if resolve_scheduler(address).placement is not Placement.REMOTE:
        return
    import socket
    from urllib.parse import urlsplit

    parts = urlsplit(address if "://" in address else f"tcp://{address}")
    if parts.scheme not in ("tcp", "tls"):
        return
    allowed = f"a dask.distributed scheduler address tcp://host:port, or {scheduler_help()}"
    try:
        host, port = parts.hostname, parts.port
    except ValueError:
        host, port = None, None
    if not host or port is None:
        raise CaseError("--scheduler", address, allowed, "the address needs a host and a port")
    try:
        with socket.create_connection((host, port), timeout=timeout):
            pass
    except OSError as error:
        raise CaseError("--scheduler", address, allowed,
                        f"no scheduler answers there ({error.strerror or error}); nothing was written") from None
