"""The degenerate drivetrain: two rigid gears on rigid supports, joined by their mesh.

With rigid shafts and bearings each gear keeps only its rotation θ_i about +z, and the drivetrain's matrices become
M = diag(J₁, J₂), K₀ = C₀ = 0 and the mesh vector w = s·(r_b1, r_b2) of the spur mesh element
(:mod:`thermogear.drivetrain.mesh_element`), loaded by the torque pair s·r_b1·W, s·r_b2·W. The free rotation
r = (r_b2, −r_b1) (wᵀr = 0) is removed as in any drivetrain (:mod:`thermogear.dynamics.modes.rigid_body`), and what is
left is the one mesh coordinate δ = wᵀq with the mass 1/(wᵀM⁻¹w) = J₁J₂/(J₁r_b2² + J₂r_b1²) = m_e of Luo & Li
(2020) Eq. 5: the 1-DOF pair. :class:`RigidPair` gives both forms — the general one (:meth:`periodic_system`, the
matrices every drivetrain solver takes) and the scalar one (:meth:`mesh_structure`, which sends the 1-DOF solvers to
their compiled closed-form 2×2 kernels) — and the tests hold them equal.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from thermogear.dynamics.modes.rigid_body import RigidBodyReduction, rigid_body_reduction
from thermogear.dynamics.periodic_orbits.periodic_ndof import PiecewiseLinearSystem
from thermogear.dynamics.problems.structure import MeshStructure
from thermogear.errors import CaseError

__all__ = ["RigidPair"]


@dataclass(frozen=True)
class RigidPair:
    """Polar inertias J₁, J₂ [kg·m²] and base radii r_b1, r_b2 [m] of two rigid gears on rigid supports;
    ``rotation_sense`` s = +1 when gear 1 turns counter-clockwise about +z."""

    inertia_1: float
    inertia_2: float
    base_radius_1: float
    base_radius_2: float
    rotation_sense: int = 1

    def __post_init__(self) -> None:
        for key in ("inertia_1", "inertia_2", "base_radius_1", "base_radius_2"):
            value = float(getattr(self, key))
            if not math.isfinite(value) or value <= 0.0:
                raise CaseError(key, getattr(self, key), "> 0, finite", "a rigid gear's inertia and base radius")
        if self.rotation_sense not in (1, -1):
            raise CaseError("rotation_sense", self.rotation_sense, "+1 or −1", "gear 1's turning sense about +z")

    def mass_matrix(self) -> np.ndarray:
        """diag(J₁, J₂) [kg·m²] on (θ₁, θ₂)."""
        return np.diag([float(self.inertia_1), float(self.inertia_2)])

    def mesh_vector(self) -> np.ndarray:
        """w = s·(r_b1, r_b2) [m]: δ = wᵀq (the torsional entries of the spur mesh element)."""
        return self.rotation_sense * np.array([float(self.base_radius_1), float(self.base_radius_2)])

    def torques(self, normal_load: float) -> np.ndarray:
        """The driving and load torques s·r_b1·W, s·r_b2·W [N·m] in equilibrium with W [N]."""
        return normal_load * self.mesh_vector()

    @property
    def mesh_mass(self) -> float:
        """m_e = 1/(wᵀM⁻¹w) [kg] (Luo & Li 2020 Eq. 5)."""
        w = self.mesh_vector()
        return float(1.0 / (w @ np.linalg.solve(self.mass_matrix(), w)))

    def mesh_structure(self) -> MeshStructure:
        """The 1-DOF structure M = [m_e], w = [1]: the mesh problem solved by the compiled scalar kernels."""
        return MeshStructure.single(self.mesh_mass)

    def periodic_system(self, problem, normal_load: float) -> tuple[PiecewiseLinearSystem, RigidBodyReduction]:
        """The pair as a drivetrain over one mesh period of ``problem`` (a mesh state's problem: its k(τ), c(τ) and
        load per interval), the free rotation removed: the same pieces and reduction as every drivetrain's."""
        w = self.mesh_vector()
        mean = float(np.dot(problem.stiffness, np.diff(problem.nodes)) / problem.period)
        reduction = rigid_body_reduction(self.mass_matrix(), mean * np.outer(w, w), np.eye(2))
        reduced = reduction.project_vector(w)
        pattern = np.outer(reduced, reduced)
        size = reduced.size
        system = PiecewiseLinearSystem(
            mass=reduction.project(self.mass_matrix()), stiffness=np.zeros((size, size)),
            damping=np.zeros((size, size)), force=reduction.project_vector(self.torques(normal_load)),
            nodes=problem.nodes, stiffness_pattern=pattern, stiffness_factor=problem.stiffness,
            damping_pattern=pattern, damping_factor=problem.damping, force_pattern=reduced,
            force_factor=problem.force_per_interval - normal_load)
        return system, reduction
