"""The drivetrain's backlash orbit followed up and down in speed: one mesh state per speed (each with its backlash),
the n-DOF backlash system of each (:func:`~thermogear.drivetrain.response.drivetrain_backlash_system`) and the
continuation of :mod:`thermogear.dynamics.backlash_branch_ndof`, which shows the jumps of the softening mesh
resonance (the drivetrain counterpart of :mod:`thermogear.dynamics.backlash_continuation` for the 1-DOF pair)."""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np

from thermogear.drivetrain.assembly import AssembledDrivetrain
from thermogear.drivetrain.response import drivetrain_backlash_system
from thermogear.dynamics.backlash_branch_ndof import BacklashBranchNDOF, follow_backlash_branch
from thermogear.errors import CaseError
from thermogear.mesh.state import MeshState

__all__ = ["drivetrain_backlash_branch"]


def drivetrain_backlash_branch(assembled: AssembledDrivetrain, states: Sequence[MeshState], direction: str = "up",
                               substeps: int = 8, run_in_periods: int = 200,
                               tolerance: float = 1e-10) -> BacklashBranchNDOF:
    """Follow the drivetrain's backlash orbit over mesh states ordered by pinion speed, ``direction`` "up" or
    "down"; the branch's parameter is the speed [rpm]; ``tolerance`` the shooting's relative residual (very stiff
    supports leave a rounding floor near 1e-9: ask for 1e-8 there). The state at τ = 0 carries over between speeds only when
    every state has the same reduced coordinates (one drivetrain, one rigid-mode reduction), which holds here."""
    speeds = np.array([state.speed_rpm for state in states], dtype=float)
    if speeds.size == 0 or np.any(np.diff(speeds) <= 0.0):
        raise CaseError("states", list(speeds), "mesh states at increasing pinion speeds", "a sweep in speed")
    systems = [drivetrain_backlash_system(assembled, state)[0] for state in states]
    return follow_backlash_branch(systems, direction, speeds, substeps=substeps, run_in_periods=run_in_periods,
                                  tolerance=tolerance)
