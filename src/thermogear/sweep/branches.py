"""Studies of the nonlinear (backlash) mesh: the solution branch followed in speed, up and down.

Where teeth separate the steady response of a gear pair depends on where it came from: near the primary resonance
a speed run-up stays on the high-amplitude branch beyond the linear peak and drops ("jumps down") off it, a
run-down jumps up later — the hysteresis of a backlash oscillator (Kahraman & Singh 1990). A grid point therefore
has one result per sweep direction. For every combination of the other parameters (a group), model and direction,
the points of the branch are solved in order, each from its neighbour's orbit
(:func:`~thermogear.dynamics.backlash.backlash_continuation.branch_point`, the step of
:func:`~thermogear.dynamics.backlash.backlash_continuation.follow_branch`), ``up`` (lowest speed first), ``down`` or
both.

Each branch point is one task of the one executor (:mod:`thermogear.sweep.executor`) that follows the task of its
neighbour speed; the branches run in parallel (threads: the backlash integrator releases Python's global
interpreter lock; worker processes; a scheduler by address) and every point is written to the one task store as it
finishes, with the state its branch carries on from, so progress advances per point and ``--resume`` continues
each branch from its last completed point, exactly. A point whose gears jam (the thermal expansion closes the
backlash) is marked ``jammed`` and its branch goes on from the last orbit found.
"""

from __future__ import annotations

import threading
import warnings
from collections import OrderedDict
from pathlib import Path
from typing import Any

import numpy as np

from thermogear import warning_scope
from thermogear.dynamics.backlash.backlash_continuation import branch_point
from thermogear.dynamics.problems.continuation_directions import STUDY_DIRECTIONS, direction_named, study_directions
from thermogear.errors import CaseError, JammingError
from thermogear.mesh.model import MeshModel
from thermogear.sweep.branch_store import (BRANCH_POINT, BRANCH_VARIABLES, ORBIT_SEARCH, TASK_KINDS, branch_layout,
                                           branch_region, orbit_arrays)
from thermogear.sweep.hysteresis import hysteresis_bands
from thermogear.sweep.load_held import study_load_held
from thermogear.sweep.schedulers import Placement, SERIAL, THREADS, Scheduler
from thermogear.sweep.schedulers import scheduler as scheduler_named
from thermogear.temperature.kinds import temperature_source

__all__ = ["DIRECTIONS", "BRANCH_VARIABLES", "branch_study", "hysteresis_bands", "write_branch_store"]

#: The ``direction`` values of a branch study
#: (:data:`~thermogear.dynamics.problems.continuation_directions.STUDY_DIRECTIONS`).
DIRECTIONS = tuple(STUDY_DIRECTIONS)

_FROM_BRANCH = {"kv": "kv", "max_pair_load": "max_pair_force", "max_system_load_ratio": "max_mesh_force",
                "dte_mean": "dte_mean", "dte_rms": "dte_rms", "dte_peak_to_peak": "dte_peak_to_peak",
                "contact_loss_fraction": "contact_loss_fraction", "back_contact_fraction": "back_contact_fraction",
                "floquet_multiplier_max": "largest_multiplier",
                "residual": "residual"}


def _directions(direction: str) -> tuple[str, ...]:
    return study_directions(direction, key="direction")


def _group_values(study, rest: tuple[int, ...], speed_axis: int | None) -> tuple[list, tuple]:
    """The parameter values of a group's first point and the index of the group in the grid (a slice along the
    speed axis)."""
    index: list[Any] = list(rest)
    if speed_axis is not None:
        index.insert(speed_axis, slice(None))
    values = [p.values[i] if not isinstance(i, slice) else p.values[0] for p, i in zip(study.parameters, index)]
    return values, tuple(index)


def _speed_of(study, group_case, speed_axis: int | None, speed_index: int) -> float:
    if speed_axis is None:
        return float(group_case.operating_point.speed_rpm)
    return float(np.asarray(study.parameters[speed_axis].values, dtype=float)[speed_index])


_BUILT = threading.local()  # per thread: a mesh model is never shared between threads
_CACHE_SIZE = 8


def _cached(key, build):
    """``build()`` kept per thread (a few, least recently used first out), the JammingError it raised included."""
    cache = getattr(_BUILT, "items", None)
    if cache is None:
        cache = _BUILT.items = OrderedDict()
    if key not in cache:
        try:
            cache[key] = build()
        except JammingError as error:
            cache[key] = error
        while len(cache) > _CACHE_SIZE:
            cache.popitem(last=False)
    cache.move_to_end(key)
    if isinstance(cache[key], JammingError):
        raise cache[key]
    return cache[key]


