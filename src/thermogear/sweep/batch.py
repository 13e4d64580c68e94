"""Evaluation of many operating points: the fast batch path and the one-Simulation-per-point path.

Both ask the mesh model (:class:`~thermogear.mesh.model.MeshModel`) for the physics; neither re-derives it.

Fast path
---------
Points of a study that differ only in the pinion speed form a group (one case, one mesh model). Over one mesh
period the pair positions in roll distance do not depend on the speed: with a fixed interval count the grid in
roll is the same at every speed and only the times scale, T ∝ 1/n1. So the mesh model's state — k(τ), c(τ), the
pair stiffness — is asked once per group and load, at the group's reference speed, and for each point:

* the normal load is the mesh model's at that speed (a case that gives a power keeps the power: w ∝ 1/n1);
* the damping is the reference state's scaled by the mesh model's own ``damping_scaling`` — the friction damping
  of Eqs. 27–28 is a power law in speed and load when the geometry, the oil temperature and the load shares stay
  as they are (``thermogear.friction.damping``); where the load shares move with the load (the paper's secant k_T in the
  load share) the group is split by load, and where the model cannot say (a temperature that depends on the
  speed, deviations that excite the mesh) the points go to the per-point path;
* where the stiffness depends on the load (the paper's secant k_T), one state per distinct load;
* me·ẍ + c·ẋ + k·x = w on the nodes t_s = t_ref/r (r = n1/n1,ref) is, in the reference time t_ref = r·t,
  (me·r²)·x'' + (c·r)·x' + k·x = w on the reference nodes: the periodic solver runs all speeds on one node grid;
* the metrics come from a compiled kernel (:mod:`thermogear.dynamics.periodic_orbits.periodic_batch_metrics`) that
samples the
  exact orbit as :func:`~thermogear.dynamics.response.compute_metrics` does.

The regression test runs both paths over grids of every sweepable key and both models and asks for a relative
difference of at most 1e-9 on every stored variable.

Slow path
---------
:func:`evaluate_point` runs a point's ``Simulation(case, model)``: ``.run("periodic")``.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np

from thermogear import warning_scope
from thermogear.dynamics.periodic_orbits.periodic_batch_metrics import periodic_metrics_batch
from thermogear.dynamics.problems.mesh_laws import mesh_law
from thermogear.dynamics.results.metrics import dynamic_factor
from thermogear.errors import JammingError, ModelLimitError, ProblemError
from thermogear.mesh.model import MeshModel
from thermogear.sweep.evaluation_methods import evaluation_method
from thermogear.sweep.metric_variables import DTE_VARIABLES
from thermogear.warning_causes import warning_text

__all__ = ["FLAG_VARIABLES", "MODEL_VARIABLES", "POINT_VARIABLES", "GroupTables", "empty_block_result", "evaluate_block",
           "evaluate_loads", "evaluate_point", "evaluate_speeds", "group_tables"]

#: Per-model result variables: name → (units, long name).
MODEL_VARIABLES: dict[str, tuple[str, str]] = {
    "kv": ("1", "dynamic load factor Kv = max pair dynamic load / static load (Luo & Li Eq. 29)"),
    "max_pair_load": ("N", "largest single-pair dynamic load over the period"),
    "max_system_load_ratio": ("1", "largest system dynamic load / static load"),
    **DTE_VARIABLES,
    "max_velocity": ("m/s", "largest |dx/dt| over the period"),
    "natural_frequency_hz": ("Hz", "natural frequency sqrt(mean k / me) / 2 pi"),
    "mean_mesh_stiffness": ("N/m", "time-mean mesh stiffness over one period"),
    "floquet_multiplier_max": ("1", "largest Floquet multiplier modulus (>= 1: parametric instability)"),
    "stable": ("1", "1 where a periodic steady state exists (all Floquet multipliers inside the unit circle)"),
    "contact_loss": ("1", "1 where the mesh force turns negative (the teeth would separate; linear model invalid)"),
    "jammed": ("1", "1 where the gears jam (the thermal expansion closes the backlash): no result, NaN metrics"),
}
#: The per-model flags, stored as int8 (0 where unwritten); every other variable is a float (NaN where unwritten).
FLAG_VARIABLES = ("stable", "contact_loss", "jammed")
#: Per-point result variables (the same for every model).
POINT_VARIABLES: dict[str, tuple[str, str]] = {
    "mesh_frequency_hz": ("Hz", "mesh frequency z1 n1 / 60"),
    "static_load": ("N", "static normal load w (total over the face width)"),
}


# ------------------------------------------------------------------------------------------- tables
@dataclass(frozen=True)
class GroupTables:
    """One mesh period of a mesh model at a reference speed and load, and how its damping scales."""

    model: str
    speed_rpm: float  # reference speed of the nodes and the damping [rpm]
    normal_load: float  # reference load of the damping [N]
    mass: float  # me [kg]
    nodes: np.ndarray  # (n+1,) [s] at the reference speed
    stiffness: np.ndarray  # (n,) k [N/m]
    damping: np.ndarray  # (n,) c [N·s/m] at the reference speed and load
    pair_stiffness: np.ndarray  # (slots, n) [N/m]
    include_damping_force: bool
    samples_per_interval: int  # orbit samples per interval for the metrics: the case's, as in Simulation.run
    natural_frequency_hz: float
    mean_mesh_stiffness: float
    pinion_teeth: int
    speed_exponent: float  # c ∝ n1^a at a fixed load
    load_exponent: float | None  # c ∝ w^b at a fixed speed; None: one table per load


def group_tables(mesh: MeshModel, normal_load: float | None = None, points_per_period: int | None = None
                 ) -> GroupTables | None:
    """The speed-independent tables of a mesh model at its case's speed and the load ``normal_load`` [N] (default:
    the case's); None where the fast path cannot be exact for this model (see the module docstring)."""
    scaling = mesh.damping_scaling
    if scaling is None or mesh_law(mesh.case.dynamics.mesh).backlash:  # the nonlinear mesh: sweep.branches
        return None
    state = mesh.state(normal_load=normal_load, points_per_period=points_per_period)
    if np.any(state.pair_deviation != 0.0):
        return None
    problem = state.problem()
    case = mesh.case
    return GroupTables(model=mesh.model, speed_rpm=float(state.speed_rpm), normal_load=float(state.normal_load),
                       mass=float(problem.mass), nodes=np.ascontiguousarray(problem.nodes),
                       stiffness=np.ascontiguousarray(problem.stiffness),
                       damping=np.ascontiguousarray(problem.damping),
                       pair_stiffness=np.ascontiguousarray(problem.pair_stiffness),
                       include_damping_force=bool(case.dynamics.include_damping_force),
                       samples_per_interval=int(case.dynamics.samples_per_interval),
                       natural_frequency_hz=float(problem.natural_frequency),
                       mean_mesh_stiffness=float(problem.mean_stiffness),
                       pinion_teeth=int(mesh.gear_pair.pinion.teeth), speed_exponent=float(scaling[0]),
                       load_exponent=scaling[1])


