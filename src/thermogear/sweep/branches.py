"""Studies of the nonlinear (backlash) mesh: the solution branch followed in speed, up and down.

Where teeth separate the steady response of a gear pair depends on where it came from: near the primary resonance
a speed run-up stays on the high-amplitude branch beyond the linear peak and drops ("jumps down") off it, a
run-down jumps up later — the hysteresis of a backlash oscillator (Kahraman & Singh 1990). A grid point therefore
has one result per sweep direction. For every combination of the other parameters (a group), the mesh model gives
one backlash problem per speed and :func:`~thermogear.dynamics.backlash_continuation.follow_branch` solves them in
order, each from its neighbour's orbit, ``up`` (lowest speed first), ``down`` or both.

Continuation is sequential along the speed axis, but the groups are independent: they run in parallel on a pool
of threads (the backlash integrator releases Python's global interpreter lock) and the study is written as one
zarr store at the end (no chunked resume and no Dask; a few seconds per thousand speeds and model). A group whose
gears jam (the thermal expansion closes the backlash) is marked ``jammed`` and the others are computed.
"""

from __future__ import annotations

import warnings
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

from thermogear import warning_scope
from thermogear.dynamics.backlash_continuation import follow_branch
from thermogear.errors import CaseError, JammingError
from thermogear.mesh.model import PREDICTED_AT_LOAD_TEMPERATURE_MODELS, MeshModel
from thermogear.sweep.branch_store import BRANCH_VARIABLES, branch_layout, branch_region
from thermogear.sweep.hysteresis import hysteresis_bands
from thermogear.sweep.load_held import study_load_held

__all__ = ["DIRECTIONS", "BRANCH_VARIABLES", "branch_study", "hysteresis_bands", "write_branch_store"]

DIRECTIONS = ("up", "down", "both")

_FROM_BRANCH = {"kv": "kv", "max_pair_load": "max_pair_force", "max_system_load_ratio": "max_mesh_force",
                "dte_mean": "dte_mean", "dte_rms": "dte_rms", "dte_peak_to_peak": "dte_peak_to_peak",
                "contact_loss_fraction": "contact_loss_fraction", "back_contact_fraction": "back_contact_fraction",
                "floquet_multiplier_max": "largest_multiplier",
                "residual": "residual"}


def _directions(direction: str) -> tuple[str, ...]:
    if direction not in DIRECTIONS:
        raise CaseError("direction", direction, " | ".join(DIRECTIONS),
                        "a branch is followed from the lowest speed up, from the highest down, or both")
    return ("up", "down") if direction == "both" else (direction,)


@dataclass(frozen=True)
class _Group:
    """The results of one group (one combination of the parameters other than speed), all speeds of it.

    Arrays ``(directions, models, speeds)`` per variable, ``jammed`` and ``natural_frequency_hz``
    ``(models, speeds)``, ``static_load`` and ``mesh_frequency_hz`` (speeds,)."""

    arrays: dict[str, np.ndarray]
    response: np.ndarray
    jammed: np.ndarray
    static_load: np.ndarray
    mesh_frequency_hz: np.ndarray
    natural_frequency_hz: np.ndarray  # (models, speeds) of the linear mesh with every pair in contact [Hz]


def _group_values(study, rest: tuple[int, ...], speed_axis: int | None) -> tuple[list, tuple]:
    """The parameter values of a group's first point and the index of the group in the grid (a slice along the
    speed axis)."""
    index: list[Any] = list(rest)
    if speed_axis is not None:
        index.insert(speed_axis, slice(None))
    values = [p.values[i] if not isinstance(i, slice) else p.values[0] for p, i in zip(study.parameters, index)]
    return values, tuple(index)


def _speed_cases(group_case, speeds: np.ndarray) -> list | None:
    """One case per speed where the case's temperatures are predicted at its own operating point (the gearbox
    model: each speed has its own steady temperatures, so its own hot geometry, E(T) and oil); None otherwise
    (every speed evaluated on the group's case)."""
    if group_case.temperature.model not in PREDICTED_AT_LOAD_TEMPERATURE_MODELS:
        return None
    return [group_case.with_changes(**{"operating.speed_rpm": float(speed)}) for speed in speeds]


