"""Running a study on Dask: a local cluster by default, a ``dask.distributed`` scheduler by address, one path.

Every block (chunk) of the study is one task. The driver submits the blocks that the store has not marked done;
each task computes its block and writes the block's data into the store itself (blocks are whole zarr chunks, so
workers never write the same file), and the driver writes the block's marker when the task has returned (data
first, then the marker) and shows a progress bar. Nothing but the warnings travels back, so the driver stays
idle and the workers have the cores. The tasks are pure functions of (study, block), so where they run does not
change a bit of the result: threads, a local cluster, a remote scheduler and a plain loop give the same dataset.

Schedulers (``scheduler`` argument, ``--scheduler`` on the command line):

* ``None`` / ``"local"``: the local choice: ``"threads"`` where the study runs on the fast path (its kernel
  releases the GIL, and threads start at once and share the per-case tables), ``"processes"`` for one Simulation
  per point (``method="simulation"``, the points the fast path cannot take) or with a ``dashboard``;
* ``"threads"``: a pool of worker threads in this process (all cores by default). Warnings raised in the workers
  are kept apart per thread (:mod:`thermogear.warning_scope`);
* ``"processes"``: a ``distributed.LocalCluster`` of worker processes (one thread each, all cores by default),
  started and closed by :func:`run_study` (a few seconds of start-up: worth it for long studies);
* ``"tcp://host:port"`` (any address a ``distributed.Client`` accepts): an existing scheduler and its workers;
* ``"serial"``: a plain loop in this process (debugging; the baseline of the benchmarks).
"""

from __future__ import annotations

import os
import warnings
from contextlib import ExitStack, contextmanager
from functools import cached_property
from pathlib import Path
from typing import Any, Callable, Iterator

import numpy as np

from thermogear import warning_scope
from thermogear.errors import CaseError
from thermogear.mesh.model import MeshModel
from thermogear.sweep.batch import evaluate_block, fast_path_applies
from thermogear.sweep.store import ResultStore
from thermogear.warning_causes import WarningTally, warning_text

__all__ = ["StudyRun", "compute_block", "compute_and_write_block", "local_scheduler", "run_study"]

METHODS = ("batch", "simulation")


def compute_block(study, block, method: str = "batch"):
    """One task: the arrays of a block and the warnings raised computing it (run on a worker)."""
    return evaluate_block(study, block, method)


def compute_and_write_block(study, block, method: str, path: str) -> list[str]:
    """One task of a Dask run: compute a block, write its data into the store at ``path`` (not its marker: the
    driver writes it once this returns) and return the warnings raised computing it (run on a worker)."""
    return _compute_and_store(study, block, method, ResultStore(path, study))


class StudyRun:
    """What a finished :func:`run_study` returns: the dataset (opened with xarray when first asked for, each
    variable read from the store when used, so a study of 10⁶ points is not held in memory), single variables as
    NumPy arrays (:meth:`read`: no xarray), the warnings, and how much was computed."""

    def __init__(self, store: ResultStore, messages: list[str], computed: int, skipped: int, path: Path) -> None:
        self.store = store
        self.messages = messages
        self.computed = computed
        self.skipped = skipped
        self.path = path

    @cached_property
    def dataset(self):
        """The results as a lazily loaded xarray Dataset (xarray is imported here, not by the run)."""
        return self.store.dataset(lazy=True)

    def read(self, name: str) -> np.ndarray:
        """The variable ``name`` as a NumPy array, dims ``(model, *parameters)`` or ``(*parameters)``."""
        return self.store.read(name)


@contextmanager
def _no_progress(total: int, completed: int) -> Iterator:
    yield lambda points=1: None


