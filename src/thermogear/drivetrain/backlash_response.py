"""The drivetrain with the backlash mesh: its periodic orbit sampled in time, the mesh and bearing forces, metrics.

The system is :func:`~thermogear.drivetrain.response.drivetrain_backlash_system` (the mesh coordinate
g = wᵀq − ē_j with the dead zone of the normal backlash b; a bearing with a radial clearance adds a dead zone in x and
one in y). Its periodic orbit is found by shooting
(:func:`~thermogear.dynamics.backlash.backlash_ndof.backlash_periodic_orbit`) and sampled exactly
(:func:`~thermogear.dynamics.backlash.backlash_trajectory.backlash_trajectory`). Forces:

* mesh force F = k_j·φ(g) + c_j·ġ [N] with φ(g) = g in driving contact, 0 in free flight and g + b on the back
  flanks (Kahraman & Singh, J. Sound Vib. 142 (1990) 49). The mesh damping c_j acts in free flight too, as in the
  :class:`~thermogear.dynamics.backlash.backlash_ndof.BacklashSystem` (its vector field is continuous at a contact
  switch);
* bearing force on the housing per direction: K·u + C·u̇ without clearance; with a radial clearance δ, in x and in y
  each, 0 for |u| <= δ and k(u ∓ δ) + c·u̇ beyond ±δ (a square dead zone, the stated approximation of a circular
  clearance: see :class:`~thermogear.drivetrain.point_elements.Bearing`).

Metrics (keys of the linear :class:`~thermogear.drivetrain.response.DrivetrainResponse` where they mean the same):
``kv`` = max pair load / W (W the static normal load, the pair load the elastic share k_s(δ − e_s) of a pair on the
driving flanks, zero off them; as the linear chain and as the 1-DOF backlash solver's Kv without damping force —
where no pair stiffness is known, the mesh's elastic force in single contact); ``max_system_load`` the largest
elastic mesh force k_j·φ(g); ``contact_loss_fraction`` the free-flight time over the period (exact: summed over the
segments between located switches) and ``back_contact_fraction`` likewise on the back flanks; DTE mean, RMS and
peak-to-peak of δ over the samples (trapezoid rule; every switch and node sampled on both sides, and every extremum
of δ, so that the maxima of the forces, monotone in δ on a piece in one contact region, and the peak-to-peak are
exact).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field, replace
from typing import Any

import numpy as np

from thermogear.drivetrain.assembly import AssembledDrivetrain
from thermogear.drivetrain.response import (BearingSpectra, MeshResponse, PeriodicMotion, bearing_forces,
                                            drivetrain_backlash_system)
from thermogear.drivetrain.sampled_period import (SampledMotion, mesh_contacts, mesh_trajectory,  # noqa: F401
                                                  sampled_metrics, sampled_motion, train_mesh_responses)
from thermogear.drivetrain.static_state import bearing_moments
from thermogear.drivetrain.train import MeshTrain
from thermogear.dynamics.backlash.backlash_ndof import (PERIODIC_SOLVES, WATCH_STARTUP, BacklashSystem,
                                              backlash_periodic_orbit)
from thermogear.dynamics.backlash.backlash_orbits_ndof import StartupOrbit, startup_orbit
from thermogear.dynamics.backlash.backlash_trajectory import BacklashTrajectory, backlash_trajectory
from thermogear.errors import CaseError, ModelLimitError, ProblemError
from thermogear.mesh.state import MeshState

__all__ = ["SHOOTING_TOLERANCE", "DrivetrainBacklashResponse", "PeriodForces", "SampledMotion", "bearing_forces",
           "drivetrain_backlash_response", "mesh_trajectory", "one_blas_thread", "orbit_summary",
           "reduced_backlash_system", "sampled_metrics", "sampled_motion", "train_mesh_responses"]


#: Relative residual |φ_T(z₀) − z₀| the shooting must reach. A drivetrain's stiff coordinates leave a rounding floor
#: above the 1e-10 of the small systems: measured 4.4e-10 at the linear orbit of fzg_rig_type_c (107 coordinates,
#: 1024 intervals), so Newton could never meet 1e-10 there; 1e-8 is 20× above that floor and far below what Kv or
#: the DTE resolve (an orbit off by 1e-8 of its state moves them by ~1e-8).
SHOOTING_TOLERANCE = 1e-8


@dataclass(frozen=True, eq=False)
class DrivetrainBacklashResponse(PeriodicMotion):
    """Periodic response with backlash over one mesh period (module docstring): ``time`` (S,) [s] (a switch
    instant twice, left side first); ``transmission_error`` δ = wᵀq [m] and its ``transmission_error_rate``
    [m/s]; ``mesh_force`` [N]; ``bearing_forces`` name → (S, 3) on the housing in x, y, z [N]; ``displacement``
    (S, DOFs) [SI]; ``region`` (S,) the mesh's contact region; Floquet ``multipliers``; ``converged``; ``failure``
    why not ('' when converged); ``switches`` of the mesh per period; ``contact_loss_fraction`` and
    ``back_contact_fraction`` [-]; ``metrics``; ``period`` [s]; ``notes`` what the reader must know (two coexisting
    orbits, a start-up that settled on none); a train (several meshes): ``period`` the common period, the fields
    above the first mesh's and ``meshes`` each mesh's δ, force and metrics (contact loss of its own dead zone)
    by name."""

    region: np.ndarray
    multipliers: np.ndarray
    converged: bool
    failure: str
    switches: int
    contact_loss_fraction: float
    back_contact_fraction: float
    metrics: dict[str, Any]
    period: float
    notes: tuple[str, ...] = ()
    bearing_moments: dict[str, np.ndarray] = field(default_factory=dict)  # name → (S, 2) [N·m] about x, y
    meshes: dict[str, MeshResponse] = field(default_factory=dict)

    @property
    def stable(self) -> bool:
        """Converged with every Floquet multiplier inside the unit circle."""
        return bool(self.converged and self.multipliers.size and np.abs(self.multipliers).max() < 1.0)

    @property
    def bearing_names(self) -> tuple[str, ...]:
        """The bearings' names (also where no orbit was found)."""
        return tuple(self.metrics.get("bearings", ())) or tuple(self.bearing_forces)

    @property
    def kv(self) -> float | None:
        """Dynamic factor Kv [-] (``metrics["kv"]``), None where the orbit was not found."""
        return self.metrics.get("kv") if self.converged else None


