"""The exponentials of a backlash system's pieces in each contact state, formed in batches of pieces.

A contact state (the mesh's region and each dead zone's side, :class:`~thermogear.dynamics.backlash.backlash_ndof.
BacklashSystem`) turns the piecewise-linear system into another one of the same form: out of driving or back
contact the mesh stiffness factor is zero (its damping acts throughout); on the back flanks the excitation is
k_j(e_j − b); a dead zone inside its clearance takes its spring and dashpot out of the constant matrices, one in
contact on side ±1 adds the constant force ±k·δ·v. So every piece of one contact state is that system's piece, and
its sub-step exponential e^{A_j h_j/s} comes from the batched exponentials of the periodic solver
(:func:`~thermogear.dynamics.periodic_orbits.periodic_ndof.piece_steps`: equal pieces once, the others as exact rank
updates of the mean piece) instead of one ``scipy.linalg.expm`` per piece. Pieces are formed in blocks of :data:`BLOCK`
on first use, so a contact state met on a few pieces (free flight near a switch) costs a few blocks, not the whole
period.

The whole piece's transition e^{A_j h_j} is the s-th power of the sub-step one (the same linear flow), formed by
squaring where s is a power of two. The augmented matrix A_j itself (for Brent's method on a partial sub-step and
the saltation matrices) is assembled from the state's constant matrix and the three patterns in O(m²), not stored.
Knows nothing of gears: matrices only.
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np

from thermogear.dynamics.periodic_orbits.periodic_ndof import PiecewiseLinearSystem, piece_steps

__all__ = ["BLOCK", "PieceExponentials", "contact_state_system", "exponential_action"]

#: Pieces formed together in one batched pass (a block of the period): small enough that a contact state met on a
#: few pieces costs little, large enough that the batched pass pays (it dedups equal pieces within the block).
BLOCK = 64

# the contact states as thermogear.dynamics.backlash.backlash_ndof numbers them (not imported: it imports this module)
_DRIVE, _FREE, _BACK = 0, 1, 2


def contact_state_system(system, key: tuple) -> PiecewiseLinearSystem:
    """The :class:`PiecewiseLinearSystem` of one contact state ``key`` = (mesh region, dead-zone sides) of a
    :class:`~thermogear.dynamics.backlash.backlash_ndof.BacklashSystem` (module docstring): force pattern the mesh
    vector w
    and per piece the factors (k_j or 0, c_j, k_j·shift_j)."""
    linear = system.linear
    region, sides = key
    stiffness, damping, force = linear.stiffness, linear.damping, linear.force
    meshes = []  # (column, side) of the train's further meshes
    for zone, side in zip(system.dead_zones, sides):
        if hasattr(zone, "column"):
            meshes.append((zone, side))
        elif side == 0:
            pattern = np.outer(zone.vector, zone.vector)
            stiffness, damping = stiffness - zone.stiffness * pattern, damping - zone.damping * pattern
        else:
            force = force + side * zone.stiffness * zone.clearance * zone.vector
    if linear.pattern_count == 1:
        factor = np.zeros_like(linear.stiffness_factor) if region == _FREE else linear.stiffness_factor
        shift = system.deviation - (system.backlash if region == _BACK else 0.0)
        return replace(linear, stiffness=stiffness, damping=damping, force=force, force_pattern=system.mesh_vector,
                       stiffness_factor=factor, force_factor=factor * shift)
    # a train: every mesh its own column, each zeroed in free flight and shifted by its backlash on the back flanks;
    # a mesh's further patterns (system.pattern_meshes) alike, their force moved by −b·back_shift on the back flanks
    factors, forces = linear.stiffness_factor.copy(), np.empty_like(linear.stiffness_factor)
    columns = [(0, region == _FREE, region == _BACK, system.deviation, system.backlash)]
    columns += [(zone.column, side == 0, side == -1, zone.deviation, zone.backlash) for zone, side in meshes]
    owners = np.asarray(system.pattern_meshes)
    for column, free, back, deviation, backlash in columns:
        if free:
            factors[:, column] = 0.0
        forces[:, column] = factors[:, column] * (deviation - (backlash if back else 0.0))
        for further in np.flatnonzero((owners == column) & (np.arange(owners.size) != column)):
            if free:
                factors[:, further], forces[:, further] = 0.0, 0.0
                continue
            shift = linear.stiffness_factor[:, further] if system.back_shift is None else system.back_shift[:, further]
            forces[:, further] = linear.force_factor[:, further] - (backlash * shift if back else 0.0)
    return replace(linear, stiffness=stiffness, damping=damping, force=force, stiffness_factor=factors,
                   force_factor=forces)


class PieceExponentials:
    """Per (piece, contact state): the sub-step exponential, the whole piece's transition and the augmented matrix
    of a backlash system with ``substeps`` equal sub-steps per piece (module docstring). Kept for the life of one
    system (e.g. in the ``cache`` dict of :func:`~thermogear.dynamics.backlash.backlash_ndof.backlash_flow_ndof`)."""

    def __init__(self, system, substeps: int, mass_inverse: np.ndarray):
        self.system, self.substeps, self.mass_inverse = system, int(substeps), mass_inverse
        self.pieces = system.linear.nodes.size - 1
        self._steps: dict[tuple, np.ndarray] = {}  # (key, block) → (pieces of the block, m, m)
        self._wholes: dict[tuple, np.ndarray] = {}
        self._systems: dict[tuple, tuple] = {}  # key → (its system, constant augmented matrix, three patterns)

    def _state(self, key: tuple) -> tuple:
        if key not in self._systems:
            variant = contact_state_system(self.system, key)
            inverse = self.mass_inverse
            n = variant.size
            constant = np.zeros((2 * n + 1, 2 * n + 1))
            constant[:n, n:2 * n] = np.eye(n)
            constant[n:2 * n, :n] = -inverse @ variant.stiffness
            constant[n:2 * n, n:2 * n] = -inverse @ variant.damping
            constant[n:2 * n, 2 * n] = inverse @ variant.force
            if variant.pattern_count == 1:
                patterns = np.zeros((3, 2 * n + 1, 2 * n + 1))
                patterns[0, n:2 * n, :n] = -inverse @ variant.stiffness_pattern
                patterns[1, n:2 * n, n:2 * n] = -inverse @ variant.damping_pattern
                patterns[2, n:2 * n, 2 * n] = inverse @ variant.force_pattern
            else:  # a train: one set of three per mesh (M, 2n+1, 2n+1)
                count = variant.pattern_count
                patterns = np.zeros((3, count, 2 * n + 1, 2 * n + 1))
                patterns[0, :, n:2 * n, :n] = -inverse @ variant.stiffness_pattern
                patterns[1, :, n:2 * n, n:2 * n] = -inverse @ variant.damping_pattern
                patterns[2, :, n:2 * n, 2 * n] = variant.force_pattern @ inverse.T
            self._systems[key] = (variant, constant, patterns)
        return self._systems[key]

    def _block(self, key: tuple, block: int) -> np.ndarray:
        if (key, block) not in self._steps:
            variant = self._state(key)[0]
            first, last = block * BLOCK, min((block + 1) * BLOCK, self.pieces)
            nodes = variant.nodes[first:last + 1] - variant.nodes[first]
            part = replace(variant, nodes=nodes, stiffness_factor=variant.stiffness_factor[first:last],
                           damping_factor=variant.damping_factor[first:last],
                           force_factor=variant.force_factor[first:last])
            distinct, where = piece_steps(part, self.substeps)
            self._steps[(key, block)] = distinct[where]
        return self._steps[(key, block)]

    def step(self, piece: int, key: tuple) -> np.ndarray:
        """e^{A h/s} of one piece in one contact state: one sub-step."""
        return self._block(key, piece // BLOCK)[piece % BLOCK]

    def whole(self, piece: int, key: tuple) -> np.ndarray:
        """e^{A h} of one piece in one contact state: the whole piece (the sub-step's s-th power)."""
        block = piece // BLOCK
        if (key, block) not in self._wholes:
            steps, count = self._block(key, block), self.substeps
            if count & (count - 1) == 0:  # a power of two: square
                while count > 1:
                    steps, count = steps @ steps, count // 2
                self._wholes[(key, block)] = steps
            else:
                self._wholes[(key, block)] = np.linalg.matrix_power(steps, count)
        return self._wholes[(key, block)][piece % BLOCK]

    def matrix(self, piece: int, key: tuple) -> np.ndarray:
        """The augmented matrix [[A_j, b_j], [0, 0]] of one piece in one contact state."""
        variant, constant, patterns = self._state(key)
        if patterns.ndim == 4:  # a train: the factors of every mesh
            return (constant + np.tensordot(variant.stiffness_factor[piece], patterns[0], 1)
                    + np.tensordot(variant.damping_factor[piece], patterns[1], 1)
                    + np.tensordot(variant.force_factor[piece], patterns[2], 1))
        return (constant + variant.stiffness_factor[piece] * patterns[0]
                + variant.damping_factor[piece] * patterns[1] + variant.force_factor[piece] * patterns[2])


#: The exponential's action is summed on sub-intervals over which the largest rate of the flow times the length is
#: at most this; its Taylor terms then fall at least as 0.5^k/k!.
_ACTION_REACH = 0.5
#: Beyond this many sub-intervals (a stiff flow over a long time) the full exponential (O(n³) once) is used instead.
_ACTION_INTERVALS = 8


def _action_order(reach: float) -> int:
    """Least Taylor order k whose next term bound reach^(k+1)/(k+1)! is below 2⁻⁵⁶ (an eighth of the unit
    roundoff)."""
    order, bound = 0, 1.0
    while bound > 2.0**-56:
        order += 1
        bound *= reach / order
    return order


def exponential_action(matrix: np.ndarray, state: np.ndarray, time: float) -> np.ndarray:
    """e^{A t}·z of an augmented mechanical matrix A = [[0, I, 0], [−M⁻¹K, −M⁻¹C, M⁻¹f], [0, 0, 0]] [1/s] on a state
    z (2n+1,), t >= 0 [s], without forming the exponential: the Taylor series of the action, Σ (At)ᵏz/k! in Horner
    form, on equal sub-intervals short against the fastest rate of the flow (ρ = max(√‖M⁻¹K‖∞, ‖M⁻¹C‖∞), the
    Gershgorin bounds of its frequencies and decay rates, so that the displacement and velocity parts each converge
    without cancellation), truncated where the bound ρᵏ/k! of the next term is below the unit roundoff (Moler & Van
    Loan, SIAM Review 45 (2003) 3–49, §2, the series method, here on a vector and scaled by sub-intervals). O(n²)
    per term, for the few evaluations of Brent's method, where a full exponential costs O(n³) each; where more than
    :data:`_ACTION_INTERVALS` sub-intervals would be needed, the full exponential (``scipy.linalg.expm``) is applied
    instead."""
    size = (matrix.shape[0] - 1) // 2
    stiffness = float(np.abs(matrix[size:2 * size, :size]).sum(axis=1).max(initial=0.0))
    damping = float(np.abs(matrix[size:2 * size, size:2 * size]).sum(axis=1).max(initial=0.0))
    rate = max(np.sqrt(stiffness), damping)
    count = max(1, int(np.ceil(rate * time / _ACTION_REACH)))
    if count > _ACTION_INTERVALS:  # stiff against the time: scaling and squaring of the whole exponential is cheaper
        from scipy.linalg import expm

        return expm(matrix * time) @ state
    step = time / count
    order = _action_order(rate * step)
    result = np.array(state, dtype=float)
    for _ in range(count):
        total = result
        for power in range(order, 0, -1):
            total = result + (matrix @ total) * (step / power)
        result = total
    return result
