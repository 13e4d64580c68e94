"""The error of a periodic response solved on a modal cut-off: what the modes above the cut-off would change, from
the cut-off solution's own loads, without a second periodic solve. Knows nothing of gears: matrices only.

The system M q̈ + (C₀ + c_j P) q̇ + (K₀ + k_j P) q = f₀ + g_j v with rank-one patterns P = v vᵀ (one per mesh) is
written about its mean structure, K̄ = K₀ + k̄ P, C̄ = C₀ + c̄ P (k̄, c̄ the time means of the factors), in the
undamped modes φ_i, ω_i of (K̄, M) (M-orthonormal, Φ), with D = ΦᵀC̄Φ split into its diagonal d_i and the rest
D_off (non-proportional dampers, e.g. bearings, couple the modes):

    ÿ_i + d_i ẏ_i + ω_i² y_i = φ_iᵀ[f₀ + v·ℓ(t)] − (D_off ẏ)_i,   ℓ(t) = g(t) − (k(t) − k̄)·vᵀq − (c(t) − c̄)·vᵀq̇.

With the right-hand side read off the cut-off solution (its modal coordinates y, its mesh coordinate vᵀq) each
harmonic ω_h of the load F̂_h drives mode i exactly as F̂_h,i / z_i, z_i = ω_i² − ω_h² + iω_h d_i (Craig &
Kurdila, Fundamentals of Structural Dynamics, 2nd ed., Wiley 2006, §10.2 for the modal frequency response; §14.6
for the mode-acceleration and static-correction method). The reduced model holds the modes below the cut-off
exactly and, for those above, the static-correction columns Ψ, which lie in their span (each K̄⁻¹v made
M-orthogonal to the modes below: Ψ = Φ_d A, A = Φ_dᵀMΨ); the Galerkin projection of the same equations (the same
loads, by construction of the reduced solution) answers in that span with A (AᵀZA)⁻¹ AᵀF̂_h, Z = diag(z_i) — at
ω_h → 0 the static response, exact, as the static correction promises. The first error is therefore

    ê_h = [Z⁻¹ − A (AᵀZA)⁻¹ Aᵀ] F̂_h,d   on the dropped modes,

each dropped mode's dynamic part H_i − 1/ω_i² less what the correction columns' own dynamics carry (a single
dominant dropped mode that the correction spans is no error at all). The exact error e obeys the full system with
this as its source; one step of that feedback adds the error's own loads, −(k − k̄)·vᵀe − (c − c̄)·vᵀė along v
and −D_off ė, on every mode (Z⁻¹ on the modes below the cut-off too, where a resonance amplifies them: the
non-modal damping's coupling is what makes the error of ``fzg_rig_type_c``'s DTE 2.5× the first error). The mean
harmonic is static and exact. An estimate: first order in the error beyond that one step, the damping's diagonal
taken as each mode's own, and the solution read on a uniform grid by cubic Hermite interpolation; the tests
compare it with the true error against every mode.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from thermogear.dynamics.modes.modal_reduction import MeanModes, ModalBasis, factor_means
from thermogear.dynamics.periodic_orbits.periodic_ndof import PiecewiseLinearSystem
from thermogear.dynamics.results.spectra import right_continuous
from thermogear.errors import ProblemError

__all__ = ["TruncationError", "truncation_error"]

_HARMONICS_PER_BLOCK = 128  # harmonics per block of the piecewise transform (a few MB per block)


@dataclass(frozen=True, eq=False)
class TruncationError:
    """The estimated error history of a cut-off response on ``time`` (K,) uniform over one period [s]: the
    displacement error is ``shapes`` (n, d) @ ``amplitude`` (d, K) and its rate ``shapes`` @ ``rate``."""

    time: np.ndarray
    shapes: np.ndarray
    amplitude: np.ndarray
    rate: np.ndarray

    def observed(self, rows: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """(error, rate) (K, r) of the outputs y = R q for ``rows`` R (r, n) (one row per output, e.g. a DOF)."""
        projected = np.atleast_2d(rows) @ self.shapes
        return (projected @ self.amplitude).T, (projected @ self.rate).T


def _rank_one_vectors(system: PiecewiseLinearSystem) -> np.ndarray:
    """The vectors v_m (P, n) of patterns P_K = P_C = v vᵀ (the form the estimate assumes), else ProblemError."""
    pattern_k, pattern_c, pattern_f = system.stacked()[:3]
    for mesh, vector in enumerate(pattern_f):
        outer = np.outer(vector, vector)
        scale = max(np.abs(outer).max(), 1e-300)
        if np.abs(pattern_k[mesh] - outer).max() > 1e-9 * scale or np.abs(pattern_c[mesh] - outer).max() > 1e-9 * scale:
            raise ProblemError("stiffness_pattern", f"pattern {mesh}", "P_K = P_C = v vᵀ with v the force pattern",
                               "the truncation estimate carries each pattern's load along its vector v")
    return pattern_f


def _rank_one_terms(system: PiecewiseLinearSystem, stiffness_means: np.ndarray) -> tuple[np.ndarray, ...]:
    """(vectors v_r (R, n), stiffness, damping and force factors (N, R), stiffness means (R,)): the system's
    patterns as rank-one terms. Patterns P_K = P_C = v vᵀ with v the force pattern are taken as they are (one term
    each); otherwise (e.g. a mesh whose contact spreads across the face: w w_zᵀ + w_z wᵀ) each pattern P_K = P_C is
    split into its eigenvectors, P = Σ λ_r u_r u_rᵀ, each a term with factors λ_r·k and λ_r·c and no force, and each
    force pattern is a term of its own with force factor g and no stiffness: the load ℓ_r along v_r below is then
    the same sum, term by term (ProblemError where P_K ≠ P_C)."""
    pattern_k, pattern_c, pattern_f, factor_k, factor_c, factor_f = system.stacked()
    try:
        return _rank_one_vectors(system), factor_k, factor_c, factor_f, np.asarray(stiffness_means, dtype=float)
    except ProblemError:
        pass
    vectors, columns_k, columns_c, columns_f, means = [], [], [], [], []
    zero = np.zeros(factor_k.shape[0])
    for index, pattern in enumerate(pattern_k):
        scale = max(np.abs(pattern).max(), 1e-300)
        if np.abs(pattern_c[index] - pattern).max() > 1e-9 * scale:
            raise ProblemError("damping_pattern", f"pattern {index}", "P_C = P_K",
                               "the truncation estimate splits each pattern into rank-one terms of both")
        values, shapes = np.linalg.eigh(pattern)
        for value, shape in zip(values, shapes.T):
            if abs(value) > 1e-12 * scale:
                vectors.append(shape)
                columns_k.append(value * factor_k[:, index])
                columns_c.append(value * factor_c[:, index])
                columns_f.append(zero)
                means.append(value * stiffness_means[index])
        vectors.append(pattern_f[index])
        columns_k.append(zero)
        columns_c.append(zero)
        columns_f.append(factor_f[:, index])
        means.append(0.0)
    return (np.array(vectors), np.column_stack(columns_k), np.column_stack(columns_c), np.column_stack(columns_f),
            np.array(means))


def truncation_error(system: PiecewiseLinearSystem, basis: ModalBasis, modes: MeanModes, time: np.ndarray,
                     displacement: np.ndarray, velocity: np.ndarray) -> TruncationError:
    """The error (module docstring) of a periodic response of ``system`` solved on ``basis``, given by its
    ``displacement`` and ``velocity`` (S, n) [SI] at ``time`` (S,) [s] on [0, T] (the solver's samples: each piece's
    own, the period's end last); ``modes`` those of the mean system the basis was built on (it may be another
    speed's: its pattern means are used). The mesh load ℓ, which jumps with the factors, is transformed piece by
    piece (linear between the samples, each segment's integral against e^{−iωt} exact: no jump smeared onto a grid);
    the smooth modal coordinates on a uniform grid of S − 1 points (rounded up to even) by cubic Hermite
    interpolation."""
    vectors, factor_k, factor_c, factor_f, stiffness_means = _rank_one_terms(system, modes.stiffness_means)
    time = np.asarray(time, dtype=float)
    points = max(4, 2 * (time.size // 2))  # the samples' count, even (one period's samples less its end)
    grid = np.arange(points) * (system.period / points)
    omega = 2.0 * np.pi * np.arange(points // 2 + 1) / system.period
    sampled, sampled_rate = _on_uniform_grid(time, displacement, velocity, grid)
    modal_rate = np.fft.rfft(modes.shapes.T @ system.mass @ sampled_rate, axis=1).T  # (H, n): the modal rates
    damping_means = factor_means(factor_c, system)
    pattern_damping_means = factor_means(system.stacked()[4], system)
    coordinate = np.asarray(displacement, dtype=float) @ vectors.T  # (S, P): vᵀq at the samples
    rate = np.asarray(velocity, dtype=float) @ vectors.T
    # ℓ on each segment between samples, with the factors of the piece the segment lies in
    middle = 0.5 * (time[:-1] + time[1:])
    piece = np.clip(np.searchsorted(system.nodes, middle, side="right") - 1, 0, system.nodes.size - 2)

    def segment_load(at: slice) -> np.ndarray:
        return (factor_f[piece] - (factor_k[piece] - stiffness_means) * coordinate[at]
                - (factor_c[piece] - damping_means) * rate[at])

    load = _piecewise_linear_transform(time, segment_load(slice(0, -1)), segment_load(slice(1, None)), omega,
                                       points / system.period)  # ℓ̂ (H, P), the rfft's scale
    # the factors on the grid for the error's own load (second order): the mean of the two sides at a node
    after = np.clip(np.searchsorted(system.nodes, grid, side="right") - 1, 0, system.nodes.size - 2)
    before = (np.searchsorted(system.nodes, grid, side="left") - 1) % (system.nodes.size - 1)
    stiffness_change = 0.5 * (factor_k[before] + factor_k[after]) - stiffness_means
    damping_change = 0.5 * (factor_c[before] + factor_c[after]) - damping_means
    mean_damping = system.damping + np.einsum("m,mij->ij", pattern_damping_means, system.stacked()[1])
    coupling = modes.shapes.T @ mean_damping @ modes.shapes  # D = ΦᵀC̄Φ
    modal_damping = np.diag(coupling).copy()
    np.fill_diagonal(coupling, 0.0)  # D_off: the damping's coupling between modes, carried as a load
    z = modes.frequencies[None, :] ** 2 - omega[:, None] ** 2 + 1j * omega[:, None] * modal_damping[None, :]
    participation = vectors @ modes.shapes  # (P, n): vᵀφ_i
    forcing = load @ participation - modal_rate @ coupling.T  # Φᵀ(vℓ̂ − C_off q̂̇) (H, n)
    dropped = modes.dropped
    error = np.zeros(z.shape, dtype=complex)
    error[:, dropped] = forcing[:, dropped] / z[:, dropped]
    corrections = modes.shapes[:, dropped].T @ (system.mass @ basis.basis[:, basis.mode_count:])  # A (d, k)
    if corrections.shape[1]:
        galerkin = np.einsum("ia,hi,ib->hab", corrections, z[:, dropped], corrections)
        error[:, dropped] -= (np.linalg.solve(galerkin, (forcing[:, dropped] @ corrections)[..., None])[..., 0]
                              @ corrections.T)
    error[0] = 0.0  # the mean is static: the static corrections keep it exact
    # one step of the coupling: the first error's damping force on every mode, and its mesh load
    error_coordinate = np.fft.irfft(error @ participation.T, n=points, axis=0)
    error_rate = np.fft.irfft(1j * omega[:, None] * (error @ participation.T), n=points, axis=0)
    error_load = np.fft.rfft(-stiffness_change * error_coordinate - damping_change * error_rate, axis=0)
    error = error + (error_load @ participation - 1j * omega[:, None] * (error @ coupling.T)) / z
    amplitude = np.fft.irfft(error.T, n=points, axis=1)
    velocity_error = np.fft.irfft(1j * omega[None, :] * error.T, n=points, axis=1)
    return TruncationError(grid, modes.shapes, amplitude, velocity_error)


def _piecewise_linear_transform(time: np.ndarray, start: np.ndarray, end: np.ndarray, omega: np.ndarray,
                                scale: float) -> np.ndarray:
    """scale·∫ x(t) e^{−iωt} dt (H, P) over one period of x linear on each segment [t_s, t_s+1] from ``start`` to
    ``end`` (S − 1, P), ``omega`` the harmonics h·ω₁ of the period (Filon's rule of degree one: each segment's
    integral exact; a segment of zero width adds nothing). Integrated by parts over the periodic x, only its jumps
    J_k and its slope's changes β_k at the samples remain: ∫ = Σ_k e^{−iωt_k} (J_k/(iω) + β_k/ω²) for ω > 0, the
    powers e^{−ihω₁t_k} formed by repeated products (no exponential per harmonic)."""
    width = np.diff(time)
    end = np.where(width[:, None] > 0.0, end, start)  # a segment of zero width: no jump inside it
    result = np.zeros((omega.size, start.shape[1]), dtype=complex)
    result[0] = scale * (0.5 * width) @ (start + end)
    if omega.size == 1:
        return result
    slope = np.divide(end - start, width[:, None], out=np.zeros_like(start), where=width[:, None] > 0.0)
    count = start.shape[1]
    jumps = np.hstack([start - np.roll(end, 1, axis=0),  # at t_k (k = 0: the period's end folded onto its start)
                       np.roll(slope, 1, axis=0) - slope]).astype(complex)  # (S − 1, 2P): J_k, β_k
    step = np.exp(-1j * omega[1] * time[:-1])  # e^{−iω₁t_k}
    powers = np.empty((_HARMONICS_PER_BLOCK, step.size), dtype=complex)
    powers[-1] = 1.0
    for first in range(1, omega.size, _HARMONICS_PER_BLOCK):
        rows = min(_HARMONICS_PER_BLOCK, omega.size - first)
        np.multiply(powers[-1], step, out=powers[0])
        for row in range(1, rows):  # e^{−ihω₁t_k} = e^{−i(h−1)ω₁t_k}·e^{−iω₁t_k}
            np.multiply(powers[row - 1], step, out=powers[row])
        if rows < _HARMONICS_PER_BLOCK:
            powers = powers[:rows]
        sums = powers @ jumps
        frequency = omega[first:first + rows, None]
        result[first:first + rows] = scale * (sums[:, :count] / (1j * frequency) + sums[:, count:] / frequency**2)
    return result


def _on_uniform_grid(time: np.ndarray, displacement: np.ndarray, velocity: np.ndarray,
                     grid: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """(q, q̇) (n, K) on the uniform ``grid`` from the samples (S, n) at ``time``: the cubic Hermite interpolant of
    q and q̇ (SciPy's ``CubicHermiteSpline``, third order) and its derivative, read right-continuously at a jump."""
    from scipy.interpolate import CubicHermiteSpline

    kept_time, values = right_continuous(time, np.asarray(displacement, dtype=float).T)
    rates = right_continuous(time, np.asarray(velocity, dtype=float).T)[1]
    spline = CubicHermiteSpline(kept_time, values, rates, axis=1)
    return spline(grid), spline(grid, 1)
