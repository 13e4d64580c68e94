"""Follow the periodic orbits of an n-DOF system with a backlash mesh over a sequence of problems ordered by speed,
sweeping up or down, to show the jumps of a softening resonance with contact loss.

Each point starts the shooting (:func:`~thermogear.dynamics.backlash.backlash_ndof.backlash_periodic_orbit`) from the
converged state of its neighbour at τ = 0 (the mesh period scales with the speed, so the state at τ = 0 carries
over). Where that Newton fails or lands on an unstable orbit the branch has ended: the point is run in from the
neighbour's state for ``run_in_periods`` periods of the exact flow (what a slowly swept gearbox does: it falls on the
attractor that is left) and shot again from there. Up and down sweeps through the resonance then jump at different
speeds (Kahraman & Singh, J. Sound Vib. 142 (1990) 49–75). Knows nothing of gears: matrices only.

Systems solved on different bases of one full system (e.g. each speed's reduction) give ``coordinates``, each
system's basis C_i (q = C_i η, q the full coordinates), and the full system's mass matrix as ``metric`` M: the
neighbour's state then carries over by the M-orthogonal projection η_i = (C_iᵀ M C_i)⁻¹ C_iᵀ M C_j η_j of its
positions and of its velocities, exact where the two bases span the same subspace.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass

import numpy as np

from thermogear.dynamics.backlash.backlash_ndof import BacklashSystem, backlash_flow_ndof, backlash_periodic_orbit
from thermogear.dynamics.problems.continuation_directions import DIRECTIONS
from thermogear.dynamics.problems.continuation_inputs import continuation_labels, continuation_order
from thermogear.errors import ModelLimitError, ProblemError

__all__ = ["BacklashBranchNDOF", "BranchStep", "branch_step", "follow_backlash_branch", "from_full", "to_full"]


@dataclass(frozen=True, eq=False)
class BacklashBranchNDOF:
    """One entry per system in the order given: ``parameter`` labels (e.g. speed [rpm]); ``direction``;
    ``converged`` and ``stable``; ``run_in`` (the neighbour's orbit was lost and the point was run in);
    ``free_flight_fraction`` of the period out of contact [-]; ``peak_to_peak`` of the mesh coordinate wᵀq over the
    orbit [m]; ``initial_state`` (m, 2n) with n the largest system's size: system i's state (η, η̇) is the first
    2·n_i entries of its row (systems on bases of different sizes, module docstring), NaN where not converged."""

    parameter: np.ndarray
    direction: str
    converged: np.ndarray
    stable: np.ndarray
    run_in: np.ndarray
    free_flight_fraction: np.ndarray
    peak_to_peak: np.ndarray
    initial_state: np.ndarray

    def jumps(self, relative: float = 0.2) -> np.ndarray:
        """Indices i where the peak-to-peak mesh displacement changes by more than ``relative`` of the larger
        value between point i and the next point swept (i is the point where the branch was left)."""
        values = self.peak_to_peak
        step = DIRECTIONS[self.direction].step
        order = np.arange(values.size)[::step]
        found = [int(a) for a, b in zip(order[:-1], order[1:])
                 if abs(values[b] - values[a]) > relative * max(abs(values[a]), abs(values[b]))]
        return np.array(found, dtype=int)


def _peak_to_peak(system: BacklashSystem, state: np.ndarray, substeps: int, cache: dict) -> float:
    _, _, info = backlash_flow_ndof(system, state, substeps, record=True, monodromy=False, cache=cache)
    mesh = np.array(info["states"])[:, :system.linear.size] @ system.mesh_vector
    return float(np.ptp(mesh))


def to_full(state: np.ndarray, basis: np.ndarray | None) -> np.ndarray:
    """A state (η, η̇) on ``basis`` C (q = C η) in the full coordinates (q, q̇); itself without a basis."""
    if basis is None:
        return np.asarray(state, dtype=float)
    half = basis.shape[1]
    return np.concatenate((basis @ state[:half], basis @ state[half:]))


def from_full(state: np.ndarray, basis: np.ndarray | None, metric: np.ndarray | None) -> np.ndarray:
    """A full state (q, q̇) on ``basis`` C by the ``metric``-orthogonal projection (module docstring)."""
    if basis is None:
        return np.asarray(state, dtype=float)
    weighted = basis.T @ metric
    full = basis.shape[0]
    solved = np.linalg.solve(weighted @ basis, weighted @ np.stack((state[:full], state[full:]), axis=1))
    return np.concatenate((solved[:, 0], solved[:, 1]))


@dataclass(frozen=True, eq=False)
class BranchStep:
    """One point of a branch: ``orbit`` (None where none was found), ``run_in`` (the neighbour's orbit was lost
    and the point run in), and ``carried`` the full state the next point starts from (this orbit's where it
    converged, else the one this point was given; None before the first orbit)."""

    orbit: object | None
    run_in: bool
    carried: np.ndarray | None


def branch_step(system: BacklashSystem, carried: np.ndarray | None, basis: np.ndarray | None = None,
                metric: np.ndarray | None = None, substeps: int = 8, run_in_periods: int = 200,
                tolerance: float = 1e-10, max_iterations: int = 30) -> BranchStep:
    """One point of :func:`follow_backlash_branch`: the orbit of ``system`` shot from ``carried`` (the neighbour's
    full state, None: from rest), run in from there where that fails or is unstable (module docstring). A point
    depends only on its system and the state it is given, so a branch stopped after any point continues exactly
    from the ``carried`` state stored there."""
    state = None if carried is None else from_full(carried, basis, metric)
    run_in = False
    cache: dict = {}  # this point's exponentials, shared by its shootings and its run-in
    try:
        orbit = backlash_periodic_orbit(system, state, substeps, tolerance, max_iterations, cache=cache)
        if not orbit.stable and state is not None:
            start = state
            for _ in range(run_in_periods):
                start, _, _ = backlash_flow_ndof(system, start, substeps, monodromy=False, cache=cache)
            orbit = backlash_periodic_orbit(system, start, substeps, tolerance, max_iterations, cache=cache)
            run_in = True
    except (ModelLimitError, ProblemError, np.linalg.LinAlgError, ValueError):
        # no orbit at this point (ValueError: SciPy's "Array must not contain infs or NaNs" of a flow that
        # overflowed); the branch goes on from the last orbit found
        return BranchStep(None, False, carried)
    if orbit.converged:
        return BranchStep(orbit, run_in, to_full(orbit.initial_state, basis))
    return BranchStep(orbit, run_in, carried)


def follow_backlash_branch(systems: Sequence[BacklashSystem], direction: str = "up",
                           parameter: Sequence[float] | None = None, substeps: int = 8, run_in_periods: int = 200,
                           tolerance: float = 1e-10, max_iterations: int = 30,
                           coordinates: Sequence[np.ndarray] | None = None, metric: np.ndarray | None = None,
                           progress: Callable[[int], None] | None = None,
                           measure_swing: bool = True) -> BacklashBranchNDOF:
    """Continuation over ``systems`` (ordered by speed) ``direction`` "up" or "down" (module docstring);
    ``coordinates`` and ``metric`` for systems on different bases (module docstring); ``progress(1)`` is called
    after each point. ``measure_swing=False`` leaves ``peak_to_peak`` NaN (and :meth:`BacklashBranchNDOF.jumps`
    empty) and saves one recorded flow per point, for a caller that samples each orbit itself."""
    count = len(systems)
    labels = continuation_labels(direction, count, parameter, "system")
    sizes = [2 * system.linear.size for system in systems]
    size = max(sizes)
    if (coordinates is None and min(sizes) != size) or (coordinates is not None and (
            metric is None or len(coordinates) != count or any(
                basis.shape != (metric.shape[0], n // 2) for basis, n in zip(coordinates, sizes)))):
        raise ProblemError("coordinates", "absent for systems of different sizes, or not one (N, n_i) basis per "
                           "system with an (N, N) metric", "a basis per system and the metric",
                           "the state carries over through the full system")
    converged, stable, run_in = (np.zeros(count, dtype=bool) for _ in range(3))
    fraction, peak, states = np.full(count, np.nan), np.full(count, np.nan), np.full((count, size), np.nan)
    carried = None
    for index in continuation_order(direction, count):
        system = systems[index]
        step = branch_step(system, carried, None if coordinates is None else coordinates[index], metric, substeps,
                           run_in_periods, tolerance, max_iterations)
        carried, orbit = step.carried, step.orbit
        if orbit is not None:
            converged[index], stable[index], run_in[index] = orbit.converged, orbit.stable, step.run_in
            if orbit.converged:
                state = orbit.initial_state
                states[index, :state.size] = state
                fraction[index] = orbit.free_flight_time / system.linear.period
                if measure_swing:
                    peak[index] = _peak_to_peak(system, state, substeps, {})
        if progress is not None:
            progress(1)
    return BacklashBranchNDOF(labels, direction, converged, stable, run_in, fraction, peak, states)
