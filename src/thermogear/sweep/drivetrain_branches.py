"""The speed sweep of a drivetrain with the backlash mesh: the periodic orbit followed up and down in speed.

Near a mesh resonance softened by contact loss the orbit has two stable branches over a band of speeds; a run-up
stays on one, a run-down on the other, and each jumps where its branch ends (Kahraman & Singh, J. Sound Vib. 142
(1990) 49–75). Per model (cold elastic, hot thermal) and direction the orbit is continued over the speeds
(:func:`~thermogear.drivetrain.backlash_sweep.drivetrain_backlash_branch`: each speed starts from its neighbour's
orbit, run in where that branch is lost), each speed on the modes of its mean system up to the section's
``response_cutoff_hz``. At each speed whose orbit was found the response
(:func:`~thermogear.drivetrain.backlash_response.drivetrain_backlash_response`, on the same modal basis) starts at
the branch's converged state, so its shooting ends at its first residual: Kv, DTE, contact loss, back-flank
contact, the Floquet multipliers and each bearing's force on its housing in the first mesh harmonics. A speed whose
state could not be built or whose orbit was not found is stored as missing (NaN) with its status saying why, never
as valid; an orbit found but unstable keeps its numbers, marked "unstable".
"""

from __future__ import annotations

import json
import warnings
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np

from thermogear.errors import CaseError, ModelLimitError, ProblemError

__all__ = ["DIRECTIONS", "SUBSTEPS", "DrivetrainBranchSweep", "drivetrain_branch_sweep", "largest_kv"]

DIRECTIONS = ("up", "down")
#: Sub-steps per mesh-grid interval in which the shooting looks for contact switches: the backlash solver's default
#: (fewer let a switch go unseen on stiff supports, the solver's tests), the same for the branch and the response,
#: so the response re-solves exactly the system whose orbit the branch found.
SUBSTEPS = 16
#: Samples per mesh-grid interval of the response (bearing-force RMS and harmonics, DTE), as the linear drivetrain
#: sweep: with ``sweep_points_per_period`` intervals (≥ 16, 128 by default) that is ≥ 64 samples per mesh period
#: besides both sides of every contact switch, which the trajectory samples exactly; the sampling costs about
#: half of a point's time.
SAMPLES_PER_PIECE = 4
#: What a speed's numerics may raise: the solver's and the case's refusals, a singular or overflowing matrix
#: (LinAlgError; SciPy's ValueError "Array must not contain infs or NaNs", e.g. the modal basis at 1e-12 rpm).
_FAILURES = (ModelLimitError, CaseError, ProblemError, np.linalg.LinAlgError, ValueError)


@dataclass(frozen=True, eq=False)
class DrivetrainBranchSweep:
    """``dataset`` (xarray, dims model × direction × speed_rpm [× bearing × harmonic]), ``resonances`` model →
    mesh harmonics meeting modes in the range, ``hysteresis`` model → bands where the branches differ and the
    jumps of each direction (:func:`thermogear.sweep.hysteresis.hysteresis_bands` on the DTE peak-to-peak)."""

    dataset: Any
    resonances: dict[str, list[dict[str, Any]]]
    hysteresis: dict[str, Any]


def _missing(status: str) -> dict[str, Any]:
    return {"status": status, "converged": False, "stable": False, "run_in": False}


def _point(response, run_in: bool, harmonics: int) -> dict[str, Any]:
    """One speed's numbers from its response (the branch's converged state as the start)."""
    from thermogear.drivetrain.case_model import bearing_force_summary

    if not response.converged:
        return _missing(f"not computed: {response.failure or 'the orbit was not found'}")
    metrics = response.metrics
    multipliers = np.abs(response.multipliers)
    forces = bearing_force_summary(response, harmonics)
    return {"status": "valid" if metrics["valid"] else ("unstable" if not response.stable else
                                                         "not valid: a metric is not finite"),
            "converged": True, "stable": response.stable, "run_in": run_in,
            "kv": np.nan if metrics["kv"] is None else metrics["kv"],
            "dte_rms_um": metrics["dte_rms"] * 1e6, "dte_peak_to_peak_um": metrics["dte_peak_to_peak"] * 1e6,
            "contact_loss_fraction": response.contact_loss_fraction,
            "back_contact_fraction": response.back_contact_fraction,
            "back_side_contact": float(metrics["back_side_contact"]),
            "multiplier": float(multipliers.max()) if multipliers.size else np.nan,
            "bearing_rms": [forces[name]["dynamic_rms_n"] for name in forces],
            "bearing_harmonics": [forces[name]["harmonic_amplitude_n"] for name in forces]}


