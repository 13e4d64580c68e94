"""The inputs a continuation over an ordered sequence checks, the same for the 1-DOF problems
(:mod:`~.backlash_continuation`) and the n-DOF systems (:mod:`~.backlash_branch_ndof`): the sweep direction, a
non-empty sequence and one label per item; and the order in which the items are visited."""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np

from thermogear.dynamics.problems.continuation_directions import DIRECTIONS
from thermogear.errors import ProblemError

__all__ = ["continuation_labels", "continuation_order"]


def continuation_labels(direction: str, count: int, parameter: Sequence[float] | None, noun: str) -> np.ndarray:
    """(count,) labels of the items (``parameter``, or 0, 1, … without one) after checking ``direction`` ("up" from
    the first item to the last, "down" back) and ``count`` >= 1; ``noun`` names an item in the errors."""
    if direction not in DIRECTIONS:
        raise ProblemError("direction", direction, " | ".join(DIRECTIONS),
                           f"sweep from the first {noun} to the last or back")
    if count == 0:
        raise ProblemError(f"{noun}s", "empty", f">= 1 {noun}", "nothing to follow")
    labels = np.arange(count, dtype=float) if parameter is None else np.asarray(parameter, dtype=float)
    if labels.shape != (count,):
        raise ProblemError("parameter", f"shape {labels.shape}", f"({count},)", f"one label per {noun}")
    return labels


def continuation_order(direction: str, count: int) -> range:
    """The items' indices in the order a continuation visits them: ascending "up", descending "down"."""
    return DIRECTIONS[direction].order(count)
