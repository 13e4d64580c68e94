"""Triangular mesh of a tooth sector (Shewchuk's Triangle through the ``triangle`` package) as a scikit-fem mesh.

The outline's point spacing sets the local element size: fine on the flanks and fillets, coarse on the rim
sides and bore; Triangle's quality switch (minimum angle) grades the elements smoothly in between and a maximum
area caps the interior size. Boundary facets keep the outline's tags (:data:`tooth_profile.BOUNDARY_TAGS`) as
scikit-fem named boundaries.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property

import numpy as np
import skfem
import triangle

from thermogear.fem.tooth_profile import BOUNDARY_TAGS, ToothOutline, full_gear_outline, tooth_sector_outline
from thermogear.geometry import Gear

#: Minimum triangle angle [deg] asked of Triangle (its guarantee holds up to about 33°).
MINIMUM_ANGLE_DEG = 28.0


def triangulate_outline(points: np.ndarray, markers: np.ndarray, maximum_area: float,
                        segments: np.ndarray | None = None, holes: np.ndarray | None = None):
    """Quality triangulation of a closed polygon (or of several loops given by ``segments``, with ``holes``
    points): (vertices (n, 2), triangles (m, 3), boundary edges (k, 2), edge markers (k,)). ``maximum_area``
    [m²] caps the triangle size."""
    count = len(points)
    if segments is None:
        segments = np.column_stack([np.arange(count), (np.arange(count) + 1) % count])
    geometry = {"vertices": points, "segments": segments, "segment_markers": markers}
    if holes is not None:
        geometry["holes"] = holes
    result = triangle.triangulate(geometry, f"pq{MINIMUM_ANGLE_DEG:g}a{maximum_area:.6e}")
    return (result["vertices"], result["triangles"], result["segments"],
            result["segment_markers"].ravel().astype(int))


@dataclass(frozen=True)
class ToothMesh:
    """A scikit-fem ``MeshTri`` of a tooth sector with its named boundaries and the outline it came from."""

    outline: ToothOutline
    mesh: skfem.MeshTri

    @property
    def gear(self) -> Gear:
        return self.outline.gear

    @cached_property
    def boundary_facets(self) -> dict[str, np.ndarray]:
        """Facet indices per boundary tag."""
        return {name: self.mesh.boundaries[name] for name in BOUNDARY_TAGS if name in self.mesh.boundaries}

    @property
    def element_count(self) -> int:
        return self.mesh.t.shape[1]

    def facets(self, *names: str) -> np.ndarray:
        """Union of the facets of the named boundaries."""
        parts = [self.boundary_facets[name] for name in names if name in self.boundary_facets]
        return np.unique(np.concatenate(parts)) if parts else np.zeros(0, dtype=int)


def mesh_from_outline(outline: ToothOutline, maximum_area: float | None = None) -> ToothMesh:
    """Mesh an outline; the default maximum area is (m/3)² (interior elements about a third of a module)."""
    module = outline.gear.module
    maximum_area = maximum_area or (module / 3.0) ** 2
    holes = np.zeros((1, 2)) if outline.full_gear else None
    vertices, triangles, edges, edge_markers = triangulate_outline(outline.points, outline.markers, maximum_area,
                                                                   outline.segments, holes)
    mesh = skfem.MeshTri(np.ascontiguousarray(vertices.T), np.ascontiguousarray(triangles.T))
    lookup = {}
    for (a, b), marker in zip(edges, edge_markers):
        lookup[(min(a, b), max(a, b))] = int(marker)
    boundary = mesh.boundary_facets()
    facet_vertices = np.sort(mesh.facets[:, boundary], axis=0)
    facet_markers = np.array([lookup.get((int(a), int(b)), 0) for a, b in facet_vertices.T])
    names = {value: key for key, value in BOUNDARY_TAGS.items()}
    boundaries = {names[value]: boundary[facet_markers == value] for value in np.unique(facet_markers)
                  if value in names}
    mesh = mesh.with_boundaries(boundaries)
    return ToothMesh(outline, mesh)


def tooth_mesh(gear: Gear, bore_radius: float | None = None, teeth: int = 1, refinement: float = 1.0) -> ToothMesh:
    """Mesh of a sector of ``teeth`` teeth of ``gear`` down to the bore.

    ``teeth`` = 0 (or z) meshes the whole gear (bore as a hole), fine on the loaded tooth and its neighbours.
    ``refinement`` divides every length scale (boundary spacings m/20 on flank and fillet, m/10 on the tip, m/2.5
    on the rim, interior size m/3): 2 halves the element size (about 4× the elements).
    """
    bore_radius = nominal_bore_radius(gear) if bore_radius is None else bore_radius
    module = gear.module
    if teeth in (0, gear.teeth):  # the whole gear, fine around the loaded tooth
        outline = full_gear_outline(gear, bore_radius, 3, flank_spacing=module / (20.0 * refinement),
                                    fillet_spacing=module / (20.0 * refinement), tip_spacing=module / (10.0 * refinement),
                                    rim_spacing=module / (2.5 * refinement))
        return mesh_from_outline(outline, maximum_area=(module / (3.0 * refinement)) ** 2)
    outline = tooth_sector_outline(gear, bore_radius, teeth, flank_spacing=module / (20.0 * refinement),
                                   fillet_spacing=module / (20.0 * refinement),
                                   tip_spacing=module / (10.0 * refinement),
                                   rim_spacing=module / (2.5 * refinement))
    return mesh_from_outline(outline, maximum_area=(module / (3.0 * refinement)) ** 2)


def nominal_bore_radius(gear: Gear) -> float:
    """Bore radius for the FE sector: the gear's bore, or for a solid gear (bore 0) a nominal 0.3·r_f [m]."""
    return gear.bore_radius if gear.bore_radius > 0.0 else 0.3 * gear.root_radius


__all__ = ["MINIMUM_ANGLE_DEG", "ToothMesh", "mesh_from_outline", "nominal_bore_radius", "tooth_mesh",
           "triangulate_outline"]
