"""The drivetrain's backlash orbit followed up and down in speed: one mesh state per speed (each with its backlash),
the n-DOF backlash system of each (:func:`~thermogear.drivetrain.response.drivetrain_backlash_system`) and the
continuation of :mod:`thermogear.dynamics.backlash.backlash_branch_ndof`, which shows the jumps of the softening mesh
resonance (the drivetrain counterpart of :mod:`thermogear.dynamics.backlash.backlash_continuation` for the 1-DOF pair).

With a modal cut-off each speed is solved on its own modal basis
(:func:`~thermogear.drivetrain.backlash_response.reduced_backlash_system`, the very system
:func:`~thermogear.drivetrain.backlash_response.drivetrain_backlash_response` solves at that speed, so a branch's
converged state starts that response where it ends) and the state carries between speeds through the full
coordinates, projected in the mass metric."""

from __future__ import annotations

from collections.abc import Callable, Sequence

import numpy as np

from thermogear.drivetrain.assembly import AssembledDrivetrain
from thermogear.drivetrain.response import drivetrain_backlash_system
from thermogear.dynamics.backlash.backlash_branch_ndof import BacklashBranchNDOF, follow_backlash_branch
from thermogear.errors import CaseError
from thermogear.mesh.state import MeshState

__all__ = ["drivetrain_backlash_branch"]


def drivetrain_backlash_branch(assembled: AssembledDrivetrain, states: Sequence[MeshState], direction: str = "up",
                               substeps: int = 8, run_in_periods: int = 200,
                               tolerance: float = 1e-10, cutoff_hz: float | None = None,
                               progress: Callable[[int], None] | None = None,
                               measure_swing: bool = True) -> BacklashBranchNDOF:
    """Follow the drivetrain's backlash orbit over mesh states ordered by pinion speed, ``direction`` "up" or
    "down"; the branch's parameter is the speed [rpm]; ``tolerance`` the shooting's relative residual (very stiff
    supports leave a rounding floor near 1e-9: ask for 1e-8 there). The state at τ = 0 carries over between speeds
    through the full coordinates (each speed's rigid-body reduction, and modal basis, may differ by a rotation of the
    same subspace: the gyroscopic damping enters the reduction).
    ``cutoff_hz`` [Hz]: solve each speed on its modes up to it (module docstring); ``progress(1)`` after each
    point; ``measure_swing`` as :func:`~thermogear.dynamics.backlash.backlash_branch_ndof.follow_backlash_branch`."""
    speeds = np.array([state.speed_rpm for state in states], dtype=float)
    if speeds.size == 0 or np.any(np.diff(speeds) <= 0.0):
        raise CaseError("states", list(speeds), "mesh states at increasing pinion speeds", "a sweep in speed")
    built = [drivetrain_backlash_system(assembled, state) for state in states]
    systems = [system for system, _ in built]
    coordinates = [reduction.basis for _, reduction in built]
    if cutoff_hz is not None:
        from thermogear.drivetrain.backlash_response import reduced_backlash_system

        reduced = [reduced_backlash_system(system, cutoff_hz) for system in systems]
        systems = [system for system, _ in reduced]
        coordinates = [rigid @ basis.basis for rigid, (_, basis) in zip(coordinates, reduced)]
    return follow_backlash_branch(systems, direction, speeds, substeps=substeps, run_in_periods=run_in_periods,
                                  tolerance=tolerance, coordinates=coordinates, metric=assembled.mass,
                                  progress=progress, measure_swing=measure_swing)
