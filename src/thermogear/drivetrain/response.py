"""The mesh feeds the drivetrain: the n-DOF time-periodic problem of one mesh period and its exact periodic response.

Over one mesh period the mesh model gives k(τ), c(τ), the excitation Σk_i·e_i of the unloaded deviations and the
normal load W (a :class:`~thermogear.mesh.state.MeshState`). On a drivetrain with the mesh vector w this is

    M q̈ + (C + Ω·G + c(τ) w wᵀ) q̇ + (K + k(τ) w wᵀ) q = T + (Σk_i e_i)(τ)·w,

T the torque pair s·r_b1·W, s·r_b2·W on the two gears, Ω the pinion speed (Kahraman, Ozguven, Houser & Zakrajsek,
J. Mech. Des. 114 (1992) 507; Velex & Maatar, J. Sound Vib. 191 (1996) 629 for the time-varying mesh). In the limit of
rigid shafts and bearings δ = wᵀq obeys the 1-DOF equation me·δ̈ + c·δ̇ + k·(δ) = W + Σk_i e_i of the mesh state with
me = J₁J₂/(J₁r_b2² + J₂r_b1²). The free torsional rotation is removed (rigid_body_reduction); the orbit is the exact
periodic state (:mod:`thermogear.dynamics.periodic_ndof`). Outputs: dynamic transmission error δ(t) = wᵀq, the mesh
force and the metrics of the 1-DOF chain (Kv, …) computed from δ, and the force of each bearing on its housing
F_b = K_b·u + C_b·u̇ with its spectrum in mesh harmonics.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass, replace
from typing import Any

import numpy as np

from thermogear.drivetrain.assembly import AssembledDrivetrain
from thermogear.drivetrain.static_state import mesh_torque_forces
from thermogear.dynamics.backlash_ndof import BacklashSystem
from thermogear.dynamics.metrics import compute_metrics
from thermogear.dynamics.periodic_ndof import PiecewiseLinearSystem, periodic_response
from thermogear.dynamics.rigid_body import RigidBodyReduction, rigid_body_reduction
from thermogear.dynamics.spectra import harmonic_spectrum
from thermogear.errors import CaseError
from thermogear.mesh.state import MeshState

__all__ = ["DrivetrainResponse", "bearing_force_spectrum", "bearing_forces", "drivetrain_backlash_system", "drivetrain_periodic_system",
           "drivetrain_periodic_response", "drivetrain_speed_sweep"]


def drivetrain_periodic_system(assembled: AssembledDrivetrain,
                               state: MeshState) -> tuple[PiecewiseLinearSystem, RigidBodyReduction]:
    """The reduced piecewise-constant system of one mesh period and the reduction q = Q p.

    The drivetrain's single mesh takes the state's k(τ), c(τ), deviations and load; its gear 1 (the pinion) must
    sit on the first shaft, whose speed is the state's pinion speed (for the gyroscopic terms).
    """
    return _periodic_system(assembled, state, state.problem(), None)


def _periodic_system(assembled: AssembledDrivetrain, state: MeshState, problem,
                     reduction: RigidBodyReduction | None) -> tuple[PiecewiseLinearSystem, RigidBodyReduction]:
    """:func:`drivetrain_periodic_system` with the state's problem given and, optionally, a rigid-body reduction
    from another state of the same drivetrain: Q depends only on M and the rigid modes, which no mesh state
    changes (the mesh stiffness joins the shafts whatever its value), so sharing it across speeds is exact."""
    drivetrain = assembled.drivetrain
    if len(drivetrain.meshes) != 1:
        raise CaseError("meshes", len(drivetrain.meshes), "exactly one mesh",
                        "one mesh state feeds one mesh (a second mesh has another period)")
    mesh = drivetrain.meshes[0]
    if mesh.gear_1.shaft != drivetrain.shafts[0].name:
        raise CaseError(f"{mesh.name}.gear_1", mesh.gear_1.shaft, f"the first shaft, {drivetrain.shafts[0].name!r}",
                        "the reference speed is the pinion's, on the first shaft")
    w = assembled.mesh_vectors[0]
    speed = state.speed_rpm * math.pi / 30.0
    damping = assembled.structure_damping + speed * assembled.gyroscopic
    if reduction is None:
        mean_stiffness = float(np.dot(problem.stiffness, np.diff(problem.nodes)) / problem.period)
        reduction = rigid_body_reduction(assembled.mass, assembled.connection_stiffness(mean_stiffness),
                                         assembled.rigid_candidates(), damping)
    reduced_w = reduction.project_vector(w)
    pattern = np.outer(reduced_w, reduced_w)
    load = state.normal_load
    system = PiecewiseLinearSystem(
        mass=reduction.project(assembled.mass), stiffness=reduction.project(assembled.structure_stiffness),
        damping=reduction.project(damping), force=reduction.project_vector(mesh_torque_forces(assembled, load)),
        nodes=problem.nodes, stiffness_pattern=pattern, stiffness_factor=problem.stiffness,
        damping_pattern=pattern, damping_factor=problem.damping, force_pattern=reduced_w,
        force_factor=problem.force_per_interval - load)
    return system, reduction


def drivetrain_backlash_system(assembled: AssembledDrivetrain,
                               state: MeshState) -> tuple[BacklashSystem, RigidBodyReduction]:
    """The drivetrain with the backlash mesh: one dead-zone coordinate g = wᵀq − ē_j of the normal backlash of the
    state (solve with :func:`thermogear.dynamics.backlash_ndof.backlash_periodic_orbit`).

    The pairs' deviations enter as their load-weighted mean on each interval, ē_j = Σk_i·e_i / Σk_i, so the whole
    mesh separates at once (unlike the 1-DOF backlash model, where each pair leaves contact on its own); the back
    flanks take the driving flanks' stiffness. Without deviations the two descriptions coincide. A bearing with a
    ``radial_clearance`` adds a dead zone in x and one in y (:class:`~thermogear.dynamics.backlash_ndof.DeadZone`).
    """
    if state.backlash is None:
        raise CaseError("backlash", None, "a mesh state whose backlash is known", "the dead zone needs its width")
    linear, reduction = drivetrain_periodic_system(assembled, state)
    excitation = linear.force_factor
    deviation = excitation / linear.stiffness_factor
    zones = [replace(zone, vector=reduction.project_vector(zone.vector)) for _, zone in assembled.dead_zones]
    return BacklashSystem(linear, linear.force_pattern, deviation, state.backlash, tuple(zones)), reduction


@dataclass(frozen=True, eq=False)
class DrivetrainResponse:
    """Periodic response over one mesh period: ``time`` (S,) [s]; ``transmission_error`` δ = wᵀq [m] and its rate
    [m/s]; ``mesh_force`` k(δ) − Σk_ie_i + c·δ̇ [N]; ``bearing_forces`` name → (S, 3) force on the housing in
    x, y, z [N]; ``displacement`` (S, DOFs) [SI]; Floquet ``multipliers``; ``metrics`` of the 1-DOF chain computed
    from δ (kv, dte_rms, …; see :func:`thermogear.dynamics.metrics.compute_metrics`)."""

    time: np.ndarray
    transmission_error: np.ndarray
    transmission_error_rate: np.ndarray
    mesh_force: np.ndarray
    bearing_forces: dict[str, np.ndarray]
    displacement: np.ndarray
    multipliers: np.ndarray
    metrics: dict[str, Any]
    period: float

    @property
    def kv(self) -> float | None:
        """Dynamic factor Kv [-] (max pair load over the static load, as the 1-DOF chain)."""
        return self.metrics["kv"]

    def bearing_spectrum(self, name: str, points: int = 1024) -> tuple[np.ndarray, np.ndarray]:
        """(frequencies [Hz] of the mesh harmonics 0, f_m, 2f_m, …; amplitudes (3, harmonics) [N] in x, y, z) of
        one bearing's force on its housing; harmonic 0 is the mean (static) force."""
        return bearing_force_spectrum(self.time, self.bearing_forces, name, self.period, points)


