"""Periodic orbits of an n-DOF linear system with one backlash (dead-zone) coordinate, by shooting.

M q̈ + (C₀ + c_j w wᵀ) q̇ + K₀ q + k_j·φ(wᵀq − e_j)·w = f₀ on piece j of one period, with the dead zone of width b

    φ(g) = g (g > 0, driving flanks in contact),  0 (−b ≤ g ≤ 0, free flight),  g + b (g < −b, back flanks)

(Kahraman & Singh, J. Sound Vib. 142 (1990) 49–75, for one coordinate; here any structure around it). Damping acts
at all times, so the vector field is continuous across a contact switch and the saltation matrix is the identity:
the monodromy of an orbit is the product of the exact transition matrices of its linear segments (Leine & Nijmeijer,
Dynamics and Bifurcations of Non-Smooth Mechanical Systems, 2004, ch. 7). Each segment (a piece in one contact
region) is solved exactly by the augmented exponential (Van Loan 1978); switches are found on sub-steps of each piece
and located by Brent's method on the exact solution. Newton on φ_T(z₀) − z₀ with that monodromy finds the orbit,
starting from the linear periodic state (driving contact throughout). Knows nothing of gears.

Dead zones (:class:`DeadZone`, e.g. a bearing's radial clearance in one direction): a spring and dashpot on
u = vᵀq that act only beyond ±δ. Their dashpot stops at a switch, so the vector field jumps there and the monodromy
takes the saltation matrix S = I + (f⁺ − f⁻) nᵀ/(nᵀf⁻) at each of their switches (n = [v; 0] the boundary's
normal, f∓ the vector fields on either side; Leine & Nijmeijer 2004, §7.2).

A train's further meshes (:class:`MeshZone`): each the same dead zone law on its own coordinate wᵀ_m q − e_mj, its
stiffness and damping a further pattern of the linear system (column m of its factors); in free flight its stiffness
factor is zero and its damping acts on, so its switches, like the system's own mesh's, need no saltation matrix.

Limits: a double crossing inside one sub-step (grazing) is not seen; take ``substeps`` so that a sub-step is short
against the fastest mode the mesh coordinate takes part in.
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np

from thermogear.dynamics.backlash.backlash_pieces import PieceExponentials, contact_state_system
from thermogear.dynamics.backlash.backlash_system import BACK_CONTACT, DRIVING_CONTACT, FREE_FLIGHT, BacklashSystem
from thermogear.dynamics.backlash.backlash_switches import (DeadZone, MeshZone, count_crossings, first_switch,
                                                            odd_crossings, saltation)
from thermogear.dynamics.periodic_orbits.periodic_ndof import periodic_response
from thermogear.errors import ModelLimitError, ProblemError

__all__ = ["BACK_CONTACT", "DRIVING_CONTACT", "FREE_FLIGHT", "PERIODIC_SOLVES", "STARTUP_MOTION", "WATCH_STARTUP", "BacklashSystem",
           "BacklashOrbitNDOF", "DeadZone", "MeshZone", "backlash_flow_ndof", "backlash_periodic_orbit", "odd_crossings",
           "piece_exponentials", "switch_free_record"]

_DRIVE, _FREE, _BACK = DRIVING_CONTACT, FREE_FLIGHT, BACK_CONTACT


def backlash_flow_ndof(system: BacklashSystem, state: np.ndarray, substeps: int = 16, record: bool = False,
                       monodromy: bool = True, cache: dict | None = None
                       ) -> tuple[np.ndarray, np.ndarray | None, dict]:
    """φ_T(state): end state (2n,), monodromy (2n, 2n) (None without ``monodromy``) and {"switches",
    "free_flight_time", "back_contact_time", "zone_switches", "crossings", "time", "states", "segments"} (the last
    three filled when ``record``: the state after every segment and the (piece, region, dead-zone sides) that held on
    it; a segment may be empty, h = 0, where a switch was found at its start). ``cache``: a dict kept between calls
    on the same system (the pieces' exponentials of each contact state,
    :class:`~thermogear.dynamics.backlash.backlash_pieces. PieceExponentials`, are formed once per ``substeps``, in
    batches).

    Each piece is first stepped through its ``substeps`` sub-steps in the contact state it starts in, and the states
    of up to :data:`_SETTLE_EVERY` consecutive pieces of one state are checked in one call (:func:`_settle`); where
    none changed state, that is the piece's motion (the same sub-step ends the switch search looks at) and it enters
    the monodromy as the whole piece's transition. From the first piece that leaves its state, the sub-steps are
    taken one by one from the piece's start and every switch is located (module docstring); the pieces after it are
    stepped again from its end."""
    linear = system.linear
    n = linear.size
    cache = {} if cache is None else cache
    pieces = piece_exponentials(system, substeps, cache)
    z = np.append(np.asarray(state, dtype=float), 1.0)
    total = np.eye(2 * n + 1) if monodromy else None
    info = {"switches": 0, "free_flight_time": 0.0, "back_contact_time": 0.0, "zone_switches": 0, "time": [0.0],
            "states": [z[:-1]], "segments": [], "crossings": {}}
    functionals = system.state_functionals()
    key, pending, piece = None, [], 0
    while piece < linear.nodes.size - 1:
        previous, key = key, (system.region(z, piece), system.sides(z, piece))  # at a node the deviation steps: afresh
        if pending and key != pending[0][2]:  # the pieces taken so far end: are they one contact state?
            failed, z, total = _settle(system, pieces, pending, info, record, total)
            pending = []
            if failed is not None:  # the motion from that piece's start switches: followed sub-step by sub-step
                piece, previous, key, z = failed
                if previous is not None:
                    count_crossings(info["crossings"], previous, key)
                z, key, total = _switching_piece(system, pieces, piece, key, z, substeps, info, record, total)
                piece += 1
                continue
        full_step = pieces.step(piece, key)
        states = np.empty((substeps, 2 * n + 1))
        trial = z
        for index in range(substeps):
            trial = full_step @ trial
            states[index] = trial
        # taken as if it keeps its contact state, checked with the pieces of the same state in one call (_settle)
        pending.append((piece, previous, key, z, states, states[:, :2 * n] @ functionals.T))
        z = states[-1]
        piece += 1
        if len(pending) == _SETTLE_EVERY or piece == linear.nodes.size - 1:
            failed, z, total = _settle(system, pieces, pending, info, record, total)
            pending = []
            if failed is not None:
                piece, previous, key, z = failed
                if previous is not None:
                    count_crossings(info["crossings"], previous, key)
                z, key, total = _switching_piece(system, pieces, piece, key, z, substeps, info, record, total)
                piece += 1
    count_crossings(info["crossings"], key, (system.region(z, 0), system.sides(z)))  # the period's end node
    return z[:-1], None if total is None else total[:-1, :-1], info


#: Pieces taken as keeping their contact state before their states are checked in one call (:func:`_settle`).
_SETTLE_EVERY = 64


def _settle(system: BacklashSystem, pieces: PieceExponentials, pending: list, info: dict, record: bool,
            total: np.ndarray | None) -> tuple[tuple | None, np.ndarray, np.ndarray | None]:
    """Take the ``pending`` pieces (piece, key before it, its key, start state, sub-step states, their functionals;
    one key) up to the first whose sub-step states leave its contact state: (that piece's (piece, key before it, key,
    start state) or None, the state where the kept ones end, the monodromy so far). The check is the per-piece rule of
    :meth:`BacklashSystem.keeps_projected_state` on the same functionals, all rows at once; where it fails, piece by
    piece to find the first."""
    key = pending[0][2]
    values = np.concatenate([entry[5] for entry in pending])
    rows = np.repeat([entry[0] for entry in pending], pending[0][4].shape[0])
    kept = len(pending)
    if not system.keeps_projected_state(values, rows, key):
        kept = next(index for index, entry in enumerate(pending)
                    if not system.keeps_projected_state(entry[5], entry[0], key))
    nodes, substeps = system.linear.nodes, pending[0][4].shape[0]
    z = pending[0][3]
    finite = kept == 0 or bool(np.isfinite([entry[4][-1] for entry in pending[:kept]]).all())
    for piece, previous, key, _, states, _ in pending[:kept]:
        if previous is not None and previous != key:  # the same state on both sides crosses nothing
            count_crossings(info["crossings"], previous, key)
        start, stop = nodes[piece], nodes[piece + 1]
        if key[0] == _FREE:
            info["free_flight_time"] += stop - start
        elif key[0] == _BACK:
            info["back_contact_time"] += stop - start
        if record:
            step = (stop - start) / substeps
            info["time"].extend([start + (index + 1) * step for index in range(substeps - 1)] + [stop])
            info["states"].extend(states[:, :-1])
            info["segments"].extend([(piece, key[0], key[1])] * substeps)
        z = states[-1]
        if total is not None:
            total = pieces.whole(piece, key) @ total
        if not finite and not np.all(np.isfinite(z)):
            raise ProblemError("state", "not finite", "a bounded motion", "the coefficients are out of range")
    failed = None if kept == len(pending) else pending[kept][:4]
    return failed, z, total


def _switching_piece(system: BacklashSystem, pieces: PieceExponentials, piece: int, key: tuple, z: np.ndarray,
                     substeps: int, info: dict, record: bool, total: np.ndarray | None
                     ) -> tuple[np.ndarray, tuple, np.ndarray | None]:
    """One piece whose motion leaves its contact state, from ``z`` at its start: sub-step by sub-step, every switch
    located (module docstring). Returns (the end state, the contact state there, the monodromy so far)."""
    from scipy.linalg import expm

    start, stop = system.linear.nodes[piece], system.linear.nodes[piece + 1]
    step = (stop - start) / substeps
    product = []
    t = start
    while t < stop - 1e-12 * (stop - start):
        matrix, full_step = pieces.matrix(piece, key), pieces.step(piece, key)
        h = min(step, stop - t)
        trial = (full_step if h == step else expm(matrix * h)) @ z
        after = (system.region(trial, piece), system.sides(trial, piece))
        following, zone = key, None
        if after != key:
            h, following, zone, switched, seen = first_switch(system, piece, key, after, matrix, z, h, stop - start)
            info["switches" if zone is None else "zone_switches"] += switched
            if seen:  # a crossing at a known instant (not a change taken over a whole sub-step)
                count_crossings(info["crossings"], key, following)
        if h > 0.0:
            segment = full_step if h == step else expm(matrix * h)
            if total is not None:
                product.append(segment)
            z = segment @ z
            if key[0] == _FREE:
                info["free_flight_time"] += h
            elif key[0] == _BACK:
                info["back_contact_time"] += h
            t += h
        if zone is not None and total is not None and system.dead_zones[zone].jumps:  # its dashpot starts or stops
            product.append(saltation(matrix, pieces.matrix(piece, following), system.dead_zones[zone].vector, z))
        if record:
            info["time"].append(t)
            info["states"].append(z[:-1])
            info["segments"].append((piece, key[0], key[1]))
        key = following
        if not np.all(np.isfinite(z)):
            raise ProblemError("state", "not finite", "a bounded motion", "the coefficients are out of range")
    for matrix in product:
        total = matrix @ total
    return z, key, total


def piece_exponentials(system: BacklashSystem, substeps: int, cache: dict) -> PieceExponentials:
    """The :class:`~thermogear.dynamics.backlash.backlash_pieces.PieceExponentials` of ``system`` with ``substeps``
    sub-steps per piece, kept in ``cache`` (a dict kept between calls on the same system)."""
    entry = ("pieces", int(substeps))
    if entry not in cache:
        cache[entry] = PieceExponentials(system, int(substeps), np.linalg.inv(system.linear.mass))
    return cache[entry]


@dataclass(frozen=True, eq=False)
class BacklashOrbitNDOF:
    """A periodic orbit with backlash: ``initial_state`` z₀ (2n,), Floquet ``multipliers`` of its monodromy,
    ``converged`` (Newton residual below tolerance and every boundary crossed an even number of times),
    ``residual`` (relative), contact statistics per period, ``substeps`` the sub-steps per piece it was found
    with, ``failure`` why it is not converged ('' when it is)."""

    initial_state: np.ndarray
    multipliers: np.ndarray
    converged: bool
    residual: float
    iterations: int
    switches: int
    free_flight_time: float
    back_contact_time: float
    failure: str = ""
    substeps: int = 16

    @property
    def stable(self) -> bool:
        """Converged with every multiplier inside the unit circle."""
        return bool(self.converged and np.abs(self.multipliers).max() < 1.0)


MAX_SUBSTEPS = 64  # the odd-crossing guard refines the sub-steps up to this many per piece
#: A ``cache`` entry set to True by a caller that will run the start-up check (the motion from rest under the
#: switch-free orbit's linear flow, :func:`~thermogear.dynamics.backlash.backlash_orbits_ndof.startup_orbit`): the
#: switch-free orbit's solve then prepares that motion on its own pass of sub-step exponentials
#: (:class:`~thermogear.dynamics.periodic_orbits.periodic_motion.MotionProjector`, kept in the cache under
#``STARTUP_MOTION``).
WATCH_STARTUP = "watch the start-up"
STARTUP_MOTION = "start-up motion"
#: A ``cache`` entry holding a :class:`~thermogear.dynamics.periodic_orbits.periodic_solves.PeriodicSolves` shared with
#the caller: : the switch-free orbit's periodic solve is kept there (and taken from there where the same system, bit for
#bit, : was solved before), e.g. for the linear periodic response of the same operating point.
PERIODIC_SOLVES = "periodic solves"


def backlash_periodic_orbit(system: BacklashSystem, initial_state: np.ndarray | None = None, substeps: int = 16,
                            tolerance: float = 1e-10, max_iterations: int = 30, cache: dict | None = None
                            ) -> BacklashOrbitNDOF:
    """Shooting (damped Newton with the exact monodromy) from ``initial_state`` or the linear periodic state.

    A point where Newton converged but some boundary is crossed an odd number of times (:func:`odd_crossings`: a
    switch was missed within a sub-step) is shot again from there with twice the sub-steps, up to
    :data:`MAX_SUBSTEPS`; if the count is still odd the orbit is returned with ``converged`` False and the reason in
    ``failure``. ``cache``: the flows' exponentials (:func:`backlash_flow_ndof`), shared with a later flow of the
    same system (e.g. its sampling).
    """
    cache = {} if cache is None else cache
    if initial_state is None:
        state, orbit = _switch_free_orbit(system, int(substeps), tolerance, cache)
        if orbit is not None:
            return orbit
    else:
        state = np.asarray(initial_state, dtype=float)
    steps = int(substeps)
    while True:
        orbit, crossings = _shoot(system, state, steps, tolerance, max_iterations, cache)
        odd = odd_crossings(crossings)
        if not orbit.converged or not odd:
            return replace(orbit, failure="" if orbit.converged else
                           f"Newton stopped at residual {orbit.residual:.3g} > {tolerance:g}")
        if 2 * steps > MAX_SUBSTEPS:
            return replace(orbit, converged=False, failure=(
                f"boundaries crossed an odd number of times per period ({', '.join(map(str, odd))}) with "
                f"{steps} sub-steps per piece: a switch is missed, the point is no closed orbit"))
        state, steps = orbit.initial_state, 2 * steps


def _switch_free_orbit(system: BacklashSystem, substeps: int, tolerance: float, cache: dict
                       ) -> tuple[np.ndarray, BacklashOrbitNDOF | None]:
    """(the linear periodic state, the orbit where it needs no shooting, else None).

    The linear periodic state (every element in contact, no clearance) starts the shooting. Where its contact state
    (driving flanks, each dead zone's side) gives a periodic orbit of that state's own linear system (with the
    clearances' constant forces) that keeps the state at every sub-step end — the instants at which the flow looks
    for switches — the flow from it never switches: it is a closed orbit of the backlash system, and its monodromy is
    that system's. So it is returned without a flow: one periodic solution of the contact state's system
    (:func:`~thermogear.dynamics.periodic_orbits.periodic_ndof.periodic_response`, all pieces batched) instead of
    Newton's flows of the whole period with their monodromy products. Its sub-step states are kept in ``cache`` for the
    sampling
    (:func:`switch_free_record`)."""
    projector = None
    if cache.get(WATCH_STARTUP):  # the start-up check will follow: prepare its motion on this solve's pass
        from thermogear.dynamics.periodic_orbits.periodic_motion import MotionProjector

        projector = MotionProjector(system.linear, substeps, system.state_functionals())
    solve = cache[PERIODIC_SOLVES].response if PERIODIC_SOLVES in cache else periodic_response
    response = solve(system.linear, substeps, observer=None if projector is None else projector.add)
    if projector is not None and projector.complete:
        cache[(STARTUP_MOTION, substeps)] = projector
    start = response.initial_state
    key = (system.region(start, 0), system.sides(start))
    if key[0] != _DRIVE:
        return start, None
    if any(not side == 1 for zone, side in zip(system.dead_zones, key[1]) if isinstance(zone, MeshZone)):
        return start, None  # a further mesh out of driving contact in the linear state: no switch-free orbit
    if any(zone.opens() for zone in system.dead_zones):  # the clearances' forces: another system
        # each loaded clearance closed on the side its load pushes it to (the sign of its deflection in the linear
        # state): the contact state of a shaft that rests in its bearings
        n = system.linear.size
        key = (_DRIVE, tuple(zone.resting_side(zone.vector @ start[:n]) for zone in system.dead_zones))
        try:
            response = periodic_response(contact_state_system(system, key), substeps)
        except ModelLimitError:
            return start, None
        # where its start rests against the sides assumed, the shooting starts from this orbit even if it is no orbit of
        # the backlash system (a switch later in the period): the shaft rests against the side of each clearance the
        # load pushes it to, δ from the bearing's centre, which the linear state (every clearance closed) misses by δ —
        # tens of μm against a few μm of deflection. Otherwise (a clearance wider than the load moves the shaft) the
        # linear state is the better start.
        if system.sides(response.initial_state) == key[1]:
            start = response.initial_state
    states = np.hstack([response.displacement, response.velocity])
    pieces = system.linear.nodes.size - 1
    rows = np.arange(states.shape[0])
    # each sub-step end on its own piece (as the flow checks it) and each piece's start on the new piece
    if not (system.keeps_state(states[1:], (rows[1:] - 1) // substeps, key)
            and system.keeps_state(states[:-1], rows[:-1] // substeps, key)):
        return start, None
    n = system.linear.size
    initial = response.initial_state
    scale = np.concatenate([np.full(n, max(np.abs(initial[:n]).max(), 1e-300)),
                            np.full(n, max(np.abs(initial[n:]).max(), 1e-300))])
    residual = float(np.abs((states[-1] - states[0]) / scale).max())
    if residual > tolerance:
        return start, None
    cache[("switch-free orbit", substeps)] = (initial, states, response.time, key, pieces)
    orbit = BacklashOrbitNDOF(initial, response.multipliers, True, residual, 0, 0, 0.0, 0.0, substeps=substeps)
    return initial, orbit


def switch_free_record(cache: dict, state: np.ndarray, substeps: int) -> tuple[np.ndarray, dict] | None:
    """(end state, the record of :func:`backlash_flow_ndof`) of one period from ``state`` where it is the orbit
    :func:`backlash_periodic_orbit` found without switches (its sub-step states, kept in ``cache``), else None."""
    entry = cache.get(("switch-free orbit", int(substeps)))
    if entry is None or not np.array_equal(entry[0], state):
        return None
    initial, states, time, key, pieces = entry
    rows = np.arange(1, states.shape[0])
    info = {"switches": 0, "free_flight_time": 0.0, "back_contact_time": 0.0, "zone_switches": 0,
            "time": list(time), "states": list(states), "crossings": {},
            "segments": [(int(piece), key[0], key[1]) for piece in (rows - 1) // int(substeps)]}
    return states[-1], info


def _shoot(system: BacklashSystem, state: np.ndarray, substeps: int, tolerance: float, max_iterations: int,
           cache: dict) -> tuple[BacklashOrbitNDOF, dict]:
    """Damped Newton from ``state``: the orbit (failure not yet set) and the crossings of its last flow."""
    n = system.linear.size
    scale = np.concatenate([np.full(n, max(np.abs(state[:n]).max(), 1e-300)),
                            np.full(n, max(np.abs(state[n:]).max(), 1e-300))])

    def measure(difference):
        return float(np.abs(difference / scale).max())

    end, matrix, info = backlash_flow_ndof(system, state, substeps, cache=cache)
    residual, iterations = measure(end - state), 0
    while residual > tolerance and iterations < max_iterations:
        iterations += 1
        step = np.linalg.solve(matrix - np.eye(2 * n), -(end - state))
        factor = 1.0
        for _ in range(9):
            trial = state + factor * step
            trial_end, trial_matrix, trial_info = backlash_flow_ndof(system, trial, substeps, cache=cache)
            trial_residual = measure(trial_end - trial)
            if trial_residual < residual:
                break
            factor *= 0.5
        else:
            break
        state, end, matrix, info, residual = trial, trial_end, trial_matrix, trial_info, trial_residual
    multipliers = np.linalg.eigvals(matrix)
    orbit = BacklashOrbitNDOF(state, multipliers[np.argsort(-np.abs(multipliers))], residual <= tolerance, residual,
                              iterations, info["switches"], info["free_flight_time"], info["back_contact_time"],
                              substeps=substeps)
    return orbit, info["crossings"]
