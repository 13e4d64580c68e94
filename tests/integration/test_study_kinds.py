"""Every kind of study (issue 34) on the one executor and the one store: serial, local worker processes and an
external `dask scheduler` with two `dask worker` processes give the same store file for file, bit for bit; killed
with SIGKILL part-way and resumed, a study gives the store of an uninterrupted run, and no process of it is left.

Tiny grids: the two-shaft drivetrain cut to 32 intervals and a 10 kHz modal cut-off, the FZG pair's branches at
three speeds (and with a two-start search at every point), luo2019's grid (the paper's linear mesh), the FZG
gearbox's steady grid and its warm-ups at three torques.
"""

from __future__ import annotations

import hashlib
import os
import signal
import subprocess
import sys
import time
import warnings
from pathlib import Path

import numpy as np
import pytest

from test_sweep_distributed import cluster  # noqa: F401  (module-scoped: one scheduler and two workers here)

DATA = Path(__file__).resolve().parents[1] / "data"
pytestmark = [pytest.mark.slow, pytest.mark.filterwarnings("ignore")]


def _drivetrain_case(tmp_path: Path, mesh: str) -> Path:
    text = (DATA / "two_shaft_drivetrain.toml").read_text(encoding="utf-8")
    text = text.replace('mesh = "linear"', f'mesh = "{mesh}"').replace(
        "[drivetrain]\n", "[drivetrain]\nsweep_points_per_period = 32\nresponse_cutoff_hz = 10000.0\n", 1)
    path = tmp_path / f"drivetrain_{mesh}.toml"
    path.write_text(text, encoding="utf-8")
    return path


def _files(store: Path) -> dict[str, str]:
    """Every file of a store (but the ownership marker, which names the writing process) and its digest."""
    found = {}
    for folder, _, names in os.walk(store):
        for name in names:
            if name == ".thermogear-owner.json":
                continue
            path = Path(folder) / name
            found[str(path.relative_to(store))] = hashlib.sha256(path.read_bytes()).hexdigest()
    return found


def _study(kind: str, tmp_path: Path) -> tuple[object, dict]:
    """The case and the arguments of ``thermogear.sweep`` of each kind."""
    if kind == "drivetrain-linear":
        return _drivetrain_case(tmp_path, "linear"), {"vary": {"speed_rpm": "1000:3000:4", "torque_nm": [100, 150]},
                                                        "model": "elastic", "chunk_points": 2}
    if kind == "drivetrain-backlash":
        return _drivetrain_case(tmp_path, "nonlinear"), {"vary": {"speed_rpm": [2000, 3000], "torque_nm": [150]},
                                                           "model": "elastic"}
    if kind == "branches":
        return "fzg_type_c", {"vary": {"torque_nm": [100, 200], "speed_rpm": "8000:24000:3"}, "model": "elastic"}
    if kind == "warmup":  # the FZG gearbox's warm-up (10 min, the mesh every 5 min) at three torques
        from thermogear.sweep.warmup_study import WarmupSettings

        return DATA / "gearbox" / "fzg_gearbox.toml", {"vary": {"torque_nm": [50, 100, 150]}, "kind": "warmup",
                                                       "warmup": WarmupSettings(600.0, 300.0)}
    if kind == "multistart":  # the branches and, at every point, the search from two starts
        return "fzg_type_c", {"vary": {"torque_nm": [200], "speed_rpm": "16000:24000:3"}, "model": "elastic",
                              "multistart": 2}
    return "luo2019", {"vary": {"speed_rpm": "1000:12000:24", "torque_nm": [100, 200]},
                                    "chunk_points": 8}


def _gearbox_grid(out: Path, scheduler: str, workers=None) -> None:
    from thermogear.case import load_case
    from thermogear.gearbox.case_model import gearbox_model_from_case, gearbox_operating_point
    from thermogear.sweep.gearbox_grid import run_gearbox_grid

    case = load_case(str(DATA / "gearbox" / "fzg_gearbox.toml"))
    ambient = gearbox_operating_point(case.operating_point, case.gearbox).ambient_c
    run_gearbox_grid(gearbox_model_from_case(case), np.linspace(400.0, 4000.0, 5), [50.0, 150.0, 300.0], ambient,
                     scheduler, workers, out=out, chunk_points=4, case=case)


KINDS = ("grid", "branches", "multistart", "drivetrain-linear", "drivetrain-backlash", "gearbox-grid", "warmup")


# one worker runs these five, so that they share the module's one scheduler and two workers
@pytest.mark.xdist_group(name="study-kinds-cluster")
@pytest.mark.parametrize("kind", KINDS)
def test_serial_local_workers_and_a_scheduler_give_the_same_store(kind, tmp_path, cluster):
    import thermogear

    address, _ = cluster
    stores = {}
    for name, scheduler, workers in (("serial", "serial", None), ("local", "processes", 2),
                                     ("remote", address, None)):
        out = tmp_path / f"{name}.zarr"
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            if kind == "gearbox-grid":
                _gearbox_grid(out, scheduler, workers)
            else:
                case, arguments = _study(kind, tmp_path)
                thermogear.sweep(case, out=out, scheduler=scheduler, workers=workers, **arguments)
        stores[name] = _files(out)
    assert len(stores["serial"]) > 3
    assert stores["local"] == stores["serial"]
    assert stores["remote"] == stores["serial"]


