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
from enum import Enum

from thermogear.errors import CaseError

__all__ = ["ADDRESS", "LOCAL_DEFAULT_NAMES", "PROCESSES", "Placement", "SCHEDULERS", "SERIAL", "THREADS", "Scheduler",
           "check_dashboard", "scheduler", "scheduler_help"]


class Placement(Enum):
    """Where the tasks of a study run (one of four, the callers branch on which):

    * ``CALLING_THREAD``: one after the other in the calling thread (one worker at most);
    * ``THREADS``: on threads of this process (their warnings are routed per thread);
    * ``LOCAL_CLUSTER``: on a ``distributed.LocalCluster`` started here and closed with the study (it serves a
      dashboard where asked);
    * ``REMOTE``: on the workers of a scheduler at an address (they are its own).

    The first two run in this process, which holds one BLAS thread for the study."""

    CALLING_THREAD = "calling thread"
    THREADS = "threads"
    LOCAL_CLUSTER = "local cluster"
    REMOTE = "remote"


@dataclass(frozen=True)
class Scheduler:
    """One scheduler of a study: ``name`` (the ``--scheduler`` value: a registered name, or the address of a
    remote scheduler) and where it runs the tasks (:class:`Placement`)."""

    name: str
    placement: Placement

    @property
    def in_this_process(self) -> bool:
        """Whether the tasks run in this process (the calling thread or its threads)."""
        return self.placement in (Placement.CALLING_THREAD, Placement.THREADS)

    @property
    def serves_dashboard(self) -> bool:
        """Whether a dashboard can be served (the local Dask cluster's)."""
        return self.placement is Placement.LOCAL_CLUSTER

    def worker_count(self, workers: int | None) -> int | None:
        """The threads or processes to start for ``workers`` (None: every core); 1 for the calling thread; None for a
        remote scheduler (its workers are its own). A CaseError naming ``--workers`` where the count cannot apply."""
        if self.placement is Placement.CALLING_THREAD:
            if workers not in (None, 1):
                raise CaseError("--workers", workers, f"absent (or 1) with --scheduler {self.name}",
                                "the serial scheduler computes in the calling thread")
            return 1
        if self.placement is Placement.REMOTE:
            if workers is not None:
                raise CaseError("--workers", workers, "only with a local scheduler (threads or processes)",
                                "a remote scheduler has its own workers")
            return None
        return int(workers or os.cpu_count() or 1)


SERIAL = Scheduler("serial", Placement.CALLING_THREAD)
THREADS = Scheduler("threads", Placement.THREADS)
PROCESSES = Scheduler("processes", Placement.LOCAL_CLUSTER)
#: The kind of every value that names no scheduler of this machine: the address of a dask.distributed scheduler.
ADDRESS = Scheduler("address", Placement.REMOTE)

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
