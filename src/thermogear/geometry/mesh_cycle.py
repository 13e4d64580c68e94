"""One mesh cycle: where each tooth pair is, which pairs are in contact, and the parallel sum over pairs.

Time origin τ = 0 when a pair enters contact at A (Luo & Li Eq. 25). Pair slot j (j = 0 … slots − 1) is the
pair that entered j mesh periods earlier; its roll distance from T1 is T1A + r_b1 ω1 (τ mod T_m) + j p_b and it
is in contact while that is ≤ T1E (involute geometry: docs/stiffness.md, path of contact). Valid for any contact ratio ε_α > 1 (also ≥ 2): there are
ceil(ε_α) slots. Pairs in contact act in parallel and share the load in proportion to their stiffness.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from thermogear.geometry import GearPair

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


def load_shares(pair_stiffness, in_contact) -> np.ndarray:
    """Share of the static load carried by each tooth pair, k_i / Σ_j k_j over the pairs in contact (axis 0) [–];
    0 where a pair is out of contact or no pair is.

    Pairs in contact act as springs in parallel between the same two base circles: with no deviation between
    them each takes the load in proportion to its stiffness (ISO 6336-1 load sharing of an unmodified mesh;
    Luo & Li (2020) Sect. 2.3). The one load-share function of thermogear: the damping, the paper's thermal model
    (pair-share load basis), the dynamics and the report all use it.
    """
    stiffness = np.where(in_contact, np.asarray(pair_stiffness, dtype=float), 0.0)
    total = stiffness.sum(axis=0, keepdims=True)
    return np.divide(stiffness, total, out=np.zeros_like(stiffness), where=total > 0)


def simultaneous_pairs(roll, path_start: float, path_end: float, base_pitch: float,
                       tolerance: float = 1e-12) -> tuple[np.ndarray, np.ndarray]:
    """Roll distances [m] of the tooth pairs in mesh at the same instant as a pair at ``roll`` and whether each is
    on the path [A, E]: arrays (2·reach + 1, *roll.shape), row 0 the pair itself, the others whole base pitches
    ahead and behind (successive pairs are one base pitch apart along the line of action)."""
    roll = np.asarray(roll, dtype=float)
    reach = int(np.ceil((path_end - path_start) / base_pitch)) + 1
    offsets = [0] + [j for step in range(1, reach + 1) for j in (-step, step)]
    positions = roll[None, ...] + np.array(offsets, dtype=float).reshape((-1,) + (1,) * roll.ndim) * base_pitch
    inside = (positions >= path_start - tolerance) & (positions <= path_end + tolerance)
    return positions, inside


def load_share_at(roll, stiffness_at, path_start: float, path_end: float, base_pitch: float) -> tuple[np.ndarray, np.ndarray]:
    """(load share [–], own stiffness [N/m]) of the pair at roll distances ``roll`` [m] on [A, E] among the pairs
    in mesh with it, by :func:`load_shares`; ``stiffness_at(roll) -> k`` [N/m] is the pair stiffness along the path."""
    positions, inside = simultaneous_pairs(roll, path_start, path_end, base_pitch)
    stiffness = np.zeros(positions.shape)
    stiffness[inside] = np.asarray(stiffness_at(np.clip(positions[inside], path_start, path_end)), dtype=float)
    return load_shares(stiffness, inside)[0], stiffness[0]

