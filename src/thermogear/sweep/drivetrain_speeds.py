"""A speed sweep of a case's drivetrain: Kv, DTE and the bearing forces per speed, mesh-dominated resonances marked.

The study machinery's fast path batches the 1-DOF pair; a drivetrain has hundreds of DOFs, so its sweep runs per
speed: for each pinion speed the mesh model's state over one mesh period (``[drivetrain] sweep_points_per_period``
intervals) and the exact periodic response on the modal reduction of the drivetrain up to ``response_cutoff_hz``.
The speeds of one worker task share the rigid-body reduction and the modal basis
(:func:`~thermogear.drivetrain.response.drivetrain_speed_sweep`): the reduction is exact, and the basis of the
task's first speed equals each speed's own wherever the mean mesh stiffness does not change with speed (measured
to rounding, 1e-11, on the built-in sets; the tests). A speed that fails is marked "not computed" with its reason,
the others are computed. This function runs in the calling process; the study of a case on the executor (worker
processes with one BLAS thread each, a scheduler, a store) is :mod:`thermogear.sweep.drivetrain_study`. The mesh is linear (permanent
contact) here.
"""

from __future__ import annotations

import warnings
from dataclasses import dataclass
from typing import Any, Callable

import numpy as np

from thermogear.errors import CaseError, ModelLimitError

__all__ = ["DrivetrainSweep", "SweepOrigin", "drivetrain_speed_sweep", "plot_drivetrain_sweep"]

@dataclass(frozen=True)
class SweepOrigin:
    """What a drivetrain sweep records of its case and what its worker processes rebuild it from: ``name``,
    ``source`` (where the case was read), ``document`` (the case as read: the workers build the drivetrain from it)
    and ``load_held`` (what stays fixed as the speed varies, e.g. "constant torque")."""

    name: str
    source: str
    document: dict
    load_held: str


#: Speeds per task: small enough for a live progress bar, large enough that a task outweighs its dispatch.
_SPEEDS_PER_TASK = 8


_FAILURES = (ModelLimitError, CaseError, np.linalg.LinAlgError)


def _point(response, harmonics: int) -> dict[str, Any]:
    from thermogear.drivetrain.result_tables import bearing_force_summary

    if isinstance(response, np.linalg.LinAlgError):  # e.g. a transition matrix that overflowed at a tiny speed
        return {"status": f"not computed: the periodic solve failed ({response})"}
    if isinstance(response, Exception):
        return {"status": f"not computed: {response}"}
    multipliers = np.abs(response.multipliers)
    largest = float(multipliers.max()) if multipliers.size else 0.0
    forces = bearing_force_summary(response, harmonics)
    point = {"status": "valid" if largest < 1.0 else "unstable", "kv": response.kv,
             "dte_rms_um": response.metrics["dte_rms"] * 1e6,
             "dte_peak_to_peak_um": response.metrics["dte_peak_to_peak"] * 1e6, "multiplier": largest,
             "bearing_rms": [forces[name]["dynamic_rms_n"] for name in forces],
             "bearing_harmonics": [forces[name]["harmonic_amplitude_n"] for name in forces]}
    if len(response.meshes) > 1:  # a train: each mesh's Kv, DTE RMS and largest force (stage order)
        from thermogear.drivetrain.result_tables import stage_summary

        stages = stage_summary(response).values()
        point.update({f"stage_{key}": [item[key] for item in stages]
                      for key in ("kv", "dte_rms_um", "max_mesh_force_n")})
    return point


def _compute_with(built, models: tuple[str, ...], speeds: list[float]) -> list[dict[str, dict[str, Any]]]:
    """One task's speeds: per model one shared reduction and modal basis (``CaseDrivetrain.speed_responses``)."""
    section = built.section
    responses = {model: built.speed_responses(model, speeds, section.sweep_points_per_period, _FAILURES)
                 for model in models}
    return [{model: _point(responses[model][index], section.bearing_harmonics) for model in models}
            for index in range(len(speeds))]


