"""The mesh feeds the drivetrain: the n-DOF time-periodic problem of one mesh period and its exact periodic response.

Over one mesh period the mesh model gives k(τ), c(τ), the excitation Σk_i·e_i of the unloaded deviations and the
normal load W (a :class:`~thermogear.mesh.state.MeshState`). On a drivetrain with the mesh vector w this is

    M q̈ + (C + Ω·G + c(τ) w wᵀ) q̇ + (K + k(τ) w wᵀ) q = T + (Σk_i e_i)(τ)·w,

T the torque pair s·r_b1·W, s·r_b2·W on the two gears, Ω the pinion speed (Kahraman, Ozguven, Houser & Zakrajsek,
J. Mech. Des. 114 (1992) 507; Velex & Maatar, J. Sound Vib. 191 (1996) 629 for the time-varying mesh). In the limit of
rigid shafts and bearings δ = wᵀq obeys the 1-DOF equation me·δ̈ + c·δ̇ + k·(δ) = W + Σk_i e_i of the mesh state with
me = J₁J₂/(J₁r_b2² + J₂r_b1²). The free torsional rotation is removed (rigid_body_reduction); the orbit is the exact
periodic state (:mod:`thermogear.dynamics.periodic_orbits.periodic_ndof`). Outputs: dynamic transmission error δ(t) =
wᵀq, the mesh force and the metrics of the 1-DOF chain (Kv, …) computed from δ, and the force of each bearing on its
housing F_b = K_b·u + C_b·u̇ with its spectrum in mesh harmonics.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass, field, replace
from typing import Any

import numpy as np

from thermogear.drivetrain.assembly import AssembledDrivetrain
from thermogear.drivetrain.static_state import bearing_moments, mesh_torque_forces
from thermogear.drivetrain.train import MeshTrain, TrainGrid, train_grid
from thermogear.dynamics.backlash.backlash_ndof import BacklashSystem, MeshZone
from thermogear.dynamics.modes.rigid_body import RigidBodyReduction, rigid_body_reduction
from thermogear.dynamics.periodic_orbits.periodic_ndof import PiecewiseLinearSystem, periodic_response
from thermogear.dynamics.results.metrics import compute_metrics
from thermogear.dynamics.results.spectra import harmonic_spectrum
from thermogear.errors import CaseError
from thermogear.mesh.state import MeshState

__all__ = ["BearingSpectra", "DrivetrainResponse", "MeshResponse", "PeriodicMotion", "bearing_dofs",
           "bearing_force_spectrum", "bearing_forces", "drivetrain_backlash_system", "drivetrain_periodic_response",
           "drivetrain_periodic_system", "drivetrain_speed_sweep", "train_problems"]


def drivetrain_periodic_system(assembled: AssembledDrivetrain,
                               state: MeshState | MeshTrain) -> tuple[PiecewiseLinearSystem, RigidBodyReduction]:
    """The reduced piecewise-constant system of one period and the reduction q = Q p.

    One mesh takes the state's k(τ), c(τ), deviations and load over one mesh period; several take a
    :class:`~thermogear.drivetrain.train.MeshTrain` (one state per mesh) over the train's common period, the mesh
    terms summed (:mod:`thermogear.drivetrain.train`). The first mesh's gear 1 must sit on the first shaft, whose
    speed is the first state's pinion speed (for the gyroscopic terms).
    """
    train = _as_train(assembled, state)
    problems = tuple(item.problem() for item in train.states)
    return _periodic_system(assembled, train, problems, _grid(train, problems), None)


def _as_train(assembled: AssembledDrivetrain, state: MeshState | MeshTrain) -> MeshTrain:
    """The states as a train, checked against the drivetrain's meshes."""
    train = state if isinstance(state, MeshTrain) else MeshTrain((state,))
    drivetrain = assembled.drivetrain
    if len(drivetrain.meshes) != len(train.states):
        raise CaseError("meshes", len(drivetrain.meshes), f"{len(train.states)} (one mesh state per mesh)",
                        "each mesh of the drivetrain takes the mesh state of its gear pair")
    mesh = drivetrain.meshes[0]
    if mesh.gear_1.shaft != drivetrain.shafts[0].name:
        raise CaseError(f"{mesh.name}.gear_1", mesh.gear_1.shaft, f"the first shaft, {drivetrain.shafts[0].name!r}",
                        "the reference speed is the pinion's, on the first shaft")
    return train


