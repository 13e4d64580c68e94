"""Two rigid rotors on rigid supports joined by one mesh: the structure of the 1-DOF pair.

Each rotor keeps only its rotation θ_i about +z, so the structure's matrices are M = diag(J₁, J₂), K₀ = C₀ = 0, and
the mesh strains along w = s·(r₁, r₂) (r_i the radius at which the mesh acts on rotor i, s the turning sense of
rotor 1), loaded by the torque pair s·r₁·W, s·r₂·W. The free rotation r = (r₂, −r₁) does no work on the mesh
(wᵀr = 0); removing it leaves the one mesh coordinate δ = wᵀq with the mass m_e = 1/(wᵀM⁻¹w) =
1/(r₁²/J₁ + r₂²/J₂) = J₁J₂/(J₁r₂² + J₂r₁²) (Luo & Li 2020 Eq. 5 for two gears of base radii r_b1, r_b2).
:meth:`RigidPair.mesh_structure` is that 1-DOF structure, which sends the mesh problem to the compiled closed-form
2×2 kernels; :mod:`thermogear.drivetrain.rigid_pair` gives the same pair as the matrices every drivetrain solver
takes, and the tests hold the two equal. Knows nothing of gears.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from thermogear.dynamics.problems.structure import MeshStructure
from thermogear.errors import CaseError

__all__ = ["RigidPair"]


@dataclass(frozen=True)
class RigidPair:
    """Polar inertias J₁, J₂ [kg·m²] of two rigid rotors and the radii r₁, r₂ [m] at which their mesh acts (a gear
    pair's base radii); ``rotation_sense`` s = +1 when rotor 1 turns counter-clockwise about +z."""

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
        """w = s·(r₁, r₂) [m]: δ = wᵀq (the torsional entries of the spur mesh element)."""
        return self.rotation_sense * np.array([float(self.base_radius_1), float(self.base_radius_2)])

    def torques(self, normal_load: float) -> np.ndarray:
        """The driving and load torques s·r₁·W, s·r₂·W [N·m] in equilibrium with W [N]."""
        return normal_load * self.mesh_vector()

    @property
    def mesh_mass(self) -> float:
        """m_e = 1/(wᵀM⁻¹w) = J₁J₂/(J₁r₂² + J₂r₁²) [kg] (module docstring; M is diagonal)."""
        inertia_1, inertia_2 = float(self.inertia_1), float(self.inertia_2)
        return inertia_1 * inertia_2 / (inertia_1 * float(self.base_radius_2)**2
                                        + inertia_2 * float(self.base_radius_1)**2)

    def mesh_structure(self) -> MeshStructure:
        """The 1-DOF structure M = [m_e], w = [1]: the mesh problem solved by the compiled scalar kernels."""
        return MeshStructure.single(self.mesh_mass)
