"""The store is laid out with zarr directly; xarray's own writer, given the same dataset, lays out the same."""

from __future__ import annotations

import json
import warnings

import numpy as np
import pytest

from thermogear.sweep import Study
from thermogear.sweep.batch import FLAG_VARIABLES, MODEL_VARIABLES, POINT_VARIABLES
from thermogear.sweep.store import ResultStore, _attributes, open_result


def _xarray_layout(target, study) -> None:
    """The reference: xarray's to_zarr of a template of lazy Dask arrays (metadata only, compute=False)."""
    import dask.array as da
    import xarray as xr
    import zarr

    coords = {"model": ("model", np.array(study.models, dtype=str))}
    for parameter in study.parameters:
        coords[parameter.name] = (parameter.name, np.array(parameter.values), {"case_key": parameter.key})
    data_vars, encoding = {}, {}
    for name, (units, long_name) in MODEL_VARIABLES.items():
        dtype = np.int8 if name in FLAG_VARIABLES else np.float64
        data = da.full((len(study.models), *study.shape), 0 if dtype is np.int8 else np.nan, dtype=dtype, chunks=-1)
        data_vars[name] = (("model", *study.dims), data, {"units": units, "long_name": long_name})
        encoding[name] = {"chunks": (len(study.models), *study.chunk_shape)}
    for name, (units, long_name) in POINT_VARIABLES.items():
        data = da.full(study.shape, np.nan, dtype=np.float64, chunks=-1)
        data_vars[name] = (study.dims, data, {"units": units, "long_name": long_name})
        encoding[name] = {"chunks": study.chunk_shape}
    data_vars["chunk_done"] = ("chunk", da.zeros(len(study.blocks()), dtype=np.uint8, chunks=-1),
                               {"long_name": "1 where the block (task) of this number is completely written"})
    encoding["chunk_done"] = {"chunks": (1,)}
    xr.Dataset(data_vars=data_vars, coords=coords, attrs=_attributes(study)).to_zarr(
        str(target), mode="w", compute=False, encoding=encoding, consolidated=True, safe_chunks=False)
    group = zarr.open_group(str(target), mode="r+", use_consolidated=False)
    group.attrs["thermogear_initialized"] = 1  # the creation record, written last
    zarr.consolidate_metadata(str(target))


def _array_metadata(root) -> dict[str, dict]:
    return {path.parent.name: json.loads(path.read_text()) for path in sorted(root.glob("*/zarr.json"))}


@pytest.mark.parametrize("vary", [["speed_rpm=1000:9000:30", "torque_nm=200,400"],
                                  ["dynamics.points_per_period=512,1024", "speed_rpm=2000,4000,6000"]])
def test_layout_equals_xarrays(luo2019, tmp_path, vary):
    study = Study.define(luo2019, vary, chunk_points=7)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # zarr's notes on its string dtype and consolidated metadata
        ResultStore.create(tmp_path / "direct.zarr", study)
        _xarray_layout(tmp_path / "xarray.zarr", study)
        direct, reference = open_result(tmp_path / "direct.zarr", keep_record=True), \
            open_result(tmp_path / "xarray.zarr", keep_record=True)
    ours, theirs = _array_metadata(tmp_path / "direct.zarr"), _array_metadata(tmp_path / "xarray.zarr")
    assert sorted(ours) == sorted(theirs)
    for name in theirs:
        assert ours[name] == theirs[name], name
    assert direct.identical(reference)
    for name in reference.variables:
        assert direct[name].dtype == reference[name].dtype
        assert np.array_equal(direct[name].encoding.get("_FillValue", 0), reference[name].encoding.get("_FillValue", 0),
                              equal_nan=True), name
