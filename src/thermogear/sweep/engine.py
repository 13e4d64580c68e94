"""Running a study on Dask: a local cluster by default, a ``dask.distributed`` scheduler by address, one path.

Every block (chunk) of the study is one task of the one executor (:mod:`thermogear.sweep.executor`). The driver
submits the blocks that the store has not marked done; each task computes its block and returns its arrays, and
the driver, the store's only writer process, writes them and then the block's marker as each task finishes (data
first, then the marker) and advances the progress bar; on threads of this process each thread writes the data of
its own block (whole zarr chunks) and the driver the marker. The tasks are pure functions of (study, block), so where they run
does not change a bit of the result: threads, a local cluster, a remote scheduler and a plain loop give the same
dataset.

Schedulers (``scheduler`` argument, ``--scheduler`` on the command line):

* ``None`` / ``"local"``: the local choice: ``"threads"`` where the study runs on the fast path (its kernel
  releases the GIL, and threads start at once and share the per-case tables), ``"processes"`` for one Simulation
  per point (``method="simulation"``, the points the fast path cannot take) or with a ``dashboard``;
* ``"threads"``: Dask's threaded scheduler in this process (all cores by default). Warnings raised in the workers
  are kept apart per thread (:mod:`thermogear.warning_scope`);
* ``"processes"``: a ``distributed.LocalCluster`` of worker processes (one thread each, all cores by default),
  started and closed by :func:`run_study` (a few seconds of start-up: worth it for long studies);
* ``"tcp://host:port"`` (any address a ``distributed.Client`` accepts): an existing scheduler and its workers;
* ``"serial"``: a plain loop in this process (debugging; the baseline of the benchmarks).
"""

from __future__ import annotations

from contextlib import ExitStack, contextmanager
from functools import cached_property
from pathlib import Path
from typing import Any, Callable, Iterator

import numpy as np

from thermogear import warning_scope
from thermogear.mesh.model import MeshModel
from thermogear.sweep.batch import evaluate_block, fast_path_applies
from thermogear.sweep.evaluation_methods import EVALUATION_METHODS, evaluation_method, is_batched
from thermogear.sweep.schedulers import Placement, PROCESSES, THREADS, Scheduler, check_dashboard
from thermogear.sweep.schedulers import scheduler as scheduler_named
from thermogear.sweep.store import ResultStore
from thermogear.warning_causes import WarningTally, warning_text

__all__ = ["StudyRun", "compute_block", "local_scheduler", "run_study"]

#: The evaluation methods by name (:mod:`thermogear.sweep.evaluation_methods`).
METHODS = tuple(EVALUATION_METHODS)


def compute_block(shared: tuple, block):
    """One task: the arrays of a block and the warnings raised computing it (``shared``: the study and the method;
    run on a worker, the arrays written by the driver)."""
    study, method = shared
    return evaluate_block(study, block, method)


def compute_and_store_block(shared: tuple, block):
    """One task on a thread of this process: compute a block and write its data through the driver's store (blocks
    are whole zarr chunks, so threads never write the same file; the driver marks the block once this returns).
    The thread that computed a block writes it, so Dask's scheduler thread never holds up the next task while it
    writes (a driver writing every block cost the two threads a third of their gain)."""
    study, method, store = shared
    arrays, messages = evaluate_block(study, block, method)
    store.write_data(block, arrays)
    return None, messages


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
    from thermogear.sweep.executor import execute

    evaluation_method(method)  # an unknown method is refused before anything is written
    kind = scheduler_named(scheduler, default=local_scheduler(study, method, dashboard))
    check_dashboard(kind, dashboard)  # refused before anything is written
    store = ResultStore.resume(out, study) if resume else ResultStore.create(out, study, overwrite=overwrite)
    blocks = study.blocks()
    done = store.done_blocks()
    pending = [block for block in blocks if block.number not in done]
    tally = WarningTally()  # once per cause: a friction warning at 10⁵ unit loads is one message

    with ExitStack() as stack:
        advance = stack.enter_context((progress or _no_progress)(
            study.size, sum(block.size for block in blocks if block.number in done)))
        store.open_arrays()

        def stored(index: int, result) -> None:  # data first (here, or by the thread), then the block's marker
            arrays, messages = result
            block = pending[index]
            if arrays is not None:
                store.write_data(block, arrays)
            store.mark_done(block)
            tally.update(messages)
            if on_block is not None:
                on_block(block.number)
            advance(block.size)

        if kind.placement is Placement.THREADS:  # the workers' warnings are kept apart per thread
            unscoped = stack.enter_context(warning_scope.routed())
            execute(compute_and_store_block, (study, method, store), pending, stored, kind, workers)
            stack.close()  # the router is gone: its unscoped warnings are final
            tally.update(warning_text(item) for item in unscoped)
        else:
            execute(compute_block, (study, method), pending, stored, kind, workers, dashboard)
    return StudyRun(store, tally.messages(), computed=len(pending), skipped=len(done), path=Path(out))


def local_scheduler(study, method: str, dashboard: str | None = None) -> Scheduler:
    """The local scheduler for a study: threads where every model of its case runs on the fast path (the
    numba kernel releases the GIL), processes otherwise (pure-Python points need processes to run in
    parallel) and wherever a dashboard is asked for (the Dask cluster serves it)."""
    if dashboard is None and is_batched(method) and fast_path_applies(MeshModel(study.case, model)
                                                                      for model in study.models):
        return THREADS
    return PROCESSES


