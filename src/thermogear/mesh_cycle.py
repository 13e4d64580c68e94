"""One mesh cycle: where each tooth pair is, which pairs are in contact, and the parallel sum over pairs.

Time origin τ = 0 when a pair enters contact at A (Luo & Li Eq. 25). Pair slot j (j = 0 … slots − 1) is the
pair that entered j mesh periods earlier; its roll distance from T1 is T1A + r_b1 ω1 (τ mod T_m) + j p_b and it
is in contact while that is ≤ T1E (physics.md §2). Valid for any contact ratio ε_α > 1 (also ≥ 2): there are
ceil(ε_α) slots. Pairs in contact act in parallel and share the load in proportion to their stiffness.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from thermogear.geometry import GearPair
from thermogear.materials import Material

#: Uniform grid nodes closer than this fraction of the step to an inserted transition are dropped.
_MERGE_FRACTION = 0.25


@dataclass(frozen=True, eq=False)
class MeshGrid:
    """Time grid over one mesh period whose nodes include every contact-count transition."""

    nodes: np.ndarray  # (n+1,) times [s], nodes[0] = 0, nodes[-1] = period
    midpoints: np.ndarray  # (n,) [s]
    roll: np.ndarray  # (slots, n) roll distance of each pair slot at the midpoints [m]
    in_contact: np.ndarray  # (slots, n) bool
    contact_count: np.ndarray  # (n,) int

    @property
    def steps(self) -> np.ndarray:
        """Interval lengths [s] (n,)."""
        return np.diff(self.nodes)

    def time_average(self, values) -> np.ndarray:
        """Time average over the period of values given at the midpoints (last axis)."""
        values = np.asarray(values, dtype=float)
        return values @ self.steps / (self.nodes[-1] - self.nodes[0])


@dataclass(frozen=True)
class MeshCycle:
    """The mesh cycle of a gear pair at a pinion speed [rpm]."""

    gear_pair: GearPair
    speed_rpm: float

    def __post_init__(self) -> None:
        if not self.speed_rpm > 0.0:
            raise ValueError("MeshCycle: speed_rpm must be positive")
        if not self.gear_pair.contact_ratio > 1.0:
            raise ValueError("MeshCycle: the contact ratio must exceed 1")

    @property
    def period(self) -> float:
        """Mesh period T_m = 60/(z1 n1) [s]."""
        return self.gear_pair.mesh_period(self.speed_rpm)

    @property
    def slots(self) -> int:
        """Number of pair slots, ceil(ε_α)."""
        return int(math.ceil(self.gear_pair.contact_ratio - 1e-12))

    @property
    def contact_speed(self) -> float:
        """Speed of the contact point along the line of action r_b1 ω1 [m/s]."""
        return self.gear_pair.pinion.base_radius * self.speed_rpm * math.pi / 30.0

    @property
    def transition_times(self) -> np.ndarray:
        """Sorted times in [0, T_m) where the number of pairs in contact changes [s]:
        0 (a pair enters at A) and (ε_α − floor ε_α)·T_m (a pair leaves at E)."""
        fraction = self.gear_pair.contact_ratio - math.floor(self.gear_pair.contact_ratio)
        times = [0.0]
        if fraction * self.period > 1e-12 * self.period:
            times.append(fraction * self.period)
        return np.array(sorted(times))

    def positions(self, times) -> tuple[np.ndarray, np.ndarray]:
        """Roll distances (slots, m) [m] and contact flags (slots, m) of every pair slot at ``times`` [s]
        (taken modulo the period)."""
        times = np.atleast_1d(np.asarray(times, dtype=float))
        phase = np.mod(times, self.period)
        phase[phase > self.period * (1.0 - 1e-12)] = 0.0  # whole periods land on 0, not on T − ε
        points = self.gear_pair.path_points
        base_pitch = self.gear_pair.base_pitch
        roll = (points["A"] + self.contact_speed * phase)[None, :] + base_pitch * np.arange(self.slots)[:, None]
        in_contact = roll <= points["E"] + 1e-12
        return roll, in_contact

    def grid(self, count: int) -> MeshGrid:
        """About ``count`` intervals over one period: uniform nodes with every transition inserted as a node
        (uniform nodes within a quarter step of a transition are dropped)."""
        if count < 2:
            raise ValueError("MeshCycle.grid: count must be at least 2")
        period = self.period
        uniform = np.linspace(0.0, period, count + 1)
        transitions = self.transition_times
        inner = transitions[transitions > 0.0]
        if inner.size:
            distance = np.min(np.abs(uniform[:, None] - inner[None, :]), axis=1)
            keep = distance > _MERGE_FRACTION * period / count
            keep[0] = keep[-1] = True
            nodes = np.union1d(uniform[keep], inner)
        else:
            nodes = uniform
        midpoints = 0.5 * (nodes[1:] + nodes[:-1])
        roll, in_contact = self.positions(midpoints)
        return MeshGrid(nodes, midpoints, roll, in_contact, in_contact.sum(axis=0))

    @staticmethod
    def total(per_pair, in_contact) -> np.ndarray:
        """Sum over the pairs in contact (parallel pairs): (slots, n) → (n,)."""
        return np.where(in_contact, per_pair, 0.0).sum(axis=0)

    @staticmethod
    def load_share(per_pair_stiffness, in_contact) -> np.ndarray:
        """Load share of each pair k_i / Σ k_j (0 where not in contact): (slots, n) [–] (physics.md §2)."""
        stiffness = np.where(in_contact, per_pair_stiffness, 0.0)
        return stiffness / stiffness.sum(axis=0, keepdims=True)


def mesh_stiffness(gear_pair: GearPair, material: Material, speed_rpm: float,
                   count: int = 1024) -> tuple[MeshGrid, np.ndarray, np.ndarray]:
    """Elastic mesh stiffness over one mesh period, total over the face width [N/m].

    Returns (grid, per-pair stiffness (slots, n) — 0 where a pair is out of contact —, mesh stiffness (n,)),
    all at the grid midpoints. Pair stiffness from the cached PEM table (physics.md §3.4).
    """
    from thermogear.stiffness.table import pair_stiffness_at

    cycle = MeshCycle(gear_pair, speed_rpm)
    grid = cycle.grid(count)
    end = gear_pair.path_points["E"]
    per_pair = np.zeros_like(grid.roll)
    per_pair[grid.in_contact] = pair_stiffness_at(gear_pair, material,
                                                  np.minimum(grid.roll[grid.in_contact], end))
    return grid, per_pair, MeshCycle.total(per_pair, grid.in_contact)
