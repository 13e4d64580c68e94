"""Nonlinear-mesh studies over grids: speed × other keys on threads, jammed points marked, back-contact fraction.

Each test failed before its fix: a nonlinear study without a speed axis raised "setting an array element with a
sequence"; a study with one jamming value was refused whole; the store had no back-contact fraction.
"""

from __future__ import annotations

import json
import subprocess
import sys
import warnings

import numpy as np
import pytest

from thermogear.case import load_case
from thermogear.sweep import Study, run_study
from thermogear.sweep.branches import branch_study


def _quiet(function, *args, **kwargs):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return function(*args, **kwargs)


@pytest.fixture(scope="module")
def tight_fzg():
    # FZG type C with 60 μm of normal backlash at 20 °C: the gears (steel in a cast-iron housing at the 60 °C
    # sump) jam at a bulk temperature of about 135 °C, so 180 °C jams and 60/100 °C do not
    return load_case("fzg_type_c").with_changes(**{"gears.backlash_normal_um": 60.0})


def test_nonlinear_sweep_of_the_oil_temperature_alone_runs(tmp_path):
    # the command of the issue, one model to keep it short: no speed axis, one orbit per value and direction
    out = tmp_path / "oil.zarr"
    result = subprocess.run([sys.executable, "-m", "thermogear", "sweep", "fzg_type_c", "--vary",
                             "oil_temperature_c=40,80", "--model", "elastic", "--out", str(out), "--json",
                             "--no-progress"], capture_output=True, text=True, timeout=300)
    assert result.returncode == 0, result.stderr
    assert "Traceback" not in result.stderr
    summary = json.loads(result.stdout)
    assert summary["dims"] == {"oil_temperature_c": 2} and summary["failed_points"]["elastic/up"] == 0
    import xarray as xr

    stored = xr.open_zarr(out)
    assert stored["kv"].dims == ("direction", "model", "oil_temperature_c")
    assert stored["jammed"].dims == ("model", "oil_temperature_c")
    assert np.all(np.isfinite(stored["kv"].values)) and np.all(stored["kv"].values > 1.0)
    assert set(stored["response"].values.ravel().astype(str)) == {"periodic"}


def test_a_grid_of_speed_and_torque_is_one_branch_pair_per_torque():
    # each torque's slice of the grid is exactly the study of that torque alone (same problems, same
    # continuation), whatever the number of threads: equality to the last bit
    case = load_case("fzg_type_c")
    grid = Study.define(case, {"torque_nm": [100.0, 200.0], "speed_rpm": "14000:22000:5"}, model="elastic")
    threaded = _quiet(branch_study, grid, "both", workers=2)
    serial = _quiet(branch_study, grid, "both", workers=1)
    for name in ("kv", "dte_peak_to_peak", "back_contact_fraction", "contact_loss_fraction"):
        np.testing.assert_array_equal(threaded[name].values, serial[name].values)
    alone = Study.define(grid.case_at((200.0, 14000.0)), {"speed_rpm": "14000:22000:5"}, model="elastic")
    single = _quiet(branch_study, alone, "both", workers=1)
    np.testing.assert_array_equal(threaded["kv"].sel(torque_nm=200.0).values, single["kv"].values)
    # the load changes the response, so the two slices differ (the axis is not ignored)
    assert not np.array_equal(threaded["kv"].sel(torque_nm=100.0).values, single["kv"].values)


def test_jammed_points_of_a_branch_study_are_marked_and_the_rest_computed(tight_fzg):
    study = Study.define(tight_fzg, {"bulk_temperature_c": [60.0, 180.0], "speed_rpm": "2000:6000:2"},
                         model="both")
    data = _quiet(branch_study, study, "both", workers=2)
    jammed = data["jammed"].values  # (model, bulk, speed)
    assert np.all(jammed[:, 1] == 1) and np.all(jammed[:, 0] == 0)
    hot = data.sel(bulk_temperature_c=180.0)
    assert np.all(np.isnan(hot["kv"].values)) and np.all(hot["converged"].values == 0)
    assert set(hot["response"].values.ravel().astype(str)) == {"jammed"}
    cold = data.sel(bulk_temperature_c=60.0)
    assert np.all(np.isfinite(cold["kv"].values)) and np.all(cold["converged"].values == 1)


@pytest.mark.parametrize("method", ["batch", "simulation"])
def test_jammed_points_of_a_linear_study_are_marked_never_valid(tmp_path, tight_fzg, method):
    from thermogear.cli.sweep_summary import response_summary
    from thermogear.sweep.plots import linear_model_valid

    linear = tight_fzg.with_changes(**{"dynamics.mesh": "linear"})
    study = Study.define(linear, {"bulk_temperature_c": [100.0, 180.0], "speed_rpm": "2000:4000:2"})
    run = _quiet(run_study, study, tmp_path / "linear.zarr", scheduler="serial", method=method)
    jammed, kv = run.read("jammed"), run.read("kv")  # (model, bulk, speed)
    assert np.all(jammed[:, 1] == 1) and np.all(jammed[:, 0] == 0)
    assert np.all(np.isnan(kv[:, 1])) and np.all(np.isfinite(kv[:, 0]))
    valid = linear_model_valid({name: run.read(name) for name in ("stable", "contact_loss", "jammed")})
    assert not np.any(valid[:, 1])
    summary = response_summary(run, study.models)
    assert summary["jammed_points"] == 4 and summary["unstable_points"] == 0  # 2 models × 2 speeds


def test_the_store_keeps_the_back_contact_fraction():
    # luo2019 with 131 μm of backlash: the down sweep's high branch strikes the back flanks at 8000 rpm (the
    # orbit's back-contact time over its period, summed exactly by the integrator: 0.2068 when this test was
    # written); where no back flank is struck the fraction is exactly 0
    case = load_case("luo2019").with_changes(**{"dynamics.mesh": "nonlinear", "gears.backlash_normal_um": 131.0})
    study = Study.define(case, {"speed_rpm": "8000:14000:4"}, model="elastic")
    data = _quiet(branch_study, study, "both", workers=1).sel(model="elastic")
    flag, fraction = data["back_side_contact"].values, data["back_contact_fraction"].values
    assert np.all((fraction > 0.0) == (flag == 1))
    assert flag[1, 0] == 1 and 0.1 < fraction[1, 0] < 0.5  # direction down, 8000 rpm
    assert data["back_contact_fraction"].attrs["units"] == "1"


def test_the_backlash_integrator_releases_the_gil():
    # the branch study's threads compute in parallel only if the compiled integrator releases Python's GIL
    from thermogear.dynamics.backlash.backlash_kernel import integrate_periods

    assert integrate_periods.targetoptions.get("nogil") is True


def test_resuming_a_store_written_before_the_jammed_flag_is_refused_clearly(tmp_path):
    # a store of an earlier version lacks `jammed`; resuming it would fail on the first write (KeyError): refuse it
    # before computing, naming the variable and what to do
    import shutil

    import zarr

    from thermogear.errors import CaseError
    from thermogear.sweep.store import ResultStore

    study = Study.define(load_case("luo2019"), {"speed_rpm": "1000:3000:3"})
    out = tmp_path / "old.zarr"
    _quiet(run_study, study, out, scheduler="serial")
    shutil.rmtree(out / "jammed")
    _quiet(zarr.consolidate_metadata, str(out))
    with pytest.raises(CaseError, match="lacks jammed.*--overwrite"):
        _quiet(ResultStore.resume, out, study)
