"""The sampled period of a drivetrain's motion with the backlash mesh: the solver's samples on every DOF with δ,
the mesh and bearing forces (:class:`SampledMotion`), the metrics of one period (:func:`sampled_metrics`; the forces
and metrics are defined in :mod:`thermogear.drivetrain.backlash_response`), and for a train of several meshes each
mesh's own period (:func:`train_mesh_responses`: its region from its own dead zone, :func:`mesh_trajectory`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace
from typing import Any

import numpy as np

from thermogear.drivetrain.assembly import AssembledDrivetrain
from thermogear.drivetrain.response import MeshResponse, bearing_dofs, bearing_forces, train_problems
from thermogear.drivetrain.train import MeshTrain
from thermogear.dynamics.backlash.backlash_ndof import (BACK_CONTACT, DRIVING_CONTACT, FREE_FLIGHT, BacklashSystem,
                                                        MeshZone)
from thermogear.dynamics.backlash.backlash_trajectory import BacklashTrajectory
from thermogear.dynamics.results.metrics import sampled_load
from thermogear.dynamics.results.period_metrics import (contact_loss_summary, contact_time_metrics, dte_statistics,
                                                        frequency_metrics, load_metrics, multiplier_moduli,
                                                        pair_load_maximum)

__all__ = ["SampledMotion", "mesh_contacts", "mesh_trajectory",
           "sampled_metrics", "sampled_motion", "train_mesh_responses"]


def mesh_trajectory(trajectory: BacklashTrajectory, zone: int) -> BacklashTrajectory:
    """The trajectory as a further mesh of a train sees it (its
    :class:`~thermogear.dynamics.backlash.backlash_ndof.MeshZone` is dead zone ``zone``): its region from the zone's
    side (+1 driving, 0 free flight, −1 back flanks), its time without contact and on the back flanks summed over the
    samples (every switch of every dead zone is sampled on both sides and every node, so between two samples of
    different instants the region holds: exact), its switches
    the changes of region between samples."""
    sides = trajectory.sides[:, zone]
    region = np.where(sides > 0, DRIVING_CONTACT, np.where(sides < 0, BACK_CONTACT, FREE_FLIGHT))
    steps, held = np.diff(trajectory.time), region[1:]
    return replace(trajectory, region=region, switches=int(np.count_nonzero(held != region[:-1])),
                   free_flight_time=float(np.sum(steps[held == FREE_FLIGHT])),
                   back_contact_time=float(np.sum(steps[held == BACK_CONTACT])))


def mesh_contacts(system: BacklashSystem, trajectory: BacklashTrajectory) -> list[tuple]:
    """Per mesh of a train's backlash system (the system's own first, then each
    :class:`~thermogear.dynamics.backlash.backlash_ndof.MeshZone` by its column): (the trajectory as that mesh sees it,
    its
    deviation per piece [m], its backlash [m]), for :func:`train_mesh_responses`."""
    zones = sorted((zone.column, index) for index, zone in enumerate(system.dead_zones) if isinstance(zone, MeshZone))
    return [(trajectory, system.deviation, system.backlash)] + [
        (mesh_trajectory(trajectory, index), system.dead_zones[index].deviation, system.dead_zones[index].backlash)
        for _, index in zones]


def train_mesh_responses(assembled: AssembledDrivetrain, train: MeshTrain, reduction, basis, contacts: list[tuple],
                         multipliers: np.ndarray, converged: bool) -> tuple[dict[str, MeshResponse], SampledMotion]:
    """(each mesh's δ, force and metrics over the common period by name, the first mesh's sampled motion) of a
    train's sampled motion: each mesh with its own problem on the common pieces and its ``contacts`` entry
    (trajectory as it sees it, deviation, backlash: :func:`mesh_contacts`; in permanent contact the trajectory, its
    deviation and an infinite backlash), its mesh frequency its own (as the linear train's metrics)."""
    on_grid, own, _ = train_problems(train)
    meshes, first = {}, None
    for column, (mesh, (seen, deviation, backlash)) in enumerate(zip(assembled.drivetrain.meshes, contacts)):
        motion = sampled_motion(assembled, on_grid[column], reduction, basis, seen, deviation, backlash, column)
        metrics = sampled_metrics(on_grid[column], seen, motion, multipliers, converged)
        metrics["mesh_frequency_hz"] = own[column].mesh_frequency
        metrics["frequency_ratio"] = own[column].mesh_frequency / metrics["natural_frequency_hz"]
        meshes[mesh.name] = MeshResponse(motion.transmission_error, motion.transmission_error_rate, motion.mesh_force,
                                         metrics, own[column].period)
        first = motion if first is None else first
    return meshes, first


@dataclass(frozen=True, eq=False)
class SampledMotion:
    """A sampled motion: ``displacement`` (S, DOFs) on every DOF (None where only δ and the forces were formed, e.g.
    the whole motion from rest), δ = wᵀq [m] and its rate [m/s], the ``mesh_force`` k_j·φ(g) + c_j·ġ and its elastic
    part k_j·φ(g) [N], ``bearing_forces`` name → (S, 3) [N]."""

    displacement: np.ndarray | None
    transmission_error: np.ndarray
    transmission_error_rate: np.ndarray
    mesh_force: np.ndarray
    elastic_force: np.ndarray
    bearing_forces: dict[str, np.ndarray]


def sampled_motion(assembled: AssembledDrivetrain, problem, reduction, basis, trajectory: BacklashTrajectory,
                   deviation: np.ndarray, backlash: float, mesh: int = 0, every_dof: bool = True) -> SampledMotion:
    """The trajectory (in the solver's coordinates) on every DOF with δ and the forces of the module docstring;
    ``deviation`` ē_j [m] per piece and the ``backlash`` b [m] of the mesh coordinate g = δ − ē_j of the
    drivetrain's ``mesh``-th mesh (``trajectory.region`` its region). Without ``every_dof`` only δ, its rate and the
    bearings' DOFs are formed (``displacement`` None): what a long motion needs, at a fraction of the memory."""
    expansion, w = reduction.expansion(None if basis is None else basis.basis), assembled.mesh_vectors[mesh]
    if every_dof:
        displacement = trajectory.displacement @ expansion.T
        velocity = trajectory.velocity @ expansion.T
        delta, rate, forces = displacement @ w, velocity @ w, bearing_forces(assembled, displacement, velocity)
    else:
        on_mesh, dofs = expansion.T @ w, bearing_dofs(assembled)
        delta, rate = trajectory.displacement @ on_mesh, trajectory.velocity @ on_mesh
        rows = expansion[dofs].T
        displacement, forces = None, bearing_forces(assembled, trajectory.displacement @ rows,
                                                    trajectory.velocity @ rows, dofs=dofs)
    piece, region = trajectory.piece, trajectory.region
    gap = delta - deviation[piece]
    elastic = np.where(region == DRIVING_CONTACT, gap, np.where(region == BACK_CONTACT, gap + backlash, 0.0))
    elastic = problem.stiffness[piece] * elastic
    return SampledMotion(displacement, delta, rate, elastic + problem.damping[piece] * rate, elastic, forces)


def sampled_metrics(problem, trajectory: BacklashTrajectory, motion: SampledMotion, multipliers: np.ndarray,
                    converged: bool) -> dict[str, Any]:
    """The module docstring's metrics of one sampled period (of an orbit, or the last of a motion)."""
    delta, rate, elastic = motion.transmission_error, motion.transmission_error_rate, motion.elastic_force
    w0, period, piece = problem.static_load, problem.period, trajectory.piece
    driving = trajectory.region == DRIVING_CONTACT
    pair, pair_loads, single_loads = problem.pair_arrays(), None, None
    if pair is not None:
        loads = sampled_load(pair[0], pair[1], problem.pair_offset, piece, delta, rate, False)
        pair_loads = np.where(driving[None, :], loads, 0.0)
    elif np.any(problem.contact_count == 1):
        single_loads = np.where((problem.contact_count[piece] == 1) & driving, elastic, 0.0)
    max_pair, basis = pair_load_maximum(pair_loads, single_loads)
    dte = dte_statistics(trajectory.time, delta)
    moduli = multiplier_moduli(multipliers)
    stable = bool(converged and moduli.size and moduli[0] < 1.0)
    free = trajectory.region == FREE_FLIGHT
    starts, durations = _runs(trajectory.time, free)
    max_system = float(np.max(elastic))
    metrics: dict[str, Any] = {
        **load_metrics(w0, problem.face_width, max_pair, basis, max_system), **dte,
        "max_velocity": float(np.max(np.abs(rate))), **frequency_metrics(problem),
        "floquet_multipliers_abs": [float(m) for m in moduli], "converged": bool(converged), "stable": stable,
        "contact_loss": contact_loss_summary(trajectory.free_flight_time > 0.0, starts, durations,
                                             trajectory.free_flight_time / trajectory.periods, np.min(elastic), w0),
        **contact_time_metrics(trajectory.free_flight_time, trajectory.back_contact_time, trajectory.switches,
                               period * trajectory.periods, trajectory.periods, trajectory.back_contact_time > 0.0),
    }
    finite = all(math.isfinite(value) for value in (dte["dte_mean"], dte["dte_rms"], max_system)
                 + (() if max_pair is None else (max_pair,)))
    metrics["valid"] = bool(converged and stable and finite)
    return metrics


def _runs(time: np.ndarray, mask: np.ndarray) -> tuple[list[float], list[float]]:
    """Start times and durations [s] of the runs of ``mask`` (a run ends at the first sample outside it, which a
    switch's right-side sample places at the switch)."""
    edges = np.diff(np.concatenate([[0], mask.astype(np.int8), [0]]))
    first, last = np.flatnonzero(edges == 1), np.flatnonzero(edges == -1)
    starts = [float(time[a]) for a in first]
    durations = [float(time[min(b, time.size - 1)] - time[a]) for a, b in zip(first, last, strict=True)]
    return starts, durations
