"""Result store of a study: a zarr group written chunk by chunk, resumable after any interruption.

Layout (xarray conventions, readable with ``xarray.open_zarr``):

* one coordinate per swept parameter (its values) and ``model`` (``elastic``/``thermal``);
* per-model variables with dims ``(model, *parameters)``, per-point variables with dims ``(*parameters)``, all
  chunked like the study's blocks (one task = one chunk of every variable);
* ``chunk_done`` (dim ``chunk``, one zarr chunk per block): the completion record. A block's marker is written
  only after all of its data chunks are written, and every zarr chunk file is written atomically (a temporary
  file renamed into place), so a marker set means the block's data is complete. A study killed at any moment
  (SIGKILL included) therefore leaves finished blocks marked, an unfinished block unmarked (recomputed on resume,
  its partial data overwritten by identical numbers), and nothing marked that is not there;
* attributes: ``thermogear_version``, the case document (JSON), the study definition (JSON), and
  ``thermogear_initialized`` written last when the store is created (a store of thermogear's without it is
  created anew);
* the ownership marker file (:mod:`thermogear.ownership`), written first when the store is created. An existing
  path is only overwritten (``--overwrite``) or resumed (``--resume``) when it carries that marker; anything else
  is refused, untouched. ``--resume`` never deletes a store that holds finished blocks.
* metadata consolidated (``zarr.json`` of the group lists every array), so that opening a store reads one file
  and does not warn.

No time stamps are stored, so an interrupted and resumed study gives exactly the store of an uninterrupted one.
"""

from __future__ import annotations

import base64
import json
import os
import shutil
import tempfile
import warnings
from contextlib import contextmanager
from pathlib import Path
from typing import Any

import numpy as np

from thermogear.errors import CaseError
from thermogear.ownership import (is_owned, remove_interrupted_writes, require_no_foreign_entries, require_owned,
                                  resolve_output, write_marker)
from thermogear.sweep.batch import FLAG_VARIABLES, MODEL_VARIABLES, POINT_VARIABLES

__all__ = ["ResultStore", "open_result", "study_description"]

_INITIALIZED = "thermogear_initialized"
_DONE = "chunk_done"
_KIND = "sweep-store"


def _umask() -> int:
    umask = os.umask(0)
    os.umask(umask)
    return umask


@contextmanager
def _quiet_zarr():
    """Silence zarr's warnings about its own specification (``UnstableSpecificationWarning``: the fixed-length
    string dtype of the ``model`` coordinate has no final zarr v3 specification yet) where the store is written
    and read; thermogear reads back what it wrote, so the warning says nothing to the user. Also silenced: zarr's
    note that the ownership marker file is not part of the zarr hierarchy (it is not meant to be), and its note
    that consolidated metadata is not yet in the zarr v3 specification (zarr-python and xarray read it)."""
    with warnings.catch_warnings():
        warnings.filterwarnings("ignore", message=r"Consolidated metadata is currently not part")
        warnings.filterwarnings("ignore", message=r".*is not recognized as a component of a Zarr hierarchy")
        try:
            from zarr.errors import UnstableSpecificationWarning
        except ImportError:  # older zarr: no such warning
            pass
        else:
            warnings.simplefilter("ignore", UnstableSpecificationWarning)
        yield


def _attributes(study) -> dict[str, Any]:
    from thermogear import __version__
    from thermogear.sweep.load_held import study_load_held

    load, load_note = study_load_held(study)

    return {
        "title": "thermogear parameter study",
        "thermogear_version": __version__,
        "case_name": study.case.name,
        "case_source": str(study.case.source),
        "case_json": json.dumps(study.case.document, sort_keys=True, default=str),
        "study_json": json.dumps(study.describe(), sort_keys=True),
        "models": ",".join(study.models),
        "load": load,  # constant torque | constant power (issue 24: every sweep output names it)
        "load_note": load_note,
    }


