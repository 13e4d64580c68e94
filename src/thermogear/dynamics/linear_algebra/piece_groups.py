"""Intervals of a piecewise-constant period grouped within a tolerance, so that nearly equal intervals share one
matrix exponential.

A k(τ) from a table, a measurement, another tool or a finite-element contact analysis repeats its few levels only
to the last bits (a spread of 1e-13 is typical): bit-identical grouping would take one exponential per interval.
:func:`group_rows` groups the rows (one per interval: duration h_j, k_j, c_j, g_j, …) whose every column lies
within ``tolerance`` × that column's largest magnitude of one representative row, and the solvers then use the
representative's values for the whole group.

What that changes, to first order (the perturbation of a linear periodic system; Nayfeh & Mook, Nonlinear
Oscillations, 1979, §5.2, for the Floquet form): the solved system differs from the given one by Δk_j, Δc_j, Δg_j
with |Δk_j| ≤ ε·k_max, |Δc_j| ≤ ε·c_max, |Δg_j| ≤ ε·g_max and the piece boundaries moved by at most ε·h_max each,
ε = ``tolerance``. The change Δq of the periodic orbit is the orbit of the same system under the extra load
−(Δk·wᵀq + Δc·wᵀq̇ − Δg)·w, whose size is at most ε·(k_max·|δ|_max + c_max·|δ̇|_max + g_max) against the load
W + g of the orbit itself (δ = wᵀq). A moved boundary exchanges k_j and k_{j+1} over ε·h_max, the same as a
change of ε·h_max/h_j in the piece's mean coefficients, which the bound covers with h_max/h_min for 1. The
response to the extra load is at most the dynamic amplification A of the system (the peak of the mesh receptance
over the static one; 1/(2ζ) at a resonance of damping ratio ζ) times its static response, so

    |Δδ|_max / |δ|_max ≤ ε · (h_max/h_min) · A · (k_max·|δ|_max + c_max·|δ̇|_max + g_max) / (k_min·|δ|_min)

(:func:`grouping_bound`). With the default ε = 1e-9 the change lies many orders below the accuracy of any measured
or computed stiffness; ``tolerance = 0`` restores grouping of bit-identical intervals only. Knows nothing of gears:
arrays only.
"""

from __future__ import annotations

import numpy as np

from thermogear.errors import ProblemError

__all__ = ["PIECE_TOLERANCE", "grouping_bound", "group_rows", "representative_rows"]

#: Default relative tolerance ε within which two intervals share one exponential.
PIECE_TOLERANCE = 1e-9


def _column_labels(values: np.ndarray, width: float) -> np.ndarray:
    """Labels of the clusters of one column: sorted values, a new cluster where a value lies more than ``width``
    above its cluster's first (so every cluster spans at most ``width``). A gap above ``width`` between neighbours
    always starts a cluster, and a run between such gaps that spans at most ``width`` is one cluster; only a run
    that spans more is scanned value by value (the rule's own order), so the labels are those of the scan."""
    order = np.argsort(values, kind="stable")
    ordered = values[order]
    starts = np.zeros(values.size, dtype=bool)
    starts[1:] = np.diff(ordered) > width
    runs = np.flatnonzero(np.append(True, starts[1:])) if values.size else np.zeros(0, dtype=np.int64)
    ends = np.append(runs[1:], values.size)
    wide = ordered[ends - 1] - ordered[runs] > width if values.size else np.zeros(0, dtype=bool)
    for first, end in zip(runs[wide].tolist(), ends[wide].tolist()):
        start = ordered[first]
        for position in range(first + 1, end):
            if ordered[position] - start > width:
                starts[position], start = True, ordered[position]
    labels = np.empty(values.size, dtype=np.int64)
    labels[order] = np.cumsum(starts)
    return labels


def group_rows(rows: np.ndarray, tolerance: float = PIECE_TOLERANCE) -> tuple[np.ndarray, np.ndarray]:
    """(distinct (D, q), where (N,)): the representative rows of the groups of ``rows`` (N, q) and each row's group,
    ``distinct[where]`` ≈ ``rows`` within ``tolerance`` × each column's largest magnitude (module docstring). With
    ``tolerance = 0`` exactly ``np.unique(rows, axis=0, return_inverse=True)``; with any tolerance the distinct rows
    come sorted as np.unique sorts them, and bit-identical rows always share a group."""
    rows = np.asarray(rows, dtype=float)
    if not np.isfinite(tolerance) or tolerance < 0.0 or tolerance > 1e-3:
        raise ProblemError("piece_tolerance", tolerance, "0 to 1e-3", "the relative spread within which "
                           "intervals share one exponential")
    if tolerance == 0.0 or rows.shape[0] < 2:
        distinct, where = np.unique(rows, axis=0, return_inverse=True)
        return distinct, where.ravel()
    exact, exact_where = np.unique(rows, axis=0, return_inverse=True)  # identical rows first: fewer to cluster
    exact_where = exact_where.ravel()
    scales = np.abs(exact).max(axis=0)
    labels = np.column_stack([_column_labels(exact[:, column], tolerance * scales[column])
                              for column in range(exact.shape[1])])
    _, first, group = np.unique(labels, axis=0, return_index=True, return_inverse=True)
    representatives = exact[first]
    distinct, order = np.unique(representatives, axis=0, return_inverse=True)
    return distinct, order.ravel()[group.ravel()][exact_where]


def representative_rows(rows: np.ndarray, tolerance: float = PIECE_TOLERANCE) -> np.ndarray:
    """(N,) for each row of ``rows`` (N, q) the index of the first row of its group (:func:`group_rows`): a solver
    that caches per interval can take the representative's matrices for every member."""
    _, where = group_rows(rows, tolerance)
    first = np.full(int(where.max()) + 1 if where.size else 0, -1)
    for index, group in enumerate(where.tolist()):
        if first[group] < 0:
            first[group] = index
    return first[where]


def grouping_bound(tolerance: float, widths: np.ndarray, stiffness: np.ndarray, damping: np.ndarray,
                   excitation: np.ndarray, deflection: np.ndarray, rate: np.ndarray, amplification: float) -> float:
    """The first-order bound of the module docstring on |Δδ|_max/|δ|_max [-]: ``widths`` h_j [s], ``stiffness``
    k_j [N/m], ``damping`` c_j [N·s/m], ``excitation`` g_j [N] per interval; ``deflection`` δ [m] and ``rate`` δ̇
    [m/s] of the orbit; ``amplification`` A [-] the dynamic amplification (>= 1)."""
    widths, stiffness = np.asarray(widths, float), np.asarray(stiffness, float)
    load = (float(np.abs(stiffness).max()) * float(np.abs(deflection).max())
            + float(np.abs(damping).max()) * float(np.abs(rate).max()) + float(np.abs(excitation).max()))
    static = float(np.abs(stiffness).min()) * max(float(np.abs(deflection).min()), 1e-300)
    return float(tolerance * widths.max() / widths.min() * max(amplification, 1.0) * load / static)
