"""The schedulers a study runs on, chosen once by name (``--scheduler``; issue 33: every choice resolved once from a
registry, never compared as a string): each entry says what the executor and the study drivers ask of it.

* ``"serial"``: a plain loop in the calling thread (debugging; the baseline of the benchmarks): one worker;
* ``"threads"``: Dask's threaded scheduler in this process (``workers`` threads, all cores by default): the warnings
  of the tasks are kept apart per thread (:mod:`thermogear.warning_scope`), and each thread writes its own block;
* ``"processes"``: a ``distributed.LocalCluster`` of single-thread worker processes (all cores by default), started
  for the study and closed when it ends; the only one that serves a Bokeh dashboard;
* any other value: the address of a running ``dask.distributed`` scheduler (``tcp://host:port``), whose workers
  are its own (no ``--workers``).

``None``, ``""`` and ``"local"`` ask for the caller's local default (each study kind names its own:
:func:`scheduler`'s ``default``). A new scheduler is one entry of :data:`SCHEDULERS`.
"""

from __future__ import annotations

import os
from dataclasses import dataclass, replace

from thermogear.errors import CaseError

__all__ = ["ADDRESS", "LOCAL_DEFAULT_NAMES", "PROCESSES", "SCHEDULERS", "SERIAL", "THREADS", "Scheduler",
           "check_dashboard", "scheduler", "scheduler_help"]


@dataclass(frozen=True)
class Scheduler:
    """One scheduler of a study: ``name`` (the ``--scheduler`` value: a registered name, or the address of a
    remote scheduler) and what the callers branch on:

    * ``calling_thread``: the tasks run one after the other in the calling thread (one worker at most);
    * ``threads``: the tasks run on threads of this process (their warnings are routed per thread);
    * ``local_cluster``: a ``distributed.LocalCluster`` is started here and closed with the study (it serves a
      dashboard where asked);
    * ``remote``: the tasks run on the workers of a scheduler at the address ``name`` (they are its own).

    The first two run in this process, which holds one BLAS thread for the study."""

    name: str
    calling_thread: bool = False
    threads: bool = False
    local_cluster: bool = False
    remote: bool = False

    @property
    def in_this_process(self) -> bool:
        """Whether the tasks run in this process (the calling thread or its threads)."""
        return self.calling_thread or self.threads

    @property
    def serves_dashboard(self) -> bool:
        """Whether a dashboard can be served (the local Dask cluster's)."""
        return self.local_cluster

    def worker_count(self, workers: int | None) -> int | None:
        """The threads or processes to start for ``workers`` (None: every core); 1 for the calling thread; None for a
        remote scheduler (its workers are its own). A CaseError naming ``--workers`` where the count cannot apply."""
        if self.calling_thread:
            if workers not in (None, 1):
                raise CaseError("--workers", workers, f"absent (or 1) with --scheduler {self.name}",
                                "the serial scheduler computes in the calling thread")
            return 1
        if self.remote:
            if workers is not None:
                raise CaseError("--workers", workers, "only with a local scheduler (threads or processes)",
                                "a remote scheduler has its own workers")
            return None
        return int(workers or os.cpu_count() or 1)


SERIAL = Scheduler("serial", calling_thread=True)
THREADS = Scheduler("threads", threads=True)
PROCESSES = Scheduler("processes", local_cluster=True)
#: The kind of every value that names no scheduler of this machine: the address of a dask.distributed scheduler.
ADDRESS = Scheduler("address", remote=True)

#: The schedulers of this machine by name: the one place their names are compared.
SCHEDULERS: dict[str, Scheduler] = {kind.name: kind for kind in (SERIAL, THREADS, PROCESSES)}
#: The values that ask for the caller's local default.
LOCAL_DEFAULT_NAMES = ("", "local")


def scheduler(name: "str | Scheduler | None", default: Scheduler = SERIAL) -> Scheduler:
    """The scheduler named ``name``: a registered one, ``default`` for None, ``""`` or ``"local"``, else the remote
    scheduler at the address ``name`` (a Scheduler already resolved is returned as it is)."""
    if isinstance(name, Scheduler):
        return name
    if name is None or name in LOCAL_DEFAULT_NAMES:
        return default
    return SCHEDULERS.get(name) or replace(ADDRESS, name=name)


def check_dashboard(kind: Scheduler, dashboard: str | None) -> None:
    """Refuse a ``dashboard`` address (CaseError naming ``--dashboard``) where the scheduler ``kind`` serves none."""
    if dashboard is not None and not kind.serves_dashboard:
        raise CaseError("--dashboard", dashboard, "only with the local Dask cluster (--scheduler processes)",
                        f"the {kind.name} scheduler serves no dashboard of its own")


def scheduler_help() -> str:
    """The registered names as the command line lists them (``serial | threads | processes``)."""
    return " | ".join(SCHEDULERS)
