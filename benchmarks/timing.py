"""Timing helper shared by the benchmark scripts (run as `python benchmarks/NAME.py`, so this folder is on the path)."""

from __future__ import annotations

import time

import numpy as np


def wall_times(function, repeat: int) -> np.ndarray:
    """Wall-clock seconds of ``repeat`` calls of ``function`` (no arguments), one value per call."""
    values = []
    for _ in range(repeat):
        start = time.perf_counter()
        function()
        values.append(time.perf_counter() - start)
    return np.array(values)


def compile_bytecode(*sources) -> bool:
    """Compile the bytecode of thermogear (and of each further ``sources`` folder) before whole commands are timed,
    as ``pip install`` does for an installed package. Where PYTHONDONTWRITEBYTECODE is set (this project's
    development machine sets it) an editable install otherwise compiles every module changed since its last cached
    bytecode in every timed process: about 160 modules and 0.3 s of a ``run`` after a day's edits, a cost no
    installed package pays. Returns True where every folder compiled."""
    import compileall
    from pathlib import Path

    import thermogear

    folders = [Path(thermogear.__file__).resolve().parent, *(Path(source) for source in sources)]
    return all(compileall.compile_dir(str(folder), quiet=1) for folder in folders)
