"""Every stable orbit of the backlash drivetrain that a multi-start search finds, each with its basin share.

The drivetrain's backlash system (:func:`~thermogear.drivetrain.response.drivetrain_backlash_system`, on the modal
cut-off as ``run`` solves it) goes to the solver's search (:func:`~thermogear.dynamics.backlash.backlash_orbits_ndof.
stable_orbits_ndof`: the state at rest and a grid over the mesh coordinate and its rate lifted onto the mesh's
static shape, each run in and shot); each distinct stable orbit is sampled and described as ``run`` describes its
orbit (:class:`~thermogear.drivetrain.backlash_response.DrivetrainBacklashResponse`: Kv, DTE, contact loss, bearing
forces), with the share of the starts that settle on it and whether the start from rest is among them.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from thermogear.drivetrain.assembly import AssembledDrivetrain
from thermogear.drivetrain.backlash_response import (SHOOTING_TOLERANCE, DrivetrainBacklashResponse, _response,
                                                    one_blas_thread, reduced_backlash_system)
from thermogear.drivetrain.response import drivetrain_backlash_system
from thermogear.dynamics.backlash.backlash_orbits_ndof import stable_orbits_ndof
from thermogear.dynamics.backlash.backlash_trajectory import backlash_trajectory
from thermogear.mesh.state import MeshState

__all__ = ["DrivetrainOrbitCensus", "DrivetrainStableOrbit", "case_stable_orbits", "census_summary",
           "drivetrain_stable_orbits"]


@dataclass(frozen=True, eq=False)
class DrivetrainStableOrbit:
    """One stable orbit: its sampled ``response``, ``start_count`` starts settled on it (``basin_share`` of all),
    ``from_rest`` whether the start from rest is one of them."""

    response: DrivetrainBacklashResponse
    start_count: int
    basin_share: float
    from_rest: bool


@dataclass(frozen=True, eq=False)
class DrivetrainOrbitCensus:
    """The distinct stable ``orbits`` (largest basin share first) of ``starts`` starts; the shares of the starts
    that settled on no stable one-period orbit (``unresolved``) or grew without bound (``unbounded``)."""

    orbits: tuple[DrivetrainStableOrbit, ...]
    starts: int
    unresolved: float
    unbounded: float


def drivetrain_stable_orbits(assembled: AssembledDrivetrain, state: MeshState, starts: int = 16,
                             run_in_periods: int = 60, substeps: int = 16, samples_per_piece: int = 8,
                             cutoff_hz: float | None = None, tolerance: float = SHOOTING_TOLERANCE,
                             progress=None) -> DrivetrainOrbitCensus:
    """Multi-start search (module docstring) with ``starts`` starts (the first at rest), each run in over
    ``run_in_periods`` mesh periods and shot to ``tolerance``; ``substeps`` per piece to find the switches;
    ``cutoff_hz`` [Hz] the modal cut-off (None: every DOF); ``progress(1)`` after each start."""
    system, reduction = drivetrain_backlash_system(assembled, state)
    basis = None
    if cutoff_hz is not None:
        system, basis = reduced_backlash_system(system, cutoff_hz)
    cache: dict = {}
    with one_blas_thread():
        census = stable_orbits_ndof(system, starts, run_in_periods, substeps, tolerance, progress=progress)
        found = []
        for item in census.orbits:
            orbit = item.orbit
            trajectory = backlash_trajectory(system, orbit.initial_state, 1, samples_per_piece, orbit.substeps,
                                             system.mesh_vector, cache)
            response = _response(assembled, state, system, reduction, basis, trajectory, orbit.initial_state,
                                 orbit.multipliers, orbit.converged, orbit.failure, orbit.switches)
            found.append(DrivetrainStableOrbit(response, item.start_count, item.basin_share, item.from_rest))
    count = census.outcome.size
    return DrivetrainOrbitCensus(tuple(found), count, float(np.mean(census.outcome == -1)),
                                 float(np.mean(census.outcome == -2)))


def census_summary(census: DrivetrainOrbitCensus) -> dict:
    """JSON-ready: per orbit its numbers (:func:`~thermogear.drivetrain.backlash_response.orbit_summary`), basin
    share and whether a start from rest reaches it; the unresolved and unbounded shares."""
    from thermogear.drivetrain.backlash_response import orbit_summary

    return {"starts": census.starts, "unresolved_share": census.unresolved, "unbounded_share": census.unbounded,
            "orbits": [{**orbit_summary(item.response), "basin_share": item.basin_share,
                        "start_count": item.start_count, "reached_from_rest": item.from_rest}
                       for item in census.orbits]}



def case_stable_orbits(built, model: str, starts: int = 16, speed_rpm: float | None = None,
                       progress=None) -> DrivetrainOrbitCensus:
    """:func:`drivetrain_stable_orbits` of a case's drivetrain (``built``: a
    :class:`~thermogear.drivetrain.case_model.CaseDrivetrain`) for one mesh ``model`` at a pinion speed [rpm]
    (default the case's), solved as ``run`` solves its orbit (the case's points per period, sub-steps and modal
    cut-off), each start run in over the case's ``dynamics.transient_periods``."""
    from thermogear.drivetrain.case_model import SAMPLES_PER_PIECE, backlash_substeps

    state = built.models[model].state(speed_rpm=speed_rpm, points_per_period=built.dynamics.points_per_period)
    return drivetrain_stable_orbits(built.assembled(model), state, starts, built.dynamics.transient_periods,
                                    backlash_substeps(state.grid.nodes.size - 1), SAMPLES_PER_PIECE,
                                    built.section.response_cutoff_hz, progress=progress)
