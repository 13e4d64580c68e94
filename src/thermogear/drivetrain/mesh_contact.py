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
  periodic response takes k(τ) on w(z̄), the tilting term at its period mean k̄ρ̄², and, where the mesh carries a
  :class:`FaceVariation` (the case's helical pairs do), the moments' variation over the period (below).

**The variation over the period.** With the slices in contact at mesh position τ (k_j, z_j along +z from mid-face,
unloaded gaps e_j), expanded about the mesh's mean load centre z̄ (w = w(z̄), ζ_j = z_j − z̄):

    Σ_j k_j w(z_j)w(z_j)ᵀ = k w wᵀ + k₁′ (w w_zᵀ + w_z wᵀ) + k₂′ w_z w_zᵀ,    k₁′ = Σk_jζ_j,  k₂′ = Σk_jζ_j²,
    Σ_j k_j e_j w(z_j)   = (Σk_je_j) w + (Σk_je_jζ_j) w_z,

so a spread mesh is three stiffness patterns of the periodic solvers (w wᵀ, w w_zᵀ + w_z wᵀ, w_z w_zᵀ; their range
is {w, w_z}: the rank update of a mesh grows from 1 to 2) and two force patterns (w, w_z: the gaps' moment about
the load centre tilts the gears, the static force of lead deviations and thermal distortion). :class:`FaceVariation`
holds, per interval of the period, the slice model's fluctuation of k₁/k and k₂/k about their stiffness-weighted
period means (f₁, f₂) and the gaps' moment per stiffness; the mean itself stays the mesh's (z̄, ρ), so the mean
matrix and the modes are those above whatever the variation, and the factors are

    k₁′ = k(τ) f₁,   k₂′ − k̄ρ² = k(τ)(ρ² + f₂ − 2z̄f₁) − k̄ρ²  (k̄ρ² w_zw_zᵀ is in the constant matrices),
    Σk_je_jζ_j = k(τ)·m_e − z̄·Σk_je_j,

the damping alike with c(τ) (a slice's damping is proportional to its stiffness, :mod:`thermogear.mesh.helical_model`).
The slice model's face coordinate z_s (0 … b from the end face a contact line leaves last, where the oil leaves the
mesh) maps onto the shaft axis by the hand and the turning sense: ζ = sH (z_s − b/2) (:func:`face_variation`).
Derivation: a contact line runs along l̂ = σH sin β_b u + cos β_b ẑ in the plane of action (σ = s on the drive
flanks, :mod:`thermogear.helical.mesh_vector`), so its path position grows by sH tan β_b per unit of +z, and it
grows by tan β_b per unit of z_s in the slice model (:mod:`thermogear.helical.slices`). A mirror image of the pair
in a plane through its axis (the other hand, the other turning sense) keeps sH and so every axial position.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace
from typing import TYPE_CHECKING, Callable

import numpy as np

from thermogear.errors import CaseError
from thermogear.helical.face_load import FaceStiffnessMoments

if TYPE_CHECKING:
    from thermogear.helical.geometry import HelicalPair
    from thermogear.materials import Material

__all__ = ["MESH_CONTACTS", "FaceVariation", "MeshContact", "face_contact_moments", "face_variation", "mesh_contact",
           "case_face_variations", "pair_face_variation", "with_face_variations"]


@dataclass(frozen=True)
class MeshContact:
    """A contact option: ``moments(mesh)`` gives (load centre z̄ [m] from mid-face along +z, radius of gyration
    ρ [m] of the stiffness about it) for a :class:`~thermogear.drivetrain.mesh_element.GearMesh`."""

    name: str
    moments: Callable
    description: str
    varies: bool = False  # whether a mesh's FaceVariation (the moments over the period) enters with this contact


def _point(mesh) -> tuple[float, float]:
    return 0.0, 0.0


def _spread(mesh) -> tuple[float, float]:
    gyration = mesh.face_width / math.sqrt(12.0) if mesh.load_gyration is None else mesh.load_gyration
    return float(mesh.load_centre), float(gyration)


MESH_CONTACTS: dict[str, MeshContact] = {
    "point": MeshContact("point", _point, "a constant normal stiffness at the operating pitch point at mid-face"),
    "spread": MeshContact("spread", _spread, "the stiffness spread across the face (load centre and tilting "
                                             "stiffness k̄ρ² of the slice model's mean distribution, and their "
                                             "variation over the period where the mesh carries one)", True),
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
    in the slice model's face coordinate: the means of :func:`pair_face_variation` (every line in contact)."""
    variation = pair_face_variation(helical, material, points, 1, slices)
    return variation.mean_load_centre, variation.mean_gyration


@dataclass(frozen=True, eq=False)
class FaceVariation:
    """The moments of a spread contact's stiffness across the face over one mesh period (module docstring), per
    interval of the mesh state's period (equal intervals, ``first.size`` of them), along +z of the shaft axis:
    ``first`` f₁ = k₁/k − ⟨k₁⟩/⟨k⟩ [m], ``second`` f₂ = k₂/k − ⟨k₂⟩/⟨k⟩ [m²] (moments about mid-face; their
    stiffness-weighted period means are zero), ``gap_moment`` m_e = Σk_je_jz_j / k [m²] about mid-face (zero
    without deviations); ``mean_load_centre`` ⟨k₁⟩/⟨k⟩ [m] and ``mean_gyration`` [m] of the slice model, for
    reference (the mesh's own z̄ and ρ give the mean matrix)."""

    first: np.ndarray
    second: np.ndarray
    gap_moment: np.ndarray
    mean_load_centre: float = 0.0
    mean_gyration: float = 0.0

    def __post_init__(self) -> None:
        arrays = [np.asarray(getattr(self, key), dtype=float).ravel() for key in ("first", "second", "gap_moment")]
        if arrays[0].size < 1 or any(array.shape != arrays[0].shape for array in arrays):
            raise CaseError("face_variation", [array.size for array in arrays], "three arrays of one length >= 1",
                            "one value per interval of the mesh period")
        if not all(np.all(np.isfinite(array)) for array in arrays):
            raise CaseError("face_variation", "not finite", "finite moments", "the slice model's moments per interval")
        for key, array in zip(("first", "second", "gap_moment"), arrays):
            array.setflags(write=False)
            object.__setattr__(self, key, array)

    def on(self, nodes: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """(f₁, f₂, m_e) on the intervals of ``nodes`` (N+1,) from 0 to the period: the value of the equal
        interval of this variation that holds each interval's midpoint (the same arrays where the grids agree)."""
        nodes = np.asarray(nodes, dtype=float)
        count = self.first.size
        if nodes.size == count + 1 and np.allclose(nodes / nodes[-1], np.arange(count + 1) / count, atol=1e-12):
            return self.first, self.second, self.gap_moment
        middle = 0.5 * (nodes[1:] + nodes[:-1]) / nodes[-1]
        index = np.minimum((middle * count).astype(int), count - 1)
        return self.first[index], self.second[index], self.gap_moment[index]


def face_variation(stiffness: np.ndarray, first_moment: np.ndarray, second_moment: np.ndarray,
                   gap_moment: np.ndarray, sense: int) -> FaceVariation:
    """The :class:`FaceVariation` of the slice model's moments per interval, about mid-face in the slice model's
    face coordinate (k₀ = Σk_j [N/m], k₁ = Σk_jz_j [N], k₂ = Σk_jz_j² [N·m], Σk_je_jz_j [N·m]), mapped
    onto the shaft axis by ``sense`` = sH (rotation sense × hand of gear 1; module docstring): odd moments × sH."""
    stiffness = np.asarray(stiffness, dtype=float)
    if sense not in (1, -1):
        raise CaseError("face_variation.sense", sense, "+1 or −1", "the rotation sense times the hand of gear 1")
    if np.any(stiffness <= 0.0):
        raise CaseError("face_variation.stiffness", float(np.min(stiffness)), "> 0 N/m at every mesh position",
                        "the moments are taken per unit of the stiffness in contact")
    # the period-mean matrix's load centre and gyration are the face moments' (intervals of equal length)
    means = FaceStiffnessMoments(np.arange(stiffness.size, dtype=float), stiffness, np.asarray(first_moment, float),
                                 np.asarray(second_moment, float))
    centre = sense * means.mean_load_centre
    mean_second = float(np.mean(means.second_moment) / np.mean(means.stiffness))
    return FaceVariation(sense * means.first_moment / stiffness - centre, means.second_moment / stiffness - mean_second,
                         sense * np.asarray(gap_moment) / stiffness, centre, means.mean_gyration)


def pair_face_variation(helical: HelicalPair, material: Material, points: int, sense: int,
                        slices: int = 100) -> FaceVariation:
    """The :class:`FaceVariation` of a pair without deviations (every slice in contact) on ``points`` equal
    intervals of the mesh period, each at its midpoint (the intervals of
    :func:`~thermogear.mesh.helical_state.helical_mesh_state`), for a drivetrain built in Python; ``sense`` = sH,
    the mesh's rotation sense times gear 1's hand. The case route takes each model's own, with its deviations
    (:func:`with_face_variations`)."""
    from thermogear.helical.slices import contact_stiffness

    phases = (np.arange(points) + 0.5) / points * helical.transverse_base_pitch
    centres, stiffness = contact_stiffness(helical, material, phases, slices)
    moments = FaceStiffnessMoments.of_slices(phases, stiffness.sum(axis=-2), centres - helical.face_width / 2.0)
    return face_variation(moments.stiffness, moments.first_moment, moments.second_moment, np.zeros(points), sense)


def _model_variation(mesh, model, points: int) -> FaceVariation | None:
    """The variation of a mesh model's helical pair at the case's load (None: a spur pair, or a contact that takes
    none)."""
    helical = getattr(model.case, "helical_pair", None)
    if not mesh.contact.varies or helical is None or helical.base_helix_angle == 0.0:
        return None
    from thermogear.mesh.helical_model import helical_face_moments

    moments = helical_face_moments(model, model.state(points_per_period=points, damping=False).normal_load, points)
    return face_variation(moments[0], moments[1], moments[2], moments[4], mesh.rotation_sense * mesh.hand)


def with_face_variations(drivetrain, models: tuple, points: int, references: tuple | None = None):
    """``drivetrain`` with each spread helical mesh's :class:`FaceVariation` from its mesh model (``models``: one
    :class:`~thermogear.mesh.model.MeshModel` per mesh, in order) at the case's load on ``points`` intervals.
    ``references``: the mesh models whose slice means the mesh's own z̄ and ρ stand for (the same pairs without
    deviations, the elastic models); the difference of the means (the load centre a partial contact moves, and its
    spread) moves the mesh's z̄ and ρ², so the mean matrix follows the deviations and equals the mesh's own where
    there are none. Where the case gives a power, the load is the case speed's."""
    meshes = []
    for index, (mesh, model) in enumerate(zip(drivetrain.meshes, models)):
        variation = _model_variation(mesh, model, points)
        if variation is None:
            meshes.append(mesh)
            continue
        changes = {"face_variation": variation}
        reference = None if references is None else _model_variation(mesh, references[index], points)
        if reference is not None and reference is not variation:
            centre, gyration = mesh.contact.moments(mesh)
            shift = variation.mean_gyration**2 - reference.mean_gyration**2
            changes.update(load_centre=centre + variation.mean_load_centre - reference.mean_load_centre,
                           load_gyration=math.sqrt(max(gyration**2 + shift, 0.0)))
        meshes.append(replace(mesh, **changes))
    return replace(drivetrain, meshes=tuple(meshes))


def case_face_variations(drivetrains: dict, mesh_models: dict, stage_models: dict, points: int,
                         reference: str) -> dict:
    """Each model's drivetrain (name → drivetrain) with :func:`with_face_variations` of its own mesh models
    (``mesh_models[name]`` for the first mesh, ``stage_models[name]`` for the further stages), the means moved from
    those of the ``reference`` model (the elastic one: no deviations)."""
    references = (mesh_models[reference], *stage_models[reference])
    return {name: with_face_variations(drivetrain, (mesh_models[name], *stage_models[name]), points,
                                       None if name == reference else references)
            for name, drivetrain in drivetrains.items()}
