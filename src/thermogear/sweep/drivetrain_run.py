"""Run a drivetrain study (:mod:`thermogear.sweep.drivetrain_study`) on the one executor into the one task store:
fresh, overwritten or resumed (each branch from its last completed point), with progress per point."""

from __future__ import annotations

import json
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

from thermogear.sweep.chains import pending_chains
from thermogear.sweep.drivetrain_store import backlash_arrays, drivetrain_layout, task_region
from thermogear.sweep.drivetrain_study import DIRECTIONS, plan_drivetrain_study, point_case, run_task

__all__ = ["DrivetrainStudyRun", "run_drivetrain_study"]


@dataclass(frozen=True, eq=False)
class DrivetrainStudyRun:
    """A finished drivetrain study: ``dataset`` (the store, loaded), ``resonances`` model → mesh harmonics meeting
    modes in the speed range (of the case's own drivetrain), ``hysteresis`` (backlash, both directions: per group
    label, per model, :func:`~thermogear.sweep.hysteresis.hysteresis_bands`), ``computed`` and ``kept`` tasks."""

    dataset: Any
    resonances: dict[str, list[dict[str, Any]]]
    hysteresis: dict[str, Any]
    computed: int
    kept: int
    path: Path


def _resonances(built, models, speeds: np.ndarray) -> dict[str, list[dict[str, Any]]]:
    import warnings

    from thermogear.drivetrain.case_model import mode_table, resonance_speeds

    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return {model: [r for r in resonance_speeds(mode_table(built.modes(model), built.drivetrains[model]),
                                                    built.teeth, built.section.bearing_harmonics, built.stages)
                        if speeds.min() <= r["speed_rpm"] <= speeds.max()] for model in models}


def _pending(plan, done: set[int], store) -> tuple[list, list]:
    """The tasks still to compute and whom each follows (indices into the pending list). A branch continues from
    its first unfinished point, started from the state its last finished point stored."""
    if not plan.backlash:
        pending = [number for number in range(len(plan.tasks)) if number not in done]
        return [(number, plan.tasks[number]) for number in pending], [None] * len(pending)
    names = ["model", "direction", *plan.study.dims]
    states: list = []  # read once, where a branch is continued

    def stored_state(number: int):
        region = task_region(plan, plan.tasks[number])
        states[:] = states or [store.read_variable("branch_state")]
        values = states[0][tuple(region.get(name, slice(None)) for name in names)]
        return None if not np.isfinite(values).any() else np.asarray(values, dtype=float)

    return pending_chains(plan.tasks, plan.follows, done, stored_state)


def run_drivetrain_study(study, out: str | Path, directions: tuple[str, ...] = DIRECTIONS,
                         scheduler: str = "processes", workers: int | None = None, resume: bool = False,
                         overwrite: bool = False, chunk_points: int | None = None,
                         progress: Callable | None = None, attrs: dict | None = None,
                         dashboard: str | None = None) -> DrivetrainStudyRun:
    """Plan ``study`` (of a case with a ``[drivetrain]``), run it on ``scheduler``
    (:func:`thermogear.sweep.executor.execute`) and write it to the store ``out`` as the points finish.
    ``progress(total, completed)``: a context manager yielding ``advance(points)``, as :func:`run_study`'s."""
    import warnings
    from contextlib import nullcontext

    from thermogear.drivetrain.case_model import case_drivetrain
    from thermogear.sweep.executor import execute
    from thermogear.sweep.hysteresis import hysteresis_bands
    from thermogear.sweep.load_held import study_load_held
    from thermogear.sweep.task_store import TaskStore

    speed_axis = next((a for a, p in enumerate(study.parameters) if p.key == "operating.speed_rpm"), None)
    first_group = tuple(0 for axis, _ in enumerate(study.parameters) if axis != speed_axis)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        built = case_drivetrain(point_case(study, first_group, speed_axis, None, False), tuple(study.models))
    plan = plan_drivetrain_study(study, built, chunk_points or 8, tuple(directions))
    speeds = (np.asarray(study.parameters[speed_axis].values, dtype=float) if speed_axis is not None
              else np.array([study.case.operating_point.speed_rpm]))
    resonances = _resonances(built, plan.models, speeds)
    load, load_note = study_load_held(study)
    section = built.section
    layout = drivetrain_layout(plan, {
        "case": study.case.name, "case_name": study.case.name, "case_source": str(study.case.source),
        "kind": "drivetrain backlash speed sweep" if plan.backlash else "drivetrain speed sweep",
        "mesh": ("nonlinear (backlash; the orbit followed in speed)" if plan.backlash
                 else "linear (permanent contact)"),
        "directions": ", ".join(plan.directions), "points_per_period": section.sweep_points_per_period,
        "response_cutoff_hz": section.response_cutoff_hz, "load": load, "load_note": load_note,
        "load_held": load, "temperatures": ("per point (the gearbox model's steady state at each operating point)"
                                            if plan.per_point_case else "the case's"),
        "resonances": json.dumps(resonances), **(attrs or {})})
    store = TaskStore.open(out, layout, resume=resume, overwrite=overwrite)
    done = store.done_tasks()
    pending, follows = _pending(plan, done, store)
    per_task = [_points(plan, task) for task in plan.tasks]
    total = sum(per_task)
    completed = sum(per_task[number] for number in done)
    with (progress(total, completed) if progress is not None else nullcontext(lambda points=1: None)) as advance:
        def finished(index: int, result) -> None:
            number, task = pending[index]
            region = task_region(plan, plan.tasks[number])
            arrays = backlash_arrays(result, plan.state_size, len(plan.meshes)) if plan.backlash else result
            store.write(number, region, arrays)
            advance(per_task[number])

        execute(run_task, plan, [task for _, task in pending], finished, scheduler, workers, dashboard,
                follows=follows)
    dataset = store.dataset()
    hysteresis = {}
    if plan.backlash and tuple(plan.directions) == DIRECTIONS and speed_axis is not None:
        for group in _groups(plan):
            select = {p.name: p.values[i] for p, i in zip([p for a, p in enumerate(study.parameters)
                                                            if a != speed_axis], group)}
            swings = dataset[["dte_peak_to_peak_um"]].where(dataset["valid"])
            label = ", ".join(f"{name}={value:g}" for name, value in select.items()) or "all"
            hysteresis[label] = hysteresis_bands(swings, variable="dte_peak_to_peak_um", select=select or None)
    return DrivetrainStudyRun(dataset, resonances, hysteresis, len(pending), len(done), store.path)


def _groups(plan) -> list[tuple[int, ...]]:
    others = [p.size for a, p in enumerate(plan.study.parameters) if a != plan.speed_axis]
    return list(np.ndindex(*others)) if others else [()]


def _points(plan, task) -> int:
    """Grid points × models a task computes (a branch point: one)."""
    if plan.backlash:
        return 1
    where = task[1]
    return (where.stop - where.start) * len(plan.models)
