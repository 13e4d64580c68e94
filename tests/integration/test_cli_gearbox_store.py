"""`thermogear gearbox CASE --speeds … --torques … --out X.zarr` (issue 28): the steady grid of a gearbox in a zarr
store written like a study's (owner marker, --overwrite of thermogear's own store only), its points solved on
worker processes (--workers), and `thermogear export` of it."""

from __future__ import annotations

import csv
import io
import math
from pathlib import Path

import numpy as np
import pytest
import xarray as xr

from inprocess_cli import invoke
from thermogear.case import load_case
from thermogear.gearbox.case_model import gearbox_model_from_case, gearbox_operating_point
from thermogear.gearbox.losses import NODES
from thermogear.gearbox.sweep import steady_sweep
from thermogear.ownership import MARKER

CASE = Path(__file__).parents[1] / "data" / "gearbox" / "fzg_gearbox.toml"
SPEEDS, TORQUES = (400.0, 1400.0, 4000.0), (50.0, 1000.0)
# 4000 rpm, 1000 N·m (419 kW through a 1.25 L gearbox) has no stable steady state (its stable branch ends near
# 600 N·m); 1400 rpm, 1000 N·m has one, far above the material data: a result, flagged, not valid
RUNAWAY = (2, 1)
HOT = (1, 1)
pytestmark = pytest.mark.filterwarnings("ignore::UserWarning")


def gearbox_command(*arguments: str) -> tuple[int, str, str]:
    return invoke("gearbox", str(CASE), "--speeds", ",".join(map(str, SPEEDS)),
                  "--torques", ",".join(map(str, TORQUES)), *arguments)


@pytest.fixture(scope="module")
def serial():
    """The serial loop's grid (steady_sweep without workers), the reference of the store."""
    case = load_case(str(CASE))
    operating = gearbox_operating_point(case.operating_point, case.gearbox)
    return steady_sweep(gearbox_model_from_case(case), SPEEDS, TORQUES, operating.ambient_c)


@pytest.fixture(scope="module")
def store(tmp_path_factory):
    path = tmp_path_factory.mktemp("gearbox") / "steady.zarr"
    code, _, stderr = gearbox_command("--out", str(path), "--scheduler", "threads", "--workers", "3", "--chunk-points", "2")
    assert code == 0, stderr
    return path


def test_threads_give_the_serial_loop_bit_for_bit(serial):
    # each point is the same deterministic computation whichever thread runs it: equality, not a tolerance
    from thermogear.sweep.gearbox_grid import run_gearbox_grid

    case = load_case(str(CASE))
    threaded = run_gearbox_grid(gearbox_model_from_case(case), SPEEDS, TORQUES, serial.ambient_c, "threads",
                                workers=3, chunk_points=2).result
    np.testing.assert_array_equal(threaded.runaway, serial.runaway)
    for name in ("temperatures_c", "mesh_loss", "bearing_loss", "seal_loss", "churning_loss", "efficiency",
                 "backlash"):
        np.testing.assert_array_equal(np.ma.filled(getattr(threaded, name), np.nan),
                                      np.ma.filled(getattr(serial, name), np.nan))


def test_the_store_holds_the_serial_grid(store, serial):
    assert (store / MARKER).is_file()
    with xr.open_zarr(store) as data:
        assert data["speed_rpm"].values.tolist() == list(SPEEDS)
        assert data["torque_nm"].values.tolist() == list(TORQUES)
        expected = {f"temperature_{name}": serial.node(name) for name in NODES}
        expected.update(mesh_loss=serial.mesh_loss, bearing_loss=serial.bearing_loss, seal_loss=serial.seal_loss,
                        churning_loss=serial.churning_loss, total_loss=serial.total_loss,
                        efficiency=serial.efficiency, backlash=serial.backlash)
        for name, values in expected.items():  # the same floats, NaN where masked
            np.testing.assert_array_equal(data[name].values, np.ma.filled(values, np.nan), err_msg=name)
        assert data["temperature_oil"].attrs["units"] == "degC" and data["backlash"].attrs["units"] == "m"
        assert data["mesh_loss"].attrs["units"] == "W"
        assert data.attrs["case_name"] == "fzg_gearbox_test"
        assert data.attrs["thermogear_version"] and data.attrs["case_json"].startswith("{")