def fast_path_applies(meshes) -> bool:
    """True where every mesh model of ``meshes`` (one per model of a study's case) runs on the fast path (a study's
    scheduler choice: its other points may still differ, and each group falls back to the per-point path where it
    must)."""
    with warning_scope.ignored():  # the blocks raise these warnings again, and report them
        return all(group_tables(mesh) is not None for mesh in meshes)


# ------------------------------------------------------------------------------------------- fast path
LOAD_KEYS = ("operating.torque_nm", "operating.power_kw", "operating.fzg_load_stage")  # keys that set the load


def evaluate_loads(tables: GroupTables, speeds_rpm, loads, samples: int | None = None) -> dict[str, np.ndarray]:
    """Metrics of one group at many (speed [rpm], normal load [N]) points; arrays of the shape of ``speeds_rpm``.
    Loads other than the table's need its ``load_exponent``. Unstable points (a Floquet multiplier modulus >= 1)
    get NaN metrics and ``stable`` 0."""
    speeds = np.atleast_1d(np.asarray(speeds_rpm, dtype=float))
    loads = np.broadcast_to(np.asarray(loads, dtype=float), speeds.shape).astype(float)
    load_ratio = loads / tables.normal_load
    if tables.load_exponent is None and np.any(load_ratio != 1.0):
        raise ValueError("evaluate_loads: this model's damping is not a power law in the load; "
                         "build one GroupTables per load")
    ratio = speeds / tables.speed_rpm
    mass = tables.mass * ratio**2
    # damping at (n1, w) is c_ref·r^a·(w/w_ref)^b; in the reference time it is multiplied by r
    factor = ratio ** (tables.speed_exponent + 1.0)
    if tables.load_exponent is not None:
        factor = factor * load_ratio**tables.load_exponent
    _check_coefficients(tables, mass, factor, loads)
    moduli, values = periodic_metrics_batch(np.ascontiguousarray(mass), tables.nodes, tables.stiffness,
                                            tables.damping, np.ascontiguousarray(factor), np.ascontiguousarray(loads),
                                            tables.pair_stiffness,
                                            int(tables.samples_per_interval if samples is None else samples),
                                            tables.include_damping_force)
    stable = moduli[:, 0] < 1.0
    with np.errstate(invalid="ignore"):
        contact_loss = np.where(stable, values[:, 2] < 0.0, False)
    return {
        "kv": dynamic_factor(values[:, 0], loads),
        "max_pair_load": values[:, 0],
        "max_system_load_ratio": values[:, 1] / loads,
        "dte_mean": values[:, 3],
        "dte_rms": values[:, 4],
        "dte_peak_to_peak": values[:, 5] - values[:, 6],
        "max_velocity": values[:, 7] * ratio,
        "natural_frequency_hz": np.full(speeds.shape, tables.natural_frequency_hz),
        "mean_mesh_stiffness": np.full(speeds.shape, tables.mean_mesh_stiffness),
        "floquet_multiplier_max": moduli[:, 0].copy(),
        "stable": stable.astype(np.int8),
        "contact_loss": contact_loss.astype(np.int8),
        "jammed": np.zeros(speeds.shape, dtype=np.int8),  # a jammed point never reaches the fast path
        "mesh_frequency_hz": tables.pinion_teeth * speeds / 60.0,
        "static_load": loads.copy(),
    }


