"""Two exact routes of :func:`~thermogear.dynamics.periodic_orbits.periodic_ndof.periodic_response` for large systems
and long runs of equal pieces: the periodic orbit solved on the coordinates the forces reach
(:func:`reached_coordinates`, :func:`on_reached`) and built run by run from powers of the pieces' exponentials
(:func:`by_runs`). Knows nothing of gears: matrices only.
"""

from __future__ import annotations

import numpy as np

from thermogear.dynamics.linear_algebra.monodromy_range import floquet, floquet_of_maps, uses_range
from thermogear.errors import ModelLimitError

__all__ = ["by_runs", "floquet", "on_reached", "reached_coordinates"]


def by_runs(system, steps, where: np.ndarray, starts: np.ndarray,
            samples: int) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """:func:`periodic_response` on runs of equal pieces (a k(τ) of a few levels on many intervals; every large
    system). ``steps``: the distinct pieces' sub-step exponentials (D, m, m), or their powers
    (:mod:`~thermogear.dynamics.linear_algebra.piece_powers`: each sub-step S_j = B_j^(n_j) of a common step). A run of
    L equal pieces of s sub-steps each is B_j^(n_j·L·s): the binary powers B, B², B⁴, … are formed once per distinct
    piece by squaring (log₂(n_j·L·s) products instead of L·s − 1), the monodromy is the product of one such power per
    run, and the sampled states of a run follow by doubling, [z, Sz] → [z, Sz, S²z, S³z] → …, each step one matrix
    product (n_j = 1) with all states found so far (Moler & Van Loan, SIAM Review 45 (2003) 3–49, §3, for the
    powers). Exact: only the order of the floating-point products differs from the block route. The multipliers
    and the periodic state come from the run maps as factors
    (:func:`~thermogear.dynamics.linear_algebra.monodromy_range.
    floquet_of_maps`: on a large system from the range of the monodromy, never formed)."""
    from thermogear.dynamics.linear_algebra.piece_powers import DensePowers, power_factors

    powers = DensePowers(steps) if isinstance(steps, np.ndarray) else steps
    lengths = np.diff(np.append(starts, where.size)) * samples
    pieces = where[starts]
    size = powers.power(0, 0).shape[0]
    # the range route multiplies the maps only into blocks of columns: there the highest power is left out and
    # applied twice (or three times), which costs less than its squaring (half a product against a full one)
    lean = uses_range(size - 1)
    tops = {}
    for piece in np.unique(pieces).tolist():
        longest = int(powers.multiples[piece]) * int(lengths[pieces == piece].max())
        tops[piece] = max((longest // 2 if lean else longest).bit_length() - 1, 0)

    def run_map(piece: int, count: int) -> list[np.ndarray]:
        """The run's map as factors (each applied after the one before): several on the range route, one matrix
        otherwise."""
        factors = power_factors(powers, piece, int(powers.multiples[piece]) * count, tops[piece])
        if lean:
            return factors
        total = factors[0]
        for factor in factors[1:]:
            total = factor @ total
        return [total]

    run_maps, cache = [], {}
    for piece, count in zip(pieces.tolist(), lengths.tolist()):
        if (piece, count) not in cache:
            cache[(piece, count)] = run_map(piece, count)
        run_maps.append(cache[(piece, count)])
    multipliers, initial = floquet_of_maps([factor for factors in run_maps for factor in factors])
    n = system.size
    states = np.empty((where.size * samples + 1, size))
    state, row = np.append(initial, 1.0), 0
    for piece, count, factors in zip(pieces.tolist(), lengths.tolist(), run_maps):
        found = state[None]
        multiple = int(powers.multiples[piece])
        while found.shape[0] < count:  # doubling with S, S², S⁴, …, then strides of the highest power
            level = min(int(found.shape[0]).bit_length() - 1, max(tops[piece] - multiple.bit_length() + 1, 0))
            stride, first = 2 ** level, found.shape[0] - 2 ** level
            block = found[first:first + min(stride, count - found.shape[0])]
            for factor in power_factors(powers, piece, multiple << level, tops[piece]):
                block = block @ factor.T
            found = np.vstack([found, block])
        states[row:row + count] = found[:count]
        row += count
        for factor in factors:
            state = factor @ state
    states[-1] = state
    if powers.scale is not None:  # the powers' balanced coordinates: z = D z_b
        states = states * powers.scale
        initial = initial * powers.scale[:-1]
    offsets = np.arange(samples) / samples
    time = np.concatenate([(system.nodes[:-1, None] + np.diff(system.nodes)[:, None] * offsets).ravel(),
                           [system.period]])
    return time, states[:, :n], states[:, n:2 * n], multipliers, initial


def _linked(matrix: np.ndarray, by_rows: bool = True) -> np.ndarray:
    """Entries of a matrix above rounding: |X_ij| > 1e-13·sqrt(r_i·r_j), r the largest magnitude of each row and
    column (a coupling left by the rounding of a projection is ~1e-16 of them); ``by_rows`` False: above 1e-13 of
    the largest entry (a pattern w wᵀ, whose rows may be rounding noise of a projection as a whole)."""
    magnitude = np.abs(matrix)
    if not by_rows:
        return magnitude > 1e-13 * max(float(magnitude.max()), 1e-300)
    scale = np.maximum(magnitude.max(axis=1), magnitude.max(axis=0))
    return magnitude > 1e-13 * np.sqrt(np.outer(scale, scale))


def reached_coordinates(system) -> np.ndarray:
    """Mask (n,) of the coordinates that the forces reach: those loaded by f₀ or the force pattern, closed under
    every coupling of M, K, C and the patterns. The others form a constant-coefficient block that starts nowhere
    and is never forced, so its periodic motion is zero (for a spur drivetrain: the axial DOFs). Solving on the
    reached coordinates only is exact and saves (m_reached/m)³ of the exponentials."""
    forces = np.abs(system.force) + np.abs(system.force_pattern)
    reached = forces > 1e-13 * max(forces.max(), 1e-300)
    links = np.zeros((system.size, system.size), dtype=bool)
    for name in ("mass", "stiffness", "damping"):
        links |= _linked(getattr(system, name))
    for name in ("stiffness_pattern", "damping_pattern"):
        links |= _linked(getattr(system, name), by_rows=False)
    while True:
        grown = reached | links[:, reached].any(axis=1)
        if grown.sum() == reached.sum():
            return grown
        reached = grown


def on_reached(system, reached: np.ndarray, solve) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray,
                                                              np.ndarray]:
    """``solve`` (the periodic response of a system) on the reached coordinates, the others at rest: (time,
    displacement, velocity, multipliers, initial state). The Floquet multipliers of the block left out, e^{λT} of
    its constant state matrix, join the reached block's."""
    from dataclasses import replace

    inside = np.ix_(reached, reached)
    reduced = replace(system, **{name: getattr(system, name)[inside] for name in (
        "mass", "stiffness", "damping", "stiffness_pattern", "damping_pattern")},
        force=system.force[reached], force_pattern=system.force_pattern[reached])
    others = ~reached
    outside = np.ix_(others, others)
    multipliers = np.zeros(0, dtype=complex)
    if others.any():
        count = int(others.sum())
        inverse = np.linalg.inv(system.mass[outside])
        state = np.block([[np.zeros((count, count)), np.eye(count)],
                          [-inverse @ system.stiffness[outside], -inverse @ system.damping[outside]]])
        multipliers = np.exp(np.linalg.eigvals(state) * system.period)
    radius = float(np.abs(multipliers).max()) if multipliers.size else 0.0
    if not np.isfinite(radius) or radius >= 1.0:
        raise ModelLimitError(f"a Floquet multiplier has modulus {radius:.6g} >= 1: parametric instability, an "
                              "undamped or a rigid-body mode; there is no attracting periodic orbit")
    response = solve(reduced)
    displacement = np.zeros((response.time.size, system.size))
    velocity = np.zeros_like(displacement)
    displacement[:, reached], velocity[:, reached] = response.displacement, response.velocity
    initial = np.zeros(2 * system.size)
    initial[np.concatenate([reached, reached])] = response.initial_state
    multipliers = np.concatenate([response.multipliers, multipliers])
    multipliers = multipliers[np.argsort(-np.abs(multipliers), kind="stable")]
    return response.time, displacement, velocity, multipliers, initial