def _problems(group_case, model: str, speeds: np.ndarray) -> tuple[list, np.ndarray]:
    """The backlash problem of every speed [rpm] of one model of a group's case, and the static loads [N]. A speed
    whose gears jam gives None (with a gearbox case each speed has its own temperatures: some may jam, others
    not); on the group's case a jam at the case's temperatures raises JammingError (every speed jams)."""
    cases = _speed_cases(group_case, speeds)
    if cases is None:
        mesh = MeshModel(group_case, model)
        loads = np.array([mesh.normal_load(speed) for speed in speeds])
        problems = [mesh.state(speed_rpm=speed, normal_load=load).backlash_problem(
            group_case.dynamics.damping_in_flight) for speed, load in zip(speeds, loads)]
        return problems, loads
    problems, loads = [], np.full(speeds.size, np.nan)
    for index, (case, speed) in enumerate(zip(cases, speeds)):
        try:
            mesh = MeshModel(case, model)
            loads[index] = mesh.normal_load(speed)
            problems.append(mesh.state(speed_rpm=speed, normal_load=loads[index]).backlash_problem(
                case.dynamics.damping_in_flight))
        except JammingError:  # this speed's steady temperatures close the backlash
            problems.append(None)
        except CaseError as error:  # e.g. temperatures beyond the material data: say at which speed
            raise CaseError(error.key, error.value, error.allowed, f"{error.reason} (at {speed:g} rpm, the gearbox "
                            "model's steady temperatures there)") from None
    return problems, loads


def _solve_group(study, rest: tuple[int, ...], speed_axis: int | None, directions: tuple[str, ...]) -> _Group:
    """Both branches of every model of one group. A case whose gears jam (the thermal expansion closes the
    backlash) gives NaN results marked ``jammed``, never an error: the other groups are computed."""
    values, _ = _group_values(study, rest, speed_axis)
    speeds = (np.asarray(study.parameters[speed_axis].values, dtype=float) if speed_axis is not None else None)
    count = 1 if speeds is None else speeds.size
    shape = (len(directions), len(study.models), count)
    arrays = {name: np.full(shape, np.nan) for name in BRANCH_VARIABLES}
    arrays["converged"][:] = 0.0  # a jammed point has no orbit: never labelled converged (nor NaN)
    response = np.full(shape, "jammed", dtype=object)
    jammed = np.zeros((len(study.models), count), dtype=bool)
    static_load, frequency = np.full(count, np.nan), np.full(count, np.nan)
    natural = np.full((len(study.models), count), np.nan)
    try:
        group_case = study.case_at(tuple(values))
    except JammingError:
        jammed[:] = True
        return _Group(arrays, response, jammed, static_load, frequency, natural)
    if speeds is None:
        speeds = np.array([group_case.operating_point.speed_rpm], dtype=float)
    frequency[:] = group_case.gear_pair.pinion.teeth * speeds / 60.0
    for model_index, model in enumerate(study.models):
        try:
            problems, loads = _problems(group_case, model, speeds)
        except JammingError:  # a temperature the model computes closes the backlash
            jammed[model_index] = True
            continue
        static_load[:] = loads
        # the speeds whose gears do not jam, followed in order (with a gearbox case a jammed speed is skipped: the
        # branch goes on from the last orbit found, which only seeds Newton at the next speed)
        free = np.array([problem is not None for problem in problems])
        jammed[model_index] = ~free
        if not free.any():
            continue
        solvable = [problem for problem in problems if problem is not None]
        natural[model_index, free] = [problem.natural_frequency for problem in solvable]
        for direction_index, way in enumerate(directions):
            branch = follow_branch(solvable, way, parameter=speeds[free],
                                   include_damping_force=group_case.dynamics.include_damping_force)
            target = (direction_index, model_index, free)
            for name, source in _FROM_BRANCH.items():
                arrays[name][target] = (branch[source] / loads[free] if name == "max_system_load_ratio"
                                        else branch[source])
            arrays["back_side_contact"][target] = branch["back_side_contact"].astype(float)
            arrays["period_count"][target] = branch.period_count.astype(float)
            arrays["converged"][target] = branch.converged.astype(float)
            response[target] = branch.response
    return _Group(arrays, response, jammed, static_load, frequency, natural)


def _search_point(study, rest: tuple[int, ...], speed_axis: int | None, model_index: int, speed_index: int,
                  starts: int) -> dict | None:
    """The multi-start orbit search at one point and model (:func:`thermogear.sweep.multistart.point_orbits`);
    None where the gears jam."""
    from thermogear.sweep.multistart import point_orbits  # noqa: PLC0415

    values, _ = _group_values(study, rest, speed_axis)
    try:
        group_case = study.case_at(tuple(values))
        speeds = (np.asarray(study.parameters[speed_axis].values, dtype=float)[[speed_index]]
                  if speed_axis is not None else np.array([group_case.operating_point.speed_rpm], dtype=float))
        problems, _ = _problems(group_case, study.models[model_index], speeds)
    except JammingError:
        return None
    if problems[0] is None:  # this speed's own temperatures jam the gears (a gearbox case)
        return None
    return point_orbits(problems[0], starts, group_case.dynamics.include_damping_force)


def _execute(study, task: tuple, speed_axis, directions, starts: int):
    """One task: ("group", rest) → :func:`_solve_group`; ("orbits", rest, model, speed) → :func:`_search_point`."""
    if task[0] == "group":
        return _solve_group(study, task[1], speed_axis, directions)
    return _search_point(study, task[1], speed_axis, task[2], task[3], starts)


