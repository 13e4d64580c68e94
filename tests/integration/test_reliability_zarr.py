"""A sweep's zarr store is written without zarr's own specification warnings and opens without any (issue 15):
the metadata are consolidated, and the warnings zarr raises about its own format are silenced where thermogear
writes and reads the store."""

from __future__ import annotations

import warnings

import xarray as xr

from thermogear.ownership import is_owned
from thermogear.sweep import Study, run_study


def test_store_is_written_and_opened_without_warnings(luo2019, tmp_path):
    study = Study.define(luo2019, ["speed_rpm=1000,2000"], model="elastic")
    out = tmp_path / "study.zarr"
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        run_study(study, out, scheduler="serial", progress=False)
    zarr_warnings = [str(w.message) for w in caught if "zarr" in (w.filename + w.category.__module__).lower()]
    assert zarr_warnings == []
    assert is_owned(out, "sweep-store")
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # a user opening the store: no "consolidated metadata" warning
        dataset = xr.open_zarr(out)
        assert dataset["kv"].shape == (1, 2)
        dataset.close()
