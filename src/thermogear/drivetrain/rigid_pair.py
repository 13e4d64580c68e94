"""The degenerate drivetrain: two rigid gears on rigid supports, joined by their mesh, as the matrices every
drivetrain solver takes.

:class:`~thermogear.dynamics.problems.rigid_pair.RigidPair` is the 1-DOF pair's structure (M = diag(J₁, J₂),
w = s·(r_b1, r_b2), the mesh mass m_e of Luo & Li 2020 Eq. 5, and the scalar structure the compiled 1-DOF kernels
take); :func:`rigid_pair_system` gives the same pair over one mesh period as a drivetrain's piecewise-linear system
with the free rotation removed (:mod:`thermogear.dynamics.modes.rigid_body`), so the two routes can be held equal.
"""

from __future__ import annotations

import numpy as np

from thermogear.dynamics.modes.rigid_body import RigidBodyReduction, rigid_body_reduction
from thermogear.dynamics.periodic_orbits.periodic_ndof import PiecewiseLinearSystem
from thermogear.dynamics.problems.rigid_pair import RigidPair

__all__ = ["rigid_pair_system"]


def rigid_pair_system(pair: RigidPair, problem, normal_load: float) -> tuple[PiecewiseLinearSystem,
                                                                            RigidBodyReduction]:
    """The rigid ``pair`` as a drivetrain over one mesh period of ``problem`` (a mesh state's problem: its k(τ),
    c(τ) and load per interval) under the normal load W [N], the free rotation removed: the same pieces and
    reduction as every drivetrain's."""
    w = pair.mesh_vector()
    mean = float(np.dot(problem.stiffness, np.diff(problem.nodes)) / problem.period)
    reduction = rigid_body_reduction(pair.mass_matrix(), mean * np.outer(w, w), np.eye(2))
    reduced = reduction.project_vector(w)
    pattern = np.outer(reduced, reduced)
    size = reduced.size
    system = PiecewiseLinearSystem(
        mass=reduction.project(pair.mass_matrix()), stiffness=np.zeros((size, size)),
        damping=np.zeros((size, size)), force=reduction.project_vector(pair.torques(normal_load)),
        nodes=problem.nodes, stiffness_pattern=pattern, stiffness_factor=problem.stiffness,
        damping_pattern=pattern, damping_factor=problem.damping, force_pattern=reduced,
        force_factor=problem.force_per_interval - normal_load)
    return system, reduction
