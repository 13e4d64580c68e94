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