class ResultStore:
    """A study's zarr store. Create with :meth:`create`, reopen with :meth:`resume`."""

    def __init__(self, path: str | Path, study) -> None:
        import zarr

        self.path = Path(path)
        self.study = study
        with _quiet_zarr():
            self._group = zarr.open_group(str(self.path), mode="r+", use_consolidated=False)
        self._arrays: dict[str, Any] = {}

    # ------------------------------------------------------------------------------ opening
    @classmethod
    def create(cls, path: str | Path, study, overwrite: bool = False) -> "ResultStore":
        """A new store for ``study``; an existing path is refused unless ``overwrite``."""
        target = resolve_output(path)
        if target.exists() and not overwrite:
            raise CaseError("out", str(target), "a path that does not exist yet (or --resume / --overwrite)",
                            "the result store exists; resume it or overwrite it explicitly")
        create_owned_folder(target, target.exists(), _KIND)
        with _quiet_zarr():
            _write_layout(target, study)
        return cls(target, study)

    @classmethod
    def resume(cls, path: str | Path, study) -> "ResultStore":
        """Reopen the store of ``study`` at ``path`` (created anew when it is absent or was never completely
        created). A store of another study or case is refused."""
        import zarr

        target = resolve_output(path)
        if not target.exists():
            return cls.create(target, study)
        require_owned(target, _KIND, "--out", "resumed or deleted")
        remove_interrupted_writes(target)  # a killed writer's half-written chunks
        try:
            with _quiet_zarr():
                group = zarr.open_group(str(target), mode="r")
                attrs = dict(group.attrs)
                done = int(np.sum(group[_DONE][:])) if _DONE in group else 0
        except (FileNotFoundError, ValueError, KeyError, OSError, TypeError):
            attrs, done = {}, 0
        if not attrs.get(_INITIALIZED):
            if done:  # never: the record is created before any block; but --resume must not delete results
                raise CaseError("--out", str(target), "a completely created store",
                                "the store holds finished blocks but no creation record; nothing was changed")
            return cls.create(target, study, overwrite=True)
        stored = json.loads(attrs.get("study_json", "{}"))
        if stored != json.loads(json.dumps(study.describe(), sort_keys=True)):
            raise CaseError("out", str(target), "a store of the same study (case, parameters, models, chunks)",
                            "--resume continues the study that created this store; this study differs "
                            f"(stored: {json.dumps(stored)[:300]})")
        store = cls(target, study)
        missing = [name for name in (*MODEL_VARIABLES, *POINT_VARIABLES) if name not in store._group]
        if missing:  # written by an earlier thermogear, before these variables existed
            raise CaseError("--resume", str(target), "a store with every variable of this version",
                            f"the store lacks {', '.join(missing)} (an earlier thermogear wrote it); run the study "
                            "again with --overwrite")
        return store

    # ------------------------------------------------------------------------------ blocks
    def done_blocks(self) -> set[int]:
        """Numbers of the blocks whose data are completely written."""
        marks = np.asarray(self._group[_DONE][:])
        return {int(i) for i in np.flatnonzero(marks == 1)}

    def write_data(self, block, arrays: dict[str, np.ndarray]) -> None:
        """Write a block's arrays into their region, without its marker (a worker writes its own block's data;
        the driver marks the block once the worker has returned). Blocks are whole zarr chunks, so processes
        writing different blocks never touch the same file."""
        import asyncio

        from zarr.core.sync import sync

        region = tuple(block.slices)
        writes = [self._array(name).async_array.setitem((slice(None), *region), arrays[name])
                  for name in MODEL_VARIABLES]
        writes += [self._array(name).async_array.setitem(region, arrays[name]) for name in POINT_VARIABLES]

        async def write_all() -> None:  # one trip to zarr's event loop for all arrays, written concurrently
            await asyncio.gather(*writes)

        sync(write_all())

    def mark_done(self, block) -> None:
        """Record a block whose data are completely written."""
        self._array(_DONE)[block.number] = 1

    def open_arrays(self) -> None:
        """Open every array now (the driver of a threaded run does, so its workers only write data)."""
        for name in (*MODEL_VARIABLES, *POINT_VARIABLES, _DONE):
            self._array(name)

    def _array(self, name: str):
        """The zarr array ``name``, opened once per store object (opening reads its metadata from disk)."""
        if name not in self._arrays:
            with _quiet_zarr():
                self._arrays[name] = self._group[name]
        return self._arrays[name]

    def read(self, name: str) -> np.ndarray:
        """The whole array ``name`` as NumPy (dims ``(model, *parameters)`` or ``(*parameters)``), read with zarr:
        a summary of the study needs neither xarray nor the coordinates."""
        with _quiet_zarr():
            return np.asarray(self._array(name)[...])

    @property
    def complete(self) -> bool:
        return len(self.done_blocks()) == len(self.study.blocks())

    def dataset(self, keep_record: bool = False, lazy: bool = False):
        """The results as an xarray Dataset (loaded into memory; ``lazy``: read from the store when used)."""
        return open_result(self.path, keep_record=keep_record, lazy=lazy)


