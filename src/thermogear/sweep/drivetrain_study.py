"""Studies of a case with a ``[drivetrain]``: the pinion speed × any other case keys, with the linear mesh (each
speed's exact periodic response) or the backlash mesh (the orbit followed up and down in speed), planned into tasks
for the one executor and written point by point to the one task store.

Planning. The grid is a :class:`~thermogear.sweep.study.Study` (the same ``--vary`` keys, checks and held load as
every study). A *group* is one combination of the parameters other than the speed; its case is built once per worker
and reused (:func:`point_case`). With ``temperature.model = "gearbox"`` every point's case is built at its own
speed, so each point has its own steady temperatures (:func:`point_case` is the one place the temperatures of a
point are decided; the neighbour's orbit only seeds Newton, its temperatures never carry over).

* Linear mesh: a task is a group and a slice of about ``chunk_points`` speeds, which share the rigid-body reduction
  and the modal basis (:meth:`~thermogear.drivetrain.case_model.CaseDrivetrain.speed_responses`); the slices depend
  only on the study, never on the workers.
* Backlash mesh: a task is one point of one branch (group × model × direction); it follows the task of its
  neighbour speed and starts from the full state that task carried
  (:func:`~thermogear.dynamics.backlash.backlash_branch_ndof. branch_step`). The carried state is stored with the point,
  so ``--resume`` continues each branch from its last completed point, exactly as the uninterrupted run would.
"""

from __future__ import annotations

import json
import threading
import warnings
from collections import OrderedDict
from dataclasses import dataclass
from typing import Any

import numpy as np

from thermogear.dynamics.problems.continuation_directions import direction_named
from thermogear.errors import CaseError, JammingError, ModelLimitError, ProblemError
from thermogear.sweep.drivetrain_branches import DIRECTIONS
from thermogear.sweep.drivetrain_store import STAGE_KEYS, TEMPERATURES
from thermogear.temperature.kinds import temperature_source

__all__ = ["DrivetrainPlan", "plan_drivetrain_study", "point_case", "run_task"]

#: What a point's numerics may raise: the solver's and the case's refusals, a singular or overflowing matrix.
FAILURES = (ModelLimitError, CaseError, ProblemError, JammingError, np.linalg.LinAlgError, ValueError)
_CACHE_SIZE = 4
_BUILT: OrderedDict = OrderedDict()
_LOCK = threading.Lock()


@dataclass(frozen=True, eq=False)
class DrivetrainPlan:
    """A planned drivetrain study (what every task shares): ``study``, ``models``, ``directions`` (empty: the
    linear mesh), ``bearings`` (names), ``harmonics`` (the section's mesh harmonics), ``lines`` (the bearing
    spectrum's lines: the harmonics j·L_m of every stage of a train; 1 … harmonics for one mesh), ``meshes`` (their
    names; a train stores each stage's Kv, DTE and force), ``state_size`` (2 N: the full state a branch carries) and
    ``tasks`` (independent slices, or branch points with ``follows``)."""

    study: Any
    models: tuple[str, ...]
    directions: tuple[str, ...]
    bearings: tuple[str, ...]
    harmonics: int
    state_size: int
    per_point_case: bool
    speed_axis: int | None
    tasks: tuple
    follows: tuple
    identity: str = ""  # the study's definition (JSON): the key of the drivetrains built for it in a worker
    lines: tuple[int, ...] = ()
    meshes: tuple[str, ...] = ()

    @property
    def train(self) -> bool:
        return len(self.meshes) > 1

    @property
    def backlash(self) -> bool:
        return bool(self.directions)

    @property
    def dims(self) -> tuple[str, ...]:
        return ("model", *(("direction",) if self.backlash else ()), *self.study.dims)


def _speeds(study, speed_axis: int | None) -> np.ndarray:
    if speed_axis is None:
        return np.array([study.case.operating_point.speed_rpm], dtype=float)
    return np.asarray(study.parameters[speed_axis].values, dtype=float)


def point_case(study, group: tuple[int, ...], speed_axis: int | None, speed: float | None, per_point: bool):
    """The case of a group (``group``: its index along every parameter but the speed), at ``speed`` [rpm] where
    ``per_point`` (temperatures predicted at each operating point: the gearbox model), else at the case's own speed
    (each speed then evaluated on that case's mesh models). The one place a study decides which temperatures a
    point has."""
    others = [p for axis, p in enumerate(study.parameters) if axis != speed_axis]
    pairs = [(p, p.values[i]) for p, i in zip(others, group)]
    if per_point and speed_axis is not None:
        pairs.append((study.parameters[speed_axis], speed))
    return study.case.with_changes(**study._changes_for(pairs))


