"""Static state of a loaded drivetrain at the mean mesh stiffness: K̄ q̄ = f̄, mesh deflection and bearing reactions.

f̄ holds the driving and load torques in equilibrium with the normal tooth load W of each mesh (s·r_b1·W on gear 1,
s·r_b2·W on gear 2, global sense) and the mean unloaded deviation, k̄·ē·w (Kahraman et al. 1992: the deviation enters
as a force through the mesh stiffness). A free train is solved on the complement of its rigid-body modes; the
torques must then do no work on them (rᵀf̄ = 0) or the train would accelerate. A bearing's reaction on the housing is
K_b·u at its node (Friswell et al. 2010 §5.5); on a shaft with two bearings it splits the tooth load by the lever rule.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from thermogear.drivetrain.assembly import AssembledDrivetrain
from thermogear.dynamics.modes.rigid_body import rigid_body_reduction
from thermogear.errors import CaseError

__all__ = ["StaticState", "bearing_moments", "mesh_torque_forces", "static_state"]


@dataclass(frozen=True, eq=False)
class StaticState:
    """Static displacement (DOFs,) [SI], mesh deflection δ̄ = wᵀq̄ [m] and force k̄(δ̄ − ē) [N] per mesh, the
    force of each bearing on its housing (name → (3,) [N] in x, y, z: radial x, y and axial z) and its tilting
    moment (name → (2,) [N·m] about x and y; zero where the bearing has no tilting stiffness)."""

    displacement: np.ndarray
    mesh_deflection: np.ndarray
    mesh_force: np.ndarray
    bearing_forces: dict[str, np.ndarray]
    bearing_moments: dict[str, np.ndarray] = field(default_factory=dict)


def mesh_torque_forces(assembled: AssembledDrivetrain, normal_loads: np.ndarray) -> np.ndarray:
    """Force vector (DOFs,) of the driving and load torques of each mesh for normal tooth loads W [N] (one per mesh).

    A single stage: the driving torque on gear 1 and the load torque on gear 2. A train: the torques at its ends
    only, on the gears whose shaft carries no other mesh's gear; on an intermediate shaft the torque passes from one
    mesh to the next through the shaft (the torques of the two meshes there would cancel, but applied at the gears
    they would take the twist off the shaft between them). The loads must then balance the train, W_m·r_b of the
    wheel = W_m+1·r_b of the next pinion, or the train accelerates (static_state checks it).
    """
    meshes = assembled.drivetrain.meshes
    loads = np.broadcast_to(np.asarray(normal_loads, dtype=float), (len(meshes),))
    carried: dict[str, int] = {}
    for mesh in meshes:
        for shaft in {mesh.gear_1.shaft, mesh.gear_2.shaft}:
            carried[shaft] = carried.get(shaft, 0) + 1
    forces = np.zeros(assembled.size)
    for mesh, load in zip(meshes, loads):
        first, second = mesh.torques(load)
        if carried[mesh.gear_1.shaft] == 1:
            forces[assembled.dof(mesh.gear_1, "theta")] += first
        if carried[mesh.gear_2.shaft] == 1:
            forces[assembled.dof(mesh.gear_2, "theta")] += second
    return forces


def bearing_reactions(assembled: AssembledDrivetrain, displacement: np.ndarray) -> dict[str, np.ndarray]:
    """Force of each bearing on its housing, K_b·u (3,) [N], for a displacement (DOFs,) [SI]."""
    forces = {}
    for bearing in assembled.drivetrain.bearings:
        u = displacement[assembled.translation_dofs(bearing.location)][None]
        forces[bearing.name] = bearing.housing_force(u, np.zeros_like(u), clearance=False)[0]
    return forces


def bearing_moments(assembled: AssembledDrivetrain, displacement: np.ndarray) -> dict[str, np.ndarray]:
    """Tilting moment of each bearing on its housing (…, 2) [N·m] about x and y for displacements (…, DOFs)."""
    moments = {}
    for bearing in assembled.drivetrain.bearings:
        dofs = [assembled.dof(bearing.location, name) for name in ("alpha", "beta")]
        moments[bearing.name] = bearing.housing_moment(np.asarray(displacement)[..., dofs])
    return moments


def static_state(assembled: AssembledDrivetrain, normal_loads: np.ndarray | float,
                 mean_deviation: np.ndarray | float = 0.0, mesh_stiffness: np.ndarray | None = None,
                 external_forces: np.ndarray | None = None) -> StaticState:
    """Solve K̄ q̄ = f̄ (see the module docstring). ``external_forces`` (DOFs,) replaces the mesh torque pairs."""
    meshes = len(assembled.drivetrain.meshes)
    stiffness_values = assembled._mesh_values(mesh_stiffness)
    deviation = np.broadcast_to(np.asarray(mean_deviation, dtype=float), (meshes,))
    forces = (mesh_torque_forces(assembled, normal_loads) if external_forces is None
              else np.asarray(external_forces, dtype=float).copy())
    forces = forces + assembled.mesh_vectors.T @ (stiffness_values * deviation)
    stiffness = assembled.stiffness(stiffness_values)
    reduction = rigid_body_reduction(assembled.mass, assembled.connection_stiffness(stiffness_values),
                                     assembled.rigid_candidates())
    if reduction.rigid_modes.shape[1]:
        work = np.abs(reduction.rigid_modes.T @ forces).max()
        if work > 1e-9 * max(np.abs(forces).max(), 1e-300):
            raise CaseError("torques", f"|rᵀf| = {work:.3g}", "torques in equilibrium on every free rigid motion",
                            "unbalanced torques on a free train accelerate it: there is no static state")
    reduced = np.linalg.solve(reduction.project(stiffness), reduction.project_vector(forces))
    displacement = reduction.expand(reduced)
    deflection = assembled.mesh_vectors @ displacement
    return StaticState(displacement, deflection, stiffness_values * (deflection - deviation),
                       bearing_reactions(assembled, displacement), bearing_moments(assembled, displacement))