def execute_recorded(shared: tuple, task) -> tuple[Any, list]:
    """One task of the executor (``shared``: the study, the speed axis, the directions, the starts): :func:`_execute`
    with its warnings recorded (in the thread's own scope on a thread) as ``(text, category, file, line)``."""
    study, speed_axis, directions, starts = shared
    with warning_scope.recorded() as caught:
        result = _execute(study, task, speed_axis, directions, starts)
    return result, [(str(item.message), item.category, item.filename, item.lineno) for item in caught]


def branch_study(study, direction: str = "both", progress=None, workers: int | None = None, multistart: int = 0,
                 scheduler: str | None = None, out=None, resume: bool = False, overwrite: bool = False):
    """The xarray Dataset of a nonlinear-mesh study: dims ``(direction, model, *parameters)`` for the variables of
    :data:`BRANCH_VARIABLES` and ``response`` ("periodic" | "subharmonic" | "non-periodic" | "failed" | "jammed"),
    ``jammed`` with dims ``(model, *parameters)`` (1 where the thermal expansion closes the backlash: no result,
    NaN there), plus the per-point ``static_load`` [N] and ``mesh_frequency_hz`` [Hz].

    Each combination of the parameters other than the speed (a group) is one task: its up and down branches in
    speed (one point at the case's speed without a speed axis). The tasks run on ``workers`` threads (default:
    one per core; 1: in the calling thread): the backlash integrator releases Python's global interpreter lock.
    The numbers do not depend on the thread count. Warnings raised by the tasks are raised again in the calling
    thread, once each. ``progress(points)`` is called as each group finishes (``points``: its speeds).
    ``scheduler``: any of :func:`thermogear.sweep.executor.execute` (default: threads; serial where ``workers`` is
    1). ``out``: the zarr store the groups are written to as they finish (:mod:`thermogear.sweep.task_store`;
    ``resume`` continues it, the finished groups kept; ``overwrite`` replaces thermogear's own store); the dataset
    returned is then the store's (its ``orbit`` dimension as long as the starts).

    ``multistart`` N > 0: at every point and model also the multi-start search of
    :func:`~thermogear.dynamics.backlash_orbits.stable_orbits` from N starts (about 0.1 s per start and point):
    the variables of :data:`thermogear.sweep.multistart.ORBIT_VARIABLES` with an extra ``orbit`` dimension (the
    largest basin share first), ``stable_orbit_count`` and ``unsettled_start_share``.
    """
    import xarray as xr  # noqa: PLC0415

    directions = _directions(direction)
    speed_axis = next((a for a, p in enumerate(study.parameters) if p.key == "operating.speed_rpm"), None)
    shape = study.shape
    full = (len(directions), len(study.models), *shape)
    arrays = {name: np.full(full, np.nan) for name in BRANCH_VARIABLES}
    response = np.full(full, "", dtype=object)
    jammed = np.zeros((len(study.models), *shape), dtype=np.int8)
    natural = np.full((len(study.models), *shape), np.nan)
    static_load = np.full(shape, np.nan)
    frequency = np.full(shape, np.nan)
    if int(multistart) != multistart or multistart < 0:
        raise CaseError("multistart", multistart, "an integer >= 0 (0: no search)", "number of starts per point")
    censuses = np.full((len(study.models), *shape), None, dtype=object) if multistart else None
    others = [p.size for a, p in enumerate(study.parameters) if a != speed_axis]
    groups = list(np.ndindex(*others)) if others else [()]

    def place(task: tuple, result) -> None:
        rest = task[1]
        _, where = _group_values(study, rest, speed_axis)
        if task[0] == "orbits":  # the census of one point and model
            point = tuple(task[3] if isinstance(i, slice) else i for i in where)
            censuses[(task[2], *point)] = result
            return
        group = result
        pick = (lambda a: a) if speed_axis is not None else (lambda a: a[..., 0])
        for name in BRANCH_VARIABLES:
            arrays[name][(slice(None), slice(None), *where)] = pick(group.arrays[name])
        response[(slice(None), slice(None), *where)] = pick(group.response)
        jammed[(slice(None), *where)] = group.jammed if speed_axis is not None else group.jammed[:, 0]
        natural[(slice(None), *where)] = (group.natural_frequency_hz if speed_axis is not None
                                          else group.natural_frequency_hz[:, 0])
        static_load[where] = pick(group.static_load)
        frequency[where] = pick(group.mesh_frequency_hz)
        if progress is not None:
            progress(int(group.static_load.size))

    tasks = [("group", rest) for rest in groups]
    if multistart:  # one task per point and model: a few speeds searched on every worker
        speed_count = study.parameters[speed_axis].size if speed_axis is not None else 1
        tasks += [("orbits", rest, model, speed) for rest in groups for model in range(len(study.models))
                  for speed in range(speed_count)]
    store = None
    if out is not None:
        from thermogear.sweep.task_store import TaskStore  # noqa: PLC0415

        store = TaskStore.open(out, branch_layout(study, directions, int(multistart), len(tasks)), resume=resume,
                               overwrite=overwrite)
    done = store.done_tasks() if store is not None else set()
    pending = [(number, task) for number, task in enumerate(tasks) if number not in done]
    caught: list = []

    def finished(index: int, outcome) -> None:
        number, task = pending[index]
        result, messages = outcome
        caught.extend(messages)
        place(task, result)
        if store is not None:
            store.write(number, *branch_region(study, task, speed_axis, result, int(multistart)))

    kind = scheduler if scheduler not in (None, "", "local") else ("serial" if workers == 1 else "threads")
    _run_tasks((study, speed_axis, directions, int(multistart)), [task for _, task in pending], finished, kind,
               None if kind == "serial" else workers, caught)
    if store is not None:
        return store.dataset()
    coords: dict[str, Any] = {"direction": ("direction", np.array(directions, dtype=str)),
                              "model": ("model", np.array(study.models, dtype=str))}
    for parameter in study.parameters:
        coords[parameter.name] = (parameter.name, np.asarray(parameter.values))
    dims = ("direction", "model", *study.dims)
    data = {name: (dims, values, {"units": BRANCH_VARIABLES[name][0], "long_name": BRANCH_VARIABLES[name][1]})
            for name, values in arrays.items()}
    data["response"] = (dims, response.astype(str),
                        {"long_name": "periodic | subharmonic | non-periodic | failed | jammed"})
    data["jammed"] = (("model", *study.dims), jammed,
                      {"units": "1", "long_name": "1 where the gears jam (the thermal expansion closes the backlash): "
                                                  "no result, NaN"})
    data["natural_frequency_hz"] = (("model", *study.dims), natural,
                                    {"units": "Hz", "long_name": "natural frequency of the linear mesh with every "
                                                                 "pair in contact, sqrt(mean k / me) / 2 pi"})
    data["static_load"] = (study.dims, static_load, {"units": "N", "long_name": "static normal load w"})
    data["mesh_frequency_hz"] = (study.dims, frequency, {"units": "Hz", "long_name": "mesh frequency z1 n1 / 60"})
    if censuses is not None:
        from thermogear.sweep.multistart import orbit_dataset_variables  # noqa: PLC0415

        data.update(orbit_dataset_variables(censuses, study.models, study.dims, int(multistart)))
    load, load_note = study_load_held(study)
    return xr.Dataset(data, coords=coords, attrs={"mesh": "nonlinear", "directions": ",".join(directions),
                                                   "case": study.case.name, "load": load, "load_note": load_note})


