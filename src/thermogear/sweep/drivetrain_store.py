"""The store of a drivetrain study (:mod:`thermogear.sweep.drivetrain_study`): its layout
(:class:`~thermogear.sweep.task_store.StoreLayout`: the response per model (× direction) × parameters, each
bearing's forces, a train's stages, the temperatures of each point's case and the state each backlash branch carries
on from) and the region and values each task writes."""

from __future__ import annotations

import json
from typing import Any

import numpy as np

__all__ = ["STAGE_KEYS", "TEMPERATURES", "backlash_arrays", "drivetrain_layout", "task_region"]

#: A train's per-stage results: stored as ``stage_<key>`` (model, *parameters, mesh).
STAGE_KEYS = {"kv": ("1", "dynamic factor Kv of each stage's mesh"),
              "dte_rms_um": ("um", "RMS of each stage's dynamic transmission error"),
              "max_mesh_force_n": ("N", "largest force of each stage's mesh")}
#: Per point: the temperatures its case was built with [°C].
TEMPERATURES = ("oil_temperature_c", "housing_temperature_c")


def drivetrain_layout(plan, extra_attrs: dict):
    """The store of a drivetrain study: per model (× direction) × parameters the response, per bearing its forces,
    and for a backlash study the state each branch carries on (``branch_state``)."""
    from thermogear.sweep.study import case_fingerprint
    from thermogear.sweep.task_store import StoreLayout, StoreVariable

    study = plan.study
    dims = plan.dims
    scalar = [("kv", "float", "1", "dynamic factor Kv of the drivetrain's mesh"),
              ("dte_rms_um", "float", "um", "RMS of the dynamic transmission error"),
              ("dte_peak_to_peak_um", "float", "um", "peak-to-peak dynamic transmission error"),
              ("largest_floquet_multiplier_abs", "float", "1", "largest Floquet multiplier modulus"),
              ("valid", "bool", "1", "True where the point has a stable periodic orbit with finite metrics"),
              ("status", "str", "", "valid | unstable | not computed: why")]
    if plan.backlash:
        scalar += [("contact_loss_fraction", "float", "1", "share of the period without driving-flank contact"),
                   ("back_contact_fraction", "float", "1", "share of the period on the back flanks"),
                   ("back_side_contact", "float", "1", "1 where a back flank is struck"),
                   ("converged", "bool", "1", "True where the orbit was found"),
                   ("stable", "bool", "1", "True where the orbit found is stable"),
                   ("run_in", "bool", "1", "True where the neighbour's orbit was lost and the point run in")]
    variables = [StoreVariable(name, dims, kind, units, text) for name, kind, units, text in scalar]
    variables += [StoreVariable("bearing_dynamic_rms_n", (*dims, "bearing"), "float", "N",
                                "RMS of each bearing's dynamic force"),
                  StoreVariable("bearing_harmonic_amplitude_n", (*dims, "bearing", "harmonic"), "float", "N",
                                "radial amplitude of each bearing's force at the mesh harmonics")]
    variables += [StoreVariable("oil_temperature_c", study.dims, "float", "degC", "oil temperature of the point's "
                                "case (the gearbox model's steady state with temperature.model = 'gearbox')"),
                  StoreVariable("housing_temperature_c", study.dims, "float", "degC", "housing temperature of the "
                                "point's case (NaN where the case gives none)")]
    if plan.train:  # each stage's values (the backlash branches too)
        variables += [StoreVariable(f"stage_{key}", (*dims, "mesh"), "float", units, text)
                      for key, (units, text) in STAGE_KEYS.items()]
    if plan.backlash:
        variables.append(StoreVariable("branch_state", (*dims, "state"), "float", "",
                                       "full state (q, dq/dt) the branch carries on from this point (resume)"))
    coords: dict[str, Any] = {"model": list(plan.models)}
    if plan.backlash:
        coords["direction"] = list(plan.directions)
    for parameter in study.parameters:
        coords[parameter.name] = np.asarray(parameter.values)
    coords["bearing"] = list(plan.bearings)
    coords["harmonic"] = np.asarray(plan.lines)
    if plan.train:
        coords["mesh"] = list(plan.meshes)
    if plan.backlash:
        coords["state"] = np.arange(plan.state_size)
    chunks = {"model": 1, "direction": 1, **{p.name: 1 for p in study.parameters if p.key != "operating.speed_rpm"}}
    definition = {**study.describe(), "kind": "drivetrain backlash branches" if plan.backlash else
                  "drivetrain speeds", "directions": list(plan.directions)}
    if not plan.backlash:  # the slices of speeds the tasks share a modal basis over: part of the study's identity
        definition["speeds_per_task"] = max((task[1].stop - task[1].start for task in plan.tasks), default=1)
    attrs = {"case_json": json.dumps(study.case.document, sort_keys=True, default=str),
             "case_document_sha256": case_fingerprint(study.case.document), **extra_attrs}
    return StoreLayout(coords=coords, variables=tuple(variables), tasks=len(plan.tasks), definition=definition,
                       attrs=attrs, chunks=chunks)


def task_region(plan, task) -> dict[str, Any]:
    """The store region one task writes."""
    study = plan.study
    if plan.backlash:
        group, model_index, direction_index, speed_index = task
        region: dict[str, Any] = {"model": model_index, "direction": direction_index}
    else:
        group, speeds = task
        region = {}
    names = [p.name for a, p in enumerate(study.parameters) if a != plan.speed_axis]
    region.update(dict(zip(names, group)))
    if plan.speed_axis is not None:
        region[study.parameters[plan.speed_axis].name] = speed_index if plan.backlash else speeds
    return region


def backlash_arrays(point: dict[str, Any], state_size: int, meshes: int = 1) -> dict[str, Any]:
    """The stored values of one branch point (the carried state NaN before the first orbit; a train of ``meshes``
    meshes: each stage's values, NaN where the point was not computed)."""
    values = {name: point.get(name, np.nan) for name in ("kv", "dte_rms_um", "dte_peak_to_peak_um",
                                                          "largest_floquet_multiplier_abs", "contact_loss_fraction",
                                                          "back_contact_fraction", "back_side_contact")}
    values.update({name: bool(point.get(name, False)) for name in ("valid", "converged", "stable", "run_in")})
    values.update({name: point.get(name, np.nan) for name in TEMPERATURES})
    values["status"] = point["status"]
    values["bearing_dynamic_rms_n"] = point["bearing_dynamic_rms_n"]
    values["bearing_harmonic_amplitude_n"] = point["bearing_harmonic_amplitude_n"]
    if meshes > 1:
        values.update({f"stage_{key}": np.asarray(point.get(f"stage_{key}", [np.nan] * meshes), dtype=float)
                       for key in STAGE_KEYS})
    carried = point["carried"]
    values["branch_state"] = np.full(state_size, np.nan) if carried is None else np.asarray(carried, dtype=float)
    return values
