"""A worker plugin that ends a local worker process when the study's driver is gone (imported by the workers of a
local cluster only: it needs ``distributed``)."""

from __future__ import annotations

import os
import threading
import time

from distributed.diagnostics.plugin import WorkerPlugin

__all__ = ["DriverWatch"]

#: How often [s] a local worker process looks whether its driver is still there.
WATCH_INTERVAL_S = 0.25


class DriverWatch(WorkerPlugin):
    """A daemon thread in each local worker process that ends the process when the driver (the process that
    started the local cluster) is gone, so that no worker outlives its study however the driver ends: a worker
    otherwise waits for its lost scheduler for minutes. The worker processes of a local cluster are the driver's
    children, so a parent that changed means the driver ended (its number cannot have been reused while it is the
    parent); elsewhere the driver's process number is asked for."""

    name = "thermogear-driver-watch"
    idempotent = True

    def __init__(self, driver_pid: int) -> None:
        self.driver_pid = int(driver_pid)

    def setup(self, worker) -> None:
        threading.Thread(target=_watch, args=(self.driver_pid, os.getppid()), name="thermogear-driver-watch",
                         daemon=True).start()


def _watch(driver_pid: int, parent_pid: int) -> None:
    while True:
        if parent_pid == driver_pid:
            gone = os.getppid() != driver_pid
        else:
            try:
                os.kill(driver_pid, 0)
                gone = False
            except ProcessLookupError:
                gone = True
            except PermissionError:  # the number now belongs to another user's process: the driver is gone
                gone = True
        if gone:
            os._exit(0)
        time.sleep(WATCH_INTERVAL_S)
