"""Periodic orbits of an n-DOF linear system with one backlash (dead-zone) coordinate, by shooting.

M q̈ + (C₀ + c_j w wᵀ) q̇ + K₀ q + k_j·φ(wᵀq − e_j)·w = f₀ on piece j of one period, with the dead zone of width b

    φ(g) = g (g > 0, driving flanks in contact),  0 (−b ≤ g ≤ 0, free flight),  g + b (g < −b, back flanks)

(Kahraman & Singh, J. Sound Vib. 142 (1990) 49–75, for one coordinate; here any structure around it). Damping acts
at all times, so the vector field is continuous across a contact switch and the saltation matrix is the identity:
the monodromy of an orbit is the product of the exact transition matrices of its linear segments (Leine & Nijmeijer,
Dynamics and Bifurcations of Non-Smooth Mechanical Systems, 2004, ch. 7). Each segment (a piece in one contact
region) is solved exactly by the augmented exponential (Van Loan 1978); switches are found on sub-steps of each piece
and located by Brent's method on the exact solution. Newton on φ_T(z₀) − z₀ with that monodromy finds the orbit,
starting from the linear periodic state (driving contact throughout). Knows nothing of gears.

Limits: a double crossing inside one sub-step (grazing) is not seen; take ``substeps`` so that a sub-step is short
against the fastest mode the mesh coordinate takes part in.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from thermogear.dynamics.periodic_ndof import PiecewiseLinearSystem, periodic_response
from thermogear.dynamics.problem import checked_array
from thermogear.errors import ProblemError

__all__ = ["BacklashSystem", "BacklashOrbitNDOF", "backlash_flow_ndof", "backlash_periodic_orbit"]

_DRIVE, _FREE, _BACK = 0, 1, 2


@dataclass(frozen=True, eq=False)
class BacklashSystem:
    """The linear structure (``linear``: a :class:`PiecewiseLinearSystem` whose stiffness, damping and force
    patterns are w wᵀ, w wᵀ and w with factors k_j, c_j and k_j e_j — the mesh in driving contact) and the backlash
    b [m] of the mesh coordinate g = wᵀq − e_j; ``mesh_vector`` w and ``deviation`` e_j (N,) [m]."""

    linear: PiecewiseLinearSystem
    mesh_vector: np.ndarray
    deviation: np.ndarray
    backlash: float

    def __post_init__(self) -> None:
        n, pieces = self.linear.size, self.linear.nodes.size - 1
        object.__setattr__(self, "mesh_vector", checked_array("mesh_vector", self.mesh_vector, (n,), "one per DOF"))
        object.__setattr__(self, "deviation", checked_array("deviation", self.deviation, (pieces,)))
        if not np.isfinite(self.backlash) or self.backlash <= 0.0:
            raise ProblemError("backlash", self.backlash, "> 0 m", "a zero or negative backlash is a jammed mesh")

    def region_matrix(self, piece: int, region: int, mass_inverse: np.ndarray) -> np.ndarray:
        """Augmented (2n+1)² matrix of one piece in one contact region."""
        system = self.linear
        n = system.size
        k = system.stiffness_factor[piece] if region != _FREE else 0.0
        shift = {_DRIVE: self.deviation[piece], _FREE: 0.0, _BACK: self.deviation[piece] - self.backlash}[region]
        stiffness = system.stiffness + k * system.stiffness_pattern
        damping = system.damping + system.damping_factor[piece] * system.damping_pattern
        force = system.force + k * shift * self.mesh_vector
        matrix = np.zeros((2 * n + 1, 2 * n + 1))
        matrix[:n, n:2 * n] = np.eye(n)
        matrix[n:2 * n, :n] = -mass_inverse @ stiffness
        matrix[n:2 * n, n:2 * n] = -mass_inverse @ damping
        matrix[n:2 * n, 2 * n] = mass_inverse @ force
        return matrix

    def region(self, state: np.ndarray, piece: int) -> int:
        """Contact region of a state (n-DOF displacement first) on a piece, by g and, on a boundary, by ġ."""
        n = self.linear.size
        gap = self.mesh_vector @ state[:n] - self.deviation[piece]
        rate = self.mesh_vector @ state[n:2 * n]
        if gap > 0.0 or (gap == 0.0 and rate > 0.0):
            return _DRIVE
        if gap < -self.backlash or (gap == -self.backlash and rate < 0.0):
            return _BACK
        return _FREE


def backlash_flow_ndof(system: BacklashSystem, state: np.ndarray, substeps: int = 16,
                       record: bool = False) -> tuple[np.ndarray, np.ndarray, dict]:
    """φ_T(state): end state (2n,), monodromy (2n, 2n) and {"switches", "free_flight_time", "back_contact_time",
    "time", "states"} (the last two filled when ``record``: the state after every segment)."""
    from scipy.linalg import expm
    from scipy.optimize import brentq

    linear = system.linear
    n = linear.size
    inverse = np.linalg.inv(linear.mass)
    z = np.append(np.asarray(state, dtype=float), 1.0)
    total = np.eye(2 * n + 1)
    info = {"switches": 0, "free_flight_time": 0.0, "back_contact_time": 0.0, "time": [0.0], "states": [z[:-1]]}
    w = system.mesh_vector
    for piece in range(linear.nodes.size - 1):
        start, stop = linear.nodes[piece], linear.nodes[piece + 1]
        step = (stop - start) / substeps
        matrices, full_steps = {}, {}
        region = system.region(z, piece)  # at a node the deviation steps: the region is decided afresh
        t = start
        while t < stop - 1e-12 * (stop - start):
            if region not in matrices:
                matrices[region] = system.region_matrix(piece, region, inverse)
            matrix = matrices[region]
            h = min(step, stop - t)
            if region not in full_steps:
                full_steps[region] = expm(matrix * step)
            trial_step = full_steps[region] if h == step else expm(matrix * h)
            after = system.region(trial_step @ z, piece)
            following = region
            if after != region:
                # the boundary crossed first: from free flight the one on the side the motion ends
                boundary = -system.backlash if (region == _BACK or (region == _FREE and after == _BACK)) else 0.0
                following = _FREE if region != _FREE else after

                def distance(s, m=matrix, b=boundary):
                    return w @ (expm(m * s) @ z)[:n] - system.deviation[piece] - b

                low, high = distance(0.0), distance(h)
                if low * high < 0.0:
                    h = brentq(distance, 0.0, h, xtol=1e-13 * (stop - start), rtol=1e-14)
                    info["switches"] += 1
                elif low == 0.0:
                    h = 0.0
            if h > 0.0:
                segment = full_steps[region] if h == step else expm(matrix * h)
                total = segment @ total
                z = segment @ z
                if region == _FREE:
                    info["free_flight_time"] += h
                elif region == _BACK:
                    info["back_contact_time"] += h
                t += h
            region = following
            if record:
                info["time"].append(t)
                info["states"].append(z[:-1])
            if not np.all(np.isfinite(z)):
                raise ProblemError("state", "not finite", "a bounded motion", "the coefficients are out of range")
    return z[:-1], total[:-1, :-1], info


@dataclass(frozen=True, eq=False)
class BacklashOrbitNDOF:
    """A periodic orbit with backlash: ``initial_state`` z₀ (2n,), Floquet ``multipliers`` of its monodromy,
    ``converged`` (Newton residual below tolerance), ``residual`` (relative), contact statistics per period."""

    initial_state: np.ndarray
    multipliers: np.ndarray
    converged: bool
    residual: float
    iterations: int
    switches: int
    free_flight_time: float
    back_contact_time: float

    @property
    def stable(self) -> bool:
        """Converged with every multiplier inside the unit circle."""
        return bool(self.converged and np.abs(self.multipliers).max() < 1.0)


def backlash_periodic_orbit(system: BacklashSystem, initial_state: np.ndarray | None = None, substeps: int = 16,
                            tolerance: float = 1e-10, max_iterations: int = 30) -> BacklashOrbitNDOF:
    """Shooting (damped Newton with the exact monodromy) from ``initial_state`` or the linear periodic state."""
    state = (periodic_response(system.linear, 1).initial_state if initial_state is None
             else np.asarray(initial_state, dtype=float))
    n = system.linear.size
    scale = np.concatenate([np.full(n, max(np.abs(state[:n]).max(), 1e-300)),
                            np.full(n, max(np.abs(state[n:]).max(), 1e-300))])

    def measure(difference):
        return float(np.abs(difference / scale).max())

    end, matrix, info = backlash_flow_ndof(system, state, substeps)
    residual, iterations = measure(end - state), 0
    while residual > tolerance and iterations < max_iterations:
        iterations += 1
        step = np.linalg.solve(matrix - np.eye(2 * n), -(end - state))
        factor = 1.0
        for _ in range(9):
            trial = state + factor * step
            trial_end, trial_matrix, trial_info = backlash_flow_ndof(system, trial, substeps)
            trial_residual = measure(trial_end - trial)
            if trial_residual < residual:
                break
            factor *= 0.5
        else:
            break
        state, end, matrix, info, residual = trial, trial_end, trial_matrix, trial_info, trial_residual
    multipliers = np.linalg.eigvals(matrix)
    return BacklashOrbitNDOF(state, multipliers[np.argsort(-np.abs(multipliers))], residual <= tolerance, residual,
                             iterations, info["switches"], info["free_flight_time"], info["back_contact_time"])
