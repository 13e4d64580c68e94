"""The clusters of one column of the piece grouping against the value-by-value scan that defines them."""

from __future__ import annotations

import numpy as np
import pytest

from thermogear.dynamics.linear_algebra.piece_groups import _column_labels


def _scan(values: np.ndarray, width: float) -> np.ndarray:
    """The rule itself: sorted values, a new cluster where a value lies more than ``width`` above its cluster's
    first (the former implementation, value by value)."""
    order = np.argsort(values, kind="stable")
    labels = np.empty(values.size, dtype=np.int64)
    label, start = 0, values[order[0]] if values.size else 0.0
    for position in order:
        if values[position] - start > width:
            label, start = label + 1, values[position]
        labels[position] = label
    return labels


@pytest.mark.parametrize("width", [0.0, 1e-9, 3e-9, 0.5])
def test_column_labels_are_the_scan(width):
    rng = np.random.default_rng(17)
    columns = [np.array([]), np.array([2.0]), np.zeros(5), rng.normal(size=256),
               np.repeat(rng.normal(size=4), 30) + 1e-14 * rng.normal(size=120),  # levels repeated to the last bits
               np.arange(40) * 0.7e-9]  # a chain of small gaps spanning many widths: the scan's own order decides
    columns += [rng.permutation(np.cumsum(rng.exponential(size=int(rng.integers(2, 50))))) * scale
                for scale in (1e-10, 1e-9, 1.0) for _ in range(20)]
    for values in columns:
        assert np.array_equal(_column_labels(values, width), _scan(values, width))
