"""The gearbox's steady grid (speeds × torques) as a study: planned into blocks of points, run on the study executor
(:mod:`thermogear.sweep.executor`: serial, threads, worker processes or a scheduler address), each block written to
the store (:mod:`thermogear.sweep.task_store`) as it finishes, resumable.

Each point is one steady solve of the network (about 2 ms of pure Python that holds the interpreter lock), so
threads do not make a grid faster; worker processes do. A block is a pure function of the gearbox model and its
points (:func:`thermogear.gearbox.sweep.solve_grid`), so every scheduler gives the same bits. The blocks depend only
on the grid and ``chunk_points``, never on the number of workers.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from typing import Any, Callable

import numpy as np

from thermogear.gearbox.losses import NODES
from thermogear.gearbox.sweep import OUTPUTS, check_grid, grid_result, solve_grid, warn_oil_range
from thermogear.temperature.limits import FLAG_MEANINGS
from thermogear.sweep.study import _chunk_shape

__all__ = ["DEFAULT_GRID_CHUNK_POINTS", "GridRun", "gearbox_grid_layout", "run_gearbox_grid"]

#: Points per task and per stored chunk: about 0.1 s of solving, so a task outweighs its dispatch and the progress
#: bar moves several times a second.
DEFAULT_GRID_CHUNK_POINTS = 50
_DIMS = ("speed_rpm", "torque_nm")
#: Stored name, the output of :func:`~thermogear.gearbox.sweep.solve_grid`, units, long name.
_STORED = (("mesh_loss", "mesh", "W", "tooth friction loss of the mesh"),
           ("bearing_loss", "bearings", "W", "bearing loss"),
           ("seal_loss", "seals", "W", "seal loss"),
           ("churning_loss", "churning", "W", "churning loss of the dipped gears"),
           ("injection_loss", "injection", "W", "impulse loss of the oil jet"),
           ("efficiency", "efficiency", "1", "efficiency of the gearbox"),
           ("backlash", "backlash", "m", "normal backlash at the steady temperatures"))


@dataclass(frozen=True)
class GridRun:
    """A finished grid: ``result`` the :class:`~thermogear.gearbox.sweep.SteadySweep`, ``path`` the store (None
    without one), ``computed`` and ``kept`` tasks, ``messages`` the warnings once each."""

    result: Any
    path: Path | None
    computed: int
    kept: int
    messages: list[str]


def _blocks(shape: tuple[int, int], chunk_points: int) -> list[tuple[slice, slice]]:
    chunk = _chunk_shape(shape, chunk_points)
    return [(slice(i, min(i + chunk[0], shape[0])), slice(j, min(j + chunk[1], shape[1])))
            for i in range(0, shape[0], chunk[0]) for j in range(0, shape[1], chunk[1])]


def solve_block(shared: tuple, block: tuple[slice, slice]) -> tuple[dict[str, np.ndarray], list[str]]:
    """One task: the steady states of a block of the grid and the warnings raised (``shared``: the gearbox model,
    the speeds, the torques and the ambient temperature)."""
    from thermogear import warning_scope
    from thermogear.warning_causes import warning_text

    model, speeds, torques, ambient_c = shared
    with warning_scope.recorded() as caught:
        arrays = solve_grid(model, speeds[block[0]], torques[block[1]], ambient_c)
    return arrays, [warning_text(item) for item in caught]


def gearbox_grid_layout(model, speeds: np.ndarray, torques: np.ndarray, ambient_c: float, chunk_points: int,
                        case_name: str, case_source: str, case_document: dict):
    """The store of a grid (:class:`~thermogear.sweep.task_store.StoreLayout`): per point the node temperatures
    [°C], the losses by source and their sum [W], the efficiency, the backlash [m], ``runaway``, ``valid``, the fold
    torque of a runaway point and the plausibility flags."""
    import json

    from thermogear.sweep.study import case_fingerprint
    from thermogear.sweep.task_store import StoreLayout, StoreVariable

    variables = [StoreVariable(f"temperature_{name}", _DIMS, "float", "degC", f"steady temperature of the {name}")
                 for name in NODES]
    jet = model.description.oil_jet is not None
    variables += [StoreVariable(name, _DIMS, "float", units, text) for name, _, units, text in _STORED
                  if jet or name != "injection_loss"]
    variables += [StoreVariable("total_loss", _DIMS, "float", "W", "sum of the losses"),
                  StoreVariable("runaway", _DIMS, "int8", "1", "1 where the network has no steady state (thermal "
                                "runaway); the values there are NaN"),
                  StoreVariable("valid", _DIMS, "int8", "1", "1 where the point has a stable steady state with every "
                                "gear within the material data (thermogear.temperature.limits)"),
                  StoreVariable("fold_torque", _DIMS, "float", "N m", "where the point has no stable steady state: the "
                                "torque at which the stable branch ended (NaN elsewhere)")]
    variables += [StoreVariable(f"flag_{flag}", _DIMS, "int8", "1", f"1 where the steady state has {meaning}")
                  for flag, meaning in FLAG_MEANINGS.items()]
    chunk = _chunk_shape((speeds.size, torques.size), chunk_points)
    tasks = len(_blocks((speeds.size, torques.size), chunk_points))
    definition = {"kind": "gearbox steady grid", "speeds_rpm": speeds.tolist(), "torques_nm": torques.tolist(),
                  "ambient_c": float(ambient_c), "chunk_points": int(chunk_points),
                  "case_document_sha256": case_fingerprint(case_document)}
    attrs = {"title": "thermogear steady gearbox sweep", "case_name": case_name, "case_source": str(case_source),
             "case_json": json.dumps(case_document, sort_keys=True, default=str), "ambient_c": float(ambient_c),
             "load": "constant torque", "load_note": "the grid varies the torque: each point holds its torque",
             "row_dimensions": ",".join(_DIMS)}  # `thermogear export`: one row per point
    return StoreLayout(coords={"speed_rpm": speeds, "torque_nm": torques}, variables=tuple(variables), tasks=tasks,
                       definition=definition, attrs=attrs, chunks=dict(zip(_DIMS, chunk)),
                       coord_attrs={"speed_rpm": {"units": "rpm", "long_name": "pinion speed"},
                                    "torque_nm": {"units": "N m", "long_name": "pinion torque"}})


def _stored_arrays(arrays: dict[str, np.ndarray], jet: bool) -> dict[str, np.ndarray]:
    stored = {f"temperature_{name}": arrays["temperatures"][index] for index, name in enumerate(NODES)}
    stored.update({name: arrays[source] for name, source, _, _ in _STORED if jet or name != "injection_loss"})
    total = arrays["mesh"] + arrays["bearings"] + arrays["seals"] + arrays["churning"]
    stored["total_loss"] = total + arrays["injection"] if jet else total
    stored["runaway"] = arrays["runaway"].astype(np.int8)
    stored["valid"] = (~arrays["runaway"] & ~arrays["flag_above_material_data"]).astype(np.int8)
    stored["fold_torque"] = arrays["fold"]
    stored.update({f"flag_{flag}": arrays[f"flag_{flag}"].astype(np.int8) for flag in FLAG_MEANINGS})
    return stored


def run_gearbox_grid(model, speeds_rpm, torques, ambient_c: float, scheduler: str = "serial",
                     workers: int | None = None, out: str | Path | None = None, resume: bool = False,
                     overwrite: bool = False, chunk_points: int | None = None,
                     progress: Callable[[int], None] | None = None, case=None) -> GridRun:
    """The steady grid of ``model`` on ``scheduler`` (:func:`thermogear.sweep.executor.execute`), into the store
    ``out`` when given (``case``: the loaded case, whose name, source and document the store records), else in
    memory. ``progress(points)`` as each block finishes."""
    from thermogear.sweep.executor import execute
    from thermogear.sweep.task_store import TaskStore
    from thermogear.warning_causes import WarningTally

    speeds, loads = check_grid(speeds_rpm, torques)
    chunk_points = int(chunk_points or DEFAULT_GRID_CHUNK_POINTS)
    blocks = _blocks((speeds.size, loads.size), chunk_points)
    jet = model.description.oil_jet is not None
    store = None
    if out is not None:
        layout = gearbox_grid_layout(model, speeds, loads, ambient_c, chunk_points, case.name, str(case.source),
                                     case.document)
        store = TaskStore.open(out, layout, resume=resume, overwrite=overwrite)
    done = store.done_tasks() if store is not None else set()
    pending = [number for number in range(len(blocks)) if number not in done]
    arrays = {"temperatures": np.full((len(NODES), speeds.size, loads.size), np.nan),
              **{name: np.full((speeds.size, loads.size), np.nan) for name in OUTPUTS},
              "runaway": np.zeros((speeds.size, loads.size), dtype=bool),
              "fold": np.full((speeds.size, loads.size), np.nan),
              **{f"flag_{flag}": np.zeros((speeds.size, loads.size), dtype=bool) for flag in FLAG_MEANINGS}}
    tally = WarningTally()

    def finished(index: int, result) -> None:
        number = pending[index]
        block_arrays, messages = result
        block = blocks[number]
        for name, values in block_arrays.items():
            arrays[name][(..., *block)] = values
        if store is not None:
            store.write(number, dict(zip(_DIMS, block)), _stored_arrays(block_arrays, jet))
        tally.update(messages)
        if progress is not None:
            progress(int(block_arrays["runaway"].size))

    execute(solve_block, (model, speeds, loads, float(ambient_c)), [blocks[n] for n in pending], finished,
            scheduler, workers)
    if store is not None and done:  # the blocks of an earlier run: read back from the store
        stored = store.dataset()
        for index, name in enumerate(NODES):
            arrays["temperatures"][index] = stored[f"temperature_{name}"].values
        for name, source, _, _ in _STORED:
            if name in stored:
                arrays[source] = stored[name].values
        arrays["runaway"] = stored["runaway"].values.astype(bool)
        arrays["fold"] = stored["fold_torque"].values
        for flag in FLAG_MEANINGS:
            arrays[f"flag_{flag}"] = stored[f"flag_{flag}"].values.astype(bool)
    warn_oil_range(model, arrays["temperatures"])
    return GridRun(grid_result(model, speeds, loads, ambient_c, arrays), None if store is None else store.path,
                   len(pending), len(done), tally.messages())
