"""A sweep against a `dask scheduler` with two `dask worker` processes gives the dataset of the local default.

The scheduler and the workers are separate processes started here on 127.0.0.1 with free ports, and always torn
down (their process groups are killed in a finally block).
"""

from __future__ import annotations

import json
import os
import shutil
import signal
import subprocess
import sys
import time
import warnings

import numpy as np
import pytest

from thermogear.case import load_case
from thermogear.sweep import Study, run_study


def _dask_command() -> list[str]:
    executable = shutil.which("dask")
    return [executable] if executable else [sys.executable, "-m", "distributed.cli.dask_spec"]


def _scheduler_address(scheduler_file, scheduler: subprocess.Popen, deadline: float) -> str:
    """The address the scheduler wrote into its scheduler file (it chose a free port itself: --port 0)."""
    while True:
        try:
            return str(json.loads(scheduler_file.read_text(encoding="utf-8"))["address"])
        except (OSError, ValueError, KeyError):
            if scheduler.poll() is not None or time.monotonic() > deadline:
                raise RuntimeError("the dask scheduler wrote no address") from None
            time.sleep(0.2)


@pytest.fixture(scope="module")
def cluster(tmp_path_factory):
    """(address, processes) of a scheduler and two single-thread workers on this machine, one for the tests of a
    module (their stores do not depend on what ran on the workers before). Ports and dashboard: the scheduler picks
    a free port itself and starts no dashboard, so that test workers running in parallel cannot collide."""
    if shutil.which("dask") is None:
        pytest.skip("the `dask` command line is not installed")
    scheduler_file = tmp_path_factory.mktemp("dask") / "scheduler.json"
    env = {**os.environ, "PYTHONWARNINGS": "ignore"}
    processes = [subprocess.Popen(["dask", "scheduler", "--host", "127.0.0.1", "--port", "0", "--no-dashboard",
                                   "--scheduler-file", str(scheduler_file)],
                                  stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, start_new_session=True,
                                  env=env)]
    try:
        deadline = time.monotonic() + 45
        address = _scheduler_address(scheduler_file, processes[0], deadline)
        for _ in range(2):
            processes.append(subprocess.Popen(["dask", "worker", address, "--nthreads", "1", "--nworkers", "1",
                                               "--host", "127.0.0.1", "--no-dashboard"],
                                              stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                                              start_new_session=True, env=env))
        from distributed import Client

        while True:
            try:
                with Client(address, timeout="5s") as client:
                    client.wait_for_workers(2, timeout=max(deadline - time.monotonic(), 1))
                break
            except (OSError, TimeoutError):
                if time.monotonic() > deadline:
                    raise
                time.sleep(0.3)
        yield address, processes
    finally:
        for process in processes:
            if process.poll() is None:
                os.killpg(process.pid, signal.SIGTERM)
        for process in processes:
            try:
                process.wait(timeout=10)
            except subprocess.TimeoutExpired:
                os.killpg(process.pid, signal.SIGKILL)
                process.wait()


def test_scheduler_address_gives_the_local_dataset(tmp_path, cluster):
    address, processes = cluster
    study = Study.define(load_case("luo2019"), ["speed_rpm=1000:12000:48", "oil_temperature_c=40,80"],
                         chunk_points=16)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        remote = run_study(study, tmp_path / "remote.zarr", scheduler=address, progress=False)
        local = run_study(study, tmp_path / "local.zarr", workers=2, progress=False)
    assert remote.computed == len(study.blocks()) == local.computed
    assert remote.dataset.identical(local.dataset)
    for name in local.dataset.data_vars:
        assert np.array_equal(np.asarray(remote.dataset[name]), np.asarray(local.dataset[name]), equal_nan=True)
    assert all(process.poll() is None for process in processes)  # the cluster outlives the study
    stable = remote.dataset["stable"] == 1
    assert bool(stable.any()) and bool(np.isfinite(remote.dataset["kv"].where(stable, 0.0)).all())
