"""The backlash system the n-DOF backlash solvers take (:mod:`thermogear.dynamics.backlash.backlash_ndof`): a linear
piecewise-constant structure with the mesh in driving contact, the mesh's dead zone of width b on g = wᵀq − e_j, and
further dead zones (bearing clearances, a train's further meshes); its contact regions and the test of whether
states keep a contact state. Knows nothing of gears: matrices only.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property

import numpy as np

from thermogear.dynamics.backlash.backlash_switches import DeadZone, MeshZone
from thermogear.dynamics.problems.piecewise_system import PiecewiseLinearSystem
from thermogear.dynamics.problems.problem import checked_array
from thermogear.errors import ProblemError

__all__ = ["BACK_CONTACT", "DRIVING_CONTACT", "FREE_FLIGHT", "BacklashSystem"]

DRIVING_CONTACT, FREE_FLIGHT, BACK_CONTACT = 0, 1, 2  # the mesh's contact regions (driving flanks, none, back flanks)
_DRIVE, _FREE, _BACK = DRIVING_CONTACT, FREE_FLIGHT, BACK_CONTACT


@dataclass(frozen=True, eq=False)
class BacklashSystem:
    """The linear structure (``linear``: a :class:`PiecewiseLinearSystem` whose stiffness, damping and force
    patterns are w wᵀ, w wᵀ and w with factors k_j, c_j and k_j e_j — the mesh in driving contact) and the backlash
    b [m] of the mesh coordinate g = wᵀq − e_j; ``mesh_vector`` w and ``deviation`` e_j (N,) [m]; ``dead_zones``
    further clearances (:class:`DeadZone`), included in the linear system as if in contact.

    A mesh may own several patterns (e.g. the moments of a contact spread across a face): ``pattern_meshes`` gives,
    per pattern of a multi-pattern system, the column of its mesh's own pattern (empty: every pattern a mesh of its
    own); every pattern of a mesh loses its stiffness factor in free flight, and on the back flanks its force factor
    moves by −b times ``back_shift`` (N, P) (None: the stiffness factor, the mesh's own pattern)."""

    linear: PiecewiseLinearSystem
    mesh_vector: np.ndarray
    deviation: np.ndarray
    backlash: float
    dead_zones: tuple[DeadZone, ...] = ()
    pattern_meshes: tuple[int, ...] = ()
    back_shift: np.ndarray | None = None

    def __post_init__(self) -> None:
        n, pieces = self.linear.size, self.linear.nodes.size - 1
        object.__setattr__(self, "dead_zones", tuple(self.dead_zones))
        for zone in self.dead_zones:
            if not isinstance(zone, (DeadZone, MeshZone)) or zone.vector.shape != (n,):
                raise ProblemError("dead_zones", type(zone).__name__,
                                   f"DeadZone or MeshZone with a vector of {n} entries",
                                   "one entry per DOF of the linear system")
        count = self.linear.pattern_count
        object.__setattr__(self, "pattern_meshes", tuple(self.pattern_meshes) or tuple(range(count)))
        owners = self.pattern_meshes
        if len(owners) != count or owners[0] != 0 or any(owners[owner] != owner for owner in owners):
            raise ProblemError("pattern_meshes", owners, f"{count} columns, each the column of its mesh's own "
                               "pattern (0 first)", "every pattern of the linear system belongs to one mesh")
        columns = sorted(zone.column for zone in self.dead_zones if isinstance(zone, MeshZone))
        if columns != sorted(set(owners) - {0}):  # the own mesh is column 0, the train's the others
            raise ProblemError("linear", f"{len(set(owners))} meshes", f"1 + {len(columns)} MeshZone(s)",
                               "each further mesh of the linear system is a MeshZone of its own pattern's column")
        if self.back_shift is not None:
            object.__setattr__(self, "back_shift", checked_array("back_shift", self.back_shift, (pieces, count)))
        for zone in self.dead_zones:
            if isinstance(zone, MeshZone) and zone.deviation.shape != (pieces,):
                raise ProblemError("mesh_zone.deviation", zone.deviation.shape, f"({pieces},)", "one per piece")
        object.__setattr__(self, "mesh_vector", checked_array("mesh_vector", self.mesh_vector, (n,), "one per DOF"))
        object.__setattr__(self, "deviation", checked_array("deviation", self.deviation, (pieces,)))
        if not np.isfinite(self.backlash) or self.backlash <= 0.0:
            raise ProblemError("backlash", self.backlash, "> 0 m", "a zero or negative backlash is a jammed mesh")

    def keeps_state(self, states: np.ndarray, piece, key: tuple) -> bool:
        """Whether every state of ``states`` (k, ≥ 2n) on a piece (or, an array of k, each on its own) is in the
        contact state ``key`` (mesh region, dead zone sides), by the rules of :meth:`region` and
        :meth:`DeadZone.side`, for all rows at once."""
        return self.keeps_projected_state(states[:, :2 * self.linear.size] @ self.state_functionals().T, piece, key)

    def state_functionals(self) -> np.ndarray:
        """(2 + 2·zones, 2n): the rows that give g + e_j = wᵀq, ġ = wᵀq̇ and each dead zone's u = vᵀq and u̇ of a
        state (for :meth:`keeps_projected_state`); formed once (read-only), since a flow asks for them on every
        piece."""
        return self._state_functionals

    @cached_property
    def _state_functionals(self) -> np.ndarray:
        n = self.linear.size
        rows = np.zeros((2 + 2 * len(self.dead_zones), 2 * n))
        rows[0, :n], rows[1, n:] = self.mesh_vector, self.mesh_vector
        for index, zone in enumerate(self.dead_zones):
            rows[2 + 2 * index, :n], rows[3 + 2 * index, n:] = zone.vector, zone.vector
        rows.setflags(write=False)
        return rows

    def keeps_projected_state(self, values: np.ndarray, piece, key: tuple) -> bool:
        """:meth:`keeps_state` from the states' :meth:`state_functionals` ``values`` (k, 2 + 2·zones)."""
        gap, rate = values[:, 0] - self.deviation[piece], values[:, 1]
        region, sides = key
        driving = (gap > 0.0) | ((gap == 0.0) & (rate > 0.0))
        back = (gap < -self.backlash) | ((gap == -self.backlash) & (rate < 0.0))
        inside = driving if region == _DRIVE else back if region == _BACK else ~(driving | back)
        if not inside.all():
            return False
        for index, (zone, side) in enumerate(zip(self.dead_zones, sides)):
            value, speed = values[:, 2 + 2 * index], values[:, 3 + 2 * index]
            upper, lower = zone.bounds(piece)
            above = (value > upper) | ((value == upper) & (speed > 0.0))
            below = (value < lower) | ((value == lower) & (speed < 0.0))
            if not (above if side > 0 else below if side < 0 else ~(above | below)).all():
                return False
        return True

    def sides(self, state: np.ndarray, piece: int = 0) -> tuple[int, ...]:
        """The side of every dead zone on a piece (:meth:`DeadZone.side`, :meth:`MeshZone.side`)."""
        return tuple(zone.side(state, self.linear.size, piece) for zone in self.dead_zones)

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