def _branch_points(built, model: str, states: dict[int, Any], direction: str,
                   progress: Callable[[int], None] | None) -> dict[int, dict[str, Any]]:
    """The points of one model and direction: the continuation over the speeds whose state was built, then the
    response at each speed where the orbit was found."""
    from thermogear.drivetrain.backlash_response import SHOOTING_TOLERANCE, drivetrain_backlash_response
    from thermogear.drivetrain.backlash_sweep import drivetrain_backlash_branch

    section = built.section
    order = sorted(states)
    assembled = built.assembled(model)
    try:
        branch = drivetrain_backlash_branch(assembled, [states[i] for i in order], direction, substeps=SUBSTEPS,
                                            tolerance=SHOOTING_TOLERANCE, cutoff_hz=section.response_cutoff_hz,
                                            progress=progress, measure_swing=False)
    except _FAILURES as error:  # a speed whose system cannot be built takes the branch down: find it, go on
        bad = _unbuildable(assembled, states, section.response_cutoff_hz)
        if not bad or len(bad) == len(order):  # not one speed's fault (e.g. the backlash unknown), or all of them
            if progress is not None:
                progress(len(order))
            return {i: _missing(f"not computed: {bad.get(i, error)}") for i in order}
        if progress is not None:
            progress(len(bad))
        rest = {i: state for i, state in states.items() if i not in bad}
        return {**{i: _missing(f"not computed: {reason}") for i, reason in bad.items()},
                **_branch_points(built, model, rest, direction, progress)}
    points = {}
    for place, index in enumerate(order):
        if not branch.converged[place]:
            points[index] = _missing("not computed: no periodic orbit found (the shooting did not converge from "
                                     "the neighbour's orbit nor after running in)")
            continue
        try:
            start = branch.initial_state[place]
            response = drivetrain_backlash_response(assembled, states[index], start[np.isfinite(start)],
                                                    SUBSTEPS, SAMPLES_PER_PIECE, section.response_cutoff_hz)
        except _FAILURES as error:
            points[index] = _missing(f"not computed: {error}")
            continue
        points[index] = _point(response, bool(branch.run_in[place]), section.bearing_harmonics)
    return points


def _unbuildable(assembled, states: dict[int, Any], cutoff_hz: float) -> dict[int, Exception]:
    """The speeds whose backlash system (and modal basis) cannot be built, with the error."""
    from thermogear.drivetrain.backlash_response import reduced_backlash_system
    from thermogear.drivetrain.response import drivetrain_backlash_system

    bad = {}
    for index, state in states.items():
        try:
            reduced_backlash_system(drivetrain_backlash_system(assembled, state)[0], cutoff_hz)
        except _FAILURES as error:
            bad[index] = error
    return bad


def _task(built, task: tuple[str, str, list[float]],
          progress: Callable[[int], None] | None = None) -> dict[int, dict[str, Any]]:
    """One model and direction over the speeds (a worker's task): the mesh state of each speed (a speed whose state
    fails is missing with the reason), then the branch and the responses."""
    model, direction, speeds = task
    states, failed = {}, {}
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # the case's warnings were printed by its checks
        for index, speed in enumerate(speeds):
            try:
                states[index] = built.models[model].state(speed_rpm=speed,
                                                          points_per_period=built.section.sweep_points_per_period)
            except _FAILURES as error:
                failed[index] = _missing(f"not computed: {error}")
        if progress is not None and failed:
            progress(len(failed))
        return {**failed, **(_branch_points(built, model, states, direction, progress) if states else {})}


