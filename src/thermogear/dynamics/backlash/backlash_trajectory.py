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
                        cache: dict | None = None) -> BacklashTrajectory:
    """The motion from ``state`` (2n,) at τ = 0 over ``periods`` periods, sampled as the module docstring says.

    ``substeps`` per piece to find the switches (see
    :func:`~thermogear.dynamics.backlash.backlash_ndof.backlash_flow_ndof`). ``extremum_vector`` v (n,): also sample
    every extremum of vᵀq inside a segment (a zero of vᵀq̇ between two samples, located by Brent's method on the exact
    solution), so that a quantity monotone in vᵀq on a segment (a mesh force in one contact region) takes its exact
    maximum at a sample. ``cache``: the flow's exponentials, e.g. those of the shooting that found the orbit
    (:func:`~thermogear.dynamics.backlash.backlash_ndof.backlash_flow_ndof`).
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
        for k, key in enumerate(info["segments"]):
            if info["time"][k + 1] > info["time"][k]:  # a segment cut to nothing at a switch has no inside
                times.append((offset + info["time"][k], offset + info["time"][k + 1]))
                starts.append(info["states"][k])
                keys.append(key)
    bounds = np.array(times)
    tolerance = 1e-12 * period
    # the grid: samples_per_piece steps on each piece of each period, and the end
    steps = np.arange(int(samples_per_piece)) / samples_per_piece
    grid = (linear.nodes[:-1, None] + np.diff(linear.nodes)[:, None] * steps).ravel()
    grid = np.concatenate([(grid[None, :] + period * np.arange(int(periods))[:, None]).ravel(), [periods * period]])
    samples = []  # (time, rank, segment index, time into the segment); rank 0: left side, 1: right side
    for k in range(len(keys)):
        if k > 0 and keys[k] != keys[k - 1]:
            samples.append((bounds[k, 0], 0, k - 1, bounds[k - 1, 1] - bounds[k - 1, 0]))
            samples.append((bounds[k, 0], 1, k, 0.0))
    changes = {round(float(bounds[k, 0]) / tolerance) for k in range(1, len(keys)) if keys[k] != keys[k - 1]}
    segment_of = np.clip(np.searchsorted(bounds[:, 0], grid, side="right") - 1, 0, len(keys) - 1)
    for t, k in zip(grid, segment_of):
        if any(round(float(t) / tolerance) + shift in changes for shift in (-1, 0, 1)):
            continue  # the switch's own right-side sample stands for it
        into = min(float(t) - bounds[k, 0], bounds[k, 1] - bounds[k, 0])
        # a grid time on a recorded segment start (sub-steps a multiple of the grid) differs from it by rounding of
        # the summed times only: the recorded state stands for it (no exponential; the shift is ~1e-16 of T)
        samples.append((float(t), 1, int(k), 0.0 if into <= 1e-13 * period else into))
    pieces = piece_exponentials(system, substeps, cache)

    def evaluate(k: int, into: float) -> np.ndarray:
        if into == 0.0:
            return starts[k]
        if k + 1 < len(starts) and abs(bounds[k, 1] - bounds[k, 0] - into) <= 1e-13 * period:
            return starts[k + 1]  # the segment's end: the state is continuous across every switch
        matrix = pieces.matrix(keys[k][0], (keys[k][1], keys[k][2]))
        return exponential_action(matrix, np.append(starts[k], 1.0), into)[:-1]

    samples.sort(key=lambda item: (item[0], item[1]))
    values = [evaluate(k, into) for _, _, k, into in samples]
    if extremum_vector is not None:
        extra = _extrema(samples, values, keys, np.asarray(extremum_vector, dtype=float), n, evaluate)
        samples, values = samples + [item[0] for item in extra], values + [item[1] for item in extra]
        order = sorted(range(len(samples)), key=lambda row: (samples[row][0], samples[row][1]))
        samples, values = [samples[row] for row in order], [values[row] for row in order]
    values = np.array(values).reshape(len(samples), 2 * n)
    chosen = [keys[k] for _, _, k, _ in samples]
    zones = len(system.dead_zones)
    return BacklashTrajectory(
        np.array([item[0] for item in samples]), values, np.array([key[0] for key in chosen], dtype=int),
        np.array([key[1] for key in chosen], dtype=int),
        np.array([key[2] for key in chosen], dtype=int).reshape(len(chosen), zones), z,
        int(totals["switches"]), int(totals["zone_switches"]), float(totals["free_flight_time"]),
        float(totals["back_contact_time"]), float(period), int(periods))


def _extrema(samples: list, values: list, keys: list, vector: np.ndarray, n: int, evaluate) -> list:
    """Samples (time, rank, segment, time into it) with their states at the zeros of vᵀq̇ between consecutive
    samples of one contact state."""
    from scipy.optimize import brentq

    found = []
    for row in range(len(samples) - 1):
        (t0, _, k, into0), (t1, _, k1, _) = samples[row], samples[row + 1]
        if keys[k1] != keys[k] or t1 <= t0:  # the sub-steps of one contact state are one linear flow
            continue
        into1 = into0 + (t1 - t0)
        low, high = vector @ values[row][n:], vector @ values[row + 1][n:]
        if low * high < 0.0:
            def rate(s, k=k):
                return vector @ evaluate(k, s)[n:]

            root = brentq(rate, into0, into1, xtol=1e-14 * max(into1, 1e-300), rtol=4 * np.finfo(float).eps)
            found.append(((t0 + root - into0, 1, k, root), evaluate(k, root)))
    return found


def linear_trajectory(system: PiecewiseLinearSystem, state: np.ndarray, periods: int = 1,
                      samples_per_piece: int = 8) -> BacklashTrajectory:
    """The motion of the piecewise-linear system (a mesh in permanent contact) from ``state`` (2n,) over
    ``periods`` periods, exact at ``samples_per_piece`` equal steps per piece and the end (each step the exponential
    of the piece's augmented matrix); in the form of :func:`backlash_trajectory`, region driving contact throughout
    and no dead zone."""
    for key, value in (("periods", periods), ("samples_per_piece", samples_per_piece)):
        if isinstance(value, bool) or int(value) != value or value < 1:
            raise ProblemError(key, value, "integer >= 1", "whole periods and samples per piece")
    n, pieces, samples = system.size, system.nodes.size - 1, int(samples_per_piece)
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