def test_a_runaway_point_is_flagged_and_never_a_number(store, serial):
    assert serial.runaway[RUNAWAY] and serial.runaway.sum() == 1
    with xr.open_zarr(store) as data:
        np.testing.assert_array_equal(data["runaway"].values, serial.runaway.astype(np.int8))
        np.testing.assert_array_equal(data["valid"].values, serial.valid.astype(np.int8))
        assert data["valid"].values[HOT] == 0 and data["flag_above_material_data"].values[HOT] == 1
        assert np.isfinite(data["temperature_pinion"].values[HOT]) and data["runaway"].values[HOT] == 0
        assert np.isnan(data["temperature_pinion"].values[RUNAWAY]) and np.isnan(data["efficiency"].values[RUNAWAY])
        valid = data["runaway"].values == 0
        for name in ("temperature_oil", "mesh_loss", "efficiency", "backlash"):
            assert np.all(np.isfinite(data[name].values[valid])), name


def test_export_writes_one_row_per_speed_and_torque(store, tmp_path):
    target = tmp_path / "steady.csv"
    code, _, stderr = invoke("export", str(store), "--out", str(target))
    assert code == 0, stderr
    lines = target.read_text(encoding="utf-8").splitlines()
    assert any(line.startswith("# case: fzg_gearbox_test") for line in lines)
    table = list(csv.reader(io.StringIO("\n".join(line for line in lines if not line.startswith("#")))))
    columns, rows = table[0], table[1:]
    assert columns[:2] == ["speed_rpm [rpm]", "torque_nm [N m]"] and "temperature_oil [degC]" in columns
    assert len(rows) == len(SPEEDS) * len(TORQUES)
    flagged = [row for row in rows if row[columns.index("runaway")] == "1"]
    assert [(float(row[0]), float(row[1])) for row in flagged] == [(SPEEDS[RUNAWAY[0]], TORQUES[RUNAWAY[1]])]
    assert math.isnan(float(flagged[0][columns.index("temperature_oil [degC]")]))


def test_an_existing_folder_not_thermogears_is_refused_before_any_work(tmp_path):
    folder = tmp_path / "mine"
    folder.mkdir()
    (folder / "notes.txt").write_text("keep", encoding="utf-8")
    # a case that does not exist: the path is refused first, so the case is never read
    for extra in ((), ("--overwrite",)):
        code, _, stderr = invoke("gearbox", str(tmp_path / "no-such-case.toml"), "--out", str(folder), *extra)
        assert code != 0 and "--out" in stderr and "no-such-case" not in stderr, stderr
    assert sorted(entry.name for entry in folder.iterdir()) == ["notes.txt"]


def test_overwrite_replaces_only_thermogears_own_store(tmp_path):
    path = tmp_path / "steady.zarr"
    assert gearbox_command("--out", str(path))[0] == 0
    code, _, stderr = gearbox_command("--out", str(path))  # exists: refused without --overwrite
    assert code != 0 and "--overwrite" in stderr
    assert gearbox_command("--out", str(path), "--overwrite")[0] == 0
    (path / "notes.txt").write_text("keep", encoding="utf-8")  # a user's file in the store is never deleted
    code, _, stderr = gearbox_command("--out", str(path), "--overwrite")
    assert code != 0 and "notes.txt" in stderr
    assert (path / "notes.txt").is_file() and (path / MARKER).is_file()
    (path / "notes.txt").unlink()
    (path / "mesh_loss" / "notes.txt").write_text("keep", encoding="utf-8")  # nor one inside an array's folder
    (path / "runaway" / "c" / "mine.csv").write_text("keep", encoding="utf-8")  # nor among its chunks
    code, _, stderr = gearbox_command("--out", str(path), "--overwrite")
    assert code != 0 and "mesh_loss/notes.txt" in stderr and "runaway/c/mine.csv" in stderr, stderr
    assert (path / "mesh_loss" / "notes.txt").is_file() and (path / "runaway" / "c" / "mine.csv").is_file()


def test_without_out_the_command_writes_nothing_and_prints_as_before(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    code, stdout, stderr = gearbox_command("--json")
    assert code == 0, stderr
    assert '"oil_c"' in stdout and "wrote" not in stderr
    assert list(tmp_path.iterdir()) == []


def test_overwrite_without_out_is_refused():
    code, _, stderr = gearbox_command("--overwrite")
    assert code != 0 and "--overwrite" in stderr and "only with --out" in stderr
