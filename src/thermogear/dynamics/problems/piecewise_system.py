"""The piecewise-constant linear time-periodic system the exact periodic solvers take: its matrices, the patterns
scaled per piece, and the augmented state matrices of its pieces (the solvers: :mod:`thermogear.dynamics.
periodic_ndof`, :mod:`thermogear.dynamics.backlash.backlash_ndof`). Knows nothing of gears: matrices only.

M q̈ + C_j q̇ + K_j q = f_j on piece j; with z = [q; q̇] the piece is ż = A_j z + b_j, A_j = [[0, I], [−M⁻¹K_j,
−M⁻¹C_j]], b_j = [0; M⁻¹f_j], whose augmented matrix [[A_j, b_j], [0, 0]] the solvers exponentiate (Van Loan, IEEE
TAC 23 (1978) 395–404).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from thermogear.dynamics.problems.problem import checked_array, checked_nodes
from thermogear.errors import ProblemError

__all__ = ["PiecewiseLinearSystem"]


@dataclass(frozen=True, eq=False)
class PiecewiseLinearSystem:
    """M q̈ + (C₀ + c_j P_C) q̇ + (K₀ + k_j P_K) q = f₀ + g_j P_f on the pieces between ``nodes`` [s].

    ``mass``, ``stiffness``, ``damping``, ``stiffness_pattern``, ``damping_pattern``: (n, n) [SI];
    ``force``, ``force_pattern``: (n,); ``stiffness_factor``, ``damping_factor``, ``force_factor``: (N,) one per
    piece; ``nodes`` (N+1,) from 0 to the period. Several patterns (one per mesh, summed): the patterns (P, n, n)
    and (P, n), the factors (N, P); :meth:`stacked` gives either form stacked.
    """

    mass: np.ndarray
    stiffness: np.ndarray
    damping: np.ndarray
    force: np.ndarray
    nodes: np.ndarray
    stiffness_pattern: np.ndarray
    stiffness_factor: np.ndarray
    damping_pattern: np.ndarray
    damping_factor: np.ndarray
    force_pattern: np.ndarray
    force_factor: np.ndarray

    def __post_init__(self) -> None:
        mass = np.asarray(self.mass, dtype=float)
        if mass.ndim != 2 or mass.shape[0] != mass.shape[1]:
            raise ProblemError("mass", f"array of shape {mass.shape}", "a square matrix", "M of the system")
        size = mass.shape[0]
        nodes = checked_nodes(self.nodes)
        object.__setattr__(self, "nodes", nodes)
        pieces = nodes.size - 1
        square = (size, size)
        for name in ("mass", "stiffness", "damping"):
            object.__setattr__(self, name, checked_array(name, getattr(self, name), square, "one row/column per DOF"))
        object.__setattr__(self, "force", checked_array("force", self.force, (size,), "one value per DOF"))
        many = np.ndim(self.stiffness_pattern) == 3
        count = (int(np.shape(self.stiffness_pattern)[0]),) if many else ()
        for name in ("stiffness_pattern", "damping_pattern"):
            object.__setattr__(self, name, checked_array(name, getattr(self, name), count + square,
                                                         "one row/column per DOF (and one matrix per mesh)"))
        object.__setattr__(self, "force_pattern", checked_array("force_pattern", self.force_pattern, count + (size,),
                                                                "one value per DOF (and one row per mesh)"))
        for name in ("stiffness_factor", "damping_factor", "force_factor"):
            object.__setattr__(self, name, checked_array(name, getattr(self, name), (pieces, *count)))

    @property
    def pattern_count(self) -> int:
        """P, the number of patterns (meshes) whose factors vary per piece."""
        return 1 if self.stiffness_pattern.ndim == 2 else self.stiffness_pattern.shape[0]

    def stacked(self) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
        """(P_K (P, n, n), P_C (P, n, n), P_f (P, n), k (N, P), c (N, P), g (N, P)): the patterns and factors
        with one entry per pattern, whichever form the system holds."""
        if self.stiffness_pattern.ndim == 3:
            return (self.stiffness_pattern, self.damping_pattern, self.force_pattern, self.stiffness_factor,
                    self.damping_factor, self.force_factor)
        return (self.stiffness_pattern[None], self.damping_pattern[None], self.force_pattern[None],
                self.stiffness_factor[:, None], self.damping_factor[:, None], self.force_factor[:, None])

    @property
    def size(self) -> int:
        """Number of DOFs n."""
        return self.mass.shape[0]

    @property
    def period(self) -> float:
        """T [s]."""
        return float(self.nodes[-1])

    def piece(self, index: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """(K_j, C_j, f_j) of one piece."""
        pattern_k, pattern_c, pattern_f, factor_k, factor_c, factor_f = self.stacked()
        stiffness, damping, force = self.stiffness, self.damping, self.force
        for mesh in range(pattern_k.shape[0]):
            stiffness = stiffness + factor_k[index, mesh] * pattern_k[mesh]
            damping = damping + factor_c[index, mesh] * pattern_c[mesh]
            force = force + factor_f[index, mesh] * pattern_f[mesh]
        return stiffness, damping, force

    def augmented_stack(self, mass_inverse: np.ndarray) -> np.ndarray:
        """The (N, 2n+1, 2n+1) stack of [[A_j, b_j], [0, 0]], one per piece, built in one vectorised pass."""
        n = self.size
        pattern_k, pattern_c, pattern_f, factor_k, factor_c, factor_f = self.stacked()
        stiffness, damping = mass_inverse @ self.stiffness, mass_inverse @ self.damping
        force = mass_inverse @ self.force
        stiffness_block, damping_block, force_block = -stiffness, -damping, force
        for mesh in range(pattern_k.shape[0]):  # the sum over meshes (one term for a single mesh)
            stiffness_block = stiffness_block - factor_k[:, mesh, None, None] * (mass_inverse @ pattern_k[mesh])
            damping_block = damping_block - factor_c[:, mesh, None, None] * (mass_inverse @ pattern_c[mesh])
            force_block = force_block + factor_f[:, mesh, None] * (mass_inverse @ pattern_f[mesh])
        stack = np.zeros((self.nodes.size - 1, 2 * n + 1, 2 * n + 1))
        stack[:, :n, n:2 * n] = np.eye(n)
        stack[:, n:2 * n, :n] = stiffness_block
        stack[:, n:2 * n, n:2 * n] = damping_block
        stack[:, n:2 * n, 2 * n] = force_block
        return stack

    def augmented(self, index: int, mass_inverse: np.ndarray) -> np.ndarray:
        """The (2n+1)² matrix [[A_j, b_j], [0, 0]] of one piece."""
        n = self.size
        stiffness, damping, force = self.piece(index)
        matrix = np.zeros((2 * n + 1, 2 * n + 1))
        matrix[:n, n:2 * n] = np.eye(n)
        matrix[n:2 * n, :n] = -mass_inverse @ stiffness
        matrix[n:2 * n, n:2 * n] = -mass_inverse @ damping
        matrix[n:2 * n, 2 * n] = mass_inverse @ force
        return matrix
