"""Floquet multipliers and the periodic state of a large system from the range of its monodromy, without forming
the monodromy or taking the eigenvalues of the full matrix.

The one-period map of a structural model with many strongly damped modes has low numerical rank: a mode that
decays by e^{−σT} < 1e-16 over the period leaves no trace in Φ_T (on a 409-DOF geared rotor, 238 of its 818
singular values lie above 1e-16 of the largest). Where Φ_T = X_{L−1}···X₀ is given as a product of maps (the
runs of :func:`~thermogear.dynamics.periodic_orbits.periodic_runs.by_runs`), its range is found by the randomized range
finder (Halko, Martinsson & Tropp, "Finding structure with randomness", SIAM Review 53 (2011) 217–288, Algorithm 4.2):
Y = Φ_T G for a Gaussian block G, Q an orthonormal basis of Y, grown block by block until the a-posteriori bound
of their §4.3,

    ‖(I − QQᵀ)Φ_T‖ ≤ 10·√(2/π)·max_i ‖(I − QQᵀ)Φ_T g_i‖    (probability ≥ 1 − 10⁻¹⁰ over ten probes g_i),

lies below :data:`RANGE_TOLERANCE` of ‖Φ_T‖ (estimated from the same products). Then Φ_T = QQᵀΦ_T + R with
‖R‖ ≤ tol·‖Φ_T‖, and

- the multipliers are the eigenvalues of the small matrix T = Qᵀ Φ_T Q (those of QQᵀΦ_T are these and zeros):
  the eigenvalues of Φ_T + E with ‖E‖ ≤ tol·‖Φ_T‖, the same backward error as a dense eigensolver's, up to the
  factor tol/ε; a multiplier below tol·‖Φ_T‖ is reported as 0 (a dense solver gives rounding noise there);
- the periodic state z₀ = Φ_T z₀ + p has z₀ − p = Φ_T z₀ in the range, z₀ = p + Q c with (I − T) c = Qᵀ Φ_T p,
  refined by residual steps with the exact operator (each costs one product with the maps) until the residual
  of z₀ = Φ_T z₀ + p is at rounding level: z₀ is then that of the dense solve.

The work is a few products of the maps with blocks of k ≈ rank columns instead of the L − 1 dense products, the
(2n)³ eigenvalue problem and the dense solve. The system is balanced first (an exact diagonal similarity of the
first map): displacements and velocities differ by the frequencies, and the tolerance is meant relative to the
balanced map (a few vectorised sweeps of the Parlett–Reinsch scaling: any scaling gives the same result, it only
sets what the tolerance is relative to). Where the rank exceeds :data:`LARGEST_RANK_SHARE` of the size, the dense
product and eigenvalues are taken instead (:func:`floquet`). The random blocks come from a fixed seed: the result
does not change between runs. Knows nothing of gears: matrices only.
"""

from __future__ import annotations

import numpy as np

from thermogear.errors import ModelLimitError

__all__ = ["LARGEST_RANK_SHARE", "RANGE_TOLERANCE", "floquet", "floquet_of_maps", "uses_range"]

#: Bound on ‖(I − QQᵀ)Φ_T‖ / ‖Φ_T‖ (balanced) of the range found.
RANGE_TOLERANCE = 1e-13
#: Above this share of the size the range finder stops and the dense route is taken.
LARGEST_RANK_SHARE = 0.45
_PROBES = 10
_FIRST_BLOCK = 160
_BLOCK = 32
_SEED = 20110517  # any fixed seed: the result is the same to the tolerance for every seed


