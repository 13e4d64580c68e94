"""A case's drivetrain cold and hot: modes, the periodic response to the mesh, bearing forces and what heat moved.

The cold drivetrain carries the elastic mesh model (E at 20 °C, the pair as built, shafts at 20 °C); the hot one
the case's thermal mesh model, put in its warm state as :mod:`thermogear.drivetrain.heat` does: the shafts' E(T)
at their temperature (each shaft's ``temperature_c``; else the temperature model's prediction where it makes one —
the gearbox network's shafts node, :mod:`thermogear.drivetrain.heat_source` —; else the gears' mean tooth
temperature) with the gears' β_E, the hot mean mesh stiffness, and the hot pair's base radii and operating pressure angle at the centre distance
the housing moved (thermo-elastic model; under the paper's ``luo2020`` model only the mesh stiffness changes).
Masses, inertias and bearing stiffnesses are held (stated in :mod:`thermogear.drivetrain.heat`); a bearing's play
follows its ring temperatures where the temperature model gives them (:mod:`thermogear.drivetrain.warm_state`).

For each model: the lowest modes (undamped, mean mesh stiffness) with a label, the strain-energy shares of the
mesh, each bearing, shaft, coupling and support; the exact periodic response to one mesh period of the model's mesh
state on the modes up to the section's ``response_cutoff_hz`` (:func:`~thermogear.drivetrain.response.
drivetrain_periodic_response`): DTE, Kv, and per bearing the dynamic force on the housing (RMS of F − F̄ over the
period, and the amplitude of the first mesh harmonics). With the case's nonlinear mesh the backlash orbit (or the
motion from rest) of every mesh's dead zone instead; a train of several meshes is solved over its common period
(:mod:`thermogear.drivetrain.train`), each mesh its own dead zone.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field, replace
from types import MappingProxyType
from typing import TYPE_CHECKING, Any

import numpy as np

from thermogear.case.pieces import call_with_pieces
from thermogear.composition import DRIVETRAIN_HEAT, builtin
from thermogear.drivetrain.assembly import Drivetrain
from thermogear.drivetrain.case_layout import drivetrain_from_section
from thermogear.drivetrain.heat import ModeShifts, WarmState, thermal_mode_shifts, warm_drivetrain
from thermogear.drivetrain.mesh_contact import case_face_variations
from thermogear.drivetrain.modes import DrivetrainModes, drivetrain_modes
from thermogear.drivetrain.response import DrivetrainResponse, drivetrain_periodic_response, drivetrain_speed_sweep
from thermogear.drivetrain.stages import stage_train
from thermogear.drivetrain.warm_state import operating_clearances, shaft_temperatures, with_clearances
from thermogear.dynamics.periodic_orbits.periodic_solves import PeriodicSolves
from thermogear.dynamics.problems.mesh_laws import mesh_law
from thermogear.drivetrain.result_tables import (SPECTRUM_POINTS, bearing_force_summary, heat_table,  # noqa: F401
                                                 mode_table, resonance_speeds, stage_summary)
from thermogear.drivetrain.results import (MESH_COUPLED_SHARE, MESH_DOMINATED_SHARE, DrivetrainBacklashResult,
                                           DrivetrainLinearResult, DrivetrainResults, DrivetrainTransientResult,
                                           ModeRow, bearing_forces_of, heat_rows, mode_rows, resonances_of,
                                           stage_results, unknown_bearing_forces)
from thermogear.errors import CaseError
from thermogear.mesh.model import MeshModel
from thermogear.mesh.model_names import ELASTIC, THERMAL
from thermogear.thermoelastic.materials import MODULUS_REFERENCE_C, MODULUS_TEMPERATURE_COEFFICIENTS_PER_K

if TYPE_CHECKING:
    from thermogear.drivetrain.backlash_response import DrivetrainBacklashResponse
    from thermogear.drivetrain.transient_response import DrivetrainTransient

__all__ = ["BACKLASH_SUBSTEPS_PER_PERIOD", "MESH_COUPLED_SHARE", "MESH_DOMINATED_SHARE",
           "CaseDrivetrain", "backlash_substeps", "bearing_force_summary", "case_drivetrain",
           "drivetrain_results", "heat_table", "mode_table", "resonance_speeds", "stage_summary"]

#: Samples per mesh-grid interval of the periodic response (the bearing-force RMS is a trapezoidal integral over
#: them; the harmonics come from the exact orbit resampled uniformly).
SAMPLES_PER_PIECE = 4
#: Sub-steps per mesh period on which the backlash shooting looks for contact switches: T/2048 is short against the
#: mesh modes (fzg_rig_type_c: 0.84 μs at 2175 rpm against the 149 μs period of its 6.7 kHz torsional mode), and a
#: switch missed within a sub-step is caught by the odd-crossing guard, which refines them.
BACKLASH_SUBSTEPS_PER_PERIOD = 2048


def backlash_substeps(pieces: int) -> int:
    """Sub-steps per piece: :data:`BACKLASH_SUBSTEPS_PER_PERIOD` over the period, a multiple of
    :data:`SAMPLES_PER_PIECE` (the samples then fall on the flow's own sub-step ends, at no cost)."""
    wanted = math.ceil(BACKLASH_SUBSTEPS_PER_PERIOD / max(pieces, 1))
    return SAMPLES_PER_PIECE * max(1, math.ceil(wanted / SAMPLES_PER_PIECE))


@dataclass(frozen=True, eq=False)
class CaseDrivetrain:
    """The drivetrain of a case in the states of its mesh models: ``section`` the case's [drivetrain] section,
    ``dynamics`` its [dynamics] section (mesh, method, points per period, transient periods), ``teeth`` the
    pinion's, ``drivetrains`` model → Drivetrain, ``models`` model → MeshModel, ``notes`` what was assumed (shaft
    temperatures); ``warm_moduli`` the hot drivetrain before its thermal expansion (None where it did not expand),
    for the attribution of the expansion; ``warm_state`` the shafts' temperatures and where they came from, and the
    bearings' ring temperatures and play (:mod:`~thermogear.drivetrain.warm_state`)."""

    section: Any
    dynamics: Any
    teeth: int
    drivetrains: dict[str, Drivetrain]
    models: dict[str, MeshModel]
    notes: tuple[str, ...] = ()
    warm_moduli: Drivetrain | None = None
    stage_models: dict[str, tuple[MeshModel, ...]] = field(default_factory=dict)
    stage_speeds: tuple[float, ...] = ()
    train_repeats: tuple[int, ...] = (1,)
    train_phases: tuple[float, ...] = (0.0,)
    _assembled: dict = field(default_factory=dict, repr=False)
    warm_state: dict = field(default_factory=dict)
    _solves: PeriodicSolves = field(default_factory=PeriodicSolves, repr=False)  # the linear and switch-free solves

    @property
    def stages(self) -> tuple[tuple[str, float], ...]:
        """The further stages of a train: (mesh name, its pinion's teeth × its speed per unit input speed)."""
        return tuple((stage.name, model.gear_pair.pinion.teeth * factor) for stage, model, factor in zip(
            self.section.stages, self.stage_models.get(ELASTIC, ()), self.stage_speeds))

    def mesh_states(self, model: str, speed_rpm: float | None = None, points_per_period: int | None = None):
        """The first mesh's state at a pinion speed [rpm] (default the case's), or for a train the
        :class:`~thermogear.drivetrain.train.MeshTrain` of every stage's state at its own pinion speed."""
        points = points_per_period or self.dynamics.points_per_period
        first = self.models[model].state(speed_rpm=speed_rpm, points_per_period=points)
        if not self.stage_speeds:
            return first
        from thermogear.drivetrain.train import MeshTrain

        states = [first] + [stage.state(speed_rpm=first.speed_rpm * factor, points_per_period=points)
                            for stage, factor in zip(self.stage_models[model], self.stage_speeds)]
        return MeshTrain(tuple(states), self.train_repeats, self.train_phases)

    def _pieces(self, state) -> int:
        """The pieces of one period of a state (a train: of its common period, the union of its meshes' grids)."""
        from thermogear.drivetrain.train import MeshTrain

        if isinstance(state, MeshTrain) and len(state.states) > 1:
            from thermogear.drivetrain.response import train_problems

            return train_problems(state)[2].nodes.size - 1
        return state.grid.nodes.size - 1

    @property
    def backlash_mesh(self) -> bool:
        """Whether the drivetrain's mesh may separate (the case's ``dynamics.mesh`` is nonlinear)."""
        return mesh_law(self.dynamics.mesh).backlash

    def assembled(self, model: str):
        """The assembled drivetrain of one model (cached)."""
        if model not in self._assembled:
            self._assembled[model] = self.drivetrains[model].assemble()
        return self._assembled[model]

    def modes(self, model: str) -> DrivetrainModes:
        """Lowest ``mode_count`` undamped modes at the model's mean mesh stiffness."""
        return drivetrain_modes(self.assembled(model), count=self.section.mode_count)

    def response(self, model: str, speed_rpm: float | None = None,
                 points_per_period: int | None = None) -> DrivetrainResponse:
        """Exact periodic response to one mesh period of ``model`` at a pinion speed [rpm] (default the case's)."""
        state = self.mesh_states(model, speed_rpm, points_per_period)
        return drivetrain_periodic_response(self.assembled(model), state, samples_per_piece=SAMPLES_PER_PIECE,
                                            cutoff_hz=self.section.response_cutoff_hz, solves=self._solves)

    def cutoff_error(self, model: str, response: DrivetrainResponse | None = None, second_solve: bool = False):
        """The estimated error of the linear response of ``model`` (default computed here) on the section's
        ``response_cutoff_hz`` (:func:`~thermogear.drivetrain.cutoff.cutoff_error_of`: from the modes above the
        cut-off, or with ``second_solve`` from a second solve on twice it). The backlash orbit and the motion from
        rest are solved on the same modes, so this is also the estimate of the truncation their modes carry."""
        from thermogear.drivetrain.cutoff import cutoff_error_of

        response = self.response(model) if response is None else response
        return cutoff_error_of(self.assembled(model), self.mesh_states(model), response,
                               self.section.response_cutoff_hz, SAMPLES_PER_PIECE, second_solve)

    def backlash_response(self, model: str, speed_rpm: float | None = None,
                          initial_state: np.ndarray | None = None) -> DrivetrainBacklashResponse:
        """The periodic orbit with the backlash mesh (and the bearings' clearances) of ``model`` at a pinion speed
        [rpm] (default the case's), on the modes up to the section's ``response_cutoff_hz`` plus the static
        corrections of the mesh, the torque loads and every clearance, as the linear response (its error in Kv is the
        linear cut-off's: 2.5e-4 on fzg_rig_type_c at 30 kHz; set the cut-off higher to approach every DOF)."""
        from thermogear.drivetrain.backlash_response import drivetrain_backlash_response

        state = self.mesh_states(model, speed_rpm)
        return drivetrain_backlash_response(self.assembled(model), state, initial_state,
                                            substeps=backlash_substeps(self._pieces(state)),
                                            samples_per_piece=SAMPLES_PER_PIECE,
                                            cutoff_hz=self.section.response_cutoff_hz,
                                            startup_periods=self.dynamics.transient_periods, solves=self._solves)

    def transient(self, model: str) -> DrivetrainTransient:
        """The motion from rest over the case's ``dynamics.transient_periods`` mesh periods (backlash mesh where the
        case's mesh is nonlinear, else permanent contact), solved as the periodic orbit (cut-off, sub-steps)."""
        from thermogear.drivetrain.transient_response import drivetrain_transient

        state = self.mesh_states(model)
        return drivetrain_transient(self.assembled(model), state, self.dynamics.transient_periods,
                                    backlash=self.backlash_mesh, samples_per_piece=SAMPLES_PER_PIECE,
                                    substeps=backlash_substeps(self._pieces(state)),
                                    cutoff_hz=self.section.response_cutoff_hz)

    def speed_responses(self, model: str, speeds_rpm: list[float], points_per_period: int,
                        failures: tuple[type[Exception], ...]) -> list[DrivetrainResponse | Exception]:
        """:meth:`response` at each speed [rpm], sharing the rigid-body reduction and the modal basis of the first
        speed whose state was built (:func:`~thermogear.drivetrain.response.drivetrain_speed_sweep`). A speed whose
        state or response raises one of ``failures`` gets that exception in its place: if the shared solve fails,
        each speed is solved on its own so that one bad speed does not take the others with it."""
        results: list[DrivetrainResponse | Exception | None] = [None] * len(speeds_rpm)
        states = {}
        for index, speed in enumerate(speeds_rpm):
            try:
                states[index] = self.mesh_states(model, speed, points_per_period)
            except failures as error:
                results[index] = error
        assembled = self.assembled(model)
        try:
            solved = drivetrain_speed_sweep(assembled, list(states.values()), SAMPLES_PER_PIECE,
                                            self.section.response_cutoff_hz)
        except failures:
            solved = []
            for state in states.values():
                try:
                    solved.append(drivetrain_periodic_response(assembled, state, SAMPLES_PER_PIECE,
                                                               self.section.response_cutoff_hz))
                except failures as error:
                    solved.append(error)
        for index, response in zip(states, solved):
            results[index] = response
        return results

    def heat_shifts(self) -> ModeShifts:
        """Each mode's shift from the cold (elastic) to the hot (thermal) drivetrain, attributed per cause."""
        return thermal_mode_shifts(self.drivetrains[ELASTIC], self.drivetrains[THERMAL],
                                   count=self.section.mode_count, expansion_from=self.warm_moduli)


def _mean_state(model: MeshModel, points: int) -> tuple[float, float]:
    state = model.state(points_per_period=points)
    weights = np.diff(state.grid.nodes) / state.period
    return float(state.mean_mesh_stiffness), float(np.dot(state.mesh_damping, weights))


def _helix(helical) -> tuple[float, int]:
    """(β_b [rad], the pinion's hand) of a pair's :class:`~thermogear.helical.geometry.HelicalPair` (None: a spur
    pair, (0, +1))."""
    return (0.0, 1) if helical is None else (helical.base_helix_angle, helical.pinion_hand)


def case_drivetrain(case, models: tuple[str, ...] = (ELASTIC, THERMAL)) -> CaseDrivetrain:
    """Build the case's drivetrain for its elastic (cold) and thermal (hot) mesh models (module docstring)."""
    if (section := case.drivetrain) is None:
        raise CaseError("drivetrain", None, "a [drivetrain] section", "this case is the pair on rigid supports")
    points = case.dynamics.points_per_period
    mesh_models = {name: MeshModel(case, name) for name in (ELASTIC, THERMAL)}  # the simulation models
    stiffness, damping = _mean_state(mesh_models[ELASTIC], points)
    train = call_with_pieces(stage_train, case)  # each stage's own case below: the case with the stage's changes
    stage_cases = tuple(replace(case, **changes) for changes in train.case_changes)
    stage_models = {name: tuple(MeshModel(stage_case, name) for stage_case in stage_cases) for name in (ELASTIC, THERMAL)}
    cold_stages = tuple((stage.gear_pair, *_mean_state(model, points))
                        for stage, model in zip(case.stages, stage_models[ELASTIC]))
    cold = drivetrain_from_section(section, case.gear_pair, case.material, stiffness, damping, case.inertias,
                                   cold_stages, tuple(_helix(item.helical_pair) for item in (case, *stage_cases)))
    drivetrains = {ELASTIC: cold}
    notes: list[str] = []
    warm_moduli, warm_state = None, {}
    if THERMAL in models:
        hot_model = mesh_models[THERMAL]
        hot_stiffness, _ = _mean_state(hot_model, points)
        thermoelastic = hot_model.thermoelastic_mesh
        if thermoelastic is not None:
            tooth_c = float(np.mean(thermoelastic.tooth_c))
            beta = thermoelastic.gears[0].modulus_coefficient_per_k
            expansion = thermoelastic.gears[0].expansion_per_k  # the shafts of the case's [material], as the gears
            pair = hot_model.gear_pair
            geometry = {"base_radius_1": pair.pinion.base_radius, "base_radius_2": pair.wheel.base_radius,
                        "operating_pressure_angle": pair.operating_pressure_angle}
        else:  # the paper's k_T: no hot geometry; the shafts at the case's uniform bulk temperature if it has one
            bulk = getattr(case.temperature, "bulk_c", None)
            tooth_c = MODULUS_REFERENCE_C if bulk is None else float(bulk)
            beta, geometry = MODULUS_TEMPERATURE_COEFFICIENTS_PER_K["carbon_steel"], {}
            expansion = 0.0  # the paper's model keeps the cold geometry
        # the temperatures the case's temperature model predicts for the drivetrain (its provider in
        # composition.DRIVETRAIN_HEAT), or None where that model predicts none
        provider = builtin(DRIVETRAIN_HEAT, case.temperature.model)
        heat = None if provider is None else call_with_pieces(provider, case)  # the pieces it names
        temperatures, warm_state, note = shaft_temperatures(section, tooth_c, heat, thermoelastic is not None)
        notes += [note] if note else []
        stage_stiffness = tuple(_mean_state(model, points)[0] for model in stage_models[THERMAL])
        warm = WarmState(temperatures, beta, mesh_stiffness=hot_stiffness, expansion_coefficient_per_k=expansion,
                         stage_mesh_stiffness=stage_stiffness, **geometry)
        if stage_stiffness:
            notes.append("drivetrain: the further stages' meshes take their hot mean stiffness in the warm state; "
                         "their base radii and pressure angles stay cold in the mesh vectors")
        clearances = operating_clearances(section, heat, warm_state, notes)
        drivetrains[THERMAL] = with_clearances(warm_drivetrain(cold, warm), clearances)
        if expansion:
            warm_moduli = with_clearances(warm_drivetrain(cold, replace(warm, expansion_coefficient_per_k=0.0)),
                                          clearances)
    drivetrains = case_face_variations(drivetrains, mesh_models, stage_models, points, ELASTIC)  # helical spread
    return CaseDrivetrain(section, case.dynamics, case.gear_pair.pinion.teeth, drivetrains, mesh_models, tuple(notes),
                          warm_moduli, stage_models if case.stages else {}, train.speeds, train.repeats, train.phases,
                          warm_state=warm_state)


def _linear_result(response: DrivetrainResponse, harmonics: int, **common) -> DrivetrainLinearResult:
    metrics = response.metrics
    multipliers = np.abs(response.multipliers)
    train = {}
    if len(response.meshes) > 1:  # a train: each mesh over the common period
        train = {"common_period_s": response.period, "stages": stage_results(response)}
    return DrivetrainLinearResult(
        metrics["kv"], metrics["dte_rms"], metrics["dte_peak_to_peak"],
        float(multipliers.max()) if multipliers.size else None, bool(multipliers.size == 0 or multipliers.max() < 1.0),
        bearing_forces_of(response, harmonics, SPECTRUM_POINTS), response=response, **train, **common)


def _backlash_result(response: DrivetrainBacklashResponse, harmonics: int, **common) -> DrivetrainBacklashResult:
    """The backlash orbit's numbers: those of the linear result, None where the orbit was not found (with the
    reason), and the contact it makes."""
    metrics, found = response.metrics, response.converged
    multipliers = np.abs(response.multipliers)

    def shown(key: str):
        value = metrics.get(key)
        return None if not found or value is None or not math.isfinite(value) else value

    startup = metrics.get("startup") or {}
    train = {}
    if found and len(response.meshes) > 1:  # a train: each mesh over the common period, with its own contact
        train = {"common_period_s": response.period, "stages": stage_results(response)}
    forces = (bearing_forces_of(response, harmonics, SPECTRUM_POINTS) if found
              else unknown_bearing_forces(response.bearing_names, response.period, harmonics))
    return DrivetrainBacklashResult(
        shown("kv"), shown("dte_rms"), shown("dte_peak_to_peak"),
        float(multipliers.max()) if found and multipliers.size else None, response.stable, forces,
        response=response, converged=bool(found), failure=response.failure,
        contact_loss_fraction=shown("contact_loss_fraction"),
        back_side_contact=bool(metrics.get("back_side_contact")) if found else None,
        back_contact_fraction=shown("back_contact_fraction"), switches_per_period=shown("switches_per_period"),
        reached_from=startup.get("reached_from"), branch=startup.get("branch"),
        coexisting_orbits=tuple(startup.get("coexisting", [])), orbit_notes=tuple(response.notes), **train, **common)


def _transient_result(transient: DrivetrainTransient, harmonics: int, **common) -> DrivetrainTransientResult:
    """The last period of the motion from rest: Kv, DTE, contact and bearing forces (no orbit: no multipliers)."""
    metrics = transient.last_period
    train = {}
    if len(transient.meshes) > 1:  # a train: each mesh's last period
        train = {"common_period_s": transient.period, "stages": stage_results(transient)}
    return DrivetrainTransientResult(
        metrics["kv"], metrics["dte_rms"], metrics["dte_peak_to_peak"], None, None,
        bearing_forces_of(transient.last_period_forces, harmonics, SPECTRUM_POINTS), response=transient,
        transient_periods=transient.periods, contact_loss_fraction=metrics["contact_loss_fraction"],
        back_side_contact=metrics["back_side_contact"], back_contact_fraction=metrics["back_contact_fraction"],
        **train, **common)


def mesh_modes_above(built: CaseDrivetrain, model: str, rows: tuple[ModeRow, ...]) -> tuple[ModeRow, ...]:
    """The mesh-dominated modes above the listed ``rows`` (the section's ``mode_count``) and up to its
    ``response_cutoff_hz`` (issue 36: the mesh mode of a drivetrain with many shaft and bearing modes lies above the
    first twelve and must not go unlisted)."""
    every = drivetrain_modes(built.assembled(model), max_frequency_hz=built.section.response_cutoff_hz)
    return tuple(row for row in mode_rows(every, built.drivetrains[model], first=len(rows)) if row.mesh_dominated)


def drivetrain_results(built: CaseDrivetrain, models: tuple[str, ...] = (ELASTIC, THERMAL),
                       transient: bool = False, progress=None, series: dict | None = None) -> DrivetrainResults:
    """Everything ``run`` reports of a case's drivetrain (``built`` by :func:`case_drivetrain`), typed
    (:class:`~thermogear.drivetrain.results.DrivetrainResults`): per model the modes, the response (Kv, DTE, Floquet
    stability, bearing forces; with the case's nonlinear mesh the backlash orbit, its contact loss and whether it was
    found; with ``transient`` the last period of the motion from rest instead) and the speeds where mesh harmonics
    meet mesh-dominated modes; with both models, what heat moved per mode. ``progress`` is called with a step's name
    before each model's response. A ``series`` dict receives, per model, the periodic response's arrays for a results
    file (:func:`~thermogear.drivetrain.response_dataset.response_dataset_parts`)."""
    section = built.section
    mesh = f"{mesh_law(built.dynamics.mesh).description} on the drivetrain"
    if transient:
        mesh += f"; last of {built.dynamics.transient_periods} periods from rest"
    results = {}
    for model in models:
        if progress is not None:
            progress(f"drivetrain, {model} model")
        rows = mode_rows(built.modes(model), built.drivetrains[model])
        common = {"modes": rows, "mesh_modes": mesh_modes_above(built, model, rows),
                  "resonances": resonances_of(rows, built.teeth, section.bearing_harmonics, built.stages)}
        if transient:
            results[model] = _transient_result(built.transient(model), section.bearing_harmonics,
                                               cutoff_error=built.cutoff_error(model), **common)
            continue
        if built.backlash_mesh:
            response = built.backlash_response(model)
            results[model] = _backlash_result(response, section.bearing_harmonics,
                                              cutoff_error=built.cutoff_error(model), **common)
        else:
            response = built.response(model)
            results[model] = _linear_result(response, section.bearing_harmonics,
                                            cutoff_error=built.cutoff_error(model, response), **common)
        if series is not None:
            from thermogear.drivetrain.response_dataset import response_dataset_parts

            parts = response_dataset_parts(response, section.bearing_harmonics,
                                           {"model": model, "mesh": mesh, "speed_rpm": built.models[model].speed_rpm},
                                           SPECTRUM_POINTS)
            if parts is not None:
                series[model] = parts
    heat = (heat_rows(built.heat_shifts(), built.drivetrains[ELASTIC]) if ELASTIC in models and THERMAL in models
            else None)
    return DrivetrainResults(built.assembled(ELASTIC).size, section.response_cutoff_hz, mesh, built.backlash_mesh,
                             bool(transient), f"modes up to {section.response_cutoff_hz:.0f} Hz",
                             tuple(built.notes) + tuple(f"drivetrain, {name} model: {note}"
                                                        for name, result in results.items()
                                                        for note in getattr(result, "orbit_notes", ())),
                             MappingProxyType(results), heat, MappingProxyType(built.warm_state))