@dataclass(frozen=True, eq=False)
class PeriodForces(BearingSpectra):
    """The bearing forces of one mesh period: ``time`` (S,) [s] from 0 to ``period`` [s], ``bearing_forces``
    name → (S, 3) [N] (e.g. the last period of a motion from rest)."""

    time: np.ndarray
    bearing_forces: dict[str, np.ndarray]
    period: float
    bearing_moments: dict[str, np.ndarray] = field(default_factory=dict)  # name → (S, 2) [N·m] about x, y


def one_blas_thread():
    """A context in which BLAS runs on one thread (threadpoolctl). The backlash flow multiplies small matrices (~200²)
    thousands of times, where BLAS threads only contend: on the loaded 2-core development machine fzg_rig_type_c's
    response took 27 s CPU on one thread and had not finished after 9 min of CPU with the default threads."""
    from threadpoolctl import threadpool_limits

    return threadpool_limits(limits=1, user_api="blas")


def reduced_backlash_system(system: BacklashSystem, cutoff_hz: float):
    """(the system on a modal basis, the basis): the modes of the mean system up to ``cutoff_hz`` [Hz] and the
    static corrections of the mesh vector, the torque loads and every dead zone's vector
    (:func:`thermogear.dynamics.modes.modal_reduction.modal_basis`), so that each contact state's quasi-static response
    stays in the basis."""
    from thermogear.dynamics.modes.modal_reduction import modal_basis

    if not math.isfinite(cutoff_hz) or cutoff_hz <= 0.0:
        raise CaseError("cutoff_hz", cutoff_hz, "> 0 Hz, finite", "the highest mode frequency kept")
    basis = modal_basis(system.linear, 2.0 * math.pi * cutoff_hz, [zone.vector for zone in system.dead_zones])
    b = basis.basis
    zones = tuple(replace(zone, vector=b.T @ zone.vector) for zone in system.dead_zones)
    return BacklashSystem(basis.reduce(system.linear), b.T @ system.mesh_vector, system.deviation, system.backlash,
                          zones, system.pattern_meshes, system.back_shift), basis


