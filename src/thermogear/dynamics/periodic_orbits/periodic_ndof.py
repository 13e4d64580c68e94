"""Exact periodic steady state of an n-DOF linear time-periodic system with piecewise-constant coefficients.

M q̈ + C_j q̇ + K_j q = f_j on piece j, t in [t_j, t_{j+1}), of one period T = t_N. With z = [q; q̇] the piece is
ż = A_j z + b_j, A_j = [[0, I], [−M⁻¹K_j, −M⁻¹C_j]], b_j = [0; M⁻¹f_j], solved exactly by the exponential of the
augmented matrix (Van Loan, "Computing integrals involving the matrix exponential", IEEE TAC 23 (1978) 395–404):

    expm([[A_j, b_j], [0, 0]]·h_j) = [[Φ_j, p_j], [0, 1]],   z(t_{j+1}) = Φ_j z(t_j) + p_j.

The monodromy Φ_T = Φ_{N−1}···Φ_0 and the image p of z = 0 after one period give the periodic state
z₀ = (I − Φ_T)⁻¹ p, unique and attracting iff every Floquet multiplier (eigenvalue of Φ_T) lies inside the unit
circle (Floquet 1883; Nayfeh & Mook, Nonlinear Oscillations, 1979, §5.2). The exponentials of all pieces are
taken in one vectorised pass (:mod:`thermogear.dynamics.linear_algebra.batched_exponential`): pieces equal within a
relative 1e-9 once (:mod:`thermogear.dynamics.linear_algebra.piece_groups`, which bounds the effect), and pieces that
differ only through low-rank patterns as rank updates of the mean one (``_piece_steps``). The monodromy is the product
of √N blocks, blocks of the same pieces multiplied once, and the states at the nodes follow from the block products
(``_blocks``); long runs of equal pieces and large systems take the run route instead, on the coordinates the
forces reach (:mod:`thermogear.dynamics.periodic_orbits.periodic_runs`); z₀ is one linear solve. Knows
nothing of gears: matrices only. With a rigid-body mode (K r = 0) a multiplier is 1 and I − Φ_T is singular:
remove such modes first (``rigid_body.rigid_body_reduction``).

``K_j = K₀ + k_j·P_K``, ``C_j = C₀ + c_j·P_C`` and ``f_j = f₀ + g_j·P_f``: a constant part plus a pattern scaled per piece
(a gear mesh: P_K = P_C = w wᵀ, P_f = w), which is how the pieces are stored. Several meshes (a gear train) give a
sum over patterns, ``K_j = K₀ + Σ_m k_jm·P_K,m`` and likewise for C and f: the patterns are then stacked (P, n, n),
(P, n) and the factors (N, P), one column per mesh, over the train's common period.
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np

from thermogear.dynamics.linear_algebra.modal_chain import modal_basis
from thermogear.dynamics.linear_algebra.matrix_chains import (block_products as _blocks, ordered_product,
                                                              power as _power, states_at_nodes as _orbit_nodes)
from thermogear.dynamics.linear_algebra.piece_groups import PIECE_TOLERANCE, group_rows
from thermogear.dynamics.linear_algebra.sub_steps import DenseSteps, PartedSteps
from thermogear.dynamics.periodic_orbits.periodic_runs import by_runs, floquet, on_reached, reached_coordinates
from thermogear.dynamics.problems.piecewise_system import PiecewiseLinearSystem
from thermogear.errors import ProblemError

__all__ = ["RUN_ROUTE_SIZE", "PiecewiseLinearSystem", "PeriodicResponse", "chunked_transitions", "grouped_pieces",
           "monodromy", "ordered_product", "periodic_response", "piece_steps"]


@dataclass(frozen=True, eq=False)
class PeriodicResponse:
    """The periodic orbit: ``time`` (S,) [s] with ``samples_per_piece`` equal steps per piece plus the period's
    end; ``displacement``, ``velocity`` (S, n); Floquet ``multipliers`` (2n,) complex, largest modulus first;
    ``initial_state`` z₀ (2n,)."""

    time: np.ndarray
    displacement: np.ndarray
    velocity: np.ndarray
    multipliers: np.ndarray
    initial_state: np.ndarray

    @property
    def spectral_radius(self) -> float:
        """max |μ| [-] (< 1: stable)."""
        return float(np.abs(self.multipliers).max())


def _mass_inverse(system: PiecewiseLinearSystem) -> np.ndarray:
    from scipy.linalg import LinAlgError, cho_factor, cho_solve

    try:
        factor = cho_factor(system.mass)
    except LinAlgError as error:
        raise ProblemError("mass", "not positive definite", "a symmetric positive definite matrix",
                           "every DOF needs inertia") from error
    return cho_solve(factor, np.eye(system.size))


def _piece_steps(system: PiecewiseLinearSystem, samples: int,
                 tolerance: float = PIECE_TOLERANCE) -> tuple[np.ndarray, np.ndarray]:
    """(D, 2n+1, 2n+1) exponentials of the D distinct augmented pieces over one sub-step h_j/samples each, and the
    index (N,) of each piece's among them.

    Two economies. Pieces with the same (h_j, k_j, c_j, g_j) within ``tolerance`` (relative to each column's
    largest magnitude: :func:`~thermogear.dynamics.linear_algebra.piece_groups.group_rows`, whose docstring bounds the
    effect) share one exponential, taken once (a square-wave or piecewise-constant k(τ) of a few levels needs a few
    exponentials for any number of pieces, also where a table repeats its levels only to the last bits).
    When the patterns have low rank r (a gear mesh: r = 1, everything acts through w), every piece is the mean matrix
    plus a rank-r term, and :func:`~thermogear.dynamics.linear_algebra.batched_exponential.expm_of_rank_updates` forms
    all of them at O(r·n²)
    each instead of the O(n³) of a full Taylor polynomial
    (:func:`~thermogear.dynamics.linear_algebra.batched_exponential.batched_expm`); below ``_RANK_ROUTE_PIECES``
    distinct pieces the full exponentials cost little and keep Al-Mohy & Higham's tighter scaling, so they are used.
    """
    distinct, where = grouped_pieces(system, samples, tolerance)
    return _exponentials(system, distinct), where


def grouped_pieces(system: PiecewiseLinearSystem, samples: int,
                 tolerance: float = PIECE_TOLERANCE) -> tuple[np.ndarray, np.ndarray]:
    """(distinct rows (D, 1 + 3P) of (sub-step width h_j/``samples`` [s], k_j, c_j, g_j), the index (N,) of each
    piece's row among them): the pieces grouped as :func:`_piece_steps` groups them (``tolerance``: see there)."""
    widths = np.diff(system.nodes) / samples
    factor_k, factor_c, factor_f = system.stacked()[3:]
    return group_rows(np.column_stack([widths, factor_k, factor_c, factor_f]), tolerance)


def _exponentials(system: PiecewiseLinearSystem, distinct: np.ndarray,
                  operators: tuple[np.ndarray, np.ndarray] | None = None, powers: bool = False):
    """(D, 2n+1, 2n+1) exponentials e^{A_j h_j} of the augmented pieces whose rows (h_j, k_j, c_j, g_j) are
    ``distinct`` (:func:`grouped_pieces`; the routes: :func:`_piece_steps`); ``operators`` (M⁻¹, the patterns' range).
    ``powers``: for a few large pieces over commensurate durations, the powers of their common step instead
    (:class:`~thermogear.dynamics.linear_algebra.shared_pade.SharedPowers`, which the run route continues: no sub-step
    exponential and its squarings formed apart)."""
    from thermogear.dynamics.linear_algebra.batched_exponential import batched_expm, expm_of_rank_updates

    route = _rank_route(system, distinct, operators)
    if route is not None:
        return expm_of_rank_updates(*route)
    inverse, full_range = operators or (_mass_inverse(system), None)
    units = _with_factors(system, distinct).augmented_stack(inverse)
    if 2 * system.size + 1 >= _SINGLE_ROUTE_SIZE:  # a few large pieces: one Padé evaluation, or each by itself
        return _large_pieces(system, units, distinct[:, 0], inverse, full_range, powers)
    return batched_expm(units * distinct[:, :1, None])


def _rank_route(system: PiecewiseLinearSystem, distinct: np.ndarray,
                operators: tuple[np.ndarray, np.ndarray] | None = None,
                least_pieces: int | None = None, mean: tuple[np.ndarray, np.ndarray] | None = None) -> tuple | None:
    """The arguments (X₀, U, C, t, V) of :func:`~thermogear.dynamics.linear_algebra.batched_exponential.
    expm_of_rank_updates` for the pieces ``distinct`` (``mean``: X₀'s factors and X₀; default their mean's), or None
    where they take the full exponentials (fewer than ``least_pieces`` pieces, default :data:`_RANK_ROUTE_PIECES`, or
    patterns of high rank: :func:`_piece_steps`)."""
    n = system.size
    if distinct.shape[0] < max(1, _RANK_ROUTE_PIECES if least_pieces is None else least_pieces):
        return None
    inverse, full_range = operators or (_mass_inverse(system), None)
    range_basis = _pattern_range(system) if full_range is None else full_range
    rank = range_basis.shape[1]
    if rank == 0 or rank * _RANK_ROUTE_RATIO > 2 * n + 1:
        return None
    pattern_k, pattern_c, pattern_f = system.stacked()[:3]
    mean_factors, mean = (distinct[:, 1:].mean(axis=0), None) if mean is None else mean
    mean = _with_factors(system, np.append(1.0, mean_factors)[None]).augmented_stack(inverse)[0] if mean is None else mean
    left = np.zeros((2 * n + 1, range_basis.shape[1]))
    left[n:2 * n] = inverse @ range_basis
    shift = distinct[:, 1:] - mean_factors
    meshes = pattern_k.shape[0]
    rows = np.zeros((3 * meshes * rank, 2 * n + 1))  # the stiffness, damping and excitation rows, r per mesh
    for mesh in range(meshes):
        rows[mesh * rank:(mesh + 1) * rank, :n] = range_basis.T @ pattern_k[mesh]
        rows[(meshes + mesh) * rank:(meshes + mesh + 1) * rank, n:2 * n] = range_basis.T @ pattern_c[mesh]
        rows[(2 * meshes + mesh) * rank:(2 * meshes + mesh + 1) * rank, 2 * n] = range_basis.T @ pattern_f[mesh]
    signs = (-1.0,) * (2 * meshes) + (1.0,) * meshes  # columns of shift: k per mesh, c per mesh, g per mesh
    right = np.concatenate([np.eye(rank) * sign * shift[:, column, None, None]
                            for column, sign in enumerate(signs)], axis=2)  # (D, r, 3Pr)
    return mean, left, right, distinct[:, 0], rows


def _transitions(system: PiecewiseLinearSystem, distinct: np.ndarray, operators, which: np.ndarray,
                 dense: bool = True, modal=None, wholes: bool = False) -> DenseSteps | PartedSteps | None:
    """The exponentials of the pieces ``distinct`` (each piece of a chunk: ``which``) as their parts
    (:class:`~thermogear.dynamics.linear_algebra.sub_steps.PartedSteps`, O(q·m) numbers a piece) where the rank-update
    route takes them without squarings (any number of pieces: the parts are what is kept, not the matrices' cost), else
    as matrices (:class:`~thermogear.dynamics.linear_algebra.sub_steps.DenseSteps`; None without ``dense``). ``modal``
    (an eigenbasis of a piece X₀, (X₀'s factors, X₀)): the parts about X₀, their chain in its basis and
    their shared exponentials from it (none for ``wholes``, which only chain)."""
    from thermogear.dynamics.linear_algebra.batched_exponential import RankUpdateExponentials, rank_update_parts

    basis, mean = modal if modal is not None else (None, None)
    route = _rank_route(system, distinct, operators, least_pieces=1, mean=mean)
    if route is not None and basis is not None:  # the shared exponentials from the basis (the wholes need none)
        parts = rank_update_parts(*route, shared=False)
        if isinstance(parts, RankUpdateExponentials) and not parts.squarings:
            shared = None if wholes else np.stack([basis.exponential(time, parts.scale) for time in parts.times])
            return PartedSteps(replace(parts, exponentials=shared), which, basis)
    parts = None if route is None else rank_update_parts(*route)
    if isinstance(parts, RankUpdateExponentials) and not parts.squarings:
        return PartedSteps(parts, which)
    if not dense:
        return None
    if parts is None:
        return DenseSteps(_exponentials(system, distinct, operators), which)
    return DenseSteps(parts if isinstance(parts, np.ndarray) else parts.matrices(), which)


def _large_pieces(system: PiecewiseLinearSystem, units: np.ndarray, durations: np.ndarray, inverse: np.ndarray,
                  full_range: np.ndarray | None, powers: bool = False):
    """e^{A_j τ_j} of a few large pieces (unit-width augmented ``units``, ``durations`` τ_j): over commensurate
    durations from one Padé evaluation and rank updates through the patterns' range (:mod:`~thermogear.dynamics.
    shared_pade`; with ``powers`` as their :class:`~thermogear.dynamics.linear_algebra.shared_pade.SharedPowers`),
    otherwise each by itself with scipy's Padé-13 scaling and squaring (Al-Mohy & Higham 2009)."""
    from scipy.linalg import expm

    shared = _shared_powers(system, units, durations, inverse, full_range)
    if shared is not None:
        return shared if powers else shared.sub_steps()
    return np.stack([expm(matrix * duration) for matrix, duration in zip(units, durations)])


def _shared_powers(system: PiecewiseLinearSystem, units: np.ndarray, durations: np.ndarray, inverse: np.ndarray,
                   full_range: np.ndarray | None):
    """The pieces' powers from one Padé evaluation
    (:func:`~thermogear.dynamics.linear_algebra.shared_pade.shared_piece_powers`) through the force patterns' span or,
    where the differences do not lie in it, the range of every pattern; None
    where the pieces are not commensurate rank updates of each other (or there is one piece)."""
    from thermogear.dynamics.linear_algebra.shared_pade import shared_piece_powers

    n = system.size
    # the force patterns' span first (a mesh: P_K = P_C = w wᵀ, P_f = w; the differences are checked to lie in
    # it), the range of every pattern (an SVD) where they do not
    candidates = [np.linalg.qr(system.stacked()[2].T)[0], lambda: _pattern_range(system) if full_range is None
                  else full_range]
    for candidate in candidates if units.shape[0] > 1 else ():
        basis = candidate() if callable(candidate) else candidate
        left = np.zeros((2 * n + 1, basis.shape[1]))
        left[n:2 * n] = inverse @ basis
        left_inverse = np.zeros((basis.shape[1], 2 * n + 1))
        left_inverse[:, n:2 * n] = basis.T @ system.mass
        shared = shared_piece_powers(units, left, left_inverse, durations)
        if shared is not None:
            return shared
    return None


def piece_steps(system: PiecewiseLinearSystem, samples: int) -> tuple[np.ndarray, np.ndarray]:
    """(D, 2n+1, 2n+1) exponentials of the D distinct augmented pieces over one sub-step h_j/``samples`` each, and
    the index (N,) of each piece's among them (equal pieces once, the others as rank updates of the mean piece:
    ``_piece_steps``). For other solvers of piecewise-linear flows (the backlash pieces of each contact state)."""
    return _piece_steps(system, samples)


# The rank-update route costs about 6·d·r·m² per piece (Krylov products and the rank-(d·r) sum, d ≈ 15 terms; m = 2n+1)
# against about 12·m³ for the full Taylor polynomial (six products of 2m³): it pays from m ≈ 7.5·r, hence r ≤ m/8.
# Below 16 distinct pieces the full exponentials take well under a millisecond and keep the tighter scaling.
_RANK_ROUTE_PIECES = 16
_RANK_ROUTE_RATIO = 8
# From this state size on (about 200 DOF) a few distinct pieces are exponentiated one by one with scipy's Padé-13
# scaling and squaring (Al-Mohy & Higham, SIAM J. Matrix Anal. Appl. 31 (2009) 970–989): its wider scaling
# threshold (θ₁₃ = 5.37 against the Taylor stack's 0.5) saves about three squarings of a large matrix, measured
# 1.0 s against 1.35 s on a 985-square piece (one BLAS thread).
_SINGLE_ROUTE_SIZE = 401
# Above this augmented size (about 100 DOF) the orbit is always built run by run: the stacks of the block route hold
# a matrix per piece (N·m² numbers: 5 GB for 1000 pieces of 800 coordinates).
RUN_ROUTE_SIZE = 201
# Above this size of one stack of every distinct piece's (2n+1)² matrix [bytes] the orbit is built chunk by chunk
# (``_by_chunks``): the block route holds several such stacks at once (the sub-steps, their powers, the padded
# blocks, the tree's levels: 1.3 GB for the 1024 pieces of an 83-coordinate drivetrain, each freshly allocated, so
# that filling memory cost as much time as multiplying), the chunked route one chunk of matrices.
LEAN_ROUTE_BYTES = 32 * 2**20
CHUNK_BYTES = 16 * 2**20  # one chunk's matrices (75 pieces of 167 × 167): few chunks, small temporaries
# The chunked route's whole pieces multiplied in the real eigenbasis of one mean piece where its guard trusts it
# (:mod:`~thermogear.dynamics.linear_algebra.modal_chain`, O(q·m²) a piece; only the rounding differs, 4e-11 relative
# on the drivetrain outputs measured). False: in the parts' own coordinates, O(m³) a piece.
MODAL_CHAIN = True


def _with_factors(system: PiecewiseLinearSystem, rows: np.ndarray) -> PiecewiseLinearSystem:
    """The system's matrices with the factors of ``rows`` (width, k, c, g; per mesh where several) as its pieces
    (unit widths)."""
    if system.stiffness_pattern.ndim == 2:
        return replace(system, nodes=np.arange(rows.shape[0] + 1, dtype=float), stiffness_factor=rows[:, 1],
                       damping_factor=rows[:, 2], force_factor=rows[:, 3])
    meshes = system.pattern_count
    return replace(system, nodes=np.arange(rows.shape[0] + 1, dtype=float), stiffness_factor=rows[:, 1:1 + meshes],
                   damping_factor=rows[:, 1 + meshes:1 + 2 * meshes], force_factor=rows[:, 1 + 2 * meshes:])


def _pattern_range(system: PiecewiseLinearSystem) -> np.ndarray:
    """Orthonormal basis Q (n, r) of the column space of [P_K, P_C, P_f]: every piece's variation acts through it."""
    pattern_k, pattern_c, pattern_f = system.stacked()[:3]
    stacked = np.hstack([*pattern_k, *pattern_c, pattern_f.T])
    vectors, values, _ = np.linalg.svd(stacked, full_matrices=False)
    if values.size == 0 or values[0] == 0.0:
        return np.zeros((system.size, 0))
    return vectors[:, values > 1e-13 * values[0]]


def monodromy(system: PiecewiseLinearSystem, piece_tolerance: float = PIECE_TOLERANCE) -> tuple[np.ndarray, np.ndarray]:
    """Monodromy Φ_T (2n, 2n) and the image p (2n,) of z = 0 after one period (``piece_tolerance``: see
    :func:`periodic_response`)."""
    distinct, where = _piece_steps(system, 1, piece_tolerance)
    total = ordered_product(distinct[where])
    return total[:-1, :-1], total[:-1, -1]


def periodic_response(system: PiecewiseLinearSystem, samples_per_piece: int = 16,
                      piece_tolerance: float = PIECE_TOLERANCE, observer=None) -> PeriodicResponse:
    """The exact periodic steady state, sampled at ``samples_per_piece`` equal steps per piece.

    ``piece_tolerance`` ε: pieces whose (h_j, k_j, c_j, g_j) agree within ε of each column's largest magnitude share
    one exponential (:mod:`~thermogear.dynamics.linear_algebra.piece_groups` bounds the effect; 0: bit-identical pieces
    only). ``observer``(first piece, sub-step transitions[, whole transitions, transitions from the period's start to
    each piece's start]): fed each chunk where the solve forms them chunk by chunk (``_by_chunks``; :class:`~thermogear.
    dynamics.periodic_motion.MotionProjector`), else never called.

    Raises ModelLimitError when a Floquet multiplier has modulus >= 1 (parametric instability, an undamped mode or
    a rigid-body mode left in the system): there is then no attracting periodic orbit.
    """
    if int(samples_per_piece) != samples_per_piece or samples_per_piece < 1:
        raise ProblemError("samples_per_piece", samples_per_piece, "integer >= 1", "sub-steps per piece")
    samples = int(samples_per_piece)
    # one mesh pattern: solve on the coordinates the forces reach (a train's stacked patterns take every DOF)
    reached = reached_coordinates(system) if system.stiffness_pattern.ndim == 2 else None
    if reached is not None and not reached.all():
        return PeriodicResponse(*on_reached(system, reached, lambda reduced: periodic_response(
            reduced, samples, piece_tolerance)))
    rows, where = grouped_pieces(system, samples, piece_tolerance)
    starts = np.flatnonzero(np.diff(where, prepend=-1))  # runs of equal pieces
    size = 2 * system.size + 1
    if 4 * starts.size <= where.size or size > RUN_ROUTE_SIZE:
        return PeriodicResponse(*by_runs(system, _exponentials(system, rows, powers=True), where, starts, samples))
    if rows.shape[0] * size**2 * 8 > LEAN_ROUTE_BYTES:
        return _by_chunks(system, rows, where, samples, observer)
    return _by_blocks(system, _exponentials(system, rows), where, samples)


def chunked_transitions(system: PiecewiseLinearSystem, rows: np.ndarray, where: np.ndarray, samples: int,
                        dense_steps: bool = True, wholes: bool = True):
    """Yield (first piece, the whole transitions e^{A_j h_j} of the pieces first … first + c − 1, their sub-step
    transitions e^{A_j h_j/s}, s = ``samples``) over consecutive chunks of about :data:`CHUNK_BYTES` of matrices,
    in one pass: each as the parts of its rank-update exponential where it has them without squarings
    (:class:`~thermogear.dynamics.linear_algebra.sub_steps.PartedSteps`, O(q·m) numbers a piece, no (m, m) matrix per
    piece formed; the wholes' chain in modal coordinates where :data:`MODAL_CHAIN`), else as matrices
    (:class:`~thermogear.dynamics.linear_algebra.sub_steps.DenseSteps`); sub-steps None where not parted with
    ``dense_steps`` False (the caller forms them in a pass of its own), the wholes None without ``wholes``."""
    chunk_pieces = max(1, CHUNK_BYTES // (8 * (2 * system.size + 1) ** 2))
    operators = (_mass_inverse(system), _pattern_range(system))
    mean_factors = rows[:, 1:].mean(axis=0)  # every piece about one mean piece of the period, chained in its eigenbasis
    route = _rank_route(system, rows[:1], operators, 1, (mean_factors, None)) if MODAL_CHAIN else None
    basis = None if route is None else modal_basis(route[0], where.size)
    modal = None if basis is None else (basis, (mean_factors, route[0]))
    for first in range(0, where.size, chunk_pieces):
        unique, inverse = np.unique(where[first:first + chunk_pieces], return_inverse=True)
        chunk = rows[unique]
        whole = chunk.copy()
        whole[:, 0] *= samples
        which = inverse.ravel()
        yield (first, _transitions(system, whole, operators, which, modal=modal, wholes=True) if wholes else None,
               _transitions(system, chunk, operators, which, dense_steps, modal))


def _sample_times(system: PiecewiseLinearSystem, samples: int) -> np.ndarray:
    """(N·s + 1,) [s]: s = ``samples`` equal steps per piece and the period's end."""
    offsets = np.arange(samples) / samples
    return np.append((system.nodes[:-1, None] + np.diff(system.nodes)[:, None] * offsets).ravel(), system.period)


def _by_chunks(system: PiecewiseLinearSystem, rows: np.ndarray, where: np.ndarray,
               samples: int, observer=None) -> PeriodicResponse:
    """:func:`periodic_response` where a stack of every distinct piece's matrix would be large (above
    :data:`LEAN_ROUTE_BYTES`): the monodromy as the product of the whole pieces' transitions one after another
    (:func:`chunked_transitions`: the N − 1 products of the block route's tree, through the parts of each piece's
    exponential where it has them; the observer takes the transitions from the period's start to each piece's start
    on the way), then the state at every sub-step by stepping z₀ through the sub-step transitions (N·s products with
    a vector). Exact as the block route (e^{A_j h_j} itself instead of the sub-step's power, other orders of products:
    both differ at the unit roundoff), holding a chunk of matrices at most. Sub-steps held as parts are formed in the
    first pass and kept; otherwise a second pass forms their matrices chunk by chunk."""
    size = 2 * system.size + 1
    total = np.eye(size)
    kept: list | None = []
    fed = 0
    for first, wholes, steps in chunked_transitions(system, rows, where, samples, dense_steps=False):
        kept = None if kept is None or steps is None else [*kept, (first, steps)]
        if kept is not None and observer is not None and fed == first:  # it takes each piece's start transition
            total, starts = wholes.chain_starts(total)
            observer(first, steps, starts, total)
            fed = first + len(steps)
        else:
            total = wholes.chain(total)
    multipliers, initial = floquet(total)
    n, pieces = system.size, where.size
    states = np.empty((pieces * samples + 1, 2 * n + 1))
    state = np.append(initial, 1.0)
    if kept is None:  # a second pass: the sub-steps' matrices, chunk by chunk
        kept = ((first, steps) for first, _, steps in chunked_transitions(system, rows, where, samples, wholes=False))
    for first, steps in kept:
        if observer is not None and first >= fed:
            observer(first, steps)
        for offset in range(len(steps)):
            row = (first + offset) * samples
            state = steps.walk(offset, state, samples, states[row:row + samples])
    states[-1] = state
    return PeriodicResponse(_sample_times(system, samples), states[:, :n], states[:, n:2 * n], multipliers, initial)


def _by_blocks(system: PiecewiseLinearSystem, distinct: np.ndarray, where: np.ndarray,
               samples: int) -> PeriodicResponse:
    """:func:`periodic_response` by √N blocks of pieces (:func:`_blocks`), vectorised over the pieces: the route
    for small systems whose pieces change often."""
    padded, products = _blocks(_power(distinct, samples), where)
    total = ordered_product(products)
    multipliers, initial = floquet(total)
    n, pieces = system.size, where.size
    nodes = _orbit_nodes(padded, products, np.append(initial, 1.0), pieces)
    within = np.empty((pieces, samples, 2 * n + 1))
    current = nodes[:-1]
    steps = distinct[where] if samples > 1 else None
    for sample in range(samples):  # the sub-steps of every piece at once
        within[:, sample] = current
        if sample + 1 < samples:
            current = (steps @ current[:, :, None])[:, :, 0]
    states = np.vstack([within.reshape(pieces * samples, 2 * n + 1), nodes[-1:]])
    return PeriodicResponse(_sample_times(system, samples), states[:, :n], states[:, n:2 * n], multipliers, initial)