def _group_case(study, identity: str, rest: tuple[int, ...], speed_axis: int | None):
    """The case of a group (JammingError where its gears jam at the case's temperatures)."""
    values, _ = _group_values(study, rest, speed_axis)
    return _cached(("case", identity, rest), lambda: study.case_at(tuple(values)))


def _point_problem(study, identity: str, rest: tuple[int, ...], group_case, model: str, speed: float):
    """The backlash problem of one point and model and its static load [N]. With temperatures predicted at the
    operating point (the gearbox model) the point's case is the group's at this speed (its own steady
    temperatures, hot geometry, E(T) and oil); otherwise every speed is evaluated on the group's mesh model.
    JammingError where the gears jam."""
    if temperature_source(group_case.temperature.model).predicted_at_load:
        try:
            mesh = _cached(("mesh", identity, rest, model, speed), lambda: MeshModel(
                group_case.with_changes(**{"operating.speed_rpm": float(speed)}), model))
        except CaseError as error:  # e.g. temperatures beyond the material data: say at which speed
            raise CaseError(error.key, error.value, error.allowed, f"{error.reason} (at {speed:g} rpm, the gearbox "
                            "model's steady temperatures there)") from None
    else:
        mesh = _cached(("mesh", identity, rest, model), lambda: MeshModel(group_case, model))
    load = mesh.normal_load(speed)
    return mesh.state(speed_rpm=speed, normal_load=load).backlash_problem(
        mesh.case.dynamics.damping_in_flight), load


def _static_load(study, identity: str, rest, group_case, speed: float, problem_load: float | None) -> float:
    """The stored static load of a point: the last model's whose problem is built there (a model whose gears jam
    gives way to the one before it; with the gearbox model the last model's, NaN where it jams)."""
    if problem_load is not None or temperature_source(group_case.temperature.model).predicted_at_load:
        return np.nan if problem_load is None else float(problem_load)
    for model in reversed(study.models[:-1]):
        try:
            return float(_point_problem(study, identity, rest, group_case, model, speed)[1])
        except JammingError:
            continue
    return np.nan


def _branch_point(shared: tuple, task: tuple, previous: dict | None) -> dict[str, Any]:
    """One point of one branch (``task``: ("point", group, model, direction, speed[, stored state])), solved from
    the state its neighbour's result carries (``previous``), or the state stored with the neighbour (a resumed
    branch), or from the linear response (the first point). A point whose gears jam passes the state on."""
    study, speed_axis, _, _, identity = shared
    _, rest, model_index, _, speed_index, *stored = task
    carried = previous["carried"] if previous is not None else (stored[0] if stored else None)
    values: dict[str, Any] = {name: np.nan for name in BRANCH_VARIABLES}
    values.update(converged=0.0, response="jammed", jammed=np.int8(1), natural_frequency_hz=np.nan)
    last_model = model_index == len(study.models) - 1
    try:
        group_case = _group_case(study, identity, rest, speed_axis)
    except JammingError:
        if last_model:
            values.update(static_load=np.nan, mesh_frequency_hz=np.nan)
        return {"values": values, "carried": carried}
    speed = _speed_of(study, group_case, speed_axis, speed_index)
    load = None
    try:
        problem, load = _point_problem(study, identity, rest, group_case, study.models[model_index], speed)
    except JammingError:  # a temperature the model computes closes the backlash (at this speed)
        problem = None
    if last_model:
        values["static_load"] = _static_load(study, identity, rest, group_case, speed, load)
        values["mesh_frequency_hz"] = group_case.gear_pair.pinion.teeth * speed / 60.0
    if problem is None:
        return {"values": values, "carried": carried}
    point = branch_point(problem, carried, include_damping_force=group_case.dynamics.include_damping_force)
    for name, source in _FROM_BRANCH.items():
        values[name] = point.metrics[source] / load if name == "max_system_load_ratio" else point.metrics[source]
    values.update(back_side_contact=float(point.metrics["back_side_contact"]), period_count=float(point.period_count),
                  converged=float(point.converged), response=point.response, jammed=np.int8(0),
                  natural_frequency_hz=problem.natural_frequency)
    return {"values": values, "carried": point.carried}


def _search_point(shared: tuple, task: tuple) -> dict | None:
    """The multi-start orbit search at one point and model (:func:`thermogear.sweep.multistart.point_orbits`);
    None where the gears jam."""
    from thermogear.sweep.multistart import point_orbits  # noqa: PLC0415

    study, speed_axis, _, starts, identity = shared
    _, rest, model_index, speed_index, *_ = task
    try:
        group_case = _group_case(study, identity, rest, speed_axis)
        speed = _speed_of(study, group_case, speed_axis, speed_index)
        problem, _ = _point_problem(study, identity, rest, group_case, study.models[model_index], speed)
    except JammingError:
        return None
    return point_orbits(problem, starts, group_case.dynamics.include_damping_force)