def drivetrain_backlash_response(assembled: AssembledDrivetrain, state: MeshState | MeshTrain,
                                 initial_state: np.ndarray | None = None, substeps: int = 16,
                                 samples_per_piece: int = 8, cutoff_hz: float | None = None,
                                 tolerance: float = SHOOTING_TOLERANCE,
                                 startup_periods: int | None = None, solves=None) -> DrivetrainBacklashResponse:
    """The periodic orbit of the drivetrain with the backlash mesh (module docstring), shot from
    ``initial_state`` (in the solver's coordinates, e.g. a neighbouring speed's ``metrics["initial_state"]``) or
    from the linear periodic state; ``substeps`` per piece to find the switches; ``samples_per_piece`` samples per
    piece; ``cutoff_hz`` [Hz] solves on a modal basis (:func:`reduced_backlash_system`), None on every DOF;
    ``tolerance`` the shooting's relative residual.

    ``startup_periods``: also start from rest and run in over this many mesh periods before shooting
    (:func:`~thermogear.dynamics.backlash.backlash_orbits_ndof.startup_orbit`). Where the start-up settles on another
    stable orbit than the one shot from the linear state, both coexist: the start-up's orbit is returned (what the
    gearbox shows after starting up) and the other is described in ``metrics["startup"]["coexisting"]``; ``metrics
    ["startup"]`` also says which start reached the orbit returned, its ``branch`` ("low" or "high" by the DTE
    peak-to-peak, as the 1-DOF response; "unique" where one orbit was seen) and ``notes`` say so in words.

    ``solves``: a :class:`~thermogear.dynamics.periodic_orbits.periodic_solves.PeriodicSolves` that keeps the
    switch-free orbit's periodic solve (the linear periodic state, every contact closed) for a later linear response of
    the same
    reduced system, or hands it over where that system was solved before."""
    system, reduction = drivetrain_backlash_system(assembled, state)
    basis = None
    if cutoff_hz is not None:
        system, basis = reduced_backlash_system(system, cutoff_hz)
    bearings = [bearing.name for bearing in assembled.drivetrain.bearings]
    recovered: tuple[str, ...] = ()
    try:
        cache: dict = {}  # the pieces' exponentials, computed by the shooting and reused by the sampling
        if startup_periods is not None:  # the switch-free orbit's solve also prepares the start-up check's motion
            cache[WATCH_STARTUP] = True
        if solves is not None:
            cache[PERIODIC_SOLVES] = solves
        with one_blas_thread():
            orbit = backlash_periodic_orbit(system, initial_state, substeps, tolerance, cache=cache)
            startup = None
            if startup_periods is not None:
                try:  # a start from rest (where Newton failed from the linear state, it may settle there)
                    startup = startup_orbit(system, orbit if orbit.converged else None, int(startup_periods),
                                            orbit.substeps, tolerance, cache=cache)
                except (ProblemError, ModelLimitError, np.linalg.LinAlgError) as error:
                    startup = StartupOrbit(None, False, True, int(startup_periods), f"{error}")
            if startup is not None and not orbit.converged:
                if startup.orbit is not None:
                    reason = orbit.failure
                    orbit, startup = startup.orbit, None
                    recovered = (f"shot from the linear solution the orbit was not found ({reason}); the motion from "
                                 f"rest, run in over {int(startup_periods)} mesh periods and shot, settled on the "
                                 "orbit reported",)
            trajectory = backlash_trajectory(system, orbit.initial_state, 1, samples_per_piece, orbit.substeps,
                                             system.mesh_vector, cache)
            other = None
            if startup is not None and startup.orbit is not None and not startup.same:
                other = backlash_trajectory(system, startup.orbit.initial_state, 1, samples_per_piece,
                                            startup.orbit.substeps, system.mesh_vector, cache)
        failure = orbit.failure
    except (ProblemError, ModelLimitError, np.linalg.LinAlgError) as error:
        return _failed(state, f"no orbit: {error}", bearings)
    shot = _response(assembled, state, system, reduction, basis, trajectory, orbit.initial_state, orbit.multipliers,
                     orbit.converged, failure, orbit.switches)
    if startup is None:
        if recovered:
            shot.metrics["startup"] = {"reached_from": "rest", "branch": "unique", "startup_settled": True,
                                       "left_contact_from_rest": True, "run_in_periods": int(startup_periods),
                                       "coexisting": []}
        return replace(shot, notes=recovered)
    if other is None:
        settled = startup.orbit is not None
        why = f" ({startup.failure})" if startup.failure else ""
        if not shot.converged:
            return replace(shot, failure=(
                f"{shot.failure}; the motion from rest, run in over 2 × {startup.run_in_periods} mesh periods, settled "
                f"on no stable one-period orbit either{why}: the motion may be non-periodic or repeat over several "
                "periods (`--method transient` follows it)"))
        note = () if settled else (
            f"the motion from rest settled on no stable one-period orbit within 2 × {startup.run_in_periods} mesh "
            f"periods{why}: the orbit shot from the linear solution is reported; a start-up may show another "
            "motion (`--method transient` follows it)",)
        shot.metrics["startup"] = {"reached_from": "rest and the linear solution" if settled else "the linear solution",
                                   "branch": "unique", "startup_settled": settled,
                                   "left_contact_from_rest": startup.left_contact_state,
                                   "run_in_periods": startup.run_in_periods, "coexisting": []}
        return replace(shot, notes=note)
    reached = _response(assembled, state, system, reduction, basis, other, startup.orbit.initial_state,
                        startup.orbit.multipliers, startup.orbit.converged, startup.orbit.failure,
                        startup.orbit.switches)
    own, theirs = reached.metrics["dte_peak_to_peak"], shot.metrics["dte_peak_to_peak"]
    branch, other_branch = ("low", "high") if own < theirs else ("high", "low")
    reached.metrics["startup"] = {
        "reached_from": "rest", "branch": branch, "startup_settled": True, "left_contact_from_rest": True,
        "run_in_periods": startup.run_in_periods,
        "coexisting": [{**orbit_summary(shot), "reached_from": "the linear solution", "branch": other_branch}]}
    note = (f"two stable orbits coexist at this operating point: a start from rest (run in over "
            f"{startup.run_in_periods} mesh periods, then shot) settles on the {branch} branch (Kv "
            f"{_shown(reached.kv)}, contact loss {reached.contact_loss_fraction:.3f}), which is reported; shot from "
            f"the linear solution the orbit is the {other_branch} branch (Kv {_shown(shot.kv)}, contact loss "
            f"{shot.contact_loss_fraction:.3f}). The multi-start search (`thermogear run CASE --multistart N`; in "
            "Python thermogear.drivetrain.backlash_orbits.drivetrain_stable_orbits) lists every stable orbit a grid "
            "of starts finds, with its basin share",)
    return replace(reached, notes=note)


