"""The one store writer of the studies that are not the 1-DOF grid: drivetrain speeds (linear and backlash), the
nonlinear pair's branches and multi-start searches, and the gearbox's steady grid.

A study of these kinds is planned as a :class:`StoreLayout` (coordinates, variables with their dimensions, the
chunking, the attributes and the study's definition) and a list of tasks, each writing one region of the
variables. :class:`TaskStore` creates the zarr store (the ownership marker first, then every array with its fill
value, the metadata consolidated, the creation record last), writes each task's region as the task finishes (the
driver is the only writer) and then the task's entry in the completion record ``task_done``; ``--resume`` reopens a
store of the same study and computes only the unmarked tasks. zarr writes every chunk file atomically, so a marked
task is complete, and no time stamps are stored: an interrupted and resumed study is the store of an uninterrupted
one, bit for bit. ``--overwrite`` replaces only a store thermogear wrote that holds nothing else, at any depth.
"""

from __future__ import annotations

import json
from collections.abc import Mapping
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

from thermogear.errors import CaseError
from thermogear.ownership import remove_interrupted_writes, require_owned, resolve_output

__all__ = ["DONE", "MemoryStore", "StoreLayout", "StoreVariable", "TaskStore", "store_is_complete"]

#: The completion record: one entry (and one zarr chunk) per task.
DONE = "task_done"
_INITIALIZED = "thermogear_initialized"
_KIND = "sweep-store"
#: Fill values of the stored kinds (what a point no task has written reads as).
_FILL = {"float": np.nan, "int8": 0, "bool": False, "str": ""}


@dataclass(frozen=True)
class StoreVariable:
    """One stored array: ``dims`` (names of the layout's dimensions), ``kind`` float | int8 | bool | str, ``units``
    and ``long_name``."""

    name: str
    dims: tuple[str, ...]
    kind: str = "float"
    units: str = ""
    long_name: str = ""
    width: int = 400  # characters of a str variable (fixed-length UTF-32, as xarray writes text: read back as str)


@dataclass(frozen=True)
class StoreLayout:
    """What a study stores: ``coords`` name → values (one dimension each), ``variables``, ``chunks`` dim → chunk
    length (whole dimension where absent), ``attrs`` (JSON-ready), ``tasks`` their number, and ``definition``
    (JSON-ready: the study; ``--resume`` continues only a store whose definition is the same)."""

    coords: Mapping[str, Any]
    variables: tuple[StoreVariable, ...]
    tasks: int
    definition: Mapping[str, Any]
    attrs: Mapping[str, Any] = field(default_factory=dict)
    chunks: Mapping[str, int] = field(default_factory=dict)
    coord_attrs: Mapping[str, Mapping[str, str]] = field(default_factory=dict)

    def shape(self, dims: tuple[str, ...]) -> tuple[int, ...]:
        return tuple(len(self.coords[name]) for name in dims)

    def chunk_shape(self, dims: tuple[str, ...]) -> tuple[int, ...]:
        return tuple(max(1, min(int(self.chunks.get(name, len(self.coords[name]))), len(self.coords[name])))
                     for name in dims)

    def definition_json(self) -> str:
        return json.dumps(self.definition, sort_keys=True, default=str)