def execute_recorded(shared: tuple, task, *previous) -> tuple[Any, list]:
    """One task of the executor (``shared``: the study, the speed axis, the directions, the starts, the study's
    identity): a branch point (:func:`_branch_point`, after ``previous``: its neighbour's outcome) or a point's
    multi-start search (:func:`_search_point`), with its warnings recorded (in the thread's own scope on a thread)
    as ``(text, category, file, line)``."""
    with warning_scope.recorded() as caught:
        if TASK_KINDS[task[0]].follows_branch:
            result = _branch_point(shared, task, previous[0][0] if previous else None)
        else:
            result = _search_point(shared, task)
    return result, [(str(item.message), item.category, item.filename, item.lineno) for item in caught]


def plan_branches(study, directions: tuple[str, ...], multistart: int) -> tuple[list, list]:
    """The tasks of a branch study and whom each follows: per group (combination of the other parameters), model
    and direction the chain of its speeds, each point following its neighbour (up: lowest speed first); then, with
    ``multistart``, one search per point and model (independent)."""
    speed_axis = next((a for a, p in enumerate(study.parameters) if p.key == "operating.speed_rpm"), None)
    others = [p.size for a, p in enumerate(study.parameters) if a != speed_axis]
    groups = list(np.ndindex(*others)) if others else [()]
    count = study.parameters[speed_axis].size if speed_axis is not None else 1
    tasks: list = []
    follows: list = []
    for rest in groups:
        for model_index in range(len(study.models)):
            for direction_index, way in enumerate(directions):
                previous = None
                for speed_index in direction_named(way).order(count):
                    tasks.append((BRANCH_POINT.name, rest, model_index, direction_index, speed_index))
                    follows.append(previous)
                    previous = len(tasks) - 1
    if multistart:  # one task per point and model: a few speeds searched on every worker
        for rest in groups:
            for model_index in range(len(study.models)):
                for speed_index in range(count):
                    tasks.append((ORBIT_SEARCH.name, rest, model_index, speed_index))
                    follows.append(None)
    return tasks, follows


def branch_study(study, direction: str = "both", progress=None, workers: int | None = None, multistart: int = 0,
                 scheduler: str | None = None, out=None, resume: bool = False, overwrite: bool = False):
    """The xarray Dataset of a nonlinear-mesh study: dims ``(direction, model, *parameters)`` for the variables of
    :data:`BRANCH_VARIABLES` and ``response`` ("periodic" | "subharmonic" | "non-periodic" | "failed" | "jammed"),
    ``jammed`` with dims ``(model, *parameters)`` (1 where the thermal expansion closes the backlash: no result,
    NaN there), plus the per-point ``static_load`` [N] and ``mesh_frequency_hz`` [Hz].

    Each point of each branch (group × model × direction × speed; a group is one combination of the parameters
    other than the speed; without a speed axis one point at the case's speed) is one task, which follows the task
    of its neighbour speed and starts Newton from the orbit state that task carried
    (:func:`~thermogear.dynamics.backlash.backlash_continuation.branch_point`, as
    :func:`~thermogear.dynamics.backlash.backlash_continuation.follow_branch` solves each point). The tasks run on the
    one executor (:func:`thermogear.sweep.executor.execute`; ``scheduler`` default threads, serial where ``workers``
    is 1: the backlash integrator releases Python's global interpreter lock); the numbers do not depend on where
    they run. Warnings raised by the tasks are raised again in the calling thread, once each.
    ``progress(total, completed)``: a context manager yielding ``advance(points)``, advanced by one as each branch
    point (of one model and direction) or point search finishes. ``out``: the zarr store the points are written to
    as they finish (:mod:`thermogear.sweep.task_store`), with the state each branch carries on from
    (``branch_state``), so ``resume`` continues every branch from its last completed point, exactly as the
    uninterrupted study; ``overwrite`` replaces thermogear's own store. The dataset returned is then the store's
    (its ``orbit`` dimension as long as the starts).

    ``multistart`` N > 0: at every point and model also the multi-start search of
    :func:`~thermogear.dynamics.backlash.backlash_orbits.stable_orbits` from N starts (about 0.1 s per start and point):
    the variables of :data:`thermogear.sweep.multistart.ORBIT_VARIABLES` with an extra ``orbit`` dimension (the
    largest basin share first), ``stable_orbit_count`` and ``unsettled_start_share``.
    """
    import json  # noqa: PLC0415
    from contextlib import nullcontext  # noqa: PLC0415

    from thermogear.sweep.chains import pending_chains  # noqa: PLC0415
    from thermogear.sweep.task_store import MemoryStore, TaskStore  # noqa: PLC0415

    directions = _directions(direction)
    if int(multistart) != multistart or multistart < 0:
        raise CaseError("multistart", multistart, "an integer >= 0 (0: no search)", "number of starts per point")
    speed_axis = next((a for a, p in enumerate(study.parameters) if p.key == "operating.speed_rpm"), None)
    tasks, follows = plan_branches(study, directions, int(multistart))
    layout = branch_layout(study, directions, int(multistart), len(tasks))
    store = (TaskStore.open(out, layout, resume=resume, overwrite=overwrite) if out is not None
             else MemoryStore(layout))
    done = store.done_tasks()

    states: list = []  # read once, where a branch is continued

    def stored_state(number: int):
        region = branch_region(study, tasks[number], speed_axis)
        states[:] = states or [store.read_variable("branch_state")]
        state = states[0][tuple(region.get(name, slice(None)) for name in
                                                          ("direction", "model", *study.dims))]
        return None if not np.isfinite(state).all() else tuple(float(value) for value in state)

    pending, pending_follows = pending_chains(tasks, follows, done, stored_state)
    censuses: dict = {}
    caught: list = []

    def finished(index: int, outcome) -> None:
        number = pending[index][0]
        task = tasks[number]
        result, messages = outcome
        caught.extend(messages)
        region = branch_region(study, task, speed_axis)
        if not TASK_KINDS[task[0]].follows_branch:  # a point's orbit search
            censuses[task] = result
            store.write(number, region, orbit_arrays(result, int(multistart)))
        else:
            state = result["carried"]
            store.write(number, region, {**result["values"], "branch_state": np.full(2, np.nan) if state is None
                                         else np.asarray(state, dtype=float)})
        advance(1)

    kind = scheduler_named(scheduler, default=SERIAL if workers == 1 else THREADS)
    identity = json.dumps(layout.definition, sort_keys=True, default=str)
    with (progress(len(tasks), len(done)) if progress is not None else nullcontext(lambda points=1: None)) as advance:
        serial = kind.placement is Placement.CALLING_THREAD
        _run_tasks((study, speed_axis, directions, int(multistart), identity), [task for _, task in pending],
                   finished, kind, None if serial else workers, caught, pending_follows)
    if out is not None:
        return store.dataset()
    return _memory_dataset(store, study, directions, censuses, speed_axis, int(multistart))


