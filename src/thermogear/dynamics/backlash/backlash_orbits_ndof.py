"""Which stable orbits of an n-DOF backlash system a start reaches: a start-up from rest, and a multi-start search.

A system with a dead zone can hold several stable periodic orbits at one operating point (Kahraman & Singh, J.
Sound Vib. 142 (1990) 49–75: the no-impact and the impacting orbits of a softening resonance coexist over a band
of speeds). Shooting from the linear periodic state (:func:`~thermogear.dynamics.backlash.backlash_ndof.
backlash_periodic_orbit`) finds one of them; which one a gearbox shows depends on how it got there.

* :func:`startup_orbit`: the orbit the motion from rest (q = q̇ = 0 at τ = 0: the loads and the mesh switched on
  at once, as the 1-DOF model starts) settles on: ``run_in_periods`` mesh periods of the exact flow, then shooting
  from there (a second run-in if the first did not settle). Where the reference orbit keeps one contact state
  throughout (no switch), the motion from rest is first followed under that state's linear flow
  (:func:`~thermogear.dynamics.periodic_orbits.periodic_motion.motion_projections`): if it never leaves the contact
  state, it is the motion of the backlash system and it tends to the reference orbit (the linear system's only periodic
  orbit), so no flow with switches is needed.
* :func:`stable_orbits_ndof`: every stable orbit of one mesh period that a set of starts settles on, with the share
  of starts that reach it (an estimate of its basin's size over the start window, not a probability of the
  operating gearbox). The default starts are the state at rest, the linear periodic state (the start of the orbit
  ``run`` shoots) and a grid over the mesh coordinate and its rate,
  as the 1-DOF search's (:mod:`thermogear.dynamics.backlash.backlash_orbits`): the state of the structure is the mesh's
  static shape φ (the static response to a unit mesh force, scaled to wᵀφ = 1) times x0, and its velocity φ times
  ẋ0, over x0 ∈ [−2(b + 2δ), 2(b + 2δ)] and ẋ0 ∈ [−2ω(b + 2δ), 2ω(b + 2δ)], b the backlash, δ the static mesh
  deflection wᵀq̄ and ω = √(φᵀK̄φ / φᵀMφ) the Rayleigh frequency of that shape. Two orbits are one when their
  states at τ = 0 agree within ``match_tolerance`` in the scaled norm of the shooting.

Only orbits of one mesh period are shot (subharmonic orbits of the n-DOF system are not searched): a start that
settles on none is counted ``unresolved``, one that grows without bound ``unbounded``. No finite search proves an
orbit absent. Knows nothing of gears: matrices only.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from thermogear.dynamics.backlash.backlash_ndof import (DRIVING_CONTACT, STARTUP_MOTION, BacklashOrbitNDOF,
                                                        BacklashSystem, backlash_flow_ndof, backlash_periodic_orbit)
from thermogear.dynamics.backlash.backlash_pieces import contact_state_system
from thermogear.dynamics.periodic_orbits.periodic_motion import motion_projections
from thermogear.dynamics.periodic_orbits.periodic_ndof import periodic_response
from thermogear.dynamics.periodic_orbits.periodic_solves import same_system
from thermogear.errors import ModelLimitError, ProblemError

__all__ = ["OrbitCensusNDOF", "StartupOrbit", "StableOrbitNDOF", "orbit_distance", "settle", "start_states_ndof",
           "startup_orbit", "stable_orbits_ndof"]

_UNBOUNDED = 1e6  # scaled |state| beyond which a run-in grows without bound
WINDOW_MARGIN = 2.0  # the default start window: this many times the backlash plus two static deflections


def orbit_distance(first: np.ndarray, second: np.ndarray) -> float:
    """Distance of two states (2n,) in the scaled norm of the shooting: displacements over the larger of their
    largest displacements, velocities likewise."""
    n = first.size // 2
    distance = 0.0
    for part in (slice(0, n), slice(n, 2 * n)):
        scale = max(np.abs(first[part]).max(initial=0.0), np.abs(second[part]).max(initial=0.0), 1e-300)
        distance = max(distance, float(np.abs(first[part] - second[part]).max(initial=0.0)) / scale)
    return distance


def settle(system: BacklashSystem, start: np.ndarray, run_in_periods: int, substeps: int, tolerance: float,
           max_iterations: int = 30, cache: dict | None = None) -> BacklashOrbitNDOF | None:
    """The stable orbit the motion from ``start`` (2n,) settles on: ``run_in_periods`` periods of the exact flow, then
    shooting; once more from a second run-in where the first did not give a stable converged orbit; else None.
    Raises ModelLimitError where the motion grows without bound."""
    cache = {} if cache is None else cache
    state = np.asarray(start, dtype=float)
    reference = None
    for _ in range(2):
        for _ in range(int(run_in_periods)):
            state, _, _ = backlash_flow_ndof(system, state, substeps, monodromy=False, cache=cache)
        if not np.all(np.isfinite(state)):
            raise ModelLimitError("the backlash motion grows without bound from this start")
        size = float(np.abs(state).max())
        if reference is None:
            reference = max(size, 1e-300)
        elif size > _UNBOUNDED * reference:
            raise ModelLimitError("the backlash motion grows without bound from this start")
        orbit = backlash_periodic_orbit(system, state, substeps, tolerance, max_iterations, cache=cache)
        if orbit.stable:
            return orbit
    return None


@dataclass(frozen=True, eq=False)
class StartupOrbit:
    """What a start from rest reaches: its ``orbit`` (None where it settled on no stable one-period orbit);
    ``same`` whether it is the ``reference`` orbit it was compared with (within the match tolerance);
    ``left_contact_state`` whether the motion from rest ever left the reference's contact state (False: it was
    followed as a linear motion, module docstring); ``run_in_periods`` per run-in; ``failure`` why no orbit was
    reached where the motion could not be followed ('' otherwise)."""

    orbit: BacklashOrbitNDOF | None
    same: bool
    left_contact_state: bool
    run_in_periods: int
    failure: str = ""


def _stays_in_contact(system: BacklashSystem, reference: BacklashOrbitNDOF, periods: int, substeps: int,
                      cache: dict | None = None) -> bool:
    """Whether the motion from rest, under the linear flow of the reference orbit's contact state, keeps that state
    at every sub-step end of ``periods`` periods (its start, at rest, may sit on the mesh boundary: g = 0). The
    motion prepared by the switch-free orbit's solve (``cache``, :data:`~thermogear.dynamics.backlash.backlash_ndof.
    STARTUP_MOTION`) serves where its system is this contact state's, the same numbers without a pass of its own."""
    n = system.linear.size
    key = (system.region(reference.initial_state, 0), system.sides(reference.initial_state))
    if key[0] != DRIVING_CONTACT or reference.switches or reference.free_flight_time or reference.back_contact_time:
        return False
    rest = np.zeros(2 * n)
    if system.mesh_vector @ rest[:n] - system.deviation[0] < 0.0:
        return False
    flow = contact_state_system(system, key)
    prepared = (cache or {}).get((STARTUP_MOTION, substeps))
    if prepared is not None and same_system(prepared.system, flow) \
            and np.array_equal(prepared.rows, system.state_functionals()):
        values = prepared.projections(rest, periods)
    else:
        values = motion_projections(flow, rest, periods, substeps, system.state_functionals())
    pieces = system.linear.nodes.size - 1
    rows = np.arange(1, values.shape[0])
    ends = ((rows - 1) % (pieces * substeps)) // substeps  # each sub-step end on its own piece
    starts = (rows[:-1] % (pieces * substeps)) // substeps  # and each piece's start on the new piece
    return (system.keeps_projected_state(values[1:], ends, key)
            and system.keeps_projected_state(values[1:-1], starts, key))


def startup_orbit(system: BacklashSystem, reference: BacklashOrbitNDOF | None, run_in_periods: int = 60,
                  substeps: int = 16, tolerance: float = 1e-10, match_tolerance: float = 1e-5,
                  max_iterations: int = 30, cache: dict | None = None) -> StartupOrbit:
    """The orbit the motion from rest settles on, compared with ``reference`` (e.g. the orbit shot from the linear
    periodic state; module docstring). Raises ModelLimitError where the motion from rest grows without bound."""
    if isinstance(run_in_periods, bool) or int(run_in_periods) != run_in_periods or run_in_periods < 1:
        raise ProblemError("run_in_periods", run_in_periods, "integer >= 1", "mesh periods of the run-in from rest")
    if reference is not None and reference.stable and _stays_in_contact(system, reference, int(run_in_periods),
                                                                         int(substeps), cache):
        return StartupOrbit(reference, True, False, int(run_in_periods))
    rest = np.zeros(2 * system.linear.size)
    orbit = settle(system, rest, int(run_in_periods), int(substeps), tolerance, max_iterations, cache)
    same = bool(orbit is not None and reference is not None and reference.converged
                and orbit_distance(orbit.initial_state, reference.initial_state) <= match_tolerance)
    return StartupOrbit(orbit, same, True, int(run_in_periods))


@dataclass(frozen=True, eq=False)
class StableOrbitNDOF:
    """One stable orbit found: the ``orbit`` and how many starts settled on it (``start_count``; ``basin_share``
    = start_count / starts); ``from_rest`` whether the start from rest is among them."""

    orbit: BacklashOrbitNDOF
    start_count: int
    basin_share: float
    from_rest: bool


@dataclass(frozen=True, eq=False)
class OrbitCensusNDOF:
    """What a multi-start search found: the distinct stable ``orbits`` (largest basin share first);
    ``start_states`` (starts, 2n); ``outcome`` (starts,) the index into ``orbits`` each start settled on, −1
    unresolved (no stable one-period orbit), −2 unbounded."""

    orbits: tuple[StableOrbitNDOF, ...]
    start_states: np.ndarray
    outcome: np.ndarray


def start_states_ndof(system: BacklashSystem, starts: int) -> np.ndarray:
    """(starts, 2n): the state at rest, the linear periodic state (where there is one), then an evenly spaced grid
    of (x0, ẋ0) of the mesh coordinate lifted onto the mesh's static shape (module docstring), row by row."""
    if isinstance(starts, bool) or int(starts) != starts or starts < 1:
        raise ProblemError("starts", starts, "integer >= 1", "number of initial states of the multi-start search")
    linear = system.linear
    n = linear.size
    widths = np.diff(linear.nodes) / linear.period
    if linear.pattern_count == 1:
        stiffness = linear.stiffness + float(widths @ linear.stiffness_factor) * linear.stiffness_pattern
        force = linear.force + float(widths @ linear.force_factor) * linear.force_pattern
    else:  # several patterns (a train, a face's moments): the period-mean system
        pattern_k, _, pattern_f, factor_k, _, factor_f = linear.stacked()
        stiffness = linear.stiffness + np.tensordot(widths @ factor_k, pattern_k, 1)
        force = linear.force + (widths @ factor_f) @ pattern_f
    shape = np.linalg.solve(stiffness, system.mesh_vector)
    shape = shape / (system.mesh_vector @ shape)
    deflection = abs(float(system.mesh_vector @ np.linalg.solve(stiffness, force)))
    omega = math.sqrt(abs(shape @ stiffness @ shape) / max(shape @ linear.mass @ shape, 1e-300))
    reach = WINDOW_MARGIN * (system.backlash + 2.0 * deflection)
    states = [np.zeros(2 * n)]
    if starts > 1:
        try:  # the linear periodic state: the start of the orbit ``run`` shoots, so the search sees that one too
            states.append(periodic_response(linear, 1).initial_state)
        except ModelLimitError:
            pass
    grid = int(starts) - len(states)
    if grid > 0:
        columns = int(math.ceil(math.sqrt(grid)))
        rows = int(math.ceil(grid / columns))
        xs = np.linspace(-reach, reach, columns)
        vs = np.linspace(-omega * reach, omega * reach, rows) if rows > 1 else np.array([0.0])
        states += [np.concatenate([x * shape, v * shape]) for v in vs for x in xs][:grid]
    return np.array(states)


def stable_orbits_ndof(system: BacklashSystem, starts: int = 16, run_in_periods: int = 60, substeps: int = 16,
                       tolerance: float = 1e-10, match_tolerance: float = 1e-5, max_iterations: int = 30,
                       start_states: np.ndarray | None = None, progress=None) -> OrbitCensusNDOF:
    """Multi-start search for the stable one-period orbits of ``system`` (module docstring): from each of
    ``starts`` states (:func:`start_states_ndof`, the first at rest) or the given ``start_states`` (m, 2n), a run-in
    of ``run_in_periods`` periods and shooting (:func:`settle`). ``progress(1)`` after each start."""
    grid = start_states_ndof(system, starts) if start_states is None else np.asarray(start_states, dtype=float)
    size = 2 * system.linear.size
    if grid.ndim != 2 or grid.shape[1] != size or grid.shape[0] < 1 or not np.all(np.isfinite(grid)):
        raise ProblemError("start_states", f"shape {grid.shape}", f"(m >= 1, {size}) finite", "one state per start")
    cache: dict = {}
    outcome = np.full(grid.shape[0], -1, dtype=np.int64)
    found: list[BacklashOrbitNDOF] = []
    for index, start in enumerate(grid):
        try:
            orbit = settle(system, start, run_in_periods, substeps, tolerance, max_iterations, cache)
        except (ModelLimitError, ProblemError, np.linalg.LinAlgError):
            outcome[index] = -2
            orbit = None
        if orbit is not None:
            match = next((number for number, known in enumerate(found)
                          if orbit_distance(orbit.initial_state, known.initial_state) <= match_tolerance), None)
            if match is None:
                found.append(orbit)
                match = len(found) - 1
            outcome[index] = match
        if progress is not None:
            progress(1)
    counts = np.bincount(outcome[outcome >= 0], minlength=len(found))
    order = sorted(range(len(found)), key=lambda number: (-counts[number], number))
    renumber = {old: new for new, old in enumerate(order)}
    outcome = np.array([renumber.get(int(value), int(value)) for value in outcome], dtype=np.int64)
    rest_index = int(outcome[0]) if start_states is None else -3
    orbits = tuple(StableOrbitNDOF(found[number], int(counts[number]), float(counts[number]) / grid.shape[0],
                                   renumber[number] == rest_index) for number in order)
    return OrbitCensusNDOF(orbits, grid, outcome)