def _shown(value) -> str:
    return "not found" if value is None else f"{value:.4g}"


def orbit_summary(response: DrivetrainBacklashResponse) -> dict[str, Any]:
    """The numbers that tell one orbit from another: Kv, DTE RMS and peak-to-peak [μm], contact-loss and
    back-contact fractions, the largest Floquet multiplier's modulus, stable."""
    metrics = response.metrics
    return {"kv": response.kv, "dte_rms_um": metrics.get("dte_rms", math.nan) * 1e6,
            "dte_peak_to_peak_um": metrics.get("dte_peak_to_peak", math.nan) * 1e6,
            "contact_loss_fraction": response.contact_loss_fraction,
            "back_contact_fraction": response.back_contact_fraction,
            "largest_floquet_multiplier_abs": float(np.abs(response.multipliers).max())
            if response.multipliers.size else None, "stable": response.stable}


def _failed(state: MeshState | MeshTrain, failure: str, bearings: list[str]) -> DrivetrainBacklashResponse:
    """A response that carries no motion, only why."""
    period = state.period if isinstance(state, MeshTrain) else state.problem().period
    state = state.states[0] if isinstance(state, MeshTrain) else state
    empty = np.zeros(0)
    metrics = {"static_load": state.normal_load, "kv": None, "valid": False, "converged": False, "stable": False,
               "bearings": bearings}
    return DrivetrainBacklashResponse(empty, empty, empty, empty, {}, np.zeros((0, 0)), np.zeros(0, dtype=int),
                                      empty, False, failure, 0, math.nan, math.nan, metrics, period)


def _response(assembled: AssembledDrivetrain, state: MeshState, system: BacklashSystem, reduction, basis,
              trajectory: BacklashTrajectory, initial_state: np.ndarray, multipliers: np.ndarray, converged: bool,
              failure: str, switches: int) -> DrivetrainBacklashResponse:
    """The sampled orbit expanded to every DOF, with δ, the forces and the metrics (of every mesh of a train)."""
    meshes = {}
    if isinstance(state, MeshTrain) and len(state.states) > 1:
        meshes, motion = train_mesh_responses(assembled, state, reduction, basis, mesh_contacts(system, trajectory),
                                              multipliers, converged)
        metrics = dict(next(iter(meshes.values())).metrics)
        period = state.period
    else:
        state = state.states[0] if isinstance(state, MeshTrain) else state
        problem = state.problem()
        motion = sampled_motion(assembled, problem, reduction, basis, trajectory, system.deviation, system.backlash)
        metrics = sampled_metrics(problem, trajectory, motion, multipliers, converged)
        period = problem.period
    metrics["initial_state"] = [float(value) for value in initial_state]
    return DrivetrainBacklashResponse(trajectory.time, motion.transmission_error, motion.transmission_error_rate,
                                      motion.mesh_force, motion.bearing_forces, motion.displacement,
                                      trajectory.region, multipliers, bool(converged), failure, int(switches),
                                      trajectory.free_flight_time / period, trajectory.back_contact_time / period,
                                      metrics, period, meshes=meshes,
                                      bearing_moments=bearing_moments(assembled, motion.displacement))
