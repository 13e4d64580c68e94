"""How long the command line took to start: the seconds from Python's first import of thermogear to the command's
first line (thermogear's and typer's imports, argument parsing). The report lists them as its ``start-up`` stage,
so that its ``timings_s`` cover the command from there.

The interpreter's own start before that (about 20 ms) is left out on purpose. The process's start time in
``/proc/self/stat`` is not the interpreter's: a shell that runs ``pip install . && thermogear reproduce luo2019`` as
one ``bash -c`` hands its own process to the last command (exec), and the process then "started" before pip ran, so
summary.json counted the install as start-up (issue 36).
"""

from __future__ import annotations

import time

import thermogear

__all__ = ["seconds_since_import"]


def seconds_since_import() -> float:
    """Seconds since Python began importing thermogear [s] (module docstring)."""
    return time.perf_counter() - thermogear.IMPORT_STARTED
