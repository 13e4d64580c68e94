"""The motion of a piecewise-linear time-periodic system from a given state over many periods, watched through
linear functionals of its state (e.g. the gap of a mesh) without stepping it period by period: the pieces'
sub-step and whole transitions of :func:`~thermogear.dynamics.periodic_orbits.periodic_ndof.chunked_transitions`,
carried back to
the period's start once. Knows nothing of gears: matrices only."""

from __future__ import annotations

import numpy as np

from thermogear.dynamics.linear_algebra.modal_chain import left_product
from thermogear.dynamics.linear_algebra.sub_steps import as_steps
from thermogear.dynamics.periodic_orbits.periodic_ndof import PiecewiseLinearSystem, chunked_transitions, grouped_pieces
from thermogear.errors import ProblemError

__all__ = ["MotionProjector", "motion_projections"]


def motion_projections(system: PiecewiseLinearSystem, state: np.ndarray, periods: int, samples_per_piece: int,
                       rows: np.ndarray) -> np.ndarray:
    """(P·N·s + 1, r): the functionals ``rows`` (r, 2n) of the state z(t) at the s = ``samples_per_piece`` equal
    sub-steps of every piece of P = ``periods`` periods of the motion from ``state`` (2n,) at t = 0, and at the end.

    One pass over the pieces carries each sample's functionals back to the period's start, rows·e^{A_j h_j i/s}·T_j
    with T_j the transition from the start to node j (one (2n+1)² product per piece, as the monodromy), so that each
    period then costs one product with its start state and the period's transition: the motion from rest over
    many periods is watched (e.g. for the mesh gap) without stepping it. Exact as
    :func:`~thermogear.dynamics.periodic_orbits.periodic_ndof.periodic_response`."""
    projector = MotionProjector(system, samples_per_piece, rows)
    grouped, where = grouped_pieces(system, int(samples_per_piece))
    total = np.eye(2 * system.size + 1)
    for first, wholes, steps in chunked_transitions(system, grouped, where, int(samples_per_piece)):
        total, starts = wholes.chain_starts(total)  # as the chunked periodic solve forms them for its observer
        projector.add(first, steps, starts, total)
    return projector.projections(state, periods)


class MotionProjector:
    """The pass of :func:`motion_projections` fed chunk by chunk with the sub-step transitions of ``system`` and
    their whole pieces' (those of :func:`~thermogear.dynamics.periodic_orbits.periodic_ndof.chunked_transitions`, in
    order), so that a solve that forms them anyway (``periodic_response(..., observer=projector.add)``, whose first pass
    forms both) also prepares the motion from any start without a pass of its own, with the numbers of
    :func:`motion_projections`. Fed without the wholes (a solve whose second pass forms the sub-steps' matrices),
    it forms them here chunk by chunk. ``complete`` says whether every piece was fed (a solve on another route
    feeds none)."""

    def __init__(self, system: PiecewiseLinearSystem, samples_per_piece: int, rows: np.ndarray):
        self.system, self.samples = system, int(samples_per_piece)
        grouped, self._where = grouped_pieces(system, self.samples)
        self.rows = np.atleast_2d(np.asarray(rows, dtype=float))
        n, count = system.size, self.rows.shape[0]
        self._augmented = np.zeros((count, 2 * n + 1))
        self._augmented[:, :2 * n] = self.rows
        self._transfer = np.empty((self._where.size, self.samples, count, 2 * n + 1))
        self._transition = np.eye(2 * n + 1)
        self._grouped = grouped
        self._wholes = None  # formed here only where a solve feeds the sub-steps without them
        self._fed = 0

    @property
    def complete(self) -> bool:
        """Whether every piece's sub-step exponential was fed."""
        return self._fed == self._where.size

    def add(self, first: int, steps, starts: np.ndarray | None = None, end: np.ndarray | None = None) -> None:
        """Take the sub-step transitions ``steps`` of the pieces first … first + c − 1 (the next chunk: a (c, 2n+1,
        2n+1) array or a :mod:`~thermogear.dynamics.linear_algebra.sub_steps` form) with ``starts`` (c, 2n+1, 2n+1, or
        :class:`~thermogear.dynamics.linear_algebra.modal_chain.FactoredStarts`) the
        transitions from the period's start to each piece's start and ``end`` the one to the chunk's end, as the caller
        formed them (None: formed here from the whole transitions of
        :func:`~thermogear.dynamics.periodic_orbits.periodic_ndof.
        chunked_transitions`, one after another as there: the same numbers)."""
        if first != self._fed:
            raise ProblemError("first", first, f"= {self._fed}", "the chunks are fed in order")
        steps = as_steps(steps)
        if starts is None:
            if self._wholes is None:
                self._wholes = chunked_transitions(self.system, self._grouped, self._where, self.samples,
                                                   dense_steps=False)
            start, wholes, _ = next(self._wholes)
            while start < first:
                self._transition = wholes.chain(self._transition)
                start, wholes, _ = next(self._wholes)
            end, starts = wholes.chain_starts(self._transition)
        if len(starts) != len(steps):
            raise ProblemError("starts", len(starts), f"= {len(steps)}", "one start transition per piece")
        count, rows = len(steps), self._augmented.shape[0]
        current = np.broadcast_to(self._augmented, (count, *self._augmented.shape))
        samples = np.empty((count, self.samples, *self._augmented.shape))
        for sample in range(self.samples):  # every piece of the chunk at once
            samples[:, sample] = current
            if sample + 1 < self.samples:
                current = steps.apply_left_all(current)
        # every sample's rows of a piece against its start transition in one product (each start read once)
        transfer = left_product(samples.reshape(count, self.samples * rows, -1), starts)
        self._transfer[first:first + count] = transfer.reshape(count, self.samples, rows, -1)
        self._transition, self._fed = end, first + count

    def projections(self, state: np.ndarray, periods: int) -> np.ndarray:
        """The (P·N·s + 1, r) functionals of the motion from ``state`` over ``periods`` periods
        (:func:`motion_projections`)."""
        if not self.complete:
            raise ProblemError("pieces", self._fed, f"all {self._where.size} fed", "the motion needs every piece")
        count, size = self.rows.shape[0], self._transfer.shape[-1]
        z = np.append(np.asarray(state, dtype=float), 1.0)
        starts = np.empty((size, int(periods)))  # the state at each period's start, then all periods at once
        for period in range(int(periods)):
            starts[:, period] = z
            z = self._transition @ z
        flat = self._transfer.reshape(self._where.size * self.samples * count, size)
        values = (flat @ starts).reshape(self._where.size * self.samples, count, int(periods)).transpose(2, 0, 1)
        return np.vstack([values.reshape(-1, count), (self._augmented @ z)[None]])