def _grid(train: MeshTrain, problems) -> TrainGrid:
    """The pieces of the period: one mesh's own grid, or the union over the common period."""
    if len(problems) == 1 and train.phases[0] == 0.0 and train.repeats[0] == 1:
        return TrainGrid(problems[0].nodes, np.arange(problems[0].nodes.size - 1)[:, None], (1,), (0.0,))
    return train_grid([problem.nodes for problem in problems], train.repeats, train.phases)


def _periodic_system(assembled: AssembledDrivetrain, train: MeshTrain, problems, grid: TrainGrid,
                     reduction: RigidBodyReduction | None,
                     projected: dict | None = None) -> tuple[PiecewiseLinearSystem, RigidBodyReduction]:
    """:func:`drivetrain_periodic_system` with the states' problems and grid given and, optionally, a rigid-body
    reduction from another state of the same drivetrain: Q depends only on M and the rigid modes, which no mesh state
    changes (the mesh stiffness joins the shafts whatever its value), so sharing it across speeds is exact.
    ``projected``: a dict shared by the speeds of a sweep with that reduction, holding QᵀMQ and QᵀKQ (no speed
    changes them; the damping, with Ω·G, is projected per speed), filled on the first call."""
    speed = train.states[0].speed_rpm * math.pi / 30.0
    damping = assembled.structure_damping + speed * assembled.gyroscopic
    if reduction is None:
        means = np.array([float(np.dot(problem.stiffness, np.diff(problem.nodes)) / problem.period)
                          for problem in problems])
        reduction = rigid_body_reduction(assembled.mass, assembled.connection_stiffness(
            means[0] if means.size == 1 else means), assembled.rigid_candidates(), damping)
    loads = np.array([item.normal_load for item in train.states])
    patterns, damping_patterns, vectors, stiffness, damping_factor, force = _mesh_patterns(
        assembled, reduction, problems, grid, loads)
    if patterns.shape[0] == 1:  # one mesh of one pattern: its own pattern and factors (the single-pattern form)
        patterns, damping_patterns, vectors = patterns[0], damping_patterns[0], vectors[0]
        stiffness, damping_factor, force = stiffness[:, 0], damping_factor[:, 0], force[:, 0]
    projected = {} if projected is None else projected
    if "mass" not in projected:
        projected["mass"] = reduction.project(assembled.mass)
        projected["stiffness"] = reduction.project(assembled.structure_stiffness)
    system = PiecewiseLinearSystem(
        mass=projected["mass"], stiffness=projected["stiffness"], damping=reduction.project(damping),
        force=reduction.project_vector(mesh_torque_forces(assembled, loads[0] if loads.size == 1 else loads)),
        nodes=grid.nodes, stiffness_pattern=patterns, stiffness_factor=stiffness,
        damping_pattern=damping_patterns, damping_factor=damping_factor, force_pattern=vectors, force_factor=force)
    return system, reduction


def mesh_columns(assembled: AssembledDrivetrain) -> tuple[int, ...]:
    """The mesh each pattern of the drivetrain's periodic system belongs to, by its first pattern's column: one
    pattern per mesh, three for a mesh whose moments vary over the period (:meth:`GearMesh.varies`: w wᵀ, then
    w w_zᵀ + w_z wᵀ and w_z w_zᵀ, :mod:`thermogear.drivetrain.mesh_contact`)."""
    owners: list[int] = []
    for mesh in assembled.drivetrain.meshes:
        owners += [len(owners)] * (3 if mesh.varies() else 1)
    return tuple(owners)


