"""Where a gear mesh's stiffness acts across the face: the contact options of the mesh element (a registry).

A mesh's contact lines lie across the face; slice j (axial position z_j from mid-face, stiffness k_j) strains by
δ_j = w(z_j)ᵀq, and the mesh vector is linear in the axial position of the contact (the arm p_i = r_wi e_c + z ẑ
enters through p_i × n, :mod:`thermogear.helical.mesh_vector`):

    w(z) = w₀ + z·w_z,   w_z = [0 ; ẑ × n | 0 ; −ẑ × n]  (rotations only: a relative tilt of the gears).

The stiffness of the whole face is Σ_j k_j w(z_j) w(z_j)ᵀ. With the total k = Σk_j, the load centre
z̄ = Σk_j z_j / k and the radius of gyration ρ² = Σk_j (z_j − z̄)² / k of the stiffness about it, the cross terms of
(z_j − z̄) vanish by the definition of z̄ and

    Σ_j k_j w(z_j) w(z_j)ᵀ = k·w(z̄) w(z̄)ᵀ + k ρ²·w_z w_zᵀ                                   (exact)

(first principles; the same expansion of the distributed contact as in Velex & Maatar, J. Sound Vib. 191 (1996)
629, where the mesh stiffness matrix collects the contact lines' elementary stiffnesses at their points
on the face, and Kahraman, J. Mech. Des. 116 (1994), whose helical mesh couples the tilts through the axial
position of the force). The load centre's offset z̄ therefore moves the point the force acts at (it adds z̄·ẑ × n to
the tilting entries of w, so the axial force F n_z and the transverse force make a moment about the transverse
axes), and the spread ρ adds a tilting stiffness k ρ² about the load centre that no single point gives.

The options (:data:`MESH_CONTACTS`):
- ``point``: a constant normal stiffness at one point, the operating pitch point at mid-face (z̄ = 0, ρ = 0): the
  element other rotordynamics tools use, so modes can be compared with theirs; it is the spur element of today.
- ``spread``: the stiffness spread across the face. The modes and static state take the period-mean of the slice
  model exactly (per slice, its stiffness averaged over one mesh period: every slice of a pair without lead
  deviations sees the same stiffness history shifted in phase, so the mean is uniform across the face, z̄ = 0 and
  ρ² = b²/12 in the limit of many slices; :func:`face_contact_moments` computes them from the slice model). The
  periodic response keeps the slice model's k(τ) on w(z̄) and the tilting term at its period mean k̄ρ̄²: the
  fluctuation of the load centre and of the spread over the mesh period (a tilting excitation) is left out.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import TYPE_CHECKING, Callable

import numpy as np

from thermogear.errors import CaseError

if TYPE_CHECKING:
    from thermogear.helical.geometry import HelicalPair
    from thermogear.materials import Material

__all__ = ["MESH_CONTACTS", "MeshContact", "face_contact_moments", "mesh_contact"]


@dataclass(frozen=True)
class MeshContact:
    """A contact option: ``moments(mesh)`` gives (load centre z̄ [m] from mid-face along +z, radius of gyration
    ρ [m] of the stiffness about it) for a :class:`~thermogear.drivetrain.mesh_element.GearMesh`."""

    name: str
    moments: Callable
    description: str


def _point(mesh) -> tuple[float, float]:
    return 0.0, 0.0


def _spread(mesh) -> tuple[float, float]:
    gyration = mesh.face_width / math.sqrt(12.0) if mesh.load_gyration is None else mesh.load_gyration
    return float(mesh.load_centre), float(gyration)


MESH_CONTACTS: dict[str, MeshContact] = {
    "point": MeshContact("point", _point, "a constant normal stiffness at the operating pitch point at mid-face"),
    "spread": MeshContact("spread", _spread, "the stiffness spread across the face (load centre and tilting "
                                             "stiffness k̄ρ² of the slice model's mean distribution)"),
}


def mesh_contact(name: str, key: str = "drivetrain.helical_contact") -> MeshContact:
    """The contact option named ``name`` (a clear error naming ``key`` otherwise)."""
    if name not in MESH_CONTACTS:
        raise CaseError(key, name, f"one of {', '.join(MESH_CONTACTS)}", "where the mesh stiffness acts on the face")
    return MESH_CONTACTS[name]


def face_contact_moments(helical: HelicalPair, material: Material, slices: int = 100,
                         points: int = 64) -> tuple[float, float]:
    """(z̄ [m] from mid-face, ρ [m]) of the slice model's stiffness averaged over one mesh period (``points``
    phases, midpoints of equal steps; ``slices`` across the face; :func:`thermogear.helical.slices.contact_stiffness`),
    by the moments of :class:`~thermogear.helical.face_load.FaceStiffnessMoments` (every line in contact)."""
    from thermogear.helical.face_load import FaceStiffnessMoments
    from thermogear.helical.slices import contact_stiffness

    phases = (np.arange(points) + 0.5) / points * helical.transverse_base_pitch
    centres, stiffness = contact_stiffness(helical, material, phases, slices)
    per_slice = stiffness.sum(axis=-2)  # (phases, slices): each slice's stiffness over its lines
    position = centres - helical.face_width / 2.0
    moments = FaceStiffnessMoments(phases, per_slice.sum(axis=-1), per_slice @ position, per_slice @ position**2)
    return moments.mean_load_centre, moments.mean_gyration
