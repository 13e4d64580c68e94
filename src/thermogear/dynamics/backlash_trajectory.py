"""Time samples of a motion with backlash (and dead zones): the exact state on a uniform grid and at every switch.

From a state z₀ the flow of :func:`thermogear.dynamics.backlash_ndof.backlash_flow_ndof` is followed over P periods
and recorded segment by segment (a segment: one piece in one contact region of the mesh and one side of every dead
zone). On a segment that starts at t_k in the state z_k the motion is the exact solution of a linear system,
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

from thermogear.dynamics.backlash_ndof import BacklashSystem, backlash_flow_ndof
from thermogear.errors import ProblemError

__all__ = ["BacklashTrajectory", "backlash_trajectory"]


@dataclass(frozen=True, eq=False)
class BacklashTrajectory:
    """Samples of a motion: ``time`` (S,) [s] from 0 (non-decreasing: a switch instant appears twice, left side
    first); ``state`` (S, 2n) displacement then velocity; ``piece`` (S,) index within the period; ``region`` (S,)
    the mesh's contact region (:data:`~thermogear.dynamics.backlash_ndof.DRIVING_CONTACT`, ``FREE_FLIGHT``,
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


def backlash_trajectory(system: BacklashSystem, state: np.ndarray, periods: int = 1, samples_per_piece: int = 8,
                        substeps: int = 16) -> BacklashTrajectory:
    """The motion from ``state`` (2n,) at τ = 0 over ``periods`` periods, sampled as the module docstring says.

    ``substeps`` per piece to find the switches (see :func:`~thermogear.dynamics.backlash_ndof.backlash_flow_ndof`).
    """
    from scipy.linalg import expm

    for key, value in (("periods", periods), ("samples_per_piece", samples_per_piece)):
        if isinstance(value, bool) or int(value) != value or value < 1:
            raise ProblemError(key, value, "integer >= 1", "whole periods and samples per piece")
    linear = system.linear
    n, period = linear.size, linear.period
    z = np.asarray(state, dtype=float)
    times, starts, keys = [], [], []
    totals = {"switches": 0, "zone_switches": 0, "free_flight_time": 0.0, "back_contact_time": 0.0}
    for index in range(int(periods)):
        z, _, info = backlash_flow_ndof(system, z, substeps, record=True)
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
        samples.append((float(t), 1, int(k), min(float(t) - bounds[k, 0], bounds[k, 1] - bounds[k, 0])))
    samples.sort(key=lambda item: (item[0], item[1]))
    inverse = np.linalg.inv(linear.mass)
    matrices: dict[tuple, np.ndarray] = {}
    values = np.empty((len(samples), 2 * n))
    for row, (_, _, k, into) in enumerate(samples):
        piece, region, sides = keys[k]
        if keys[k] not in matrices:
            matrices[keys[k]] = system.region_matrix(piece, region, inverse, sides)
        start = np.append(starts[k], 1.0)
        values[row] = start[:-1] if into == 0.0 else (expm(matrices[keys[k]] * into) @ start)[:-1]
    chosen = [keys[k] for _, _, k, _ in samples]
    zones = len(system.dead_zones)
    return BacklashTrajectory(
        np.array([item[0] for item in samples]), values, np.array([key[0] for key in chosen], dtype=int),
        np.array([key[1] for key in chosen], dtype=int),
        np.array([key[2] for key in chosen], dtype=int).reshape(len(chosen), zones), z,
        int(totals["switches"]), int(totals["zone_switches"]), float(totals["free_flight_time"]),
        float(totals["back_contact_time"]), float(period), int(periods))
