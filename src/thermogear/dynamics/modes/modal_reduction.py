"""Modal reduction of a piecewise-constant linear system with the static correction of its time-varying parts.

The Ritz basis is the undamped modes of the mean system (K̄ = K₀ + k̄·P_K, k̄ the time mean of k_j) up to a cut-off
frequency ω_c, completed by the static corrections K̄⁻¹v of the loads v that the modes truncate: the range of the
pattern P_K (for a gear mesh the mesh vector w), the force pattern P_f and the constant force f₀, each made
M-orthogonal to the modes and to each other (Craig & Kurdila, Fundamentals of Structural Dynamics, 2nd ed., Wiley
2006, §14.6 "mode-acceleration / static correction"; Dickens, Nakagawa & Wittbrodt, Comput. Struct. 62 (1997) 1037
for the correction vectors). Why the mesh compliance stays exact: on every piece K_j = K̄ + (k_j − k̄)·w wᵀ, and by
Sherman–Morrison K_j⁻¹v = K̄⁻¹v − K̄⁻¹w·(k_j − k̄)·wᵀK̄⁻¹v / (1 + (k_j − k̄)·wᵀK̄⁻¹w) lies in span{K̄⁻¹v, K̄⁻¹w}; the
Galerkin projection recovers a static solution that lies in its subspace, so the quasi-static response of every
piece is exact and only the dynamics of the modes above ω_c are lost. Columns the loads cannot reach through any
coupling of the reduced matrices are dropped (exact: their motion is zero). Knows nothing of gears: matrices only.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

from thermogear.dynamics.periodic_orbits.periodic_ndof import PiecewiseLinearSystem
from thermogear.errors import ProblemError

__all__ = ["MeanModes", "ModalBasis", "factor_means", "mean_modes", "mean_stiffness", "modal_basis"]


@dataclass(frozen=True, eq=False)
class ModalBasis:
    """q = B η: ``basis`` B (n, m) M-orthonormal, its first ``mode_count`` columns the excited modes below
    ``cutoff`` [rad/s], the rest static corrections; ``mode_frequencies`` [rad/s] of the kept modes."""

    basis: np.ndarray
    mode_count: int
    cutoff: float
    mode_frequencies: np.ndarray

    @property
    def size(self) -> int:
        """m, the reduced number of coordinates."""
        return self.basis.shape[1]

    def reduce(self, system: PiecewiseLinearSystem) -> PiecewiseLinearSystem:
        """The Galerkin projection BᵀXB, Bᵀf of every matrix and vector of the system (same nodes and factors)."""
        b = self.basis
        matrices = {name: b.T @ getattr(system, name) @ b for name in (
            "mass", "stiffness", "damping", "stiffness_pattern", "damping_pattern")}
        pattern = system.force_pattern
        return PiecewiseLinearSystem(
            force=b.T @ system.force, force_pattern=b.T @ pattern if pattern.ndim == 1 else pattern @ b,
            nodes=system.nodes,
            stiffness_factor=system.stiffness_factor, damping_factor=system.damping_factor,
            force_factor=system.force_factor, **matrices)

    def expand(self, reduced: np.ndarray) -> np.ndarray:
        """q = B η on (m,) or (m, k) arrays."""
        return self.basis @ reduced


def factor_means(factors: np.ndarray, system: PiecewiseLinearSystem) -> np.ndarray:
    """The time means (P,) of per-piece factors (N, P) of ``system`` over its period (weights the piece widths)."""
    widths = np.diff(system.nodes)
    return np.array([float(np.dot(factors[:, mesh], widths) / system.period) for mesh in range(factors.shape[1])])


def mean_stiffness(system: PiecewiseLinearSystem) -> np.ndarray:
    """K̄ = K₀ + Σ_m k̄_m P_K,m, the stiffness of the mean system (k̄_m the time mean of pattern m's factor)."""
    pattern_k, factor_k = system.stacked()[0], system.stacked()[3]
    mean = system.stiffness
    for mesh, value in enumerate(factor_means(factor_k, system)):
        mean = mean + value * pattern_k[mesh]
    return mean


@dataclass(frozen=True, eq=False)
class MeanModes:
    """Every undamped mode of a mean system: eigenvalues ``values`` ω_i² (n,) [rad²/s²] increasing and ``shapes``
    (n, n) M-orthonormal, of the mean stiffness whose pattern factors have the means ``stiffness_means`` (P,); those
    above ``cutoff`` ω_c [rad/s] are the ones :func:`modal_basis` on that cut-off leaves out."""

    cutoff: float
    values: np.ndarray
    shapes: np.ndarray
    stiffness_means: np.ndarray

    @property
    def frequencies(self) -> np.ndarray:
        """ω_i [rad/s] (a tiny negative eigenvalue of rounding read as 0)."""
        return np.sqrt(np.clip(self.values, 0.0, None))

    @property
    def dropped(self) -> np.ndarray:
        """Mask of the modes above the cut-off."""
        return ~(self.values <= self.cutoff**2)


def mean_modes(system: PiecewiseLinearSystem, cutoff: float) -> MeanModes:
    """Every mode of the mean system K̄ = :func:`mean_stiffness`, M of ``system``, split at ``cutoff`` ω_c [rad/s]."""
    from scipy.linalg import eigh

    if not np.isfinite(cutoff) or cutoff <= 0.0:
        raise ProblemError("cutoff", cutoff, "> 0 rad/s, finite", "the highest mode frequency kept")
    values, shapes = eigh(mean_stiffness(system), system.mass)
    return MeanModes(float(cutoff), values, shapes, factor_means(system.stacked()[3], system))


def modal_basis(system: PiecewiseLinearSystem, cutoff: float, loads: Sequence[np.ndarray] = (),
                modes: MeanModes | None = None) -> ModalBasis:
    """The modes of the mean system up to ``cutoff`` ω_c [rad/s] plus the static corrections (see the module
    docstring). ``cutoff`` above the highest mode keeps every mode: the reduction is then exact. ``loads``: further
    load vectors (n,) whose static corrections join the basis and which count as forcing the system (e.g. the
    vector of a dead zone, whose force switches on and off: its static response must lie in the basis as the mesh
    vector's does). ``modes``: the :func:`mean_modes` of this system, where the caller has them (else solved here)."""
    from scipy.linalg import solve

    if not np.isfinite(cutoff) or cutoff <= 0.0:
        raise ProblemError("cutoff", cutoff, "> 0 rad/s, finite", "the highest mode frequency kept")
    pattern_k, _, pattern_f = system.stacked()[:3]
    modes = mean_modes(system, cutoff) if modes is None else modes
    mean = mean_stiffness(system)
    mass = system.mass
    values, modes = modes.values, modes.shapes
    keep = values <= cutoff**2
    modes, frequencies = modes[:, keep], np.sqrt(np.clip(values[keep], 0.0, None))
    extra = tuple(loads)
    loads = []
    for pattern in pattern_k:
        pattern_values, pattern_vectors = np.linalg.eigh(pattern)
        loads += [pattern_vectors[:, index] for index in np.flatnonzero(
            np.abs(pattern_values) > 1e-12 * max(np.abs(pattern_values).max(), 1e-300))]
    loads += [*pattern_f, system.force, *(np.asarray(load, dtype=float) for load in extra)]
    columns = [modes]
    for load in loads:
        if not np.any(load):
            continue
        vector = solve(mean, load, assume_a="sym")
        scale = np.sqrt(vector @ mass @ vector)
        for _ in range(2):  # Gram–Schmidt twice against the columns so far (M inner product)
            basis = np.hstack(columns)
            vector = vector - basis @ (basis.T @ (mass @ vector))
        norm = np.sqrt(max(vector @ mass @ vector, 0.0))
        if norm > 1e-8 * scale:  # a correction already in the span adds nothing
            columns.append((vector / norm)[:, None])
    basis = np.hstack(columns)
    excited = _excited_columns(basis, system, extra)
    kept_modes = excited[:modes.shape[1]]
    return ModalBasis(basis[:, excited], int(kept_modes.sum()), float(cutoff), frequencies[kept_modes])


def _excited_columns(basis: np.ndarray, system: PiecewiseLinearSystem, extra: Sequence[np.ndarray] = ()
                     ) -> np.ndarray:
    """Mask of the basis columns that the loads reach: those the forces load directly, closed under every coupling
    of the reduced matrices (stiffness, damping with the gyroscopic terms, both patterns). The columns left out
    span an invariant subspace that starts at rest and is never forced, so their motion is identically zero and
    dropping them is exact (for a spur mesh: the axial modes and the bending out of the line of action's plane
    when no damping or gyroscopic term couples them)."""
    pattern_k, pattern_c, pattern_f = system.stacked()[:3]
    forces = [basis.T @ system.force, *(basis.T @ pattern for pattern in pattern_f),
              *(basis.T @ load for load in extra)]
    couplings = [basis.T @ matrix @ basis for matrix in (system.mass, system.stiffness, system.damping, *pattern_k,
                                                           *pattern_c)]
    excited = np.zeros(basis.shape[1], dtype=bool)
    for force in forces:
        excited |= np.abs(force) > 1e-12 * max(np.abs(force).max(), 1e-300)
    links = np.zeros((basis.shape[1], basis.shape[1]), dtype=bool)
    for matrix in couplings:
        links |= np.abs(matrix) > 1e-12 * max(np.abs(matrix).max(), 1e-300)
    while True:
        grown = excited | links[:, excited].any(axis=1)
        if grown.sum() == excited.sum():
            return grown
        excited = grown
