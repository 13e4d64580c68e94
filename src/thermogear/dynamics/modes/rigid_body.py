"""Rigid-body modes of a structural model and the reduction onto their mass-orthogonal complement (matrices only).

A free train (no torsional ground, constant torques) has K r = 0 for its rigid rotation r; with C r = 0 the rigid
motion decouples from the elastic one and the equations can be solved on q = Q p with Q spanning
{v : rᵀ M v = 0} (M_Q = QᵀMQ, K_Q = QᵀKQ, C_Q = QᵀCQ, f_Q = Qᵀf), provided rᵀf = 0 (otherwise the train
accelerates and there is no steady state). See e.g. Géradin & Rixen, Mechanical Vibrations, 3rd ed. (2015), §2.6
on rigid-body modes and the projection onto the elastic subspace.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from thermogear.errors import ProblemError

__all__ = ["RigidBodyReduction", "rigid_body_modes", "rigid_body_reduction"]

_NULL_TOLERANCE = 1e-9  # on the diagonally scaled matrix: rigid combinations give rounding (~1e-16), a connection O(1)


def rigid_body_modes(connection_stiffness: np.ndarray, candidates: np.ndarray,
                     tolerance: float = _NULL_TOLERANCE) -> np.ndarray:
    """Columns r (DOFs, count), orthonormal, spanning the rigid-body motions K r = 0 inside the span of
    ``candidates``.

    ``candidates`` are motions that strain no body on its own (the rigid motions of each shaft), and
    ``connection_stiffness`` the stiffness of what joins the bodies to each other and to ground (bearings,
    couplings, meshes): the bodies' own stiffness is left out, since it does no work on the candidates. The null
    space is that of S = RᵀKR scaled by its diagonal (S_ij/√(S_ii S_jj)), whose eigenvalues are O(1) for a
    connected combination whatever the stiffness magnitudes; a candidate with S_ii = 0 is free.
    """
    stiffness = np.asarray(connection_stiffness, dtype=float)
    candidates = np.asarray(candidates, dtype=float)
    if candidates.size == 0:
        return np.zeros((stiffness.shape[0], 0))
    small = candidates.T @ stiffness @ candidates
    small = 0.5 * (small + small.T)
    diagonal = np.diag(small).copy()
    touched = diagonal > 0.0
    null_columns = [np.eye(candidates.shape[1])[:, ~touched]]
    if np.any(touched):
        scale = 1.0 / np.sqrt(diagonal[touched])
        scaled = small[np.ix_(touched, touched)] * np.outer(scale, scale)
        values, vectors = np.linalg.eigh(scaled)
        free = np.zeros((candidates.shape[1], int(np.sum(values <= tolerance))))
        free[touched] = vectors[:, values <= tolerance] * scale[:, None]
        null_columns.append(free)
    modes = candidates @ np.hstack(null_columns)
    if modes.shape[1]:
        modes, _ = np.linalg.qr(modes)
    return modes


@dataclass(frozen=True, eq=False)
class RigidBodyReduction:
    """q = Q p on the M-orthogonal complement of the rigid modes r (columns); Q has orthonormal columns."""

    rigid_modes: np.ndarray
    basis: np.ndarray

    def project(self, matrix: np.ndarray) -> np.ndarray:
        """QᵀXQ."""
        return self.basis.T @ matrix @ self.basis

    def project_vector(self, vector: np.ndarray) -> np.ndarray:
        """Qᵀf (for a force) — and Qᵀw for a mesh vector, since δ = wᵀQp."""
        return self.basis.T @ vector

    def expand(self, reduced: np.ndarray) -> np.ndarray:
        """q = Q p (works on (count,) and (count, k) arrays)."""
        return self.basis @ reduced

    def expansion(self, basis: np.ndarray | None = None) -> np.ndarray:
        """E with q = E η for the coordinates η of a ``basis`` B (r, k) of the reduced space (e.g. a modal basis):
        E = Q B, formed once, so that samples pass straight from η to q (S·n·k) instead of through p (S·n·r); Q
        itself without one."""
        return self.basis if basis is None else self.basis @ basis


def rigid_body_reduction(mass: np.ndarray, connection_stiffness: np.ndarray, candidates: np.ndarray,
                         damping: np.ndarray | None = None) -> RigidBodyReduction:
    """The reduction onto the complement of the rigid modes (identity basis when there are none); the rigid modes
    are found from the candidates and the connection stiffness as in :func:`rigid_body_modes`.

    ProblemError when the damping acts on a rigid mode (C r ≠ 0): then the rigid motion does not decouple (an
    absolute damper on a free rotation needs a spring to ground: a speed-controlled motor).
    """
    from scipy.linalg import null_space

    mass = np.asarray(mass, dtype=float)
    size = mass.shape[0]
    rigid = rigid_body_modes(connection_stiffness, candidates)
    if rigid.shape[1] == 0:
        return RigidBodyReduction(rigid, np.eye(size))
    if damping is not None:
        leak = np.abs(damping @ rigid).max()
        if leak > 1e-9 * max(np.abs(damping).max(), 1e-300):
            raise ProblemError("damping", f"|C r| = {leak:.3g}", "C r = 0 on every rigid-body mode",
                               "damping on a free rotation couples it to the elastic motion; hold the motor at "
                               "speed (a torsional spring to ground) instead")
    basis = null_space((mass @ rigid).T)
    return RigidBodyReduction(rigid, basis)