def create_owned_folder(target: Path, replace: bool, kind: str = _KIND) -> None:
    """Create the folder of a store with its ownership marker already in it (a hidden sibling renamed into place:
    a kill never leaves it unmarked); ``replace``: the existing folder is deleted first, only when thermogear wrote
    it as ``kind`` and it holds nothing else at any depth (a user's notes.txt is never deleted)."""
    if replace:
        require_owned(target, kind, "--out", "overwritten")
        require_no_foreign_entries(target)
        shutil.rmtree(target)
    try:
        target.parent.mkdir(parents=True, exist_ok=True)
        staging = Path(tempfile.mkdtemp(prefix=f".{target.name}.creating-", dir=target.parent))
        try:
            write_marker(staging, kind)
            os.chmod(staging, 0o777 & ~_umask())
            os.rename(staging, target)
        finally:
            if staging.exists():
                shutil.rmtree(staging, ignore_errors=True)
    except OSError as error:
        raise CaseError("--out", str(target), "a folder thermogear can create and write",
                        f"cannot write there: {error.strerror or error}") from None


def _write_layout(target: Path, study) -> None:
    """The arrays (data unwritten: chunks read as the fill value until a block writes them), the coordinates and
    the attributes of a new store, in xarray's zarr v3 conventions (``dimension_names``; a float array's fill value
    also as the base64 ``_FillValue`` attribute), then the metadata consolidated and the creation record last.
    Written with zarr directly: an xarray template of lazy Dask arrays gives the same metadata (tested) but costs
    about 0.8 s of imports and graph building on every study."""
    import zarr

    # mode "a" into the folder that holds only the marker: "w" would clear the folder, marker included
    group = zarr.open_group(str(target), mode="a", attributes=_attributes(study))
    group.create_array("model", data=np.array(study.models, dtype=str), dimension_names=("model",))
    for parameter in study.parameters:
        values = np.array(parameter.values)
        group.create_array(parameter.name, data=values, dimension_names=(parameter.name,),
                           fill_value=np.nan if values.dtype.kind == "f" else None,
                           attributes={"case_key": parameter.key, **_fill_attribute(values.dtype)})
    model_shape = (len(study.models), *study.shape)
    for name, (units, long_name) in MODEL_VARIABLES.items():
        dtype = np.dtype(np.int8 if name in FLAG_VARIABLES else np.float64)
        group.create_array(name, shape=model_shape, chunks=(len(study.models), *study.chunk_shape), dtype=dtype,
                           fill_value=0 if dtype.kind == "i" else np.nan, dimension_names=("model", *study.dims),
                           attributes={"units": units, "long_name": long_name, **_fill_attribute(dtype)})
    for name, (units, long_name) in POINT_VARIABLES.items():
        group.create_array(name, shape=study.shape, chunks=study.chunk_shape, dtype=np.float64, fill_value=np.nan,
                           dimension_names=study.dims,
                           attributes={"units": units, "long_name": long_name,
                                       **_fill_attribute(np.dtype(np.float64))})
    group.create_array(_DONE, shape=(len(study.blocks()),), chunks=(1,), dtype=np.uint8, fill_value=0,
                       dimension_names=("chunk",),
                       attributes={"long_name": "1 where the block (task) of this number is completely written"})
    group.attrs[_INITIALIZED] = 1
    zarr.consolidate_metadata(str(target))


def _fill_attribute(dtype: np.dtype) -> dict[str, str]:
    """xarray's ``_FillValue`` attribute of a float array in a zarr v3 store: NaN as base64 of its bytes."""
    if dtype.kind != "f":
        return {}
    return {"_FillValue": base64.standard_b64encode(np.array(np.nan, dtype=dtype).tobytes()).decode("ascii")}


def open_result(path: str | Path, keep_record: bool = False, lazy: bool = False):
    """Open a study's store as an xarray Dataset, loaded; ``lazy``: each variable is read from the store when it
    is used (no Dask; memory of the variables used, not of the whole grid). ``keep_record`` keeps the
    ``chunk_done`` record."""
    import xarray as xr

    with _quiet_zarr():
        dataset = xr.open_zarr(str(path), consolidated=None, chunks=None)
        if not lazy:
            dataset = dataset.load()
    if not keep_record:
        dataset = dataset.drop_vars(_DONE)
    return dataset


def study_description(path: str | Path) -> dict[str, Any] | None:
    """The study definition stored at ``path`` (for ``--resume`` without repeating ``--vary``), or None when
    there is no completely created store there."""
    import zarr

    target = resolve_output(path)
    if not target.exists() or not is_owned(target, _KIND):
        return None
    try:
        with _quiet_zarr():
            attrs = dict(zarr.open_group(str(target), mode="r").attrs)
    except (FileNotFoundError, ValueError, KeyError, OSError, TypeError):
        return None
    if not attrs.get(_INITIALIZED):
        return None
    if "study_json" in attrs:
        return json.loads(attrs["study_json"])
    if "study_definition" in attrs:  # a task store (drivetrain, branches): the study's own definition in it
        stored = json.loads(attrs["study_definition"])
        return stored if "parameters" in stored else None
    return None