def _check_coefficients(tables: GroupTables, mass: np.ndarray, factor: np.ndarray, loads: np.ndarray) -> None:
    """The linear mesh model needs k > 0, c >= 0, me > 0 and finite numbers (as the per-point solver)."""
    if (np.any(tables.stiffness <= 0.0) or np.any(tables.damping < 0.0) or np.any(factor < 0.0)
            or np.any(mass <= 0.0)):
        raise ProblemError("stiffness/damping/mass", "non-positive value", "k > 0, c >= 0, me > 0",
                           "the linear mesh model needs positive stiffness and mass and non-negative damping")
    if not (np.all(np.isfinite(tables.stiffness)) and np.all(np.isfinite(tables.damping))
            and np.all(np.isfinite(factor)) and np.all(np.isfinite(mass)) and np.all(np.isfinite(loads))):
        raise ProblemError("stiffness/damping/force", "non-finite value", "finite numbers", "NaN has no meaning here")


def evaluate_speeds(tables: GroupTables, speeds_rpm, samples: int | None = None) -> dict[str, np.ndarray]:
    """Metrics of one group at many speeds [rpm] under the table's load."""
    return evaluate_loads(tables, speeds_rpm, tables.normal_load, samples)


def load_scaled_tables(mesh: MeshModel) -> bool:
    """True where one GroupTables serves every load of this model by its damping's load exponent (its stiffness
    and load shares do not move with the load): the points that differ only in speed and load share one."""
    scaling = mesh.damping_scaling
    return scaling is not None and scaling[1] is not None and not mesh.stiffness_depends_on_load


