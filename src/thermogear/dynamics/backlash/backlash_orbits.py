"""Every stable orbit of the backlash model that a grid of starts finds, with the share of starts that reach it.

A piecewise-linear oscillator with clearance can hold several stable steady responses at one operating point:
the no-impact and the single-sided-impact orbits of the primary resonance, a double-sided-impact orbit, and
subharmonic orbits (Kahraman & Singh 1990, J. Sound Vib. 142(1):49–75; measured on a rig: Kahraman & Blankenship
1997, ASME J. Appl. Mech. 64:217–226). Continuation in speed (:mod:`thermogear.dynamics.backlash.backlash_continuation`)
follows one branch from its neighbour and meets at most the branches its path runs along, so it cannot see an orbit
whose basin its path never enters. :func:`stable_orbits` searches the state plane instead (a multi-start search):

1. starts: an evenly spaced grid of ``starts`` states (x0, ẋ0) at τ = 0 over x0 ∈ [−2(j + 2δ), 2(j + 2δ)] and
   ẋ0 ∈ [−2ω(j + 2δ), 2ω(j + 2δ)] by default, j the backlash, δ the largest static deflection and ω the largest
   natural angular frequency of the mesh: the starts cover both flanks and the velocities of impacts across the
   whole backlash, with a margin of 2 (on luo2019 with 131 μm of backlash at 13 000 rpm the stable period-3 orbit,
   308 μm peak-to-peak, has starts in its basin with the margin and none without); both ranges can be given;
2. from each start a transient run-in of ``run_in_periods`` mesh periods (the exact event-driven flow), then
   Newton shooting on N = 1, 2, …, ``max_period_count`` periods from its end, the N after which the end state
   returns closest to itself first (Newton's own basins are not the flow's: on N = 1 from a point of a period-3
   orbit it can converge to another orbit); the first stable converged orbit is kept, reduced to its least
   period. A start whose run-in does not settle on such an orbit gets a second,
   equally long run-in and one more round; after that it is counted as ``unresolved`` (non-periodic, or periodic
   with more periods than searched), one whose motion grows without bound as ``unbounded``;
3. deduplication: two orbits are one when they have the same least period N and the state at τ = 0 of one lies on
   the other's N phase states φ_kT(y0), k = 0 … N−1 (a subharmonic is found with any of its N phases), within
   ``match_tolerance`` in the scaled norm of :func:`~thermogear.dynamics.backlash.backlash_periodic.shoot`.

The basin share of an orbit is the fraction of the starts that settle on it: an estimate of the size of its basin
of attraction over the start window (not a probability of the operating gearbox, which depends on its history).
Orbits that no start reaches — small basins between the grid points or outside the window — are not found:
more starts, a wider window or longer periods widen the search; no finite search proves an orbit absent.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from thermogear.dynamics.backlash.backlash_periodic import (BacklashOrbit, backlash_flow, least_period, orbit_from_shot,
                                                   scaled_distance, shoot, shot_is_stable)
from thermogear.dynamics.problems.backlash_problem import BacklashMeshProblem
from thermogear.errors import ModelLimitError, ProblemError

__all__ = ["OrbitCensus", "StableOrbit", "start_grid", "stable_orbits"]

_UNBOUNDED = 1e6  # scaled |state| beyond which a run-in grows without bound (as periodic_response)
WINDOW_MARGIN = 2.0  # the default start window: this many times the backlash plus two static deflections


@dataclass(frozen=True)
class StableOrbit:
    """One stable orbit found: the ``orbit`` (its least period N, state at τ = 0, multipliers, history) and how
    many of the starts settled on it (``start_count``; ``basin_share`` = start_count / starts)."""

    orbit: BacklashOrbit
    start_count: int
    basin_share: float

    @property
    def period_count(self) -> int:
        return int(self.orbit.period_count)


@dataclass(frozen=True)
class OrbitCensus:
    """What a multi-start search found (module docstring).

    ``orbits``: the distinct stable orbits, the largest basin share first; ``start_states`` (starts, 2) [m, m/s];
    ``outcome`` (starts,): the index into ``orbits`` each start settled on, −1 unresolved, −2 unbounded;
    ``unresolved`` / ``unbounded``: how many starts ended so.
    """

    orbits: tuple[StableOrbit, ...]
    start_states: np.ndarray
    outcome: np.ndarray
    max_period_count: int

    @property
    def starts(self) -> int:
        return int(self.outcome.size)

    @property
    def unresolved(self) -> int:
        return int(np.sum(self.outcome == -1))

    @property
    def unbounded(self) -> int:
        return int(np.sum(self.outcome == -2))


def start_grid(problem: BacklashMeshProblem, starts: int, displacement_range: tuple[float, float] | None = None,
               velocity_range: tuple[float, float] | None = None) -> np.ndarray:
    """(starts, 2) initial states [m, m/s] evenly spaced over the window (module docstring), row by row: about
    sqrt(starts) displacements × sqrt(starts) velocities, the first ``starts`` of that grid."""
    if int(starts) != starts or starts < 1:
        raise ProblemError("starts", starts, "integer >= 1", "number of initial states of the multi-start search")
    reach = WINDOW_MARGIN * (problem.backlash + 2.0 * problem.displacement_scale)
    omega = problem.velocity_scale / problem.displacement_scale
    low_x, high_x = (-reach, reach) if displacement_range is None else map(float, displacement_range)
    low_v, high_v = (-omega * reach, omega * reach) if velocity_range is None else map(float, velocity_range)
    if not (np.isfinite([low_x, high_x, low_v, high_v]).all() and low_x <= high_x and low_v <= high_v):
        raise ProblemError("displacement_range/velocity_range", (low_x, high_x, low_v, high_v),
                           "finite (low, high) pairs with low <= high", "the window of the starts")
    columns = int(math.ceil(math.sqrt(starts)))
    rows = int(math.ceil(starts / columns))
    xs = np.linspace(low_x, high_x, columns)
    vs = np.linspace(low_v, high_v, rows) if rows > 1 else np.array([0.5 * (low_v + high_v)])
    grid = np.array([(x, v) for v in vs for x in xs])
    return grid[: int(starts)]


def _settle(problem: BacklashMeshProblem, start: np.ndarray, max_period_count: int, run_in_periods: int,
            tolerance: float, max_iterations: int) -> tuple[dict, int] | None:
    """Run in from ``start`` and shoot on 1 … max periods; (Newton result, least period) or None. Raises
    ModelLimitError when the motion grows without bound."""
    state = (float(start[0]), float(start[1]))
    for _ in range(2):
        end, _, _ = backlash_flow(problem, state, run_in_periods)
        if not np.all(np.isfinite(end)) or scaled_distance(problem, end) > _UNBOUNDED:
            raise ModelLimitError("the backlash mesh motion grows without bound from this start")
        state = (float(end[0]), float(end[1]))
        # shoot first on the period count the run-in's end repeats best after: Newton on N = 1 from a point of a
        # period-3 orbit can converge to another orbit (its own basin is not the flow's)
        mismatch = [scaled_distance(problem, backlash_flow(problem, state, count)[0] - end)
                    for count in range(1, max_period_count + 1)]
        for count in np.argsort(mismatch, kind="stable") + 1:
            count = int(count)
            result = shoot(problem, state, count, tolerance, max_iterations)
            if not shot_is_stable(result, problem):
                continue
            least = least_period(problem, result["state"], count, tolerance)
            if least != count:
                result = shoot(problem, result["state"], least, tolerance, max_iterations)
                if not shot_is_stable(result, problem):
                    continue
            return result, least
    return None


def _phases(problem: BacklashMeshProblem, state: np.ndarray, period_count: int) -> np.ndarray:
    """The N states at τ = 0 of an N-period orbit: φ_kT(y0), k = 0 … N−1."""
    phases = [np.asarray(state, dtype=float)]
    for _ in range(period_count - 1):
        phases.append(backlash_flow(problem, phases[-1], 1)[0])
    return np.array(phases)


def stable_orbits(problem: BacklashMeshProblem, starts: int = 64, max_period_count: int = 3,
                  run_in_periods: int = 200, displacement_range: tuple[float, float] | None = None,
                  velocity_range: tuple[float, float] | None = None, tolerance: float = 1e-10,
                  max_iterations: int = 30, match_tolerance: float = 1e-5,
                  samples_per_interval: int = 4, start_states=None) -> OrbitCensus:
    """Multi-start search for the stable orbits of ``problem`` (module docstring).

    Parameters
    ----------
    starts:
        Number of initial states (an evenly spaced grid over the window, :func:`start_grid`).
    max_period_count:
        Largest N (mesh periods) shot on; orbits of longer period count as unresolved.
    run_in_periods:
        Mesh periods of transient before shooting (twice at most per start).
    displacement_range, velocity_range:
        The start window [m], [m/s]; defaults in the module docstring.
    tolerance, max_iterations:
        Newton's scaled residual and iteration limit (:func:`~thermogear.dynamics.backlash.backlash_periodic.shoot`).
    match_tolerance:
        Scaled distance below which two orbit states are the same orbit.
    samples_per_interval:
        Sub-steps per interval of each orbit's recorded history.
    start_states:
        (m, 2) initial states [m, m/s] to use instead of the grid (``starts`` and the ranges are then ignored).
    """
    if int(max_period_count) != max_period_count or max_period_count < 1:
        raise ProblemError("max_period_count", max_period_count, "integer >= 1", "largest period count shot on")
    if int(run_in_periods) != run_in_periods or run_in_periods < 1:
        raise ProblemError("run_in_periods", run_in_periods, "integer >= 1", "mesh periods of run-in per start")
    if start_states is None:
        grid = start_grid(problem, starts, displacement_range, velocity_range)
    else:
        grid = np.asarray(start_states, dtype=float)
        if grid.ndim != 2 or grid.shape[1] != 2 or grid.shape[0] < 1 or not np.all(np.isfinite(grid)):
            raise ProblemError("start_states", f"shape {grid.shape}", "(m >= 1, 2) finite [m, m/s]",
                               "one (x0, v0) per start")
    outcome = np.full(grid.shape[0], -1, dtype=np.int64)
    found: list[tuple[dict, int, np.ndarray]] = []  # Newton result, least period, phase states
    for index, start in enumerate(grid):
        try:
            settled = _settle(problem, start, int(max_period_count), int(run_in_periods), tolerance, max_iterations)
        except ModelLimitError:
            outcome[index] = -2
            continue
        if settled is None:
            continue
        result, least = settled
        match = next((number for number, (_, period, phases) in enumerate(found) if period == least
                      and min(scaled_distance(problem, result["state"] - phase)
                              for phase in phases) <= match_tolerance),
                     None)
        if match is None:
            found.append((result, least, _phases(problem, result["state"], least)))
            match = len(found) - 1
        outcome[index] = match
    counts = np.bincount(outcome[outcome >= 0], minlength=len(found))
    order = sorted(range(len(found)), key=lambda number: (-counts[number], number))
    renumber = {old: new for new, old in enumerate(order)}
    outcome = np.array([renumber.get(int(value), int(value)) for value in outcome], dtype=np.int64)
    orbits = tuple(StableOrbit(orbit=orbit_from_shot(problem, found[number][0], found[number][1], samples_per_interval,
                                            found[number][0]["iterations"]),
                               start_count=int(counts[number]), basin_share=float(counts[number]) / grid.shape[0])
                   for number in order)
    return OrbitCensus(orbits=orbits, start_states=grid, outcome=outcome, max_period_count=int(max_period_count))
