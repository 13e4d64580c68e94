"""Contact switches of a backlash flow (:mod:`thermogear.dynamics.backlash.backlash_ndof`): the dead zones beside the
mesh's (:class:`DeadZone`) and the further meshes of a train (:class:`MeshZone`); the first boundary a segment
crosses, located by Brent's method on the exact solution; the saltation matrix at a dead zone's switch; and the count
of boundary crossings per period, whose parity tells a closed orbit from a point where a switch was missed. Knows
nothing of gears: matrices only.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from thermogear.dynamics.backlash.backlash_pieces import exponential_action
from thermogear.errors import ProblemError

__all__ = ["DeadZone", "MeshZone", "count_crossings", "first_switch", "odd_crossings", "saltation"]

_DRIVE, _FREE, _BACK = 0, 1, 2  # as thermogear.dynamics.backlash.backlash_ndof (which imports this module)


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

    #: the dashpot stops at a switch: the vector field jumps (saltation matrix)
    jumps = True

    def bounds(self, piece=0) -> tuple[float, float]:
        """The boundaries (+δ, −δ) of u on a piece (the same on every piece)."""
        return self.clearance, -self.clearance

    def opens(self) -> bool:
        """Whether the linear system (the element in contact, no gap) differs from the element's contact law."""
        return self.clearance > 0.0

    def resting_side(self, value: float) -> int:
        """The side a static deflection u = ``value`` pushes the element to (+1 at u >= 0, else −1)."""
        return 1 if value >= 0.0 else -1

    def side(self, state: np.ndarray, size: int, piece: int = 0) -> int:
        """+1 or −1 in contact beyond +δ or −δ, 0 inside the clearance (on a boundary, by the rate)."""
        value, rate = self.vector @ state[:size], self.vector @ state[size:2 * size]
        if value > self.clearance or (value == self.clearance and rate > 0.0):
            return 1
        if value < -self.clearance or (value == -self.clearance and rate < 0.0):
            return -1
        return 0


@dataclass(frozen=True, eq=False)
class MeshZone:
    """A further mesh of a train beside the :class:`~thermogear.dynamics.backlash.backlash_ndof.BacklashSystem`'s own:
    the dead zone of width ``backlash`` b [m] on g = vᵀq − e_j (``vector`` v, ``deviation`` e_j (N,) [m] per piece),
    whose stiffness k_j and damping c_j are column ``column`` of the linear system's multi-pattern factors (the mesh
    in driving contact, force factor k_j·e_j). Side +1: driving flanks (g > 0); 0: free flight (−b <= g <= 0, the
    stiffness factor 0, the damping acting throughout as for the system's own mesh); −1: back flanks (g < −b,
    force factor k_j(e_j − b)). As the system's own mesh, the force k_j·φ(g) is continuous at a switch and the
    damping unchanged, so the vector field does not jump (no saltation; Kahraman & Singh 1990's law per mesh)."""

    vector: np.ndarray
    column: int
    deviation: np.ndarray
    backlash: float

    jumps = False

    def __post_init__(self) -> None:
        object.__setattr__(self, "vector", np.asarray(self.vector, dtype=float))
        object.__setattr__(self, "deviation", np.asarray(self.deviation, dtype=float))
        if not np.isfinite(self.backlash) or self.backlash <= 0.0:
            raise ProblemError("backlash", self.backlash, "> 0 m", "a zero or negative backlash is a jammed mesh")
        if not np.all(np.isfinite(self.deviation)):
            raise ProblemError("deviation", "not finite", "finite per piece", "the mesh's loaded deviation")

    def bounds(self, piece=0) -> tuple:
        """The boundaries of u = vᵀq on a piece (or an array of pieces): (e_j, e_j − b)."""
        upper = self.deviation[piece]
        return upper, upper - self.backlash

    def opens(self) -> bool:
        """False: the linear system holds the mesh in driving contact, as its contact law there."""
        return False

    def resting_side(self, value: float) -> int:
        """+1: a loaded mesh rests on its driving flanks."""
        return 1

    def side(self, state: np.ndarray, size: int, piece: int = 0) -> int:
        """+1 driving, −1 back flanks, 0 free flight (on a boundary, by the rate)."""
        value, rate = self.vector @ state[:size], self.vector @ state[size:2 * size]
        upper, lower = self.bounds(piece)
        if value > upper or (value == upper and rate > 0.0):
            return 1
        if value < lower or (value == lower and rate < 0.0):
            return -1
        return 0


def count_crossings(counts: dict, before: tuple, after: tuple) -> None:
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


def first_switch(system, piece: int, key: tuple, after: tuple, matrix: np.ndarray, z: np.ndarray,
                  h: float, width: float) -> tuple[float, tuple, int | None, int, bool]:
    """The first boundary crossed within h: (time to it, the region after it, the dead zone's index or None for the
    mesh, 1 when a crossing was located by a sign change, whether its instant is known at all — on the boundary
    already counts). Without a crossing found (a double crossing or a boundary state) the step is taken whole and
    the region of the first changed element moves on, as for one element."""
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
            upper, lower = zone.bounds(piece)
            boundary = upper if (old > 0 or (old == 0 and new > 0)) else lower
            side = 0 if old != 0 else (1 if new > 0 else -1)
            candidates.append((zone.vector, boundary, (region, sides[:index] + (side,) + sides[index + 1:]), index))
    best = None
    for vector, boundary, following, index in candidates:
        def distance(s, m=matrix, v=vector, b=boundary):
            return v @ exponential_action(m, z, s)[:n] - b

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


def saltation(before: np.ndarray, after: np.ndarray, vector: np.ndarray, z: np.ndarray) -> np.ndarray:
    """S = I + (f⁺ − f⁻) nᵀ/(nᵀ f⁻) on the augmented state at a switch of u = vᵀq (identity at a grazing one)."""
    size = vector.size
    normal = np.zeros(z.size)
    normal[:size] = vector
    field_before, field_after = before @ z, after @ z
    rate = normal @ field_before
    if rate == 0.0:
        return np.eye(z.size)
    return np.eye(z.size) + np.outer(field_after - field_before, normal) / rate