class TaskStore:
    """A study's zarr store written task by task. Create with :meth:`open` (new, overwritten or resumed)."""

    def __init__(self, path: Path, layout: StoreLayout) -> None:
        import zarr

        from thermogear.sweep.store import _quiet_zarr

        self.path = path
        self.layout = layout
        with _quiet_zarr():
            group = zarr.open_group(str(path), mode="r+", use_consolidated=False)
            self._arrays = {variable.name: group[variable.name] for variable in layout.variables}
            self._done = group[DONE]

    @classmethod
    def open(cls, path: str | Path, layout: StoreLayout, resume: bool = False, overwrite: bool = False
             ) -> "TaskStore":
        """The store at ``path``: created (an existing path refused unless ``overwrite`` or ``resume``), or
        reopened by ``resume`` when it holds the same study (a store never completely created is created anew;
        a store of another study is refused, untouched)."""
        from thermogear.sweep.store import create_owned_folder

        target = resolve_output(path)
        if resume and target.exists():
            require_owned(target, _KIND, "--out", "resumed or deleted")
            remove_interrupted_writes(target)  # a killed writer's half-written chunks
            attrs = _read_attributes(target)
            if attrs.get(_INITIALIZED):
                stored = attrs.get("study_definition")
                if stored != layout.definition_json():
                    raise CaseError("--resume", str(target), "a store of the same study (case, parameters, models, "
                                    "options)", "--resume continues the study that created this store; this study "
                                    f"differs (stored: {str(stored)[:300]})")
                return cls(target, layout)
            if _read_done_count(target):  # never: the record is written before any task; results are never deleted
                raise CaseError("--out", str(target), "a completely created store",
                                "the store holds finished tasks but no creation record; nothing was changed")
            overwrite = True
        if target.exists() and not overwrite:
            raise CaseError("--out", str(target), "a path that does not exist yet (or --resume / --overwrite)",
                            "the result store exists; resume it or overwrite it explicitly")
        create_owned_folder(target, overwrite and target.exists(), _KIND)
        _write_layout(target, layout)
        return cls(target, layout)

    def done_tasks(self) -> set[int]:
        """Numbers of the tasks whose regions are completely written."""
        return {int(i) for i in np.flatnonzero(np.asarray(self._done[:]) == 1)}

    def write(self, number: int, region: Mapping[str, Any], arrays: Mapping[str, Any]) -> None:
        """Write one task's ``arrays`` (name → values over ``region``: dim → slice or index, the other dims whole),
        then mark the task done (data first: a marked task is complete)."""
        from thermogear.sweep.store import _quiet_zarr

        with _quiet_zarr():
            for name, values in arrays.items():
                selection, values = _placed(self.layout, name, region, values)
                self._arrays[name][selection] = values
            self._done[number] = 1

    def read_variable(self, name: str) -> np.ndarray:
        """One stored variable as a NumPy array (zarr only)."""
        from thermogear.sweep.store import _quiet_zarr

        with _quiet_zarr():
            return np.asarray(self._arrays[name][...])

    def dataset(self):
        """The store as a loaded xarray Dataset, without its completion record."""
        return open_task_store(self.path)


def _placed(layout: StoreLayout, name: str, region: Mapping[str, Any], values) -> tuple[tuple, Any]:
    """Where a task's values of variable ``name`` go (``region``: dim → slice or index) and the values as stored."""
    variable = next(v for v in layout.variables if v.name == name)
    if variable.kind == "str":
        values = np.asarray(values, dtype=object).astype(str).astype(f"<U{variable.width}")
    return tuple(region.get(dim, slice(None)) for dim in variable.dims), values


class MemoryStore:
    """A study's arrays held in memory, written task by task as :class:`TaskStore` writes its store (a study run
    without ``out``): the same layout, regions and fill values."""

    def __init__(self, layout: StoreLayout) -> None:
        self.layout = layout
        self._arrays = {variable.name: np.full(layout.shape(variable.dims), _FILL[variable.kind],
                                               dtype=f"<U{variable.width}" if variable.kind == "str" else
                                               {"float": np.float64, "int8": np.int8, "bool": bool}[variable.kind])
                        for variable in layout.variables}

    def done_tasks(self) -> set[int]:
        return set()

    def write(self, number: int, region: Mapping[str, Any], arrays: Mapping[str, Any]) -> None:
        for name, values in arrays.items():
            selection, values = _placed(self.layout, name, region, values)
            self._arrays[name][selection] = values

    def read_variable(self, name: str) -> np.ndarray:
        return self._arrays[name]


