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
  ``thermogear_initialized`` written last when the store is created (a store without it is created anew).

No time stamps are stored, so an interrupted and resumed study gives exactly the store of an uninterrupted one.
"""

from __future__ import annotations

import json
import shutil
from pathlib import Path
from typing import Any

import numpy as np

from thermogear.errors import CaseError
from thermogear.sweep.batch import MODEL_VARIABLES, POINT_VARIABLES

__all__ = ["ResultStore", "open_result", "study_description"]

_INITIALIZED = "thermogear_initialized"
_DONE = "chunk_done"


def _attributes(study) -> dict[str, Any]:
    from thermogear import __version__

    return {
        "title": "thermogear parameter study",
        "thermogear_version": __version__,
        "case_name": study.case.name,
        "case_source": str(study.case.source),
        "case_json": json.dumps(study.case.document, sort_keys=True, default=str),
        "study_json": json.dumps(study.describe(), sort_keys=True),
        "models": ",".join(study.models),
    }


class ResultStore:
    """A study's zarr store. Create with :meth:`create`, reopen with :meth:`resume`."""

    def __init__(self, path: str | Path, study) -> None:
        import zarr

        self.path = Path(path)
        self.study = study
        self._group = zarr.open_group(str(self.path), mode="r+")

    # ------------------------------------------------------------------------------ opening
    @classmethod
    def create(cls, path: str | Path, study, overwrite: bool = False) -> "ResultStore":
        """A new store for ``study``; an existing path is refused unless ``overwrite``."""
        import dask.array as da
        import xarray as xr
        import zarr

        target = Path(path)
        if target.exists():
            if not overwrite:
                raise CaseError("out", str(target), "a path that does not exist yet (or --resume / --overwrite)",
                                "the result store exists; resume it or overwrite it explicitly")
            shutil.rmtree(target) if target.is_dir() else target.unlink()
        dims = study.dims
        chunks = study.chunk_shape
        coords: dict[str, Any] = {"model": ("model", np.array(study.models, dtype=str))}
        for parameter in study.parameters:
            coords[parameter.name] = (parameter.name, np.array(parameter.values),
                                      {"case_key": parameter.key})
        data_vars: dict[str, Any] = {}
        encoding: dict[str, Any] = {}
        model_shape = (len(study.models), *study.shape)
        for name, (units, long_name) in MODEL_VARIABLES.items():
            dtype = np.int8 if name in ("stable", "contact_loss") else np.float64
            fill = 0 if dtype is np.int8 else np.nan
            data = da.full(model_shape, fill, dtype=dtype, chunks=(len(study.models), *chunks))
            data_vars[name] = (("model", *dims), data, {"units": units, "long_name": long_name})
            encoding[name] = {"chunks": (len(study.models), *chunks)}
        for name, (units, long_name) in POINT_VARIABLES.items():
            data = da.full(study.shape, np.nan, dtype=np.float64, chunks=chunks)
            data_vars[name] = (dims, data, {"units": units, "long_name": long_name})
            encoding[name] = {"chunks": chunks}
        blocks = len(study.blocks())
        data_vars[_DONE] = ("chunk", da.zeros(blocks, dtype=np.uint8, chunks=1),
                            {"long_name": "1 where the block (task) of this number is completely written"})
        encoding[_DONE] = {"chunks": (1,)}
        dataset = xr.Dataset(data_vars=data_vars, coords=coords, attrs=_attributes(study))
        dataset.to_zarr(str(target), mode="w", compute=False, encoding=encoding, consolidated=False)
        group = zarr.open_group(str(target), mode="r+")
        group.attrs[_INITIALIZED] = 1
        return cls(target, study)

    @classmethod
    def resume(cls, path: str | Path, study) -> "ResultStore":
        """Reopen the store of ``study`` at ``path`` (created anew when it is absent or was never completely
        created). A store of another study or case is refused."""
        import zarr

        target = Path(path)
        if not target.exists():
            return cls.create(target, study)
        try:
            group = zarr.open_group(str(target), mode="r")
            attrs = dict(group.attrs)
        except (FileNotFoundError, ValueError, KeyError, OSError, TypeError):
            attrs = {}
        if not attrs.get(_INITIALIZED):
            return cls.create(target, study, overwrite=True)
        stored = json.loads(attrs.get("study_json", "{}"))
        if stored != json.loads(json.dumps(study.describe(), sort_keys=True)):
            raise CaseError("out", str(target), "a store of the same study (case, parameters, models, chunks)",
                            "--resume continues the study that created this store; this study differs "
                            f"(stored: {json.dumps(stored)[:300]})")
        return cls(target, study)

    # ------------------------------------------------------------------------------ blocks
    def done_blocks(self) -> set[int]:
        """Numbers of the blocks whose data are completely written."""
        marks = np.asarray(self._group[_DONE][:])
        return {int(i) for i in np.flatnonzero(marks == 1)}

    def write_block(self, block, arrays: dict[str, np.ndarray]) -> None:
        """Write a block's arrays into their region, then mark the block done (the marker goes last)."""
        region = tuple(block.slices)
        for name in MODEL_VARIABLES:
            self._group[name][(slice(None), *region)] = arrays[name]
        for name in POINT_VARIABLES:
            self._group[name][region] = arrays[name]
        self._group[_DONE][block.number] = 1

    @property
    def complete(self) -> bool:
        return len(self.done_blocks()) == len(self.study.blocks())

    def dataset(self, keep_record: bool = False):
        """The results as an xarray Dataset (loaded into memory)."""
        return open_result(self.path, keep_record=keep_record)


def open_result(path: str | Path, keep_record: bool = False):
    """Open a study's store as an xarray Dataset (loaded); ``keep_record`` keeps the ``chunk_done`` record."""
    import xarray as xr

    dataset = xr.open_zarr(str(path), consolidated=False).load()
    if not keep_record:
        dataset = dataset.drop_vars(_DONE)
    return dataset


def study_description(path: str | Path) -> dict[str, Any] | None:
    """The study definition stored at ``path`` (for ``--resume`` without repeating ``--vary``), or None when
    there is no completely created store there."""
    import zarr

    target = Path(path)
    if not target.exists():
        return None
    try:
        attrs = dict(zarr.open_group(str(target), mode="r").attrs)
    except (FileNotFoundError, ValueError, KeyError, OSError, TypeError):
        return None
    if not attrs.get(_INITIALIZED) or "study_json" not in attrs:
        return None
    return json.loads(attrs["study_json"])
