"""Studies of the nonlinear (backlash) mesh: the solution branch followed in speed, up and down.

Where teeth separate the steady response of a gear pair depends on where it came from: near the primary resonance
a speed run-up stays on the high-amplitude branch beyond the linear peak and drops ("jumps down") off it, a
run-down jumps up later — the hysteresis of a backlash oscillator (Kahraman & Singh 1990). A grid point therefore
has one result per sweep direction. For every combination of the other parameters (a group), the mesh model gives
one backlash problem per speed and :func:`~thermogear.dynamics.backlash_continuation.follow_branch` solves them in
order, each from its neighbour's orbit, ``up`` (lowest speed first), ``down`` or both.

Continuation is sequential along the speed axis: these studies run in one process and write one zarr store at
the end (no chunked resume and no Dask; a few seconds per thousand speeds and model).
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

import numpy as np

from thermogear.dynamics.backlash_continuation import follow_branch
from thermogear.errors import CaseError
from thermogear.mesh.model import MeshModel

__all__ = ["DIRECTIONS", "BRANCH_VARIABLES", "branch_study", "hysteresis_bands", "write_branch_store"]

DIRECTIONS = ("up", "down", "both")

#: Per-direction, per-model result variables: name → (units, long name).
BRANCH_VARIABLES: dict[str, tuple[str, str]] = {
    "kv": ("1", "dynamic load factor Kv = max pair force / static load (Luo & Li Eq. 29)"),
    "max_pair_load": ("N", "largest single-pair force over the orbit"),
    "max_system_load_ratio": ("1", "largest mesh force / static load"),
    "dte_mean": ("m", "mean dynamic transmission error"),
    "dte_rms": ("m", "RMS of the dynamic transmission error about its mean"),
    "dte_peak_to_peak": ("m", "peak-to-peak dynamic transmission error"),
    "contact_loss_fraction": ("1", "fraction of the period without driving-flank contact"),
    "back_side_contact": ("1", "1 where a back flank is struck"),
    "period_count": ("1", "mesh periods after which the response repeats (1 periodic, >1 subharmonic)"),
    "converged": ("1", "1 where a stable periodic or subharmonic orbit was found"),
    "floquet_multiplier_max": ("1", "largest Floquet multiplier modulus of the orbit"),
    "residual": ("1", "scaled residual |phi_NT(y0) - y0| of the orbit's Newton iteration (large: not converged)"),
}
_FROM_BRANCH = {"kv": "kv", "max_pair_load": "max_pair_force", "max_system_load_ratio": "max_mesh_force",
                "dte_mean": "dte_mean", "dte_rms": "dte_rms", "dte_peak_to_peak": "dte_peak_to_peak",
                "contact_loss_fraction": "contact_loss_fraction", "floquet_multiplier_max": "largest_multiplier",
                "residual": "residual"}


def _directions(direction: str) -> tuple[str, ...]:
    if direction not in DIRECTIONS:
        raise CaseError("direction", direction, " | ".join(DIRECTIONS),
                        "a branch is followed from the lowest speed up, from the highest down, or both")
    return ("up", "down") if direction == "both" else (direction,)


def branch_study(study, direction: str = "both", progress=None):
    """The xarray Dataset of a nonlinear-mesh study: dims ``(direction, model, *parameters)`` for the variables of
    :data:`BRANCH_VARIABLES` and ``response`` ("periodic" | "subharmonic" | "non-periodic" | "failed"), plus the
    per-point ``static_load`` and ``mesh_frequency_hz``. ``progress(points)`` is called after each group."""
    import xarray as xr  # noqa: PLC0415

    directions = _directions(direction)
    parameters = study.parameters
    speed_axis = next((a for a, p in enumerate(parameters) if p.key == "operating.speed_rpm"), None)
    shape = study.shape
    full = (len(directions), len(study.models), *shape)
    arrays = {name: np.full(full, np.nan) for name in BRANCH_VARIABLES}
    response = np.full(full, "", dtype=object)
    static_load = np.full(shape, np.nan)
    frequency = np.full(shape, np.nan)
    others = [range(p.size) for a, p in enumerate(parameters) if a != speed_axis]
    for rest in np.ndindex(*[len(r) for r in others]) if others else [()]:
        index = list(rest)
        if speed_axis is not None:
            index.insert(speed_axis, slice(None))
        values = [p.values[i] if not isinstance(i, slice) else p.values[0] for p, i in zip(parameters, index)]
        group_case = study.case_at(tuple(values))
        speeds = (np.asarray(parameters[speed_axis].values, dtype=float) if speed_axis is not None
                  else np.array([group_case.operating_point.speed_rpm]))
        for model_index, model in enumerate(study.models):
            mesh = MeshModel(group_case, model)
            loads = np.array([mesh.normal_load(speed) for speed in speeds])
            problems = [mesh.state(speed_rpm=speed, normal_load=load).backlash_problem(
                group_case.dynamics.damping_in_flight) for speed, load in zip(speeds, loads)]
            where = tuple(index)
            static_load[where] = loads if speed_axis is not None else loads[0]
            frequency[where] = (mesh.gear_pair.pinion.teeth * speeds / 60.0 if speed_axis is not None
                                else mesh.gear_pair.pinion.teeth * speeds[0] / 60.0)
            for direction_index, way in enumerate(directions):
                branch = follow_branch(problems, way, parameter=speeds,
                                       include_damping_force=group_case.dynamics.include_damping_force)
                target = (direction_index, model_index, *where)
                for name, source in _FROM_BRANCH.items():
                    values = branch[source] / loads if name == "max_system_load_ratio" else branch[source]
                    arrays[name][target] = values if speed_axis is not None else values[0]
                arrays["back_side_contact"][target] = branch["back_side_contact"].astype(float)
                arrays["period_count"][target] = branch.period_count.astype(float)
                arrays["converged"][target] = branch.converged.astype(float)
                response[target] = branch.response if speed_axis is not None else branch.response[0]
        if progress is not None:
            progress(int(speeds.size))
    coords: dict[str, Any] = {"direction": ("direction", np.array(directions, dtype=str)),
                              "model": ("model", np.array(study.models, dtype=str))}
    for parameter in parameters:
        coords[parameter.name] = (parameter.name, np.asarray(parameter.values))
    dims = ("direction", "model", *study.dims)
    data = {name: (dims, values, {"units": BRANCH_VARIABLES[name][0], "long_name": BRANCH_VARIABLES[name][1]})
            for name, values in arrays.items()}
    data["response"] = (dims, response.astype(str), {"long_name": "periodic | subharmonic | non-periodic | failed"})
    data["static_load"] = (study.dims, static_load, {"units": "N", "long_name": "static normal load w"})
    data["mesh_frequency_hz"] = (study.dims, frequency, {"units": "Hz", "long_name": "mesh frequency z1 n1 / 60"})
    return xr.Dataset(data, coords=coords, attrs={"mesh": "nonlinear", "directions": ",".join(directions),
                                                   "case": study.case.name})


def hysteresis_bands(dataset, variable: str = "dte_peak_to_peak", tolerance: float = 0.02,
                     jump: float = 0.5) -> dict[str, Any]:
    """Where the up and the down branch differ (the jump phenomenon), per model: the speed band [rpm] in which
    ``variable`` differs by more than ``tolerance`` (relative to the larger), and per sweep direction its jumps —
    the changes of ``variable`` between neighbouring speeds larger than ``jump`` (relative to the smaller), each
    with the speed midway between them, in the order the sweep meets them, and whether the amplitude rises or falls
    there (a smooth branch has none). Empty without a speed axis or without both directions."""
    if "speed_rpm" not in dataset.dims or list(dataset["direction"].values) != ["up", "down"]:
        return {}
    result = {}
    speeds = np.asarray(dataset["speed_rpm"].values, dtype=float)
    for model in dataset["model"].values:
        selected = dataset[variable].sel(model=model)
        extra = [d for d in selected.dims if d not in ("direction", "speed_rpm")]
        if extra:  # one band per study: take the first value of any other parameter
            selected = selected.isel({d: 0 for d in extra})
        branches = {d: np.asarray(selected.sel(direction=d).values, dtype=float) for d in ("up", "down")}
        up, down = branches["up"], branches["down"]
        differ = np.abs(up - down) > tolerance * np.maximum(np.abs(up), np.abs(down))
        entry: dict[str, Any] = {"differ": bool(np.any(differ))}
        if np.any(differ):
            entry["band_rpm"] = [float(speeds[differ].min()), float(speeds[differ].max())]
        for way, values in branches.items():
            if way == "down":  # the down sweep visits the speeds from the highest
                values, order = values[::-1], speeds[::-1]
            else:
                order = speeds
            smaller = np.maximum(np.minimum(np.abs(values[:-1]), np.abs(values[1:])), 1e-300)
            change = np.abs(np.diff(values)) / smaller
            jumps = np.flatnonzero(np.nan_to_num(change) > jump)
            entry[f"{way}_sweep_jumps"] = [
                {"speed_rpm": float(0.5 * (order[i] + order[i + 1])),
                 "amplitude": "rises" if values[i + 1] > values[i] else "falls", "ratio": float(change[i] + 1.0)}
                for i in jumps]
        result[str(model)] = entry
    return result


def write_branch_store(dataset, path, overwrite: bool = False):
    """Write a branch study to the zarr store ``path`` (consolidated metadata, ownership marker); an existing path
    is refused unless ``overwrite``, and then only when thermogear wrote it. Written into a hidden sibling folder
    and renamed, so an interrupted run leaves the previous store or none."""
    import shutil  # noqa: PLC0415
    import tempfile  # noqa: PLC0415

    from thermogear.ownership import require_owned, resolve_output, write_marker  # noqa: PLC0415
    from thermogear.sweep.store import _quiet_zarr  # noqa: PLC0415

    target = resolve_output(path)
    if target.exists():
        if not overwrite:
            raise CaseError("out", str(target), "a path that does not exist yet (or --overwrite)",
                            "the result store exists; overwrite it explicitly")
        require_owned(target, "sweep-store", "--out", "overwritten")
    try:
        target.parent.mkdir(parents=True, exist_ok=True)
        staging = Path(tempfile.mkdtemp(prefix=f".{target.name}.partial-", dir=target.parent))
    except OSError as error:
        raise CaseError("--out", str(target), "a folder thermogear can create and write",
                        f"cannot write there: {error.strerror or error}") from None
    try:
        write_marker(staging, "sweep-store")
        with _quiet_zarr():
            dataset.to_zarr(str(staging), mode="a", consolidated=True)
        if target.exists():
            shutil.rmtree(target)
        staging.rename(target)
    finally:
        if staging.exists():
            shutil.rmtree(staging, ignore_errors=True)
    return target
