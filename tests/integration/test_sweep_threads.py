"""The threaded local scheduler: the serial dataset bit for bit, every warning once, no warning state touched."""

from __future__ import annotations

import threading
import warnings

import numpy as np
import pytest

from thermogear.sweep import Study, run_study
from thermogear.sweep import engine

# luo2019 at 30 °C oil warns that the viscosity line is extrapolated; 8 chunks give the two threads four each
GRID = ["speed_rpm=1000:12000:40", "torque_nm=200,300,400,500"]


@pytest.fixture()
def study(luo2019):
    return Study.define(luo2019, GRID, chunk_points=20)


@pytest.fixture()
def catch_warnings_in_workers(monkeypatch):
    """Names of the non-main threads that open a catch_warnings block (it would race the other workers); the
    watch is on while the test sets ``watch[0] = True``."""
    entered: list[str] = []
    watch = [False]
    original = warnings.catch_warnings

    class Watched(original):
        def __enter__(self):
            if watch[0] and threading.current_thread() is not threading.main_thread():
                entered.append(threading.current_thread().name)
            return super().__enter__()

    monkeypatch.setattr(warnings, "catch_warnings", Watched)
    return entered, watch


def test_local_default_is_threads_on_the_fast_path_and_processes_otherwise(study, luo2019):
    from thermogear.sweep.schedulers import PROCESSES, THREADS

    assert engine.local_scheduler(study, "batch") is THREADS
    assert engine.local_scheduler(study, "simulation") is PROCESSES  # pure Python per point: processes
    assert engine.local_scheduler(study, "batch", dashboard=":0") is PROCESSES  # the Dask cluster serves it
    nonlinear = Study.define(luo2019.with_changes(**{"dynamics.mesh": "nonlinear"}), GRID, chunk_points=20)
    assert engine.local_scheduler(nonlinear, "batch") is PROCESSES  # no fast path: one point at a time


def test_threads_give_the_serial_dataset_and_its_warnings(study, tmp_path, catch_warnings_in_workers):
    outside_main, watch = catch_warnings_in_workers
    before = (warnings.showwarning, list(warnings.filters))
    serial = run_study(study, tmp_path / "serial.zarr", scheduler="serial")
    watch[0] = True
    threaded = run_study(study, tmp_path / "threads.zarr", scheduler="threads", workers=2)
    watch[0] = False
    assert threaded.computed == serial.computed == len(study.blocks()) == 8
    for name in serial.dataset.data_vars:
        assert np.array_equal(np.asarray(threaded.dataset[name]), np.asarray(serial.dataset[name]), equal_nan=True)
    assert threaded.messages == serial.messages
    assert any("extrapolated" in message for message in serial.messages)
    assert outside_main == []
    assert (warnings.showwarning, list(warnings.filters)) == before


def test_a_failing_block_stops_the_threaded_run_and_stays_unmarked(study, tmp_path, monkeypatch):
    from thermogear.sweep.store import open_result

    def fail_on_third(study_, block, method):
        if block.number == 2:
            raise RuntimeError("block 2 failed")
        return original(study_, block, method)

    original = engine.evaluate_block
    monkeypatch.setattr(engine, "evaluate_block", fail_on_third)
    with pytest.raises(RuntimeError, match="block 2 failed"):
        run_study(study, tmp_path / "r.zarr", scheduler="threads", workers=2)
    done = np.asarray(open_result(tmp_path / "r.zarr", keep_record=True)["chunk_done"])
    assert done[2] == 0
    monkeypatch.undo()
    resumed = run_study(study, tmp_path / "r.zarr", scheduler="threads", workers=2, resume=True)
    assert resumed.computed == 8 - int(done.sum()) and resumed.skipped == int(done.sum())


def test_a_dashboard_needs_the_dask_cluster_and_is_refused_before_writing(study, tmp_path):
    from thermogear.errors import CaseError

    for scheduler in ("threads", "serial"):
        with pytest.raises(CaseError) as raised:
            run_study(study, tmp_path / "r.zarr", scheduler=scheduler, dashboard=":0")
        assert raised.value.key == "--dashboard"
    assert not (tmp_path / "r.zarr").exists()


def test_per_point_path_on_threads_touches_no_warning_state(luo2019, tmp_path, catch_warnings_in_workers):
    # one Simulation per point (the path of points the fast path cannot take), two blocks of four points
    outside_main, watch = catch_warnings_in_workers
    small = Study.define(luo2019, ["speed_rpm=2000,4000,6000,8000", "torque_nm=200,400"], chunk_points=4)
    serial = run_study(small, tmp_path / "serial.zarr", scheduler="serial", method="simulation")
    watch[0] = True
    threaded = run_study(small, tmp_path / "threads.zarr", scheduler="threads", workers=2, method="simulation")
    watch[0] = False
    for name in serial.dataset.data_vars:
        assert np.array_equal(np.asarray(threaded.dataset[name]), np.asarray(serial.dataset[name]), equal_nan=True)
    assert threaded.messages == serial.messages
    assert outside_main == []