def evaluate_group(mesh: MeshModel, speeds_rpm, reference: GroupTables | None = None, loads=None
                   ) -> dict[str, np.ndarray] | None:
    """Metrics of a mesh model at many speeds [rpm]; None where the fast path cannot be exact for this model (the
    caller runs the per-point path). ``loads``: the normal load [N] at each speed (default: the mesh model's at
    that speed); the mesh model takes them as arguments, so the model of one case serves the points of cases that
    differ from it only in load. ``reference``: tables of the same case at another load, where
    :func:`load_scaled_tables` lets them serve every load."""
    speeds = np.asarray(speeds_rpm, dtype=float)
    loads = mesh.normal_loads(speeds) if loads is None else np.asarray(loads, dtype=float)
    if load_scaled_tables(mesh):
        reference = reference if reference is not None else group_tables(mesh)
        return None if reference is None else evaluate_loads(reference, speeds, loads)
    result: dict[str, np.ndarray] = {}
    for load in np.unique(loads):
        members = np.flatnonzero(loads == load)
        tables = group_tables(mesh, float(load))
        if tables is None:
            return None
        values = evaluate_loads(tables, speeds[members], loads[members])
        for name, array in values.items():
            result.setdefault(name, np.empty(speeds.shape, dtype=array.dtype))[members] = array
    return result


# ------------------------------------------------------------------------------------------- slow path
def evaluate_point(simulation) -> dict[str, float]:
    """Metrics of one point from its :class:`~thermogear.simulation.Simulation` (one case under one model, the
    reference path): ``simulation.run("periodic")``, and its dynamics problem where the solution is refused."""
    from thermogear.dynamics.periodic_orbits.periodic import floquet_multipliers

    problem = simulation.problem
    result = {name: math.nan for name in MODEL_VARIABLES}
    result.update(natural_frequency_hz=problem.natural_frequency, mean_mesh_stiffness=problem.mean_stiffness,
                  mesh_frequency_hz=problem.mesh_frequency, static_load=problem.static_load, contact_loss=0,
                  jammed=0)
    try:
        with warning_scope.ignored():
            metrics = simulation.run("periodic").metrics
    except ModelLimitError:
        result["floquet_multiplier_max"] = float(np.max(np.abs(floquet_multipliers(problem))))
        result["stable"] = 0
        return result
    result.update(kv=metrics["kv"], max_pair_load=metrics["max_pair_load"],
                  max_system_load_ratio=metrics["max_system_load_ratio"], dte_mean=metrics["dte_mean"],
                  dte_rms=metrics["dte_rms"], dte_peak_to_peak=metrics["dte_peak_to_peak"],
                  max_velocity=metrics["max_velocity"], floquet_multiplier_max=metrics["floquet_multipliers_abs"][0],
                  stable=int(metrics["stable"]), contact_loss=int(metrics["contact_loss"]["detected"]))
    return result


# ------------------------------------------------------------------------------------------- blocks
def empty_block_result(models: tuple[str, ...], shape: tuple[int, ...]) -> dict[str, np.ndarray]:
    """Arrays of a block: per-model variables (models, *shape), per-point variables (*shape)."""
    result: dict[str, np.ndarray] = {}
    for name in MODEL_VARIABLES:
        dtype = np.int8 if name in FLAG_VARIABLES else float
        result[name] = np.full((len(models), *shape), 0 if dtype is np.int8 else np.nan, dtype=dtype)
    for name in POINT_VARIABLES:
        result[name] = np.full(shape, np.nan)
    return result


