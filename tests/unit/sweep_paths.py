"""Shared check of the sweep tests: the fast path against one Simulation per point on the first block of a study."""

from __future__ import annotations

import warnings

import numpy as np

from thermogear.sweep.batch import MODEL_VARIABLES, POINT_VARIABLES, evaluate_block


def assert_fast_path_equals_simulation(study, label: str = "") -> dict[str, np.ndarray]:
    """Compare every stored variable of the first block on both paths; returns the fast path's arrays.

    Both paths ask the same mesh model and evaluate the same exact periodic orbit at the same samples; only
    rounding separates them (measured below 1e-13), so 1e-9 relative is the issue's bound with a wide margin. NaN
    (unstable points) must sit at the same places."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        fast, _ = evaluate_block(study, study.blocks()[0], "batch")
        slow, _ = evaluate_block(study, study.blocks()[0], "simulation")
    for variable in (*MODEL_VARIABLES, *POINT_VARIABLES):
        a, b = np.asarray(fast[variable], float), np.asarray(slow[variable], float)
        assert np.array_equal(np.isfinite(a), np.isfinite(b)), (label, variable)
        finite = np.isfinite(b)
        assert np.all(np.abs(a[finite] - b[finite]) <= 1e-9 * np.maximum(np.abs(b[finite]), 1e-300)), (label, variable)
    return fast