def bearing_force_spectrum(time: np.ndarray, forces: dict[str, np.ndarray], name: str, period: float,
                           points: int = 1024) -> tuple[np.ndarray, np.ndarray]:
    """(frequencies [Hz] of the mesh harmonics 0, 1/T, 2/T, …; amplitudes (3, harmonics) [N] in x, y, z) of
    ``forces[name]`` (S, 3) sampled at ``time`` over one ``period`` T [s]; harmonic 0 is the mean."""
    if name not in forces:
        raise CaseError("bearing", name, f"one of {sorted(forces)}", "bearing forces by name")
    amplitudes = []
    for axis in range(3):
        frequencies, values = harmonic_spectrum(time, forces[name][:, axis], period, points)
        amplitudes.append(values)
    return frequencies, np.array(amplitudes)


def drivetrain_periodic_response(assembled: AssembledDrivetrain, state: MeshState, samples_per_piece: int = 8,
                                 cutoff_hz: float | None = None) -> DrivetrainResponse:
    """Exact periodic response of the drivetrain to one mesh period (see the module docstring).

    ``cutoff_hz`` [Hz]: solve on the modes of the mean system up to this frequency plus the static corrections of
    the mesh vector and the torque loads (:mod:`thermogear.dynamics.modal_reduction`: the mesh compliance stays
    exact, the dynamics of the modes above the cut-off are lost); None solves on every DOF. A cut-off a few times
    the highest mesh harmonic of interest converges (see the tests).
    """
    return drivetrain_speed_sweep(assembled, (state,), samples_per_piece, cutoff_hz)[0]