def _run_tasks(shared, tasks, finished, scheduler: str, workers: int | None, caught: list) -> None:
    """Every task on the one executor (:mod:`thermogear.sweep.executor`); ``finished(index, (result, warnings))``
    in the calling thread as each finishes; the warnings raised again in the calling thread, once per text."""
    from contextlib import ExitStack  # noqa: PLC0415

    from thermogear.sweep.executor import execute  # noqa: PLC0415

    with ExitStack() as stack:
        unscoped = stack.enter_context(warning_scope.routed()) if scheduler == "threads" else []
        execute(execute_recorded, shared, tasks, finished, scheduler, workers)
        stack.close()
        caught.extend((str(item.message), item.category, item.filename, item.lineno) for item in unscoped)
    seen = set()
    for text, category, filename, lineno in caught:
        if (category, text) not in seen:
            seen.add((category, text))
            warnings.warn_explicit(text, category, filename, lineno)


def write_branch_store(dataset, path, overwrite: bool = False):
    """Write a branch study to the zarr store ``path`` (consolidated metadata, ownership marker); an existing path
    is refused unless ``overwrite``, and then only when thermogear wrote it and it holds nothing else (a user's
    notes.txt is never deleted, whoever calls this). Written into a hidden sibling folder and renamed, so an
    interrupted run leaves the previous store or none."""
    import shutil  # noqa: PLC0415
    import tempfile  # noqa: PLC0415

    from thermogear.ownership import (require_no_foreign_entries, require_owned, resolve_output,  # noqa: PLC0415
                                      write_marker)
    from thermogear.sweep.store import _quiet_zarr  # noqa: PLC0415

    target = resolve_output(path)
    if target.exists():
        if not overwrite:
            raise CaseError("out", str(target), "a path that does not exist yet (or --overwrite)",
                            "the result store exists; overwrite it explicitly")
        require_owned(target, "sweep-store", "--out", "overwritten")
        require_no_foreign_entries(target)
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
