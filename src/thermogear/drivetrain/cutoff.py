"""The drivetrain's periodic response on a modal cut-off chosen from the mesh harmonics of interest, with an error
estimate computed per run, and the speed-independent reduced matrices shared across speeds.

The cut-off. The response to the mesh harmonics j·f_m, j ≤ H, is carried by the modes up to the highest of them
resonantly and by the others quasi-statically; the static corrections of the basis
(:mod:`thermogear.dynamics.modes.modal_reduction`) keep every interval's quasi-static response exact, so what a cut-off
f_c loses is the dynamic part of the modes above it, a mode at f_i answering a harmonic at f with the dynamic
amplification 1/(1 − (f/f_i)²) of an undamped oscillator, i.e. (f/f_i)² beyond its static response (Craig & Kurdila,
Fundamentals of Structural Dynamics, 2nd ed. 2006, §14.6, the mode-acceleration method). With f_c =
``factor``·H·f_m (default 4·H·f_m) the truncated modes' dynamic part is below (1/4)² = 6 % of their own small
share; :func:`cutoff_for_harmonics` gives it.

The estimate. What the cut-off drops is computed from the cut-off solution itself, without a second periodic solve
(:mod:`thermogear.dynamics.modes.truncation_error`): the response's own loads on the mean structure — the mesh's
time-varying stiffness and damping force along the mesh vector, and the damping forces that couple the modes (the
bearings' dampers are not modal) — drive the modes above f_c, each with its dynamic part H_i(jω) − 1/ω_i², less
what the static-correction columns' own dynamics already carry (Craig & Kurdila, Fundamentals of Structural
Dynamics, 2nd ed. 2006, §14.6 mode acceleration; §10.2 modal frequency response); one step of the error's own
feedback (through the mesh's variation and the damping coupling into the modes below f_c, which a resonance there
amplifies) completes it. Its largest DTE and bearing-force deviation over the period, relative to the DTE's
peak-to-peak and the largest bearing-force peak-to-peak, is the :class:`CutoffError`. Against the true error (the
response on every mode, tests/unit/test_cutoff_truncation_estimate.py) it is within 0.81–1.12× on the test cases;
without the damping coupling it was 2.5× low on ``fzg_rig_type_c``. An estimate, not a bound: it is first order in
the error and takes each mode's own damping as modal.

The exact check stays callable (``second_solve``): the same speed solved again on 2·f_c, with the error estimated
as 4/3 of the difference d of the two responses (the error falls at least as (1/f_c)² with the static correction,
so the response on 2·f_c keeps at most a quarter of the error e at f_c, e ≤ d + e/4; measured faster: the tests'
pair 1.8e-3, 2.0e-6, 5e-12 at 5, 20, 80 kHz; the 492-DOF rotor of the benchmarks 2.1e-3, 1.0e-4, 8.6e-6 at 10,
20, 40 kHz). It costs a second solve, about as much as the first.

Sharing across speeds. The rigid-body reduction Q and the modal bases B (of the first speed's mean system) serve
every speed, as in :func:`~thermogear.drivetrain.response.drivetrain_speed_sweep`; here the reduced matrices that no
speed changes — (QB)ᵀM(QB), the structure's stiffness and damping, the gyroscopic matrix, the mesh vector — are
projected once, so each speed costs the periodic solve on the few reduced coordinates plus the expansion to every
DOF (no product of full-size matrices per speed).
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

from thermogear.drivetrain.assembly import AssembledDrivetrain
from thermogear.drivetrain.response import (DrivetrainResponse, _as_train, _grid, _periodic_system, _response,
                                            drivetrain_periodic_response)
from thermogear.drivetrain.train import MeshTrain
from thermogear.drivetrain.static_state import mesh_torque_forces
from thermogear.dynamics.periodic_orbits.periodic_ndof import PiecewiseLinearSystem
from thermogear.errors import CaseError
from thermogear.mesh.state import MeshState

__all__ = ["CUTOFF_FACTOR", "CUTOFF_HARMONICS", "CutoffError", "CutoffResponse", "cutoff_error_against",
           "cutoff_error_estimate", "cutoff_error_of", "cutoff_for_harmonics", "drivetrain_cutoff_response",
           "drivetrain_cutoff_sweep"]

#: Mesh harmonics of interest by default (the spectra reported, and most of a square wave's energy).
CUTOFF_HARMONICS = 5
#: f_c = factor · H · f_m (module docstring).
CUTOFF_FACTOR = 4.0
_CONVERGENCE = 4.0 / 3.0  # e ≤ d + e/4 for an error falling at least as (1/f_c)² (module docstring)


def cutoff_for_harmonics(mesh_frequency_hz: float, harmonics: int = CUTOFF_HARMONICS,
                         factor: float = CUTOFF_FACTOR) -> float:
    """The cut-off f_c = factor·H·f_m [Hz] for the mesh harmonics up to H of the mesh frequency f_m [Hz]."""
    if int(harmonics) != harmonics or harmonics < 1:
        raise CaseError("harmonics", harmonics, "an integer >= 1", "the highest mesh harmonic of interest")
    if not math.isfinite(factor) or factor < 1.0:
        raise CaseError("factor", factor, ">= 1, finite", "the cut-off lies above the highest harmonic")
    if not math.isfinite(mesh_frequency_hz) or mesh_frequency_hz <= 0.0:
        raise CaseError("mesh_frequency_hz", mesh_frequency_hz, "> 0 Hz", "the mesh frequency")
    return float(factor * int(harmonics) * mesh_frequency_hz)


@dataclass(frozen=True)
class CutoffError:
    """The estimated error of a response on ``cutoff_hz`` [Hz], in the DTE relative to the DTE's peak-to-peak
    (``transmission_error`` [-]) and in the bearing forces relative to the largest bearing force peak-to-peak
    (``bearing_force`` [-]); ``coordinates`` the size of the reduced system solved. ``estimated_from`` says how
    (module docstring): from the modes above the cut-off (the default; ``check_cutoff_hz`` the highest of them,
    ``check_coordinates`` the coordinates plus those modes), or as 4/3 of the difference from a second solve on
    ``check_cutoff_hz`` = 2·cutoff_hz (``check_coordinates`` its size)."""

    cutoff_hz: float
    check_cutoff_hz: float
    transmission_error: float
    bearing_force: float
    coordinates: int
    check_coordinates: int
    estimated_from: str = "second solve"

    def as_json(self) -> dict:
        """The ``cutoff_error`` object of ``run --json`` (relative errors [-], frequencies [Hz])."""
        return {"cutoff_hz": self.cutoff_hz, "check_cutoff_hz": self.check_cutoff_hz,
                "dte_relative": self.transmission_error, "bearing_force_relative": self.bearing_force,
                "coordinates": self.coordinates, "check_coordinates": self.check_coordinates,
                "estimated_from": self.estimated_from}

    def describe(self) -> str:
        """One line for a reader: what was solved and how far from the exact response it is estimated to be."""
        return (f"modes up to {self.cutoff_hz:.0f} Hz ({self.coordinates} coordinates): estimated error "
                f"{self.transmission_error:.1e} of the DTE peak-to-peak and {self.bearing_force:.1e} of the largest "
                f"bearing-force peak-to-peak ({self.estimated_from})")


@dataclass(frozen=True, eq=False)
class CutoffResponse:
    """The response on the cut-off and the estimate of its error (None where not asked for)."""

    response: DrivetrainResponse
    error: CutoffError | None


@dataclass(frozen=True, eq=False)
class _SharedReduction:
    """Q, B and the speed-independent reduced matrices on T = Q·B."""

    reduction: object
    basis: object
    mass: np.ndarray
    stiffness: np.ndarray
    damping: np.ndarray
    gyroscopic: np.ndarray
    pattern: np.ndarray
    mesh_vector: np.ndarray
    transform: np.ndarray

    @classmethod
    def build(cls, assembled: AssembledDrivetrain, system: PiecewiseLinearSystem, reduction, cutoff: float,
              modes=None):
        from thermogear.dynamics.modes.modal_reduction import modal_basis

        basis = modal_basis(system, 2.0 * math.pi * cutoff, modes=modes)
        transform = reduction.expansion(basis.basis)
        vector = transform.T @ assembled.mesh_vectors[0]
        project = (lambda matrix: transform.T @ (matrix @ transform))
        return cls(reduction, basis, project(assembled.mass), project(assembled.structure_stiffness),
                   project(assembled.structure_damping), project(assembled.gyroscopic), np.outer(vector, vector),
                   vector, transform)

    def system(self, assembled: AssembledDrivetrain, state: MeshState, problem) -> PiecewiseLinearSystem:
        """The reduced system of one speed: C = C_s + Ω·G on the shared matrices (as ``_periodic_system``)."""
        speed = state.speed_rpm * math.pi / 30.0
        load = state.normal_load
        return PiecewiseLinearSystem(
            mass=self.mass, stiffness=self.stiffness, damping=self.damping + speed * self.gyroscopic,
            force=self.transform.T @ mesh_torque_forces(assembled, load), nodes=problem.nodes,
            stiffness_pattern=self.pattern, stiffness_factor=problem.stiffness, damping_pattern=self.pattern,
            damping_factor=problem.damping, force_pattern=self.mesh_vector,
            force_factor=problem.force_per_interval - load)


def _difference(response: DrivetrainResponse, check: DrivetrainResponse) -> tuple[float, float]:
    """(DTE difference / DTE peak-to-peak, bearing-force difference / largest bearing-force peak-to-peak) [-]."""
    dte = float(np.abs(response.transmission_error - check.transmission_error).max())
    dte_scale = float(np.ptp(check.transmission_error))
    forces = [float(np.abs(response.bearing_forces[name] - check.bearing_forces[name]).max())
              for name in check.bearing_forces]
    force_scale = max((float(np.ptp(check.bearing_forces[name], axis=0).max()) for name in check.bearing_forces),
                      default=0.0)
    return (dte / dte_scale if dte_scale > 0.0 else dte,
            (max(forces) / force_scale if force_scale > 0.0 else max(forces, default=0.0)))


def cutoff_error_against(response: DrivetrainResponse, check: DrivetrainResponse, cutoff_hz: float) -> CutoffError:
    """The :class:`CutoffError` of ``response`` solved on ``cutoff_hz`` [Hz] from ``check``, the same state solved
    on 2·``cutoff_hz`` (module docstring); the sizes of the two reduced systems from their Floquet multipliers (two
    per coordinate)."""
    dte, force = _difference(response, check)
    check_size = check.multipliers.size // 2
    return CutoffError(float(cutoff_hz), 2.0 * float(cutoff_hz), _CONVERGENCE * dte, _CONVERGENCE * force,
                       response.multipliers.size // 2, check_size,
                       f"4/3 of the difference from the solve on {2.0 * cutoff_hz:.0f} Hz, {check_size} coordinates")


def cutoff_error_of(assembled: AssembledDrivetrain, state: MeshState | MeshTrain, response: DrivetrainResponse,
                    cutoff_hz: float, samples_per_piece: int, second_solve: bool = False) -> CutoffError:
    """The :class:`CutoffError` of ``response``, the state's periodic response on ``cutoff_hz`` [Hz]: from the
    modes above the cut-off (:func:`cutoff_error_estimate`), or with ``second_solve`` from the state solved again
    on twice the cut-off with ``samples_per_piece`` (:func:`cutoff_error_against`)."""
    if not second_solve:
        return cutoff_error_estimate(assembled, state, response, cutoff_hz)
    check = drivetrain_periodic_response(assembled, state, samples_per_piece=samples_per_piece,
                                         cutoff_hz=2.0 * cutoff_hz)
    return cutoff_error_against(response, check, cutoff_hz)


def cutoff_error_estimate(assembled: AssembledDrivetrain, state: MeshState | MeshTrain, response: DrivetrainResponse,
                          cutoff_hz: float, shared: tuple | None = None) -> CutoffError:
    """The :class:`CutoffError` of ``response``, the state's periodic response on ``cutoff_hz`` [Hz], from the
    modes above the cut-off driven by the response's own mesh loads (module docstring;
    :func:`~thermogear.dynamics.modes.truncation_error.truncation_error`): no second periodic solve. ``shared``: (the
    rigid-body reduction, the modal basis, the dropped modes) of a sweep's first state, whose basis solved
    ``response`` (default: built here from this state, as :func:`~thermogear.drivetrain.response.
    drivetrain_periodic_response` builds them)."""
    from thermogear.dynamics.modes.truncation_error import truncation_error

    train = _as_train(assembled, state)
    problems = tuple(item.problem() for item in train.states)
    grid = _grid(train, problems)
    if shared is None:
        system, reduction = _periodic_system(assembled, train, problems, grid, None)
        reduction, basis, dropped = _dropped(system, reduction, cutoff_hz)
    else:
        reduction, basis, dropped = shared
        system, _ = _periodic_system(assembled, train, problems, grid, reduction)
    velocity = None if response.velocity is None else response.velocity @ reduction.basis
    error = truncation_error(system, basis, dropped, response.time, response.displacement @ reduction.basis, velocity)
    dte, _ = error.observed(reduction.project_vector(assembled.mesh_vectors[0]))
    dte_scale = float(np.ptp(response.transmission_error))
    forces, force_scale = [], 0.0
    for bearing in assembled.drivetrain.bearings:
        displacement, rate = error.observed(reduction.basis[assembled.translation_dofs(bearing.location)])
        forces.append(float(np.abs(bearing.housing_force(displacement, rate, False)).max()))
        force_scale = max(force_scale, float(np.ptp(response.bearing_forces[bearing.name], axis=0).max()))
    force = max(forces, default=0.0)
    highest = float(dropped.frequencies[-1]) / (2.0 * math.pi)
    count = int(dropped.dropped.sum())
    return CutoffError(float(cutoff_hz), highest, float(np.abs(dte).max()) / dte_scale if dte_scale > 0.0 else 0.0,
                       force / force_scale if force_scale > 0.0 else force, response.multipliers.size // 2,
                       response.multipliers.size // 2 + count,
                       f"the {count} modes above it, to {highest:.0f} Hz, under the response's own loads")


def _dropped(system: PiecewiseLinearSystem, reduction, cutoff_hz: float) -> tuple:
    """(reduction, the modal basis on ``cutoff_hz`` [Hz], the modes above it) of a mean system."""
    from thermogear.dynamics.modes.modal_reduction import mean_modes, modal_basis

    cutoff = 2.0 * math.pi * cutoff_hz
    modes = mean_modes(system, cutoff)
    return reduction, modal_basis(system, cutoff, modes=modes), modes


def drivetrain_cutoff_sweep(assembled: AssembledDrivetrain, states: Sequence[MeshState],
                            cutoff_hz: float | None = None, harmonics: int = CUTOFF_HARMONICS,
                            factor: float = CUTOFF_FACTOR, samples_per_piece: int = 8,
                            estimate: bool = True, second_solve: bool = False) -> list[CutoffResponse]:
    """The periodic response at each mesh state (one per speed) on the modes up to ``cutoff_hz`` [Hz] plus the
    static corrections (module docstring); ``cutoff_hz`` None chooses it from the mesh harmonics up to
    ``harmonics`` at the highest mesh frequency of the states (:func:`cutoff_for_harmonics`). With ``estimate`` each
    speed gets its :class:`CutoffError`: from the modes above the cut-off (:func:`cutoff_error_estimate`), or with
    ``second_solve`` from the speed solved again on twice the cut-off (:func:`cutoff_error_against`, about twice
    the cost)."""
    from thermogear.dynamics.modes.modal_reduction import mean_modes

    states = list(states)
    if not states:
        return []
    if cutoff_hz is None:
        cutoff_hz = cutoff_for_harmonics(max(state.mesh_frequency_hz for state in states), harmonics, factor)
    if not math.isfinite(cutoff_hz) or cutoff_hz <= 0.0:
        raise CaseError("cutoff_hz", cutoff_hz, "> 0 Hz, finite", "the highest mode frequency kept")
    first = states[0]
    first_problem = first.problem()
    first_train = _as_train(assembled, first)  # one mesh: the cut-off's shared projection holds one mesh vector
    system, reduction = _periodic_system(assembled, first_train, (first_problem,),
                                         _grid(first_train, (first_problem,)), None)
    modes = mean_modes(system, 2.0 * math.pi * cutoff_hz)
    shared = [_SharedReduction.build(assembled, system, reduction, cutoff_hz, modes)]
    if estimate and second_solve:
        shared.append(_SharedReduction.build(assembled, system, reduction, 2.0 * cutoff_hz))
    results = []
    for state in states:
        problem = first_problem if state is first else state.problem()
        train = _as_train(assembled, state)
        grid = _grid(train, (problem,))
        responses = [_response(assembled, train, (problem,), grid, model.system(assembled, state, problem),
                               reduction, model.basis, samples_per_piece) for model in shared]
        error = None
        if estimate:
            error = (cutoff_error_against(responses[0], responses[1], cutoff_hz) if second_solve else
                     cutoff_error_estimate(assembled, state, responses[0], cutoff_hz,
                                           (reduction, shared[0].basis, modes)))
        results.append(CutoffResponse(responses[0], error))
    return results


def drivetrain_cutoff_response(assembled: AssembledDrivetrain, state: MeshState, cutoff_hz: float | None = None,
                               harmonics: int = CUTOFF_HARMONICS, factor: float = CUTOFF_FACTOR,
                               samples_per_piece: int = 8, estimate: bool = True,
                               second_solve: bool = False) -> CutoffResponse:
    """:func:`drivetrain_cutoff_sweep` at one mesh state."""
    return drivetrain_cutoff_sweep(assembled, (state,), cutoff_hz, harmonics, factor, samples_per_piece,
                                   estimate, second_solve)[0]
