"""The motion of a piecewise-linear time-periodic system from a given state over many periods, watched through
linear functionals of its state (e.g. the gap of a mesh) without stepping it period by period: the pieces'
sub-step exponentials and whole transitions of :func:`~thermogear.dynamics.periodic_ndof.chunked_exponentials`,
carried back to the period's start once. Knows nothing of gears: matrices only."""

from __future__ import annotations

import numpy as np

from thermogear.dynamics.periodic_ndof import PiecewiseLinearSystem, chunked_exponentials, grouped_pieces

__all__ = ["motion_projections"]


def motion_projections(system: PiecewiseLinearSystem, state: np.ndarray, periods: int, samples_per_piece: int,
                       rows: np.ndarray) -> np.ndarray:
    """(P·N·s + 1, r): the functionals ``rows`` (r, 2n) of the state z(t) at the s = ``samples_per_piece`` equal
    sub-steps of every piece of P = ``periods`` periods of the motion from ``state`` (2n,) at t = 0, and at the end.

    One pass over the pieces carries each sample's functionals back to the period's start, rows·e^{A_j h_j i/s}·T_j
    with T_j the transition from the start to node j (one (2n+1)² product per piece, as the monodromy), so that each
    period then costs one product with its start state and the period's transition: the motion from rest over
    many periods is watched (e.g. for the mesh gap) without stepping it. Exact as :func:`~thermogear.dynamics.periodic_ndof.periodic_response`."""
    samples = int(samples_per_piece)
    grouped, where = grouped_pieces(system, samples)
    rows = np.atleast_2d(np.asarray(rows, dtype=float))
    n, count = system.size, rows.shape[0]
    augmented = np.zeros((count, 2 * n + 1))
    augmented[:, :2 * n] = rows
    transfer = np.empty((where.size, samples, count, 2 * n + 1))
    transition = np.eye(2 * n + 1)
    # chunk by chunk (no stack of every piece's matrix is held): the sub-step exponentials and the whole transitions
    for (first, steps), (_, wholes) in zip(chunked_exponentials(system, grouped, where),
                                           chunked_exponentials(system, grouped, where, samples), strict=True):
        for offset, (step, whole) in enumerate(zip(steps, wholes, strict=True)):
            current = augmented
            for sample in range(samples):
                transfer[first + offset, sample] = current @ transition
                current = current @ step
            transition = whole @ transition
    z = np.append(np.asarray(state, dtype=float), 1.0)
    values = np.empty((int(periods), where.size * samples, count))
    flat = transfer.reshape(where.size * samples, count, 2 * n + 1)
    for period in range(int(periods)):
        values[period] = flat @ z
        z = transition @ z
    return np.vstack([values.reshape(-1, count), (augmented @ z)[None]])