def _built(plan: "DrivetrainPlan", group, speed):
    """The case's drivetrain of a group (or point) and the oil and housing temperatures [°C] of its case, built once
    per process (a few kept), keyed by the study's definition (never by an object's identity, which a later study
    may reuse)."""
    from thermogear.drivetrain.case_model import case_drivetrain

    study, speed_axis, per_point, models = plan.study, plan.speed_axis, plan.per_point_case, plan.models
    key = (plan.identity, group, speed if per_point else None, models)
    with _LOCK:
        if key in _BUILT:
            _BUILT.move_to_end(key)
            return _BUILT[key]
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # the case's warnings were printed by its checks
        case = point_case(study, group, speed_axis, speed, per_point)
        built = case_drivetrain(case, models)
        built = (built, {"oil_temperature_c": float(case.lubricant.operating_temperature_c),
                         "housing_temperature_c": np.nan if case.housing.temperature_c is None
                         else float(case.housing.temperature_c)})
    with _LOCK:
        _BUILT[key] = built
        while len(_BUILT) > _CACHE_SIZE:
            _BUILT.popitem(last=False)
    return built


def plan_drivetrain_study(study, built, chunk_points: int, directions: tuple[str, ...] = DIRECTIONS
                          ) -> DrivetrainPlan:
    """Plan the study of a drivetrain case (``built``: its drivetrain, for the bearings and the state size;
    ``directions``: the branches of a backlash study)."""
    unknown = [direction for direction in directions if direction not in DIRECTIONS]
    if unknown or not directions:
        raise CaseError("--direction", ", ".join(unknown) or "none", "up | down | both",
                        "the orbit is followed from the lowest speed up, from the highest down, or both")
    speed_axis = next((a for a, p in enumerate(study.parameters) if p.key == "operating.speed_rpm"), None)
    speeds = _speeds(study, speed_axis)
    if np.any(np.diff(speeds) <= 0.0) and speeds.size > 1:
        raise CaseError("vary.speed_rpm", list(speeds), "increasing speeds", "the drivetrain study walks the speeds "
                        "in order (a branch follows its neighbour)")
    others = [p.size for a, p in enumerate(study.parameters) if a != speed_axis]
    groups = list(np.ndindex(*others)) if others else [()]
    per_point = temperature_source(study.case.temperature.model).predicted_at_load
    models = tuple(study.models)
    first = models[0]
    bearings = tuple(bearing.name for bearing in built.drivetrains[first].bearings)
    state_size = 2 * built.assembled(first).mass.shape[0]
    tasks: list = []
    follows: list = []
    if built.backlash_mesh:
        for group in groups:
            for model_index in range(len(models)):
                for direction_index, direction in enumerate(directions):
                    order = direction_named(direction).order(speeds.size)
                    previous = None
                    for speed_index in order:
                        tasks.append((group, model_index, direction_index, int(speed_index)))
                        follows.append(previous)
                        previous = len(tasks) - 1
    else:
        step = max(1, min(int(chunk_points), speeds.size))
        for group in groups:
            for start in range(0, speeds.size, step):
                tasks.append((group, slice(start, min(start + step, speeds.size))))
                follows.append(None)
        directions = ()
    harmonics = int(built.section.bearing_harmonics)
    lines = tuple(sorted({j * repeat for repeat in built.train_repeats for j in range(1, harmonics + 1)}))
    meshes = tuple(mesh.name for mesh in built.drivetrains[first].meshes)
    return DrivetrainPlan(study, models, tuple(directions), bearings, harmonics, int(state_size), per_point,
                          speed_axis, tuple(tasks), tuple(follows), json.dumps(study.describe(), sort_keys=True,
                                                                                default=str), lines, meshes)


# ------------------------------------------------------------------------------------------------ the tasks
def _missing(status: str, bearings: int, harmonics: int) -> dict[str, Any]:
    return {"status": status, "valid": False, "converged": False, "stable": False, "run_in": False,
            "bearing_dynamic_rms_n": np.full(bearings, np.nan),
            "bearing_harmonic_amplitude_n": np.full((bearings, harmonics), np.nan)}


