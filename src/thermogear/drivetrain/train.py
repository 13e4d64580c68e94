"""Several meshes on one structure: the train's common period and the mesh excitations combined over it.

Mesh m of a train has the mesh frequency f_m = z·n/60 of either of its gears. Relative to the first mesh,
ν_m = f_m/f_1 is a ratio of integers (tooth counts: ν_m = p_m/q_m in lowest terms), so every mesh excitation repeats
after the common period T = lcm_m(q_m)·T_1, which holds L_m = lcm(q)·ν_m periods of mesh m (for two stages
z1/z2 → z3/z4, z2 and z3 on the intermediate shaft: ν_2 = z3/z2 and T = (z2/g)·T_1 = (z3/g)·T_2 = 1/g of a turn of
the intermediate shaft, g = gcd(z2, z3); Kahraman, "Dynamic analysis of a multi-mesh helical gear train", J. Mech.
Des. 116 (1994) 706, treats the meshes of a train with their relative phases in the same way).

Mesh phasing: mesh m has passed the fraction γ_m ∈ [0, 1) of its mesh cycle at t = 0, when the first mesh is at
the start of its own (γ_1 = 0); its coefficients at time t are those of its cycle at τ_m = frac(t/T_m + γ_m). The
phase depends on how the gears were clocked on the intermediate shaft at assembly; a case gives it (default 0, an
assumption to state). The pieces of the common period are the union of every mesh's breakpoints; on each, every mesh
keeps the constant coefficients of its own piece, so the train's pieces are exact (no resampling).
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass
from fractions import Fraction

import numpy as np

from thermogear.errors import CaseError

__all__ = ["MeshTrain", "TrainGrid", "common_period_repeats", "train_grid"]

#: Breakpoints of different meshes closer than this fraction of the common period are one (far below a sample).
_MERGE_TOLERANCE = 1e-12


def common_period_repeats(relative_frequencies: Sequence[Fraction]) -> tuple[int, ...]:
    """L_m, the number of periods of each mesh in the train's common period, from the exact ratios
    ν_m = f_m/f_1 (Fractions of tooth counts; the first is 1): L_m = lcm_m(q_m)·ν_m (module docstring)."""
    ratios = [Fraction(value) for value in relative_frequencies]
    if not ratios or ratios[0] != 1 or any(ratio <= 0 for ratio in ratios):
        raise CaseError("mesh frequency ratios", [str(r) for r in ratios], "positive, the first equal to 1",
                        "each mesh's frequency relative to the first mesh's")
    common = math.lcm(*(ratio.denominator for ratio in ratios))
    return tuple(int(ratio * common) for ratio in ratios)


@dataclass(frozen=True, eq=False)
class TrainGrid:
    """The pieces of the common period: ``nodes`` (N+1,) [s] from 0 to T; ``pieces`` (N, M) the index of each
    mesh's own piece (interval of its mesh grid) on each; ``repeats`` L_m and ``phases`` γ_m per mesh."""

    nodes: np.ndarray
    pieces: np.ndarray
    repeats: tuple[int, ...]
    phases: tuple[float, ...]

    @property
    def period(self) -> float:
        """T [s]."""
        return float(self.nodes[-1])


def train_grid(mesh_nodes: Sequence[np.ndarray], repeats: Sequence[int], phases: Sequence[float]) -> TrainGrid:
    """The union of the meshes' breakpoints over the common period (module docstring).

    ``mesh_nodes``: each mesh's grid nodes (n_m+1,) [s] from 0 to its period T_m; ``repeats`` L_m; ``phases`` γ_m.
    The common period is T = L_1·T_1; each mesh's grid is scaled by T/(L_m·T_m), which differs from 1 by rounding only
    (checked to 1e-9: otherwise the repeats do not belong to these periods)."""
    if not (len(mesh_nodes) == len(repeats) == len(phases)) or not mesh_nodes:
        raise CaseError("meshes", len(mesh_nodes), "one grid, repeat count and phase per mesh", "a train's meshes")
    period = repeats[0] * float(mesh_nodes[0][-1])
    unit_nodes, breaks = [], [np.array([0.0, 1.0])]
    for nodes, repeat, phase in zip(mesh_nodes, repeats, phases):
        nodes = np.asarray(nodes, dtype=float)
        if not 0.0 <= phase < 1.0:
            raise CaseError("mesh_phase", phase, "[0, 1)", "the fraction of its mesh cycle a mesh has passed at t = 0")
        mismatch = abs(repeat * nodes[-1] / period - 1.0)
        if mismatch > 1e-9:
            raise CaseError("mesh periods", f"{repeat} × {nodes[-1]:.9g} s", f"{period:.9g} s (the common period)",
                            "the repeat counts must come from the same speeds as the mesh periods")
        fractions = nodes / nodes[-1]  # τ of the mesh's nodes in [0, 1]
        unit_nodes.append(fractions)
        # t/T of the mesh's breakpoints: (i + τ_k − γ)/L for every repetition i, wrapped into [0, 1)
        shifted = (np.arange(repeat)[:, None] + fractions[None, :-1] - phase) / repeat
        breaks.append(np.mod(shifted.ravel(), 1.0))
    merged = np.sort(np.concatenate(breaks))
    keep = np.concatenate([[True], np.diff(merged) > _MERGE_TOLERANCE])
    merged = merged[keep]
    if merged[-1] > 1.0 - _MERGE_TOLERANCE:
        merged = merged[:-1]
    merged = np.append(merged, 1.0)
    middles = 0.5 * (merged[:-1] + merged[1:])
    pieces = np.empty((middles.size, len(mesh_nodes)), dtype=int)
    for column, (fractions, repeat, phase) in enumerate(zip(unit_nodes, repeats, phases)):
        cycle = np.mod(middles * repeat + phase, 1.0)
        pieces[:, column] = np.clip(np.searchsorted(fractions, cycle, side="right") - 1, 0, fractions.size - 2)
    return TrainGrid(merged * period, pieces, tuple(int(r) for r in repeats), tuple(float(p) for p in phases))


@dataclass(frozen=True, eq=False)
class MeshTrain:
    """The mesh states of a drivetrain's meshes, in the drivetrain's mesh order (each a
    :class:`~thermogear.mesh.state.MeshState` at its own pinion speed and load), with ``repeats`` L_m (mesh periods
    in the common period, :func:`common_period_repeats`) and ``phases`` γ_m (module docstring). One state alone is
    the single mesh over its own period."""

    states: tuple
    repeats: tuple[int, ...] = (1,)
    phases: tuple[float, ...] = (0.0,)

    def __post_init__(self) -> None:
        object.__setattr__(self, "states", tuple(self.states))
        object.__setattr__(self, "repeats", tuple(int(r) for r in self.repeats))
        object.__setattr__(self, "phases", tuple(float(p) for p in self.phases))
        if not self.states or not len(self.states) == len(self.repeats) == len(self.phases):
            raise CaseError("meshes", len(self.states), f"{len(self.repeats)} (one repeat count and phase per mesh)",
                            "each mesh of a train has its own period and phase")
        if self.phases[0] != 0.0:
            raise CaseError("mesh_phase", self.phases[0], "0 for the first mesh", "phases are relative to the first mesh")

    @property
    def period(self) -> float:
        """The common period T = L_1·T_1 [s]."""
        return self.repeats[0] * float(self.states[0].period)
