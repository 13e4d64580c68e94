"""Modal analysis of M q̈ + C q̇ + K q = 0 on matrices: undamped and damped modes, strain-energy shares, kinetic-
energy fractions. Knows nothing of gears.

Undamped: the symmetric-definite problem K φ = ω² M φ (scipy.linalg.eigh, M-normalised shapes φᵀMφ = 1).
Damped (or gyroscopic): the first-order form ż = A z, A = [[0, I], [−M⁻¹K, −M⁻¹C]]; each eigenvalue
λ = −ζω_n ± iω_d gives ω_n = |λ|, ζ = −Re λ/|λ|, ω_d = |Im λ| (e.g. Friswell et al., Dynamics of Rotating Machines,
CUP 2010, §2.5 and §3.6). Modal strain-energy share of element j in mode i: e_ij = φ_iᴴK_jφ_i / Σ_j φ_iᴴK_jφ_i
(Velex & Berthe 1989 use the mesh's share to single out the tooth-critical modes).
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass

import numpy as np

from thermogear.errors import ProblemError

__all__ = ["UndampedModes", "DampedModes", "undamped_modes", "damped_modes", "strain_energy_shares",
           "kinetic_energy_fractions"]


def _square(name: str, matrix: object, size: int | None = None) -> np.ndarray:
    array = np.asarray(matrix, dtype=float)
    if array.ndim != 2 or array.shape[0] != array.shape[1] or (size is not None and array.shape[0] != size):
        raise ProblemError(name, f"array of shape {array.shape}", "a square matrix matching the mass matrix",
                           "the matrices of one system share their DOFs")
    if not np.all(np.isfinite(array)):
        raise ProblemError(name, "non-finite entries", "finite numbers", "NaN has no physical meaning")
    return array


@dataclass(frozen=True, eq=False)
class UndampedModes:
    """Natural frequencies ω [rad/s] ascending (count,) and M-normalised shapes (DOFs, count)."""

    angular_frequencies: np.ndarray
    shapes: np.ndarray

    @property
    def frequencies_hz(self) -> np.ndarray:
        """f = ω/2π [Hz]."""
        return self.angular_frequencies / (2.0 * np.pi)


@dataclass(frozen=True, eq=False)
class DampedModes:
    """Eigenvalues λ (count,) with Im λ >= 0 (one per conjugate pair), sorted by ω_n; displacement shapes
    (DOFs, count) complex, each scaled to unit largest entry; ω_n [rad/s], ζ [-], ω_d [rad/s]."""

    eigenvalues: np.ndarray
    shapes: np.ndarray

    @property
    def natural_frequencies(self) -> np.ndarray:
        """ω_n = |λ| [rad/s]."""
        return np.abs(self.eigenvalues)

    @property
    def damping_ratios(self) -> np.ndarray:
        """ζ = −Re λ/|λ| [-]."""
        return -self.eigenvalues.real / np.abs(self.eigenvalues)

    @property
    def damped_frequencies(self) -> np.ndarray:
        """ω_d = |Im λ| [rad/s]."""
        return np.abs(self.eigenvalues.imag)


def undamped_modes(mass: np.ndarray, stiffness: np.ndarray, count: int | None = None) -> UndampedModes:
    """Solve K φ = ω² M φ; the lowest ``count`` modes (all by default). ProblemError if M is not positive definite
    or K has a negative eigenvalue below rounding (a zero one is a rigid-body mode and gives ω = 0)."""
    from scipy.linalg import LinAlgError, eigh

    mass = _square("mass", mass)
    stiffness = _square("stiffness", stiffness, mass.shape[0])
    subset = None if count is None else (0, min(count, mass.shape[0]) - 1)
    try:
        values, vectors = eigh(stiffness, mass, subset_by_index=subset)
    except LinAlgError as error:
        raise ProblemError("mass", "not positive definite", "a symmetric positive definite mass matrix",
                           f"every DOF needs inertia ({error})") from error
    floor = -1e-9 * max(abs(values).max(), 1.0)
    if values.min() < floor:
        raise ProblemError("stiffness", f"eigenvalue ω² = {values.min():.3g}", ">= 0",
                           "a stiffness matrix must be positive semi-definite")
    return UndampedModes(np.sqrt(np.clip(values, 0.0, None)), vectors)


def damped_modes(mass: np.ndarray, damping: np.ndarray, stiffness: np.ndarray,
                 zero_tolerance: float = 1e-6) -> DampedModes:
    """Eigenvalues of the state matrix; one of each conjugate pair (Im λ > 0) and the real ones, sorted by ω_n.
    Eigenvalues with |λ| below ``zero_tolerance`` [rad/s] (rigid-body modes) are dropped."""
    from scipy.linalg import eig, solve

    mass = _square("mass", mass)
    size = mass.shape[0]
    damping = _square("damping", damping, size)
    stiffness = _square("stiffness", stiffness, size)
    state = np.zeros((2 * size, 2 * size))
    state[:size, size:] = np.eye(size)
    state[size:, :size] = -solve(mass, stiffness, assume_a="pos")
    state[size:, size:] = -solve(mass, damping, assume_a="pos")
    values, vectors = eig(state)
    scale = np.abs(values).max() if values.size else 1.0
    keep = (values.imag > 1e-12 * scale) | ((np.abs(values.imag) <= 1e-12 * scale) & (values.real < 0))
    keep &= np.abs(values) > zero_tolerance
    values, shapes = values[keep], vectors[:size, keep]
    order = np.lexsort((values.imag, np.abs(values)))
    values, shapes = values[order], shapes[:, order]
    peak = shapes[np.abs(shapes).argmax(axis=0), np.arange(shapes.shape[1])]
    return DampedModes(values, shapes / peak)


def strain_energy_shares(shapes: np.ndarray, element_stiffness: Mapping[str, np.ndarray]) -> dict[str, np.ndarray]:
    """Share of each named stiffness matrix K_j in the strain energy of each mode (columns of ``shapes``):
    e_ij = φ_iᴴK_jφ_i / Σ_j φ_iᴴK_jφ_i; the shares of a mode add up to 1 (ProblemError for a rigid-body mode,
    which stores no strain energy)."""
    shapes = np.asarray(shapes)
    energies = {name: np.real(np.sum(shapes.conj() * (np.asarray(matrix, dtype=float) @ shapes), axis=0))
                for name, matrix in element_stiffness.items()}
    total = sum(energies.values())
    if np.any(total <= 0.0):
        raise ProblemError("shapes", "a mode with no strain energy", "elastic modes only",
                           "a rigid-body mode has no strain-energy shares")
    return {name: energy / total for name, energy in energies.items()}


def kinetic_energy_fractions(shapes: np.ndarray, mass: np.ndarray,
                             masks: Mapping[str, np.ndarray]) -> dict[str, np.ndarray]:
    """Kinetic-energy fraction of each masked DOF group per mode: φ_gᴴM_ggφ_g / φᴴMφ. They add up to 1 when the
    groups partition the DOFs and M does not couple them (shaft torsion, bending and axial motion are uncoupled)."""
    shapes = np.asarray(shapes)
    mass = np.asarray(mass, dtype=float)
    total = np.real(np.sum(shapes.conj() * (mass @ shapes), axis=0))
    fractions = {}
    for name, mask in masks.items():
        part = shapes[mask]
        fractions[name] = np.real(np.sum(part.conj() * (mass[np.ix_(mask, mask)] @ part), axis=0)) / total
    return fractions