def open_task_store(path: str | Path, keep_record: bool = False):
    """A task store as a loaded xarray Dataset (``keep_record``: with ``task_done``)."""
    import xarray as xr

    from thermogear.sweep.store import _quiet_zarr

    with _quiet_zarr():
        dataset = xr.open_zarr(str(path), consolidated=None, chunks=None).load()
    return dataset if keep_record else dataset.drop_vars(DONE, errors="ignore")


def store_is_complete(dataset) -> tuple[bool, str]:
    """Whether an opened store (any of thermogear's) holds every point, and if not, what is missing: the tasks or
    chunks its completion record does not mark done; a store without a record (written whole) whose every number
    is NaN holds no result at all."""
    for record in (DONE, "chunk_done"):
        if record in dataset.variables:
            marks = np.asarray(dataset[record].values)
            if marks.size and not np.all(marks == 1):
                return False, (f"{int(np.sum(marks != 1))} of {marks.size} tasks unfinished (an interrupted study: "
                               "continue it with --resume); their points read NaN")
            return True, ""
    numbers = [name for name, values in dataset.data_vars.items() if values.dtype.kind == "f"]
    if numbers and not any(np.isfinite(np.asarray(dataset[name].values)).any() for name in numbers):
        return False, "every value is NaN (no point holds a result)"
    return True, ""


def _read_attributes(target: Path) -> dict:
    import zarr

    from thermogear.sweep.store import _quiet_zarr

    try:
        with _quiet_zarr():
            return dict(zarr.open_group(str(target), mode="r").attrs)
    except (FileNotFoundError, ValueError, KeyError, OSError, TypeError):
        return {}


def _read_done_count(target: Path) -> int:
    import zarr

    from thermogear.sweep.store import _quiet_zarr

    try:
        with _quiet_zarr():
            return int(np.sum(zarr.open_group(str(target), mode="r")[DONE][:]))
    except (FileNotFoundError, ValueError, KeyError, OSError, TypeError):
        return 0


def _write_layout(target: Path, layout: StoreLayout) -> None:
    """Every array (unwritten chunks read as the fill value), the coordinates, the attributes, the metadata
    consolidated and the creation record last, in xarray's zarr v3 conventions."""
    import zarr

    from thermogear import __version__
    from thermogear.sweep.store import _fill_attribute, _quiet_zarr

    attributes = {"thermogear_version": __version__, **layout.attrs, "study_definition": layout.definition_json()}
    with _quiet_zarr():
        group = zarr.open_group(str(target), mode="a", attributes=attributes)
        for name, values in layout.coords.items():
            data = np.asarray(values)
            if data.dtype.kind in "OU":
                data = data.astype(str)
            group.create_array(name, data=data, dimension_names=(name,),
                               fill_value=np.nan if data.dtype.kind == "f" else None,
                               attributes={**layout.coord_attrs.get(name, {}), **_fill_attribute(data.dtype)})
        for variable in layout.variables:
            dtype = {"float": np.dtype(np.float64), "int8": np.dtype(np.int8), "bool": np.dtype(bool),
                     "str": np.dtype(f"<U{variable.width}")}[variable.kind]
            attributes = {"units": variable.units, "long_name": variable.long_name}
            if variable.kind == "float":
                attributes.update(_fill_attribute(np.dtype(np.float64)))
            group.create_array(variable.name, shape=layout.shape(variable.dims),
                               chunks=layout.chunk_shape(variable.dims), dtype=dtype,
                               fill_value=_FILL[variable.kind], dimension_names=variable.dims,
                               attributes=attributes)
        group.create_array(DONE, shape=(layout.tasks,), chunks=(1,), dtype=np.uint8, fill_value=0,
                           dimension_names=("task",),
                           attributes={"long_name": "1 where the task of this number is completely written"})
        group.attrs[_INITIALIZED] = 1
        zarr.consolidate_metadata(str(target))