class DrivetrainSweep:
    """Results of :func:`drivetrain_speed_sweep`: ``dataset`` (xarray, dims model × speed_rpm [× bearing ×
    harmonic]) and ``resonances`` model → list of (speed [rpm], harmonic, mode [Hz], label, mesh share)."""

    def __init__(self, dataset, resonances: dict[str, list[dict[str, Any]]]) -> None:
        self.dataset = dataset
        self.resonances = resonances


def drivetrain_speed_sweep(built, origin: SweepOrigin, speeds: np.ndarray, models: tuple[str, ...],
                           progress: Callable[[int], None] | None = None) -> DrivetrainSweep:
    """Sweep the pinion speed [rpm] of a built drivetrain case (a :class:`~thermogear.drivetrain.case_model.
    CaseDrivetrain` holding ``models``; ``origin`` its case's name, source and document) in this process, in slices
    of speeds that share a modal basis; ``progress(count)`` as speeds finish. A study of a case (any grid, any
    scheduler, into a store) is :func:`thermogear.sweep.api.study` (``thermogear.sweep(case, ...)``)."""
    import json

    import xarray as xr

    from thermogear.drivetrain.result_tables import mode_table, resonance_speeds

    speeds = np.asarray(speeds, dtype=float)
    if speeds.ndim != 1 or speeds.size == 0 or np.any(speeds <= 0.0) or not np.all(np.isfinite(speeds)):
        raise CaseError("speed_rpm", speeds.tolist(), "positive, finite speeds [rpm]",
                        "a speed sweep of the drivetrain")
    section = built.section
    missing = [model for model in models if model not in built.drivetrains]
    if missing:
        raise CaseError("models", ", ".join(missing), ", ".join(built.drivetrains),
                        "the drivetrain was built for these models only")
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        resonances = {model: [r for r in resonance_speeds(mode_table(built.modes(model), built.drivetrains[model]),
                                                          built.teeth, section.bearing_harmonics, built.stages)
                              if speeds.min() <= r["speed_rpm"] <= speeds.max()] for model in models}
    bearings = [bearing.name for bearing in built.drivetrains["elastic"].bearings]
    chunks = [speeds[i:i + _SPEEDS_PER_TASK].tolist() for i in range(0, speeds.size, _SPEEDS_PER_TASK)]
    results: dict[int, list] = {}
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        for index, chunk in enumerate(chunks):
            results[index] = _compute_with(built, models, chunk)
            if progress is not None:
                progress(len(chunk))
    points = [point for index in range(len(chunks)) for point in results[index]]
    repeats = built.train_repeats  # a train's bearing lines: the mesh harmonics j·L_m of every stage
    lines = sorted({j * repeat for repeat in repeats for j in range(1, section.bearing_harmonics + 1)})
    harmonics = len(lines)
    meshes = [mesh.name for mesh in built.drivetrains[models[0]].meshes]
    shape = (len(models), speeds.size)

    def field(key: str, extra: tuple[int, ...] = ()) -> np.ndarray:
        values = np.full(shape + extra, np.nan)
        for j, point in enumerate(points):
            for i, model in enumerate(models):
                if key in point[model]:
                    values[(i, j)] = np.asarray(point[model][key], dtype=float).reshape(extra) if extra else \
                        (np.nan if point[model][key] is None else point[model][key])
        return values

    status = np.array([[point[model]["status"] for point in points] for model in models], dtype=object)
    dims = ("model", "speed_rpm")
    dataset = xr.Dataset(
        {"kv": (dims, field("kv")), "dte_rms_um": (dims, field("dte_rms_um")),
         "dte_peak_to_peak_um": (dims, field("dte_peak_to_peak_um")),
         "largest_floquet_multiplier_abs": (dims, field("multiplier")),
         "valid": (dims, status == "valid"), "status": (dims, status.astype(str)),
         "bearing_dynamic_rms_n": (dims + ("bearing",), field("bearing_rms", (len(bearings),))),
         "bearing_harmonic_amplitude_n": (dims + ("bearing", "harmonic"),
                                          field("bearing_harmonics", (len(bearings), harmonics)))},
        coords={"model": list(models), "speed_rpm": speeds, "bearing": bearings,
                "harmonic": np.array(lines)},
        attrs={"case": origin.name, "kind": "drivetrain speed sweep", "mesh": "linear (permanent contact)",
               "points_per_period": section.sweep_points_per_period, "response_cutoff_hz": section.response_cutoff_hz,
               "resonances": json.dumps(resonances), "load_held": origin.load_held})
    if len(meshes) > 1:
        dataset = dataset.assign_coords(mesh=meshes)
        for key, unit in (("kv", "-"), ("dte_rms_um", "um"), ("max_mesh_force_n", "N")):
            dataset[f"stage_{key}"] = (dims + ("mesh",), field(f"stage_{key}", (len(meshes),)))
            dataset[f"stage_{key}"].attrs["units"] = unit
        dataset["harmonic"].attrs["description"] = "spectrum line over the common period (j·L_m of each mesh)"
    for name, unit in (("kv", "-"), ("dte_rms_um", "um"), ("dte_peak_to_peak_um", "um"),
                       ("bearing_dynamic_rms_n", "N"), ("bearing_harmonic_amplitude_n", "N")):
        dataset[name].attrs["units"] = unit
    return DrivetrainSweep(dataset, resonances)


