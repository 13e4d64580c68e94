"""The steady load share of one tooth pair at the points of the path of contact, from the mesh model.

Pairs in mesh together act as springs in parallel (Luo & Li (2020) Sect. 2.3; ISO 6336-1 load sharing of an
unmodified mesh): a pair's share of the static load is its stiffness over the sum of the stiffnesses of the pairs
in mesh with it (:func:`thermogear.geometry.mesh_cycle.load_share_at`), with each model's own pair stiffness
(:meth:`thermogear.mesh.model.MeshModel.pair_stiffness_at`).
"""

from __future__ import annotations

import numpy as np

from thermogear.mesh.model import MeshModel
from thermogear.geometry.mesh_cycle import load_share_at

__all__ = ["pair_load_share_at_points"]


def pair_load_share_at_points(mesh: MeshModel, points: str = "ABDE") -> dict[str, float]:
    """Steady load share [–] of one tooth pair at the named points of the path (A meshing-in, B and D the ends of
    single contact, C the pitch point, E meshing-out) under the mesh model ``mesh`` (elastic or thermal), at the
    load of its operating point."""
    path = mesh.gear_pair.path_points
    roll = np.array([path[name] for name in points])
    share, _ = load_share_at(roll, mesh.pair_stiffness_at, path["A"], path["E"], mesh.gear_pair.base_pitch)
    return dict(zip(points, (float(value) for value in share)))