def run_study(study, out: str | Path, scheduler: str | None = None, resume: bool = False, overwrite: bool = False,
              workers: int | None = None, method: str = "batch", progress: Callable | None = None,
              on_block: Callable[[int], Any] | None = None, dashboard: str | None = None) -> StudyRun:
    """Compute a study into the zarr store ``out`` and return the dataset.

    ``resume``: continue the study stored at ``out`` (finished blocks are kept and not recomputed).
    ``scheduler``: see the module docstring. ``workers``: threads or processes of the local scheduler (default: all
    cores). ``method``: ``"batch"`` (fast path) or ``"simulation"`` (one Simulation per point).
    ``on_block(number)`` is called after each block is stored.
    ``dashboard``: address of the local cluster's Bokeh dashboard (e.g. ``":8787"``); None (default): none is
    started, so a study opens no port unless asked. ``progress(total, completed)``: a context manager that yields
    ``advance(points)`` (the command line passes its progress bar; None: no progress shown).
    """
    if method not in METHODS:
        raise CaseError("method", method, " | ".join(METHODS), "unknown evaluation method")
    kind = local_scheduler(study, method, dashboard) if scheduler in (None, "", "local") else scheduler
    if dashboard is not None and kind != "processes":  # refused before anything is written
        raise CaseError("--dashboard", dashboard, "only with the local Dask cluster (--scheduler processes)",
                        f"the {kind} scheduler serves no dashboard of its own")
    store = ResultStore.resume(out, study) if resume else ResultStore.create(out, study, overwrite=overwrite)
    blocks = study.blocks()
    done = store.done_blocks()
    pending = [block for block in blocks if block.number not in done]
    tally = WarningTally()  # once per cause: a friction warning at 10⁵ unit loads is one message

    def marked(block, messages) -> None:  # the block's data are stored: mark it, count its warnings
        store.mark_done(block)
        tally.update(messages)
        if on_block is not None:
            on_block(block.number)

    with ExitStack() as stack:
        advance = stack.enter_context((progress or _no_progress)(
            study.size, sum(block.size for block in blocks if block.number in done)))
        if pending and kind == "serial":
            for block in pending:
                arrays, messages = compute_block(study, block, method)
                store.write_data(block, arrays)
                marked(block, messages)
                advance(block.size)
        elif pending and kind == "threads":
            from concurrent.futures import ThreadPoolExecutor, as_completed

            store.open_arrays()  # opened here, so the workers never touch zarr's warning filters
            unscoped = stack.enter_context(warning_scope.routed())
            pool = stack.enter_context(ThreadPoolExecutor(_worker_count(workers), "thermogear-study"))
            futures = {pool.submit(_compute_and_store, study, block, method, store): block for block in pending}
            _collect(futures, as_completed, marked, advance)
            stack.close()  # the pool has finished and the router is gone: its unscoped warnings are final
            tally.update(warning_text(item) for item in unscoped)
        elif pending:
            client = stack.enter_context(_client(kind, workers, dashboard))
            from distributed import as_completed

            shared = client.scatter(study, broadcast=True, hash=False)
            futures = {client.submit(compute_and_write_block, shared, block, method, str(store.path), pure=False):
                       block for block in pending}
            try:
                _collect(futures, as_completed, marked, advance)
            finally:
                client.cancel(list(futures))
    return StudyRun(store, tally.messages(), computed=len(pending), skipped=len(done), path=Path(out))


def local_scheduler(study, method: str, dashboard: str | None = None) -> str:
    """The local scheduler for a study: ``"threads"`` where every model of its case runs on the fast path (the
    numba kernel releases the GIL), ``"processes"`` otherwise (pure-Python points need processes to run in
    parallel) and wherever a dashboard is asked for (the Dask cluster serves it)."""
    if dashboard is None and method == "batch" and fast_path_applies(MeshModel(study.case, model)
                                                                      for model in study.models):
        return "threads"
    return "processes"


def _worker_count(workers: int | None) -> int:
    return workers or os.cpu_count() or 1


def _compute_and_store(study, block, method: str, store) -> list[str]:
    """Compute a block and write its data (not its marker) through ``store``; returns its warnings."""
    arrays, messages = evaluate_block(study, block, method)
    store.write_data(block, arrays)
    return messages


def _collect(futures: dict, as_completed: Callable, marked: Callable, advance: Callable) -> None:
    """Mark each block as its task returns (a task's error is raised here: its block stays unmarked); the tasks
    not yet started are cancelled when one fails or the run is interrupted."""
    try:
        for future in as_completed(futures):
            block = futures.pop(future)
            marked(block, future.result())
            advance(block.size)
    finally:
        for future in futures:
            future.cancel()


def _client(scheduler: str | None, workers: int | None, dashboard: str | None = None):
    """A distributed Client: on a new LocalCluster (closed with the client; a dashboard only at ``dashboard``)
    or on a scheduler address."""
    from distributed import Client, LocalCluster

    if scheduler == "processes":
        count = _worker_count(workers)
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            cluster = LocalCluster(n_workers=count, threads_per_worker=1, processes=True, dashboard_address=dashboard)
        return _OwnedClient(Client(cluster), cluster)
    if workers is not None:
        raise CaseError("workers", workers, "only with a local scheduler (threads or processes)",
                        "a remote scheduler has its own workers")
    return Client(scheduler, timeout="30s")


class _OwnedClient:
    """Context manager closing a client and the local cluster it was started on."""

    def __init__(self, client, cluster) -> None:
        self.client = client
        self.cluster = cluster

    def __enter__(self):
        return self.client

    def __exit__(self, *exc) -> None:
        self.client.close()
        self.cluster.close()
