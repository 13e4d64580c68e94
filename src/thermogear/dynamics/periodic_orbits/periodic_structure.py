"""Periodic steady state of a mesh inside a structure of n degrees of freedom (the matrix form of a problem).

A :class:`~thermogear.dynamics.problems.problem.MeshDynamicsProblem` with a mass matrix stands for
M q̈ + (C₀ + c_j·w wᵀ) q̇ + (K₀ + k_j·w wᵀ) q = f₀ + g_j·w on interval j
(:mod:`~thermogear.dynamics.problems.structure`): exactly the pieces of
:class:`~thermogear.dynamics.periodic_orbits.periodic_ndof.PiecewiseLinearSystem` with the patterns P_K = P_C = w wᵀ,
P_f = w and the factors k_j, c_j, g_j, which solves it by the exponential of the augmented matrix (Van Loan 1978) and
Floquet theory (Nayfeh & Mook, Nonlinear Oscillations, 1979, §5.2). The orbit is returned as the 1-DOF solver returns
it, with the mesh deflection δ = wᵀq as its displacement, so the metrics of the mesh (loads k·δ + c·δ̇ per interval)
read it unchanged; q itself rides along.
"""

from __future__ import annotations

import numpy as np

from thermogear.dynamics.periodic_orbits.periodic_ndof import PiecewiseLinearSystem, monodromy, periodic_response
from thermogear.dynamics.problems.problem import MeshDynamicsProblem
from thermogear.dynamics.results.orbit import PeriodicOrbit

__all__ = ["piecewise_system", "structure_multipliers", "structure_orbit"]


def piecewise_system(problem: MeshDynamicsProblem) -> PiecewiseLinearSystem:
    """The problem's matrices as the pieces of a :class:`PiecewiseLinearSystem` (also for the 1-DOF mesh)."""
    structure = problem.structure
    pattern = structure.pattern()
    return PiecewiseLinearSystem(mass=structure.mass, stiffness=structure.stiffness, damping=structure.damping,
                                 force=structure.force, nodes=problem.nodes, stiffness_pattern=pattern,
                                 stiffness_factor=problem.stiffness, damping_pattern=pattern,
                                 damping_factor=problem.damping, force_pattern=structure.mesh_vector,
                                 force_factor=problem.force_per_interval)


def structure_multipliers(problem: MeshDynamicsProblem) -> np.ndarray:
    """Floquet multipliers (2n,) complex, larger modulus first."""
    transition, _ = monodromy(piecewise_system(problem))
    multipliers = np.linalg.eigvals(transition)
    return multipliers[np.argsort(-np.abs(multipliers), kind="stable")]


def structure_orbit(problem: MeshDynamicsProblem, samples_per_interval: int) -> PeriodicOrbit:
    """The exact periodic orbit sampled as the 1-DOF solver samples it; ModelLimitError where a multiplier has
    modulus >= 1 (parametric instability, an undamped or a rigid-body mode: remove rigid-body modes first)."""
    response = periodic_response(piecewise_system(problem), samples_per_piece=samples_per_interval)
    vector = problem.structure.mesh_vector
    displacement = response.displacement @ vector
    velocity = response.velocity @ vector
    intervals = problem.interval_count
    interval = np.append(np.repeat(np.arange(intervals), samples_per_interval), intervals - 1)
    return PeriodicOrbit(time=response.time, displacement=displacement, velocity=velocity,
                         multipliers=response.multipliers, stable=True,
                         initial_state=(float(displacement[0]), float(velocity[0])), interval=interval,
                         coordinates=response.displacement, coordinate_velocities=response.velocity)
