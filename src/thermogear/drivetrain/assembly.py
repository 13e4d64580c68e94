"""Assembly of a drivetrain: shafts, disks, bearings, couplings, torsional supports and gear meshes → global
matrices M, K, C, G, the mesh vectors and the per-element stiffness groups for modal strain-energy shares.

Global DOF numbering: 6 per node (x, y, z, α, β, θ), the nodes of each shaft in turn, in the order the shafts are
given. Angles are global (about +x, +y, +z). Each shaft spins at ``speed_ratio × Ω`` (signed, about +z) where Ω is the
reference speed, the speed of the first shaft taken positive in gear 1's turning sense; the ratios follow from the
meshes (ω₂/ω₁ = −r_b1/r_b2) and couplings (equal speeds). The gyroscopic matrix returned is Σ_k ratio_k·G_k, to be
multiplied by Ω [rad/s] (Friswell et al. 2010, Eq. 5.88: M q̈ + (C + ΩG) q̇ + K q = f).
"""

from __future__ import annotations

from dataclasses import dataclass, field, replace
from typing import TYPE_CHECKING

import numpy as np

from thermogear.drivetrain.elements import PlacedShaftElement, StructureElement
from thermogear.drivetrain.layout import Shaft, node_index, shaft_mesh
from thermogear.drivetrain.mesh_element import GearMesh
from thermogear.drivetrain.point_elements import Bearing, Coupling, NodeLocation, RigidDisk, TorsionalSupport
from thermogear.errors import CaseError

if TYPE_CHECKING:
    from thermogear.dynamics.backlash.backlash_ndof import DeadZone

__all__ = ["Drivetrain", "AssembledDrivetrain", "DOF_NAMES"]

DOF_NAMES = ("x", "y", "z", "alpha", "beta", "theta")