def _memory_dataset(store, study, directions: tuple[str, ...], censuses: dict, speed_axis, starts: int):
    """The dataset of a study run without a store (``out`` None): the arrays the tasks wrote, as xarray."""
    import xarray as xr  # noqa: PLC0415

    coords: dict[str, Any] = {"direction": ("direction", np.array(directions, dtype=str)),
                              "model": ("model", np.array(study.models, dtype=str))}
    for parameter in study.parameters:
        coords[parameter.name] = (parameter.name, np.asarray(parameter.values))
    data = {}
    for variable in store.layout.variables:
        if variable.name == "branch_state" or variable.dims[-1:] == ("orbit",) or variable.name in (
                "stable_orbit_count", "unsettled_start_share"):
            continue
        values = store.read_variable(variable.name)
        data[variable.name] = (variable.dims, values.astype(str) if variable.kind == "str" else values,
                               {"units": variable.units, "long_name": variable.long_name} if variable.units else
                               {"long_name": variable.long_name})
    if starts:
        from thermogear.sweep.multistart import orbit_dataset_variables  # noqa: PLC0415

        found = np.full((len(study.models), *study.shape), None, dtype=object)
        for task, census in censuses.items():
            _, rest, model_index, speed_index = task
            _, where = _group_values(study, rest, speed_axis)
            found[(model_index, *(speed_index if isinstance(i, slice) else i for i in where))] = census
        data.update(orbit_dataset_variables(found, study.models, study.dims, starts))
    load, load_note = study_load_held(study)
    return xr.Dataset(data, coords=coords, attrs={"mesh": "nonlinear", "directions": ",".join(directions),
                                                   "case": study.case.name, "load": load, "load_note": load_note})


def _run_tasks(shared, tasks, finished, scheduler: Scheduler, workers: int | None, caught: list, follows=None
               ) -> None:
    """Every task on the one executor (:mod:`thermogear.sweep.executor`); ``finished(index, (result, warnings))``
    in the calling thread as each finishes; the warnings raised again in the calling thread, once per text."""
    from contextlib import ExitStack  # noqa: PLC0415

    from thermogear.sweep.executor import execute  # noqa: PLC0415

    with ExitStack() as stack:
        unscoped = stack.enter_context(warning_scope.routed()) if scheduler.placement is Placement.THREADS else []
        execute(execute_recorded, shared, tasks, finished, scheduler, workers, follows=follows)
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