def drivetrain_branch_sweep(built, origin, speeds: np.ndarray, models: tuple[str, ...],
                            directions: Sequence[str] = DIRECTIONS, progress: Callable[[int], None] | None = None
                            ) -> DrivetrainBranchSweep:
    """Follow the backlash orbit of ``built`` (a :class:`~thermogear.drivetrain.case_model.CaseDrivetrain` holding
    ``models``; ``origin`` its case's :class:`~thermogear.sweep.drivetrain_speeds.SweepOrigin`) over the pinion
    ``speeds`` [rpm] in each direction for each model (module docstring), in this process, ``progress(1)`` per
    point. A study of a case (any grid, any scheduler, into a resumable store) is :mod:`thermogear.sweep.
    drivetrain_study` (``thermogear.sweep(case, ...)``)."""
    from thermogear.drivetrain.case_model import mode_table, resonance_speeds
    from thermogear.sweep.hysteresis import hysteresis_bands

    speeds = np.asarray(speeds, dtype=float)
    if speeds.ndim != 1 or speeds.size == 0 or np.any(speeds <= 0.0) or not np.all(np.isfinite(speeds)):
        raise CaseError("speed_rpm", speeds.tolist(), "positive, finite speeds [rpm]",
                        "a speed sweep of the drivetrain")
    speeds = np.unique(speeds)  # the continuation walks the speeds in order
    directions = tuple(directions)
    if not directions or any(d not in DIRECTIONS for d in directions) or len(set(directions)) != len(directions):
        raise CaseError("--direction", ", ".join(directions), "up | down | both",
                        "the orbit is followed from the lowest speed up, from the highest down, or both")
    section, teeth = built.section, built.teeth
    keys = [(model, direction) for model in models for direction in directions]
    tasks = [(model, direction, speeds.tolist()) for model, direction in keys]
    points: dict[tuple[str, str], dict[int, dict[str, Any]]] = {}
    for key, task in zip(keys, tasks):
        points[key] = _task(built, task, progress)
    resonances = {}
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        for model in models:
            rows = mode_table(built.modes(model), built.drivetrains[model])
            resonances[model] = [r for r in resonance_speeds(rows, teeth, section.bearing_harmonics)
                                 if speeds.min() <= r["speed_rpm"] <= speeds.max()]
    bearings = [bearing.name for bearing in built.drivetrains[models[0]].bearings]
    dataset = _dataset(points, models, directions, speeds, bearings, section.bearing_harmonics)
    dataset.attrs.update({
        "case": origin.name, "kind": "drivetrain backlash speed sweep",
        "mesh": "nonlinear (backlash; the orbit followed in speed)", "directions": ", ".join(directions),
        "points_per_period": section.sweep_points_per_period, "response_cutoff_hz": section.response_cutoff_hz,
        "substeps": SUBSTEPS, "resonances": json.dumps(resonances), "load_held": origin.load_held})
    # the branches a swept gearbox follows: unstable orbits and missing points left out (NaN ends a band)
    swings = dataset[["dte_peak_to_peak_um"]].where(dataset["valid"])
    hysteresis = hysteresis_bands(swings, variable="dte_peak_to_peak_um") if directions == DIRECTIONS else {}
    dataset.attrs["hysteresis"] = json.dumps(hysteresis)
    return DrivetrainBranchSweep(dataset, resonances, hysteresis)


def _dataset(points, models, directions, speeds, bearings, harmonics: int):
    import xarray as xr

    shape = (len(models), len(directions), speeds.size)

    def field(key: str, extra: tuple[int, ...] = (), fill: Any = np.nan, kind: Any = float) -> np.ndarray:
        values = np.full(shape + extra, fill, dtype=kind)
        for i, model in enumerate(models):
            for j, direction in enumerate(directions):
                for k, point in points[(model, direction)].items():
                    if key in point:
                        values[(i, j, k)] = np.asarray(point[key], dtype=kind).reshape(extra)
        return values

    dims = ("model", "direction", "speed_rpm")
    status = field("status", fill="", kind=object).astype(str)
    data = {name: (dims, field(key)) for name, key in (
        ("kv", "kv"), ("dte_rms_um", "dte_rms_um"), ("dte_peak_to_peak_um", "dte_peak_to_peak_um"),
        ("contact_loss_fraction", "contact_loss_fraction"), ("back_contact_fraction", "back_contact_fraction"),
        ("back_side_contact", "back_side_contact"), ("largest_floquet_multiplier_abs", "multiplier"))}
    for name in ("converged", "stable", "run_in"):
        data[name] = (dims, field(name, fill=False, kind=bool))
    data["valid"] = (dims, status == "valid")
    data["status"] = (dims, status)
    data["bearing_dynamic_rms_n"] = (dims + ("bearing",), field("bearing_rms", (len(bearings),)))
    data["bearing_harmonic_amplitude_n"] = (dims + ("bearing", "harmonic"),
                                            field("bearing_harmonics", (len(bearings), harmonics)))
    dataset = xr.Dataset(data, coords={"model": list(models), "direction": list(directions), "speed_rpm": speeds,
                                       "bearing": bearings, "harmonic": np.arange(1, harmonics + 1)})
    for name, unit in (("kv", "-"), ("dte_rms_um", "um"), ("dte_peak_to_peak_um", "um"),
                       ("contact_loss_fraction", "-"), ("back_contact_fraction", "-"),
                       ("bearing_dynamic_rms_n", "N"), ("bearing_harmonic_amplitude_n", "N")):
        dataset[name].attrs["units"] = unit
    return dataset


def largest_kv(dataset) -> dict[str, dict[str, float] | None]:
    """Per "model/direction": the largest Kv over the valid points and its speed [rpm] (None without one)."""
    result = {}
    for model in dataset["model"].values:
        for direction in dataset["direction"].values:
            part = dataset.sel(model=model, direction=direction)
            kv = np.where(part["valid"].values, part["kv"].values, np.nan)
            finite = np.isfinite(kv)
            index = int(np.nanargmax(kv)) if finite.any() else None
            result[f"{model}/{direction}"] = None if index is None else {
                "kv": float(kv[index]), "speed_rpm": float(part["speed_rpm"].values[index])}
    return result