def _forces(response, bearings: int, lines: int, harmonics: int) -> dict[str, np.ndarray]:
    """Each bearing's dynamic RMS and its amplitudes at the ``lines`` spectrum lines of the first ``harmonics`` mesh
    harmonics (of every stage of a train)."""
    from thermogear.drivetrain.case_model import bearing_force_summary

    forces = bearing_force_summary(response, harmonics)
    return {"bearing_dynamic_rms_n": np.array([forces[name]["dynamic_rms_n"] for name in forces], dtype=float),
            "bearing_harmonic_amplitude_n": np.array([forces[name]["harmonic_amplitude_n"] for name in forces],
                                                     dtype=float).reshape(bearings, lines)}


def _linear_point(response, bearings: int, lines: int, harmonics: int) -> dict[str, Any]:
    if isinstance(response, np.linalg.LinAlgError):
        return _missing(f"not computed: the periodic solve failed ({response})", bearings, lines)
    if isinstance(response, Exception):
        return _missing(f"not computed: {response}", bearings, lines)
    multipliers = np.abs(response.multipliers)
    largest = float(multipliers.max()) if multipliers.size else 0.0
    return {"status": "valid" if largest < 1.0 else "unstable", "valid": largest < 1.0, "kv": response.kv,
            "dte_rms_um": response.metrics["dte_rms"] * 1e6,
            "dte_peak_to_peak_um": response.metrics["dte_peak_to_peak"] * 1e6,
            "largest_floquet_multiplier_abs": largest, **_forces(response, bearings, lines, harmonics),
            **_stages(response)}


def linear_task(plan: DrivetrainPlan, task) -> dict[str, np.ndarray]:
    """One task of a linear drivetrain study: a group's slice of speeds, every model (arrays of the region)."""
    group, where = task
    speeds = _speeds(plan.study, plan.speed_axis)[where]
    bearings, lines, harmonics = len(plan.bearings), len(plan.lines), plan.harmonics
    points: list[list[dict]] = [[{} for _ in speeds] for _ in plan.models]
    slices = [[speed] for speed in speeds] if plan.per_point_case else [list(speeds)]
    offset = 0
    for chunk in slices:
        try:
            built, temperatures = _built(plan, group, chunk[0])
            section = built.section
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")
                responses = {model: built.speed_responses(model, [float(s) for s in chunk],
                                                          section.sweep_points_per_period, FAILURES)
                             for model in plan.models}
            for m, model in enumerate(plan.models):
                for k, response in enumerate(responses[model]):
                    points[m][offset + k] = {**_linear_point(response, bearings, lines, harmonics), **temperatures}
        except FAILURES as error:  # the group's (or point's) case or drivetrain cannot be built
            for m in range(len(plan.models)):
                for k in range(len(chunk)):
                    points[m][offset + k] = _missing(f"not computed: {error}", bearings, lines)
        offset += len(chunk)
    return _arrays(points, plan, squeeze=plan.speed_axis is None)


def _stages(response) -> dict[str, list[float]]:
    """A train's Kv, DTE RMS [um] and largest mesh force [N] of each stage (none for one mesh)."""
    if len(response.meshes) < 2:
        return {}
    from thermogear.drivetrain.case_model import stage_summary

    stages = stage_summary(response).values()
    return {f"stage_{key}": [np.nan if item[key] is None else item[key] for item in stages] for key in STAGE_KEYS}


def _arrays(points: list[list[dict]], plan: DrivetrainPlan, squeeze: bool) -> dict[str, np.ndarray]:
    """Per variable an array (model, speeds[, bearing[, harmonic]]) of the points (speed dim dropped where the
    study has no speed axis)."""
    names = {"kv": np.nan, "dte_rms_um": np.nan, "dte_peak_to_peak_um": np.nan,
             "largest_floquet_multiplier_abs": np.nan, "valid": False, "status": ""}
    result = {}
    for name, fill in names.items():
        values = np.array([[point.get(name, fill) for point in row] for row in points],
                          dtype=object if name == "status" else (bool if name == "valid" else float))
        result[name] = values
    for name in ("bearing_dynamic_rms_n", "bearing_harmonic_amplitude_n"):
        result[name] = np.array([[point[name] for point in row] for row in points], dtype=float)
    if plan.train:  # each stage's values (NaN where the point was not computed)
        for key in STAGE_KEYS:
            result[f"stage_{key}"] = np.array([[point.get(f"stage_{key}", [np.nan] * len(plan.meshes))
                                                for point in row] for row in points], dtype=float)
    for name in TEMPERATURES:  # the point's, whichever model: (speeds,)
        result[name] = np.array([[point.get(name, np.nan) for point in row] for row in points], dtype=float)
    if squeeze:
        result = {name: values[:, 0] for name, values in result.items()}
    for name in TEMPERATURES:
        result[name] = result[name][0]
    return result


