"""Time samples of a motion with backlash (and dead zones): the exact state on a uniform grid and at every switch.

From a state z₀ the flow of :func:`thermogear.dynamics.backlash.backlash_ndof.backlash_flow_ndof` is followed over P
periods and recorded segment by segment (a segment: one piece in one contact region of the mesh and one side of every
dead zone). On a segment that starts at t_k in the state z_k the motion is the exact solution of a linear system,
z(t) = exp(A_k (t − t_k))·z_k with A_k the segment's augmented matrix (Van Loan 1978), so a sample anywhere in it
carries no integration error beyond that of the exponential. Samples: ``samples_per_piece`` equal steps on every
piece of every period, the end of the last period, and both sides of every instant where the segment's region or
piece changes (a contact switch, a dead-zone switch, a node of the mesh period): the state is continuous there but
the forces are not, so the left sample carries the region before and the right one the region after. Knows nothing
of gears: matrices only.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from thermogear.dynamics.backlash.backlash_ndof import (BACK_CONTACT, DRIVING_CONTACT, FREE_FLIGHT, BacklashSystem,
                                               backlash_flow_ndof, piece_exponentials, switch_free_record)
from thermogear.dynamics.backlash.backlash_pieces import exponential_action
from thermogear.dynamics.periodic_orbits.periodic_ndof import PiecewiseLinearSystem, piece_steps
from thermogear.errors import ProblemError

__all__ = ["BacklashTrajectory", "backlash_trajectory", "linear_trajectory"]


@dataclass(frozen=True, eq=False)
class BacklashTrajectory:
    """Samples of a motion: ``time`` (S,) [s] from 0 (non-decreasing: a switch instant appears twice, left side
    first); ``state`` (S, 2n) displacement then velocity; ``piece`` (S,) index within the period; ``region`` (S,)
    the mesh's contact region (:data:`~thermogear.dynamics.backlash.backlash_ndof.DRIVING_CONTACT`, ``FREE_FLIGHT``,
    ``BACK_CONTACT``); ``sides`` (S, zones) each dead zone's side (+1, −1 in contact, 0 inside the clearance);
    ``end_state`` (2n,) after the last period; per whole motion: mesh ``switches``, ``zone_switches``,
    ``free_flight_time`` and ``back_contact_time`` [s]; ``period`` T [s] and ``periods`` P."""

    time: np.ndarray
    state: np.ndarray
    piece: np.ndarray
    region: np.ndarray
    sides: np.ndarray
    end_state: np.ndarray
    switches: int
    zone_switches: int
    free_flight_time: float
    back_contact_time: float
    period: float
    periods: int

    @property
    def size(self) -> int:
        """n, the number of coordinates."""
        return self.state.shape[1] // 2

    @property
    def displacement(self) -> np.ndarray:
        """(S, n) q at the samples."""
        return self.state[:, :self.size]

    @property
    def velocity(self) -> np.ndarray:
        """(S, n) q̇ at the samples."""
        return self.state[:, self.size:]

    def region_time(self, region: int) -> float:
        """Time [s] spent in a contact region, from the samples: exact, since every switch is sampled on both
        sides (a sample's region holds until the next sample)."""
        return float(np.sum(np.diff(self.time) * (self.region[:-1] == region)))

    def last_period(self) -> BacklashTrajectory:
        """The samples of the last period, time from 0 (its first sample the right side at its start), with the
        switch count and contact times recounted from them."""
        start = (self.periods - 1) * self.period
        first = int(np.searchsorted(self.time, start - 1e-12 * self.period))
        while first + 1 < self.time.size and self.time[first + 1] == self.time[first]:
            first += 1  # a switch at the start: keep its right side
        region = self.region[first:]
        part = BacklashTrajectory(self.time[first:] - start, self.state[first:], self.piece[first:], region,
                                  self.sides[first:], self.end_state, 0, 0, 0.0, 0.0, self.period, 1)
        changes = np.flatnonzero(region[1:] != region[:-1])
        switches = int(sum(1 + (abs(int(region[i + 1]) - int(region[i])) == 2) for i in changes))
        zone_changes = int(np.count_nonzero(part.sides[1:] != part.sides[:-1]))
        return BacklashTrajectory(part.time, part.state, part.piece, region, part.sides, self.end_state, switches,
                                  zone_changes, part.region_time(FREE_FLIGHT), part.region_time(BACK_CONTACT),
                                  self.period, 1)


def backlash_trajectory(system: BacklashSystem, state: np.ndarray, periods: int = 1, samples_per_piece: int = 8,
                        substeps: int = 16, extremum_vector: np.ndarray | None = None,
                        cache: dict | None = None, extremum_periods: int | None = None) -> BacklashTrajectory:
    """The motion from ``state`` (2n,) at τ = 0 over ``periods`` periods, sampled as the module docstring says.

    ``substeps`` per piece to find the switches (see
    :func:`~thermogear.dynamics.backlash.backlash_ndof.backlash_flow_ndof`). ``extremum_vector`` v (n,): also sample
    every extremum of vᵀq inside a segment (a zero of vᵀq̇ between two samples, located by Brent's method on the exact
    solution), so that a quantity monotone in vᵀq on a segment (a mesh force in one contact region) takes its exact
    maximum at a sample; only in the last ``extremum_periods`` periods where given (e.g. 1 where only the last
    period's maxima are read: Brent's search is a third of a long motion's cost). ``cache``: the flow's exponentials,
    e.g. those of the shooting that found the orbit (:func:`~thermogear.dynamics.backlash.backlash_ndof.
    backlash_flow_ndof`).
    """
    for key, value in (("periods", periods), ("samples_per_piece", samples_per_piece)):
        if isinstance(value, bool) or int(value) != value or value < 1:
            raise ProblemError(key, value, "integer >= 1", "whole periods and samples per piece")
    linear = system.linear
    n, period = linear.size, linear.period
    z = np.asarray(state, dtype=float)
    times, starts, keys = [], [], []
    totals = {"switches": 0, "zone_switches": 0, "free_flight_time": 0.0, "back_contact_time": 0.0}
    cache = {} if cache is None else cache  # the pieces' exponentials, computed once, reused by every period
    for index in range(int(periods)):
        recorded = switch_free_record(cache, z, substeps) if int(periods) == 1 else None
        if recorded is None:
            z, _, info = backlash_flow_ndof(system, z, substeps, record=True, monodromy=False, cache=cache)
        else:  # the orbit of one contact state the shooting found from its linear solution: its sub-step states
            z, info = recorded
        for name in totals:
            totals[name] += info[name]
        offset = index * period
        time = np.asarray(info["time"], dtype=float)
        inside = np.flatnonzero(time[1:] > time[:-1])  # a segment cut to nothing at a switch has no inside
        times.append(np.column_stack([offset + time[:-1][inside], offset + time[1:][inside]]))
        starts.append(np.asarray(info["states"][:-1])[inside])
        keys.extend(info["segments"][k] for k in inside)
    segments = _Segments.of(np.vstack(times), np.vstack(starts), keys, len(system.dead_zones))
    del times, starts  # the periods' parts, copied into the segments (a long motion's largest arrays)
    rows = _samples(segments, linear.nodes, period, int(periods), int(samples_per_piece))
    pieces = piece_exponentials(system, substeps, cache)

    matrices: dict[int, np.ndarray] = {}  # each segment's augmented matrix, formed once (Brent asks several times)

    def evaluate(k: int, into: float) -> np.ndarray:
        if into == 0.0:
            return segments.starts[k]
        if k + 1 < len(keys) and abs(segments.bounds[k, 1] - segments.bounds[k, 0] - into) <= 1e-13 * period:
            return segments.starts[k + 1]  # the segment's end: the state is continuous across every switch
        if k not in matrices:
            matrices[k] = pieces.matrix(keys[k][0], (keys[k][1], keys[k][2]))
        return exponential_action(matrices[k], np.append(segments.starts[k], 1.0), into)[:-1]

    values = segments.states_at(rows, period, evaluate)
    if extremum_vector is not None:
        extrema_from = 0.0 if extremum_periods is None else max(int(periods) - int(extremum_periods), 0) * period
        extra, extra_values = _extrema(rows, values, segments, np.asarray(extremum_vector, dtype=float), n, evaluate,
                                       extrema_from)
        rows = {name: np.concatenate([rows[name], extra[name]]) for name in rows}
        values = np.vstack([values, extra_values])
        order = np.lexsort((rows["rank"], rows["time"]))  # stable: ties keep their order, as a list sort does
        rows, values = {name: column[order] for name, column in rows.items()}, values[order]
    chosen = rows["segment"]
    return BacklashTrajectory(
        rows["time"], values, segments.piece[chosen], segments.region[chosen], segments.sides[chosen], z,
        int(totals["switches"]), int(totals["zone_switches"]), float(totals["free_flight_time"]),
        float(totals["back_contact_time"]), float(period), int(periods))


@dataclass(frozen=True, eq=False)
class _Segments:
    """The recorded segments of a motion: ``bounds`` (K, 2) start and end time [s], ``starts`` (K, 2n) the state at
    each start, and each segment's key as ``piece`` (K,), ``region`` (K,) and dead-zone ``sides`` (K, zones)."""

    bounds: np.ndarray
    starts: np.ndarray
    piece: np.ndarray
    region: np.ndarray
    sides: np.ndarray

    @classmethod
    def of(cls, bounds: np.ndarray, starts: np.ndarray, keys: list, zones: int) -> _Segments:
        count = len(keys)
        return cls(bounds.reshape(count, 2), starts, np.array([key[0] for key in keys], dtype=int),
                   np.array([key[1] for key in keys], dtype=int),
                   np.array([key[2] for key in keys], dtype=int).reshape(count, zones))

    def same_key(self, first: np.ndarray, second: np.ndarray) -> np.ndarray:
        """Whether the segments ``first`` and ``second`` (arrays of indices) have equal keys, element by element."""
        return ((self.piece[first] == self.piece[second]) & (self.region[first] == self.region[second])
                & np.all(self.sides[first] == self.sides[second], axis=1))

    def states_at(self, rows: dict, period: float, evaluate) -> np.ndarray:
        """The states (S, 2n) at the samples ``rows``: a segment's recorded start where the sample sits on it, the
        next segment's start where it sits on the segment's end (the state is continuous across every switch), the
        exact solution inside (``evaluate``)."""
        segment, into = rows["segment"], rows["into"]
        count = len(self.piece)
        width = self.bounds[segment, 1] - self.bounds[segment, 0]
        at_end = (into != 0.0) & (segment + 1 < count) & (np.abs(width - into) <= 1e-13 * period)
        source = np.where(at_end, np.minimum(segment + 1, count - 1), segment)
        values = self.starts[source]
        for row in np.flatnonzero((into != 0.0) & ~at_end):
            values[row] = evaluate(int(segment[row]), float(into[row]))
        return values


def _samples(segments: _Segments, nodes: np.ndarray, period: float, periods: int, samples_per_piece: int) -> dict:
    """The samples of the module docstring, in time order (a switch's left side first) as columns: ``time`` [s],
    ``rank`` (0 the left side of a switch, 1 otherwise), ``segment`` and ``into`` it [s]."""
    bounds = segments.bounds
    count = bounds.shape[0]
    tolerance = 1e-12 * period
    # the grid: samples_per_piece steps on each piece of each period, and the end
    steps = np.arange(samples_per_piece) / samples_per_piece
    grid = (nodes[:-1, None] + np.diff(nodes)[:, None] * steps).ravel()
    grid = np.concatenate([(grid[None, :] + period * np.arange(periods)[:, None]).ravel(), [periods * period]])
    indices = np.arange(1, count)
    changed = indices[~segments.same_key(indices, indices - 1)]  # where the key changes: both sides sampled
    switch_time = np.repeat(bounds[changed, 0], 2)
    switch_rank = np.tile([0, 1], changed.size)
    switch_segment = np.column_stack([changed - 1, changed]).ravel()
    switch_into = np.column_stack([bounds[changed - 1, 1] - bounds[changed - 1, 0], np.zeros(changed.size)]).ravel()
    # a grid time within a unit of 1e-12 T of a switch: the switch's own right-side sample stands for it
    units = np.rint(bounds[changed, 0] / tolerance).astype(np.int64)
    grid_units = np.rint(grid / tolerance).astype(np.int64)
    kept = ~(np.isin(grid_units - 1, units) | np.isin(grid_units, units) | np.isin(grid_units + 1, units))
    grid = grid[kept]
    segment_of = np.clip(np.searchsorted(bounds[:, 0], grid, side="right") - 1, 0, count - 1)
    into = np.minimum(grid - bounds[segment_of, 0], bounds[segment_of, 1] - bounds[segment_of, 0])
    # a grid time on a recorded segment start (sub-steps a multiple of the grid) differs from it by rounding of the
    # summed times only: the recorded state stands for it (no exponential; the shift is ~1e-16 of T)
    into = np.where(into <= 1e-13 * period, 0.0, into)
    rows = {"time": np.concatenate([switch_time, grid]),
            "rank": np.concatenate([switch_rank, np.ones(grid.size, dtype=int)]),
            "segment": np.concatenate([switch_segment, segment_of]).astype(int),
            "into": np.concatenate([switch_into, into])}
    order = np.lexsort((rows["rank"], rows["time"]))  # stable: ties keep their order, as a list sort does
    return {name: column[order] for name, column in rows.items()}


def _extrema(rows: dict, values: np.ndarray, segments: _Segments, vector: np.ndarray, n: int,
             evaluate, start: float = 0.0) -> tuple[dict, np.ndarray]:
    """Samples (columns as :func:`_samples` gives them) with their states at the zeros of vᵀq̇ between consecutive
    samples of one contact state, from the time ``start`` [s] on."""
    from scipy.optimize import brentq

    time, segment, into = rows["time"], rows["segment"], rows["into"]
    # which neighbours to test: vᵀq̇ for all samples in one product; its rounding differs from a dot product's by at
    # most 2γ_n·Σ|vᵢq̇ᵢ| (Higham 2002, §3.1), so a sign test is redone below, exactly, wherever it could differ
    rates = values[:, n:] @ vector
    near_zero = np.abs(rates) <= 4.0 * n * np.finfo(float).eps * (np.abs(values[:, n:]) @ np.abs(vector))
    first, second = np.arange(time.size - 1), np.arange(1, time.size)
    candidates = (segments.same_key(segment[second], segment[first]) & (time[second] > time[first])
                  & (time[first] >= start)
                  & ((rates[first] * rates[second] < 0.0) | near_zero[first] | near_zero[second]))
    found = []
    for row in np.flatnonzero(candidates):
        k, into0 = int(segment[row]), float(into[row])
        into1 = into0 + (float(time[row + 1]) - float(time[row]))
        low, high = vector @ values[row][n:], vector @ values[row + 1][n:]
        if low * high < 0.0:
            def rate(s, k=k):
                return vector @ evaluate(k, s)[n:]

            root = brentq(rate, into0, into1, xtol=1e-14 * max(into1, 1e-300), rtol=4 * np.finfo(float).eps)
            found.append((float(time[row]) + root - into0, k, root))
    extra = {"time": np.array([item[0] for item in found], dtype=float), "rank": np.ones(len(found), dtype=int),
             "segment": np.array([item[1] for item in found], dtype=int),
             "into": np.array([item[2] for item in found], dtype=float)}
    extra_values = np.array([evaluate(k, root) for _, k, root in found]).reshape(len(found), 2 * n)
    return extra, extra_values


def linear_trajectory(system: PiecewiseLinearSystem, state: np.ndarray, periods: int = 1,
                      samples_per_piece: int = 8) -> BacklashTrajectory:
    """The motion of the piecewise-linear system (a mesh in permanent contact) from ``state`` (2n,) over
    ``periods`` periods, exact at ``samples_per_piece`` equal steps per piece and the end (each step the exponential
    of the piece's augmented matrix); in the form of :func:`backlash_trajectory`, region driving contact throughout
    and no dead zone."""
    for key, value in (("periods", periods), ("samples_per_piece", samples_per_piece)):
        if isinstance(value, bool) or int(value) != value or value < 1:
            raise ProblemError(key, value, "integer >= 1", "whole periods and samples per piece")
    pieces, samples = system.nodes.size - 1, int(samples_per_piece)
    distinct, where = piece_steps(system, samples)  # every piece's sub-step exponential, batched
    steps = distinct[where]
    z = np.append(np.asarray(state, dtype=float), 1.0)
    values, times, piece_of = [], [], []
    offsets = np.arange(samples) / samples
    for index in range(int(periods)):
        for piece in range(pieces):
            start, width = system.nodes[piece], system.nodes[piece + 1] - system.nodes[piece]
            for offset in offsets:
                values.append(z[:-1])
                times.append(index * system.period + start + offset * width)
                piece_of.append(piece)
                z = steps[piece] @ z
            if not np.all(np.isfinite(z)):
                raise ProblemError("state", "not finite", "a bounded motion", "the coefficients are out of range")
    values.append(z[:-1])
    times.append(periods * system.period)
    piece_of.append(pieces - 1)
    count = len(times)
    return BacklashTrajectory(np.array(times), np.array(values), np.array(piece_of, dtype=int),
                              np.full(count, DRIVING_CONTACT, dtype=int), np.zeros((count, 0), dtype=int), z[:-1],
                              0, 0, 0.0, 0.0, float(system.period), int(periods))