# ------------------------------------------------------------------------------------------ killed and resumed
def _command(kind: str, tmp_path: Path, out: Path, scheduler: str, *extra: str) -> list[str]:
    if kind == "gearbox-grid":
        return [sys.executable, "-m", "thermogear", "gearbox", str(DATA / "gearbox" / "fzg_gearbox.toml"),
                "--speeds", "400:4000:40", "--torques", "50,150,300", "--chunk-points", "3", "--no-progress",
                "--json", "--out", str(out), "--scheduler", scheduler, *extra]
    case, arguments = _study(kind, tmp_path)
    vary = []
    for name, values in arguments["vary"].items():
        vary += ["--vary", f"{name}={values if isinstance(values, str) else ','.join(map(str, values))}"]
    options = [*(("--model", arguments["model"]) if "model" in arguments else ()),
               *(("--multistart", str(arguments["multistart"])) if "multistart" in arguments else ()),
               *(("--kind", arguments["kind"]) if "kind" in arguments else ()),
               *(("--duration-s", str(arguments["warmup"].duration_s), "--interval-s",
                  str(arguments["warmup"].interval_s)) if "warmup" in arguments else ()),
               *(("--chunk-points", str(arguments["chunk_points"])) if "chunk_points" in arguments else ())]
    return [sys.executable, "-m", "thermogear", "sweep", str(case), *vary, *options, "--out", str(out),
            "--scheduler", scheduler, "--no-progress", "--json", *extra]


def _done(out: Path) -> tuple[int, int]:
    import zarr

    for record in ("task_done", "chunk_done"):
        try:
            marks = np.asarray(zarr.open_group(str(out), mode="r")[record][:])
        except (KeyError, FileNotFoundError, ValueError, OSError):
            continue
        return int(marks.sum()), int(marks.size)
    return 0, 1


def _descendants(pid: int) -> list[int]:
    import psutil

    try:
        return [child.pid for child in psutil.Process(pid).children(recursive=True)]
    except psutil.NoSuchProcess:
        return []


@pytest.mark.parametrize("kind", KINDS)
def test_killed_part_way_and_resumed_gives_the_uninterrupted_store(kind, tmp_path):
    import psutil

    environment = {**os.environ, "PYTHONWARNINGS": "ignore"}
    reference = tmp_path / "reference.zarr"
    subprocess.run(_command(kind, tmp_path, reference, "serial"), check=True, capture_output=True, env=environment,
                   timeout=600)
    out = tmp_path / "killed.zarr"
    # the grid runs on a local cluster: killing its driver alone must not leave a worker behind
    scheduler = "processes" if kind == "grid" else "serial"
    process = subprocess.Popen(_command(kind, tmp_path, out, scheduler), stdout=subprocess.DEVNULL,
                               stderr=subprocess.DEVNULL, env=environment, start_new_session=True)
    children: set[int] = set()
    deadline = time.monotonic() + 300
    try:
        while time.monotonic() < deadline and process.poll() is None:
            children.update(_descendants(process.pid))
            if out.exists() and _done(out)[0] >= 1:
                break
            time.sleep(0.05)
        finished, total = _done(out)
        assert process.poll() is None and 1 <= finished < total, (finished, total)
        os.kill(process.pid, signal.SIGKILL)  # the driver only
        process.wait(timeout=30)
        limit = time.monotonic() + 20
        while time.monotonic() < limit and any(psutil.pid_exists(pid) and psutil.Process(pid).status() !=
                                               psutil.STATUS_ZOMBIE for pid in children):
            time.sleep(0.2)
        left = [pid for pid in children if psutil.pid_exists(pid) and psutil.Process(pid).status() !=
                psutil.STATUS_ZOMBIE]
        assert not left, f"processes of the study still running: {left}"
    finally:
        if process.poll() is None:
            os.killpg(process.pid, signal.SIGKILL)
            process.wait()
    resumed = subprocess.run(_command(kind, tmp_path, out, "serial", "--resume"), capture_output=True, text=True,
                             env=environment, timeout=600)
    assert resumed.returncode == 0, resumed.stderr[-2000:]
    assert _files(out) == _files(reference)


def test_every_drivetrain_point_gets_its_own_steady_temperatures(tmp_path):
    # the FZG gearbox case (temperature.model = "gearbox") on its drivetrain: each speed's case predicts its own
    # steady state; none carries over from the neighbour
    import thermogear
    from thermogear.case import load_case
    from thermogear.gearbox.case_model import (gearbox_model_from_case, gearbox_operating_point,
                                               predicted_steady_state)

    # the FZG gearbox with its drivetrain, each bearing described once (stiffness and loss), made lighter to sweep
    text = (DATA / "gearbox" / "fzg_gearbox_drivetrain.toml").read_text(encoding="utf-8")
    text = text.replace("response_cutoff_hz = 30000.0", "sweep_points_per_period = 32\nresponse_cutoff_hz = 10000.0", 1)
    path = tmp_path / "gearbox_drivetrain.toml"
    path.write_text(text, encoding="utf-8")
    speeds = (500.0, 1500.0)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        data = thermogear.sweep(path, vary={"speed_rpm": list(speeds)}, out=tmp_path / "s.zarr", model="thermal",
                                scheduler="serial")
        case = load_case(str(path))
        for index, speed in enumerate(speeds):
            at = case.with_changes(**{"operating.speed_rpm": speed})
            state = predicted_steady_state(gearbox_model_from_case(at),
                                           gearbox_operating_point(at.operating_point, at.gearbox))
            # the case's resolver writes the prediction rounded to 1e-6 K
            assert float(data["oil_temperature_c"].values[index]) == pytest.approx(state.oil_c, abs=1e-6)
            assert float(data["housing_temperature_c"].values[index]) == pytest.approx(state.housing_c, abs=1e-6)
    oil = data["oil_temperature_c"].values
    assert oil[1] > oil[0] + 10.0  # the faster point runs hotter: its own temperatures
    assert bool(data["valid"].values.all()) and "per point" in data.attrs["temperatures"]