def evaluate_block(study, block, method: str = "batch") -> tuple[dict[str, np.ndarray], list[str]]:
    """Result arrays of one block of a study and the distinct warning messages raised while computing it.

    ``method``: ``"batch"`` (points that differ only in speed run through the fast path where it is exact) or
    ``"simulation"`` (one Simulation per point and model).
    """
    shape = block.shape
    result = empty_block_result(study.models, shape)
    axes = [parameter.values[part] for parameter, part in zip(study.parameters, block.slices)]
    speed_axis = next((a for a, p in enumerate(study.parameters) if p.key == "operating.speed_rpm"), None)
    load_axes = {a for a, p in enumerate(study.parameters) if p.key in LOAD_KEYS}
    # per model, the mesh model (and for a load-scaled model its tables) of the first row of the rows that differ
    # only in load: the mesh model takes the load as an argument, so it serves them all
    shared: dict[tuple, tuple[MeshModel, GroupTables | None]] = {}
    messages: list[str] = []
    with warning_scope.recorded() as caught:
        # a group: the points of the block that differ only in speed (a row along the speed axis); without a
        # speed axis every point is a group of one at the case's speed
        rows = [axis for axis in range(len(shape)) if axis != speed_axis]
        members = len(axes[speed_axis]) if speed_axis is not None else 1
        for row in np.ndindex(*(shape[axis] for axis in rows)):
            position = dict(zip(rows, row))
            values = [axes[axis][position[axis]] if axis != speed_axis else axes[axis][0] for axis in range(len(shape))]
            indices = tuple(np.arange(members) if axis == speed_axis else np.full(members, position[axis])
                            for axis in range(len(shape)))
            try:
                group_case = study.case_at(tuple(values))
            except JammingError:  # the gears jam at these values (at every speed): marked, NaN, never refused
                result["jammed"][(slice(None), *indices)] = 1
                continue
            speeds = (np.array(axes[speed_axis], dtype=float) if speed_axis is not None
                      else np.array([group_case.operating_point.speed_rpm], dtype=float))
            for model_index, model in enumerate(study.models):
                try:
                    _evaluate_model(study, method, shared, group_case, model, model_index, values, axes,
                                    (speed_axis, load_axes, members), speeds, indices, result)
                except JammingError:  # a temperature the model computes closes the backlash
                    result["jammed"][(model_index, *indices)] = 1
                    for name in MODEL_VARIABLES:
                        if name not in FLAG_VARIABLES:
                            result[name][(model_index, *indices)] = np.nan
                    result["stable"][(model_index, *indices)] = 0
                    result["contact_loss"][(model_index, *indices)] = 0
    for item in caught:
        text = warning_text(item)
        if text not in messages:
            messages.append(text)
    return result, messages


def _evaluate_model(study, method, shared, group_case, model, model_index, values, axes, layout, speeds, indices,
                    result) -> None:
    """One model over one group of a block: the fast path where it is exact, else one Simulation per point."""
    from thermogear.orchestrator import Orchestrator  # noqa: PLC0415  (the model chain only where a point runs it)

    speed_axis, load_axes, members = layout
    if evaluation_method(method).batched:
        mesh = MeshModel(group_case, model)
        key = (model, *(values[a] for a in range(len(values)) if a != speed_axis and a not in load_axes))
        if key not in shared:
            shared[key] = (mesh, group_tables(mesh) if load_scaled_tables(mesh) else None)
        first, tables = shared[key]
        group = evaluate_group(first, speeds, tables, loads=mesh.normal_loads(speeds))
        if group is not None:
            _store(result, group, model_index, indices)
            return
    values = list(values)
    for member in range(members):
        if member:
            values[speed_axis] = axes[speed_axis][member]
        point_case = group_case if member == 0 else study.case_at(tuple(values))
        point = Orchestrator(point_case, (model,), "periodic").simulation(model)  # the one orchestrator's wiring
        one = {k: np.array([v]) for k, v in evaluate_point(point).items()}
        _store(result, one, model_index, tuple(np.array([index[member]]) for index in indices))


def _store(result: dict[str, np.ndarray], values: dict[str, Any], model_index: int, indices) -> None:
    for name in MODEL_VARIABLES:
        result[name][(model_index, *indices)] = values[name]
    for name in POINT_VARIABLES:
        result[name][indices] = values[name]
