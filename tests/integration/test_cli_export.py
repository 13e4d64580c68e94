"""CSV of any result (issue 24): `thermogear export` of a sweep store or a report's results.nc, `run --csv`.
One row per point or time sample, units in the column names, the case and the version in comment lines."""

from __future__ import annotations

import csv
import subprocess

import numpy as np
import pytest

import inprocess_cli
import xarray as xr

import thermogear


def thermogear_command(*arguments: str, cwd=None) -> subprocess.CompletedProcess:
    return inprocess_cli.run(*arguments, cwd=cwd)


def read_csv(text: str) -> tuple[list[str], list[str], list[list[str]]]:
    """(comment lines, columns, rows) of an exported CSV."""
    lines = text.splitlines()
    comments = [line for line in lines if line.startswith("#")]
    table = list(csv.reader(line for line in lines if not line.startswith("#")))
    return comments, table[0], table[1:]


@pytest.fixture(scope="module")
def store(tmp_path_factory):
    """A 3 × 2 sweep of the paper's case (linear mesh: a second or two)."""
    path = tmp_path_factory.mktemp("sweep") / "small.zarr"
    result = thermogear_command("sweep", "luo2019", "--vary", "speed_rpm=1000,2000,3000", "--vary",
                                "torque_nm=100,200", "--out", str(path))
    assert result.returncode == 0, result.stderr
    return path


def test_a_store_exports_one_row_per_point_with_both_models(store):
    result = thermogear_command("export", str(store))
    assert result.returncode == 0, result.stderr
    comments, columns, rows = read_csv(result.stdout)
    assert comments[0].startswith(f"# thermogear {thermogear.__version__} export of")
    assert "# case: luo2019" in comments
    assert columns[:2] == ["speed_rpm", "torque_nm"] and "kv_elastic" in columns and "kv_thermal" in columns
    assert "dte_peak_to_peak_elastic [m]" in columns  # the unit in the column name
    assert len(rows) == 6  # one per grid point
    with xr.open_dataset(store, engine="zarr") as data:
        for row in rows:
            point = {"speed_rpm": float(row[0]), "torque_nm": float(row[1])}
            for model in ("elastic", "thermal"):
                expected = float(data["kv"].sel(model=model, **point))
                assert float(row[columns.index(f"kv_{model}")]) == expected  # written to the last bit


def test_a_results_file_exports_its_steady_responses(tmp_path):
    """A results.nc laid out as a report writes it (root attributes, one group per response)."""
    path = tmp_path / "results.nc"
    time = np.linspace(0.0, 1e-3, 5)
    xr.Dataset(attrs={"case_name": "my_pair", "thermogear_version": "0.0.1"}).to_netcdf(path, engine="h5netcdf")
    for offset, group in enumerate(("elastic_steady", "thermal_steady")):
        xr.Dataset({"displacement": ("time", time * 0 + offset, {"units": "m"}),
                    "pair_load": (("slot", "time"), np.ones((2, 5)), {"units": "N"}),
                    "node_time": ("node", np.arange(3.0), {"units": "s"})},
                   coords={"time": ("time", time, {"units": "s"})}).to_netcdf(path, mode="a", group=group,
                                                                             engine="h5netcdf")
    result = thermogear_command("export", str(tmp_path))  # the report folder
    assert result.returncode == 0, result.stderr
    comments, columns, rows = read_csv(result.stdout)
    assert "# case: my_pair" in comments and "# computed by thermogear 0.0.1" in comments
    assert any("node_time" in line for line in comments)  # what is left out is said
    assert columns == ["model", "time [s]", "displacement [m]", "pair_load_0 [N]", "pair_load_1 [N]"]
    assert [row[0] for row in rows] == ["elastic"] * 5 + ["thermal"] * 5
    assert [float(row[1]) for row in rows[:5]] == list(time)
    one = thermogear_command("export", str(path), "--group", "thermal_steady", "--dimension", "node")
    assert one.returncode == 0, one.stderr
    assert read_csv(one.stdout)[1] == ["node", "node_time [s]"]


def test_run_writes_its_responses_as_csv_and_refuses_to_overwrite(tmp_path):
    target = tmp_path / "run.csv"
    result = thermogear_command("run", "luo2019", "--model", "elastic", "--csv", str(target))
    assert result.returncode == 0, result.stderr
    comments, columns, rows = read_csv(target.read_text())
    assert columns[:3] == ["model", "time [s]", "displacement [m]"] and "velocity [m/s]" in columns
    assert len(rows) > 100 and {row[0] for row in rows} == {"elastic"}
    times = [float(row[1]) for row in rows]
    assert times == sorted(times)
    again = thermogear_command("run", "luo2019", "--model", "elastic", "--csv", str(target))
    assert again.returncode == 2 and "--csv" in again.stderr and "--force" in again.stderr
    foreign = tmp_path / "mine.csv"
    foreign.write_text("a,b\n1,2\n")
    refused = thermogear_command("export", str(tmp_path), "--out", str(foreign), "--force")
    assert refused.returncode == 2 and "its own files" in refused.stderr
    assert foreign.read_text() == "a,b\n1,2\n"


def test_export_names_what_it_cannot_read(tmp_path):
    result = thermogear_command("export", str(tmp_path / "nothing.zarr"))
    assert result.returncode == 2 and "SOURCE" in result.stderr and "Traceback" not in result.stderr
