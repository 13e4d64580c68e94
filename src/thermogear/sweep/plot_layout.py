"""Layout helpers of the study plots: axes scaled to the valid points, the others marked at the edge, and
resonance labels that do not overlap.

A point where a model does not hold (contact loss under the linear mesh, a parametric instability, no orbit
found) can carry a response hundreds of times the valid ones; scaled to it, the valid curves lie flat at zero.
The plots therefore scale each axis to the valid points and draw the others as grey markers: where they fall
inside the axis at their value, where they lie beyond it on the edge (a triangle pointing out of the axes).
"""

from __future__ import annotations

import numpy as np

__all__ = ["label_speeds", "mark_invalid", "scale_to_valid"]

_MARGIN = 0.08  # of the valid range, above and below
_INVALID_COLOR = "0.55"


def scale_to_valid(axis, valid_values, log_ratio: float = 50.0) -> tuple[float, float] | None:
    """Set the y-limits of ``axis`` to the finite ``valid_values`` with a margin (a log axis when they span more
    than ``log_ratio``, all positive); returns the limits, or None (axis untouched) without a valid value."""
    values = np.asarray(valid_values, dtype=float).ravel()
    values = values[np.isfinite(values)]
    if not values.size:
        return None
    low, high = float(values.min()), float(values.max())
    if low > 0.0 and high > log_ratio * low:
        axis.set_yscale("log")
        limits = (low / 1.3, high * 1.3)
    else:
        pad = _MARGIN * (high - low) or 0.05 * max(abs(high), 1e-12)
        limits = (low - pad, high + pad)
    axis.set_ylim(*limits)
    return limits


def mark_invalid(axis, x, values, limits: tuple[float, float] | None, label: str | None = None,
                 color: str = _INVALID_COLOR) -> None:
    """Pale markers of the points where the model does not hold (in ``color``, grey by default): an ``x`` at the
    value inside the limits, a triangle on the upper (lower) edge for a value beyond them (drawn outside the
    data clipping)."""
    x = np.asarray(x, dtype=float)
    values = np.asarray(values, dtype=float)
    finite = np.isfinite(values)
    if not finite.any():
        return
    low, high = limits if limits is not None else (-np.inf, np.inf)
    inside = finite & (values >= low) & (values <= high)
    above, below = finite & (values > high), finite & (values < low)
    style = dict(linestyle="none", color=color, alpha=0.4)
    axis.plot(x[inside], values[inside], marker="x", markersize=3.5, label=label, **style)
    if above.any():
        axis.plot(x[above], np.full(above.sum(), high), marker="^", markersize=4, clip_on=False,
                  label=None if inside.any() else label, **style)
    if below.any():
        axis.plot(x[below], np.full(below.sum(), low), marker="v", markersize=4, clip_on=False,
                  label=None if (inside.any() or above.any()) else label, **style)


def label_speeds(axis, marks, minimum_gap: float = 0.06, rows: int = 3) -> None:
    """Vertical dotted lines at ``marks`` = [(speed, text, color)] and their texts above the axes, each put on
    the lowest of ``rows`` rows where it keeps ``minimum_gap`` (a fraction of the axis width) from the texts
    already there, so that neighbouring marks (the same order of two models) stay readable."""
    low, high = axis.get_xlim()
    span = (high - low) or 1.0
    placed: list[list[float]] = [[] for _ in range(rows)]
    for speed, text, color in sorted(marks):
        if not low <= speed <= high:
            continue
        axis.axvline(speed, color=color, linewidth=0.7, alpha=0.6, linestyle=":")
        position = (speed - low) / span
        row = next((r for r in range(rows) if all(abs(position - p) >= minimum_gap for p in placed[r])), rows - 1)
        placed[row].append(position)
        axis.annotate(text, (speed, 1.0), xycoords=("data", "axes fraction"), xytext=(0, 2 + 9 * row),
                      textcoords="offset points", ha="center", va="bottom", fontsize=7, color=color,
                      annotation_clip=False)