def drivetrain_speed_sweep(assembled: AssembledDrivetrain, states: Sequence[MeshState], samples_per_piece: int = 8,
                           cutoff_hz: float | None = None) -> list[DrivetrainResponse]:
    """:func:`drivetrain_periodic_response` at each mesh state (one per speed), sharing what no speed changes.

    The rigid-body reduction is shared exactly (see :func:`_periodic_system`). With ``cutoff_hz`` the modal basis
    of the first state's mean system serves every state: each state's pieces are K̄ + (k_j − k̄)·w wᵀ for any
    reference k̄, and by Sherman–Morrison their static solutions stay in span{K̄⁻¹w, K̄⁻¹f₀} (f₀ the torque pair,
    whose direction no load changes), so the static corrections keep every piece's quasi-static response exact at
    every speed; what changes is only which undamped modes of a slightly different mean stiffness k̄ carry the
    dynamics below the cut-off (the speed enters the damping, Ω·G, which the basis never uses). The difference
    from a basis per speed is measured in the tests.
    """
    if cutoff_hz is not None and (not math.isfinite(cutoff_hz) or cutoff_hz <= 0.0):
        raise CaseError("cutoff_hz", cutoff_hz, "> 0 Hz, finite", "the highest mode frequency kept")
    reduction, basis, responses = None, None, []
    for state in states:
        problem = state.problem()
        system, reduction = _periodic_system(assembled, state, problem, reduction)
        if cutoff_hz is not None:
            from thermogear.dynamics.modal_reduction import modal_basis

            if basis is None:
                basis = modal_basis(system, 2.0 * math.pi * cutoff_hz)
            system = basis.reduce(system)
        responses.append(_response(assembled, state, problem, system, reduction, basis, samples_per_piece))
    return responses


def _response(assembled: AssembledDrivetrain, state: MeshState, problem, system: PiecewiseLinearSystem,
              reduction: RigidBodyReduction, basis, samples_per_piece: int) -> DrivetrainResponse:
    """The periodic orbit of the (reduced) system expanded to every DOF, with δ, the mesh and bearing forces and the
    metrics."""
    response = periodic_response(system, samples_per_piece)
    displacement, velocity = response.displacement.T, response.velocity.T
    if basis is not None:
        displacement, velocity = basis.expand(displacement), basis.expand(velocity)
    displacement, velocity = reduction.expand(displacement).T, reduction.expand(velocity).T
    w = assembled.mesh_vectors[0]
    delta, rate = displacement @ w, velocity @ w
    pieces = problem.stiffness.size
    interval = np.minimum(np.arange(delta.size) // samples_per_piece, pieces - 1)
    excitation = problem.force_per_interval - state.normal_load
    force = problem.stiffness[interval] * delta - excitation[interval] + problem.damping[interval] * rate
    forces = bearing_forces(assembled, displacement, velocity, clearance=False)  # the linear system: in contact
    metrics = compute_metrics(problem, response.time, delta, rate, interval, response.multipliers)
    return DrivetrainResponse(response.time, delta, rate, force, forces, displacement, response.multipliers,
                              metrics, problem.period)


def bearing_forces(assembled: AssembledDrivetrain, displacement: np.ndarray, velocity: np.ndarray,
                   clearance: bool = True) -> dict[str, np.ndarray]:
    """Force of each bearing on its housing (S, 3) [N] at the samples (S, DOFs): K·u + C·u̇, and per direction x, y
    of a bearing with a radial clearance δ, zero for |u| <= δ and k(u ∓ δ) + c·u̇ beyond (``clearance`` False: every
    bearing in contact, as the linear system solves it)."""
    forces = {}
    for bearing in assembled.drivetrain.bearings:
        dofs = [assembled.dof(bearing.location, name) for name in ("x", "y", "z")]
        forces[bearing.name] = bearing.housing_force(displacement[:, dofs], velocity[:, dofs], clearance)
    return forces