def _mesh_patterns(assembled: AssembledDrivetrain, reduction: RigidBodyReduction, problems, grid: TrainGrid,
                   loads: np.ndarray) -> tuple[np.ndarray, ...]:
    """(stiffness patterns (P, n, n), damping patterns (P, n, n), force patterns (P, n), stiffness, damping and
    force factors (N, P)) of the meshes on the reduced coordinates, in the order of :func:`mesh_columns`: a mesh's
    k(τ) w wᵀ, c(τ) w wᵀ and (Σk_ie_i)(τ) w less its static load, and where its moments vary the two further
    patterns of the face (:meth:`GearMesh.face_factors`; the force of the gaps' moment along w_z on the second)."""
    vectors = np.array([reduction.project_vector(w) for w in assembled.mesh_vectors])
    if not any(mesh.varies() for mesh in assembled.drivetrain.meshes):  # one rank-one pattern per mesh
        patterns = np.einsum("mi,mj->mij", vectors, vectors)
        columns = [(problem.stiffness[grid.pieces[:, m]], problem.damping[grid.pieces[:, m]],
                    (problem.force_per_interval - load)[grid.pieces[:, m]])
                   for m, (problem, load) in enumerate(zip(problems, loads))]
        factors = (np.column_stack([column[kind] for column in columns]) for kind in range(3))
        return (patterns, patterns, vectors, *factors)
    stiffness_patterns, force_patterns, columns = [], [], []
    for m, (mesh, problem, load) in enumerate(zip(assembled.drivetrain.meshes, problems, loads)):
        w, index = vectors[m], grid.pieces[:, m]
        excitation = problem.force_per_interval - load
        stiffness_patterns.append(np.outer(w, w))
        force_patterns.append(w)
        columns.append((problem.stiffness[index], problem.damping[index], excitation[index]))
        if not mesh.varies():
            continue
        tilt = reduction.project_vector(assembled.tilt_vectors[m])
        k_first, c_first, k_tilt, c_tilt, moment = mesh.face_factors(problem.nodes, problem.stiffness,
                                                                     problem.damping, excitation)
        cross = np.outer(w, tilt)
        stiffness_patterns += [cross + cross.T, np.outer(tilt, tilt)]
        force_patterns += [tilt, tilt]
        columns += [(k_first[index], c_first[index], moment[index]), (k_tilt[index], c_tilt[index], 0.0 * index)]
    patterns = np.array(stiffness_patterns)
    factors = (np.column_stack([column[kind] for column in columns]) for kind in range(3))
    return (patterns, patterns, np.array(force_patterns), *factors)


def drivetrain_backlash_system(assembled: AssembledDrivetrain,
                               state: MeshState | MeshTrain) -> tuple[BacklashSystem, RigidBodyReduction]:
    """The drivetrain with the backlash mesh: one dead-zone coordinate g = wᵀq − ē_j of the normal backlash of the
    state (solve with :func:`thermogear.dynamics.backlash.backlash_ndof.backlash_periodic_orbit`).

    The pairs' deviations enter as their load-weighted mean on each interval, ē_j = Σk_i·e_i / Σk_i, so the whole
    mesh separates at once (unlike the 1-DOF backlash model, where each pair leaves contact on its own); the back
    flanks take the driving flanks' stiffness. Without deviations the two descriptions coincide. A bearing with a
    ``radial_clearance`` adds a dead zone in x and one in y
    (:class:`~thermogear.dynamics.backlash.backlash_ndof.DeadZone`).

    A train (:class:`~thermogear.drivetrain.train.MeshTrain`): every mesh has its own dead zone of its own normal
    backlash, deviation and stiffness factor on the pieces of the common period; the first mesh is the system's own,
    each further one a :class:`~thermogear.dynamics.backlash.backlash_ndof.MeshZone` of its column (listed before the
    bearings' clearances).
    """
    states = state.states if isinstance(state, MeshTrain) else (state,)
    for index, item in enumerate(states):
        if item.backlash is None:
            raise CaseError("backlash", None, "a mesh state whose backlash is known",
                            f"the dead zone of mesh {index + 1} needs its width")
    linear, reduction = drivetrain_periodic_system(assembled, state)
    zones = [replace(zone, vector=reduction.project_vector(zone.vector)) for _, zone in assembled.dead_zones]
    if linear.pattern_count == 1:
        deviation = linear.force_factor / linear.stiffness_factor
        return BacklashSystem(linear, linear.force_pattern, deviation, states[0].backlash, tuple(zones)), reduction
    owners = mesh_columns(assembled)
    firsts = sorted(set(owners))  # each mesh's own pattern w wᵀ: its dead zone is along w
    deviation = {column: linear.force_factor[:, column] / linear.stiffness_factor[:, column]  # e_j = Σk_ie_i / Σk_i
                 for column in firsts}
    meshes = [MeshZone(linear.force_pattern[column], column, deviation[column], states[m].backlash)
              for m, column in enumerate(firsts) if m > 0]
    # on the back flanks every slice's gap grows by b: the force moves by −b·(k w + k₁′ w_z), along the mesh's own
    # pattern and the face's first (its force pattern w_z), not the second
    shift = linear.stiffness_factor.copy()
    for column, owner in enumerate(owners):
        if column - owner == 2:  # w_z w_zᵀ (mesh_columns' order)
            shift[:, column] = 0.0
    return BacklashSystem(linear, linear.force_pattern[0], deviation[0], states[0].backlash,
                          tuple(meshes) + tuple(zones), owners, shift), reduction