def backlash_task(plan: DrivetrainPlan, task, previous: dict | None = None) -> dict[str, Any]:
    """One point of a branch of a backlash drivetrain study, started from the state ``previous`` (the neighbour's
    result) carried, or the state the task holds (a resumed branch; None: from rest)."""
    from thermogear.drivetrain.backlash_response import (SHOOTING_TOLERANCE, drivetrain_backlash_response,
                                                         reduced_backlash_system)
    from thermogear.drivetrain.response import drivetrain_backlash_system
    from thermogear.dynamics.backlash.backlash_branch_ndof import branch_step
    from thermogear.sweep.drivetrain_branches import SAMPLES_PER_PIECE, SUBSTEPS

    group, model_index, direction_index, speed_index, *stored = task
    carried = previous["carried"] if previous is not None else (stored[0] if stored else None)
    model = plan.models[model_index]
    speed = float(_speeds(plan.study, plan.speed_axis)[speed_index])
    bearings, harmonics = len(plan.bearings), len(plan.lines)
    point = _missing("", bearings, harmonics)
    try:
        built, temperatures = _built(plan, group, speed)
        point.update(temperatures)
        section = built.section
        assembled = built.assembled(model)
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            state = built.mesh_states(model, speed, section.sweep_points_per_period)  # a train: every stage's
            system, reduction = drivetrain_backlash_system(assembled, state)
            reduced, basis = reduced_backlash_system(system, section.response_cutoff_hz)
            coordinates = reduction.basis @ basis.basis
            step = branch_step(reduced, carried, coordinates, assembled.mass, SUBSTEPS, 200, SHOOTING_TOLERANCE)
            carried = step.carried
            orbit = step.orbit
            if orbit is None or not orbit.converged:
                point = {**_missing("not computed: no periodic orbit found (the shooting did not converge from the "
                                    "neighbour's orbit nor after running in)", bearings, harmonics), **temperatures}
                point["run_in"] = step.run_in
            else:
                response = drivetrain_backlash_response(assembled, state, orbit.initial_state, SUBSTEPS,
                                                        SAMPLES_PER_PIECE, section.response_cutoff_hz)
                point = {**_backlash_point(response, step.run_in, bearings, harmonics, plan.harmonics), **temperatures}
    except FAILURES as error:
        point = _missing(f"not computed: {error}", bearings, harmonics)
    point["carried"] = carried
    return point


def _backlash_point(response, run_in: bool, bearings: int, harmonics: int,
                    mesh_harmonics: int | None = None) -> dict[str, Any]:
    """``harmonics`` the spectrum lines kept, ``mesh_harmonics`` the mesh harmonics they come from (of every stage of
    a train; default the same)."""
    if not response.converged:
        return _missing(f"not computed: {response.failure or 'the orbit was not found'}", bearings, harmonics)
    metrics = response.metrics
    multipliers = np.abs(response.multipliers)
    status = "valid" if metrics["valid"] else ("unstable" if not response.stable else
                                               "not valid: a metric is not finite")
    return {"status": status, "valid": status == "valid", "converged": True, "stable": bool(response.stable),
            "run_in": run_in, "kv": np.nan if metrics["kv"] is None else metrics["kv"],
            "dte_rms_um": metrics["dte_rms"] * 1e6, "dte_peak_to_peak_um": metrics["dte_peak_to_peak"] * 1e6,
            "contact_loss_fraction": response.contact_loss_fraction,
            "back_contact_fraction": response.back_contact_fraction,
            "back_side_contact": float(metrics["back_side_contact"]),
            "largest_floquet_multiplier_abs": float(multipliers.max()) if multipliers.size else np.nan,
            **_forces(response, bearings, harmonics, mesh_harmonics or harmonics), **_stages(response)}


def run_task(plan: DrivetrainPlan, task, *previous):
    """The executor's function for either kind (the plan says which)."""
    if plan.backlash:
        return backlash_task(plan, task, *previous)
    return linear_task(plan, task)
