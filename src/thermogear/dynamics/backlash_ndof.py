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

Limits: a double crossing inside one sub-step (grazing) is not seen; take ``substeps`` so that a sub-step is short
against the fastest mode the mesh coordinate takes part in.
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np

from thermogear.dynamics.periodic_ndof import PiecewiseLinearSystem, periodic_response
from thermogear.dynamics.piece_groups import representative_rows
from thermogear.dynamics.problem import checked_array
from thermogear.errors import ProblemError

__all__ = ["BACK_CONTACT", "DRIVING_CONTACT", "FREE_FLIGHT", "BacklashSystem", "BacklashOrbitNDOF", "DeadZone",
           "backlash_flow_ndof", "backlash_periodic_orbit", "odd_crossings"]

DRIVING_CONTACT, FREE_FLIGHT, BACK_CONTACT = 0, 1, 2  # the mesh's contact regions (driving flanks, none, back flanks)
_DRIVE, _FREE, _BACK = DRIVING_CONTACT, FREE_FLIGHT, BACK_CONTACT


@dataclass(frozen=True, eq=False)
class DeadZone:
    """A spring ``stiffness`` k [N/m] and dashpot ``damping`` c [N·s/m] on u = vᵀq (``vector`` v) that act only
    beyond the ``clearance`` ±δ [m] >= 0: the force along v is −k(u − δ) − c·u̇ for u > δ, −k(u + δ) − c·u̇ for
    u < −δ and zero in between. The linear system of the :class:`BacklashSystem` includes k v vᵀ and c v vᵀ (the
    element in contact); with δ = 0 the element is linear."""

    vector: np.ndarray
    stiffness: float
    damping: float
    clearance: float

    def __post_init__(self) -> None:
        object.__setattr__(self, "vector", np.asarray(self.vector, dtype=float))
        for key in ("stiffness", "damping", "clearance"):
            value = getattr(self, key)
            if not isinstance(value, (int, float)) or not np.isfinite(value) or value < 0.0:
                raise ProblemError(f"dead_zone.{key}", value, ">= 0, finite", "a spring, dashpot and gap of a contact")

    def engaged(self, value: np.ndarray, rate: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """The dead-zone law on samples of u = vᵀq [m], u̇ [m/s]: the stretch u ∓ δ beyond ±δ and the rate in contact
        (0 inside); the force along v is −(k·stretch + c·rate) (written once; the solver's regions: :meth:`side`)."""
        value, rate = np.asarray(value, dtype=float), np.asarray(rate, dtype=float)
        beyond = np.abs(value) > self.clearance
        return (np.where(beyond, value - np.sign(value) * self.clearance, 0.0),
                np.where(beyond, rate, 0.0))

    def side(self, state: np.ndarray, size: int) -> int:
        """+1 or −1 in contact beyond +δ or −δ, 0 inside the clearance (on a boundary, by the rate)."""
        value, rate = self.vector @ state[:size], self.vector @ state[size:2 * size]
        if value > self.clearance or (value == self.clearance and rate > 0.0):
            return 1
        if value < -self.clearance or (value == -self.clearance and rate < 0.0):
            return -1
        return 0


@dataclass(frozen=True, eq=False)
class BacklashSystem:
    """The linear structure (``linear``: a :class:`PiecewiseLinearSystem` whose stiffness, damping and force
    patterns are w wᵀ, w wᵀ and w with factors k_j, c_j and k_j e_j — the mesh in driving contact) and the backlash
    b [m] of the mesh coordinate g = wᵀq − e_j; ``mesh_vector`` w and ``deviation`` e_j (N,) [m]; ``dead_zones``
    further clearances (:class:`DeadZone`), included in the linear system as if in contact."""

    linear: PiecewiseLinearSystem
    mesh_vector: np.ndarray
    deviation: np.ndarray
    backlash: float
    dead_zones: tuple[DeadZone, ...] = ()

    def __post_init__(self) -> None:
        n, pieces = self.linear.size, self.linear.nodes.size - 1
        if self.linear.pattern_count != 1:  # the shooting follows one mesh coordinate's dead zone
            raise ProblemError("linear", f"{self.linear.pattern_count} meshes", "one mesh", "one backlash coordinate")
        object.__setattr__(self, "dead_zones", tuple(self.dead_zones))
        for zone in self.dead_zones:
            if not isinstance(zone, DeadZone) or zone.vector.shape != (n,):
                raise ProblemError("dead_zones", type(zone).__name__, f"DeadZone with a vector of {n} entries",
                                   "one entry per DOF of the linear system")
        object.__setattr__(self, "mesh_vector", checked_array("mesh_vector", self.mesh_vector, (n,), "one per DOF"))
        object.__setattr__(self, "deviation", checked_array("deviation", self.deviation, (pieces,)))
        if not np.isfinite(self.backlash) or self.backlash <= 0.0:
            raise ProblemError("backlash", self.backlash, "> 0 m", "a zero or negative backlash is a jammed mesh")

    def region_matrix(self, piece: int, region: int, mass_inverse: np.ndarray,
                      sides: tuple[int, ...] = ()) -> np.ndarray:
        """Augmented (2n+1)² matrix of one piece in one contact region of the mesh and, for each dead zone, its
        side (+1, −1 in contact; 0 inside the clearance; all in contact when ``sides`` is empty)."""
        system = self.linear
        n = system.size
        k = system.stiffness_factor[piece] if region != _FREE else 0.0
        shift = {_DRIVE: self.deviation[piece], _FREE: 0.0, _BACK: self.deviation[piece] - self.backlash}[region]
        stiffness = system.stiffness + k * system.stiffness_pattern
        damping = system.damping + system.damping_factor[piece] * system.damping_pattern
        force = system.force + k * shift * self.mesh_vector
        for zone, side in zip(self.dead_zones, sides):
            if side == 0:
                pattern = np.outer(zone.vector, zone.vector)
                stiffness, damping = stiffness - zone.stiffness * pattern, damping - zone.damping * pattern
            else:
                force = force + side * zone.stiffness * zone.clearance * zone.vector
        matrix = np.zeros((2 * n + 1, 2 * n + 1))
        matrix[:n, n:2 * n] = np.eye(n)
        matrix[n:2 * n, :n] = -mass_inverse @ stiffness
        matrix[n:2 * n, n:2 * n] = -mass_inverse @ damping
        matrix[n:2 * n, 2 * n] = mass_inverse @ force
        return matrix

    def sides(self, state: np.ndarray) -> tuple[int, ...]:
        """The side of every dead zone (:meth:`DeadZone.side`)."""
        return tuple(zone.side(state, self.linear.size) for zone in self.dead_zones)

    def region(self, state: np.ndarray, piece: int) -> int:
        """Contact region of a state (n-DOF displacement first) on a piece, by g and, on a boundary, by ġ."""
        n = self.linear.size
        gap = self.mesh_vector @ state[:n] - self.deviation[piece]
        rate = self.mesh_vector @ state[n:2 * n]
        if gap > 0.0 or (gap == 0.0 and rate > 0.0):
            return _DRIVE
        if gap < -self.backlash or (gap == -self.backlash and rate < 0.0):
            return _BACK
        return _FREE


def backlash_flow_ndof(system: BacklashSystem, state: np.ndarray, substeps: int = 16, record: bool = False,
                       monodromy: bool = True, cache: dict | None = None
                       ) -> tuple[np.ndarray, np.ndarray | None, dict]:
    """φ_T(state): end state (2n,), monodromy (2n, 2n) (None without ``monodromy``) and {"switches",
    "free_flight_time", "back_contact_time", "zone_switches", "crossings", "time", "states", "segments"} (the last
    three filled when ``record``: the state after every segment and the (piece, region, dead-zone sides) that held on
    it; a segment may be empty, h = 0, where a switch was found at its start). ``cache``: a dict kept between calls
    on the same system (the exponentials of each piece's contact states are computed once per ``substeps``). A piece
    crossed without a switch enters the monodromy as one cached power of its sub-step exponential."""
    from scipy.linalg import expm

    linear = system.linear
    n = linear.size
    inverse = np.linalg.inv(linear.mass)
    z = np.append(np.asarray(state, dtype=float), 1.0)
    total = np.eye(2 * n + 1) if monodromy else None
    cache = {} if cache is None else cache
    info = {"switches": 0, "free_flight_time": 0.0, "back_contact_time": 0.0, "zone_switches": 0, "time": [0.0],
            "states": [z[:-1]], "segments": [], "crossings": {}}

    if "representative" not in cache:  # pieces equal within PIECE_TOLERANCE share their exponentials
        cache["representative"] = representative_rows(np.column_stack([
            np.diff(linear.nodes), linear.stiffness_factor, linear.damping_factor, system.deviation]))
    representative = cache["representative"]

    def exponentials(piece: int, key: tuple) -> tuple[np.ndarray, np.ndarray]:
        """(augmented matrix, its exponential over one sub-step) of a piece in one contact state, cached (on the
        first piece of its group: :func:`~thermogear.dynamics.piece_groups.representative_rows`)."""
        piece = int(representative[piece])
        if (piece, key, substeps) not in cache:
            matrix = system.region_matrix(piece, key[0], inverse, key[1])
            width = linear.nodes[piece + 1] - linear.nodes[piece]
            cache[(piece, key, substeps)] = (matrix, expm(matrix * (width / substeps)))
        return cache[(piece, key, substeps)]

    key = None
    for piece in range(linear.nodes.size - 1):
        start, stop = linear.nodes[piece], linear.nodes[piece + 1]
        step = (stop - start) / substeps
        previous, key = key, (system.region(z, piece), system.sides(z))  # at a node the deviation steps: afresh
        if previous is not None:
            _count_crossings(info["crossings"], previous, key)
        first_key, uniform, product = key, True, []
        t = start
        while t < stop - 1e-12 * (stop - start):
            matrix, full_step = exponentials(piece, key)
            h = min(step, stop - t)
            trial = (full_step if h == step else expm(matrix * h)) @ z
            after = (system.region(trial, piece), system.sides(trial))
            following, zone = key, None
            if after != key:
                h, following, zone, switched, seen = _first_switch(system, piece, key, after, matrix, z, h,
                                                                   stop - start)
                info["switches" if zone is None else "zone_switches"] += switched
                if seen:  # a crossing at a known instant (not a change taken over a whole sub-step)
                    _count_crossings(info["crossings"], key, following)
            if h > 0.0:
                segment = full_step if h == step else expm(matrix * h)
                uniform = uniform and h == step and key == first_key
                if monodromy:
                    product.append(segment)
                z = segment @ z
                if key[0] == _FREE:
                    info["free_flight_time"] += h
                elif key[0] == _BACK:
                    info["back_contact_time"] += h
                t += h
            if zone is not None:  # the dead zone's dashpot starts or stops: the vector field jumps
                uniform = False
                if monodromy:
                    product.append(_saltation(matrix, exponentials(piece, following)[0],
                                              system.dead_zones[zone].vector, z))
            if record:
                info["time"].append(t)
                info["states"].append(z[:-1])
                info["segments"].append((piece, key[0], key[1]))
            key = following
            if not np.all(np.isfinite(z)):
                raise ProblemError("state", "not finite", "a bounded motion", "the coefficients are out of range")
        if monodromy:
            total = _piece_product(cache, (int(representative[piece]), first_key, substeps), product,
                                   uniform) @ total
    _count_crossings(info["crossings"], key, (system.region(z, 0), system.sides(z)))  # the period's end node
    return z[:-1], None if total is None else total[:-1, :-1], info


def _piece_product(cache: dict, entry: tuple, product: list, uniform: bool) -> np.ndarray:
    """The transition over one piece: where one contact state held throughout in full sub-steps, the cached power
    of its sub-step exponential (exact: the same linear flow), else the product of its segments and saltations."""
    if uniform and product:
        if ("piece", *entry) not in cache:
            cache[("piece", *entry)] = np.linalg.matrix_power(cache[entry][1], len(product))
        return cache[("piece", *entry)]
    result = np.eye(cache[entry][0].shape[0])
    for matrix in product:
        result = matrix @ result
    return result


def _count_crossings(counts: dict, before: tuple, after: tuple) -> None:
    """Add the boundaries crossed from contact state ``before`` to ``after`` to ``counts``: ("mesh", 0) the
    driving-flank boundary g = 0, ("mesh", 1) the back-flank one g = −b, ("zone", i, ±1) dead zone i's u = ±δ."""
    regions = {before[0], after[0]}
    if regions & {_DRIVE} and regions - {_DRIVE}:
        counts[("mesh", 0)] = counts.get(("mesh", 0), 0) + 1
    if regions & {_BACK} and regions - {_BACK}:
        counts[("mesh", 1)] = counts.get(("mesh", 1), 0) + 1
    for index, (old, new) in enumerate(zip(before[1], after[1])):
        for side in (1, -1):
            if (old == side) != (new == side):
                counts[("zone", index, side)] = counts.get(("zone", index, side), 0) + 1


def odd_crossings(counts: dict) -> list:
    """The boundaries crossed an odd number of times (``counts`` as the flow's "crossings"). A closed orbit crosses
    each boundary an even number of times per period (it returns to the side it started on), counting the jumps of
    the boundary at the nodes (the deviation steps); an odd count on a "periodic" point means a crossing that was
    not located — a change of region taken over a whole sub-step — so the point is no orbit of the system."""
    return sorted(boundary for boundary, count in counts.items() if count % 2)


def _first_switch(system: BacklashSystem, piece: int, key: tuple, after: tuple, matrix: np.ndarray, z: np.ndarray,
                  h: float, width: float) -> tuple[float, tuple, int | None, int, bool]:
    """The first boundary crossed within h: (time to it, the region after it, the dead zone's index or None for the
    mesh, 1 when a crossing was located by a sign change, whether its instant is known at all — on the boundary
    already counts). Without a crossing found (a double crossing or a boundary state) the step is taken whole and
    the region of the first changed element moves on, as for one element."""
    from scipy.linalg import expm
    from scipy.optimize import brentq

    n = system.linear.size
    candidates = []  # (vector, boundary, offset, region after, zone index)
    region, sides = key
    if after[0] != region:
        # the boundary crossed first: from free flight the one on the side the motion ends
        boundary = -system.backlash if (region == _BACK or (region == _FREE and after[0] == _BACK)) else 0.0
        following = _FREE if region != _FREE else after[0]
        candidates.append((system.mesh_vector, boundary + system.deviation[piece], (following, sides), None))
    for index, (old, new) in enumerate(zip(sides, after[1])):
        if old != new:
            zone = system.dead_zones[index]
            boundary = zone.clearance if (old > 0 or (old == 0 and new > 0)) else -zone.clearance
            side = 0 if old != 0 else (1 if new > 0 else -1)
            candidates.append((zone.vector, boundary, (region, sides[:index] + (side,) + sides[index + 1:]), index))
    best = None
    for vector, boundary, following, index in candidates:
        def distance(s, m=matrix, v=vector, b=boundary):
            return v @ (expm(m * s) @ z)[:n] - b

        low, high = distance(0.0), distance(h)
        if low * high < 0.0:
            root, located = brentq(distance, 0.0, h, xtol=1e-13 * width, rtol=1e-14), 1
        elif low == 0.0 or (index is not None and abs(low) <= 1e-8 * abs(high)):
            # on the boundary already (a switch just located leaves |u − ±δ| ~ 1e-13 of the motion, on either
            # side): the element passes through at once — a zero clearance has no inside to dwell in
            root, located = 0.0, 0
        else:
            continue
        if best is None or root < best[0]:
            best = (root, following, index, located)
    if best is None:
        _, _, following, index = candidates[0]
        return h, following, index, 0, False
    return (*best, True)


def _saltation(before: np.ndarray, after: np.ndarray, vector: np.ndarray, z: np.ndarray) -> np.ndarray:
    """S = I + (f⁺ − f⁻) nᵀ/(nᵀ f⁻) on the augmented state at a switch of u = vᵀq (identity at a grazing one)."""
    size = vector.size
    normal = np.zeros(z.size)
    normal[:size] = vector
    field_before, field_after = before @ z, after @ z
    rate = normal @ field_before
    if rate == 0.0:
        return np.eye(z.size)
    return np.eye(z.size) + np.outer(field_after - field_before, normal) / rate


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
    state = (periodic_response(system.linear, 1).initial_state if initial_state is None
             else np.asarray(initial_state, dtype=float))
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
