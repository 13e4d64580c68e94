"""Kill test: a sweep killed with SIGKILL at random moments and resumed gives exactly the uninterrupted dataset.

Each run is a separate `thermogear sweep ... --resume` process in its own session; SIGKILL goes to the whole
process group (the local Dask cluster's nanny and worker processes included), so nothing gets to clean up. The
kill moments are drawn at random in the span of an uninterrupted run (the seed is in the failure message).
"""

from __future__ import annotations

import os
import random
import signal
import subprocess
import sys
import time

import numpy as np
import pytest
import zarr

import inprocess_cli
from thermogear.sweep.store import open_result

STUDY = ["luo2019", "--vary", "speed_rpm=1000:9000:90", "--vary", "torque_nm=200,300,400", "--chunk-points", "6",
         "--method", "simulation", "--no-progress"]


def _command(out, scheduler: str) -> list[str]:
    extra = ["--scheduler", "serial"] if scheduler == "serial" else ["--workers", "2"]
    return [sys.executable, "-m", "thermogear", "sweep", *STUDY, "--out", str(out), "--resume", *extra]


def _run(out, scheduler: str, kill_at_chunks: int | None = None, delay: float = 0.0) -> int | None:
    """Run one sweep process. With ``kill_at_chunks``, SIGKILL its whole process group ``delay`` seconds after at
    least that many chunks are stored (a moment chosen by progress, not by wall time, so that a loaded machine
    cannot push the kill past the end of the run). Returns the exit code, or None when it was killed."""
    process = subprocess.Popen(_command(out, scheduler), stdout=subprocess.DEVNULL, stderr=subprocess.PIPE,
                               start_new_session=True, env={**os.environ, "PYTHONWARNINGS": "ignore"})
    try:
        if kill_at_chunks is None:
            process.wait(timeout=300)
            return process.returncode
        deadline = time.perf_counter() + 300
        while process.poll() is None and _done_count(out) < kill_at_chunks and time.perf_counter() < deadline:
            time.sleep(0.01)
        time.sleep(delay)
        if process.poll() is not None:
            return process.returncode
        os.killpg(process.pid, signal.SIGKILL)
        process.wait()
        return None
    finally:
        if process.poll() is None:  # pragma: no cover - never leave a process behind
            os.killpg(process.pid, signal.SIGKILL)
            process.wait()
        if process.stderr:
            process.stderr.close()


def _done_count(out) -> int:
    try:
        return int(np.sum(zarr.open_group(str(out), mode="r")["chunk_done"][:]))
    except Exception:  # noqa: BLE001 - a store killed during creation may not open; it counts as empty
        return 0


def test_killed_and_resumed_sweep_equals_uninterrupted(tmp_path):
    reference = tmp_path / "reference.zarr"
    assert _run(reference, "serial") == 0
    seed = random.SystemRandom().randrange(2**32)
    rng = random.Random(seed)
    store = tmp_path / "killed.zarr"
    total = int(zarr.open_group(str(reference), mode="r")["chunk_done"].shape[0])
    history = []
    # three kills at random progress (one of them while a local Dask cluster computes), then a resume to the end
    for scheduler in ("serial", "local", "serial"):
        done = _done_count(store)
        if done >= total - 2:
            break
        target = rng.randint(done + 1, total - 2)
        code = _run(store, scheduler, kill_at_chunks=target, delay=rng.uniform(0.0, 0.05))
        history.append((scheduler, target, code, _done_count(store)))
        assert code is None, f"seed {seed}: the run ended before it could be killed {history}"
    assert _run(store, "serial") == 0
    history.append(("serial", None, 0, _done_count(store)))
    message = f"seed {seed}, runs (scheduler, kill moment, exit code, chunks done) {history}"
    print(message)
    assert any(0 < done < total for _, _, code, done in history if code is None), message
    expected = open_result(reference, keep_record=True)  # thermogear's reader: no zarr notes about its marker
    resumed = open_result(store, keep_record=True)
    assert int(resumed["chunk_done"].sum()) == total, message
    assert resumed.identical(expected), message
    for name in expected.data_vars:  # bit for bit, NaN where NaN
        assert np.array_equal(np.asarray(resumed[name]), np.asarray(expected[name]), equal_nan=True), (name, message)


def test_resume_refuses_another_study(tmp_path):
    out = tmp_path / "a.zarr"
    base = ["sweep", "luo2019", "--out", str(out), "--scheduler", "serial", "--no-progress"]
    first = inprocess_cli.run(*base, "--vary", "speed_rpm=1000,2000")
    assert first.returncode == 0, first.stderr
    again = inprocess_cli.run(*base, "--vary", "speed_rpm=1000,2000")
    assert again.returncode == 2 and "--resume" in again.stderr
    other = inprocess_cli.run(*base, "--vary", "speed_rpm=1000,3000", "--resume")
    assert other.returncode == 2 and "same study" in other.stderr
    same = inprocess_cli.run(*base, "--resume")
    assert same.returncode == 0 and "0 computed, 1 kept" in " ".join(same.stdout.split()), same.stdout


@pytest.mark.parametrize("kill", [False])
def test_interrupted_store_without_marker_is_recomputed(tmp_path, kill):
    """A block whose data were written but whose marker was not (a kill between the two) is computed again."""
    from thermogear.case import load_case
    from thermogear.sweep import Study, run_study

    study = Study.define(load_case("luo2019"), ["speed_rpm=1000:4000:6"], model="elastic", chunk_points=2)
    out = tmp_path / "s.zarr"
    with np.errstate(all="ignore"):
        import warnings

        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            full = run_study(study, out, scheduler="serial", progress=False).dataset
            group = zarr.open_group(str(out), mode="r+")
            group["chunk_done"][1] = 0
            group["kv"][:, 2:4] = -1.0  # stale data of the unmarked block
            again = run_study(study, out, scheduler="serial", resume=True, progress=False)
    assert again.computed == 1 and again.skipped == 2
    assert again.dataset.identical(full)
