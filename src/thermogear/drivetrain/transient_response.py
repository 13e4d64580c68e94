"""The drivetrain's motion from rest: q = q̇ = 0 (in the coordinates without the free rotation) when the torque and
the mesh act at τ = 0, over N mesh periods, by the exact flow of the piecewise-linear system with (backlash mesh)
or without (mesh in permanent contact) its switches (:mod:`thermogear.dynamics.backlash.backlash_trajectory`): no
integration error beyond the exponentials. The samples and forces are those of
:mod:`thermogear.drivetrain.backlash_response`; the metrics are those of the last period, which approaches the
periodic orbit as the slowest Floquet multiplier's modulus to the power N.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

import numpy as np

from thermogear.drivetrain.assembly import AssembledDrivetrain
from thermogear.drivetrain.backlash_response import (PeriodForces, SampledMotion, one_blas_thread,
                                                    mesh_contacts, reduced_backlash_system, sampled_metrics,
                                                    sampled_motion, train_mesh_responses)
from thermogear.drivetrain.response import drivetrain_backlash_system, drivetrain_periodic_system, train_problems
from thermogear.drivetrain.static_state import bearing_moments
from thermogear.drivetrain.train import MeshTrain
from thermogear.dynamics.backlash.backlash_trajectory import backlash_trajectory, linear_trajectory
from thermogear.errors import CaseError
from thermogear.mesh.state import MeshState

__all__ = ["DrivetrainTransient", "drivetrain_transient"]

_ORBIT_KEYS = ("floquet_multipliers_abs", "converged", "stable", "valid")  # no orbit: these do not apply


@dataclass(frozen=True, eq=False)
class DrivetrainTransient:
    """The motion from rest: ``time`` (S,) [s] over ``periods`` mesh periods of ``period`` [s]; ``motion`` its
    samples (δ, its rate, the mesh and bearing forces, no displacement of every DOF: 60 periods of a 100-DOF
    drivetrain would hold about a gigabyte; :class:`~thermogear.drivetrain.backlash_response.SampledMotion`);
    ``region`` (S,) of the mesh; ``backlash`` whether the mesh may separate; ``end_state`` the solver's state after
    the last period; ``last_period`` the metrics of the last period (keys of
    :func:`~thermogear.drivetrain.backlash_response.sampled_metrics` less the orbit's) and ``last_period_forces`` its
    bearing forces. A train: ``period`` the common period, the fields above
    the first mesh's, ``meshes`` each mesh's last period (δ, force, metrics) by name."""

    time: np.ndarray
    motion: SampledMotion
    region: np.ndarray
    backlash: bool
    end_state: np.ndarray
    last_period: dict[str, Any]
    last_period_forces: PeriodForces
    period: float
    periods: int
    meshes: dict = field(default_factory=dict)

    @property
    def transmission_error(self) -> np.ndarray:
        """δ = wᵀq [m] at the samples."""
        return self.motion.transmission_error


def drivetrain_transient(assembled: AssembledDrivetrain, state: MeshState | MeshTrain, periods: int,
                         backlash: bool = True,
                         samples_per_piece: int = 8, substeps: int = 16,
                         cutoff_hz: float | None = None) -> DrivetrainTransient:
    """The motion from rest over ``periods`` mesh periods (module docstring): with ``backlash`` the backlash mesh
    (and every bearing clearance), else the linear mesh in permanent contact; ``samples_per_piece`` per piece;
    ``substeps`` per piece to find the switches; ``cutoff_hz`` [Hz] solves on the modes up to it plus the static
    corrections (:func:`~thermogear.drivetrain.backlash_response.reduced_backlash_system`, as the periodic orbit),
    None on every DOF. Rest is q = q̇ = 0 on either basis (the basis holds the rest state exactly)."""
    if isinstance(periods, bool) or int(periods) != periods or periods < 1:
        raise CaseError("periods", periods, "integer >= 1", "whole mesh periods of the motion from rest")
    train = isinstance(state, MeshTrain) and len(state.states) > 1
    problem = train_problems(state)[0][0] if train else (
        state.states[0] if isinstance(state, MeshTrain) else state).problem()
    basis = None
    if backlash:
        system, reduction = drivetrain_backlash_system(assembled, state)
        if cutoff_hz is not None:
            system, basis = reduced_backlash_system(system, cutoff_hz)
        start = np.zeros(2 * system.linear.size)
        with one_blas_thread():
            # the extrema only where maxima are read: the last period's metrics
            trajectory = backlash_trajectory(system, start, int(periods), samples_per_piece, substeps,
                                             system.mesh_vector, extremum_periods=1)
        deviation, gap = system.deviation, system.backlash
    else:
        linear, reduction = drivetrain_periodic_system(assembled, state)
        if cutoff_hz is not None:
            from thermogear.dynamics.modes.modal_reduction import modal_basis

            basis = modal_basis(linear, 2.0 * np.pi * cutoff_hz)
            linear = basis.reduce(linear)
        trajectory = linear_trajectory(linear, np.zeros(2 * linear.size), int(periods), samples_per_piece)
        deviation = np.divide(linear.force_factor, linear.stiffness_factor,
                              out=np.zeros_like(linear.force_factor), where=linear.stiffness_factor != 0.0)
        deviation = deviation[:, 0] if deviation.ndim == 2 else deviation  # a train: the first mesh's
        gap = np.inf
    motion = sampled_motion(assembled, problem, reduction, basis, trajectory, deviation, gap, every_dof=False)
    last = trajectory.last_period()
    meshes = {}
    if train:  # each mesh from its own dead zone, or in permanent contact from its own deviation
        if backlash:
            contacts = mesh_contacts(system, last)
        else:
            factors = linear.stiffness_factor
            deviations = np.divide(linear.force_factor, factors, out=np.zeros_like(factors), where=factors != 0.0)
            contacts = [(last, deviations[:, column], np.inf) for column in range(factors.shape[1])]
        meshes, last_motion = train_mesh_responses(assembled, state, reduction, basis, contacts, np.zeros(0), True)
        metrics = dict(next(iter(meshes.values())).metrics)
    else:
        last_motion = sampled_motion(assembled, problem, reduction, basis, last, deviation, gap)
        metrics = sampled_metrics(problem, last, last_motion, np.zeros(0), True)
    for values in [metrics] + [item.metrics for item in meshes.values()]:
        for key in _ORBIT_KEYS:
            values.pop(key, None)
    return DrivetrainTransient(trajectory.time, motion, trajectory.region, bool(backlash), trajectory.end_state,
                               metrics, PeriodForces(last.time, last_motion.bearing_forces, problem.period,
                                                     bearing_moments(assembled, last_motion.displacement)),
                               problem.period, int(periods), meshes)