@dataclass(frozen=True, eq=False)
class MeshResponse:
    """One mesh's part of a periodic response: ``transmission_error`` δ = wᵀq [m] and its rate [m/s], the
    ``mesh_force`` [N] at the response's samples, its ``metrics`` (Kv, DTE, …, over the response's period) and its
    own ``mesh_period`` [s]."""

    transmission_error: np.ndarray
    transmission_error_rate: np.ndarray
    mesh_force: np.ndarray
    metrics: dict[str, Any]
    mesh_period: float


class BearingSpectra:
    """The bearing-force spectra of a response over one period: it holds ``time`` (S,) [s], ``bearing_forces``
    name → (S, 3) [N] and ``period`` T [s]."""

    def bearing_spectrum(self, name: str, points: int = 1024) -> tuple[np.ndarray, np.ndarray]:
        """(frequencies [Hz] of the mesh harmonics 0, f_m, 2f_m, …; amplitudes (3, harmonics) [N] in x, y, z) of
        one bearing's force on its housing; harmonic 0 is the mean (static) force."""
        return bearing_force_spectrum(self.time, self.bearing_forces, name, self.period, points)


@dataclass(frozen=True, eq=False)
class PeriodicMotion(BearingSpectra):
    """The samples every periodic drivetrain response (linear or with backlash) holds: ``time`` (S,) [s],
    ``transmission_error`` δ = wᵀq [m] and its ``transmission_error_rate`` [m/s], the ``mesh_force`` [N],
    ``bearing_forces`` name → (S, 3) on the housing in x, y, z [N] and ``displacement`` (S, DOFs) [SI]; a
    subclass adds the ``period`` and what its solver finds."""

    time: np.ndarray
    transmission_error: np.ndarray
    transmission_error_rate: np.ndarray
    mesh_force: np.ndarray
    bearing_forces: dict[str, np.ndarray]
    displacement: np.ndarray


@dataclass(frozen=True, eq=False)
class DrivetrainResponse(PeriodicMotion):
    """Periodic response over one mesh period: ``time`` (S,) [s]; ``transmission_error`` δ = wᵀq [m] and its rate
    [m/s]; ``mesh_force`` k(δ) − Σk_ie_i + c·δ̇ [N]; ``bearing_forces`` name → (S, 3) force on the housing in
    x, y, z [N] (``bearing_moments`` name → (S, 2) its tilting moment about x, y [N·m]); ``displacement`` (S, DOFs) [SI]; Floquet ``multipliers``; ``metrics`` of the 1-DOF chain computed
    from δ (kv, dte_rms, …; see :func:`thermogear.dynamics.results.metrics.compute_metrics`). ``period`` is the mesh
    period, or a train's common period; ``meshes`` holds each mesh's δ, force and metrics by name (the fields above are
    the
    first mesh's)."""

    multipliers: np.ndarray
    metrics: dict[str, Any]
    period: float
    meshes: dict[str, MeshResponse] = field(default_factory=dict)
    bearing_moments: dict[str, np.ndarray] = field(default_factory=dict)  # name → (S, 2) [N·m] about x, y
    velocity: np.ndarray | None = None  # (S, DOFs) [SI/s], the displacement's rate (None where not kept)

    @property
    def kv(self) -> float | None:
        """Dynamic factor Kv [-] (max pair load over the static load, as the 1-DOF chain)."""
        return self.metrics["kv"]


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
                                 cutoff_hz: float | None = None, solves=None) -> DrivetrainResponse:
    """Exact periodic response of the drivetrain to one mesh period (see the module docstring).

    ``cutoff_hz`` [Hz]: solve on the modes of the mean system up to this frequency plus the static corrections of
    the mesh vector and the torque loads (:mod:`thermogear.dynamics.modes.modal_reduction`: the mesh compliance stays
    exact, the dynamics of the modes above the cut-off are lost); None solves on every DOF. A cut-off a few times
    the highest mesh harmonic of interest converges (see the tests). ``solves``: a
    :class:`~thermogear.dynamics.periodic_orbits.periodic_solves.PeriodicSolves` whose response of the same reduced
    system (bit for bit, e.g. the backlash solver's switch-free orbit) is taken instead of a solve of its own, and which
    keeps this one.
    """
    return drivetrain_speed_sweep(assembled, (state,), samples_per_piece, cutoff_hz, solves)[0]