def floquet(total: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """(multipliers largest first, z₀) of the augmented one-period map (formed: the dense route); ModelLimitError
    where |μ| >= 1."""
    transition, image = total[:-1, :-1], total[:-1, -1]
    multipliers = np.linalg.eigvals(transition)
    multipliers = multipliers[np.argsort(-np.abs(multipliers))]
    _unstable(float(np.abs(multipliers).max()))
    return multipliers, np.linalg.solve(np.eye(transition.shape[0]) - transition, image)


def _dense(maps: list[np.ndarray]) -> tuple[np.ndarray, np.ndarray]:
    total = maps[0]
    for matrix in maps[1:]:
        total = matrix @ total
    return floquet(total)


def _unstable(radius: float) -> None:
    if not np.isfinite(radius) or radius >= 1.0:
        raise ModelLimitError(f"a Floquet multiplier has modulus {radius:.6g} >= 1: parametric instability, an "
                              "undamped or a rigid-body mode; there is no attracting periodic orbit")


def _balancing_scale(matrix: np.ndarray, sweeps: int = 4) -> np.ndarray:
    """Diagonal d (powers of 2) with D⁻¹XD of more even row and column 1-norms: ``sweeps`` simultaneous passes
    of the Parlett–Reinsch step d_i ← d_i·√(c_i/r_i) (Numer. Math. 13 (1969) 293–304), at O(m²) each instead of
    gebal's row-by-row iteration to convergence. Only a scaling of the tolerance: any d gives the same result."""
    magnitude = np.abs(matrix)
    np.fill_diagonal(magnitude, 0.0)
    scale = np.ones(matrix.shape[0])
    for _ in range(sweeps):  # row and column sums of |D⁻¹XD| as two products with vectors
        rows, columns = (magnitude @ scale) / scale, (magnitude.T @ (1.0 / scale)) * scale
        usable = (rows > 0.0) & (columns > 0.0)
        step = np.ones_like(scale)
        step[usable] = 2.0 ** np.round(0.5 * np.log2(rows[usable] / columns[usable]))
        if np.all(step == 1.0):
            break
        scale *= step
    return scale


def uses_range(size: int) -> bool:
    """Whether :func:`floquet_of_maps` tries the range of the monodromy for a state of this size (else it takes
    the dense product and eigenvalues)."""
    return int(LARGEST_RANK_SHARE * size) >= _FIRST_BLOCK


def floquet_of_maps(maps: list[np.ndarray]) -> tuple[np.ndarray, np.ndarray]:
    """(multipliers (m,) largest modulus first, z₀ (m,)) of the augmented one-period map X_{L−1}···X₀ given as its
    factors ``maps`` ((m+1)², each [[Φ_i, p_i], [0, 1]]), by the range of the monodromy (module docstring).
    ModelLimitError where a multiplier has modulus >= 1."""
    size = maps[0].shape[0] - 1
    limit = int(LARGEST_RANK_SHARE * size)
    if not uses_range(size):
        return _dense(maps)
    scale = _balancing_scale(maps[0][:-1, :-1])
    scaled = np.append(scale, 1.0)  # Φ_b = D⁻¹ Φ D; the forcing column stays in the original units over D

    transitions = [matrix[:-1, :-1] for matrix in maps]  # views: the products skip the forcing row and column

    def apply(block: np.ndarray, forced: bool = False) -> np.ndarray:
        """Φ_b·block (m, c) (``forced``: the augmented map of the balanced state, [Φ_b x + D⁻¹p])."""
        if not forced:
            state = block * scale[:, None]
            for matrix in transitions:
                state = matrix @ state
            return state / scale[:, None]
        state = np.vstack([block * scale[:, None], np.ones((1, block.shape[1]))])
        for matrix in maps:
            state = matrix @ state
        return state[:-1] / scale[:, None]

    generator = np.random.default_rng(_SEED)
    probes = apply(generator.standard_normal((size, _PROBES)))
    width = _FIRST_BLOCK
    basis = np.zeros((size, 0))
    norm = 0.0
    while True:
        block = apply(generator.standard_normal((size, width)))
        if not norm:  # ‖Φ G‖₂ ≈ σ₁·√width for a Gaussian G (its top singular direction gets √width of it)
            norm = float(np.linalg.norm(block, 2)) / np.sqrt(width)
        for _ in range(2):  # block Gram–Schmidt and normalisation, twice: a block left at the rounding level of
            block -= basis @ (basis.T @ block)  # the range by the first pass is orthogonal only after the second
            block, _ = np.linalg.qr(block)
        basis = np.hstack([basis, block])
        probes -= block @ (block.T @ probes)
        bound = 10.0 * np.sqrt(2.0 / np.pi) * float(np.linalg.norm(probes, axis=0).max())
        if bound <= RANGE_TOLERANCE * norm:
            break
        if basis.shape[1] + _BLOCK > limit:
            return _dense(maps)
        width = _BLOCK
    image = apply(basis)
    small = basis.T @ image
    multipliers = np.linalg.eigvals(small)
    multipliers = np.concatenate([multipliers[np.argsort(-np.abs(multipliers))],
                                  np.zeros(size - multipliers.size, dtype=complex)])
    _unstable(float(np.abs(multipliers[0])))
    inverse = np.linalg.inv(np.eye(small.shape[0]) - small)
    start = apply(np.zeros((size, 1)), forced=True)[:, 0]  # D⁻¹p
    state = start + basis @ (inverse @ (basis.T @ apply(start[:, None])[:, 0]))
    for _ in range(3):  # residual steps with the exact map: z₀ to rounding
        residual = apply(state[:, None], forced=True)[:, 0] - state
        state = state + residual + basis @ (inverse @ (basis.T @ apply(residual[:, None])[:, 0]))
        if np.linalg.norm(residual) <= 1e-15 * np.linalg.norm(state):
            break
    return multipliers, state * scale