def plot_drivetrain_sweep(sweep: DrivetrainSweep):
    """Kv and the largest first-harmonic bearing force against speed, invalid points left out, the mesh-dominated
    resonances (harmonic j meets a mode) as dashed lines. Returns the figure."""
    import matplotlib.pyplot as plt

    data = sweep.dataset
    figure, (top, bottom) = plt.subplots(2, 1, figsize=(8.0, 6.0), sharex=True, constrained_layout=True)
    for index, model in enumerate(data["model"].values):
        valid = data["valid"].values[index]
        speeds = data["speed_rpm"].values
        kv = np.where(valid, data["kv"].values[index], np.nan)
        first = np.where(valid, np.nanmax(data["bearing_harmonic_amplitude_n"].values[index, :, :, 0], axis=1),
                         np.nan)
        style = "-" if index == 0 else "--"
        top.plot(speeds, kv, style, label=str(model))
        bottom.plot(speeds, first, style, label=str(model))
        for resonance in sweep.resonances.get(str(model), []) if index == 0 else ():  # cold modes (hot: table)
            dominated = resonance["mesh_dominated"]
            for axis in (top, bottom):
                axis.axvline(resonance["speed_rpm"], color="0.3" if dominated else "0.7",
                             linestyle="--" if dominated else ":", linewidth=1.0)
            top.annotate(f"{resonance['harmonic']}× {resonance['mode_hz']:.0f} Hz", (resonance["speed_rpm"], 1.0),
                         xycoords=("data", "axes fraction"), fontsize=7, rotation=90, va="top", ha="right",
                         color="0.2" if dominated else "0.5")
    top.set_ylabel("Kv [-]")
    bottom.set_ylabel("largest bearing force, 1× mesh [N]")
    bottom.set_xlabel("pinion speed [rpm]")
    top.legend(fontsize=8)
    top.set_title(f"{data.attrs['case']}: drivetrain speed sweep ({data.attrs['load_held']}); mesh harmonic meets a "
                  f"mode: dashed mesh-dominated, dotted mesh-coupled ({data['model'].values[0]} modes)", fontsize=9)
    if not np.any(data["valid"].values):
        top.text(0.5, 0.5, "no valid point", transform=top.transAxes, ha="center")
    return figure
