"""How long the command line took to start: the seconds from the process's start to the command's first line
(interpreter, thermogear's and typer's imports, argument parsing). The report lists them as its ``start-up``
stage, so that its ``timings_s`` cover the whole command."""

from __future__ import annotations

import os
import time

__all__ = ["seconds_since_process_start"]

#: When this module was imported (the command line imports it first): the fallback origin off Linux.
_IMPORTED = time.perf_counter()


def seconds_since_process_start() -> float:
    """Seconds since the process started [s]: from ``/proc`` on Linux (to the kernel's clock tick, 10 ms),
    elsewhere since the command line was imported (which leaves out the interpreter's own start)."""
    try:
        with open("/proc/self/stat", encoding="ascii") as stat:
            fields = stat.read().rsplit(")", 1)[1].split()  # after the command name, which may hold spaces
        with open("/proc/uptime", encoding="ascii") as uptime:
            now = float(uptime.read().split()[0])
        started = int(fields[19]) / os.sysconf("SC_CLK_TCK")  # field 22 of proc(5): start time after boot
        return max(0.0, now - started)
    except (OSError, ValueError, IndexError, AttributeError):
        return time.perf_counter() - _IMPORTED