@dataclass(frozen=True)
class Drivetrain:
    """The description of a drivetrain (inputs only; :meth:`assemble` builds the matrices)."""

    shafts: tuple[Shaft, ...]
    disks: tuple[RigidDisk, ...] = ()
    bearings: tuple[Bearing, ...] = ()
    couplings: tuple[Coupling, ...] = ()
    meshes: tuple[GearMesh, ...] = ()
    torsional_supports: tuple[TorsionalSupport, ...] = ()
    further_elements: tuple[StructureElement, ...] = ()  # elements of any other class with the element interface

    def __post_init__(self) -> None:
        for key in ("shafts", "disks", "bearings", "couplings", "meshes", "torsional_supports", "further_elements"):
            object.__setattr__(self, key, tuple(getattr(self, key)))
        names = [shaft.name for shaft in self.shafts]
        if not names or len(set(names)) != len(names):
            raise CaseError("shafts", names, "at least one shaft, unique names", "shafts are found by name")
        for item in self.further_elements:
            if not isinstance(item, StructureElement):
                raise CaseError("further_elements", type(item).__name__, "objects with the element interface",
                                "thermogear.drivetrain.elements.StructureElement: locations, matrices, dead zones")
        element_names = [item.name for group in (self.disks, self.bearings, self.couplings, self.meshes,
                                                 self.torsional_supports, self.further_elements) for item in group]
        duplicated = sorted({name for name in element_names if element_names.count(name) > 1} | (set(element_names) & set(names)))
        if duplicated:
            raise CaseError("element names", duplicated, "unique names (and not a shaft's name)",
                            "energy shares and bearing forces are reported by name")
        for location in self._locations():
            if location.shaft not in names:
                raise CaseError("shaft", location.shaft, f"one of {names}", "an element sits on a named shaft")

    def _locations(self) -> list[NodeLocation]:
        points = [item.location for group in (self.disks, self.bearings, self.torsional_supports) for item in group]
        points += [point for coupling in self.couplings for point in (coupling.first, coupling.second)]
        points += [point for mesh in self.meshes for point in (mesh.gear_1, mesh.gear_2)]
        points += [point for item in self.further_elements for point in item.locations]
        return points

    def speed_ratios(self) -> dict[str, float]:
        """Signed spin speed of each shaft over the reference speed (first shaft: +1, or the first mesh's
        rotation sense when the first shaft carries its gear 1), propagated through meshes and couplings."""
        names = [shaft.name for shaft in self.shafts]
        first = names[0]
        start = 1.0
        for mesh in self.meshes:
            if mesh.gear_1.shaft == first:
                start = float(mesh.rotation_sense)
                break
        ratios = {first: start}
        links = [(m.gear_1.shaft, m.gear_2.shaft, m.speed_ratio) for m in self.meshes]
        links += [(c.first.shaft, c.second.shaft, 1.0) for c in self.couplings if c.first.shaft != c.second.shaft]
        changed = True
        while changed:
            changed = False
            for one, two, ratio in links:
                if one in ratios and two not in ratios:
                    ratios[two], changed = ratios[one] * ratio, True
                elif two in ratios and one not in ratios:
                    ratios[one], changed = ratios[two] / ratio, True
                elif one in ratios and abs(ratios[two] - ratios[one] * ratio) > 1e-9 * abs(ratios[two]):
                    raise CaseError(f"link {one} → {two}", ratio, f"{ratios[two] / ratios[one]:.6g} (the speed ratio "
                                    "the other links give)", "a link between shafts whose speeds the gears already "
                                    "fix to differ would jam the train (conflicting speed ratios)")
        return {name: ratios.get(name, 1.0) for name in names}

    def nodes(self) -> dict[str, tuple[np.ndarray, list]]:
        """Per shaft: its node positions [m] and its Timoshenko elements between consecutive nodes (nodes at the
        segment ends and every attachment, :func:`~thermogear.drivetrain.layout.shaft_mesh`)."""
        attachments: dict[str, list[float]] = {shaft.name: [] for shaft in self.shafts}
        for location in self._locations():
            attachments[location.shaft].append(float(location.position))
        return {shaft.name: shaft_mesh(shaft, attachments[shaft.name]) for shaft in self.shafts}

    def elements(self, meshed: dict[str, tuple[np.ndarray, list]] | None = None) -> tuple[StructureElement, ...]:
        """Every element behind the one interface (:mod:`thermogear.drivetrain.elements`), in assembly order: the
        shafts' elements shaft by shaft, the disks, bearings, torsional supports, couplings, meshes and the
        ``further_elements``."""
        meshed = self.nodes() if meshed is None else meshed
        placed = []
        for shaft in self.shafts:
            positions, elements = meshed[shaft.name]
            placed += [PlacedShaftElement(shaft.name, NodeLocation(shaft.name, float(positions[number])),
                                          NodeLocation(shaft.name, float(positions[number + 1])), element,
                                          shaft.material_damping)
                       for number, element in enumerate(elements)]
        return (*placed, *self.disks, *self.bearings, *self.torsional_supports, *self.couplings, *self.meshes,
                *self.further_elements)

    def assemble(self) -> AssembledDrivetrain:
        """Global matrices of the drivetrain (see :class:`AssembledDrivetrain`): one loop over :meth:`elements`,
        each element's blocks added on its nodes' DOFs, its stiffness to its energy group, its dead zones and mesh
        vector placed in the global DOFs."""
        meshed = self.nodes()
        nodes, offsets, count = {}, {}, 0
        for shaft in self.shafts:
            nodes[shaft.name] = meshed[shaft.name][0]
            offsets[shaft.name] = count
            count += nodes[shaft.name].size
        size = 6 * count

        def dofs(location: NodeLocation) -> np.ndarray:
            node = offsets[location.shaft] + node_index(nodes[location.shaft], location.shaft, location.position)
            return np.arange(6 * node, 6 * node + 6)

        mass, damping, gyroscopic = np.zeros((size, size)), np.zeros((size, size)), np.zeros((size, size))
        groups: dict[str, np.ndarray] = {}
        vectors, tilts, zones, mesh_names = [], [], [], []
        ratios = self.speed_ratios()
        for element in self.elements(meshed):
            where = np.concatenate([dofs(location) for location in element.locations])
            block = np.ix_(where, where)
            vector = element.mesh_vector()
            if vector is not None:  # a mesh: its stiffness is its state's, k(τ)·w wᵀ, plus any constant part
                full = np.zeros(size)
                full[where] += vector
                vectors.append(full)
                tilt = np.zeros(size)
                if getattr(element, "varies", lambda: False)():  # a spread contact's w_z, for its moments' variation
                    tilt[where] += element.tilt_vector()
                tilts.append(tilt)
                mesh_names.append(element.name)
                constant = element.stiffness_matrix()
                if np.any(constant):  # a spread contact's tilting stiffness, under the mesh's name
                    groups.setdefault(element.energy_group, np.zeros((size, size)))[block] += constant
                damping[block] += element.damping_matrix()
                continue
            mass[block] += element.mass_matrix()
            damping[block] += element.damping_matrix()
            gyroscopic[block] += ratios[element.spin_shaft] * element.gyroscopic_matrix()
            if element.energy_group is not None:
                groups.setdefault(element.energy_group, np.zeros((size, size)))[block] += element.stiffness_matrix()
            for zone in element.dead_zones():
                full = np.zeros(size)
                full[where] = zone.vector
                zones.append((element.name, replace(zone, vector=full)))
        structure = sum(groups.values(), np.zeros((size, size)))
        return AssembledDrivetrain(
            drivetrain=self, node_positions=nodes, node_offsets=offsets, mass=mass, structure_stiffness=structure,
            structure_damping=damping, gyroscopic=gyroscopic,
            mesh_vectors=np.array(vectors) if vectors else np.zeros((0, size)), stiffness_groups=groups,
            speed_ratios=ratios, dead_zones=tuple(zones),
            tilt_vectors=np.array(tilts) if tilts else np.zeros((0, size)))