def drivetrain_speed_sweep(assembled: AssembledDrivetrain, states: Sequence[MeshState | MeshTrain],
                           samples_per_piece: int = 8, cutoff_hz: float | None = None,
                           solves=None) -> list[DrivetrainResponse]:
    """:func:`drivetrain_periodic_response` at each mesh state (one per speed; a train of states per speed where
    the drivetrain has several meshes), sharing what no speed changes.

    The rigid-body reduction and the projected mass and stiffness are shared exactly (see
    :func:`_periodic_system`). With ``cutoff_hz`` the modal basis
    of the first state's mean system serves every state: each state's pieces are K̄ + (k_j − k̄)·w wᵀ for any
    reference k̄, and by Sherman–Morrison their static solutions stay in span{K̄⁻¹w, K̄⁻¹f₀} (f₀ the torque pair,
    whose direction no load changes), so the static corrections keep every piece's quasi-static response exact at
    every speed; what changes is only which undamped modes of a slightly different mean stiffness k̄ carry the
    dynamics below the cut-off (the speed enters the damping, Ω·G, which the basis never uses). The difference
    from a basis per speed is measured in the tests. With several meshes the same holds mesh by mesh (the static
    corrections of every mesh vector are in the basis).
    """
    if cutoff_hz is not None and (not math.isfinite(cutoff_hz) or cutoff_hz <= 0.0):
        raise CaseError("cutoff_hz", cutoff_hz, "> 0 Hz, finite", "the highest mode frequency kept")
    reduction, basis, responses, projected = None, None, [], {}
    for state in states:
        train = _as_train(assembled, state)
        problems = tuple(item.problem() for item in train.states)
        grid = _grid(train, problems)
        system, reduction = _periodic_system(assembled, train, problems, grid, reduction, projected)
        if cutoff_hz is not None:
            from thermogear.dynamics.modes.modal_reduction import modal_basis

            if basis is None:
                basis = modal_basis(system, 2.0 * math.pi * cutoff_hz)
            system = basis.reduce(system)
        responses.append(_response(assembled, train, problems, grid, system, reduction, basis, samples_per_piece,
                                   solves))
    return responses


def train_problems(train: MeshTrain) -> tuple[tuple, tuple, TrainGrid]:
    """(each mesh's problem with its per-interval arrays on the train's common pieces, each mesh's own problem over
    its own period, the common grid), for the metrics of each mesh of a train."""
    problems = tuple(item.problem() for item in train.states)
    grid = _grid(train, problems)
    return tuple(_on_grid(problem, grid, m) for m, problem in enumerate(problems)), problems, grid


def _on_grid(problem, grid: TrainGrid, column: int):
    """A mesh's problem with its per-interval arrays taken on the train's pieces (the same mesh over the common
    period), for its metrics."""
    from thermogear.dynamics.problems.problem import MeshDynamicsProblem

    index = grid.pieces[:, column]
    force = problem.force_per_interval[index]
    return MeshDynamicsProblem(mass=problem.mass, nodes=grid.nodes, stiffness=problem.stiffness[index],
                               damping=problem.damping[index], force=force, contact_count=problem.contact_count[index],
                               pair_stiffness=None if problem.pair_stiffness is None else problem.pair_stiffness[:, index],
                               face_width=problem.face_width,
                               pair_deviation=None if problem.pair_deviation is None else problem.pair_deviation[:, index])


