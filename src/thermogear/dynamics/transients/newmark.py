"""Reference: the Newmark average-acceleration integrator (γ = 1/2, β = 1/4) run period after period to the steady
state of a piecewise-constant linear system — a baseline for the exact periodic solver in tests and benchmarks,
not a production path.

On a step h of piece j: (K_j + γ/(βh)·C_j + M/(βh²))·q_{k+1} = f_j + M·(q_k/(βh²) + q̇_k/(βh) + (1/(2β) − 1)·q̈_k)
+ C_j·(γ/(βh)·q_k + (γ/β − 1)·q̇_k + h(γ/(2β) − 1)·q̈_k), then q̈_{k+1} and q̇_{k+1} from the Newmark relations
(Newmark, "A method of computation for structural dynamics", J. Eng. Mech. Div. ASCE 85 (1959) 67–94; Géradin &
Rixen, Mechanical Vibrations, 3rd ed. 2015, §7.2). Unconditionally stable and second-order accurate, with no
numerical damping: it converges to the exact orbit as h², and reaches the steady state only as fast as the physical
damping lets the transient die out. Knows nothing of gears: matrices only.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from thermogear.dynamics.periodic_orbits.periodic_ndof import PiecewiseLinearSystem
from thermogear.errors import ModelLimitError, ProblemError

__all__ = ["NewmarkSteadyState", "newmark_steady_state"]

_GAMMA, _BETA = 0.5, 0.25


@dataclass(frozen=True, eq=False)
class NewmarkSteadyState:
    """The last period: ``time`` (S,) [s] at ``steps_per_piece`` steps per piece plus the end, ``displacement``,
    ``velocity`` (S, n) [SI]; ``periods`` integrated from rest until two period ends agreed."""

    time: np.ndarray
    displacement: np.ndarray
    velocity: np.ndarray
    periods: int


def newmark_steady_state(system: PiecewiseLinearSystem, steps_per_piece: int = 16, tolerance: float = 1e-8,
                         max_periods: int = 5000) -> NewmarkSteadyState:
    """Integrate from rest until the displacement at two successive period ends differs by less than
    ``tolerance`` × its largest entry; ModelLimitError after ``max_periods``."""
    from scipy.linalg import lu_factor, lu_solve

    if int(steps_per_piece) != steps_per_piece or steps_per_piece < 1:
        raise ProblemError("steps_per_piece", steps_per_piece, "integer >= 1", "Newmark steps per piece")
    steps = int(steps_per_piece)
    mass, n = system.mass, system.size
    widths = np.diff(system.nodes) / steps
    pieces = []
    for index, h in enumerate(widths):
        stiffness, damping, force = system.piece(index)
        effective = lu_factor(stiffness + _GAMMA / (_BETA * h) * damping + mass / (_BETA * h * h))
        pieces.append((h, stiffness, damping, force, effective))
    q, v = np.zeros(n), np.zeros(n)
    stiffness, damping, force = system.piece(0)
    a = np.linalg.solve(mass, force - damping @ v - stiffness @ q)
    for period in range(1, max_periods + 1):
        rows_q, rows_v = [q], [v]
        start = q.copy()
        for h, stiffness, damping, force, effective in pieces:
            a = np.linalg.solve(mass, force - damping @ v - stiffness @ q)  # the jump of q̈ at the node
            for _ in range(steps):
                rhs = (force + mass @ (q / (_BETA * h * h) + v / (_BETA * h) + (0.5 / _BETA - 1.0) * a)
                       + damping @ (_GAMMA / (_BETA * h) * q + (_GAMMA / _BETA - 1.0) * v
                                    + h * (_GAMMA / (2.0 * _BETA) - 1.0) * a))
                q_next = lu_solve(effective, rhs)
                a_next = (q_next - q - h * v) / (_BETA * h * h) - (0.5 / _BETA - 1.0) * a
                v = v + h * ((1.0 - _GAMMA) * a + _GAMMA * a_next)
                q, a = q_next, a_next
                rows_q.append(q)
                rows_v.append(v)
        scale = max(np.abs(q).max(), 1e-300)
        if np.abs(q - start).max() < tolerance * scale:
            offsets = np.arange(steps) / steps
            time = np.concatenate([(system.nodes[:-1, None] + np.diff(system.nodes)[:, None] * offsets).ravel(),
                                   [system.period]])
            return NewmarkSteadyState(time, np.array(rows_q), np.array(rows_v), period)
    raise ModelLimitError(f"Newmark did not reach a steady state to {tolerance:g} in {max_periods} periods")