@dataclass(frozen=True, eq=False)
class AssembledDrivetrain:
    """Global matrices [SI] of a drivetrain on its 6·nodes DOFs.

    ``structure_stiffness`` and ``structure_damping`` hold shafts, bearings, couplings and torsional supports (of a
    mesh only a helical spread contact's constant tilting part); ``mesh_vectors`` (meshes, DOFs) the w of each mesh; ``stiffness_groups`` one matrix per shaft, bearing,
    coupling and support by name (they add up to ``structure_stiffness``); ``gyroscopic`` is per unit reference
    speed [rad/s]; ``dead_zones`` (element name, dead zone on the global DOFs) of every element with one, in
    element order (a bearing's clearance: x, then y); ``tilt_vectors`` (meshes, DOFs) the w_z of each mesh whose
    moments vary over the period (:meth:`GearMesh.varies`; zero for the others).
    """

    drivetrain: Drivetrain
    node_positions: dict[str, np.ndarray]
    node_offsets: dict[str, int]
    mass: np.ndarray
    structure_stiffness: np.ndarray
    structure_damping: np.ndarray
    gyroscopic: np.ndarray
    mesh_vectors: np.ndarray
    stiffness_groups: dict[str, np.ndarray]
    speed_ratios: dict[str, float]
    dead_zones: tuple[tuple[str, DeadZone], ...] = ()
    tilt_vectors: np.ndarray | None = None
    _cache: dict = field(default_factory=dict, repr=False, compare=False)

    @property
    def size(self) -> int:
        """Number of DOFs."""
        return self.mass.shape[0]

    def dof(self, location: NodeLocation, name: str) -> int:
        """Global index of one DOF (``name`` in x, y, z, alpha, beta, theta) at a shaft node."""
        if name not in DOF_NAMES:
            raise CaseError("dof", name, f"one of {DOF_NAMES}", "the six DOFs of a node")
        local = node_index(self.node_positions[location.shaft], location.shaft, location.position)
        return 6 * (self.node_offsets[location.shaft] + local) + DOF_NAMES.index(name)

    def translation_dofs(self, location: NodeLocation) -> list[int]:
        """Global indices of the node's x, y, z DOFs (where a bearing's forces act)."""
        return [self.dof(location, name) for name in ("x", "y", "z")]

    def dof_mask(self, names: tuple[str, ...], shaft: str | None = None) -> np.ndarray:
        """Boolean mask (DOFs,) of the named DOF kinds, on one shaft or all."""
        mask = np.zeros(self.size, dtype=bool)
        kinds = [DOF_NAMES.index(name) for name in names]
        for shaft_name, offset in self.node_offsets.items():
            if shaft is not None and shaft_name != shaft:
                continue
            nodes = offset + np.arange(self.node_positions[shaft_name].size)
            mask[(6 * nodes[:, None] + np.array(kinds)[None, :]).ravel()] = True
        return mask

    def mesh_stiffness_groups(self, mesh_stiffness: np.ndarray | None = None) -> dict[str, np.ndarray]:
        """k̄·w wᵀ of each mesh by name (the meshes' own stiffness where none is given), plus its constant part (a
        helical spread contact's tilting stiffness, :mod:`thermogear.drivetrain.mesh_contact`)."""
        values = self._mesh_values(mesh_stiffness)
        return {mesh.name: value * np.outer(w, w) + self.stiffness_groups.get(mesh.name, 0.0)
                for mesh, w, value in zip(self.drivetrain.meshes, self.mesh_vectors, values)}

    def _mesh_values(self, mesh_stiffness: np.ndarray | None) -> np.ndarray:
        if mesh_stiffness is None:
            return np.array([mesh.stiffness for mesh in self.drivetrain.meshes])
        return np.broadcast_to(np.asarray(mesh_stiffness, dtype=float), (len(self.drivetrain.meshes),))

    def stiffness(self, mesh_stiffness: np.ndarray | None = None) -> np.ndarray:
        """Total stiffness K + Σ k̄ w wᵀ [SI]."""
        values = self._mesh_values(mesh_stiffness)
        return self.structure_stiffness + (self.mesh_vectors.T * values) @ self.mesh_vectors

    def connection_stiffness(self, mesh_stiffness: np.ndarray | None = None) -> np.ndarray:
        """The stiffness that joins the shafts to each other and to ground (total less the shafts' own): what
        the shafts' rigid motions can strain, for finding the rigid-body modes."""
        shafts = sum((self.stiffness_groups[shaft.name] for shaft in self.drivetrain.shafts),
                     np.zeros((self.size, self.size)))
        return self.stiffness(mesh_stiffness) - shafts

    def damping(self, speed: float = 0.0, mesh_damping: np.ndarray | None = None) -> np.ndarray:
        """Total velocity matrix C + Σ c̄ w wᵀ + Ω·G at reference speed Ω [rad/s]."""
        values = (np.array([mesh.damping for mesh in self.drivetrain.meshes]) if mesh_damping is None
                  else np.broadcast_to(np.asarray(mesh_damping, dtype=float), (len(self.drivetrain.meshes),)))
        return self.structure_damping + (self.mesh_vectors.T * values) @ self.mesh_vectors + speed * self.gyroscopic

    def rigid_candidates(self) -> np.ndarray:
        """(DOFs, 6·shafts) rigid motions of each shaft on its own: translations x, y, z, rotations about x, y
        (with the slopes dy/dz = −α, dx/dz = +β) and torsion."""
        columns = []
        for shaft_name, offset in self.node_offsets.items():
            positions = self.node_positions[shaft_name]
            for kind in range(6):
                vector = np.zeros(self.size)
                for node, z in enumerate(positions):
                    base = 6 * (offset + node)
                    if kind in (0, 1, 2, 5):
                        vector[base + kind] = 1.0
                    elif kind == 3:
                        vector[base + 3], vector[base + 1] = 1.0, -z
                    else:
                        vector[base + 4], vector[base] = 1.0, z
                columns.append(vector)
        return np.array(columns).T