def _response(assembled: AssembledDrivetrain, train: MeshTrain, problems, grid: TrainGrid,
              system: PiecewiseLinearSystem, reduction: RigidBodyReduction, basis,
              samples_per_piece: int, solves=None) -> DrivetrainResponse:
    """The periodic orbit of the (reduced) system expanded to every DOF, with δ, the mesh and bearing forces and the
    metrics of each mesh (the orbit from ``solves`` where it holds the same system's, else solved)."""
    response = (periodic_response if solves is None else solves.response)(system, samples_per_piece)
    expansion = reduction.expansion(None if basis is None else basis.basis)  # the solver's coordinates → every DOF
    displacement, velocity = response.displacement @ expansion.T, response.velocity @ expansion.T
    pieces = grid.nodes.size - 1
    interval = np.minimum(np.arange(displacement.shape[0]) // samples_per_piece, pieces - 1)
    meshes = {}
    for column, (mesh, w, state, problem) in enumerate(zip(assembled.drivetrain.meshes, assembled.mesh_vectors,
                                                           train.states, problems)):
        delta, rate = displacement @ w, velocity @ w
        own = grid.pieces[interval, column]
        excitation = problem.force_per_interval - state.normal_load
        force = problem.stiffness[own] * delta - excitation[own] + problem.damping[own] * rate
        if mesh.varies():  # the face's first moment about the load centre strains the mesh with the relative tilt
            k_first, c_first = mesh.face_factors(problem.nodes, problem.stiffness, problem.damping, excitation)[:2]
            tilt = assembled.tilt_vectors[column]
            force = force + k_first[own] * (displacement @ tilt) + c_first[own] * (velocity @ tilt)
        if len(problems) == 1:
            metrics = compute_metrics(problem, response.time, delta, rate, interval, response.multipliers)
        else:
            metrics = compute_metrics(_on_grid(problem, grid, column), response.time, delta, rate, interval,
                                      response.multipliers)
            metrics["mesh_frequency_hz"] = problem.mesh_frequency
            metrics["frequency_ratio"] = problem.mesh_frequency / metrics["natural_frequency_hz"]
        meshes[mesh.name] = MeshResponse(delta, rate, force, metrics, problem.period)
    forces = bearing_forces(assembled, displacement, velocity, clearance=False)  # the linear system: in contact
    first = next(iter(meshes.values()))
    return DrivetrainResponse(response.time, first.transmission_error, first.transmission_error_rate,
                              first.mesh_force, forces, displacement, response.multipliers, first.metrics,
                              grid.period, meshes, bearing_moments(assembled, displacement), velocity)


def bearing_dofs(assembled: AssembledDrivetrain) -> list[int]:
    """The DOFs the bearings sit on (x, y, z of each bearing's node), in order, each once."""
    bearings = assembled.drivetrain.bearings
    return sorted({dof for bearing in bearings for dof in assembled.translation_dofs(bearing.location)})


def bearing_forces(assembled: AssembledDrivetrain, displacement: np.ndarray, velocity: np.ndarray,
                   clearance: bool = True, dofs: list[int] | None = None) -> dict[str, np.ndarray]:
    """Force of each bearing on its housing (S, 3) [N] at the samples (S, DOFs): K·u + C·u̇, and per direction x, y
    of a bearing with a radial clearance δ, zero for |u| <= δ and k(u ∓ δ) + c·u̇ beyond (``clearance`` False: every
    bearing in contact, as the linear system solves it). ``dofs``: the DOFs the columns of ``displacement`` and
    ``velocity`` hold (e.g. :func:`bearing_dofs`), None where they hold every DOF in order."""
    column = None if dofs is None else {dof: index for index, dof in enumerate(dofs)}
    forces = {}
    for bearing in assembled.drivetrain.bearings:
        own = assembled.translation_dofs(bearing.location)
        own = own if column is None else [column[dof] for dof in own]
        forces[bearing.name] = bearing.housing_force(displacement[:, own], velocity[:, own], clearance)
    return forces
