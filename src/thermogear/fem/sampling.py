"""Point evaluation of finite-element fields that tolerates points on (or a rounding error outside) the polygonal
boundary: each point goes to the nearby element where it is "most inside" (largest smallest barycentric
coordinate), and the element's basis is evaluated there (a short extrapolation for points just outside)."""

from __future__ import annotations

import numpy as np
import skfem
from scipy.sparse import coo_matrix
from scipy.spatial import cKDTree


def containing_cells(mesh: skfem.MeshTri, points: np.ndarray, candidates: int = 12) -> np.ndarray:
    """Index of the triangle holding each point (2, n) [m], or the nearest one for points just outside."""
    centroids = np.mean(mesh.p[:, mesh.t], axis=1).T
    count = min(candidates, mesh.t.shape[1])
    _, nearest = cKDTree(centroids).query(points.T, count)
    nearest = np.atleast_2d(nearest).reshape(points.shape[1], count)
    vertices = mesh.p[:, mesh.t[:, nearest]]  # (2, 3, n, count)
    a, b, c = vertices[:, 0], vertices[:, 1], vertices[:, 2]
    v0, v1, v2 = b - a, c - a, points[:, :, None] - a
    d00 = np.sum(v0 * v0, axis=0)
    d01 = np.sum(v0 * v1, axis=0)
    d11 = np.sum(v1 * v1, axis=0)
    d20 = np.sum(v2 * v0, axis=0)
    d21 = np.sum(v2 * v1, axis=0)
    denominator = d00 * d11 - d01 * d01
    second = (d11 * d20 - d01 * d21) / denominator
    third = (d00 * d21 - d01 * d20) / denominator
    smallest = np.minimum(np.minimum(second, third), 1.0 - second - third)
    return nearest[np.arange(points.shape[1]), np.argmax(smallest, axis=1)]


def probe_matrix(basis: skfem.CellBasis, points: np.ndarray):
    """Sparse matrix P with P @ dofs = field values at ``points`` (2, n); for a vector basis the rows are the
    x components of all points, then the y components (as ``skfem.CellBasis.probes``)."""
    points = np.asarray(points, dtype=float)
    cells = containing_cells(basis.mesh, points)
    local = basis.mapping.invF(points[:, :, np.newaxis], tind=cells)
    phis = np.array([basis.elem.gbasis(basis.mapping, local, k, tind=cells)[0]
                     for k in range(basis.Nbfun)]).flatten()
    components = int(np.prod(basis._base_tensor_order))
    rows = np.tile(np.arange(components * points.shape[1], dtype=np.int32), basis.Nbfun)
    columns = basis.element_dofs[:, np.tile(cells, components)].flatten()
    return coo_matrix((phis, (rows, columns)), shape=(components * points.shape[1], basis.N)).tocsr()


__all__ = ["containing_cells", "probe_matrix"]
