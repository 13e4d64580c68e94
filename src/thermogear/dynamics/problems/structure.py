"""The matrices of a mesh problem: one gear mesh inside a linear structure of n degrees of freedom.

    M q̈ + (C₀ + c(τ)·w wᵀ) q̇ + (K₀ + k(τ)·w wᵀ) q = f₀ + g(τ)·w

q (n,) are the generalised coordinates [m or rad], M (n, n) the mass matrix, K₀ and C₀ (n, n) the constant
structural stiffness and damping (shafts, bearings, couplings), f₀ (n,) constant external loads, and w (n,) the
mesh vector: the mesh deflection along the line of action is δ = wᵀq, the mesh force k·δ + c·ẋ acts on the
coordinates through w (the gear mesh element of a lumped or finite-element drivetrain, e.g. Kahraman, Özgüven,
Houser & Zakrajsek, "Dynamic analysis of geared rotors by finite elements", J. Mech. Des. 114 (1992) 507–514).
The mesh stiffness k(τ), damping c(τ) and mesh load g(τ) are the problem's per-interval scalars, so the whole
period is stored as a constant part plus one rank-one pattern scaled per interval.

The 1-DOF mesh of Luo & Li (2020) Eq. (5) is the 1×1 case: q = x (the transmission error), M = [me], w = [1],
K₀ = C₀ = 0, f₀ = 0. It is kept as the scalar ``mass`` me so its solvers take the closed-form 2×2 kernels
(:mod:`thermogear.dynamics.linear_algebra.transition_2x2`); :attr:`MeshStructure.is_scalar_mesh` is the one place that
decides. Arrays only; nothing here knows of gears.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from thermogear.errors import ProblemError

__all__ = ["MeshStructure", "checked_structure"]


def _square(name: str, value: object, size: int, symmetric: bool = False) -> np.ndarray:
    array = np.array(value, dtype=float, copy=True)
    if array.shape != (size, size):
        raise ProblemError(name, f"array of shape {array.shape}", f"shape ({size}, {size})",
                           "one row and one column per degree of freedom of the mass matrix")
    if not np.all(np.isfinite(array)):
        raise ProblemError(name, "non-finite values", "finite numbers", "a NaN coefficient has no physical meaning")
    # symmetric to rounding: a projected matrix QᵀMQ carries ~1e-16 relative asymmetry, so 1e-12 of the largest entry
    if symmetric and not np.allclose(array, array.T, rtol=0.0, atol=1e-12 * float(np.abs(array).max())):
        raise ProblemError(name, "not symmetric", "a symmetric matrix", "a mass matrix (kinetic energy) is symmetric")
    array.setflags(write=False)
    return array


@dataclass(frozen=True, eq=False)
class MeshStructure:
    """M, K₀, C₀, f₀ and the mesh vector w of a mesh problem (module docstring), checked and read-only.

    ``mass`` (n, n) [kg or kg·m²], symmetric positive definite; ``stiffness`` K₀, ``damping`` C₀ (n, n) [N/m,
    N·s/m or per radian], not required symmetric (C₀ may hold the skew gyroscopic term Ω·G of a rotor); ``force`` f₀ (n,) [N or N·m]; ``mesh_vector`` w (n,) [-] or [m] (a base radius for
    a rotation), not all zero.
    """

    mass: np.ndarray
    mesh_vector: np.ndarray
    stiffness: np.ndarray
    damping: np.ndarray
    force: np.ndarray

    @classmethod
    def single(cls, mass: float) -> MeshStructure:
        """The 1×1 structure of the 1-DOF mesh: M = [me], w = [1], K₀ = C₀ = 0, f₀ = 0."""
        return checked_structure(mass, None, None, None, None)

    @property
    def degrees_of_freedom(self) -> int:
        """n."""
        return int(self.mass.shape[0])

    @property
    def is_scalar_mesh(self) -> bool:
        """True for the 1-DOF mesh (M = [me], w = [1], no structural K₀, C₀, f₀): closed-form 2×2 kernels apply."""
        return (self.degrees_of_freedom == 1 and self.mesh_vector[0] == 1.0 and self.stiffness[0, 0] == 0.0
                and self.damping[0, 0] == 0.0 and self.force[0] == 0.0)

    @property
    def mesh_mass(self) -> float:
        """Equivalent mass of the mesh coordinate δ = wᵀq [kg]: 1/(wᵀM⁻¹w) (me itself in the 1-DOF case)."""
        if self.is_scalar_mesh:
            return float(self.mass[0, 0])
        return float(1.0 / (self.mesh_vector @ np.linalg.solve(self.mass, self.mesh_vector)))

    def require_scalar_mesh(self, solver: str) -> None:
        """ProblemError (naming ``mass``) unless this is the 1-DOF mesh: for the solvers written on its closed-form
        2×2 flow (``solver`` names the one refusing)."""
        if not self.is_scalar_mesh:
            raise ProblemError("mass", f"a {self.degrees_of_freedom}-DOF structure", "the 1-DOF mesh (scalar mass)",
                               f"{solver} solves the 1-DOF mesh me·ẍ + c·ẋ + k·x = w; a mesh in a structure of "
                               "many degrees of freedom is solved through its matrices")

    def pattern(self) -> np.ndarray:
        """w wᵀ (n, n): the stiffness and damping pattern scaled by k(τ) and c(τ)."""
        return np.outer(self.mesh_vector, self.mesh_vector)


def checked_structure(mass: object, mesh_vector: object, stiffness: object, damping: object,
                      force: object) -> MeshStructure:
    """The checked :class:`MeshStructure` of a problem's inputs; ProblemError naming the input otherwise.

    ``mass`` is me [kg] (a positive scalar: the 1-DOF mesh) or M (n, n); the others default to w = [1, 0, …]
    only for n = 1 (w must be given for n > 1), K₀ = C₀ = 0 and f₀ = 0.
    """
    matrix = np.array(mass, dtype=float, copy=True)
    if matrix.ndim == 0:
        if not np.isfinite(matrix) or matrix <= 0.0:
            raise ProblemError("mass", mass, "> 0 kg, finite", "the equivalent mass me of Eq. (5) must be positive")
        matrix = matrix.reshape(1, 1)
    if matrix.ndim != 2 or matrix.shape[0] != matrix.shape[1] or matrix.shape[0] < 1:
        raise ProblemError("mass", f"array of shape {matrix.shape}", "a positive scalar or a square matrix",
                           "the mass me of the 1-DOF mesh or the mass matrix M of a structure")
    size = matrix.shape[0]
    matrix = _square("mass", matrix, size, symmetric=True)
    if np.any(np.linalg.eigvalsh(matrix) <= 0.0):
        raise ProblemError("mass", "not positive definite", "a symmetric positive definite matrix",
                           "every degree of freedom needs inertia")
    if mesh_vector is None:
        if size != 1:
            raise ProblemError("mesh_vector", None, f"an array of shape ({size},)",
                               "with a mass matrix the mesh vector w says which coordinates the mesh couples")
        mesh_vector = [1.0]
    vector = np.array(mesh_vector, dtype=float, copy=True)
    if vector.shape != (size,) or not np.all(np.isfinite(vector)) or not np.any(vector != 0.0):
        raise ProblemError("mesh_vector", f"array of shape {vector.shape}", f"shape ({size},), finite, not all 0",
                           "the mesh deflection is wᵀq")
    vector.setflags(write=False)
    zeros = np.zeros((size, size))
    stiffness_matrix = _square("structural_stiffness", zeros if stiffness is None else stiffness, size)
    damping_matrix = _square("structural_damping", zeros if damping is None else damping, size)
    load = np.array(np.zeros(size) if force is None else force, dtype=float, copy=True)
    if load.shape != (size,) or not np.all(np.isfinite(load)):
        raise ProblemError("structural_force", f"array of shape {load.shape}", f"finite, shape ({size},)",
                           "one constant external load per degree of freedom")
    load.setflags(write=False)
    return MeshStructure(mass=matrix, mesh_vector=vector, stiffness=stiffness_matrix, damping=damping_matrix,
                         force=load)
